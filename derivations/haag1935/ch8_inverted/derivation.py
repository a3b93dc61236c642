"""Haag 1935, chapter VIII, n°100–103: the inverted blade (g → −g), derived from chapter III's forms.

The memoir's rule (n°101): chapter III's formulas hold with ω → iω, u → iu (M = −λ²/u² < 0), and
chapter VII's with ε → −ε (312).  C (317) is derived apart, from the closed forms of (9)–(10) with a
negative M (trigonometric, by dsolve), not by u → iu.
"""
from __future__ import annotations

import sympy as sp

from pendsym import blade
from .. import ch1_model
from ..common import rid
from ..symbols import a, beta1, lam, mg, s, u, vl, wl
from ..ch7_gravity.symbols import eps


def derived_of(deps, eq: int, name: str) -> sp.Expr:
    return deps[rid(eq, name)].derived


def rotated(expr: sp.Expr) -> sp.Expr:
    """u → iu (n°101), written with circular functions."""
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
