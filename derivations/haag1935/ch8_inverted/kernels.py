"""Haag 1935, chapter VIII: the inverted blade's n² (the period), K, stated in ε, and C on the window n = 1, as
kernels (issue #13).

Measured by make audit (20,000 points each, scaled = ulp/max(1, κ)): n² (N2_EPS_KERNEL) 2.44 Python, 1.9 C;
K (K_EPS_KERNEL) 2.46 in both (session 10; κ = 1.03 there, u = 2.019 near the stationary point of 1/(u sin u),
whose rounding κ does not cover); C on the window n = 1 (C_WINDOW1_KERNEL) 1.0 (κ ≥ 37 on that window).
Session 9's form of K, −ελS/(D(2R² + S)), measured 0.83 on the derive's sample and 5.02 in make audit (ε = 9.1e-7,
u = 2.066): the engine's stable-form synthesis had split it into a polynomial in ε, R, λ whose coefficients are
functions of u (the radicand P² + 4R²D² expanded in ε: leaves such as −2 + 4 tan(u/2)/u − 4/(u sin u), 130 ulp on
their own grid), and the sample of 259 points in four arguments had not met the points where those cancel.  The
form now derived (:func:`K_eps`) is (36) itself, K = (a + wλ)/(a + z − vλ) = −ε/(d + ζ) over λ, with the root
ζ = z/λ written without cancellation; as derived it measures 0.58 on the sample, so the engine keeps it whole.

Stated in a, the inverted blade's n² and K have no box for a domain: both vibrations exist only where
a + wλ < 0 (305) and β1 < 0 (304), and a1 = −wλ = λ/(u tan u) (310) moves with u.  Stated in
ε = (a1 − a)/λ (312) instead, the existence condition (305) is ε > 0 whatever u, and (304) holds on the
whole window 0 < u < π (309, n = 0).  The domain is the box u ∈ [1e-6, π] (π: the double below π),
ε ∈ [1e-9, 0.25], with R, λ and g as for the direct blade's kernels.  Why ε ≤ 1/4: the form takes z,
the positive root of (30) times D = a − vλ = λ(1/(u sin u) − ε), as 2R²D/S, which holds for D > 0, and
D > 0 on the whole window for ε < min 1/(u sin u) = 0.5495 (at tan u = −u, u = 2.029); towards that curve
D → 0 and the emitted form loses accuracy (make audit: 18 ulp × κ at ε = 0.5, 6.9 on random points of
ε ∈ [0.4, 0.5], under 4 below 0.4), so the box stops at ε = 1/4, where D ≥ 0.3λ.
A gravity meter works near its critical distance (ε ≪ 1; G of (314) is the principal part in ε).

The forms are derived here by SymPy from the Results: n² of the inverted uniform blade
(``eq034.n2_inverted``: (34), (36), (30) with u → iu, g → −g) and K of (36) built the same way, with
a = a1 − ελ, a1 of (310), and the root z = 2R²D/S, S = P + √(P² + 4R²D²) written without cancellation
(P + Q for P ≥ 0, 4R²D²/(Q − P) otherwise): n² = 2gελ/(2R² + S); K = −ε/(d + ζ) (:func:`K_eps`).  Through the root
as eq034.n2_inverted writes it, (a + z − vλ) and z both vanish on the curve D = 0 (ε = 1/(u sin u)), and the
form as derived loses up to 1.4e5 ulp (×κ) at u = π/2, ε = 10.  a = λ(cot u/u − ε) is negative for
u > π/2 and where cot u/u < ε: the formulas, and the truth (the eigenproblem of the directly solved inverted
blade, which the chapter's window checks run at a = −1 m), hold for a centre of mass on either side of the
blade's end.  The window n = 1 (2x1 < u < 3π, (309)) has a1 < 0 throughout (tan u < 0): n² and K are not
emitted there; C of (317), a function of u alone, is, as the Result eq317.C_window1 (one kernel per Result).

The thread limit u → ∞ does not exist for the inverted blade (u → iu: the functions are circular).
"""
from __future__ import annotations

import sympy as sp

from pendsym.result import KernelArg, KernelSpec

