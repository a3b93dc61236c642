"""Haag 1935, chapter III: the uniform blade, n°47–57, eqs. (156)–(183).

Every derived form starts from the two-point problem (9)–(10) of chapter I
with a constant M = λ²/u² (156), solved by SymPy dsolve
(:func:`pendsym.blade.closed_forms`); the integrals (79) are integrated from
those closed forms, and the recurrences (162)–(167) are obtained by the
integrations by parts of the memoir, done symbolically.  The independent truth
is the numerical blade of :mod:`pendsym.blade` (shooting with mpmath odefun and
mpmath quad of the definitions), at 30 digits with a confirmation at 42.

Page numbers: the footnote of n°51 is cited later in the memoir as "la note de
la page 159"; the other pages of chapter III are not marked in the OCR.
"""
from __future__ import annotations

import functools

import mpmath as mp
import sympy as sp
from sympy.functions.elementary.hyperbolic import HyperbolicFunction

from pendsym import blade as B
from pendsym import verify
from pendsym.result import Evidence, KernelArg, KernelSpec, Reading, Source, Spec
from pendsym.roots import quadratic_roots
from . import ch1_model
from .symbols import (DEFS, K, K_OF_k, E, Fn, Gam, Gn, M, R, T, U, U1, U2, Y, a, a1, b, beta1, c, e, g, k, lam,
                      mb, n, omega, s, theta, u, vl, w0, wl, x0, xl, z, zp)

MEMOIR = "haag1935"
P = MEMOIR
D = dict(DEFS)
TANH, U1X, U2X = D[U], D[U1], D[U2]
READ_VW = Reading("ν, ω (for v, w)", "v, w: the OCR renders Haag's v, w as ν, ω; ω alone is 1/√M of (156)")


def rid(eq: int, name: str) -> str:
    return f"{P}.eq{eq:03d}.{name}"


def src(para: str, eq: str | None, page: int | None = None) -> Source:
    return Source(MEMOIR, para, page, eq)


def defs_u(expr: sp.Expr) -> sp.Expr:
    """Apply (156), (160): ω = u/λ, M = λ²/u², U = th(u/2), U1 = 1/sh u, U2 = 1/th u."""
    return expr.subs(D, simultaneous=True)


# ================================================================ rational form in th(u/2)
_Q = sp.Symbol("Q", positive=True)      # e^{u/2}
_T = sp.Symbol("T_h", positive=True)    # th(u/2)


