"""First-order perturbation of the harmonic oscillator by variation of constants.

The perturbed equation is  θ'' + k²θ + εφ = 0,  where φ may depend on θ, θ'
and t.  The unperturbed motion is θ0(t) = θ_i cos kt + (ω_i/k) sin kt; with
The memoirs' start at rest at −α it is θ0 = −α cos kt.

Variation of constants (Duhamel) gives the first-order correction that keeps
the initial conditions of θ0:

    θ1(t) = (ε/k) [E_s(t) cos kt − E_c(t) sin kt],
    θ1'(t) = −ε [E_s(t) sin kt + E_c(t) cos kt],

with  E_s(t) = ∫_0^t φ(τ) sin kτ dτ  and  E_c(t) = ∫_0^t φ(τ) cos kτ dτ,
φ being evaluated along θ0.  These are the integrals E_s, E_c of the variation of constants; the
general formulas of n°8–9 are rebuilt from them by :func:`turning_shift`,
:func:`crossing_shift` and the value of θ1 or θ1' at those events.

Every function returns SymPy objects and is valid for any positive k, any φ
(explicit time dependence included) and any initial conditions.
"""
from __future__ import annotations

import sympy as sp


def unperturbed(t: sp.Symbol, k: sp.Expr, theta_i: sp.Expr, omega_i: sp.Expr = sp.S.Zero) -> sp.Expr:
    """θ0(t) with θ0(0) = θ_i and θ0'(0) = ω_i (a start at rest: θ_i = −α, ω_i = 0)."""
    return theta_i * sp.cos(k * t) + omega_i / k * sp.sin(k * t)


def along(phi: sp.Expr, theta: sp.Symbol, dtheta: sp.Symbol, theta0: sp.Expr, t: sp.Symbol) -> sp.Expr:
    """φ(θ, θ', t) evaluated along the unperturbed motion θ0(t) (n°18)."""
    return phi.subs({theta: theta0, dtheta: sp.diff(theta0, t)}, simultaneous=True)


def _phase_integral(phi_t: sp.Expr, weight, t: sp.Symbol, k: sp.Expr) -> sp.Expr:
    """∫_0^t φ(τ) w(kτ) dτ, computed in the phase x = kτ as the memoir does (∫ … d(kt))."""
    x = sp.Dummy("x", real=True)
    integrand = sp.expand(sp.expand_trig(phi_t.subs(t, x / k) * weight(x)))
    # conds="none": the generic branch, valid for every k that is not a resonance of φ
    antider = sp.integrate(integrand, (x, 0, k * t), conds="none") / k
    return sp.simplify(antider)


def E_s(phi_t: sp.Expr, t: sp.Symbol, k: sp.Expr) -> sp.Expr:
    """E_s(t) = ∫_0^t φ sin kτ dτ  (the memoir's n°18)."""
    return _phase_integral(phi_t, sp.sin, t, k)


def E_c(phi_t: sp.Expr, t: sp.Symbol, k: sp.Expr) -> sp.Expr:
    """E_c(t) = ∫_0^t φ cos kτ dτ  (the memoir's n°18)."""
    return _phase_integral(phi_t, sp.cos, t, k)


def theta1(Es: sp.Expr, Ec: sp.Expr, eps: sp.Expr, k: sp.Expr, t: sp.Symbol) -> sp.Expr:
    """First-order correction θ1 = (ε/k)(E_s cos kt − E_c sin kt) (rebuilt n°8)."""
    return eps / k * (Es * sp.cos(k * t) - Ec * sp.sin(k * t))


def dtheta1(Es: sp.Expr, Ec: sp.Expr, eps: sp.Expr, k: sp.Expr, t: sp.Symbol) -> sp.Expr:
    """θ1' = −ε (E_s sin kt + E_c cos kt) (rebuilt n°8; the E' terms cancel)."""
    return -eps * (Es * sp.sin(k * t) + Ec * sp.cos(k * t))


def first_order(theta0: sp.Expr, Es: sp.Expr, Ec: sp.Expr, eps: sp.Expr, k: sp.Expr,
                t: sp.Symbol) -> tuple[sp.Expr, sp.Expr]:
    """(θ, θ') to first order in ε: θ0 + θ1 and θ0' + θ1' (rebuilt n°8)."""
    return (theta0 + theta1(Es, Ec, eps, k, t),
            sp.diff(theta0, t) + dtheta1(Es, Ec, eps, k, t))


def turning_shift(theta0: sp.Expr, dth1: sp.Expr, t: sp.Symbol, t_star: sp.Expr) -> sp.Expr:
    """Shift of a turning point t* of θ0 (θ0'(t*) = 0): Δt = −θ1'(t*)/θ0''(t*) (rebuilt n°9)."""
    return sp.simplify(-dth1.subs(t, t_star) / sp.diff(theta0, t, 2).subs(t, t_star))


def crossing_shift(theta0: sp.Expr, th1: sp.Expr, t: sp.Symbol, t_star: sp.Expr) -> sp.Expr:
    """Shift of a zero t* of θ0 (θ0(t*) = 0): Δt = −θ1(t*)/θ0'(t*) (rebuilt n°9, 3°)."""
    return sp.simplify(-th1.subs(t, t_star) / sp.diff(theta0, t).subs(t, t_star))


def residual_of_ode(theta: sp.Expr, t: sp.Symbol, k: sp.Expr, eps: sp.Expr, phi_t: sp.Expr) -> sp.Expr:
    """θ'' + k²θ + εφ(t) for a candidate θ(t); zero to first order for the rebuilt θ."""
    return sp.simplify(sp.diff(theta, t, 2) + k**2 * theta + eps * phi_t)
