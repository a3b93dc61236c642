"""Haag 1935, chapter IV, n°58–63: the thread as the limit u → ∞ of the uniform blade, (184)–(197).

* :mod:`.derivation`: the limits of chapter III's derived forms (SymPy ``limit``) and the
  direct study of n°59–63 from the positions of A and G;
* :mod:`.printed`: the formulas as printed, with their readings;
* :mod:`.truth`: the shot uniform blade at large u (order of the difference to the limit)
  and :mod:`pendsym.thread_pendulum`, the exact double pendulum;
* :mod:`.table`: the Result table.
"""
from __future__ import annotations

from .table import specs

__all__ = ["specs"]
