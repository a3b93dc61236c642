"""Haag 1935, chapter VIII, n°100–103: the inverted blade (g → −g).

:mod:`.derivation` (u → iu of chapter III's derived forms, ε → −ε; C from dsolve with M < 0),
:mod:`.printed`, :mod:`.truth` (the directly solved inverted blade, its eigenproblem, findroot of the
windows' ends, the signs of the existence conditions), :mod:`.table` (n°100–103) and
:mod:`.table_existence` (the steps (302), (303), (306), (308) and (312)), :mod:`.table_kernels` and
:mod:`.kernels` (n² and K stated in ε = (a1 − a)/λ, for the kernels).
"""
from __future__ import annotations

from pendsym.result import Spec

from ..memoir_order import merged
from . import table, table_existence, table_kernels


def specs() -> tuple[Spec, ...]:
    """table's Results with table_existence's inserted in the memoir's order."""
    return merged(table.specs(), table_existence.specs(), table_kernels.specs())


__all__ = ["specs"]
