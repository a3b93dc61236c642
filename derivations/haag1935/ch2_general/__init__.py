"""Haag 1935, chapter II, n°26–30, eqs. (88)–(114): the general theory of perturbations and the isochronism error.

:mod:`.derivation` (SymPy, from chapter I's equations kept to the next order), :mod:`.printed` (the text and
its readings), :mod:`.truth` (the exact large-deflection blade of :mod:`pendsym.nonlinear_blade`, the rigid
pendulum's exact period, the exact trigonometric terms), :mod:`.table` (the Results).
"""
from .table import PERIOD as PERIOD_RESULTS, specs

__all__ = ["specs", "PERIOD_RESULTS"]
