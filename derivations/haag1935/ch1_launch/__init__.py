"""Haag 1935, chapter I, n°16–20, eqs. (64)–(76): the principal oscillation and the launching.

:mod:`.derivation` (SymPy: the oscillations, the statics, the blow), :mod:`.printed`
(the text and its readings), :mod:`.truth` (the direct blade's modes and static
offset, the blow solved from the mechanics), :mod:`.table` (the Results).
"""
from .table import specs

__all__ = ["specs"]
