"""Haag 1935, chapter I, n°1–9, eqs. (1)–(41): equations, properties of v and w, foci, periods, existence.

In progress (issue 3): no Result is declared yet.
"""
from __future__ import annotations

from pendsym.result import Spec


def specs() -> tuple[Spec, ...]:
    return ()
