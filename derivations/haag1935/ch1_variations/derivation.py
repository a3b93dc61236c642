"""Haag 1935, chapter I, n°10–15, eqs. (42)–(63): small variations of the period, temperature, g.

Pure SymPy.  (42)–(44) are total differentials of n² = −Kg/z' (34) with K from
(35) or (36) and zz' = −R² (31) (:mod:`..ch1_model`), taken symbol by symbol
(da, dR, dλ, dv0, dvλ, dwλ, dz, dz', dβ1, dK); (46)–(52) solve the two-point problem
satisfied by u = ∂v/∂λ; (53)–(57) are the variation of constants with the
Wronskian w0 (15); (58) substitutes (51), (52), (56), (57) into (44); (60)–(63)
specialise (58).  A step that uses other Results takes them as ``deps`` (by id).
"""
from __future__ import annotations

import functools

import sympy as sp

from .. import ch1_model
from ..common import rid
from ..symbols import (G_2, K, M_lambda, M_of_s, R, W_over_mg, a, alpha_blade, alpha_rod, beta1, beta_t, da, dbeta1,
                       dK, dlambda, dlog_g, dlog_R, dlog_zp, dR, dv0, dvl, dw0, dwl, dz, dzp, epsilon_of_s, g, lam, s,
                       t, v, v0, vl, w, w0, wl, x_of_s, z, zp)

DIFFERENTIALS = {a: da, R: dR, lam: dlambda, v0: dv0, vl: dvl, w0: dw0, wl: dwl, z: dz, zp: dzp, beta1: dbeta1, K: dK}


def total_differential(expr: sp.Expr) -> sp.Expr:
    """Σ ∂expr/∂x dx over Haag's variables (g constant)."""
    return sum(sp.diff(expr, x) * dx for x, dx in DIFFERENTIALS.items())


def dlogT_of_n2(n2: sp.Expr) -> sp.Expr:
    """dT/T = −½ d(n²)/n² for T = 2π/n."""
    return -total_differential(n2) / (2 * n2)


def n2_by_K() -> sp.Expr:
    """(34): n² = −Kg/z' (ch1_model.n2_of_focus divided by K_of_zp·(−g/z') must be 1)."""
    ratio = sp.simplify(ch1_model.n2_of_focus() / (ch1_model.K_of_zp() * (-g / zp)))
    if ratio != 1:
        raise ValueError("(34) does not follow from (28), (31)")
    return -K * g / zp


def zp_of_K() -> sp.Expr:
    """z' from (35): z' = vλ − a − Kβ1."""
    return sp.solve(sp.Eq(K, ch1_model.K_of_zp()), zp)[0]


def z_of_K() -> sp.Expr:
    """z from (36): z = (a + wλ)/K − a + vλ."""
    return sp.solve(sp.Eq(K, ch1_model.K_of_z()), z)[0]


def d_beta1() -> sp.Expr:
    """dβ1 = dλ + dvλ − dv0 from β1 = λ + vλ − v0 (22)."""
    return total_differential(ch1_model.beta1_def())


# ================================================================ n°10: (42)–(45)
def dT_42(deps) -> sp.Expr:
    """(42): dT/T from (34) with dK from (35) (implicit differentiation), z' eliminated by (35)."""
    dK_35 = total_differential(ch1_model.K_of_zp())
    expr = dlogT_of_n2(n2_by_K()).subs(dK, dK_35).subs(dzp, zp * dlog_zp)
    return sp.factor(sp.cancel(expr.subs(zp, zp_of_K())))


def dT_43(deps) -> sp.Expr:
    """(43): dT/T from (34) with dK from (36) and dz from d(zz') = d(−R²) (31); z eliminated by (36)."""
    prod, _ = ch1_model.vieta()
    dz_31 = sp.solve(sp.Eq(total_differential(z * zp), total_differential(prod)), dz)[0]
    dK_36 = total_differential(ch1_model.K_of_z())
    expr = dlogT_of_n2(n2_by_K()).subs(dK, dK_36).subs(dz, dz_31)
    expr = expr.subs({dzp: zp * dlog_zp, dR: R * dlog_R}).subs(zp, -R**2 / z)
    return sp.factor(sp.cancel(expr.subs(z, z_of_K())))


