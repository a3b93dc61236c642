"""Haag 1935, chapter VIII, n°100–103: the inverted blade (g → −g).

:mod:`.derivation` (u → iu of chapter III's derived forms, ε → −ε; C from dsolve with M < 0),
:mod:`.printed`, :mod:`.truth` (the directly solved inverted blade, its eigenproblem, findroot of the
windows' ends), :mod:`.table`.
"""
from .table import specs

__all__ = ["specs"]
