"""The frequency, period and motion of an autonomous problem by Lindstedt–Poincaré.

Two kinds of small parameter are handled:

* in the equation: θ'' + k²θ + φ(θ, θ'; ε) = 0 with φ = O(ε), a power series in ε whose
  coefficients are polynomials in θ and θ' (Duffing: φ = εθ³);
* in the initial values only (the amplitude): θ(0) = α a₀, θ'(0) = α b₀ with φ(θ, θ') = O(θ²)
  near rest (the pendulum: φ = sin θ − θ).  Then θ = α x and x'' + k²x + φ(αx, αx')/α = 0 is
  expanded in α; when only even powers of α occur it is expanded in α² (half the work).
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from . import lindstedt
from .problem import Problem


class NotApplicable(ValueError):
    """Lindstedt–Poincaré does not apply to this problem (the reason is the message)."""


@dataclass(frozen=True)
class FrequencyAnswer:
    omega: sp.Expr          # ω to the order wanted, in the problem's small parameter
    period: sp.Expr         # 2π/ω expanded to the same order
    motion: sp.Expr         # θ to the order wanted, in τ = ωt (the symbol tau)
    expected: int           # the order of the first neglected term (for the fitted-order check)
    scaled: bool            # the small parameter is the amplitude
    steps: str              # how it was expanded, in words


def _is_linear_in(expr: sp.Expr, s: sp.Symbol) -> bool:
    return sp.expand(expr - s * sp.diff(expr, s)) == 0 and not sp.diff(expr, s).has(s)


def solve(problem: Problem) -> FrequencyAnswer:
    """ω, T and θ(t) to ``problem.order`` (raises NotApplicable or lindstedt.NotAFrequency)."""
    if not problem.autonomous:
        raise NotApplicable("the equation depends explicitly on time")
    eps, n = problem.small, problem.order
    x, v = sp.Symbol("x_", real=True), sp.Symbol("v_", real=True)
    in_ics = problem.theta_i.has(eps) or problem.omega_i.has(eps)
    if in_ics:
        if problem.phi.has(eps):
            raise NotApplicable("the small parameter is both in the equation and in the initial values")
        if not (_is_linear_in(problem.theta_i, eps) and _is_linear_in(problem.omega_i, eps)):
            raise NotApplicable("initial values must be proportional to the small parameter (the amplitude)")
        a, b = sp.diff(problem.theta_i, eps), sp.diff(problem.omega_i, eps)
        g = problem.phi.subs({problem.theta: eps * x, problem.dtheta: eps * v}, simultaneous=True) / eps
    else:
        a, b = problem.theta_i, problem.omega_i
        g = problem.phi.subs({problem.theta: x, problem.dtheta: v}, simultaneous=True)
    if g.has(sp.Abs, sp.sign):
        raise NotApplicable("the perturbation is not smooth (abs or sign)")
    try:
        ser = sp.expand(sp.series(g, eps, 0, n + 1).removeO()) if g.has(eps) else sp.expand(g)
    except (ValueError, NotImplementedError, TypeError) as exc:
        raise NotApplicable(f"the perturbation has no power series in {eps} ({type(exc).__name__})") from None
    even = in_ics and all(sp.expand(ser.coeff(eps, p)) == 0 for p in range(1, n + 1, 2))
    mu = sp.Symbol("mu_", positive=True)
    if even:
        ser = sp.expand(sum(ser.coeff(eps, p) * mu**(p // 2) for p in range(2, n + 1, 2)))
        steps_n = n // 2
    else:
        ser = ser.subs(eps, mu)
        steps_n = n
    try:
        parts = lindstedt.split_polynomial(ser, x, v, mu, steps_n)
    except ValueError as exc:
        raise NotApplicable(str(exc)) from None
    if steps_n == 0:
        raise NotApplicable("the order asked is below the first correction (only even powers occur)")
    try:
        exp = lindstedt.expand(parts, problem.k, a, b, mu, steps_n)
    except lindstedt.NotAFrequency:
        raise
    except ValueError as exc:
        raise NotApplicable(str(exc)) from None
    back = eps**2 if even else eps
    omega = sp.expand(exp.frequency().subs(mu, back))
    tau = sp.Symbol("tau", real=True)
    motion = sp.expand(exp.motion(tau).subs(mu, back))
    if in_ics:
        motion = sp.expand(eps * motion)
    period = sp.expand(sp.series(2 * sp.pi / omega, eps, 0, n + 1).removeO())
    expected = 2 * steps_n + 2 if even else n + 1
    how = (f"Lindstedt–Poincaré in {eps}² to order {steps_n} (only even powers of {eps} occur; "
           f"θ = {eps}·x)" if even else
           f"Lindstedt–Poincaré in {eps} to order {n}" + (f" (θ = {eps}·x)" if in_ics else ""))
    return FrequencyAnswer(omega=omega, period=period, motion=motion, expected=expected,
                           scaled=in_ics, steps=how)
