"""Haag 1935, chapter VII, n°92–93 and n°97, eqs. (281)–(284): the gravity pendulum's perturbations in general,
its isochronism error, the flexion-law correction and internal friction.

:mod:`.derivation` (SymPy: chapter II's (104), (105), (111), (112), (141), (147), (149) with chapter VII's
a = a1 + ελ, K of (260), z' of (257) at ε → 0), :mod:`.printed` (the text and its readings), :mod:`.truth` (the slow
oscillation on the exact large-deflection blade; linear perturbations of the slow mode's n²),
:mod:`.checks_isochronism` (order checks in ε), :mod:`.table` (the Results).
"""
from . import table


def sections():
    """(module, title) of the chapter VII Result tables."""
    return ((table, "Chapter VII. Perturbations of the gravity pendulum, isochronism error (281)–(284), n°92–93, 97"),)


__all__ = ["sections"]
