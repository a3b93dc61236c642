"""Haag 1935, chapter III, n°50–57: the pendulum on a uniform blade, eqs. (30)–(37), (171)–(183).

The foci, K and n² (n°50) come from the quadratic (30) of chapter I with the
ends (159); the shape (171)–(174), the stresses (175)–(181), I_λ (182) and J (183)
from the definitions (77)–(78), (65), (67) and n°36–37 of chapter I with v, w of
(157).  Each ``derive`` function takes the built dependencies by id.
"""
from __future__ import annotations

import sympy as sp

from pendsym.roots import quadratic_roots

from .. import ch1_model
from ..symbols import (E, K, R, U, U1, U2, Y, a, b, beta1, e, g, h, lam, mb, s, theta, u, vl, wl, z, zp)
from .derivation_functions import derived_of, x_of_phi, x_of_v_w
from .launch_symbols import (K_prime, Q, V, m, m_striking, n_parasitic, n_principal, restitution, stress_scale,
                             t, weight)
from .rational import in_hyperbolic_basis, integrate_along_blade, polynomial_in_K, tanh_half_form


# ================================================================ n°50: the foci, K and n² (30)–(37)
def foci_combination(deps) -> sp.Expr:
    """(30): the combination v_λ² + β1 w_λ of the quadratic of the foci, with (159)."""
    return sp.simplify(derived_of(deps, 159, "vl") ** 2 + derived_of(deps, 159, "beta1") * derived_of(deps, 159, "wl"))


def z_prime(deps) -> sp.Expr:
    """(30): z', the negative root, with (159) (where v_0 + v_λ = 0)."""
    v0_value, vl_value = derived_of(deps, 159, "v0"), derived_of(deps, 159, "vl")
    linear = (a**2 + a * lam - R**2 - a * (v0_value + vl_value) + derived_of(deps, 30, "uniform")) / (a - vl_value)
    linear = tanh_half_form(linear)
    return -linear / 2 - sp.sqrt(linear**2 / 4 + R**2)


def K_of_35(deps) -> sp.Expr:
    """(35): K = −(a + z' − v_λ)/β1."""
    return -(a + derived_of(deps, 30, "zp_uniform") - derived_of(deps, 159, "vl")) / derived_of(deps, 159, "beta1")


def n2_of_34(deps) -> sp.Expr:
    """(34): n² = −Kg/z' with K of (35)."""
    return -derived_of(deps, 35, "K_uniform") * g / derived_of(deps, 30, "zp_uniform")


# The same through (36) and the stable root z.  (35) divides a + z' − v_λ by β1: both are
# O(u²) as u → 0 and the difference cancels completely in double precision; (36) has
# a + w_λ over a + z − v_λ, neither of which cancels for a > 0.  z is the root of (30) that
# (31) pairs with z', each root written without cancellation (pendsym.roots).
def foci_quadratic(deps) -> sp.Poly:
    """(30) of chapter I with v_λ, β1, w_λ of (159): coefficients rational in th(u/2), u, a, R, λ."""
    ends = {vl: derived_of(deps, 159, "vl"), beta1: derived_of(deps, 159, "beta1"), wl: derived_of(deps, 159, "wl")}
    coeffs = []
    for cf in ch1_model.foci_quadratic().all_coeffs():
        numerator, denominator = sp.fraction(sp.together(cf.subs(ends)))
        coeffs.append(sp.collect(tanh_half_form(sp.expand(numerator)), [a, R, lam]) /
                      sp.collect(tanh_half_form(sp.expand(denominator)), [a, R, lam]))
    return sp.Poly(coeffs, z)


def z_positive_root(deps) -> sp.Expr:
    """(30), n°7: z, the positive root, in the form of pendsym.roots."""
    plus, _minus = quadratic_roots(foci_quadratic(deps))
    return plus


def K_of_36(deps) -> sp.Expr:
    """(36): K = (a + w_λ)/(a + z − v_λ) with (159) and z of (30)."""
    ends = {vl: derived_of(deps, 159, "vl"), wl: derived_of(deps, 159, "wl"), z: derived_of(deps, 30, "z_uniform")}
    return ch1_model.K_of_z().subs(ends)


def n2_of_z(deps) -> sp.Expr:
    """(34) with (31): n² = −Kg/z' and z' = −R²/z (z z' = −R²), K of (36): n² = Kgz/R²."""
    product, _sum = ch1_model.vieta()
    n2 = -K * g / zp
    return n2.subs(zp, product / z).subs({K: derived_of(deps, 36, "K_uniform"), z: derived_of(deps, 30, "z_uniform")})


def k_of_foci(_deps) -> sp.Expr:
    """(165): k = K(1 − K) with K = (a + w_λ)/(a + z − v_λ) of (36)."""
    K_36 = (a + wl) / (a + z - vl)
    return sp.factor(sp.simplify(K_36 * (1 - K_36)))


