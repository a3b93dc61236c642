"""The toy memoir's one section: T0 = 2π/k, then T = T0(1 + α²/16) to second order in α."""
from __future__ import annotations

import os
import time

import mpmath as mp
import sympy as sp

from pendsym import checks, truth, verify
from pendsym.result import Source, Spec

MEMOIR = "toy"
t = sp.Symbol("t", real=True)
k = sp.Symbol("k", positive=True)
alpha = sp.Symbol("alpha", positive=True)
K_CHECK = "1.3"


# ----------------------------------------------------------------- derivation
def period0(_deps) -> sp.Expr:
    """T0: the period of θ'' + k²θ = 0, from its general solution."""
    theta = sp.Function("theta")
    sol = sp.dsolve(theta(t).diff(t, 2) + k**2 * theta(t), theta(t)).rhs
    omega = [a for f in sol.atoms(sp.cos) for a in [f.args[0] / t]][0]
    return 2 * sp.pi / omega


def period2(deps) -> sp.Expr:
    """T = T0 · (2/π)K(sin²(α/2)) to second order in α.  (TOY_WRONG_ORDER keeps a wrong α² coefficient,
    for the tests of a failing derive.)"""
    m = sp.sin(alpha / 2) ** 2
    series = sp.series(sp.elliptic_k(m) * 2 / sp.pi, alpha, 0, 3).removeO()
    if os.environ.get("TOY_WRONG_ORDER"):
        series += alpha**2 / 100
    return sp.expand(deps["toy.T0"].derived * series)


# ----------------------------------------------------------------- truth
def swing_period(al, dps: int) -> mp.mpf:
    """Twice the time from rest at −α to the next turning point of θ'' + k² sin θ = 0 (odefun).
    (TOY_SLOW_SECONDS makes it slow, for the tests that interrupt a derive.)"""
    time.sleep(float(os.environ.get("TOY_SLOW_SECONDS", "0")))
    kv = mp.mpf(K_CHECK)
    traj = truth.integrate(lambda _t, y: [y[1], -kv**2 * mp.sin(y[0])], [-mp.mpf(al), 0], dps=dps)
    return 2 * truth.turning_time(traj, mp.pi / kv, width=mp.mpf("0.3"))


def _period0_points(level: str, dps: int):
    for al in ("1e-6", "2e-6"):
        yield checks.Point(f"alpha={al}", {"k": mp.mpf(K_CHECK)}, swing_period(al, dps), denom=1)


def _at(expr, p) -> mp.mpf:
    return mp.mpf(verify.value_at(expr, {"k": K_CHECK, "alpha": p}))


# ----------------------------------------------------------------- table
def specs() -> tuple[Spec, ...]:
    return (
        Spec(id="toy.T0", title="Period of small oscillations", source=Source(MEMOIR, "n°1", eq="1"),
             lhs="T_0", derive=period0, printed=lambda: 2 * sp.pi / k,
             check=checks.Values(truth="period of the integrated pendulum at α ≤ 2e-6 (mpmath odefun)",
                                 points=_period0_points, tol=mp.mpf("1e-9"))),
        Spec(id="toy.T", title="Period to second order in the amplitude", source=Source(MEMOIR, "n°2", eq="2"),
             lhs="T", derive=period2, deps=("toy.T0",), printed=lambda: 2 * sp.pi / k * (1 + alpha**2 / 16),
             check=checks.Order(param="alpha", values=lambda level: verify.geometric("0.02", "0.08", 4),
                                truth=swing_period, at=_at, expected=4, band=0.3,
                                truth_desc="period of θ'' + k² sin θ = 0 integrated by mpmath odefun")),
    )