def dT_44(deps) -> sp.Expr:
    """(44): dz'/z' eliminated between (42) and (43); dβ1 by (22)."""
    X = sp.Symbol("X")
    sol = sp.solve([sp.Eq(X, deps[rid(42, "dT")].derived), sp.Eq(X, deps[rid(43, "dT")].derived)], [X, dlog_zp],
                   dict=True)[0]
    return sp.factor(sp.cancel(sol[X].subs(dbeta1, d_beta1())))


def Q_45(deps) -> sp.Expr:
    """(45): a − a1 + K²β1 with a1 = −wλ (41), a + wλ = K(a + z − vλ) (36), Kβ1 = −(a + z' − vλ) (35)."""
    expr = a + wl + K**2 * beta1
    expr = expr.subs(wl, sp.solve(sp.Eq(K, ch1_model.K_of_z()), wl)[0])
    expr = expr.subs(beta1, sp.solve(sp.Eq(K, ch1_model.K_of_zp()), beta1)[0])
    return sp.factor(sp.expand(expr))


# ================================================================ n°11: (46)–(52)
SLOPES = {(v, 0): -1, (v, lam): -1, (w, 0): 0, (w, lam): 1}     # v', w' at s = 0 and s = λ (10)


def end_slope_of_u(end_value) -> sp.Expr:
    """(∂u/∂s)_λ for u = ∂y/∂λ, y = v or w (48): y'(λ; λ) is the constant of (10) for every λ, so
    d/dλ y'_λ = (∂y'/∂s + ∂u/∂s)_λ = 0 with ∂y'/∂s = y'' = y/M (9)."""
    u_slope = sp.Symbol("u'_lambda")
    return sp.solve(sp.Eq(end_value / M_lambda + u_slope, 0), u_slope)[0]


def _u_of_end_conditions(end_value) -> sp.Expr:
    """u = c1 v + c2 w solving (9), with u'_0 = 0 (47) and u'_λ of (48)."""
    c1, c2 = sp.symbols("c_1 c_2")
    eqs = [sp.Eq(c1 * SLOPES[(v, 0)] + c2 * SLOPES[(w, 0)], 0),
           sp.Eq(c1 * SLOPES[(v, lam)] + c2 * SLOPES[(w, lam)], end_slope_of_u(end_value))]
    cs = sp.solve(eqs, [c1, c2], dict=True)[0]
    return cs[c1] * v(s) + cs[c2] * w(s)


def at_end(expr: sp.Expr, where) -> sp.Expr:
    """expr at s = 0 or λ with the slopes of (10), the end values v0 … wλ and M(λ) = Mλ."""
    slopes = {v(s).diff(s): SLOPES[(v, where)], w(s).diff(s): SLOPES[(w, where)]}
    return ch1_model.ends(expr.subs(slopes).subs(s, where)).subs(M_of_s(lam), M_lambda)


def du_ds_46(deps):
    """(46): ∂u/∂s = ∂v'/∂λ, u = ∂v/∂λ: the s-derivative of (49)."""
    return sp.diff(deps[rid(49, "dv_dlam")].derived, s)


def du_ds_at_0_47(deps):
    """(47): (46) at s = 0; w'_0 = 0 (10) makes it vanish."""
    return at_end(deps[rid(46, "du_ds")].derived, 0)


def du_ds_at_lambda_48(deps):
    """(48): (∂u/∂s)_λ from d/dλ v'_λ = 0 (10) and v'' = v/M (9)."""
    return end_slope_of_u(vl)


def dv_dlambda_49(deps):
    """(49): ∂v/∂λ, u with v'_λ = −1 constant, v''_λ = vλ/Mλ."""
    return _u_of_end_conditions(vl)


def dw_dlambda_50(deps):
    """(50): ∂w/∂λ, the same with w'_λ = 1, w''_λ = wλ/Mλ."""
    return _u_of_end_conditions(wl)


def at_0_51(dep: str):
    """(51): (∂y/∂λ) at s = 0, for y = v (dep = (49)) or w ((50))."""
    def derive(deps):
        return ch1_model.ends(deps[dep].derived.subs(s, 0))
    return derive


def at_lambda_52(dep: str, slope):
    """(52): (∂y/∂s + ∂y/∂λ) at s = λ, ∂y/∂s = y'_λ by (10)."""
    def derive(deps):
        return ch1_model.ends(slope + deps[dep].derived.subs(s, lam))
    return derive


