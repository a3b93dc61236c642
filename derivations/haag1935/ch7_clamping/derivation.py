"""Haag 1935, chapter VII, n°94–95, eqs. (286)–(290), and chapter VIII, n°103, eq. (318): the gravity pendulum's
clamping errors, derived step by step from chapter II's derived (117), (118), (127), (132), (133) and chapter VII's
derived (256)–(262), then chapter III's uniform blade (159), (169), (170); (318) from (289) by u → iu, ε → −ε.

Each function takes the built dependencies (``deps``, by id) and returns a SymPy expression.  The limit ε → 0
(a = a1 + ελ (256)) is taken as a SymPy series in ε after K of (260) and z' of (257) are put in (a kept in Q1, as
Haag keeps it, then a = a1 + ελ, a1 = −wλ (41)); the two regimes of n°95 differ by the order of j:

- not regulated (n°94–95, (286)): i, i' finite and j = ĵ/ε (j holds the factor 1/ε, (117)): the leading term,
  of order ε^{-2} in Q1;
- regulated ((288)–(289)): i, i', j of the same order: the leading term of Q1, of order ε^0.

The blade's integrals stay moments J(p, q) = ∫φ1^pφ2^q ds (:mod:`..ch2_common`) until the last step, where they
become F_n at K = 0 (F_n(0) = J(0, n)) or the A_p of (287) (the coefficients of F = 4KF_3 − F_4 (110) in K).
"""
from __future__ import annotations

import sympy as sp

from ..ch2_common import F_moments, J, h_127, h_132, i_clamp, i_prime, j_eq
from ..common import rid
from ..symbols import G, G_2, Fn, K, a, a1, lam, u, vl, w0, wl, z, zp
from ..ch7_gravity.symbols import C_s, a_r, eps

A_p = sp.symbols("A_0:5", real=True)            # F = Σ A_p K^p (287)
j_hat = sp.Symbol("hat_j", real=True)          # εj: j of the pendulum that is not regulated, j = ĵ/ε (n°95)
HALF = sp.Symbol("t", positive=True)           # th(u/2) in (289), tan(u/2) in (318)


def derived_of(deps, eq: int, name: str) -> sp.Expr:
    return deps[rid(eq, name)].derived


def leading(expr: sp.Expr, power: int) -> sp.Expr:
    """The coefficient of ε^power in the expansion of expr as ε → 0; raises if a lower power (down to ε^{power−4})
    is present."""
    series = sp.expand(sp.series(sp.expand(expr), eps, 0, power + 1).removeO())
    for k in range(power - 4, power):
        if sp.simplify(series.coeff(eps, k)) != 0:
            raise ValueError(f"a term of order ε^{k} precedes ε^{power}")
    return sp.simplify(series.coeff(eps, power))


# ---------------------------------------------------------------- Q1 near the critical distance
def Q1_in_moments(deps) -> sp.Expr:
    """Q1 of (133) with h of (127) and h' of (132) in moments (their definitions, derived in chapter II)."""
    Q1 = derived_of(deps, 133, "Q1")
    return Q1.subs({h_127: derived_of(deps, 127, "h"), h_132: derived_of(deps, 132, "hp")}, simultaneous=True)


def near_critical(deps, expr: sp.Expr) -> sp.Expr:
    """expr near a1 (a − a1 = ελ (256)): K of (260) and z' of (257) (the slow mode's focus), both O(ε) and
    w0 + O(ε); a itself kept, as Haag keeps it in Q1 (it becomes a1 = −wλ in (286), (288))."""
    return sp.sympify(expr).subs({K: derived_of(deps, 260, "K"), zp: derived_of(deps, 257, "zp")}, simultaneous=True)


def to_a1(deps, expr: sp.Expr) -> sp.Expr:
    """expr with a = a1 + ελ (256) and a1 = −wλ (41)."""
    return expr.subs(a, a1 + derived_of(deps, 256, "epsilon")).subs(a1, derived_of(deps, 41, "a1"))


def at_rest(expr: sp.Expr) -> sp.Expr:
    """Moments J(0, n) written as F_n at K = 0 (F_n(0) = ∫φ2^n ds, (79)); raises if a moment with φ1 remains."""
    expr = sp.expand(expr)
    rest = [m for m in expr.atoms(J) if int(m.args[0]) != 0]
    if rest:
        raise ValueError(f"not a function of the F_n at K = 0: {rest}")
    return expr.xreplace({m: Fn(int(m.args[1])) for m in expr.atoms(J)})


