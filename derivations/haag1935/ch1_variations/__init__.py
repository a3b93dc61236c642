"""Haag 1935, chapter I, n°10–15, eqs. (42)–(63): small variations of the periods, temperature, g.

:mod:`.derivation` (SymPy: total differentials, the two-point problem for ∂v/∂λ, the
variation of constants), :mod:`.printed` (the text and its readings), :mod:`.truth`
(stencils of the directly solved and the shot blades), :mod:`.table` (the Results).
"""
from .table import specs

__all__ = ["specs"]