def wronskian_dlambda(deps):
    """d/dλ of (16) w0 − vλ − wλ = 0 with (51), (52), reduced by (16)."""
    expr = deps[rid(51, "dw0")].derived - deps[rid(52, "dvl")].derived - deps[rid(52, "dwl")].derived
    return sp.factor(sp.expand(expr).subs(w0, ch1_model.wronskian_at_lambda()))


# ================================================================ n°12: (53)–(57)
def x_ode_53(deps):
    """(53): M x'' − x for (9) with M → M(1 + ε), v → v + x, to the first order in ε and x."""
    eta = sp.Symbol("eta")
    full = M_of_s(s) * (1 + eta * epsilon_of_s(s)) * (v(s) + eta * x_of_s(s)).diff(s, 2) - (v(s) + eta * x_of_s(s))
    first = sp.diff(full, eta).subs(eta, 0)
    return sp.expand((M_of_s(s) * x_of_s(s).diff(s, 2) - x_of_s(s)) - first)


def variation_of_constants(fn):
    """(A', B') for x'' − x/M = −εy'' (53), x = Av + Bw with A'v + B'w = 0, the Wronskian
    vw' − wv' replaced by its value w0 (15)."""
    A_prime, B_prime = sp.symbols("A' B'")
    forcing = -epsilon_of_s(s) * fn(s).diff(s, 2)
    sol = sp.solve([A_prime * v(s) + B_prime * w(s),
                    A_prime * v(s).diff(s) + B_prime * w(s).diff(s) - forcing], [A_prime, B_prime], dict=True)[0]
    wronskian = sp.expand(v(s) * w(s).diff(s) - w(s) * v(s).diff(s))
    out = []
    for x in (A_prime, B_prime):
        num, den = sp.fraction(sp.together(sol[x]))
        den = sp.expand(den)
        if sp.expand(den - wronskian) == 0:
            den = w0
        elif sp.expand(den + wronskian) == 0:
            den = -w0
        else:
            raise ValueError(f"denominator is not the Wronskian: {den}")
        out.append(num / den)
    return tuple(out)


def A_B_55(which: str):
    """(55): A (or B) = ∫_0^s A' (B') with A', B' of the variation of constants for (53)."""
    def derive(deps):
        prime = variation_of_constants(v)[0 if which == "A" else 1]
        return sp.Integral(prime.subs(s, t), (t, 0, s))
    return derive


def homogeneous_part(A_lambda, B_lambda):
    """C of x = Av + (B + C)w: x'(λ) = A_λ v'_λ + (B_λ + C) w'_λ = 0 (A'v + B'w = 0), x'_0 = 0."""
    C = sp.Symbol("C")
    return sp.solve(sp.Eq(A_lambda * SLOPES[(v, lam)] + (B_lambda + C) * SLOPES[(w, lam)], 0), C)[0]


def x_54(deps):
    """(54): x = A v + (B + C) w with A, B of (55) and C from x'(λ) = 0."""
    A, B = deps[rid(55, "A")].derived, deps[rid(55, "B")].derived
    return A * v(s) + (B + homogeneous_part(A.subs(s, lam), B.subs(s, lam))) * w(s)


@functools.lru_cache(maxsize=None)
def x_ends(fn):
    """(x0, xλ) for x = Av + (B + Aλ − Bλ)w (54): A(0) = B(0) = 0, v'(λ) = −1, w'(λ) = 1, w'(0) = 0 (10).

    Remembered per fn: (56) and (57) take the two ends of one solve."""
    A_prime, B_prime = variation_of_constants(fn)
    A_lambda = sp.Integral(A_prime, (s, 0, lam))
    B_lambda = sp.Integral(B_prime, (s, 0, lam))
    C = homogeneous_part(A_lambda, B_lambda)
    return C * w0, A_lambda * vl + (B_lambda + C) * wl


def merge_integrals(expr: sp.Expr) -> sp.Expr:
    """Σ c_i ∫f_i ds → ∫Σ c_i f_i ds (c_i free of s), y'' = y/M (9), w0 = vλ + wλ (16) outside, integrand factored."""
    expr = sp.expand(expr)
    body, rest = sp.S.Zero, sp.S.Zero
    for term in sp.Add.make_args(expr):
        integrals = [f for f in sp.Mul.make_args(term) if isinstance(f, sp.Integral)]
        if integrals:
            body += term / integrals[0] * integrals[0].function
        else:
            rest += term
    body = body.subs({v(s).diff(s, 2): v(s) / M_of_s(s), w(s).diff(s, 2): w(s) / M_of_s(s)})
    out = sp.factor(sp.expand(body))
    return rest + (sp.Integral(out, (s, 0, lam)) if out != 0 else 0)