# ---------------------------------------------------------------- n°94: the tilt of the equilibrium
def tilt_G(deps) -> sp.Expr:
    """n°94: j' of (118) with a − a1 = ελ (256) = G2/G (262): j' = G(w0 i − a i')/G2."""
    jp = derived_of(deps, 118, "j_prime")
    G262 = derived_of(deps, 262, "G")
    eps_of_G = sp.solve(sp.Eq(G262, G), eps)[0]                  # ε = G2/(λG)
    gap = derived_of(deps, 256, "epsilon").subs(eps, eps_of_G)    # a − a1 = G2/G
    return sp.factor(jp.subs(a1, a - gap)).subs(a, a_r)


# ---------------------------------------------------------------- n°95: the pendulum not regulated, (286)
def Q1_286(deps) -> sp.Expr:
    """n°95: Q1 of (133) with j = ĵ/ε ((117): j holds 1/ε), K (260), z' (257): the leading term (ε^{-2}), then
    ĵ = εj and F_n at K = 0."""
    expr = near_critical(deps, Q1_in_moments(deps)).subs(j_eq, j_hat / eps)
    lead = leading(sp.expand(expr * eps**2), 0).subs(j_hat, j_eq)
    return sp.factor(at_rest(lead))


def Q1_286_C(deps) -> sp.Expr:
    """n°95: Q1 = −(j²/4)CG2: the first form with a = a1 + ελ, a1 = −wλ (the ελj²/4 is of order ε^{-1}, below
    the leading ε^{-2}) and wλ − F_4 = CG2 (284, F_4 at K = 0)."""
    Q1 = to_a1(deps, derived_of(deps, 286, "Q1")).subs(j_eq, j_hat / eps)
    Q1 = leading(sp.expand(Q1 * eps**2), 0).subs(j_hat, j_eq)
    return sp.factor(sp.expand(Q1.subs(Fn(4), wl - C_s * G_2)))


def dT_286(deps) -> sp.Expr:
    """(286): ΔT/T = Q1/Q (134), Q = K(z − z') (45) with K = ελ/(z − z') (260), and G2 = ελG (262)."""
    Q = derived_of(deps, 45, "Q").subs(K, derived_of(deps, 260, "K_foci"))
    G2_of_G = sp.solve(sp.Eq(derived_of(deps, 262, "G"), G), G_2)[0]
    return sp.factor(sp.simplify((derived_of(deps, 286, "Q1_C") / Q).subs(G_2, G2_of_G)))


# ---------------------------------------------------------------- n°95: the pendulum regulated, (287)–(289)
def A_of_moments() -> dict:
    """(287): A_p, the coefficient of K^p in F = 4KF_3 − F_4 (110), F_n = ∫(Kφ1 + φ2)^n ds, in moments."""
    F = sp.Poly(sp.expand(4 * K * F_moments(3) - F_moments(4)), K)
    return {A_p[k]: F.coeff_monomial(K**k) for k in range(5)}


def hp_287(deps) -> sp.Expr:
    """n°95: h' of (132) at K = 0 (K → 0 with ε, (260)), its moments written in A_0, A_1, A_2 of (287);
    raises if a moment is left over."""
    hp = sp.expand(derived_of(deps, 132, "hp").subs(K, 0))
    A = A_of_moments()
    unknowns = sorted(hp.atoms(J), key=sp.srepr)
    eqs = [sp.Eq(A_p[k], A[A_p[k]]) for k in range(3)]
    for trial in sp.utilities.iterables.subsets(unknowns, 3):
        sol = sp.solve(eqs, list(trial), dict=True)
        if sol:
            out = sp.expand(hp.subs(sol[0]))
            if not out.atoms(J):
                return sp.collect(out, (i_clamp, j_eq))
    raise ValueError(f"h' at K = 0 is not a combination of A_0, A_1, A_2: {hp}")


def Q1_288(deps) -> sp.Expr:
    """n°95: 4Q1, Q1 of (133) with i, i', j finite, K (260), z' (257): the leading term (ε^0); h (127) in moments,
    h' (132) and F_2 (their symbols) taken at K = 0."""
    expr = near_critical(deps, derived_of(deps, 133, "Q1").subs(h_127, derived_of(deps, 127, "h")))
    return sp.collect(sp.expand(4 * leading(expr, 0)), a, sp.factor)


