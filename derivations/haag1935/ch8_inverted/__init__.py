"""Haag 1935, chapter VIII, n°100–103: the inverted blade (g → −g).

:mod:`.derivation` (u → iu of chapter III's derived forms, ε → −ε; C from dsolve with M < 0),
:mod:`.printed`, :mod:`.truth` (the directly solved inverted blade, its eigenproblem, findroot of the
windows' ends, the signs of the existence conditions), :mod:`.table` (n°100–103) and
:mod:`.table_existence` (the steps (302), (303), (306), (308) and (312)).
"""
from __future__ import annotations

from pendsym.result import Spec

from . import table, table_existence


def equation(spec: Spec) -> int:
    return int(spec.id.split(".")[1][2:])


def specs() -> tuple[Spec, ...]:
    """table's Results with table_existence's inserted in the memoir's order: each before the first Result of table
    with a larger equation number."""
    merged = list(table.specs())
    for spec in table_existence.specs():
        place = next((i for i, other in enumerate(merged) if equation(other) > equation(spec)), len(merged))
        merged.insert(place, spec)
    return tuple(merged)


__all__ = ["specs"]
