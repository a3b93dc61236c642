"""Haag 1935, chapter VII n°96 and chapter VIII n°103: the blade's inertia and weight in the gravity pendulum,
derived step by step.

Chapter II's (135) and (136) (:mod:`..ch2_perturbations`) at a = a1 + ελ (256), with chapter VII's K (260),
z' (257) and Q = K(z − z') = ελ ((45) with (260)), taken to their principal part as ε → 0 (a SymPy limit);
chapter III's I_λ (182), J (183) and w0 (159) for the uniform blade.  The temperature remark (294) comes from
ε = (a + wλ)/λ differentiated with chapter I's laws ((52), (57) with da = α'a, dλ = αλ, M → M(1 + β + 4α):
n°14) and compared with (270).  Chapter VIII's (319)–(320) are (291) and (293) with u → iu (n°101) and, for
the weight, ε → −ε (312).  Nothing here is typed in from chapters VII–VIII.
"""
from __future__ import annotations

import sympy as sp

from ..ch1_variations.derivation import integral_to_G2
from ..ch2_perturbations.derivation import I_lambda, J_w
from ..ch7_gravity.symbols import eps
from ..ch8_inverted.derivation import rotated
from ..common import rid
from ..symbols import K, M_of_s, Q, a, u, alpha_blade, alpha_rod, beta_t, epsilon_of_s, lam, s, v, w, w0, wl, z, zp

# ΔT/T of the weight and dT/T of a warming (n°96): the quantities (294) relates
DT_T = sp.Symbol(r"\Delta T/T", real=True)     # named as printed: the report sets the name as it is
dT_T = sp.Symbol("dT/T", real=True)
NEAR_CRITICAL = {a: -wl + eps * lam}          # (256) with a1 = −wλ (41)


def d(deps, eq: int, name: str) -> sp.Expr:
    return deps[rid(eq, name)].derived


def principal_part(expr: sp.Expr) -> sp.Expr:
    """The leading term of expr, a rational function of ε, as ε → 0 ("en ne gardant que la partie principale",
    n°84): the lowest powers of ε of its numerator and denominator (expanded), their coefficients' ratio."""
    num, den = sp.fraction(sp.together(expr))
    lowest = []
    for part in (num, den):
        poly = sp.Poly(sp.expand(part), eps)
        power = min(monom[0] for monom in poly.monoms())
        lowest.append((power, poly.coeff_monomial(eps**power)))
    (p_num, c_num), (p_den, c_den) = lowest
    return sp.factor(sp.simplify(c_num / c_den)) * eps ** (p_num - p_den)


def in_half_tangent(expr: sp.Expr) -> sp.Expr:
    """expr, a function of u through sh, ch, th of multiples of u/2, written rational in t = th(u/2) (as chapter
    III's U = th(u/2), U1 = (1 − t²)/(2t) are): e^{u/2} = x, cancelled, then x² = (1 + t)/(1 − t).  Raises if
    an odd power of e^{u/2} is left."""
    x, t = sp.Symbol("x", positive=True), sp.Symbol("t", positive=True)
    expr = expr.rewrite(sp.exp).replace(lambda e: isinstance(e, sp.exp) and (e.args[0] / u).is_number,
                                        lambda e: x ** (2 * e.args[0] / u))
    expr = sp.cancel(sp.cancel(sp.together(expr)).subs(x, sp.sqrt((1 + t) / (1 - t))))
    if expr.has(x) or any(isinstance(p, sp.Pow) and p.exp.is_Rational and not p.exp.is_integer
                          for p in expr.atoms(sp.Pow)):
        raise ValueError("an odd power of e^{u/2} is left")
    return sp.factor(expr).subs(t, sp.tanh(u / 2))


def gap_of_K(deps) -> sp.Expr:
    """z − z' = ελ/K, from K = ελ/(z − z') (260)."""
    gap = sp.Symbol("gap", real=True)
    return sp.solve(sp.Eq(K, d(deps, 260, "K_foci").subs(z - zp, gap)), gap)[0]


# ---------------------------------------------------------------- n°96: (291)–(293)
def inertia_291(deps) -> sp.Expr:
    """(291): (135) ΔT/T = −I_λ/(2mz'(z − z')) with z − z' = ελ/K (260), K of (260), z' of (257), I_λ of (182)
    at that K and w0 of (159) (the uniform blade): its limit as ε → 0 (it is finite: "indépendante du
    coefficient de sensibilité")."""
    expr = d(deps, 135, "inertia")
    expr = expr.subs(z, zp + gap_of_K(deps))
    K_near = d(deps, 260, "K")
    expr = expr.subs(I_lambda, d(deps, 182, "I").subs(K, K_near)).subs(K, K_near)
    expr = expr.subs(zp, d(deps, 257, "zp"))
    return in_half_tangent(principal_part(expr).subs(w0, d(deps, 159, "w0")))


