"""Haag 1935, chapter VII, n°82–93: the gravity pendulum with direct suspension.

:mod:`.derivation` (SymPy, from chapter I's model and chapters I/III derived forms), :mod:`.printed`
(the text and its readings), :mod:`.truth` (the directly solved blade and the pendulum's eigenproblem,
direct or inverted, shared with chapter VIII), :mod:`.checks_gravity` (order checks in ε), :mod:`.table`;
n°86, 88–90 ((269), (274)–(277), (279)) in :mod:`.derivation_launch`, :mod:`.printed_launch`,
:mod:`.checks_launch`, :mod:`.table_launch`.
"""
from __future__ import annotations

from pendsym.result import Spec

from ..memoir_order import merged
from . import table, table_launch


def specs() -> tuple[Spec, ...]:
    """table's Results with table_launch's inserted in the memoir's order."""
    return merged(table.specs(), table_launch.specs())


__all__ = ["specs"]
