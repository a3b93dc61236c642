"""Haag 1935, chapter VII, n°98–99, eqs. (295)–(301): the dissymmetric blade of a gravity pendulum with an
unbalance j; the extremes of the period and how to measure ε.

:mod:`.derivation` (SymPy: chapter II's derived (154) specialised to the gravity pendulum, plus (286) rebuilt from
chapter II's (132)–(134) and chapter VII's (260), (262), the extremes solved by SymPy), :mod:`.printed` (the text
and its readings), :mod:`.truth` (the reduced gravity pendulum with the one-sided stiffness, the cubic of (283) and
the clamping couple: its period by quadrature of the energy integral, confirmed by odefun), :mod:`.checks_dissymmetry`
(order checks in ε_E, the minimum's check), :mod:`.table` (the Results).  n°99 announces an unpublished theory: no
Result.
"""
from . import table


def sections():
    """(module, title) of the chapter VII Result tables."""
    return ((table, "Chapter VII. The dissymmetric blade of the gravity pendulum (295)–(301), n°98–99"),)


__all__ = ["sections"]
