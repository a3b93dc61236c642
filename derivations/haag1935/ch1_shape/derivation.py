"""Haag 1935, chapter I, n°21–25, eqs. (77)–(87): shape, fatigue, energy and suppleness, centre of
flexion, the fork.

Pure SymPy: the shape and the tension from (3), (13), (14); the energies of n°23 by
the series of α = ∫cos φ ds (3) and the integration by parts of n°23 (verified by
differentiation); the geometry of the fork (n°25) and its series in θ.  A step that
uses other Results takes them as ``deps`` (by id).
"""
from __future__ import annotations

import sympy as sp

from .. import ch1_model
from ..common import rid
from ..symbols import (E, Fn, Gn, I_s, K, L, M_of_s, Y, a, alpha, beta, beta1, c_axis, e, epsilon, lam, mg, n, r, s,
                       theta, v, v0, varphi, varphi1, varphi2, vl, w, w0, x_fork, zp)


def pull_integral(expr: sp.Expr, defs: dict) -> sp.Expr:
    """Integrals ∫_0^λ c·f ds with c free of s: c·name when f is one of defs (name → integrand)."""
    def pull(x):
        cst, rest = x.function.as_independent(s, as_Add=False)
        if not rest.has(s):
            (_, lo, hi), = x.limits
            return cst * rest * (hi - lo)
        for name, f in defs.items():
            if sp.expand(rest - f) == 0:
                return cst * name
        return cst * sp.Integral(rest, *x.limits)
    return expr.replace(lambda x: isinstance(x, sp.Integral), pull)


def alpha_series() -> tuple[sp.Expr, sp.Expr]:
    """α = ∫_0^λ cos φ ds (3) to the second order in φ: (λ − ½∫φ² ds, φ(s))."""
    ph = varphi(s)
    ser = sp.series(sp.cos(epsilon * ph), epsilon, 0, 4).removeO()
    return sp.integrate(ser, (s, 0, lam)).subs(epsilon, 1), ph



# ================================================================ n°21–22: (77), (78)
def shape_77(deps):
    """y = ∫_0^s φ ds (3) with φ = Yφ1 + θφ2 (13), φ1 = 1 + v', φ2 = w' (11): (77), x = s."""
    sv = sp.Symbol("sigma", positive=True)
    phi = Y * (1 + v(sv).diff(sv)) + theta * w(sv).diff(sv)
    return sp.expand(sp.integrate(phi, (sv, 0, s)).subs({v(0): v0, w(0): w0}))


def tension_78_M(deps):
    """T' = E(e/2)φ' with φ' of (14)."""
    return E * e / 2 * (Y * v(s) + theta * w(s)) / M_of_s(s)


def tension_78_I(deps):
    """(78) first form with M = EI/(mg) (1)."""
    return sp.factor(deps[rid(78, "T_M")].derived.subs(M_of_s(s), E * I_s / mg))


# ================================================================ n°23: (79)–(82)
def F_79(deps):
    """(79): F_n = ∫(Kφ1 + φ2)^n ds."""
    return sp.Integral((K * varphi1(s) + varphi2(s)) ** n, (s, 0, lam))


def G_79(deps):
    """(79): G_n = ∫(Kv + w)^n/M^{n−1} ds."""
    return sp.Integral((K * v(s) + w(s)) ** n / M_of_s(s) ** (n - 1), (s, 0, lam))


def F2_G2_integrands(deps):
    """The integrands of F2 and G2 (79)."""
    return {Fn(2): deps[rid(79, "F")].derived.subs(n, 2).function,
            Gn(2): deps[rid(79, "G")].derived.subs(n, 2).function}


def pendulum_energy_80(deps):
    """W' = mg[(λ + a) − (α + a cos θ)] (potential energy, Ox downwards), α by (3) to the second
    order, φ by (66): (80)."""
    al, ph = alpha_series()
    pot = mg * ((lam + a) - (al + a * sp.cos(theta)))
    pot = sp.series(pot.subs(theta, epsilon * theta).subs(ph, epsilon * ph), epsilon, 0, 3).removeO().subs(epsilon, 1)
    pot = pot.subs(ph, deps[rid(66, "phi")].derived)
    return sp.factor(pull_integral(pot, F2_G2_integrands(deps)))


def blade_energy_80(deps):
    """W = (mg/2)∫Mφ'² ds with φ' of (66): (80)."""
    dphi = deps[rid(66, "dphi")].derived
    energy = mg / 2 * sp.Integral(sp.factor(M_of_s(s) * dphi**2), (s, 0, lam))
    return sp.factor(pull_integral(energy, F2_G2_integrands(deps)))


def suppleness_80(deps):
    """(80): S = W'/W."""
    return sp.factor(deps[rid(80, "Wp")].derived / deps[rid(80, "W")].derived)


