"""Haag 1935, chapter IX with chapters I, VII, VIII: what a gravity meter on a rhombus-holed blade needs, derived.

Haag stops at G_2 (346) for the rhombus hole (n°110).  An inverted pendulum on that blade (a gravity meter,
chapter VIII) needs, besides G_2:

* β1 = λ + vλ − v0 ((22) of chapter I) with v0, vλ of (343): the first existence condition (304);
* a1 = −wλ ((305), n°100) with wλ of (343): the critical distance, so that ε = (a1 − a)/λ (312);
* n² of the slow vibration: (34) n² = −Kg/z' with g → −g (n°100), K of (36), z the positive root of the foci's
  quadratic (30), with vλ, β1, wλ of the rhombus blade (as eq034.n2_inverted does for the uniform one);
* G = G_2/(ελ) (262) with ε → −ε (312) and G_2 of (346) (M in absolute value, footnote (2) of n°107: the signed
  ∫w²/M ds is −(346));
* F_n = ∫ w'^n ds (n = 2, 4; (79) at K = 0, (282)) over the two halves, written in x of (334) with the constants
  (340), (342): no closed form for n = 4, so it stays an integral (evaluated by quadrature at the precision in
  force); and C = (wλ − F4)/(wλ − F2) of (284).

Every form is built by SymPy from the derived Results it names (never typed in); the Bessel values stay functions
of x_0, x_1 of (334) (Neumann's Y_n, as in (336)–(346)).
"""
from __future__ import annotations

import sympy as sp

from .. import ch1_model
from ..symbols import K, R, beta1, g, lam, omega, v0, vl, wl, z, zp
from ..ch7_gravity.symbols import eps
from . import rhombus_derivation as derivation


def derived_of(deps, rid: str) -> sp.Expr:
    return deps[rid].derived


def beta1_rhombus(v0_form: sp.Expr, vl_form: sp.Expr) -> sp.Expr:
    """(22): β1 = λ + vλ − v0 (the coefficient of Y in (21)) with v0, vλ of (343)."""
    return ch1_model.beta1_def().subs({v0: v0_form, vl: vl_form}, simultaneous=True)


def a1_rhombus(wl_form: sp.Expr) -> sp.Expr:
    """(305): the critical distance a1, where a + wλ changes sign, with wλ of (343)."""
    a = sp.Symbol("a", real=True)
    return sp.solve(sp.Eq(a + wl, 0), a)[0].subs(wl, wl_form)


def n2_slow(vl_form: sp.Expr, beta1_form: sp.Expr, wl_form: sp.Expr) -> sp.Expr:
    """n° 100 with (34), (36), (30): n² = −Kg/z' with g → −g, z' = −R²/z (31), z the root of (30) taken with + (the
    slow vibration, node z' above the bob), K of (36); vλ, β1, wλ those of the rhombus blade."""
    from pendsym.roots import quadratic_roots
    # built in the symbols vλ, β1, wλ (the Bessel forms are large: no simplification on them), then substituted
    coeffs = ch1_model.foci_quadratic().all_coeffs()
    plus, _minus = quadratic_roots(sp.Poly(sum(c * z**k for k, c in zip((2, 1, 0), coeffs)), z))
    product, _sum = ch1_model.vieta()
    if sp.simplify(product + R**2) != 0:
        raise ValueError("the product of the foci is not −R² (31)")
    n2 = (-K * g / zp).subs(g, -g).subs(zp, product / z)
    generic = n2.subs(K, ch1_model.K_of_z()).subs(z, plus)
    return generic.subs({vl: vl_form, beta1: beta1_form, wl: wl_form}, simultaneous=True)


def G_inverted(G_262: sp.Expr, G2_346: sp.Expr) -> sp.Expr:
    """(262) G = G_2/(ελ) with ε → −ε (312) and the signed G_2 = −(346) (M in absolute value in n°107–110)."""
    G2 = [x for x in G_262.free_symbols if x.name == "G_2"][0]
    return G_262.subs(eps, -eps).subs(G2, -G2_346)


def slope_integral(n: int, constants: dict) -> sp.Expr:
    """F_n = ∫_{−λ/2}^{λ/2} w'^n ds of the rhombus blade (n°107–108), in x of (334) on each half.

    On a half, w = x[A J_1 + B Y_1] (336), dw/ds = ε(dv/dx)(2ω²/(kx)) (n°107), and both halves run over
    x_0 ≤ x ≤ x_1 with |ds/dx| = 1/(dx/ds at ε = 1): the left half (s < 0, constants A', B', ε = −1) and the right
    half (A'', B'', ε = +1).  The integrand is expanded in the powers of J_0(x), Y_0(x) with the constants as symbols
    and each x-dependent part integrated once (both halves share them); then A', B', A'', B'' are replaced by their
    derived forms ``constants`` ((340), (342))."""
    x, A, B = derivation.x, derivation.A, derivation.B
    slope_x = derivation.slope_in_x()                       # dv/dx = x[AJ_0 + BY_0]
    dxds = derivation.ds_factor()                           # ε 2ω²/(kx)
    total = sp.Integer(0)
    for sign, (first, second) in ((-1, (derivation.A1, derivation.B1)), (1, (derivation.A2, derivation.B2))):
        slope_s = (slope_x * dxds).subs(derivation.eps, sign).subs({A: first, B: second}, simultaneous=True)
        total += sp.expand(slope_s**n / dxds.subs(derivation.eps, 1))          # x cancels in each term
    parts: dict = {}
    for term in sp.Add.make_args(total):
        factor, shape = term.as_independent(x, as_Add=False)
        parts[shape] = parts.get(shape, 0) + factor
    integrals = sum((sp.factor(factor) * sp.Integral(shape, (x, derivation.x0, derivation.x1))
                     for shape, factor in sorted(parts.items(), key=lambda p: sp.default_sort_key(p[0]))),
                    sp.Integer(0))
    return integrals.subs(constants, simultaneous=True)


def F2_rhombus(F2G2: sp.Expr, wl_form: sp.Expr, G2_346: sp.Expr) -> sp.Expr:
    """(81) at K = 0: F2 + G2 = wλ, with the signed G2 = −(346) (M in absolute value in n°107–110) and wλ of (343):
    F2 = wλ + (346), no integral left."""
    F2_symbol = sp.Symbol("F_2")
    G2 = sp.Symbol("G_2")
    F2 = sp.solve(sp.Eq(F2_symbol + G2, F2G2.subs(K, 0)), F2_symbol)[0]
    return F2.subs({G2: -G2_346, wl: wl_form}, simultaneous=True)


def C_rhombus(C_F2: sp.Expr, wl_form: sp.Expr, F2: sp.Expr, F4: sp.Expr) -> sp.Expr:
    """(284), second form (wλ − F4)/(wλ − F2), with wλ of (343) and F2, F4 of :func:`slope_integral`."""
    F = [f for f in C_F2.atoms(sp.Function) if f.func.__name__ == "F"]
    by_order = {f.args[0]: f for f in F}
    return C_F2.subs({by_order[2]: F2, by_order[4]: F4, wl: wl_form}, simultaneous=True)