def dT_288(deps) -> sp.Expr:
    """(288): ΔT/T = Q1/Q (134), 4Q1 of n°95 with h' of (287), Q = K(z − z') (45) with K = ελ/(z − z') (260),
    a = a1 + ελ (256) and a1 = −wλ (41): the leading term (ε^{-1})."""
    Q = derived_of(deps, 45, "Q").subs(K, derived_of(deps, 260, "K_foci"))
    Q1 = derived_of(deps, 288, "Q1").subs(h_132, derived_of(deps, 287, "hp")) / 4
    numerator = sp.expand(leading(sp.expand(to_a1(deps, Q1) / Q * eps), 0) * 4 * lam)
    return sp.collect(numerator, wl, sp.factor) / (4 * eps * lam)


def uniform_rest(deps) -> dict:
    """The uniform blade's wλ (159), F_2 at K = 0 (λ·(169)) and A_0, A_1, A_2 (λ times the coefficients of K^p
    in (170))."""
    F = sp.Poly(sp.expand(derived_of(deps, 170, "F")), K)
    table = {A_p[k]: lam * F.coeff_monomial(K**k) for k in range(3)}
    table.update({wl: derived_of(deps, 159, "wl"), Fn(2): lam * derived_of(deps, 169, "F2").subs(K, 0)})
    return table


def dT_289(deps) -> sp.Expr:
    """(289): (288) for the uniform blade, wλ of (159), F_2 (169) and A_p (170) at K = 0 (n°95: "en se reportant à
    (170) pour les coefficients A_p"), in th(u/2) and u."""
    expr = derived_of(deps, 288, "dT").subs(uniform_rest(deps), simultaneous=True)
    expr = expr.subs(sp.tanh(u), 2 * sp.tanh(u / 2) / (1 + sp.tanh(u / 2) ** 2)).subs(sp.tanh(u / 2), HALF)
    return by_errors(expr).subs(HALF, sp.tanh(u / 2))



def by_errors(expr: sp.Expr) -> sp.Expr:
    """A quadratic form in i, i', j, each coefficient (rational in ``HALF`` and u) factored."""
    poly = sp.Poly(sp.expand(expr), i_clamp, i_prime, j_eq)
    return sp.Add(*(sp.factor(sp.cancel(c)) * i_clamp**e[0] * i_prime**e[1] * j_eq**e[2] for e, c in poly.terms()))


# ---------------------------------------------------------------- n°95: the symmetric pendulum, (290)
def i_290(deps) -> sp.Expr:
    """(290): (117) with i' = 0 ("la pendule bien symétrique") at a = a1 + ελ (256), a1 = −wλ (41), solved for i;
    its leading term in ε, with vλ = w0 − wλ (16)."""
    j117 = derived_of(deps, 117, "j").subs(i_prime, 0)
    j117 = j117.subs(a, a1 + derived_of(deps, 256, "epsilon")).subs(a1, derived_of(deps, 41, "a1"))
    i_of_j = sp.solve(sp.Eq(j117, j_eq), i_clamp)[0]
    return sp.factor(leading(i_of_j.subs(vl, w0 - wl), 1) * eps)


def reduction_290(deps) -> sp.Expr:
    """n°95 after (290): the terms in j² of (288), with A_0 = −F_4 at K = 0 ((287): F = 4KF_3 − F_4 at K = 0),
    wλ − F_4 = CG2 (284) and G2 = ελG (262), minus (286): 0 when (288) reduces to (286)."""
    part = sp.Poly(derived_of(deps, 288, "dT"), i_clamp, i_prime, j_eq).coeff_monomial(j_eq**2) * j_eq**2
    A0 = at_rest(A_of_moments()[A_p[0]].subs(K, 0))
    G2_of_G = sp.solve(sp.Eq(derived_of(deps, 262, "G"), G), G_2)[0]
    part = part.subs(A_p[0], A0).subs(Fn(4), wl - C_s * G_2).subs(G_2, G2_of_G)
    return sp.simplify(part - derived_of(deps, 286, "dT"))


# ---------------------------------------------------------------- n°103: (318)
def dT_318(deps) -> sp.Expr:
    """(318): (289) with u → iu (M = λ²/u² → −λ²/u², n°101) and ε → −ε (312): th(u/2) = t → i·tan(u/2) with
    u → iu in the rational form of (289); raises if an imaginary part is left."""
    expr = derived_of(deps, 289, "dT").subs(sp.tanh(u / 2), HALF)
    expr = sp.expand(expr.subs({HALF: sp.I * HALF, u: sp.I * u}, simultaneous=True).subs(eps, -eps))
    out = by_errors(expr)
    if out.has(sp.I):
        raise ValueError("(289) with u → iu is not real")
    return out.subs(HALF, sp.tan(u / 2))