def F2G2_antiderivative(deps) -> tuple[sp.Expr, sp.Expr]:
    """The integrand of F2 + G2 by (79), and the antiderivative K²(s + 2v + vv') + 2K(w + vw') + ww'
    of n°23, verified by differentiation with φ1 = 1 + v', φ2 = w' (11) and v'' = v/M, w'' = w/M (9)."""
    fg = F2_G2_integrands(deps)
    integrand = (fg[Fn(2)] + fg[Gn(2)]).subs({varphi1(s): 1 + v(s).diff(s), varphi2(s): w(s).diff(s)})
    anti = K**2 * (s + 2 * v(s) + v(s) * v(s).diff(s)) + 2 * K * (w(s) + v(s) * w(s).diff(s)) + w(s) * w(s).diff(s)
    eq9 = {v(s).diff(s, 2): v(s) / M_of_s(s), w(s).diff(s, 2): w(s) / M_of_s(s)}
    if sp.simplify(sp.expand(anti.diff(s).subs(eq9) - integrand)) != 0:
        raise ValueError("the antiderivative of n°23 does not differentiate to the integrand")
    return integrand, anti


def F2_plus_G2_81(deps):
    """(81): the antiderivative between 0 and λ with (10) v'_0 = v'_λ = −1, w'_0 = 0, w'_λ = 1,
    w0 = vλ + wλ (16), λ = β1 − vλ + v0 (22)."""
    _, anti = F2G2_antiderivative(deps)
    dvs, dws = sp.Symbol("dv"), sp.Symbol("dw")
    plain = anti.subs({v(s).diff(s): dvs, w(s).diff(s): dws})

    def at(where, dv_value, dw_value):
        return ch1_model.ends(plain.subs({dvs: dv_value, dws: dw_value}).subs(s, where))
    val = at(lam, -1, 1) - at(0, -1, 0)
    val = val.subs(w0, ch1_model.wronskian_at_lambda()).subs(lam, beta1 - vl + v0)
    return sp.expand(val)


def suppleness_82(deps):
    """(82): S = (a + F2)/G2 with F2 = (81) − G2."""
    return sp.expand(deps[rid(80, "S")].derived.subs(Fn(2), deps[rid(81, "F2G2")].derived - Gn(2)))


# ================================================================ n°24–25: (83)–(87)
def centre_of_flexion_83(deps):
    """OF' = α + AF' with α = λ (first order, (85) at θ = 0) and AF' = AG + GF' = a + z'."""
    return deps[rid(85, "alpha")].derived.subs(theta, 0) + a + zp


def fork_84(deps):
    """L² = |CM|² with M = A + r(cos θ, sin θ), C = (c, 0): (84)."""
    ex = sp.expand((alpha + r * sp.cos(theta) - c_axis) ** 2 + (beta + r * sp.sin(theta)) ** 2 - L**2)
    return sp.collect(sp.expand(ex.subs(sp.sin(theta) ** 2, 1 - sp.cos(theta) ** 2)), r)


def alpha_85(deps):
    """α = λ − ½∫φ² ds (3) with φ of (66): (85)."""
    al, ph = alpha_series()
    return sp.expand(pull_integral(al.subs(ph, deps[rid(66, "phi")].derived), F2_G2_integrands(deps)))


def fork_series(deps):
    """(84) with (64), (85) to the second order in θ: (c0(r), c2(r))."""
    ex = deps[rid(84, "geometry")].derived.subs({beta: deps[rid(64, "beta")].derived,
                                                alpha: deps[rid(85, "alpha")].derived})
    ser = sp.expand(sp.series(ex.subs(theta, epsilon * theta), epsilon, 0, 4).removeO().subs(epsilon, 1))
    return ser.coeff(theta, 0), ser.coeff(theta, 2)


def A_fork_86(deps):
    """A = −(coefficient of θ² in (84) with (64), (85))."""
    c0, c2 = fork_series(deps)
    return sp.collect(sp.expand(-c2), r)


def r_fork_86(deps):
    """r = r0 + r2θ² in c0(r) = Aθ² to the second order: (86)."""
    c0, _ = fork_series(deps)
    r0s, r2s = sp.symbols("r_0 r_2")
    Aex = deps[rid(86, "A")].derived
    eq = sp.expand(sp.series((c0.subs(r, r0s + r2s * epsilon * theta**2) - epsilon * theta**2 * Aex.subs(r, r0s)),
                             epsilon, 0, 2).removeO())
    r0 = [x for x in sp.solve(eq.coeff(epsilon, 0), r0s) if sp.simplify(x.subs({lam: 0, c_axis: 0}) - L) == 0][0]
    r2 = sp.solve(eq.coeff(epsilon, 1).subs(r0s, r0), r2s)[0]
    return r0 + sp.factor(r2) * theta**2


def optimum_87(deps):
    """A = 0 with r = L + c − λ and λ − c = x: (87)."""
    return sp.expand(deps[rid(86, "A")].derived.subs(r, L + c_axis - lam).subs(c_axis, lam - x_fork))
