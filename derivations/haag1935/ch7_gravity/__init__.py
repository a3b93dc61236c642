"""Haag 1935, chapter VII, n°82–93: the gravity pendulum with direct suspension.

:mod:`.derivation` (SymPy, from chapter I's model and chapters I/III derived forms), :mod:`.printed`
(the text and its readings), :mod:`.truth` (the directly solved blade and the pendulum's eigenproblem,
direct or inverted, shared with chapter VIII), :mod:`.checks_gravity` (order checks in ε), :mod:`.table`;
n°86, 88–90 ((269), (274)–(277), (279)) in :mod:`.derivation_launch`, :mod:`.printed_launch`,
:mod:`.checks_launch`, :mod:`.table_launch`.
"""
from __future__ import annotations

from pendsym.result import Spec

from . import table, table_launch


def equation(spec: Spec) -> int:
    return int(spec.id.split(".")[1][2:])


def specs() -> tuple[Spec, ...]:
    """table's Results with table_launch's inserted in the memoir's order: each before the first Result of table
    with a larger equation number."""
    merged = list(table.specs())
    for spec in table_launch.specs():
        place = next((i for i, other in enumerate(merged) if equation(other) > equation(spec)), len(merged))
        merged.insert(place, spec)
    return tuple(merged)


__all__ = ["specs"]
