"""Haag 1935, chapter V, n°64–67: the point pendulum (R = 0), a point mass at the end of the blade,
equal periods and beats, (198)–(211).

* :mod:`.derivation`: from chapter I's (25)–(26), (30), (34)–(35) (:mod:`..ch1_model`) and
  chapter III's derived end values (by id);
* :mod:`.printed`: the formulas as printed, with their readings;
* :mod:`.truth`: the directly solved blade under the rigid pendulum's mass matrix (R = 0
  included) and, for the beats, the time-domain integration of the linear system;
* :mod:`.table`: the Result table.
"""
from __future__ import annotations

from .table import specs

__all__ = ["specs"]
