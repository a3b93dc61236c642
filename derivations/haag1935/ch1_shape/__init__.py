"""Haag 1935, chapter I, n°21–25, eqs. (77)–(87): shape, fatigue, energy and suppleness, centre of flexion, fork.

:mod:`.derivation` (SymPy), :mod:`.printed` (the text and its readings), :mod:`.truth`
(the direct blade's shape, curvature, energies and node; the fork's exact glide; the end's position on the
exact nonlinear orbit for n°25's orders of (64) and (85)),
:mod:`.table` (the Results).
"""
from .table import ORBIT_RESULTS, specs

__all__ = ["ORBIT_RESULTS", "specs"]