# ================================================================ n°50: the shape of the blade (171)–(174)
def shape(deps) -> sp.Expr:
    """(171): ω y with y = Y(s + v − v_0) + θ(w − w_0) (77), ω = u/λ, (157), (159); x → s."""
    v, w = derived_of(deps, 157, "v"), derived_of(deps, 157, "w")
    y = Y * (s + v - v.subs(s, 0)) + theta * (w - w.subs(s, 0))
    return in_hyperbolic_basis(u / lam * y)


def c_of_shape(deps) -> sp.Expr:
    """(172): c of (171), (ωy/Y − ωs + sh ωs)/(ch ωs − 1), found independent of s."""
    omega_y = derived_of(deps, 171, "shape")
    omega_s = u * s / lam
    c = sp.simplify(((omega_y / Y - omega_s + sp.sinh(omega_s)) / (sp.cosh(omega_s) - 1)).rewrite(sp.exp))
    if sp.simplify(sp.diff(c, s)) != 0:
        raise ValueError("c depends on s")
    return tanh_half_form(c)


def c_principal(deps) -> sp.Expr:
    """(173): c for the principal oscillation, Y = Kθ (65)."""
    return tanh_half_form(derived_of(deps, 172, "c").subs(theta, Y / K))


def c_static(deps) -> sp.Expr:
    """(174): c for the static deviation, θ/Y = (b − v_λ)/(a − a1) (67), a1 = −w_λ (41), (159)."""
    vl_value, wl_value = derived_of(deps, 159, "vl"), derived_of(deps, 159, "wl")
    return tanh_half_form(derived_of(deps, 172, "c").subs(theta, Y * (b - vl_value) / (a + wl_value)))


def static_ends(sign: int):
    """The derive function of Γ_0 − Γ_λ (sign −1) or Γ_0 + Γ_λ (sign +1) of (177) with the static c (174)."""
    def derive(deps):
        c = derived_of(deps, 174, "c")
        Gamma_0, Gamma_lambda = c, c * sp.cosh(u) - sp.sinh(u)
        return tanh_half_form((Gamma_0 - Gamma_lambda) if sign < 0 else (Gamma_0 + Gamma_lambda))
    derive.__doc__ = f"Γ_0 {'−' if sign < 0 else '+'} Γ_λ (177) with the static c (174) (n°52)."
    return derive


# ================================================================ n°51–53: fatigue (175)–(179)
def bending_stress(deps) -> sp.Expr:
    """(175): T' = (mg e/2I)(Yv + θw) (78), I = e³h/12 (the section of (156)), mg = Ee³h u²/(12λ²) by (156)."""
    weight_of_blade = E * e**3 * h * u**2 / (12 * lam**2)
    inertia = e**3 * h / 12
    v, w = derived_of(deps, 157, "v"), derived_of(deps, 157, "w")
    return sp.simplify(weight_of_blade * e / (2 * inertia)) * in_hyperbolic_basis(Y * v + theta * w)


def fatigue_Gamma(deps) -> sp.Expr:
    """(176): Γ = T'/(√(3ET) Y) with T = mg/(eh), i.e. (2λ/(E e u))·T'/Y."""
    return in_hyperbolic_basis(derived_of(deps, 175, "Tprime") * 2 * lam / (E * e * u * Y))


def fatigue_Gamma_at(where: sp.Expr):
    """The derive function of Γ_0 or Γ_λ (177): Γ of (176) at s = 0 or λ."""
    def derive(deps):
        return tanh_half_form(derived_of(deps, 176, "Gamma_f").subs(s, where))
    derive.__doc__ = f"Γ of (176) at s = {where} (177)."
    return derive


def principal_stress(deps) -> sp.Expr:
    """(178): T' for the principal oscillation, Y = Kθ (65)."""
    return in_hyperbolic_basis(derived_of(deps, 175, "Tprime").subs(Y, K * theta))


def bracket_at(where: sp.Expr):
    """The derive function of C_0, C_λ (179): the bracket of (178), T'/(θ√(3ET)), at s = 0 or λ."""
    def derive(deps):
        bracket = derived_of(deps, 178, "Tprime") * 2 * lam / (E * e * u * theta)
        return polynomial_in_K(sp.simplify(bracket.subs(s, where)))
    derive.__doc__ = f"The bracket of (178) at s = {where} (179)."
    return derive


