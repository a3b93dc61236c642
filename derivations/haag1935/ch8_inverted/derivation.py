"""Haag 1935, chapter VIII, n°100–103: the inverted blade (g → −g), derived from chapter III's forms.

The memoir's rule (n°101): chapter III's formulas hold with ω → iω, u → iu (M = −λ²/u² < 0), and
chapter VII's with ε → −ε (312).  C (317) is derived apart, from the closed forms of (9)–(10) with a
negative M (trigonometric, by dsolve), not by u → iu.
"""
from __future__ import annotations

import functools

import sympy as sp

from pendsym import blade
from .. import ch1_model
from ..common import rid
from ..symbols import a, beta1, lam, mg, s, u, vl, wl
from ..ch7_gravity.symbols import eps


def derived_of(deps, eq: int, name: str) -> sp.Expr:
    return deps[rid(eq, name)].derived


@functools.lru_cache(maxsize=None)
def rotated(expr: sp.Expr) -> sp.Expr:
    """u → iu (n°101), written with circular functions.  Remembered: the ends (159) are rotated for (313),
    (310) and n² alike."""
    return sp.simplify(sp.expand_complex(sp.expand(expr.rewrite(sp.cosh)).subs(u, sp.I * u)))


def by_rotation(eq: int, name: str):
    def derive(deps):
        return rotated(derived_of(deps, eq, name))
    derive.__doc__ = f"({eq}) {name} with u → iu (n°101, n°103)."
    return derive


def a1_310(deps) -> sp.Expr:
    """(310): a1 = −wλ (41) with wλ of (159), u → iu."""
    return -rotated(derived_of(deps, 159, "wl"))


def x1_of_308() -> sp.Float:
    """The first positive root x1 of tan x = x (309), where (308) tan(u/2) > u/2 changes sign, by nsolve."""
    x = sp.Symbol("x")
    return sp.nsolve(sp.sin(x) - x * sp.cos(x), x, sp.Rational(449, 100), prec=40)


def windows_309(_deps) -> sp.Tuple:
    """(309): the first windows' ends 2x1, 3π (n = 1) and π (n = 0): β1 < 0 (307), (304)."""
    return sp.Tuple(2 * x1_of_308(), 3 * sp.pi, sp.pi)


def x1_values(_deps) -> sp.Tuple:
    """n°101: x1 and x1 − π."""
    x1 = x1_of_308()
    return sp.Tuple(x1, x1 - sp.pi)


def weights_309(deps) -> sp.Tuple:
    """Footnote of n°102: mg ∝ u² (156); P is the weight at u = π/2 (311): the windows' ends in units of P."""
    ends = derived_of(deps, 309, "windows")
    return sp.Tuple(*[sp.nsimplify(end) ** 2 / (sp.pi / 2) ** 2 if end.has(sp.pi) else end**2 / (sp.pi / 2) ** 2
                      for end in ends])


def G_314(deps) -> sp.Expr:
    """(314): (263) with u → iu and ε → −ε (312)."""
    return sp.simplify(rotated(derived_of(deps, 263, "G")).subs(eps, -eps))


def C_317(_deps) -> sp.Expr:
    """(317): C of (284) with φ2, wλ of (9)–(10) for M = −λ²/u² (dsolve, trigonometric forms)."""
    M_neg = sp.Symbol("M", negative=True)
    forms = blade.closed_forms(M_neg, lam, s)
    phi2 = sp.simplify(forms["phi2"].subs(M_neg, -lam**2 / u**2))       # sin(us/λ)/sin u
    w_lambda = sp.simplify(forms["wl"].subs(M_neg, -lam**2 / u**2))
    x = sp.Symbol("x", positive=True)                                     # x = us/λ
    f = sp.simplify(phi2.subs(s, lam * x / u))
    F = {n: lam / u * sp.integrate(sp.expand(f**n), (x, 0, u)) for n in (2, 4)}
    return sp.simplify((w_lambda - F[4]) / (w_lambda - F[2]))


# ---------------------------------------------------------------- n°100: (302)–(306)
def potential_coefficients(_deps) -> sp.Tuple:
    """Footnote of n°100: V/(mg) = ½[βY + θ(N + aθ)] (the work of the end loads and of the weight, n°23) with
    β = β1Y + β2θ (21), β2 = −vλ (22) and N = Yvλ + θwλ ((2) at s = λ, (14)): the coefficients of Y² and θ²
    (the Yθ term cancels).  For g < 0 the equilibrium is stable when both are negative: (304), (305)."""
    Y, theta = sp.symbols("Y theta", real=True)
    beta = Y * beta1 + theta * ch1_model.beta2_def()
    N = Y * vl + theta * wl
    V = sp.expand((beta * Y + theta * (N + a * theta)) / 2)
    assert V.coeff(Y, 1).coeff(theta, 1) == 0
    return sp.Tuple(2 * V.coeff(Y, 2), 2 * V.coeff(theta, 2))


# ---------------------------------------------------------------- n°101: (311)
def weight_311(deps) -> sp.Expr:
    """(311): u < π/2 with u = λω, ω² = mg/(EI), I = e³h/12 (156), solved for mg."""
    return sp.solve(sp.Eq(derived_of(deps, 156, "u"), sp.pi / 2), mg)[0]


