"""Haag 1935, chapter I, n°10–15, eqs. (42)–(63): small variations of the period, temperature, g.

In progress (issue 3): no Result is declared yet.
"""
from __future__ import annotations

from pendsym.result import Spec


def specs() -> tuple[Spec, ...]:
    return ()
