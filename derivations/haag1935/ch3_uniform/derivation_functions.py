"""Haag 1935, chapter III, n°47–49: the functions of the uniform blade, eqs. (156)–(170).

Every form starts from the two-point problem (9)–(10) of chapter I with a
constant M = λ²/u² (156), solved by SymPy dsolve (:func:`pendsym.blade.closed_forms`);
the integrals (79) are integrated from those closed forms, and the recurrences
(162)–(167) come from the memoir's integrations by parts, done symbolically.
Each ``derive`` function takes the built dependencies by id and returns a SymPy
expression; none of them reads a printed form.
"""
from __future__ import annotations

import functools

import sympy as sp

from pendsym import blade

from ..common import rid
from ..symbols import DEFS, E, K, M, Fn, Gam, Gn, e, h, k, lam, mg, n, s, u, x0, xl
from .rational import (from_tanh_half, in_tanh_half, integrate_along_blade, polynomial_in_K, tanh_half_form,
                       with_tanh_half_symbol)


def derived_of(deps, eq: int, name: str) -> sp.Expr:
    """The derived form of the dependency haag1935.eqNNN.name."""
    return deps[rid(eq, name)].derived


# ================================================================ n°47: v, w and U, U1, U2 (156)–(161)
def omega_squared(_deps) -> sp.Expr:
    """(156): ω² = 1/M with M = EI/(mg) (1) and I = e³h/12 for a rectangular section."""
    return sp.simplify(1 / (E * (e**3 * h / 12) / mg))


def u_of_omega(deps) -> sp.Expr:
    """(156): u = λω."""
    return sp.sqrt(derived_of(deps, 156, "omega2")) * lam


@functools.lru_cache(maxsize=1)
def uniform_closed_forms() -> dict:
    """(157)–(158): v, w, φ1, φ2 of (9)–(10) for M = λ²/u² by dsolve, simplified."""
    forms = blade.closed_forms(M, lam)
    return {key: sp.simplify(value.subs(M, lam**2 / u**2)) for key, value in forms.items()}


def closed_form(key: str):
    """The derive function of v, w (157) or φ1, φ2 (158): the dsolve solution for constant M."""
    def derive(_deps):
        return uniform_closed_forms()[key]
    derive.__doc__ = f"{key} of (9)–(10) with constant M = λ²/u² (dsolve)."
    return derive


def end_value(eq: int, name: str, at: sp.Expr):
    """The derive function of an end value (159): the dependency eqNNN.name at s = at."""
    def derive(deps):
        return sp.simplify(derived_of(deps, eq, name).subs(s, at))
    derive.__doc__ = f"{name} of ({eq}) at s = {at} (159)."
    return derive


def beta1(deps) -> sp.Expr:
    """(159): β1 = λ + v_λ − v_0 (17), (22) with the closed-form ends."""
    return sp.simplify(lam + derived_of(deps, 159, "vl") - derived_of(deps, 159, "v0"))


def beta2(deps) -> sp.Expr:
    """(159): β2 = w_λ − w_0 (22)."""
    return sp.simplify(derived_of(deps, 159, "wl") - derived_of(deps, 159, "w0"))


def definition_of(value: sp.Expr):
    """The derive function of a definition of (160) or (163): the definition itself."""
    return lambda _deps: value


def identity_difference(lhs_minus_rhs: sp.Expr):
    """The derive function of an identity (161): the difference of its sides with (156), (160)
    applied, rewritten in e^u (zero when the identity holds)."""
    def derive(_deps):
        return sp.simplify(sp.expand(lhs_minus_rhs.subs(dict(DEFS), simultaneous=True).rewrite(sp.exp)))
    return derive


# ================================================================ n°48: G_n and Γ_n (162)–(166)
def x_of_v_w(deps) -> sp.Expr:
    """n°48: x = Kv + w with v, w of (157)."""
    return K * derived_of(deps, 157, "v") + derived_of(deps, 157, "w")


