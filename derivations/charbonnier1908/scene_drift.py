"""One swing of the pendulum whose length grows at a constant rate, for scenes (n°27–28's governing model).

The same model and the same integration as :func:`derivations.charbonnier1908.truth.swing` for its ``"growing"``
law (l = l0(1 + at), θ'' + (2/l)l'θ' + (g/l)θ = 0, mpmath odefun through :func:`pendsym.truth.integrate`), without
importing ``truth``: that module solves the elastic thread's implicit law (n°24) when imported, which a scene of a
growing length does not need, and it cannot be made lazy without changing the key of every Charbonnier Result
(their sections import it).  The right-hand side is written out (l' = l0 a does not involve θ'', so nothing is
solved for it; :func:`pendsym.pendulum.exact_rhs` would solve symbolically, importing most of SymPy, for the same
expression).  ``tests/test_scene_drift.py`` checks it against truth's model symbolically and the swing times.
"""
from __future__ import annotations

from functools import lru_cache

import mpmath as mp

from pendsym import truth


def theta_ddot(tt, theta, theta_dot, k_val, a_val):
    """θ'' of θ'' + (2/l)l'θ' + (g/l)θ = 0 (n°2) with l = l0(1 + at) (n°27), g = k²l0: l'/l = a/(1 + at)."""
    return -(2 * a_val * theta_dot + k_val**2 * theta) / (1 + a_val * tt)


@lru_cache(maxsize=None)
def swing_time(alpha_val: str, k_val: str, dps: int, a_val: str) -> mp.mpf:
    """The time of the first turning point of the swing started at rest at −α (l0 = 1): truth's ``swing("growing",
    alpha_val, k_val, dps, a=a_val).T``."""
    with mp.workdps(dps):
        kv = mp.mpf(k_val)
        av = mp.mpf(a_val)
        traj = truth.integrate(lambda tt, y: [y[1], theta_ddot(tt, y[0], y[1], kv, av)], [-mp.mpf(alpha_val), 0], dps)
        return truth.turning_time(traj, mp.pi / kv, width=mp.pi / (4 * kv))