def weight_292(deps) -> sp.Expr:
    """(292): (136) ΔT/T = −m'J/(mQ) with Q = K(z − z') (45) and K = ελ/(z − z') (260): Q = ελ."""
    Q_near = d(deps, 45, "Q").subs(z, zp + gap_of_K(deps))
    return principal_part(d(deps, 136, "weight").subs(Q, sp.simplify(Q_near)))


def weight_293(deps) -> sp.Expr:
    """(293): (292) with J of (183) at K of (260), the principal part in ε (J → J at K = 0)."""
    expr = d(deps, 292, "weight").subs(J_w, d(deps, 183, "J").subs(K, d(deps, 260, "K")))
    return in_half_tangent(principal_part(expr))


# ---------------------------------------------------------------- n°96: the temperature, (294)
def dwl_warming(deps) -> sp.Expr:
    """n°96: dwλ per degree, (52)·dλ + (57) with dλ = αλ and ε(s) = β + 4α constant (dE/E = β, dI/I = 4α,
    n°14): ∫(β + 4α)w²/M ds = (β + 4α)G2 ((79) at K = 0, the limit of K (260) as ε → 0)."""
    by_length = d(deps, 52, "dwl") * alpha_blade * lam
    by_stiffness = d(deps, 57, "dwl").subs(epsilon_of_s(s), beta_t + 4 * alpha_blade)
    return sp.expand(by_length + integral_to_G2_at_rest(by_stiffness))


def integral_to_G2_at_rest(expr: sp.Expr) -> sp.Expr:
    """∫c w²/M ds → c·G2, G2 of (79) at K = 0, through chapter I's :func:`integral_to_G2`."""
    def lift(integral):
        ratio = sp.factor(integral.function / (w(s) ** 2 / M_of_s(s)))
        if ratio.has(s):
            raise ValueError(f"integrand is not ∝ w²/M: {integral.function}")
        return sp.Integral(ratio * (K * v(s) + w(s)) ** 2 / M_of_s(s), *integral.limits)
    lifted = expr.replace(lambda e: isinstance(e, sp.Integral), lift)
    return integral_to_G2(lifted).subs(K, 0)


def depsilon_294(deps) -> sp.Expr:
    """n°96: dε/ε per degree, ε = (a + wλ)/λ ((256), a1 = −wλ) with da = α'a, dλ = αλ and dwλ of
    :func:`dwl_warming`: the principal part in ε (a → a1 = −wλ in α'a)."""
    epsilon_of = (a + wl) / lam
    da, dwl_s, dlam = sp.symbols("da dw_lambda dlambda", real=True)
    total = (sp.diff(epsilon_of, a) * da + sp.diff(epsilon_of, wl) * dwl_s + sp.diff(epsilon_of, lam) * dlam)
    total = total.subs({da: alpha_rod * a, dwl_s: d(deps, 294, "dwl"), dlam: alpha_blade * lam})
    relative = (total / epsilon_of).subs(NEAR_CRITICAL)
    return principal_part(relative)


def depsilon_minus2(deps) -> sp.Expr:
    """n°96: "En comparant avec (270)": dε/ε over dT/T of (270), a number (raises otherwise), times dT/T."""
    ratio = sp.simplify(d(deps, 294, "depsilon") / d(deps, 270, "dT"))
    if ratio.free_symbols:
        raise ValueError(f"dε/ε is not proportional to (270): ratio {ratio}")
    return ratio * dT_T


def period_294(deps) -> sp.Expr:
    """(294): d(ΔT)/T = (ΔT/T)·d log ΔT, d log ΔT = dT/T + d log(ΔT/T); ΔT/T of (292) depends on the
    temperature through ε to its principal part (J, λ, m'/m vary by O(α), not O(α/ε)): d log(ΔT/T) =
    (ε ∂_ε log(ΔT/T))·dε/ε, with dε/ε in dT/T from the step before."""
    weight = d(deps, 292, "weight")
    exponent = sp.simplify(eps * sp.diff(sp.log(weight), eps))
    if exponent.free_symbols:
        raise ValueError(f"ΔT/T of (292) is not a power of ε: {exponent}")
    relative = dT_T + exponent * d(deps, 294, "minus2")
    return sp.factor(DT_T * relative)


def ratio_294(deps) -> sp.Expr:
    """n°96, last sentence: the new thermal perturbation over the old one, d(ΔT)/T over dT/T, with ΔT/T of (292)."""
    return sp.simplify((d(deps, 294, "dT") / dT_T).subs(DT_T, d(deps, 292, "weight")))


# ---------------------------------------------------------------- n°103: (319)–(320)
def inertia_319(deps) -> sp.Expr:
    """(319): (291) with u → iu (n°101, n°103); no ε in it."""
    return sp.factor(sp.simplify(rotated(d(deps, 291, "inertia"))))


def weight_320(deps) -> sp.Expr:
    """(320): (293) with u → iu and ε → −ε ((312): a1 − a = ελ)."""
    return sp.simplify(sp.fu(rotated(d(deps, 293, "weight")).subs(eps, -eps)))