def first_integral_G(deps) -> sp.Expr:
    """(162): M x'² − x² for x = Kv + w and constant M = λ²/u²; constant along the blade."""
    x = x_of_v_w(deps)
    expr = sp.simplify(lam**2 / u**2 * sp.diff(x, s) ** 2 - x**2)
    if sp.simplify(sp.diff(expr, s)) != 0:
        raise ValueError("M x'^2 - x^2 is not constant")
    return expr


def G_recurrence(_deps) -> sp.Expr:
    """Between (162) and (163): n G_n by parts.

    G_n = ∫ x^{n−1} x''/M^{n−2} ds (x'' = x/M, (9)); the boundary values x'_0 = −K,
    x'_λ = 1 − K from (10); and M x'² = x² + MK² − x_0² (162) under the integral.
    """
    M_constant = sp.Symbol("M_c", positive=True)
    x_prime_0 = K * -1 + 0                 # K v'_0 + w'_0 by (10)
    x_prime_lambda = K * -1 + 1            # K v'_λ + w'_λ by (10)
    boundary = (xl ** (n - 1) * x_prime_lambda - x0 ** (n - 1) * x_prime_0) / M_constant ** (n - 2)
    # ∫ x^{n−2} x'² / M^{n−2} with x'² = (x² + M K² − x0²)/M
    integral = Gn(n) + (M_constant * K**2 - x0**2) / M_constant**2 * Gn(n - 2)
    G_n = sp.Symbol("G_n")
    solution = sp.solve(sp.Eq(G_n, boundary - (n - 1) * integral.subs(Gn(n), G_n)), G_n)[0]
    return sp.expand(n * solution).subs(M_constant, M)


def Gamma_definition(_deps) -> sp.Expr:
    """(163): Γ_n = G_n/(λ(u/λ)^{n−2})."""
    return Gn(n) / (lam * (u / lam) ** (n - 2))


def reduced_end_values(deps) -> tuple[sp.Expr, sp.Expr]:
    """x_0 u/λ and x_λ u/λ from (159)."""
    x_at_0 = K * derived_of(deps, 159, "v0") + derived_of(deps, 159, "w0")
    x_at_lambda = K * derived_of(deps, 159, "vl") + derived_of(deps, 159, "wl")
    return sp.simplify(x_at_0 * u / lam), sp.simplify(x_at_lambda * u / lam)


def Gamma_recurrence(deps) -> sp.Expr:
    """(164): the recurrence of G_n with G_n = λ(u/λ)^{n−2}Γ_n (163), M = λ²/u² and x_0, x_λ of (159)."""
    recurrence = derived_of(deps, 162, "Gn_recurrence")
    xi_0_value, xi_lambda_value = reduced_end_values(deps)
    xi_0, xi_lambda = sp.symbols("xi_0 xi_l")
    scale = lambda m: lam * (u / lam) ** (m - 2)
    r = recurrence.subs(Gn(n - 2), scale(n - 2) * Gam(n - 2))
    r = r.subs({x0: lam / u * xi_0, xl: lam / u * xi_lambda, M: lam**2 / u**2})
    r = sp.powsimp(sp.expand(sp.expand_power_base(sp.expand(r / scale(n)), force=True)), force=True)
    coefficient = sp.factor(r.coeff(Gam(n - 2)))
    rest = sp.factor(sp.expand(r - coefficient * Gam(n - 2)))
    return (tanh_half_form(coefficient.subs(xi_0, xi_0_value)) * Gam(n - 2)
            + rest.subs({xi_0: tanh_half_form(xi_0_value), xi_lambda: tanh_half_form(xi_lambda_value)}))


