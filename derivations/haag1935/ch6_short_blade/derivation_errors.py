"""Haag 1935, chapter VI, n°80–81: the clamping errors (246)–(250) and the inertia and weight of the
blade (251)–(254) of the short blade, derived step by step from chapters I–III.

Each function takes the built dependencies (``deps``, by id) and returns a SymPy expression: the
leading term in λ/a (:mod:`.expansion`) of a derived result of chapter II, then the uniform blade
(chapter III) and the thin blade (u > 5: the terms in e^{−u} dropped).  Nothing here is typed in
from chapter VI.  R is set to 0 ("négligeant R² devant a²").
"""
from __future__ import annotations

import sympy as sp

from ..ch2_common import J, h_127, h_132, i_clamp, i_prime, j_eq
from ..common import rid
from ..symbols import Fn, K, R, a, a1, beta1, lam, v0, vl, w0, wl, z, zp
from .derivation_perturbations import exponentially_small_dropped
from .expansion import leading

C = sp.symbols("c0:5")        # the coefficients of F = 4KF_3 − F_4 (110) in powers of K: F = Σ c_k K^k


def d(deps, eq: int, name: str) -> sp.Expr:
    return deps[rid(eq, name)].derived


def short(deps, expr: sp.Expr) -> sp.Expr:
    """expr with K of (216), z of (214), z' of (215), all at R = 0."""
    table = {K: d(deps, 216, "K"), z: d(deps, 214, "z"), zp: d(deps, 215, "zp")}
    return sp.sympify(expr).subs(table, simultaneous=True).subs(R, 0)


def with_w0(expr: sp.Expr) -> sp.Expr:
    """expr with v_λ = w_0 − w_λ (16)."""
    return sp.expand(expr.subs(vl, w0 - wl))


# ---------------------------------------------------------------- n°80: (246)–(250)
def sum_246(deps) -> sp.Expr:
    """(246): j + i + i', j of (117) with a1 = −w_λ (41), at its leading order in λ/a; v_λ by (16)."""
    j = d(deps, 117, "j").subs(a1, d(deps, 41, "a1"))
    return sp.collect(with_w0(leading(j + i_clamp + i_prime)), a)


def sum_247(deps) -> sp.Expr:
    """(247): (246) for the uniform blade, w_0, w_λ of (159)."""
    return sp.factor(d(deps, 246, "sum").subs({w0: d(deps, 159, "w0"), wl: d(deps, 159, "wl")}))


def Q1_248(deps) -> sp.Expr:
    """(248): Q1 of (133) with j of (117) (a1 = −w_λ), K, z, z' of (214)–(216), R = 0, at its leading order in
    λ/a; h (127), h' (132) and F_2 counted as lengths of the blade (h/a = O(λ/a))."""
    j = d(deps, 117, "j").subs(a1, d(deps, 41, "a1"))
    expr = short(deps, d(deps, 133, "Q1").subs(j_eq, j))
    expr = leading(expr, extra=(h_127, h_132, Fn(2)))
    expr = with_w0(expr.subs(beta1, d(deps, 22, "beta1")))
    return sp.collect(expr, (h_127, h_132, Fn(2)))


def moments(deps) -> dict:
    """J(i, j)/λ of the uniform blade read off the polynomials in K of (169) (F_2 = Σ C(2, i)K^iJ(i, 2 − i))
    and (170) (F = 4KF_3 − F_4, its coefficients c_k): J(2,0), J(1,1), J(0,2), and J(3,0), J(2,1), J(1,2),
    J(0,3), J(0,4) in c_k and the J(i, 4 − i) that (132) does not need alone."""
    F2 = sp.Poly(sp.expand(d(deps, 169, "F2")), K)
    table = {J(2, 0): F2.coeff_monomial(K**2), J(1, 1): F2.coeff_monomial(K) / 2, J(0, 2): F2.coeff_monomial(1)}
    F = sum(sp.binomial(3, p) * 4 * K * K**p * J(p, 3 - p) for p in range(4)) \
        - sum(sp.binomial(4, p) * K**p * J(p, 4 - p) for p in range(5))
    F = sp.Poly(sp.expand(F), K)
    unknowns = (J(0, 4), J(0, 3), J(1, 2), J(2, 1), J(3, 0))
    solved = sp.solve([F.coeff_monomial(K**k) - C[k] for k in range(5)], unknowns, dict=True)[0]
    return table, solved


def dT_249(deps) -> sp.Expr:
    """(249): ΔT/T = Q1/Q (134), Q1 of (248), Q of (221) at its leading order (a), for the uniform blade:
    h of (127) and h' of (132) at K = 1 with the moments of (169)–(170), v_0 of (159), F_2 = λ·(239)."""
    table, solved = moments(deps)
    hp = sp.expand(d(deps, 132, "hp").subs(K, 1).subs(solved))
    if hp.atoms(J):
        raise ValueError(f"h' needs moments that (170) does not give: {hp.atoms(J)}")
    F = sp.Poly(sp.expand(d(deps, 170, "F")), K)
    hp = hp.subs({C[k]: F.coeff_monomial(K**k) for k in range(5)})
    h = d(deps, 127, "h").subs(K, 1).subs(table)
    Q = leading(d(deps, 221, "Q"))
    expr = (d(deps, 248, "Q1") / Q).subs({h_127: lam * h, h_132: lam * hp, Fn(2): lam * d(deps, 239, "F2"),
                                         v0: d(deps, 159, "v0")}, simultaneous=True)
    if expr.has(i_prime):
        raise ValueError("i' is left in (249)")
    return sp.collect(sp.expand(sp.simplify(expr)), (i_clamp, j_eq), sp.simplify)


def dT_250(deps) -> sp.Expr:
    """(250): (249) for u > 5, the terms in e^{−u} dropped."""
    return sp.factor(exponentially_small_dropped(d(deps, 249, "dT")))


# ---------------------------------------------------------------- n°81: (251)–(254)
def inertia_251(deps) -> sp.Expr:
    """(251): (135) with I_λ of (182), K of (216), z, z' of (214)–(215), R = 0, at its leading order in λ/a
    (K → 1: "en faisant K = 1 dans (182)")."""
    from ..ch2_perturbations.derivation import I_lambda
    rest = sp.cancel(d(deps, 135, "inertia") / I_lambda)
    if rest.has(I_lambda):
        raise ValueError("(135) is not proportional to I_λ")
    # the leading term of a product: I_λ (exactly O(λ²)) at the leading K, times the leading rest
    inertia = d(deps, 182, "I").subs(K, leading(d(deps, 216, "K").subs(R, 0)))
    return sp.expand(leading(short(deps, rest)) * inertia)


def inertia_252(deps) -> sp.Expr:
    """(252): (251) for u > 5, the terms in e^{−u} dropped."""
    return sp.factor(exponentially_small_dropped(d(deps, 251, "dT")))


def weight_253(deps) -> sp.Expr:
    """(253): (136) with J of (183), K of (216), Q of (221), R = 0, at its leading order in λ/a."""
    from ..ch2_perturbations.derivation import J_w
    from ..symbols import Q
    expr = d(deps, 136, "weight").subs({J_w: d(deps, 183, "J"), Q: d(deps, 221, "Q")}, simultaneous=True)
    return sp.simplify(leading(short(deps, expr)))


def weight_254(deps) -> sp.Expr:
    """(254): (253) for u > 5, the terms in e^{−u} dropped."""
    return sp.factor(exponentially_small_dropped(d(deps, 253, "dT")))