# ================================================================ n°54: stresses of both vibrations (180)–(181)
def end_brackets(K_mode: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """T'/(√(3ET)θ) at s = 0 and s = λ for a mode with Y = K_mode θ (65): (177) with c = U + U1/K_mode (173)."""
    return K_mode * U + U1, U2 - K_mode * U


def modal_stress(at: int, principal: sp.Expr, parasitic: sp.Expr) -> sp.Expr:
    """n°54: T' = √(3ET)[C(K)·y_F − C(K')·y_F']/(z − z'); θ of each mode is its focus ordinate over
    ±(z − z'), and C is the bracket of (179) at the end ``at`` (0 or 1)."""
    return stress_scale * (end_brackets(K)[at] * principal - end_brackets(K_prime)[at] * parasitic) / (z - zp)


def static_launch(at: int):
    """The derive function of (180), T'_0 (at = 0) or T'_λ (at = 1), launch by the static deviation."""
    def derive(_deps):
        """(180): launch by the static deviation (67); A, A' the initial ordinates (27) of F and F'.

        K·A and K'·A' are reduced with K, K' of (36) and β1 of (33) (v_λ, w_λ, β1 eliminated),
        and each bracket C(K)·A is written (U + U1/K)·(K A) as in the memoir.
        """
        theta_0 = Q / weight * (b - vl) / (a + wl)                          # (67), a1 = −w_λ (41)
        beta_0 = Q / weight * (beta1 - vl * (b - vl) / (a + wl))
        beta1_of_33 = -(a + z - vl) * (a + zp - vl) / (a + wl)              # (33)
        K_A, K_prime_A_prime = [sp.factor((a + wl) / (a + focus - vl) * (beta_0 + (a + focus) * theta_0)
                                          .subs(beta1, beta1_of_33)) for focus in (z, zp)]
        if {vl, wl} & (K_A.free_symbols | K_prime_A_prime.free_symbols):
            raise ValueError("K·A depends on the blade")
        principal = (U + U1 / K if at == 0 else U2 / K - U) * K_A * sp.cos(n_principal * t)
        parasitic = (U + U1 / K_prime if at == 0 else U2 / K_prime - U) * K_prime_A_prime * sp.cos(n_parasitic * t)
        return stress_scale * (principal - parasitic) / (z - zp)
    return derive


def shock_launch(at: int):
    """The derive function of (181), T'_0 (at = 0) or T'_λ (at = 1), launch by a shock."""
    def derive(_deps):
        """(181): launch by the shock of a mass m' (n°19–20): θ'_0 of (74), β'_0 from (70), the focus
        velocities y'_0 = β'_0 + (a + z)θ'_0 (27) and the amplitudes y'_0/n (72)."""
        denominator = (a - b) ** 2 + R**2 * (1 + m / m_striking)
        theta_speed = (1 + restitution) * V * (b - a) / denominator                         # (74)
        beta_speed = sp.Symbol("bp")
        beta_speed = sp.solve(sp.Eq((beta_speed + a * theta_speed) * (a - b) + R**2 * theta_speed, 0),
                              beta_speed)[0]                                                  # (70)
        speeds = [sp.factor(beta_speed + (a + focus) * theta_speed) for focus in (z, zp)]
        return modal_stress(at, speeds[0] * sp.sin(n_principal * t) / n_principal,
                            speeds[1] * sp.sin(n_parasitic * t) / n_parasitic)
    return derive


# ================================================================ n°56–57: I_λ (182), J (183)
def inertia(deps) -> sp.Expr:
    """(182): I_λ = (m'/λ)∫ y² ds, y of (77) with Y = K, θ = 1 (n°36, (65)), integrated from (157)."""
    v, w = derived_of(deps, 157, "v"), derived_of(deps, 157, "w")
    y = K * (s + v - v.subs(s, 0)) + (w - w.subs(s, 0))
    integral = integrate_along_blade(sp.expand(y**2))
    return mb * lam**2 / u**2 * polynomial_in_K(sp.expand(integral * u**2 / lam**3))


def inertia_auxiliary(deps) -> sp.Expr:
    """Before (182): ∫_0^λ (Ks − x_0) x'' ds with x = Kv + w (n°56), integrated from (157)."""
    x = x_of_v_w(deps)
    integrand = (K * s - x.subs(s, 0)) * sp.diff(x, s, 2)
    return polynomial_in_K(sp.expand(integrate_along_blade(sp.expand(integrand)) * u / lam)) * lam / u


def s_minus_x(deps) -> sp.Expr:
    """Before (183): s − x = ½∫_0^s (Kφ1 + φ2)² ds (n°37, θ = 1), integrated from (158)."""
    return in_hyperbolic_basis(integrate_along_blade(sp.expand(x_of_phi(deps) ** 2), upper=s) / 2)


def J_of_blade(deps) -> sp.Expr:
    """(183): J = (1/λ)∫_0^λ (s − x) ds (n°37, uniform density m'/λ)."""
    J_value = integrate_along_blade(derived_of(deps, 183, "s_minus_x")) / lam
    return lam * polynomial_in_K(sp.expand(J_value / lam))
