"""Charbonnier's governing models, integrated at high precision (the independent truth).

Each model is the memoir's own equation before its small-parameter
approximations: the full sin θ of n°21, the variable-length equation of n°2
with the exact length law of each example (the implicit law of the elastic
thread solved for l, the linear law of the growing cable).  The measurements
are those of one swing started at rest at −α: the swing time (next turning
point), the amplitude there, the time of the lowest point and the speed there.
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import mpmath as mp
import sympy as sp

from pendsym import pendulum, truth
from .symbols import a, beta, dtheta, eps, g, k, l0, mu, q, t, theta

# Exact length laws l(θ, θ', t) of the examples (n°22, n°23, n°24, n°27).
_lam = sp.Symbol("lambda", positive=True)
ELASTIC_L = sp.solve(sp.Eq(sp.Symbol("L"), _lam * (1 + mu / g * (g * sp.cos(theta) + sp.Symbol("L") * dtheta**2))),
                     sp.Symbol("L"))[0].subs(_lam, l0 / (1 + mu))
LAWS = {
    # name: (l(θ, θ', t), restoring s(θ), model parameters)
    "sine": (l0, sp.sin(theta), ()),
    "winding": (l0 * (1 - sp.Rational(4, 9) * beta * theta**2), theta, (beta,)),
    "curve_q": (l0 * (1 + q * theta**2), theta, (q,)),
    "cycloidal_sine": (l0 * (1 + q * theta**2), sp.sin(theta), (q,)),
    "elastic": (ELASTIC_L, theta, (mu,)),
    "growing": (l0 * (1 + a * t), theta, (a,)),
}
MODEL_TEXT = {
    "sine": "θ'' + k² sin θ = 0 (n°21, 1°), mpmath odefun",
    "winding": "θ'' + (2/l)l'θ' + (g/l)θ = 0 with l = l0(1 − 4βθ²/9) (n°22), mpmath odefun",
    "curve_q": "θ'' + (2/l)l'θ' + (g/l)θ = 0 with l = l0(1 + qθ²) (n°23), mpmath odefun",
    "cycloidal_sine": "θ'' + (2/l)l'θ' + (g/l) sin θ = 0 with l = l0(1 + θ²/2) (n°23), mpmath odefun",
    "elastic": ("θ'' + (2/l)l'θ' + (g/l)θ = 0 with the implicit law l = λ[1 + (m/e)(g cos θ + l θ'²)] "
                "solved for l, θ'' kept in l' (n°24–25), mpmath odefun"),
    "growing": "θ'' + (2/l)l'θ' + (g/l)θ = 0 with l = l0(1 + at) (n°27–28), mpmath odefun",
}


@lru_cache(maxsize=None)
def _bound(name: str):
    law, restoring, params = LAWS[name]
    bind = pendulum.exact_rhs(law.subs(g, k**2 * l0), theta, dtheta, t, k**2 * l0,
                              (k, l0) + params, restoring)
    return bind, tuple(p.name for p in params)


def rhs(name: str, k_val, params: dict):
    """The right-hand side of model ``name`` for k and the model's parameters (l0 = 1)."""
    bind, names = _bound(name)
    return bind(mp.mpf(k_val), mp.mpf(1), *(mp.mpf(params[n]) for n in names))


@lru_cache(maxsize=None)
def _oscillator(phi_key: str):
    phi = PHIS[phi_key]
    f = sp.lambdify((t, theta, dtheta, k, eps), -k**2 * theta - eps * phi, modules="mpmath")
    return lambda kv, ev: (lambda tt, y: [y[1], f(tt, y[0], y[1], kv, ev)])


# Perturbations of the oscillator θ'' + k²θ + εφ = 0 used to test the general formulas.
PHIS = {
    "generic": theta**2 + theta * dtheta / 2 + sp.sin(sp.Rational(13, 10) * t) * theta + sp.Rational(1, 3),
    **{f"theta^{j}": theta**j for j in range(1, 7)},
}


@dataclass(frozen=True)
class Swing:
    T: mp.mpf        # time of the first turning point after t = 0
    amp: mp.mpf      # θ there (the amplitude on the far side)
    t_low: mp.mpf    # time of the lowest point (θ = 0)
    v_low: mp.mpf    # θ' there
    traj: truth.Trajectory


def _swing(traj: truth.Trajectory, k_val) -> Swing:
    kv = mp.mpf(k_val)
    T = truth.turning_time(traj, mp.pi / kv, width=mp.pi / (4 * kv))
    tl = truth.crossing_time(traj, mp.pi / (2 * kv), width=mp.pi / (4 * kv))
    return Swing(T, traj(T)[0], tl, traj(tl)[1], traj)


@lru_cache(maxsize=None)
def swing(name: str, alpha_val: str, k_val: str, dps: int, **params) -> Swing:
    """One swing of model ``name`` started at rest at −α (l0 = 1)."""
    with mp.workdps(dps):
        traj = truth.integrate(rhs(name, k_val, params), [-mp.mpf(alpha_val), 0], dps)
        return _swing(traj, k_val)


@lru_cache(maxsize=None)
def oscillator(phi_key: str, eps_val: str, k_val: str, theta_i: str, omega_i: str, dps: int):
    """θ'' + k²θ + εφ = 0 from (θ_i, ω_i): the trajectory (and the swing when ω_i = 0, θ_i < 0)."""
    with mp.workdps(dps):
        traj = truth.integrate(_oscillator(phi_key)(mp.mpf(k_val), mp.mpf(eps_val)),
                               [mp.mpf(theta_i), mp.mpf(omega_i)], dps)
        if mp.mpf(omega_i) == 0 and mp.mpf(theta_i) < 0:
            return _swing(traj, k_val)
        return traj