def d_at_0_56(fn):
    """(56): d(fn)_0 = x_0 of (54)."""
    def derive(deps):
        return merge_integrals(x_ends(fn)[0])
    return derive


def d_at_lambda_57(fn):
    """(57): d(fn)_λ = x_λ of (54) with vλ + wλ = w0 (16)."""
    def derive(deps):
        return merge_integrals(sp.expand(x_ends(fn)[1]).subs(wl, w0 - vl))
    return derive


def wronskian_differential(deps):
    """d(w0 − vλ − wλ) with (56), (57): the integrands cancel."""
    expr = deps[rid(56, "dw0")].derived - deps[rid(57, "dvl")].derived - deps[rid(57, "dwl")].derived
    return merge_integrals(expr)


# ================================================================ n°13–15: (58)–(63)
def P_59(deps):
    """(59): P = (Kv + w)²/M."""
    return (K * v(s) + w(s)) ** 2 / M_of_s(s)


def dT_58(deps):
    """(58): (44) with dv0, dvλ, dw0, dwλ = (51), (52) dλ + (56), (57); w0 = vλ + wλ (16); z by (36) kept."""
    def d(eq, name):
        return deps[rid(eq, name)].derived
    total = {dv0: d(51, "dv0") * dlambda + d(56, "dv0"), dvl: d(52, "dvl") * dlambda + d(57, "dvl"),
             dwl: d(52, "dwl") * dlambda + d(57, "dwl")}
    expr = d(44, "dT").subs(total)
    num, den = sp.fraction(sp.factor(sp.together(expr)))
    num = merge_integrals(sp.expand(num).subs(w0, ch1_model.wronskian_at_lambda()))
    return num / den


def integral_to_G2(expr):
    """Replace ∫c(Kv + w)²/M ds (c free of s) by c·G2 (79)."""
    def replace(integral):
        ratio = sp.factor(integral.function / ((K * v(s) + w(s)) ** 2 / M_of_s(s)))
        if ratio.has(s):
            raise ValueError(f"integrand is not ∝ (Kv + w)²/M: {integral.function}")
        return ratio * G_2
    return expr.replace(lambda e: isinstance(e, sp.Integral), replace)


def dT_60(deps):
    """(60): (58) with da = α'a, dR/R = α', dλ = αλ, ε = β + 4α constant: ∫εP = (β + 4α)G2 (79)."""
    expr = deps[rid(58, "dT")].derived.subs({da: alpha_rod * a, dlog_R: alpha_rod, dlambda: alpha_blade * lam,
                                            epsilon_of_s(s): beta_t + 4 * alpha_blade})
    return integral_to_G2(expr)


def dT_61(deps):
    """(61): (58) with ε = −dg/g (M = EI/(mg)), da = dR = dλ = 0, plus −½dg/g from the factor g of (34)."""
    expr = deps[rid(58, "dT")].derived.subs({da: 0, dlog_R: 0, dlambda: 0, epsilon_of_s(s): -dlog_g})
    g_part = -sp.diff(n2_by_K(), g) * g * dlog_g / (2 * n2_by_K())
    return sp.factor(sp.cancel(integral_to_G2(expr) + g_part))


def G_62(deps):
    """(62): G = 2(dT/T)/(dg/g) from (61)."""
    return sp.factor(sp.cancel(2 * deps[rid(61, "dT")].derived / dlog_g))


def G_63(deps):
    """(63): G2 = 2W/(mg) for θ = 1: W/(mg) = ½∫Mφ'² with φ' = (Kv + w)/M (66) in the principal oscillation."""
    phi_prime = (K * v(s) + w(s)) / M_of_s(s)
    energy = sp.Integral(sp.factor(M_of_s(s) * phi_prime**2 / 2), (s, 0, lam))
    # ∫(Kv + w)²/M = 2·(W/mg): the integrand of the energy is ½(Kv + w)²/M
    ratio = sp.simplify(energy.function / ((K * v(s) + w(s)) ** 2 / M_of_s(s)))
    return deps[rid(62, "G")].derived.subs(G_2, W_over_mg / ratio)