def shape_316(deps) -> sp.Expr:
    """(316): (278) with ω → iω, u → iu (n°103): ωy → iωy, so the rotated right side over i."""
    return sp.simplify(rotated(derived_of(deps, 278, "shape")) / sp.I)


def fatigue_inverted(deps) -> sp.Expr:
    """n°103 after (316): (280) with u → iu (M = λ²/u² → −λ²/u² and w → w(iu) together)."""
    return rotated(derived_of(deps, 280, "fatigue"))


# ---------------------------------------------------------------- n°100: (302), (303), (306); n°101: (308); (312)
def signs_302(deps) -> sp.Tuple:
    """(302): (34) n² = −Kg/z' (its derived form over K of (35) is −g/z') and n'² = −K'g/z, with g → −g, give
    K = n²z'/g, K' = n'²z/g; the foci satisfy
    zz' = −R² ((30): its constant term), z' < z, so z' = −R²/z with z > 0: SymPy finds K < 0 and K' > 0 for
    n², n'², g, z, R > 0.  Returned as the claim (K, −K'), both negative."""
    from ..symbols import K, K_prime, R, g, n_squared, z, zp
    n2_fast, z_positive = sp.Symbol("n'^2", positive=True), sp.Symbol("z", positive=True)
    product = sp.expand(derived_of(deps, 30, "quadratic").subs(z, 0))          # zz' = this constant
    if sp.simplify(product + R**2) != 0:
        raise ValueError("the product of the foci is not −R²")
    n2_over_K = sp.simplify(derived_of(deps, 34, "n2") / derived_of(deps, 35, "K"))         # −g/z'
    if n2_over_K.has(a):
        raise ValueError(f"n²/K = {n2_over_K} is not −g/z'")
    K_value = n_squared / n2_over_K.subs(g, -g)                                              # n²z'/g
    K_prime_value = K_value.subs({zp: z_positive, n_squared: n2_fast}, simultaneous=True)
    K_value = K_value.subs(zp, -R**2 / z_positive)
    if not (K_value.is_negative and K_prime_value.is_positive):
        raise ValueError(f"the signs of K = {K_value}, K' = {K_prime_value} are not (302)")
    return sp.Tuple(K, -K_prime)


def signs_303(deps) -> sp.Tuple:
    """(303): K = (a + wλ)/(a + z − vλ) (36) and K' the same with z ↔ z' (n°8): KK' < 0 (302) makes
    a + z − vλ and a + z' − vλ of opposite signs, the smaller (z' < z) negative.  Returned as
    (a + z' − vλ, −(a + z − vλ)), both negative."""
    from ..symbols import K, z, zp
    K_value = derived_of(deps, 36, "K")
    K_prime_value = K_value.subs({z: zp}, simultaneous=True)
    denominators = sp.denom(sp.together(K_value)), sp.denom(sp.together(K_prime_value))
    numerators = sp.numer(sp.together(K_value)), sp.numer(sp.together(K_prime_value))
    if sp.simplify(numerators[0] - numerators[1]) != 0:
        raise ValueError("K and K' of (36) do not share their numerator")
    return sp.Tuple(denominators[1], -denominators[0])


def sign_306(deps) -> sp.Expr:
    """(306): (305) a + wλ < 0 with a > 0 requires wλ < −a < 0: the quantity wλ, claimed negative."""
    existence = derived_of(deps, 304, "existence")
    second = existence[1]
    if sp.simplify(second - (a + wl)) != 0:
        raise ValueError("(305) is not a + wλ < 0")
    return second.subs(a, 0)


def inequality_308(deps) -> sp.Expr:
    """(308): (304) β1 < 0 with β1 of (307) (u > 0): −(u/2)β1/λ = tan(u/2) − u/2, claimed positive."""
    return sp.expand(-u / 2 * derived_of(deps, 307, "beta1") / lam)


def distance_312(_deps) -> sp.Expr:
    """(312): a1 − a = ελ (definition of ε for the inverted blade, (305))."""
    return eps * lam


# ---------------------------------------------------------------- n°101: the period of the inverted uniform blade
def n2_inverted(deps) -> sp.Expr:
    """n°101 applied to n°50: n² of the vibration whose node is z' (the slow one near a1), inverted uniform blade.

    (34) n² = −Kg/z' with g → −g (n°100), z' = −R²/z (31), K of (36) and z the positive root of (30) (n°7), with
    vλ, β1, wλ of (159) turned by u → iu (n°101, as (307), (313)): n² = −Kgz/R²."""
    from pendsym.roots import quadratic_roots
    from ..symbols import K, R, beta1, g, vl, wl, z, zp
    ends = {name: rotated(derived_of(deps, 159, str_name))
            for name, str_name in ((vl, "vl"), (beta1, "beta1"), (wl, "wl"))}
    coeffs = [sp.simplify(c.subs(ends)) for c in ch1_model.foci_quadratic().all_coeffs()]
    plus, _minus = quadratic_roots(sp.Poly(sum(c * z**k for k, c in zip((2, 1, 0), coeffs)), z))
    product, _sum = ch1_model.vieta()
    if sp.simplify(product + R**2) != 0:
        raise ValueError("the product of the foci is not −R² (31)")
    K_36 = ch1_model.K_of_z().subs(ends)
    n2 = (-K * g / zp).subs(g, -g).subs(zp, product / z)
    return n2.subs(K, K_36).subs(z, plus)
