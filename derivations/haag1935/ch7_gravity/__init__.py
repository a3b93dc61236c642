"""Haag 1935, chapter VII, n°82–93: the gravity pendulum with direct suspension.

:mod:`.derivation` (SymPy, from chapter I's model and chapters I/III derived forms), :mod:`.printed`
(the text and its readings), :mod:`.truth` (the directly solved blade and the pendulum's eigenproblem,
direct or inverted, shared with chapter VIII), :mod:`.checks_gravity` (order checks in ε), :mod:`.table`.
"""
from .table import specs

__all__ = ["specs"]
