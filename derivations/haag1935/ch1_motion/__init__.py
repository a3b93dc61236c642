"""Haag 1935, chapter I, n°5–9, eqs. (21)–(41): end loads, equations of motion, foci, periods, existence.

:mod:`.derivation` (SymPy, with the steps of :mod:`..ch1_model`), :mod:`.printed`
(the text and its readings), :mod:`.truth` (the directly solved blade and the
eigenproblem of the pendulum), :mod:`.table` (the Results).
"""
from .table import specs

__all__ = ["specs"]
