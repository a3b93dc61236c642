"""Haag 1935, chapter II, n°31–35, eqs. (116)–(134): the clamping errors and their interaction with the
isochronism error.

:mod:`.derivation` (SymPy, from the tilted (4)–(6) and the derived forms of n°26–30), :mod:`.printed` (the text
and its readings), :mod:`.truth` (the exact tilted equilibrium and the small oscillation about it,
:mod:`pendsym.nonlinear_tilt`), :mod:`.table` (the Results).
"""
from .table import TILT_RESULTS, specs

__all__ = ["specs", "TILT_RESULTS"]