from .. import ch1_model
from ..ch3_uniform.kernels import G_ARG, LAMBDA_ARG, R_ARG
from ..ch7_gravity.kernels import U_WINDOW
from ..ch7_gravity.symbols import eps
from ..common import rid
from ..symbols import K, R, a, beta1, g, lam, vl, wl, z, zp
from . import derivation

EPS_INVERTED = KernelArg("varepsilon", 1e-9, 0.25, log=True)      # (312): ε = (a1 − a)/λ > 0 (305); D > 0

N2_EPS_KERNEL = KernelSpec(args=(EPS_INVERTED, R_ARG, LAMBDA_ARG, U_WINDOW, G_ARG), unit="1/s^2",
                           doc="n² of the slow vibration of a pendulum on an inverted uniform blade (g → −g, u → iu), "
                               "at a = a1 − ελ (312), a1 = λ/(u tan u) (310): ε > 0 is the existence condition "
                               "(305), and n² ∝ ε (the period T = 2π/n).")
# (309), n = 1: the window 2x1 < u < 3π (the double above 2x1 = 8.98681891581812835…, x1 the root of tan x = x near
# 4.49 (308); the double below 3π)
U_WINDOW1 = KernelArg("u", 8.986818915818128, 9.42477796076938, log=True)
C_WINDOW1_KERNEL = KernelSpec(args=(U_WINDOW1,),
                              doc="C = (3/8)(4u − sin 4u)/(sin²u(2u + sin 2u)) (317), the isochronism coefficient of "
                                  "the gravity pendulum on an inverted uniform blade, on the stability window n = 1 "
                                  "(2x1 < u < 3π, (309)); C ~ 3/(4 sin²u) as u → 3π (the window’s end).")
K_EPS_KERNEL = KernelSpec(args=(EPS_INVERTED, R_ARG, LAMBDA_ARG, U_WINDOW),
                          doc="K of (36) of an inverted uniform blade (u → iu) at a = a1 − ελ (312), for the slow "
                              "vibration (node z' < 0): K = −ελ/(a + z − vλ) < 0 (302).")


DIST, NUM = sp.symbols("D P", real=True)     # D = a − vλ, P: the quadratic (30) times D is Dz² + Pz − R²D


def _scaled_quadratic() -> tuple[sp.Expr, sp.Expr]:
    """(D, P): (30) of chapter I, monic in z with its z coefficient P/D, times its denominator D = a − vλ."""
    c = ch1_model.foci_quadratic().all_coeffs()
    num, den = sp.fraction(sp.together(c[1]))
    if sp.simplify(den - (a - vl)) != 0 or sp.simplify(c[2] + R**2) != 0:
        raise ValueError(f"(30) is not z² + (P/(a − vλ))z − R²: {c}")
    return den, num


def _stable_parts():
    """(n², S, stable S): n² of the slow vibration in D = a − vλ > 0 and P, rational in S = P + √(P² + 4R²D²),
    and S written without cancellation: P + Q for P ≥ 0, 4R²D²/(Q − P) otherwise (Q² − P² = 4R²D², checked).

    From (34) n² = −Kg/z' with g → −g (n°100), z' = −R²/z (31), K = (a + wλ)/(a + z − vλ) (36) and z the
    positive root (Q − P)/(2D) of Dz² + Pz − R²D: z = 2R²D/S.  (K itself is formed apart, :func:`K_eps`.)"""
    Q = sp.sqrt(NUM**2 + 4 * R**2 * DIST**2)
    roots = list(sp.roots(sp.Poly(DIST * z**2 + NUM * z - R**2 * DIST, z)))
    plus = next(r for r in roots if sp.simplify(r - (Q - NUM) / (2 * DIST)) == 0)     # positive for D > 0
    S = sp.Symbol("S", positive=True)
    z_of_S = 2 * R**2 * DIST / S
    if sp.simplify(sp.together(sp.expand((plus - z_of_S.subs(S, NUM + Q)) * 2 * DIST * (NUM + Q)))) != 0:
        raise ValueError("z is not 2R²D/(P + Q)")
    if sp.expand((Q - NUM) * (Q + NUM) - 4 * R**2 * DIST**2) != 0:
        raise ValueError("Q² − P² ≠ 4R²D²")
    K_36 = ch1_model.K_of_z().subs(z, z_of_S)
    n2 = (-K * g / zp).subs(g, -g).subs(zp, -R**2 / z).subs(K, K_36).subs(z, z_of_S)
    n2 = sp.factor(sp.simplify(n2.subs(a, DIST + vl)))
    stable_S = sp.Piecewise((NUM + Q, NUM >= 0), (4 * R**2 * DIST**2 / (Q - NUM), True))
    return n2, S, stable_S


