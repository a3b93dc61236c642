"""Haag 1935, chapter I, n°1–4, eqs. (1)–(20): the equations of the blade and the functions v, w.

:mod:`.derivation` (SymPy, in the memoir's order), :mod:`.printed` (the text and its
readings), :mod:`.truth` (the shot and the directly solved blades), :mod:`.table`
(the Results).
"""
from .table import specs

__all__ = ["specs"]