def in_tanh(expr: sp.Expr) -> sp.Expr:
    """expr (exponentials/hyperbolic functions of multiples of u) as a rational function of th(u/2).

    e^{u} = (1 + t)/(1 − t) with t = th(u/2): sh u, ch u, th u are rational in t.
    """
    ex = hyp_to_exp(expr)
    ex = ex.replace(lambda x: isinstance(x, sp.exp) and sp.simplify(x.args[0] / u).is_number,
                    lambda x: _Q ** (2 * sp.simplify(x.args[0] / u)))
    if ex.has(u) and any(a.has(u) for a in ex.atoms(sp.exp)):
        raise ValueError(f"exponentials not proportional to u: {[x for x in ex.atoms(sp.exp) if x.has(u)]}")
    num, den = sp.fraction(sp.cancel(sp.together(ex)))
    P = sp.Symbol("P_q", positive=True)           # e^u = Q²
    parts = []
    for part in (num, den):
        try:
            poly = sp.Poly(part, _Q)
        except sp.PolynomialError:
            poly = None
        if poly is None or any(m[0] % 2 for m in poly.monoms()):
            return sp.cancel(sp.together(ex).subs(_Q, sp.sqrt((1 + _T) / (1 - _T))))
        parts.append(sum(cf * P ** (m[0] // 2) for m, cf in poly.terms()))
    sub = (1 + _T) / (1 - _T)
    return sp.cancel(sp.together(parts[0].subs(P, sub)) / sp.together(parts[1].subs(P, sub)))


def hyp_to_exp(expr: sp.Expr) -> sp.Expr:
    """Hyperbolic functions rewritten as exponentials (powers are left alone)."""
    return expr.replace(lambda x: isinstance(x, HyperbolicFunction), lambda x: x.rewrite(sp.exp))


def from_tanh(expr: sp.Expr) -> sp.Expr:
    return sp.factor(expr).subs(_T, TANH)


def in_hyperbolic_s(expr: sp.Expr) -> sp.Expr:
    """expr (exponentials of multiples of ωs = us/λ and of u, powers of s) in the basis ch(jωs), sh(jωs),
    with coefficients rational in th(u/2): the memoir's way of writing functions of s."""
    Z = sp.Symbol("Z_s", positive=True)
    w = sp.Symbol("w_s", positive=True)        # ωs

    def split(x):
        A = sp.expand(x.args[0])
        al = sp.expand(A.coeff(s) * lam / u)
        be = sp.expand(A - A.coeff(s) * s)
        if be.has(s) or not al.is_integer:
            raise ValueError(f"exponent not linear in ωs: {A}")
        return Z**al * sp.exp(be)
    g = hyp_to_exp(expr).replace(lambda x: isinstance(x, sp.exp) and x.has(s), split).subs(s, lam * w / u)
    num, den = sp.fraction(sp.cancel(sp.together(g)))
    dp = sp.Poly(den, Z)
    if len(dp.terms()) != 1:
        raise ValueError("denominator depends on s")
    (dz,), dc = dp.terms()[0]
    coeffs = {}
    for (jz,), cf in sp.Poly(sp.expand(num), Z).terms():
        coeffs[jz - dz] = coeffs.get(jz - dz, 0) + cf / dc
    out = sp.S.Zero
    for j in sorted({abs(j) for j in coeffs}):
        cp, cm = coeffs.get(j, 0), coeffs.get(-j, 0)
        if j == 0:
            out += _tidy(cp, w)
            continue
        out += _tidy(cp + cm, w) * sp.cosh(j * w) + _tidy(cp - cm, w) * sp.sinh(j * w)
    return out.subs(w, u * s / lam)


def _tidy(cf, w):
    """A coefficient: polynomial in ωs with coefficients rational in th(u/2)."""
    pol = sp.Poly(sp.expand(cf), w)
    return sum(from_tanh(in_tanh(c)) * w**m for (m,), c in pol.terms())


# ================================================================ n°47: (156)–(161)
@functools.lru_cache(maxsize=1)
def uniform_closed() -> dict:
    """v, w, φ1, φ2 of (9)–(10) for M = λ²/u² by dsolve (pendsym.blade.closed_forms), simplified."""
    cf = B.closed_forms(M, lam)
    return {key: sp.simplify(val.subs(M, lam**2 / u**2)) for key, val in cf.items()}


def _closed(key):
    def derive(_deps):
        f"""{key} of (9)–(10) with constant M = λ²/u² (dsolve)."""
        return uniform_closed()[key]
    return derive


def _at(dep: str, where):
    def derive(deps):
        return sp.simplify(deps[dep].derived.subs(s, where))
    return derive


def beta1_derived(deps):
    """β1 = λ + vλ − v0 (17), (22) with the closed-form ends (159)."""
    return sp.simplify(lam + deps[rid(159, "vl")].derived - deps[rid(159, "v0")].derived)


def beta2_derived(deps):
    """β2 = wλ − w0 (22)."""
    return sp.simplify(deps[rid(159, "wl")].derived - deps[rid(159, "w0")].derived)


def identity_derived(lhs_minus_rhs):
    def derive(_deps):
        """The difference of the two sides of (161) with the definitions (160), rewritten in e^u."""
        return sp.simplify(sp.expand(defs_u(lhs_minus_rhs).rewrite(sp.exp)))
    return derive


# ================================================================ n°48: G_n, (162)–(166)
def x_closed(deps):
    """x = Kv + w (n°48) from (157)."""
    return K * deps[rid(157, "v")].derived + deps[rid(157, "w")].derived


def first_integral_G(deps):
    """M x'² − x² for x = Kv + w, constant M = λ²/u²: constant along the blade (162)."""
    x = x_closed(deps)
    expr = sp.simplify(lam**2 / u**2 * sp.diff(x, s) ** 2 - x**2)
    if sp.simplify(sp.diff(expr, s)) != 0:
        raise ValueError("M x'^2 - x^2 is not constant")
    return expr


def Gn_recurrence(deps):
    """n G_n by parts: G_n = ∫ x^{n−1}x''/M^{n−2} (x'' = x/M, (9)), boundary values x'_0 = −K,
    x'_λ = 1 − K from (10), and M x'² = x² + MK² − x_0² (162) under the integral."""
    Mc = sp.Symbol("M_c", positive=True)           # the constant M
    xp0 = K * -1 + 0                               # K v'_0 + w'_0 by (10)
    xpl = K * -1 + 1                               # K v'_λ + w'_λ by (10)
    boundary = (xl ** (n - 1) * xpl - x0 ** (n - 1) * xp0) / Mc ** (n - 2)
    # ∫ x^{n−2} x'² / M^{n−2} with x'² = (x² + M K² − x0²)/M
    integral = Gn(n) + (Mc * K**2 - x0**2) / Mc**2 * Gn(n - 2)
    Gsym = sp.Symbol("G_n")
    sol = sp.solve(sp.Eq(Gsym, boundary - (n - 1) * integral.subs(Gn(n), Gsym)), Gsym)[0]
    return sp.expand(n * sol).subs(Mc, M)


def _xi(deps):
    """x_0 u/λ and x_λ u/λ from (159)."""
    X0 = K * deps[rid(159, "v0")].derived + deps[rid(159, "w0")].derived
    XL = K * deps[rid(159, "vl")].derived + deps[rid(159, "wl")].derived
    return sp.simplify(X0 * u / lam), sp.simplify(XL * u / lam)


def Gamma_recurrence(deps):
    """(164): the recurrence of n°48 with G_n = λ(u/λ)^{n−2}Γ_n (163), M = λ²/u², x_0, x_λ of (159)."""
    rec = deps[rid(162, "Gn_recurrence")].derived
    xi0, xil = _xi(deps)
    a0, al = sp.symbols("xi_0 xi_l")
    scale = lambda m: lam * (u / lam) ** (m - 2)
    r = rec.subs(Gn(n - 2), scale(n - 2) * Gam(n - 2)).subs({x0: lam / u * a0, xl: lam / u * al, M: lam**2 / u**2})
    r = sp.powsimp(sp.expand(sp.expand_power_base(sp.expand(r / scale(n)), force=True)), force=True)
    coeff = sp.factor(r.coeff(Gam(n - 2)))
    rest = sp.factor(sp.expand(r - coeff * Gam(n - 2)))
    tidy = lambda x: from_tanh(in_tanh(x))
    return tidy(coeff.subs(a0, xi0)) * Gam(n - 2) + rest.subs({a0: tidy(xi0), al: tidy(xil)})


_t = sp.Symbol("t", positive=True)


@functools.lru_cache(maxsize=None)
def _basic_integral(m: int, alpha: sp.Expr, upper: sp.Expr) -> sp.Expr:
    """∫_0^upper t^m e^{αt} dt (α a number)."""
    return sp.integrate(_t**m * sp.exp(alpha * _t), (_t, 0, upper))


def integrate_exp_poly(f: sp.Expr, upper: sp.Expr) -> sp.Expr:
    """∫_0^upper f dt for f a sum of c·t^m·e^{αt + β} (α an integer): term by term.

    Every e^{αt + β} is written Z^α e^β with a symbol Z; f must then be a
    polynomial in t, Z, 1/Z whose coefficients are free of t.
    """
    Z = sp.Symbol("Z_t", positive=True)

    def split(x):
        A = sp.expand(x.args[0])
        alpha = A.coeff(_t)
        beta = sp.expand(A - alpha * _t)
        if beta.has(_t) or not alpha.is_integer:
            raise ValueError(f"exponent not linear in t: {A}")
        return Z**alpha * sp.exp(beta)
    g = sp.expand(f).replace(lambda x: isinstance(x, sp.exp) and x.has(_t), split)
    num, den = sp.fraction(sp.cancel(sp.together(g)))
    dpoly = sp.Poly(den, Z, _t)
    if len(dpoly.terms()) != 1:
        raise ValueError(f"denominator depends on t: {den}")
    (dz, dt), dc = dpoly.terms()[0]
    if dt:
        raise ValueError("t in the denominator")
    total = sp.S.Zero
    for (jz, jt), cf in sp.Poly(sp.expand(num), Z, _t).terms():
        total += cf / dc * _basic_integral(int(jt), sp.Integer(jz - dz), upper)
    return total


def _integrate_blade(expr_s, upper=None):
    """∫_0^{upper or λ} expr ds for an expression in e^{±us/λ} and s (substitution s = λt/u)."""
    f = hyp_to_exp(expr_s).subs(s, lam * _t / u)
    up = u if upper is None else sp.expand(u * upper / lam)
    return integrate_exp_poly(f, up) * lam / u


@functools.lru_cache(maxsize=None)
def _Gamma_list(nmax: int, rec: sp.Expr, G0: sp.Expr, G1: sp.Expr) -> tuple:
    """Γ_0 … Γ_nmax from Γ_0, Γ_1 (integrated) and the recurrence, each as a polynomial in k.

    The K-polynomial is rewritten in d = K − 1/2; its odd powers vanish (symmetry K ↔ 1 − K,
    checked), and d² = 1/4 − k.
    """
    d = sp.Symbol("d")
    out = [in_tanh(G0), in_tanh(G1)]
    rec_t = in_tanh(rec.subs(Gam(n - 2), sp.Symbol("GPREV")))
    for m in range(2, nmax + 1):
        val = sp.cancel(rec_t.subs({n: m, sp.Symbol("GPREV"): out[m - 2]}) / m)
        out.append(val)
    polys = []
    for val in out:
        num, den = sp.fraction(sp.cancel(val))
        pol = sp.Poly(sp.expand(num.subs(K, d + sp.Rational(1, 2))), d)
        coeffs = dict(pol.terms())
        if any(exp[0] % 2 for exp, cf in coeffs.items() if sp.simplify(cf) != 0):
            raise ValueError("Γ_n is not symmetric in K ↔ 1 − K")
        inkk = sum(cf * (sp.Rational(1, 4) - k) ** (exp[0] // 2) for exp, cf in coeffs.items())
        pk = sp.Poly(sp.expand(inkk), k)
        polys.append(sum(sp.factor(cf / den) * k**exp[0] for exp, cf in pk.terms()))
    return tuple(polys)


def Gamma0_1(deps):
    """Γ_0, Γ_1 from G_0 = ∫M ds, G_1 = ∫x ds (79) with (157), divided as in (163)."""
    x = x_closed(deps)
    G0 = _integrate_blade(lam**2 / u**2 + 0 * s)
    G1 = _integrate_blade(x)
    return sp.simplify(G0 / (lam * (u / lam) ** -2)), sp.simplify(G1 / (lam * (u / lam) ** -1))


def Gamma_n(m: int):
    def derive(deps):
        f"""Γ_{m} from the recurrence (164), as a polynomial in k."""
        G0, G1 = Gamma0_1(deps)
        poly = _Gamma_list(5, deps[rid(164, "recurrence")].derived, G0, G1)[m]
        return from_tanh(poly) if m < 2 else sum(from_tanh(poly.coeff(k, j)) * k**j
                                                 for j in range(0, m // 2 + 1))
    return derive


def Gamma_integral(deps):
    """Γ_n as an integral over y = ωs − u/2: G_n = ∫ x^n/M^{n−1} ds with x = Kv + w of (157)."""
    yv = sp.Symbol("y", real=True)
    x = x_closed(deps)
    xs = sp.simplify(x.subs(s, lam * (yv + u / 2) / u))
    # integrand of G_n / (λ (u/λ)^{n−2}) after ds = (λ/u) dy, M = λ²/u²
    base = sp.simplify(sp.expand_trig(xs * u / lam))   # x = (λ/u)·base
    base = sp.simplify(sp.expand(base.rewrite(sp.exp)))
    return sp.Integral(base**n, (yv, -u / 2, u / 2)) / u, base


def Gamma_integral_derived(deps):
    """Footnote of (164): Γ_n = (1/u)∫_{−u/2}^{u/2} (u x/λ)^n dy, the bracket derived from (157)."""
    integral, base = Gamma_integral(deps)
    yv = sp.Symbol("y", real=True)
    # write (u x/λ) as A ch y + B sh y (it solves y'' = y in y): read A, B off the value and slope at 0
    A = sp.simplify(base.subs(yv, 0))
    Bc = sp.simplify(sp.diff(base, yv).subs(yv, 0))
    if sp.simplify((A * sp.cosh(yv) + Bc * sp.sinh(yv) - base).rewrite(sp.exp)) != 0:
        raise ValueError("u x / λ is not A ch y + B sh y")
    A, Bc = sp.simplify(2 * A), sp.simplify(2 * Bc)    # Haag writes ½[…]
    return sp.Integral((A * sp.cosh(yv) + Bc * sp.sinh(yv)) ** n, (yv, -u / 2, u / 2)) / (2**n * u)


def Sp_recurrence(_deps):
    """S_p − S_{p−1} + k S_{p−2} for S_p = K^p + L^p, L = 1 − K, k = KL, p symbolic.

    Every term is K^{p−2}·K^j or L^{p−2}·L^j: with A = K^{p−2}, B = L^{p−2} the
    difference is a polynomial in A, B, K, L, reduced with L = 1 − K.
    """
    L, A, Bp = sp.symbols("L A B")
    S_ = lambda j: A * K ** (2 - j) + Bp * L ** (2 - j)      # S_{p−j}
    expr = S_(0) - S_(1) + K * L * S_(2)
    return sp.expand(expr.subs(L, 1 - K))


def Sp_top(_deps):
    """Leading coefficients of S_{2q}, S_{2q+1} in (−k), q = 1…6, by the recurrence from S_0 = 2, S_1 = 1."""
    Sl = [sp.Integer(2), sp.Integer(1)]
    for q in range(2, 14):
        Sl.append(sp.expand(Sl[-1] - k * Sl[-2]))
    ratios = []
    for q in range(1, 7):
        ev, od = sp.Poly(Sl[2 * q], k), sp.Poly(Sl[2 * q + 1], k)
        if ev.degree() != q or od.degree() != q:
            raise ValueError("degree in k is not q")
        ratios += [ev.LC() / (-1) ** q, od.LC() / (-1) ** q]
    return sp.Tuple(*ratios)


def Gamma_top(deps):
    """Coefficient of k^p in Γ_{2p+1} (p = 1, 2) from the derived (166)."""
    out = []
    for q, m in ((1, 3), (2, 5)):
        G = deps[rid(166, f"Gamma{m}")].derived
        pol = sp.Poly(sp.expand(G), k)
        if pol.degree() != q:
            raise ValueError(f"Γ_{m} has degree {pol.degree()} in k")
        out.append(sp.simplify(pol.coeff_monomial(k**q)))
    return sp.Tuple(*out)


def Gamma_top_printed():
    return sp.Tuple(*[U ** (2 * q) / u * (-1) ** q for q in (1, 2)])


# ================================================================ n°49: F_n, (167)–(170)
def xF_closed(deps):
    """x = Kφ1 + φ2 (n°49) from (158)."""
    return K * deps[rid(158, "phi1")].derived + deps[rid(158, "phi2")].derived


def first_integral_F(deps):
    """M x'² − x² + 2Kx for x = Kφ1 + φ2: M x'' = x − K makes it constant (n°49)."""
    x = xF_closed(deps)
    Mc = lam**2 / u**2
    if sp.simplify((Mc * sp.diff(x, s, 2) - x + K).rewrite(sp.exp)) != 0:
        raise ValueError("M x'' = x − K fails")
    expr = Mc * sp.diff(x, s) ** 2 - x**2 + 2 * K * x
    return sp.factor(in_tanh(sp.simplify(expr.subs(s, 0)))).subs(_T, TANH)


def F_recurrence(deps):
    """n F_n by parts: F_n = ∫x^{n−1}(Mx'' + K) ds, x_0 = 0, x_λ = 1 (12), M x'_λ = Kv_λ + w_λ
    (φ1' = v/M, φ2' = w/M), M x'² = x² − 2Kx + C under the integral; n > 1."""
    C = deps[rid(167, "first_integral")].derived
    ends = K * deps[rid(159, "vl")].derived + deps[rid(159, "wl")].derived   # M x'_λ
    Fs = sp.Symbol("F_n")
    # ∫ x^{n−2}(x² − 2Kx + C) = F_n − 2K F_{n−1} + C F_{n−2}
    eq = sp.Eq(Fs, K * Fn(n - 1) + (1 ** (n - 1)) * ends - (n - 1) * (Fs - 2 * K * Fn(n - 1) + C * Fn(n - 2)))
    rec = sp.expand(n * sp.solve(eq, Fs)[0])
    parts = [rec.coeff(Fn(n - 1)), rec.coeff(Fn(n - 2))]
    rest = sp.expand(rec - parts[0] * Fn(n - 1) - parts[1] * Fn(n - 2))
    tidy = lambda x: sp.factor(sp.collect(sp.expand(from_tanh(in_tanh(x))), n))
    return tidy(parts[0]) * Fn(n - 1) + tidy(parts[1]) * Fn(n - 2) + tidy(rest)


def F01(deps):
    """F_0 = ∫ ds, F_1 = ∫ (Kφ1 + φ2) ds (79), integrated from (158)."""
    return lam, _integrate_blade(xF_closed(deps))


def _F_step(rec, m, prev1, prev2):
    return sp.expand(rec.subs(n, m).subs({Fn(m - 1): prev1, Fn(m - 2): prev2}) / m)


def _poly_K_tanh(expr):
    """expr as a polynomial in K, coefficients rational in th(u/2), written back with tanh."""
    ex = in_tanh(expr)
    num, den = sp.fraction(sp.cancel(ex))
    pol = sp.Poly(sp.expand(num), K)
    return sum(from_tanh(sp.cancel(cf / den)) * K**m[0] for m, cf in pol.terms())


@functools.lru_cache(maxsize=4)
def _F_list(rec, F0, F1):
    out = [F0, F1]
    for m in (2, 3, 4):
        out.append(in_tanh(_F_step(rec, m, out[-1], out[-2])))
    return tuple(out)


def F_derived(which):
    def derive(deps):
        F0, F1 = F01(deps)
        Fl = _F_list(deps[rid(167, "recurrence")].derived, F0, F1)
        if which == "F1":
            return sp.expand(_poly_K_tanh(F1 / lam))
        if which == "F2":
            return sp.expand(_poly_K_tanh(Fl[2] / lam))
        return sp.expand(_poly_K_tanh((4 * K * Fl[3] - Fl[4]) / lam))     # F = 4KF_3 − F_4 (110)
    return derive


def F_intermediate(deps):
    """4F = 4(4KF_3 − F_4) (110) with F_3, F_4 from (167), in terms of F_1 and F_2."""
    rec = deps[rid(167, "recurrence")].derived
    F3 = _F_step(rec, 3, Fn(2), Fn(1))
    F4 = _F_step(rec, 4, F3, Fn(2))
    expr = sp.expand(4 * (4 * K * F3 - F4))
    return sum(_poly_K_tanh(sp.factor(expr.coeff(f))) * f for f in (Fn(2), Fn(1))) + \
        _poly_K_tanh(expr.subs({Fn(2): 0, Fn(1): 0}))


# ================================================================ n°50: shape (171)–(174), (30)
def n50_combination(deps):
    """v_λ² + β1 w_λ of (30) with (159)."""
    return sp.simplify(deps[rid(159, "vl")].derived ** 2 + deps[rid(159, "beta1")].derived * deps[rid(159, "wl")].derived)


def shape_derived(deps):
    """ω y with y = Y(s + v − v0) + θ(w − w0) (77), ω = u/λ, (157), (159); x → s."""
    v, w = deps[rid(157, "v")].derived, deps[rid(157, "w")].derived
    y = Y * (s + v - v.subs(s, 0)) + theta * (w - w.subs(s, 0))
    return in_hyperbolic_s(u / lam * y)


def c_derived(deps):
    """c of (171): (ωy/Y − ωs + sh ωs)/(ch ωs − 1), found independent of s."""
    wy = deps[rid(171, "shape")].derived
    cc = sp.simplify(((wy / Y - u * s / lam + sp.sinh(u * s / lam)) / (sp.cosh(u * s / lam) - 1)).rewrite(sp.exp))
    if sp.simplify(sp.diff(cc, s)) != 0:
        raise ValueError("c depends on s")
    return _poly_theta(cc)


def _poly_theta(expr):
    """expr as A + B·θ/Y (or in K, b, a) with coefficients written in tanh."""
    return from_tanh(in_tanh(expr))


def c_principal(deps):
    """c for the principal oscillation, Y = Kθ (65)."""
    return from_tanh(in_tanh(deps[rid(172, "c")].derived.subs(theta, Y / K)))


def c_static(deps):
    """c for the static deviation: θ/Y = (b − v_λ)/(a − a1) (67), a1 = −w_λ (41), (159)."""
    vlv, wlv = deps[rid(159, "vl")].derived, deps[rid(159, "wl")].derived
    return from_tanh(in_tanh(deps[rid(172, "c")].derived.subs(theta, Y * (b - vlv) / (a + wlv))))


def static_ends(sign):
    def derive(deps):
        """Γ_0 ∓ Γ_λ (177) with the static c (174)."""
        cc = deps[rid(174, "c")].derived
        G0, Gl = cc, cc * sp.cosh(u) - sp.sinh(u)
        return from_tanh(in_tanh((G0 - Gl) if sign < 0 else (G0 + Gl)))
    return derive


# ================================================================ n°51–53: fatigue (175)–(179)
def fatigue_derived(deps):
    """T' = (mg e/2I)(Yv + θw) (78), I = e³h/12 (the section of (156)), mg = Ee³h u²/(12λ²) by (156)."""
    mgv = E * e**3 * sp.Symbol("h") * u**2 / (12 * lam**2)
    I = e**3 * sp.Symbol("h") / 12
    v, w = deps[rid(157, "v")].derived, deps[rid(157, "w")].derived
    return sp.simplify(mgv * e / (2 * I)) * in_hyperbolic_s(Y * v + theta * w)


def fatigue_Gamma(deps):
    """Γ of (176): T'/(√(3ET) Y) with T = mg/(eh), i.e. (2λ/(E e u))·T'/Y."""
    return in_hyperbolic_s(deps[rid(175, "Tprime")].derived * 2 * lam / (E * e * u * Y))


def fatigue_end(where):
    def derive(deps):
        return from_tanh(in_tanh(deps[rid(176, "Gamma_f")].derived.subs(s, where)))
    return derive


def fatigue_principal(deps):
    """T' for the principal oscillation, Y = Kθ (65)."""
    return in_hyperbolic_s(deps[rid(175, "Tprime")].derived.subs(Y, K * theta))


def bracket_end(where):
    def derive(deps):
        """C_0, C_λ: the bracket of (178), T'/(θ√(3ET)), at s = 0 or λ."""
        Cb = deps[rid(178, "Tprime")].derived * 2 * lam / (E * e * u * theta)
        return _poly_K_tanh(sp.simplify(Cb.subs(s, where)))
    return derive


# ================================================================ n°56–57: I_λ (182), J (183)
def I_derived(deps):
    """I_λ = (m'/λ)∫ y² ds, y of (77) with Y = K, θ = 1 (n°36, (65)), integrated from (157)."""
    v, w = deps[rid(157, "v")].derived, deps[rid(157, "w")].derived
    y = K * (s + v - v.subs(s, 0)) + (w - w.subs(s, 0))
    I = _integrate_blade(sp.expand(y**2))
    return mb * lam**2 / u**2 * _poly_K_tanh(sp.expand(I * u**2 / lam**3))


def I_aux_derived(deps):
    """∫_0^λ (Ks − x_0) x'' ds with x = Kv + w (n°56), integrated from (157)."""
    x = x_closed(deps)
    integrand = (K * s - x.subs(s, 0)) * sp.diff(x, s, 2)
    return _poly_K_tanh(sp.expand(_integrate_blade(sp.expand(integrand)) * u / lam)) * lam / u


def s_minus_x_derived(deps):
    """s − x = ½∫_0^s (Kφ1 + φ2)² ds (n°37, θ = 1), integrated from (158)."""
    X = xF_closed(deps)
    return in_hyperbolic_s(_integrate_blade(sp.expand(X**2), upper=s) / 2)


def J_derived(deps):
    """J = (1/λ)∫_0^λ (s − x) ds (n°37, uniform density μ = m'/λ)."""
    sx = deps[rid(183, "s_minus_x")].derived
    Jv = _integrate_blade(sx) / lam
    return lam * _poly_K_tanh(sp.expand(Jv / lam))


# ================================================================ K and n² of the uniform blade (30), (34), (35)
def zp_derived(deps):
    """z' = the negative root of (30) with (159): v0 + vλ = 0."""
    v0v, vlv = deps[rid(159, "v0")].derived, deps[rid(159, "vl")].derived
    comb = deps[rid(30, "uniform")].derived
    pcoef = (a**2 + a * lam - R**2 - a * (v0v + vlv) + comb) / (a - vlv)
    pcoef = from_tanh(in_tanh(pcoef))
    return -pcoef / 2 - sp.sqrt(pcoef**2 / 4 + R**2)


def K_derived(deps):
    """K = −(a + z' − v_λ)/β1 (35)."""
    return -(a + deps[rid(30, "zp_uniform")].derived - deps[rid(159, "vl")].derived) / deps[rid(159, "beta1")].derived


def n2_derived(deps):
    """n² = −Kg/z' (34)."""
    return -deps[rid(35, "K_uniform")].derived * g / deps[rid(30, "zp_uniform")].derived


# ---------------------------------------------------------------- the same through (36) and the stable root z
# (35) divides a + z' − v_λ by β1: both are O(u²) as u → 0 and the difference cancels completely
# in double; (36) has a + w_λ over a + z − v_λ, neither of which cancels for a > 0.  z is the
# root of (30) that (31) pairs with z', each root written without cancellation (pendsym.roots).
def _uniform_quadratic(deps) -> sp.Poly:
    """(30) of ch1_model with v_λ, β1, w_λ of (159): coefficients rational in th(u/2), u, a, R, λ."""
    sub = {vl: deps[rid(159, "vl")].derived, beta1: deps[rid(159, "beta1")].derived,
           wl: deps[rid(159, "wl")].derived}
    coeffs = []
    for cf in ch1_model.foci_quadratic().all_coeffs():
        num, den = sp.fraction(sp.together(cf.subs(sub)))
        coeffs.append(sp.collect(from_tanh(in_tanh(sp.expand(num))), [a, R, lam]) /
                      sp.collect(from_tanh(in_tanh(sp.expand(den))), [a, R, lam]))
    return sp.Poly(coeffs, z)


def z_derived(deps):
    """z, the positive root of (30) for the uniform blade (n°7, n°50), in the form of pendsym.roots."""
    plus, _minus = quadratic_roots(_uniform_quadratic(deps))
    return plus


def K36_derived(deps):
    """K = (a + w_λ)/(a + z − v_λ) (36) with (159) and z of (30)."""
    sub = {vl: deps[rid(159, "vl")].derived, wl: deps[rid(159, "wl")].derived, z: deps[rid(30, "z_uniform")].derived}
    return ch1_model.K_of_z().subs(sub)


def n2_z_derived(deps):
    """n² = −Kg/z' (34) with z' = −R²/z (31) and K of (36): n² = Kgz/R²."""
    prod, _total = ch1_model.vieta()                     # z z' = −R² (31)
    n2_ = -K * g / zp
    return n2_.subs(zp, prod / z).subs({K: deps[rid(36, "K_uniform")].derived, z: deps[rid(30, "z_uniform")].derived})


# ================================================================ independent truth: the numerical blade
LAM = sp.Rational(13, 10)
U_VALUES = {"quick": ("7/10", "43/10"), "full": ("7/10", "43/10", "13")}
K_VALUES = {"quick": ("0.83",), "full": ("0.83", "-0.4")}
DPS, CONFIRM_DPS = 30, 42
TOL = mp.mpf("1e-27")


@functools.lru_cache(maxsize=16)
def blade_solution(uv: str, dps: int = DPS) -> B.BladeSolution:
    """The uniform blade λ = 1.3, M = (λ/u)², solved by shooting (pendsym.blade)."""
    uq = sp.Rational(uv)
    return B.solve(B.Blade(LAM, (LAM / uq) ** 2), dps)


def evaluate(expr: sp.Expr, pt: dict, subs: dict | None = None):
    """expr at the point pt (symbol name → value), at the precision in force."""
    if subs:
        first = {x: v for x, v in subs.items() if isinstance(x, sp.Symbol)}
        expr = expr.subs(first).subs({x: v for x, v in subs.items() if x not in first})
    syms = sorted(expr.free_symbols, key=lambda x: x.name)
    f = verify.lambdify_mp(expr, syms)
    return mp.mpf(f(*[mp.mpf(pt[x.name]) if not isinstance(pt[x.name], int) else pt[x.name] for x in syms]))


def grid(level: str, with_s=False, with_K=True, extra=None):
    pts = []
    for uv in U_VALUES[level]:
        for Kv in (K_VALUES[level] if with_K else ("0",)):
            base = {"_u": uv, "u": str(sp.N(sp.Rational(uv), 60)), "lambda": str(sp.N(LAM, 60)), "K": Kv,
                    "k": str(sp.N(sp.Float(Kv, 60) * (1 - sp.Float(Kv, 60)), 60))}
            for sf in (("0.2", "0.65") if with_s else ("0",)):
                pt = dict(base, s=str(sp.N(sp.Rational(sf) * LAM, 60)))
                pts.append(dict(pt, **(extra or {})))
    return pts


def blade_check(desc: str, truth, points=None, subs_fn=None, with_s=False, with_K=True, extra=None):
    """Compare the derived form (and report the printed form) with truth(sol, pt) of the numerical blade.

    The truth at the first point is recomputed from a 42-digit shooting; the check fails
    unless the two agree to 28 digits.
    """
    def check(result, level):
        pts = points(level) if points else grid(level, with_s, with_K, extra)
        pairs, ppairs = [], []
        for pt in pts:
            sol = blade_solution(pt["_u"])
            with mp.workdps(40):
                t = truth(sol, pt)
                sub = subs_fn(sol, pt) if subs_fn else None
                pairs.append((str(pt), evaluate(result.derived_value, pt, sub), t))
                if result.printed is not None:
                    ppairs.append((str(pt), evaluate(result.printed_value, pt, sub), t))
        with mp.workdps(50):
            t_hi = truth(blade_solution(pts[0]["_u"], CONFIRM_DPS), pts[0])
        digits = verify.truth_digits(pairs[0][2], t_hi)
        note = f"truth at the first point confirmed to {digits:.1f} digits by a {CONFIRM_DPS}-digit shooting"
        if ppairs:
            pv = verify.value_check(truth_desc="", pairs=ppairs, tol=TOL)
            note += f"; printed form: max relative residual {pv.max_residual:.3g}"
        ev = verify.value_check(truth_desc=desc + f" (λ = {LAM}, u ∈ {U_VALUES[level]})", pairs=pairs, tol=TOL,
                                params=(("lambda", str(LAM)),), note=note)
        if ppairs:
            ev = Evidence(**{**ev.__dict__, "printed_agrees": pv.passed})
        if digits < 28:
            ev = Evidence(**{**ev.__dict__, "passed": False})
        return ev
    return check


def proof_zero(statement: str):
    def check(result, level):
        holds = sp.simplify(result.derived) == 0
        return verify.proof(statement=statement, holds=holds, truth_desc="symbolic proof")
    return check


BLADE = "uniform blade M = (λ/u)² solved by shooting (mpmath odefun) and mpmath quad of the definitions"


def _st(sol, pt):
    return sol.state(mp.mpf(pt["s"]))


def _x0xl(sol, pt):
    Kv = mp.mpf(pt["K"])
    return Kv * sol.v0 + sol.w0, Kv * sol.vl + sol.wl


def _Gam_blade(sol, pt, m):
    Kv, lamv, uv = mp.mpf(pt["K"]), mp.mpf(pt["lambda"]), mp.mpf(pt["u"])
    return sol.G(m, Kv) / (lamv * (uv / lamv) ** (m - 2))


# ---------------------------------------------------------------- specific truths
def _G_rec_points(level):
    pts = []
    for pt in grid(level):
        for m in (2, 3, 4, 5):
            pts.append(dict(pt, n=m))
    return pts[: 4 if level == "quick" else len(pts)]


def _G_rec_check(gamma: bool):
    def truth(sol, pt):
        m = pt["n"]
        if gamma:
            return m * _Gam_blade(sol, pt, m)
        return m * sol.G(m, mp.mpf(pt["K"]))

    def subs(sol, pt):
        m = pt["n"]
        X0, XL = _x0xl(sol, pt)
        if gamma:
            return {n: m, Gam(m - 2): sp.Float(str(_Gam_blade(sol, pt, m - 2)), 45)}
        return {n: m, Gn(m - 2): sp.Float(str(sol.G(m - 2, mp.mpf(pt["K"]))), 45),
                x0: sp.Float(str(X0), 45), xl: sp.Float(str(XL), 45)}
    what = "Γ_n = G_n/(λ(u/λ)^{n−2})" if gamma else "G_n"
    return blade_check(f"n·{what} by quadrature of (79) on the {BLADE}; the right side with the quadrature of "
                       f"the lower index and the shot x_0, x_λ; n = 2…5", truth, points=_G_rec_points, subs_fn=subs)


def _Gamma_check(m):
    return blade_check(f"Γ_{m} = G_{m}/(λ(u/λ)^{m - 2}) with G_{m} by quadrature of (79) on the {BLADE}",
                       lambda sol, pt: _Gam_blade(sol, pt, m))


def _Gamma_integral_check(result, level):
    """The integral of the footnote by mpmath quad against Γ_n from G_n by quadrature on the shot blade."""
    pairs = []
    for pt in grid(level)[:2]:
        sol = blade_solution(pt["_u"])
        for m in (2, 3, 5):
            with mp.workdps(40):
                expr = result.derived_value.subs(n, m)
                integ = next(iter(expr.atoms(sp.Integral)))
                yv = integ.limits[0][0]
                f = verify.lambdify_mp(integ.function, (yv, u, K))
                uv, Kv = mp.mpf(pt["u"]), mp.mpf(pt["K"])
                I = mp.quad(lambda y: f(y, uv, Kv), [-uv / 2, 0, uv / 2])
                rest = verify.lambdify_mp(expr.subs(integ, sp.Symbol("I_n")), (sp.Symbol("I_n"), u, K))
                pairs.append((f"n={m}", rest(I, uv, Kv), _Gam_blade(sol, pt, m)))
    return verify.value_check(truth_desc=f"Γ_n from G_n by quadrature of (79) on the {BLADE}; the integral by mpmath quad",
                              pairs=pairs, tol=TOL)


def _Sp_check(result, level):
    holds = sp.simplify(result.derived) == 0
    pairs = []
    with mp.workdps(40):
        for Kv in ("0.3", "-1.7", "2.9"):
            Kv = mp.mpf(Kv)
            kv = Kv * (1 - Kv)
            S_ = lambda q: Kv**q + (1 - Kv) ** q
            for q in (2, 5, 9):
                pairs.append((f"K={Kv},p={q}", S_(q), S_(q - 1) - kv * S_(q - 2)))
    return verify.combine(verify.proof(statement="S_p − S_{p−1} + kS_{p−2} = 0 for symbolic p", holds=holds,
                                       truth_desc="symbolic proof"),
                          verify.value_check(truth_desc="direct powers K^p + (1−K)^p", pairs=pairs, tol=TOL))


def _Sp_top_check(result, level):
    """Leading coefficients from the explicit roots K = (1 ± √(1−4k))/2, expanded by SymPy."""
    r = sp.sqrt(1 - 4 * k)
    ok = True
    for q in range(1, 7):
        for j, m in ((0, 2 * q), (1, 2 * q + 1)):
            Sx = sp.expand(((1 + r) / 2) ** m + ((1 - r) / 2) ** m)
            pol = sp.Poly(Sx, k)
            ok &= pol.degree() == q and sp.simplify(pol.LC() / (-1) ** q - result.derived[2 * (q - 1) + j]) == 0
    return verify.proof(statement="leading coefficients of S_{2q}, S_{2q+1} (q = 1…6) from the explicit roots of "
                        "t² − t + k = 0 agree with the recurrence", holds=bool(ok),
                        truth_desc="SymPy expansion of ((1+√(1−4k))/2)^m + ((1−√(1−4k))/2)^m")


def _Gamma_top_check(result, level):
    """Γ_{2p+1}(K)/k^p → top coefficient as 1/K → 0: the rest is O(1/k) = O(K^{-2})."""
    evs = []
    uv = "43/10"
    for j, (q, m) in enumerate(((1, 3), (2, 5))):
        top = result.derived_value[j]

        def truth(eps, dps, m=m, q=q):
            sol = blade_solution(uv, dps)
            Kv = 1 / eps
            kv = Kv * (1 - Kv)
            return _Gam_blade(sol, {"K": Kv, "lambda": mp.mpf(LAM), "u": mp.mpf(sp.Rational(uv))}, m) / kv**q

        tv = evaluate(top, {"u": str(sp.N(sp.Rational(uv), 50))})
        evs.append(verify.order_check(param="1/K", values=verify.geometric("1e-3", "1e-2", verify.LEVELS[level]),
                                      truth=truth, derived=lambda eps, tv=tv: tv, expected=2, band=0.3,
                                      truth_desc=f"Γ_{m}/k^{q} from G_{m} by quadrature on the {BLADE}, u = 4.3",
                                      params=(("u", "4.3"), ("n", str(m)))))
    return verify.combine(*evs)


def _F_check(m_or_name):
    def truth(sol, pt):
        Kv, lamv = mp.mpf(pt["K"]), mp.mpf(pt["lambda"])
        if m_or_name == "F":
            return (4 * Kv * sol.F(3, Kv) - sol.F(4, Kv)) / lamv
        if m_or_name == 0:
            return sol.F(0, Kv)
        return sol.F(m_or_name, Kv) / lamv
    label = "F = 4KF_3 − F_4 (110)" if m_or_name == "F" else f"F_{m_or_name}"
    return blade_check(f"{label} by quadrature of (79) on the {BLADE}", truth)


def _F_rec_check():
    def pts(level):
        return [dict(pt, n=m) for pt in grid(level) for m in (2, 3, 4)][: 3 if level == "quick" else None]

    def truth(sol, pt):
        return pt["n"] * sol.F(pt["n"], mp.mpf(pt["K"]))

    def subs(sol, pt):
        m, Kv = pt["n"], mp.mpf(pt["K"])
        return {n: m, Fn(m - 1): sp.Float(str(sol.F(m - 1, Kv)), 45), Fn(m - 2): sp.Float(str(sol.F(m - 2, Kv)), 45)}
    return blade_check(f"n F_n by quadrature of (79) on the {BLADE}; right side with F_{{n−1}}, F_{{n−2}} by quadrature",
                       truth, points=pts, subs_fn=subs)


def _F_int_check():
    def truth(sol, pt):
        Kv = mp.mpf(pt["K"])
        return 4 * (4 * Kv * sol.F(3, Kv) - sol.F(4, Kv))

    def subs(sol, pt):
        Kv = mp.mpf(pt["K"])
        return {Fn(1): sp.Float(str(sol.F(1, Kv)), 45), Fn(2): sp.Float(str(sol.F(2, Kv)), 45)}
    return blade_check(f"4(4KF_3 − F_4) by quadrature on the {BLADE}; F_1, F_2 by quadrature", truth, subs_fn=subs)


def _first_integral_check(kind):
    def truth(sol, pt):
        v, dv, w, dw = _st(sol, pt)
        Kv, Mv = mp.mpf(pt["K"]), (mp.mpf(pt["lambda"]) / mp.mpf(pt["u"])) ** 2
        if kind == "G":
            x, xp = Kv * v + w, Kv * dv + dw
            return Mv * xp**2 - x**2
        x = Kv * (1 + dv) + dw
        xp = (Kv * v + w) / Mv           # φ1' = v'' = v/M, φ2' = w/M
        return Mv * xp**2 - x**2 + 2 * Kv * x
    return blade_check(f"the shot v, w at two abscissae on the {BLADE}", truth, with_s=True)


def _shape_check(theta_of):
    """ω y against (77) on the shot blade, Y = 1 and θ from theta_of(pt, sol)."""
    def truth(sol, pt):
        th = theta_of(sol, pt)
        return mp.mpf(pt["u"]) / mp.mpf(pt["lambda"]) * sol.y(mp.mpf(pt["s"]), pt["Y"], th)

    def subs(sol, pt):
        return {Y: sp.Float(pt["Y"], 45), theta: sp.Float(str(theta_of(sol, pt)), 45)}
    return truth, subs


STATIC = {"a": "0.9", "b": "0.35"}


def _theta_static(sol, pt):
    """θ/Y of the static deviation (67) on the shot blade: (b − v_λ)/(a + w_λ)."""
    return (mp.mpf(pt["b"]) - sol.vl) / (mp.mpf(pt["a"]) + sol.wl)


def _c_check(which):
    """c enters only through the shape (171): compare (171) with this c against (77) on the blade."""
    def check(result, level):
        pts = grid(level, with_s=True, extra={"Y": "1", "theta": "0.37", **STATIC})
        pairs = []
        for pt in pts:
            sol = blade_solution(pt["_u"])
            with mp.workdps(40):
                Kv = mp.mpf(pt["K"])
                th = {"c": mp.mpf(pt["theta"]), "principal": 1 / Kv, "static": _theta_static(sol, pt)}[which]
                om, sv = mp.mpf(pt["u"]) / mp.mpf(pt["lambda"]), mp.mpf(pt["s"])
                cv = evaluate(result.derived_value, pt, {theta: sp.Float(str(th), 45)} if which == "c" else None)
                form = om * sv - mp.sinh(om * sv) + cv * (mp.cosh(om * sv) - 1)
                pairs.append((str(pt), form, om * sol.y(sv, 1, th)))
        return verify.value_check(truth_desc=f"ω y of (77) with Y = 1 on the {BLADE}, against (171) with this c",
                                  pairs=pairs, tol=TOL)
    return check


def _fatigue_check(kind):
    """T' of (78) = (mg e/2I)(Yv + θw) with the shot v, w; E = 2.1, e = 0.3 (I = e³h/12, mg by (156))."""
    def truth(sol, pt):
        v, _, w, _ = _st(sol, pt)
        Ev, ev, uv, lamv = mp.mpf(pt["E"]), mp.mpf(pt["e"]), mp.mpf(pt["u"]), mp.mpf(pt["lambda"])
        Yv = mp.mpf(pt["Y"]) if kind != "principal" else mp.mpf(pt["K"]) * mp.mpf(pt["theta"])
        val = Ev * ev * uv**2 / (2 * lamv**2) * (Yv * v + mp.mpf(pt["theta"]) * w)
        if kind == "Gamma":
            return val * 2 * lamv / (Ev * ev * uv * Yv)
        return val
    return blade_check(f"(78) with v, w of the {BLADE}", truth, with_s=True,
                       extra={"E": "2.1", "e": "0.3", "Y": "0.8", "theta": "0.37"})


def _end_fatigue_check(where, kind):
    """Γ_0, Γ_λ, C_0, C_λ from (78) with the shot ends."""
    def truth(sol, pt):
        Kv = mp.mpf(pt["K"])
        uv, lamv = mp.mpf(pt["u"]), mp.mpf(pt["lambda"])
        vv, wv = (sol.v0, sol.w0) if where == 0 else (sol.vl, sol.wl)
        if kind == "Gamma":      # (Yv + θw)·ω/Y with θ/Y = 0.37/0.8
            return uv / lamv * (vv + mp.mpf("0.37") / mp.mpf("0.8") * wv)
        return uv / lamv * (Kv * vv + wv)
    return blade_check(f"ω(Yv + θw)/Y or ω(Kv + w) at the end, shot on the {BLADE}", truth,
                       extra={"Y": "0.8", "theta": "0.37"})


def _static_check(sign):
    def truth(sol, pt):
        uv, lamv = mp.mpf(pt["u"]), mp.mpf(pt["lambda"])
        th = _theta_static(sol, pt)
        G0 = uv / lamv * (sol.v0 + th * sol.w0)
        Gl = uv / lamv * (sol.vl + th * sol.wl)
        return G0 - Gl if sign < 0 else G0 + Gl
    return blade_check(f"ω(v + θw/Y) at both ends, θ/Y = (b − v_λ)/(a + w_λ) (67), on the {BLADE}", truth,
                       extra=STATIC, with_K=False)


def _modes(sol, av, Rv, gv):
    """Normal modes of (25)–(26) with the shot β1, β2, v0, v_λ, w_λ: (z, z', n², K) with K = −n²z'/g (34)."""
    lamv = mp.mpf(sol.blade.length)
    b1, b2 = sol.beta1, sol.beta2
    A = mp.matrix([[1, av], [0, Rv**2]])
    C = mp.matrix([[-1, b2], [av - sol.vl, -(av * (lamv - sol.v0) + sol.vl**2 + b1 * sol.wl)]]) * (gv / b1)
    ev, vecs = mp.eig(mp.inverse(A) * C)
    modes = []
    for i in range(2):
        beta_i, th_i = vecs[0, i], vecs[1, i]
        modes.append((-ev[i].real, (-(beta_i / th_i) - av).real))   # (n², a + z_fixed − a)
    (n2a, zfa), (n2b, zfb) = modes
    # the principal oscillation keeps F' fixed, z' < 0 (n°9)
    (n2, zp_), (n2p, z_) = ((n2a, zfa), (n2b, zfb)) if zfa < 0 else ((n2b, zfb), (n2a, zfa))
    return z_, zp_, n2, -n2 * zp_ / gv


DYN = {"a": "0.9", "R": "0.35", "g": "9.81"}


def _dyn_check(what):
    def truth(sol, pt):
        z_, zp_, n2, Kv = _modes(sol, mp.mpf(pt["a"]), mp.mpf(pt["R"]), mp.mpf(pt["g"]))
        return {"z": z_, "zp": zp_, "K": Kv, "n2": n2, "k": Kv * (1 - Kv)}[what]

    def subs(sol, pt):
        if what != "k":
            return None
        z_, _, _, _ = _modes(sol, mp.mpf(pt["a"]), mp.mpf(pt["R"]), mp.mpf(pt["g"]))
        return {z: sp.Float(str(z_), 45), vl: sp.Float(str(sol.vl), 45), wl: sp.Float(str(sol.wl), 45),
                w0: sp.Float(str(sol.w0), 45)}
    return blade_check(f"normal modes of (25)–(26) (mpmath eig) with β1, β2, v0, v_λ, w_λ of the {BLADE}; "
                       "K = −n²z'/g (34), z' from the mode that keeps F' fixed", truth, subs_fn=subs,
                       with_K=False, extra=DYN)


# ================================================================ n°54: both vibrations, (180)–(181)
# Symbols of n°18–20 and n°54 not in symbols.py (kept local): K', n, n' of the two foci, the
# time t, the force Q of the static launch, the striking mass m' (n°20, not the blade's m' of
# n°56: the memoir uses the same letter), its speed V and the restitution coefficient h.
Kp = sp.Symbol("K'", real=True)                # K of the parasitic vibration (z ↔ z')
n_p, n_s = sp.Symbol("n", positive=True), sp.Symbol("n'", positive=True)
t_ = sp.Symbol("t", real=True)
Q = sp.Symbol("Q", real=True)
mgs = sp.Symbol("mg", positive=True)
V_, h_r = sp.Symbol("V", real=True), sp.Symbol("h", positive=True)
m_p, m_s = sp.Symbol("m", positive=True), sp.Symbol("m'", positive=True)
SQ = sp.sqrt(3 * E * T)


def _ends_stress(Kv):
    """T'/(√(3ET)θ) at s = 0 and s = λ for a mode with Y = K_v θ (65): (177) with c = U + U1/K_v (173)."""
    return Kv * U + U1, U2 - Kv * U


def _modal_stress(at, first, second):
    """T' = √(3ET)[C(K)·y_F − C(K')·y_F']/(z − z') (n°54): θ of each mode is its focus ordinate
    over ±(z − z'); C is the bracket of (179) at the end `at` (0 or 1)."""
    return SQ * (_ends_stress(K)[at] * first - _ends_stress(Kp)[at] * second) / (z - zp)


def static_launch(at):
    def derive(deps):
        """(180): launch by the static deviation (67), A, A' the initial ordinates (27) of F and F'.

        K·A and K'·A' are reduced by code with K, K' of (36) and β1 of (33) (v_λ, w_λ, β1 eliminated),
        and each bracket C(K)·A written (U + U1/K)·(K A) as in the memoir.
        """
        th0 = Q / mgs * (b - vl) / (a + wl)                          # (67), a1 = −w_λ (41)
        be0 = Q / mgs * (beta1 - vl * (b - vl) / (a + wl))
        b1_33 = -(a + z - vl) * (a + zp - vl) / (a + wl)             # (33)
        KA, KpAp = [sp.factor((a + wl) / (a + f - vl) * (be0 + (a + f) * th0).subs(beta1, b1_33)) for f in (z, zp)]
        if {vl, wl} & (KA.free_symbols | KpAp.free_symbols):
            raise ValueError("K·A depends on the blade")
        first = (U + U1 / K if at == 0 else U2 / K - U) * KA * sp.cos(n_p * t_)
        second = (U + U1 / Kp if at == 0 else U2 / Kp - U) * KpAp * sp.cos(n_s * t_)
        return SQ * (first - second) / (z - zp)
    return derive


def shock_launch(at):
    def derive(deps):
        """(181): launch by the shock of a mass m' (n°19–20): θ'_0 of (74), β'_0 from (70), the focus
        velocities y'_0 = β'_0 + (a + z)θ'_0 (27) and amplitudes y'_0/n (72)."""
        D = (a - b) ** 2 + R**2 * (1 + m_p / m_s)
        thp = (1 + h_r) * V_ * (b - a) / D                              # (74)
        bep = sp.solve(sp.Eq((sp.Symbol("bp") + a * thp) * (a - b) + R**2 * thp, 0), sp.Symbol("bp"))[0]   # (70)
        vel = [sp.factor(bep + (a + f) * thp) for f in (z, zp)]
        return _modal_stress(at, vel[0] * sp.sin(n_p * t_) / n_p, vel[1] * sp.sin(n_s * t_) / n_s)
    return derive


LAUNCH = {"a": "0.9", "R": "0.35", "g": "9.81", "b": "0.35", "Q": "0.7", "t": "0.83", "V": "0.4", "h": "0.6",
          "m": "2.5", "m'": "0.3", "E": "2.1", "T": "0.4"}


def _modal_state(sol, pt, shock):
    """(β, θ) at time t by the eigen-decomposition of (25)–(26) with the shot β1, β2, v0, v_λ, w_λ,
    started by the static deviation (67) or by the shock (70), (74)."""
    av, Rv, gv, bv, tv = (mp.mpf(pt[x]) for x in ("a", "R", "g", "b", "t"))
    lamv = mp.mpf(sol.blade.length)
    A = mp.matrix([[1, av], [0, Rv**2]])
    C = mp.matrix([[-1, sol.beta2], [av - sol.vl, -(av * (lamv - sol.v0) + sol.vl**2 + sol.beta1 * sol.wl)]]) * (gv / sol.beta1)
    ev, P = mp.eig(mp.inverse(A) * C)
    Pi = mp.inverse(P)
    if shock:
        D = (av - bv) ** 2 + Rv**2 * (1 + mp.mpf(pt["m"]) / mp.mpf(pt["m'"]))
        thp = (1 + mp.mpf(pt["h"])) * mp.mpf(pt["V"]) * (bv - av) / D
        q0, qp = mp.matrix([0, 0]), mp.matrix([-av * thp - Rv**2 * thp / (av - bv), thp])
    else:
        Qm = mp.mpf(pt["Q"]) / gv          # Q/(mg) with m = 1
        th0 = Qm * (bv - sol.vl) / (av + sol.wl)
        q0, qp = mp.matrix([Qm * (sol.beta1 - sol.vl * (bv - sol.vl) / (av + sol.wl)), th0]), mp.matrix([0, 0])
    w = [mp.sqrt(-ev[i].real) for i in range(2)]
    c0, cp = Pi * q0, Pi * qp
    modal = mp.matrix([c0[i] * mp.cos(w[i] * tv) + cp[i] * mp.sin(w[i] * tv) / w[i] for i in range(2)])
    q = P * modal
    return q[0].real, q[1].real


def _launch_check(at, shock):
    """T'_0 or T'_λ = √(3ET)(u/λ)(Y v + θ w) at the end (78), Y of (23), from the modal solution."""
    def truth(sol, pt):
        be, th = _modal_state(sol, pt, shock)
        Yv = (be + th * sol.vl) / sol.beta1
        vv, wv = (sol.v0, sol.w0) if at == 0 else (sol.vl, sol.wl)
        uv, lamv = mp.mpf(pt["u"]), mp.mpf(pt["lambda"])
        return mp.sqrt(3 * mp.mpf(pt["E"]) * mp.mpf(pt["T"])) * uv / lamv * (Yv * vv + th * wv)

    def subs(sol, pt):
        z_, zp_, n2, Kv = _modes(sol, mp.mpf(pt["a"]), mp.mpf(pt["R"]), mp.mpf(pt["g"]))
        Kpv = (mp.mpf(pt["a"]) + sol.wl) / (mp.mpf(pt["a"]) + zp_ - sol.vl)     # (36) with z ↔ z'
        Kv = (mp.mpf(pt["a"]) + sol.wl) / (mp.mpf(pt["a"]) + z_ - sol.vl)
        n2p = -Kpv * mp.mpf(pt["g"]) / z_                                      # (34) with z ↔ z'
        n2v = -Kv * mp.mpf(pt["g"]) / zp_
        f = lambda x: sp.Float(str(x), 45)
        return {z: f(z_), zp: f(zp_), K: f(Kv), Kp: f(Kpv), n_p: f(mp.sqrt(n2v)), n_s: f(mp.sqrt(n2p)),
                mgs: f(pt["g"]), m_s: f(pt["m'"])}
    what = "shock (70), (74)" if shock else "static deviation (67)"
    return blade_check(f"(78) at the end with (β, θ) at time t of the normal-mode solution of (25)–(26) (mpmath eig), "
                       f"launched by the {what}, on the {BLADE}", truth, subs_fn=subs, with_K=False, extra=LAUNCH)


_K2 = Reading("(U + U_1/K)(b − a − z) cos n't, second term",
              "transcribed as shown, with K; the derivation (n°54: the parasitic vibration has Y = K'θ) gives K' "
              "there, and the memoir's own general formula before (180) has K'U + U_1: a prime probably lost in the OCR",
              certain=False)
_K2l = Reading("(U_2/K − U)(b − a − z) cos n't, second term", _K2.read_as, certain=False)
_NOTE180 = ("Only the second (n't) term differs: the derivation has K' where the text shows K; T and mg stand for "
            "Haag's T = mg/(eh) (n°51) and the weight; the truth uses m = 1.")
_NOTE181 = ("m' is the striking mass of n°20 (not the blade's m' of n°56); h is the restitution coefficient "
            "(not the blade's width).")
_FAC181 = lambda: SQ * (1 + h_r) * V_ / ((a - b) ** 2 + R**2 * (1 + m_p / m_s))
LAUNCH_PRINTED = {
    (180, 0): (lambda: SQ * Q / mgs * ((U + U1 / K) * (b - a - zp) * sp.cos(n_p * t_)
                                      - (U + U1 / K) * (b - a - z) * sp.cos(n_s * t_)) / (z - zp), (_K2,), _NOTE180),
    (180, 1): (lambda: SQ * Q / mgs * ((U2 / K - U) * (b - a - zp) * sp.cos(n_p * t_)
                                      - (U2 / K - U) * (b - a - z) * sp.cos(n_s * t_)) / (z - zp), (_K2l,), _NOTE180),
    (181, 0): (lambda: _FAC181() * ((K * U + U1) * (b * z - a * z + R**2) * sp.sin(n_p * t_) / n_p
                                    - (Kp * U + U1) * (b * zp - a * zp + R**2) * sp.sin(n_s * t_) / n_s) / (z - zp),
               (), _NOTE181),
    (181, 1): (lambda: _FAC181() * ((U2 - K * U) * (b * z - a * z + R**2) * sp.sin(n_p * t_) / n_p
                                    - (U2 - Kp * U) * (b * zp - a * zp + R**2) * sp.sin(n_s * t_) / n_s) / (z - zp),
               (), _NOTE181),
}


# ================================================================ kernels
# The printed forms cancel as u → 0 (1/u² − U1², u − 2 th(u/2) …): the naive kernels lose
# up to 1e24 ulp there.  pendsym.emit.kernels generates piecewise stable forms (series in u,
# a middle Taylor piece, e^{−u}/expm1 forms) and measures them; pendsym.derive withholds any
# kernel over 4 ulp × max(1, κ) (listed in the report with its figures).  K and n² are
# emitted from (36) with the stable root z of (30): through (35) and z' they lose everything
# as u → 0 (a + z' − vλ and β1 are both O(u²)).
KERNELS_READY = True
U_ARG = KernelArg("u", 1e-6, 700.0, log=True)
LAM_ARG = KernelArg("lambda", 1e-3, 10.0, log=True, unit="m")
K_ARG = KernelArg("K", -3.0, 3.0, log=False)
k_ARG = KernelArg("k", -12.0, 0.25, log=False)
CANCEL = ("Printed forms cancel badly as u → 0: 1 − 2U/u, U_1 − 1/u, 1/u² − U_1², U_2/u − U_1² "
          "(each O(u²) or O(1) from O(1/u²) terms); the derived forms are rational in th(u/2) and u and "
          "cancel likewise; series in u are needed below u ≈ 1e-2.")


# the obvious reading of the printed forms in double precision: (156), (160) as written
NAIVE = ((omega, u / lam), (M, lam**2 / u**2), (U, sp.tanh(u / 2)), (U1, 1 / sp.sinh(u)), (U2, 1 / sp.tanh(u)))


def kern(doc, *args, unit="1"):
    return KernelSpec(args=tuple(args), doc=doc + " " + CANCEL, unit=unit, naive_defs=NAIVE)


# K and n² of the suspension: a the distance from the blade's end to the centre of mass, R the
# radius of gyration, λ and u of the blade (a > 0: the direct pendulum, where K > 0 (n°9)).
A_ARG = KernelArg("a", 1e-2, 5.0, log=True, unit="m")
R_ARG = KernelArg("R", 1e-3, 2.0, log=True, unit="m")
G_ARG = KernelArg("g", 9.7, 9.9, log=False, unit="m/s^2")


# ================================================================ the Specs
def specs() -> tuple[Spec, ...]:
    D_ = DEFS
    Dk = DEFS + K_OF_k
    c_def = (c, (U + U1 * theta / Y).subs(D, simultaneous=True))
    T_def = (T, E * e**2 * u**2 / (12 * lam**2))
    x0_def = (x0, (K * lam * U / u + lam * U1 / u).subs(D, simultaneous=True))
    a1_def = (a1, -lam / u * D[U2])
    h, mg = sp.Symbol("h", positive=True), sp.Symbol("mg", positive=True)
    n47, n48, n49 = "n°47", "n°48", "n°49"
    fv = lambda key: blade_check(f"{key} shot on the {BLADE}", lambda sol, pt, key=key: getattr(sol, key)(mp.mpf(pt["s"])),
                                 with_s=True, with_K=False)
    fe = lambda key: blade_check(f"{key} shot on the {BLADE}", lambda sol, pt, key=key: getattr(sol, key), with_K=False)
    return (
        # ---------------------------------------------------------------- n°47
        Spec(rid(156, "omega2"), "ω² = 1/M for a rectangular blade", src(n47, "156"), r"\omega^2",
             lambda d: sp.simplify(1 / (E * (e**3 * h / 12) / mg)), printed=lambda: 12 * mg / (E * e**3 * h),
             check=lambda r, lv: verify.proof(statement="1/M with M = EI/(mg) (1), I = e³h/12",
                                              holds=sp.simplify(r.derived - r.printed) == 0, truth_desc="exact algebra"),
             note="I = e³h/12 (rectangular section of thickness e, width h) is implied by (156), not stated."),
        Spec(rid(156, "u"), "u = λω", src(n47, "156"), "u",
             lambda d: sp.sqrt(d[rid(156, "omega2")].derived) * lam, deps=(rid(156, "omega2"),),
             printed=lambda: 2 * lam / e * sp.sqrt(3 * mg / (E * e * h)),
             check=lambda r, lv: verify.proof(statement="λ√(ω²)", holds=sp.simplify(r.derived - r.printed) == 0,
                                              truth_desc="exact algebra")),
        Spec(rid(157, "v"), "v for the uniform blade", src(n47, "157"), "v", _closed("v"),
             printed=lambda: lam * sp.sinh(u / 2 - omega * s) / (u * sp.cosh(u / 2)), readings=(READ_VW,),
             check=fv("v"), defs=D_),
        Spec(rid(157, "w"), "w for the uniform blade", src(n47, "157"), "w", _closed("w"),
             printed=lambda: lam * sp.cosh(omega * s) / (u * sp.sinh(u)), readings=(READ_VW,),
             check=fv("w"), defs=D_),
        Spec(rid(158, "phi1"), "φ1 = 1 + v'", src(n47, "158"), r"\varphi_1", _closed("phi1"),
             printed=lambda: 1 - sp.cosh(u / 2 - omega * s) / sp.cosh(u / 2), check=fv("phi1"), defs=D_),
        Spec(rid(158, "phi2"), "φ2 = w'", src(n47, "158"), r"\varphi_2", _closed("phi2"),
             printed=lambda: sp.sinh(omega * s) / sp.sinh(u), check=fv("phi2"), defs=D_),
        Spec(rid(160, "U"), "U = th(u/2)", src(n47, "160"), "U", lambda d: sp.tanh(u / 2), definition=True),
        Spec(rid(160, "U1"), "U1 = 1/sh u", src(n47, "160"), "U_1", lambda d: 1 / sp.sinh(u), definition=True),
        Spec(rid(160, "U2"), "U2 = 1/th u", src(n47, "160"), "U_2", lambda d: 1 / sp.tanh(u), definition=True),
        Spec(rid(159, "v0"), "v_0", src(n47, "159"), "v_0", _at(rid(157, "v"), 0), deps=(rid(157, "v"),),
             printed=lambda: lam * U / u, check=fe("v0"), defs=D_, readings=(READ_VW,),
             kernel=kern("v_0 = λ th(u/2)/u.", LAM_ARG, U_ARG, unit="m")),
        Spec(rid(159, "vl"), "v_λ", src(n47, "159"), r"v_\lambda", _at(rid(157, "v"), lam), deps=(rid(157, "v"),),
             printed=lambda: -lam * U / u, check=fe("vl"), defs=D_),
        Spec(rid(159, "w0"), "w_0", src(n47, "159"), "w_0", _at(rid(157, "w"), 0), deps=(rid(157, "w"),),
             printed=lambda: lam / u * U1, check=fe("w0"), defs=D_, readings=(READ_VW,),
             kernel=kern("w_0 = λ/(u sh u).", LAM_ARG, U_ARG, unit="m")),
        Spec(rid(159, "wl"), "w_λ", src(n47, "159"), r"w_\lambda", _at(rid(157, "w"), lam), deps=(rid(157, "w"),),
             printed=lambda: lam / u * U2, check=fe("wl"), defs=D_, readings=(READ_VW,),
             kernel=kern("w_λ = λ/(u th u).", LAM_ARG, U_ARG, unit="m")),
        Spec(rid(159, "beta1"), "β1 = λ + v_λ − v_0", src(n47, "159"), r"\beta_1", beta1_derived,
             deps=(rid(159, "v0"), rid(159, "vl")), printed=lambda: lam * (1 - 2 * U / u), check=fe("beta1"), defs=D_,
             kernel=kern("β1 = λ(1 − 2U/u) ~ λu²/12 as u → 0.", LAM_ARG, U_ARG, unit="m")),
        Spec(rid(159, "beta2"), "β2 = w_λ − w_0", src(n47, "159"), r"\beta_2", beta2_derived,
             deps=(rid(159, "w0"), rid(159, "wl")), printed=lambda: lam * U / u, check=fe("beta2"), defs=D_),
        Spec(rid(161, "sum"), "U2 = U + U1", src(n47, "161"), r"U_2 - U - U_1", identity_derived(U2 - U - U1),
             printed=lambda: sp.S.Zero, check=proof_zero("th(u/2) + 1/sh u − 1/th u = 0 (exponential form)")),
        Spec(rid(161, "square"), "1 − U² = 2UU1", src(n47, "161"), r"1 - U^2 - 2UU_1",
             identity_derived(1 - U**2 - 2 * U * U1), printed=lambda: sp.S.Zero,
             check=proof_zero("1 − th²(u/2) − 2 th(u/2)/sh u = 0 (exponential form)")),
        Spec(rid(161, "difference"), "U2² − U1² = 1", src(n47, "161"), r"U_2^2 - U_1^2 - 1",
             identity_derived(U2**2 - U1**2 - 1), printed=lambda: sp.S.Zero,
             check=proof_zero("coth²u − csch²u − 1 = 0 (exponential form)")),
        # ---------------------------------------------------------------- n°48
        Spec(rid(162, "first_integral"), "M x'² − x² is constant for x = Kv + w", src(n48, "162"),
             r"Mx'^2 - x^2", first_integral_G, deps=(rid(157, "v"), rid(157, "w")),
             printed=lambda: M * K**2 - x0**2, defs=D_ + (x0_def,), check=_first_integral_check("G"),
             note="x_0 = Kv_0 + w_0 with (159); x'_0 = −K by (10)."),
        Spec(rid(162, "Gn_recurrence"), "Recurrence of G_n (between (162) and (163))", src(n48, "162–163"),
             r"nG_n", Gn_recurrence, printed=lambda: (n - 1) * (x0**2 - M * K**2) / M**2 * Gn(n - 2)
             + ((1 - K) * xl ** (n - 1) + K * x0 ** (n - 1)) / M ** (n - 2), check=_G_rec_check(False), defs=D_,
             note="Unnumbered in the memoir; holds for any constant M."),
        Spec(rid(163, "Gamma"), "G_n = λ(u/λ)^{n−2}Γ_n", src(n48, "163"), r"\Gamma_n",
             lambda d: Gn(n) / (lam * (u / lam) ** (n - 2)), definition=True),
        Spec(rid(164, "recurrence"), "Recurrence of Γ_n", src(n48, "164"), r"n\Gamma_n", Gamma_recurrence,
             deps=(rid(162, "Gn_recurrence"), rid(159, "v0"), rid(159, "vl"), rid(159, "w0"), rid(159, "wl")),
             printed=lambda: (n - 1) * U1 * (U1 + 2 * k * U) * Gam(n - 2)
             + (K * (U1 + K * U) ** (n - 1) + (1 - K) * (U1 + (1 - K) * U) ** (n - 1)) / u,
             readings=(Reading("|U_1 + (1-K)U|^{n-1}", "(U_1 + (1 − K)U)^{n−1}: bars are OCR for brackets"),),
             check=_G_rec_check(True), defs=Dk),
        Spec(rid(165, "k"), "k = K(1 − K) in terms of the foci", src(n48, "165"), "k",
             lambda d: sp.factor(sp.simplify(((a + wl) / (a + z - vl)) * (1 - (a + wl) / (a + z - vl)))),
             printed=lambda: (a - a1) * (z - w0) / (a + z - vl) ** 2,
             defs=((a1, -wl), (w0, vl + wl)), check=_dyn_check("k"),
             note="Derived from K of (36); compared under a1 = −w_λ (41) and w_0 = v_λ + w_λ (16)."),
        Spec(rid(166, "Gamma_integral"), "Γ_n as an integral (footnote of n°48)", src(n48, "footnote of (164)"),
             r"\Gamma_n", Gamma_integral_derived, deps=(rid(157, "v"), rid(157, "w")),
             printed=lambda: sp.Integral((sp.cosh(sp.Symbol("y", real=True)) / sp.sinh(u / 2)
                                          + (1 - 2 * K) * sp.sinh(sp.Symbol("y", real=True)) / sp.cosh(u / 2)) ** n,
                                         (sp.Symbol("y", real=True), -u / 2, u / 2)) / (2**n * u),
             check=_Gamma_integral_check, defs=D_),
        *[Spec(rid(166, f"Gamma{m}"), f"Γ_{m}", src(n48, "166"), rf"\Gamma_{m}", Gamma_n(m),
               deps=(rid(164, "recurrence"), rid(157, "v"), rid(157, "w")), printed=pr, check=_Gamma_check(m),
               defs=D_, kernel=kern(f"Γ_{m}(u, k), polynomial in k = K(1 − K).", U_ARG, k_ARG) if m >= 2 else None,
               note=("Only the k⁰ term differs from the derivation: derived − printed = (1/(5u))·4(U_1^4 − U_1^3)."
                     if m == 5 else ""),
               readings=rd)
          for m, pr, rd in (
              (1, lambda: 1 / u, ()),
              (2, lambda: (U1**2 + U2 / u) / 2 + k * U * (U1 - 1 / u), ()),
              (3, lambda: (sp.Rational(1, 3) + U1**2 - k * U**2) / u, ()),
              (4, lambda: sp.Rational(3, 8) * U1**4 + sp.Rational(5, 8) / u * U1**2 * U2 + U2 / (4 * u)
               + k * U / 2 * (3 * U1**3 - (2 * U**2 + 3 * U1 * U2) / u)
               + k**2 * U**2 / 2 * (3 * U1**2 + (U - 3 * U1) / u), ()),
              (5, lambda: (U2**4 + 4 * U1**3 + sp.Rational(4, 3) * U1**2) / (5 * u)
               - k * U / u * (U**3 - 2 * U * U1**2 + sp.Rational(8, 3) * U1) + k**2 * U**4 / u,
               (Reading("\\frac{1}{5u}(U_2^4 + 4U_1^3 + \\frac43 U_1^2)",
                        "transcribed as shown, 4U_1^3; the derivation gives 4U_1^4 (an exponent 4 read as 3 "
                        "by the OCR, or a misprint)", certain=False),)))],
        Spec(rid(166, "Sp_recurrence"), "S_p = S_{p−1} − kS_{p−2} (footnote of (166))", src(n48, "footnote of (166)"),
             r"S_p - S_{p-1} + kS_{p-2}", Sp_recurrence, printed=lambda: sp.S.Zero, check=_Sp_check),
        Spec(rid(166, "Sp_top"), "Leading terms 2(−k)^p of S_{2p}, (2p+1)(−k)^p of S_{2p+1}",
             src(n48, "footnote of (166)"), r"(\mathrm{lc}\,S_{2q}, \mathrm{lc}\,S_{2q+1})_{q=1..6}/(-1)^q", Sp_top,
             printed=lambda: sp.Tuple(*[x for q in range(1, 7) for x in (2, 2 * q + 1)]), check=_Sp_top_check,
             note="Shown for p = 1…6 (the memoir's claim is for every p)."),
        Spec(rid(166, "Gamma_top"), "Leading term U^{2p}(−k)^p/u of Γ_{2p+1}", src(n48, "footnote of (166)"),
             r"(\mathrm{lc}_k\Gamma_3, \mathrm{lc}_k\Gamma_5)", Gamma_top,
             deps=(rid(166, "Gamma3"), rid(166, "Gamma5")), printed=Gamma_top_printed, check=_Gamma_top_check,
             defs=D_, note="Shown for p = 1, 2 (the list (166)); the memoir claims every p."),
        # ---------------------------------------------------------------- n°49
        Spec(rid(167, "first_integral"), "M x'² = x² − 2Kx + (KU + U1)² for x = Kφ1 + φ2", src(n49, "n°49 (before 167)"),
             r"Mx'^2 - x^2 + 2Kx", first_integral_F, deps=(rid(158, "phi1"), rid(158, "phi2")),
             printed=lambda: (K * U + U1) ** 2, check=_first_integral_check("F"), defs=D_),
        Spec(rid(167, "recurrence"), "Recurrence of F_n", src(n49, "167"), r"nF_n", F_recurrence,
             deps=(rid(167, "first_integral"), rid(159, "vl"), rid(159, "wl")),
             printed=lambda: (2 * n - 1) * K * Fn(n - 1) - (n - 1) * (K * U + U1) ** 2 * Fn(n - 2)
             + lam / u * (U2 - K * U), check=_F_rec_check(), defs=D_),
        Spec(rid(168, "F0"), "F_0 = λ", src(n49, "168"), "F_0", lambda d: F01(d)[0],
             deps=(rid(158, "phi1"), rid(158, "phi2")), printed=lambda: lam, check=_F_check(0), defs=D_),
        Spec(rid(168, "F1"), "F_1/λ", src(n49, "168"), r"F_1/\lambda", F_derived("F1"),
             deps=(rid(167, "recurrence"), rid(158, "phi1"), rid(158, "phi2")),
             printed=lambda: U / u + K * (1 - 2 * U / u), check=_F_check(1), defs=D_,
             kernel=kern("F_1/λ = U/u + K(1 − 2U/u).", U_ARG, K_ARG)),
        Spec(rid(169, "F2"), "F_2/λ", src(n49, "169"), r"F_2/\lambda", F_derived("F2"),
             deps=(rid(167, "recurrence"), rid(158, "phi1"), rid(158, "phi2")),
             printed=lambda: (U2 / u - U1**2) / 2 + K * U * (1 / u - U1) + K**2 * (1 + U * U1 - 3 * U / u),
             check=_F_check(2), defs=D_, kernel=kern("F_2/λ.", U_ARG, K_ARG)),
        Spec(rid(170, "intermediate"), "4F in terms of F_1, F_2", src(n49, "before (170)"), "4F", F_intermediate,
             deps=(rid(167, "recurrence"),),
             printed=lambda: 3 * Fn(2) * (2 * K**2 * (3 - U * U1) + 2 * K * U * U1 + U1**2)
             - 6 * Fn(1) * K * (K * U + U1) ** 2 + lam / u * (U2 - K * U) * (3 * K - 1),
             check=_F_int_check(), defs=D_, note="F = 4KF_3 − F_4 is the function of (110)."),
        Spec(rid(170, "F"), "F/λ = (4KF_3 − F_4)/λ", src(n49, "170"), r"F/\lambda", F_derived("F"),
             deps=(rid(167, "recurrence"), rid(158, "phi1"), rid(158, "phi2")),
             printed=lambda: ((U2 / u * (3 * U1**2 - 2) - 3 * U1**3) / 8
                              + K / 2 * ((2 * U2 + U1 - 3 * U * U1**2) / u - 3 * U * U1**3)
                              + 3 * K**2 / 2 * (U / u * (1 + 3 * U1**2) + 3 * U1**2 * (U * U1 - 1))
                              + 3 * K**3 * U * ((1 + U * U1) / u + U1 * (U * U1 - 2))
                              + 3 * K**4 * (-U / (2 * u) * (7 + U * U1) + 1 + 2 * U * U1 - U**2 * U1**2 / 2)),
             check=_F_check("F"), defs=D_, kernel=kern("F/λ of (110), (170).", U_ARG, K_ARG),
             readings=(Reading("\\frac18[\\frac{U_2}{u}(3U_1^2 - 2) - 3U_1^3]",
                               "transcribed as shown, −3U_1^3; the derivation gives −3U_1^4 (the same exponent "
                               "slip as in Γ_5 of (166): OCR or misprint)", certain=False),),
             note="Only the K⁰ term differs from the derivation: derived − printed = −(3/8)(U_1^4 − U_1^3)."),
        # ---------------------------------------------------------------- n°50
        Spec(rid(30, "uniform"), "v_λ² + β1 w_λ for the uniform blade (n°50)", src("n°50", "30"),
             r"v_\lambda^2 + \beta_1 w_\lambda", n50_combination, deps=(rid(159, "vl"), rid(159, "beta1"), rid(159, "wl")),
             printed=lambda: lam**2 / u**2 * (u * U2 - 1), defs=D_,
             readings=(Reading("v_λ^2 + β_1 v_λ", "v_λ² + β1 w_λ, the combination of (30)", certain=False),),
             check=blade_check(f"v_λ² + β1 w_λ shot on the {BLADE}", lambda sol, pt: sol.vl**2 + sol.beta1 * sol.wl,
                               with_K=False)),
        Spec(rid(30, "zp_uniform"), "z' (negative root of (30)) for the uniform blade", src("n°50", "30"), "z'",
             zp_derived, deps=(rid(159, "v0"), rid(159, "vl"), rid(30, "uniform")), check=_dyn_check("zp"), defs=D_),
        Spec(rid(35, "K_uniform"), "K of (35) for the uniform blade", src("n°50", "35"), "K", K_derived,
             deps=(rid(30, "zp_uniform"), rid(159, "vl"), rid(159, "beta1")), check=_dyn_check("K"), defs=D_),
        Spec(rid(34, "n2_uniform"), "n² = −Kg/z' for the uniform blade", src("n°50", "34"), "n^2", n2_derived,
             deps=(rid(35, "K_uniform"), rid(30, "zp_uniform")), check=_dyn_check("n2"), defs=D_),
        Spec(rid(30, "z_uniform"), "z (positive root of (30)) for the uniform blade, without cancellation",
             src("n°50", "30"), "z", z_derived, deps=(rid(159, "vl"), rid(159, "beta1"), rid(159, "wl")),
             check=_dyn_check("z"), defs=D_),
        Spec(rid(36, "K_uniform"), "K of (36) for the uniform blade", src("n°50", "36"), "K", K36_derived,
             deps=(rid(30, "z_uniform"), rid(159, "vl"), rid(159, "wl")), check=_dyn_check("K"), defs=D_,
             kernel=kern("K of (36) for given a, R, λ, u: (a + w_λ)/(a + z − v_λ), z the root of (30) "
                         "written without cancellation.", A_ARG, R_ARG, LAM_ARG, U_ARG)),
        Spec(rid(34, "n2_z_uniform"), "n² = Kgz/R² ((34) with (31)) for the uniform blade, K of (36)",
             src("n°50", "34"), "n^2", n2_z_derived, deps=(rid(36, "K_uniform"), rid(30, "z_uniform")),
             check=_dyn_check("n2"), defs=D_,
             kernel=kern("n² = Kgz/R² for given a, R, λ, u, g, with K of (36).", A_ARG, R_ARG, LAM_ARG, U_ARG,
                         G_ARG, unit="1/s^2")),
        Spec(rid(171, "shape"), "Shape of the blade ωy", src("n°50", "171"), r"\omega y", shape_derived,
             deps=(rid(157, "v"), rid(157, "w")),
             printed=lambda: Y * (omega * s - sp.sinh(omega * s) + c * (sp.cosh(omega * s) - 1)),
             readings=(Reading("ωx, sh ωx, ch ωx", "s for x (the memoir replaces s by x, (77))"),),
             defs=D_ + (c_def,),
             check=blade_check(f"ω y of (77) on the {BLADE}", lambda sol, pt: mp.mpf(pt["u"]) / mp.mpf(pt["lambda"])
                               * sol.y(mp.mpf(pt["s"]), pt["Y"], pt["theta"]), with_s=True, with_K=False,
                               extra={"Y": "0.8", "theta": "0.37"})),
        Spec(rid(172, "c"), "c = U + U1 θ/Y", src("n°50", "172"), "c", c_derived, deps=(rid(171, "shape"),),
             printed=lambda: U + U1 * theta / Y, defs=D_, check=_c_check("c"),
             readings=(Reading("θ/\\bar{Y}", "θ/Y"),)),
        Spec(rid(173, "c"), "c for the principal oscillation", src("n°50", "173"), "c", c_principal,
             deps=(rid(172, "c"),), printed=lambda: U + U1 / K, defs=D_, check=_c_check("principal")),
        Spec(rid(174, "c"), "c for the static deviation", src("n°50", "174"), "c", c_static,
             deps=(rid(172, "c"), rid(159, "vl"), rid(159, "wl")),
             printed=lambda: (a * U + b * U1 + lam / u) / (a - a1), defs=D_ + (a1_def,), check=_c_check("static")),
        # ---------------------------------------------------------------- n°51–53
        Spec(rid(175, "Tprime"), "Bending stress T' = √(3ET) YΓ", src("n°51", "175", 159), "T'", fatigue_derived,
             deps=(rid(157, "v"), rid(157, "w")),
             printed=lambda: sp.sqrt(3 * E * T) * Y * (c * sp.cosh(omega * s) - sp.sinh(omega * s)),
             defs=D_ + (c_def, T_def), check=_fatigue_check("T"),
             note="T = mg/(eh) = Ee²u²/(12λ²) by (156); Γ of (176) written out."),
        Spec(rid(176, "Gamma_f"), "Γ = c ch ωs − sh ωs", src("n°51", "176", 159), r"\Gamma", fatigue_Gamma,
             deps=(rid(175, "Tprime"),), printed=lambda: c * sp.cosh(omega * s) - sp.sinh(omega * s),
             readings=(Reading("cchωs − shωs", "c ch ωs − sh ωs"),), defs=D_ + (c_def,), check=_fatigue_check("Gamma")),
        Spec(rid(177, "Gamma0"), "Γ_0 = c", src("n°51", "177", 159), r"\Gamma_0", fatigue_end(0), deps=(rid(176, "Gamma_f"),),
             printed=lambda: c, defs=D_ + (c_def,), check=_end_fatigue_check(0, "Gamma")),
        Spec(rid(177, "Gammal"), "Γ_λ = c ch u − sh u", src("n°51", "177", 159), r"\Gamma_\lambda", fatigue_end(lam),
             deps=(rid(176, "Gamma_f"),), printed=lambda: c * sp.cosh(u) - sp.sinh(u),
             readings=(Reading("cchu − shu", "c ch u − sh u"),), defs=D_ + (c_def,),
             check=_end_fatigue_check(1, "Gamma")),
        Spec(rid(177, "static_diff"), "Γ_0 − Γ_λ for the static deviation (n°52)", src("n°52", None), r"\Gamma_0-\Gamma_\lambda",
             static_ends(-1), deps=(rid(174, "c"),), printed=lambda: ((2 * a - b) * U + lam / u) / (a - a1),
             defs=D_ + (a1_def,), check=_static_check(-1)),
        Spec(rid(177, "static_sum"), "Γ_0 + Γ_λ for the static deviation (n°52)", src("n°52", None), r"\Gamma_0+\Gamma_\lambda",
             static_ends(+1), deps=(rid(174, "c"),), printed=lambda: (b * (U1 + U2) + lam / u) / (a - a1),
             defs=D_ + (a1_def,), check=_static_check(+1)),
        Spec(rid(178, "Tprime"), "T' in the principal oscillation", src("n°53", "178"), "T'", fatigue_principal,
             deps=(rid(175, "Tprime"),),
             printed=lambda: theta * sp.sqrt(3 * E * T) * (K * sp.sinh(u / 2 - omega * s) / sp.cosh(u / 2)
                                                          + U1 * sp.cosh(omega * s)),
             defs=D_ + (T_def,), check=_fatigue_check("principal")),
        Spec(rid(179, "C0"), "C_0 = KU + U1", src("n°53", "179"), "C_0", bracket_end(0), deps=(rid(178, "Tprime"),),
             printed=lambda: K * U + U1, defs=D_, check=_end_fatigue_check(0, "C")),
        Spec(rid(179, "Cl"), "C_λ = U2 − KU = U1 + U(1 − K)", src("n°53", "179"), r"C_\lambda", bracket_end(lam),
             deps=(rid(178, "Tprime"),), printed=lambda: U2 - K * U, defs=D_, check=_end_fatigue_check(1, "C"),
             note="The second printed form U1 + U(1 − K) equals the first by (161)."),
        # ---------------------------------------------------------------- n°54
        *[Spec(rid(eq, f"T{end}"), f"{what}: {label}", src("n°54", str(eq)), lhs, derive(at),
               printed=pr, defs=D_, readings=rd, note=note, check=_launch_check(at, eq == 181))
          for eq, what, derive in ((180, "Stress at the ends, static launch", static_launch),
                                   (181, "Stress at the ends, launch by a shock", shock_launch))
          for at, end, label, lhs in ((0, "0", "T'_0", "T'_0"), (1, "l", "T'_λ", r"T'_\lambda"))
          for pr, rd, note in [LAUNCH_PRINTED[(eq, at)]]],
        # ---------------------------------------------------------------- n°56–57
        Spec(rid(182, "I"), "Moment of inertia I_λ of the blade", src("n°56", "182"), r"I_\lambda", I_derived,
             deps=(rid(157, "v"), rid(157, "w")),
             printed=lambda: mb * lam**2 / u**2 * (K**2 * (u**2 / 3 - 1 - u * U + 5 * U / u - 3 * U * U1)
                                                   + K * (2 - 5 * U / u - u * U1 + 3 * U * U1)
                                                   + sp.Rational(3, 2) * U1**2 + (U - 3 * U1) / (2 * u)),
             defs=D_, check=blade_check(f"(1/λ)∫y² ds, y of (77) with Y = K, θ = 1, by quadrature on the {BLADE}",
                                        lambda sol, pt: sol.inertia(mp.mpf(pt["K"])), extra={"m'": "1"}),
             kernel=kern("I_λ of (182).", LAM_ARG, U_ARG, K_ARG, KernelArg("m'", 1e-4, 10.0, unit="kg"),
                         unit="kg m^2")),
        Spec(rid(182, "aux"), "∫(Ks − x_0)x'' ds (n°56)", src("n°56", "before (182)"),
             r"\int_0^\lambda (Ks - x_0)x''\,ds", I_aux_derived, deps=(rid(157, "v"), rid(157, "w")),
             printed=lambda: lam / u * (k * (u - 2 * U) - U1), defs=Dk,
             check=blade_check(f"mpmath quad of (Ks − x_0)(Kv + w)/M on the {BLADE}", _aux_truth)),
        Spec(rid(183, "s_minus_x"), "s − x along the blade (n°57)", src("n°57", "before (183)"), "s - x",
             s_minus_x_derived, deps=(rid(158, "phi1"), rid(158, "phi2")),
             printed=lambda: (K**2 / 2 * (s * (sp.cosh(u) + 2) / (sp.cosh(u) + 1)
                                          + 2 * lam / u * sp.sinh(u / 2 - omega * s) / sp.cosh(u / 2)
                                          + lam / (2 * u) * sp.sinh(2 * omega * s - u) / (sp.cosh(u) + 1)
                                          - 3 * lam / (2 * u) * U)
                              - K * (s / (2 * (sp.cosh(u) + 1)) + 3 * lam / (4 * u) * U1
                                     - lam / u * U1 * sp.cosh(omega * s)
                                     + lam / (4 * u) * U1 * sp.cosh(2 * omega * s - u / 2) / sp.cosh(u / 2))
                              - U1**2 / 4 * (s - lam / (2 * u) * sp.sinh(2 * omega * s))),
             defs=D_,
             check=blade_check(f"½∫_0^s (Kφ1 + φ2)² by quadrature on the {BLADE}",
                               lambda sol, pt: _half_int(sol, mp.mpf(pt["K"]), mp.mpf(pt["s"])), with_s=True)),
        Spec(rid(183, "J"), "J (n°57)", src("n°57", "183"), "J", J_derived, deps=(rid(183, "s_minus_x"),),
             printed=lambda: lam / 8 * (1 / u**2 - U1**2)
             - K * lam / 4 * (1 / (sp.cosh(u) + 1) + 3 / u * (U1 - 1 / u))
             + K**2 * lam / 4 * ((sp.cosh(u) + 2) / (sp.cosh(u) + 1) - 3 * U / u),
             defs=D_, check=blade_check(f"(1/2λ)∫(λ − s)(Kφ1 + φ2)² ds by quadrature on the {BLADE}",
                                        lambda sol, pt: sol.weight_integral(mp.mpf(pt["K"]))),
             kernel=kern("J of (183).", LAM_ARG, U_ARG, K_ARG, unit="m")),
    )


def _aux_truth(sol, pt):
    Kv = mp.mpf(pt["K"])
    X0 = Kv * sol.v0 + sol.w0
    with mp.workdps(sol.wdps):
        return sol.integrate(lambda x: (Kv * x - X0) * (Kv * sol.v(x) + sol.w(x)) / sol.M_at(x))


def _half_int(sol, Kv, sv):
    with mp.workdps(sol.wdps):
        f = lambda x: (lambda st: (Kv * (1 + st[1]) + st[3]) ** 2)(sol.state(x))
        return mp.quad(f, [0, sv / 2, sv], method="gauss-legendre") / 2