AREA = sp.Symbol("A_w", real=True)            # a + wλ, which (312) makes −ελ
DENOM = sp.Symbol("T", positive=True)          # 2R² + S


def _at_eps(deps) -> tuple[dict, dict, sp.Expr, sp.Expr, sp.Expr]:
    """(ends, at, P, c, b) of the inverted uniform blade at a = a1 − ελ: the rotated ends v_λ, β1, w_λ
    (159), u → iu (n°101); a = a1 − ελ ((312), a1 of (310)); D = a − vλ and P of (30)'s scaled quadratic,
    P = D² + β1(a + wλ) − R² (checked); D = λ(c − ε) with c = 1/(u sin u) free of ε (checked); b = β1/λ."""
    ends = {name: derivation.rotated(deps[rid(159, str_name)].derived)
            for name, str_name in ((vl, "vl"), (beta1, "beta1"), (wl, "wl"))}
    at = {a: deps[rid(310, "a1")].derived - eps * lam}
    D_value, P_value = _scaled_quadratic()
    P_in = sp.expand(P_value.subs(a, DIST + vl).subs(wl, AREA - DIST - vl))
    if sp.expand(P_in - (DIST**2 + beta1 * AREA - R**2)) != 0:
        raise ValueError(f"P is not D² + β1(a + wλ) − R²: {P_in}")
    D_at = D_value.subs(ends).subs(at)
    c = sp.simplify(sp.expand((D_at + eps * lam) / lam).rewrite(sp.sin))      # 1/(u sin u): no tan(u/2) + cot u
    if c.has(eps) or sp.simplify((D_at - lam * (c - eps)).rewrite(sp.sin)) != 0:
        raise ValueError(f"D = {D_at} is not λ(c(u) − ε)")
    return ends, at, P_in, c, sp.simplify(ends[beta1] / lam)


def _in_eps(expr: sp.Expr, S: sp.Symbol, stable_S: sp.Expr, deps) -> sp.Expr:
    """expr (in D, P, S, a, vλ, wλ) in D, β1, A = a + wλ and Q = √(P² + 4R²D²): P = D² + β1A − R² (SymPy from
    (30)'s coefficient), 2R² + S = (R² + D² + β1A) + Q, a sum of positive terms in the window (β1 < 0 (304),
    A < 0 (305)), S stable; then D, β1, A of the rotated ends (159), u → iu (n°101), and a = a1 − ελ ((312),
    a1 of (310)): A = −ελ."""
    ends, at, P_in, c, b = _at_eps(deps)
    T_value = sp.expand(2 * R**2 + P_in) + sp.sqrt(P_in**2 + 4 * R**2 * DIST**2)
    expr = expr.subs(a, DIST + vl).xreplace({DIST + vl + wl: AREA, 2 * R**2 + S: DENOM})
    if expr.has(wl) or (expr.has(S) and expr.has(DENOM) is False):
        raise ValueError(f"a + wλ or 2R² + S is not a factor of {expr}")
    # D = λ(c − ε) and β1 = λb, c and b functions of u alone: the kernel's leaves, so that no expansion of D²
    # in ε cancels (D is small where ε nears 1/(u sin u))
    values = {DIST: lam * (c - eps), beta1: lam * b, AREA: sp.simplify((a + wl).subs(ends).subs(at))}
    return expr.subs({DENOM: T_value, S: stable_S.subs(NUM, P_in)}).subs(values)


def n2_eps(deps) -> sp.Expr:
    """n² of the inverted uniform blade at a = a1 − ελ: (34), (36), (30) as ``eq034.n2_inverted`` combines
    them (g → −g, z' = −R²/z), the root z = 2R²D/S of the scaled quadratic (:func:`_stable_parts`)."""
    n2, S, stable_S = _stable_parts()
    return _in_eps(n2, S, stable_S, deps)


