"""Haag 1935, chapter I, n°16–25, eqs. (64)–(87): principal oscillation, launching, shape, fatigue, suppleness, centre of flexion, fork.

In progress (issue 3): no Result is declared yet.
"""
from __future__ import annotations

from pendsym.result import Spec


def specs() -> tuple[Spec, ...]:
    return ()
