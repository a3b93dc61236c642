"""Haag 1935, chapter II, n°44–46, eqs. (151)–(155): a blade whose Young's modulus differs on its two sides,
with clamping errors; the fully symmetric clock; internal friction with clamping errors (n°46, :mod:`.friction`).

:mod:`.derivation` (SymPy, from (104)–(105), (117), (119), (122), (36)), :mod:`.printed` (the text and its
readings), :mod:`.truth` (the reduced equation with the one-sided stiffness, odefun over a period),
:mod:`.table` (the Results).
"""
from .table import specs

__all__ = ["specs"]
