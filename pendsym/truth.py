"""Independent truth: high-precision integration of a governing model with mpmath.

A model is a right-hand side rhs(t, y) -> dy/dt for a first-order system (for a
pendulum y = [θ, θ'] and any further state), integrated by mpmath's Taylor
series solver ``odefun`` at a scoped precision.  Events (turning points, zero
crossings) are located by ``findroot`` on the dense solution.  Nothing here
uses a perturbation formula: the guesses only pick which root is meant.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Sequence

import mpmath as mp

Rhs = Callable[[mp.mpf, list], list]


@dataclass(frozen=True)
class Trajectory:
    """A dense high-precision solution; call it at t for the state vector."""

    solve: Callable[[mp.mpf], list]
    dps: int

    def __call__(self, t) -> list:
        with mp.workdps(self.dps):
            return self.solve(mp.mpf(t))


def integrate(rhs: Rhs, y0: Sequence, dps: int = 30, t0=0) -> Trajectory:
    """Integrate y' = rhs(t, y) from t0 with mpmath.odefun at ``dps`` digits."""
    with mp.workdps(dps):
        sol = mp.odefun(rhs, mp.mpf(t0), [mp.mpf(v) for v in y0], tol=mp.mpf(10) ** (-dps - 3))
    return Trajectory(sol, dps)


def event(traj: Trajectory, g: Callable[[list, mp.mpf], mp.mpf], guess, width=None) -> mp.mpf:
    """The time t near ``guess`` where g(y(t), t) = 0.

    With ``width``, the root is bracketed in [guess − width, guess + width] and
    found by the Anderson–Björk bracketing method; without it, by the secant.
    """
    with mp.workdps(traj.dps):
        f = lambda t: g(traj.solve(t), t)
        if width is None:
            return mp.findroot(f, mp.mpf(guess))
        lo, hi = mp.mpf(guess) - width, mp.mpf(guess) + width
        return mp.findroot(f, (lo, hi), solver="anderson")


def turning_time(traj: Trajectory, guess, width=None) -> mp.mpf:
    """Time of the turning point (θ' = 0) nearest ``guess``."""
    return event(traj, lambda y, t: y[1], guess, width)


def crossing_time(traj: Trajectory, guess, width=None) -> mp.mpf:
    """Time of the zero of θ nearest ``guess`` (the lowest point)."""
    return event(traj, lambda y, t: y[0], guess, width)