@functools.lru_cache(maxsize=None)
def Gamma_polynomials(n_max: int, recurrence: sp.Expr, Gamma0: sp.Expr, Gamma1: sp.Expr) -> tuple:
    """(166): Γ_0 … Γ_nmax from Γ_0, Γ_1 (integrated) and the recurrence (164), each a polynomial in k.

    The K-polynomial is rewritten in d = K − 1/2; its odd powers vanish (the symmetry
    K ↔ 1 − K, checked), and d² = 1/4 − k (165).
    """
    d = sp.Symbol("d")
    values = [in_tanh_half(Gamma0), in_tanh_half(Gamma1)]
    recurrence_t = with_tanh_half_symbol(recurrence.subs(Gam(n - 2), sp.Symbol("GPREV")))
    for m in range(2, n_max + 1):
        values.append(sp.cancel(recurrence_t.subs({n: m, sp.Symbol("GPREV"): values[m - 2]}) / m))
    polys = []
    for value in values:
        numerator, denominator = sp.fraction(sp.cancel(value))
        coeffs = dict(sp.Poly(sp.expand(numerator.subs(K, d + sp.Rational(1, 2))), d).terms())
        if any(power[0] % 2 for power, cf in coeffs.items() if sp.simplify(cf) != 0):
            raise ValueError("Γ_n is not symmetric in K ↔ 1 − K")
        in_k = sum(cf * (sp.Rational(1, 4) - k) ** (power[0] // 2) for power, cf in coeffs.items())
        in_k_terms = sp.Poly(sp.expand(in_k), k).terms()
        polys.append(sum(sp.factor(cf / denominator) * k**power[0] for power, cf in in_k_terms))
    return tuple(polys)


def Gamma0_Gamma1(deps) -> tuple[sp.Expr, sp.Expr]:
    """Γ_0, Γ_1 from G_0 = ∫M ds, G_1 = ∫x ds (79) with (157), divided as in (163)."""
    G0 = integrate_along_blade(lam**2 / u**2 + 0 * s)
    G1 = integrate_along_blade(x_of_v_w(deps))
    return sp.simplify(G0 / (lam * (u / lam) ** -2)), sp.simplify(G1 / (lam * (u / lam) ** -1))


def Gamma_n_of(m: int):
    """The derive function of Γ_m (166): the recurrence (164) from Γ_0, Γ_1, as a polynomial in k."""
    def derive(deps):
        Gamma0, Gamma1 = Gamma0_Gamma1(deps)
        poly = Gamma_polynomials(5, derived_of(deps, 164, "recurrence"), Gamma0, Gamma1)[m]
        if m < 2:
            return from_tanh_half(poly)
        return sum(from_tanh_half(poly.coeff(k, j)) * k**j for j in range(0, m // 2 + 1))
    derive.__doc__ = f"Γ_{m} from the recurrence (164), as a polynomial in k."
    return derive


def Gamma_integrand_base(deps) -> sp.Expr:
    """u x/λ in the variable y = ωs − u/2, for x = Kv + w of (157): G_n = ∫ x^n/M^{n−1} ds with
    ds = (λ/u) dy and M = λ²/u² gives Γ_n = (1/u)∫_{−u/2}^{u/2} (u x/λ)^n dy."""
    y = sp.Symbol("y", real=True)
    x_of_y = sp.simplify(x_of_v_w(deps).subs(s, lam * (y + u / 2) / u))
    base = sp.simplify(sp.expand_trig(x_of_y * u / lam))
    return sp.simplify(sp.expand(base.rewrite(sp.exp)))


def Gamma_integral(deps) -> sp.Expr:
    """Footnote of (164): Γ_n = (1/(2^n u))∫_{−u/2}^{u/2} (A ch y + B sh y)^n dy, the bracket from (157)."""
    y = sp.Symbol("y", real=True)
    base = Gamma_integrand_base(deps)
    # u x/λ solves f'' = f in y: A ch y + B sh y, with A, B read off its value and slope at y = 0
    A = sp.simplify(base.subs(y, 0))
    B = sp.simplify(sp.diff(base, y).subs(y, 0))
    if sp.simplify((A * sp.cosh(y) + B * sp.sinh(y) - base).rewrite(sp.exp)) != 0:
        raise ValueError("u x / λ is not A ch y + B sh y")
    A, B = sp.simplify(2 * A), sp.simplify(2 * B)       # Haag writes ½[…]
    return sp.Integral((A * sp.cosh(y) + B * sp.sinh(y)) ** n, (y, -u / 2, u / 2)) / (2**n * u)


def S_p_recurrence(_deps) -> sp.Expr:
    """Footnote of (166): S_p − S_{p−1} + k S_{p−2} for S_p = K^p + L^p, L = 1 − K, k = KL, p symbolic.

    Every term is K^{p−2}·K^j or L^{p−2}·L^j: with A = K^{p−2}, B = L^{p−2} the
    difference is a polynomial in A, B, K, L, reduced with L = 1 − K.
    """
    L, A, B = sp.symbols("L A B")
    S_minus = lambda j: A * K ** (2 - j) + B * L ** (2 - j)      # S_{p−j}
    return sp.expand((S_minus(0) - S_minus(1) + K * L * S_minus(2)).subs(L, 1 - K))


def S_p_leading(_deps) -> sp.Tuple:
    """Footnote of (166): leading coefficients of S_{2q}, S_{2q+1} in (−k), q = 1…6, by the
    recurrence S_p = S_{p−1} − kS_{p−2} from S_0 = 2, S_1 = 1."""
    S_values = [sp.Integer(2), sp.Integer(1)]
    for _ in range(2, 14):
        S_values.append(sp.expand(S_values[-1] - k * S_values[-2]))
    ratios = []
    for q in range(1, 7):
        even, odd = sp.Poly(S_values[2 * q], k), sp.Poly(S_values[2 * q + 1], k)
        if even.degree() != q or odd.degree() != q:
            raise ValueError("degree in k is not q")
        ratios += [even.LC() / (-1) ** q, odd.LC() / (-1) ** q]
    return sp.Tuple(*ratios)


def Gamma_leading(deps) -> sp.Tuple:
    """Footnote of (166): the coefficient of k^p in Γ_{2p+1} (p = 1, 2) from the derived (166)."""
    out = []
    for q, m in ((1, 3), (2, 5)):
        poly = sp.Poly(sp.expand(derived_of(deps, 166, f"Gamma{m}")), k)
        if poly.degree() != q:
            raise ValueError(f"Γ_{m} has degree {poly.degree()} in k")
        out.append(sp.simplify(poly.coeff_monomial(k**q)))
    return sp.Tuple(*out)


# ================================================================ n°49: F_n and F (167)–(170)
def x_of_phi(deps) -> sp.Expr:
    """n°49: x = Kφ1 + φ2 with φ1, φ2 of (158)."""
    return K * derived_of(deps, 158, "phi1") + derived_of(deps, 158, "phi2")


def first_integral_F(deps) -> sp.Expr:
    """Before (167): M x'² − x² + 2Kx for x = Kφ1 + φ2; M x'' = x − K makes it constant."""
    x = x_of_phi(deps)
    M_uniform = lam**2 / u**2
    if sp.simplify((M_uniform * sp.diff(x, s, 2) - x + K).rewrite(sp.exp)) != 0:
        raise ValueError("M x'' = x − K fails")
    expr = M_uniform * sp.diff(x, s) ** 2 - x**2 + 2 * K * x
    return tanh_half_form(sp.simplify(expr.subs(s, 0)))


def F_recurrence(deps) -> sp.Expr:
    """(167): n F_n by parts, n > 1.

    F_n = ∫x^{n−1}(Mx'' + K) ds; x_0 = 0, x_λ = 1 (12); M x'_λ = Kv_λ + w_λ
    (φ1' = v/M, φ2' = w/M); and M x'² = x² − 2Kx + C under the integral.
    """
    C = derived_of(deps, 167, "first_integral")
    M_x_prime_lambda = K * derived_of(deps, 159, "vl") + derived_of(deps, 159, "wl")
    F_n = sp.Symbol("F_n")
    # F_n = K F_{n−1} + [x^{n−1} M x']_0^λ − (n − 1)∫ x^{n−2} M x'² ds, with x_λ^{n−1} = 1, x_0 = 0 (12),
    # and ∫ x^{n−2}(x² − 2Kx + C) = F_n − 2K F_{n−1} + C F_{n−2}
    eq = sp.Eq(F_n, K * Fn(n - 1) + (1 ** (n - 1)) * M_x_prime_lambda
               - (n - 1) * (F_n - 2 * K * Fn(n - 1) + C * Fn(n - 2)))
    # linear in F_n: solve's simplification of the solution (about 15 s on th(u/2), th u) is skipped;
    # tidy below writes each coefficient in its canonical rational form in th(u/2) anyway
    recurrence = sp.expand(n * sp.solve(eq, F_n, simplify=False)[0])
    parts = [recurrence.coeff(Fn(n - 1)), recurrence.coeff(Fn(n - 2))]
    rest = sp.expand(recurrence - parts[0] * Fn(n - 1) - parts[1] * Fn(n - 2))
    tidy = lambda x: sp.factor(sp.collect(sp.expand(tanh_half_form(x)), n))
    return tidy(parts[0]) * Fn(n - 1) + tidy(parts[1]) * Fn(n - 2) + tidy(rest)


def F0_F1(deps) -> tuple[sp.Expr, sp.Expr]:
    """(168): F_0 = ∫ ds, F_1 = ∫ (Kφ1 + φ2) ds (79), integrated from (158)."""
    return lam, integrate_along_blade(x_of_phi(deps))


def F0(deps) -> sp.Expr:
    """(168): F_0 = λ."""
    return F0_F1(deps)[0]


def F_step(recurrence: sp.Expr, m: int, previous: sp.Expr, before_previous: sp.Expr) -> sp.Expr:
    """F_m from F_{m−1}, F_{m−2} by the recurrence (167)."""
    return sp.expand(recurrence.subs(n, m).subs({Fn(m - 1): previous, Fn(m - 2): before_previous}) / m)


@functools.lru_cache(maxsize=4)
def F_list(recurrence: sp.Expr, F0_value: sp.Expr, F1_value: sp.Expr) -> tuple:
    """F_0 … F_4 by the recurrence (167), rational in th(u/2) (F_0, F_1 as given).

    The recurrence is taken with th(u/2) as a symbol and each step cancelled once: the same
    rational functions as :func:`in_tanh_half` of :func:`F_step`, at a tenth of the cost.
    """
    recurrence_t = with_tanh_half_symbol(recurrence)
    out = [F0_value, in_tanh_half(F1_value)]
    for m in (2, 3, 4):
        out.append(sp.cancel(recurrence_t.subs(n, m).subs({Fn(m - 1): out[-1], Fn(m - 2): out[-2]}) / m))
    return (F0_value, F1_value) + tuple(out[2:])


def F_over_lambda(which: str):
    """The derive function of F_1/λ (168), F_2/λ (169) or F/λ = (4KF_3 − F_4)/λ (110), (170)."""
    def derive(deps):
        F0_value, F1_value = F0_F1(deps)
        values = F_list(derived_of(deps, 167, "recurrence"), F0_value, F1_value)
        if which == "F1":
            return sp.expand(polynomial_in_K(F1_value / lam))
        if which == "F2":
            return sp.expand(polynomial_in_K(values[2] / lam))
        return sp.expand(polynomial_in_K((4 * K * values[3] - values[4]) / lam))     # F = 4KF_3 − F_4 (110)
    derive.__doc__ = f"{which}/λ from (167), (168)."
    return derive


def F_in_F1_F2(deps) -> sp.Expr:
    """Before (170): 4F = 4(4KF_3 − F_4) (110) with F_3, F_4 from (167), in terms of F_1 and F_2."""
    recurrence = derived_of(deps, 167, "recurrence")
    F3 = F_step(recurrence, 3, Fn(2), Fn(1))
    F4 = F_step(recurrence, 4, F3, Fn(2))
    expr = sp.expand(4 * (4 * K * F3 - F4))
    return (sum(polynomial_in_K(sp.factor(expr.coeff(f))) * f for f in (Fn(2), Fn(1)))
            + polynomial_in_K(expr.subs({Fn(2): 0, Fn(1): 0})))

