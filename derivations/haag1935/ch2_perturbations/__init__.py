"""Haag 1935, chapter II, n°36–39, eqs. (135)–(143): the blade's inertia and weight, Le Rolland's moment law.

:mod:`.derivation` (SymPy, from (104)–(105) of n°28), :mod:`.printed` (the text and its readings), :mod:`.truth`
(the pendulum on a blade with mass, :mod:`pendsym.massive_blade`; the stiffer linear blade), :mod:`.table`.
"""
from .table import specs

__all__ = ["specs"]