RATIO, ZETA = sp.symbols("r zeta", positive=True)      # r = R/λ, ζ = z/λ
D_L, P_L = sp.symbols("d p", real=True)                  # d = D/λ, p = P/λ²


def _K_of_root():
    """K of (36) as A/(D + z), A = a + wλ (SymPy checks (36) is that), and the positive root z of the scaled
    quadratic Dz² + Pz − R²D of (30) in units of λ: z = λζ, ζ the positive root of dζ² + pζ − r²d
    (d = D/λ, p = P/λ², r = R/λ: the quadratic divided by λ³, checked), written without cancellation:
    ζ = (q − p)/(2d) for p < 0, 2r²d/(p + q) otherwise, q = √(p² + 4r²d²) (the two are equal: (q − p)(q + p) =
    4r²d², checked).  Then K = (A/λ)/(d + ζ): λ cancels, K depends on R and λ through r alone."""
    K_36 = ch1_model.K_of_z()
    if sp.simplify(K_36 - (a + wl) / (DIST + vl + z - vl).subs(DIST, a - vl)) != 0:
        raise ValueError(f"(36) is not (a + wλ)/(a + z − vλ): {K_36}")
    quad = sp.expand((DIST * z**2 + NUM * z - R**2 * DIST).subs({z: lam * ZETA, DIST: lam * D_L, NUM: lam**2 * P_L,
                                                                 R: lam * RATIO}) / lam**3)
    if sp.expand(quad - (D_L * ZETA**2 + P_L * ZETA - RATIO**2 * D_L)) != 0:
        raise ValueError(f"the scaled quadratic in ζ is {quad}")
    q = sp.sqrt(P_L**2 + 4 * RATIO**2 * D_L**2)
    plus = (q - P_L) / (2 * D_L)
    if not any(sp.simplify(r - plus) == 0 for r in sp.roots(sp.Poly(quad, ZETA))):
        raise ValueError("(q − p)/(2d) is not a root of dζ² + pζ − r²d")
    far = 2 * RATIO**2 * D_L / (P_L + q)
    if sp.expand((q - P_L) * (q + P_L) - 4 * RATIO**2 * D_L**2) != 0:
        raise ValueError("(q − p)(q + p) ≠ 4r²d²")
    zeta = sp.Piecewise((plus, P_L < 0), (far, True))
    # (36) over λ: K = (A/λ)/(D/λ + z/λ)
    return (AREA / lam) / (D_L + zeta)


def K_eps(deps) -> sp.Expr:
    """K of (36) of the inverted uniform blade at a = a1 − ελ: K = A/(D + z) (:func:`_K_of_root`), with the rotated
    ends (159), u → iu (n°101), a = a1 − ελ ((312), a1 of (310)): A = −ελ, d = D/λ = c(u) − ε, c = 1/(u sin u), and
    p = P/λ² = d² + (β1/λ)(A/λ) − r² ((30)'s coefficient, checked in :func:`_in_eps`), r = R/λ.

    Not the form of :func:`n2_eps` (K = −ελS/(D(2R² + S))): the kernel engine split that one into a polynomial in
    ε, R, λ with leaves in u that cancel (make audit 5.02 scaled); here every sum is of terms of one sign except
    d = c − ε (c ≥ 0.5495 > 2ε) and p (whose error is small beside q where p nears 0)."""
    ends, at, P_in, c, b = _at_eps(deps)                               # b = β1/λ = 1 − 2 tan(u/2)/u
    A_value = sp.simplify((a + wl).subs(ends).subs(at))
    if sp.simplify(A_value + eps * lam) != 0:
        raise ValueError(f"a + wλ = {A_value} is not −ελ at a = a1 − ελ")
    d_value = c - eps
    p_value = sp.expand(P_in / lam**2).subs({DIST: lam * d_value, beta1: lam * b, AREA: -eps * lam, R: lam * RATIO})
    p_value = sp.expand(p_value).collect(eps)
    if sp.simplify(p_value - (d_value**2 - eps * b - RATIO**2)) != 0:
        raise ValueError(f"p = {p_value}")
    p_value = d_value**2 - eps * b - RATIO**2        # the same (checked): D² kept a square, not expanded in ε
    form = _K_of_root().subs(AREA, -eps * lam)
    return form.subs({P_L: p_value}).subs({D_L: d_value}).subs(RATIO, R / lam)
