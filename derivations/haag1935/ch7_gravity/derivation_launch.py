"""Haag 1935, chapter VII, n°86, 88–90: g' − g from two periods (269), the launching (274)–(276), the shape
(277) and the fatigue (279) of the gravity pendulum, derived from chapter I's forms with (260), (261), (268).

Each function takes the built dependencies (``deps``, by id) and returns a SymPy expression.
"""
from __future__ import annotations

import sympy as sp

from ..common import rid
from ..symbols import K, K_prime, Y, a, a1, beta1, beta1_positive, g, lam, u, vl, zp
from .symbols import a_r, eps, l_syn

T_g = sp.Symbol("T", positive=True)          # the period (half-period, π²/T² = n²) at g (269)
T_gp = sp.Symbol("T'", positive=True)        # … at g'


def d(deps, eq: int, name: str) -> sp.Expr:
    return deps[rid(eq, name)].derived


# ---------------------------------------------------------------- n°86: (269)
def g_difference_269(deps) -> sp.Expr:
    """(269): (268) is π²/T² = c·g + (a term free of g); at g and g' the difference gives g' − g =
    π²(1/T'² − 1/T²)/c, c = (1/l)(1 + λ/(3a)); with a = a1 + ελ → −λ/u² (a1 = −wλ (159)) as u → 0, cl → 1."""
    period = sp.expand(d(deps, 268, "period"))
    c = sp.diff(period, g)
    if sp.simplify(period - c * g).has(g):
        raise ValueError("(268) is not linear in g")
    a_leading = -sp.series(d(deps, 159, "wl"), u, 0, 0).removeO()                # a1 = −λ/u² + …, a = a1 + ελ
    if sp.simplify(a_leading + lam / u**2) != 0:
        raise ValueError(f"a1 of (159) does not start with −λ/u² ({a_leading})")
    factor = sp.limit(sp.simplify(c * l_syn).subs(a_r, a_leading), u, 0)
    return l_syn * sp.pi**2 * (1 / T_gp**2 - 1 / T_g**2) / factor


# ---------------------------------------------------------------- n°88: (274)–(276)
def amplitude_274(deps) -> sp.Expr:
    """(274), A: (68) A = QF'B/(Kmg) with K = ελ/(z − z') (260)."""
    return sp.factor(d(deps, 68, "A").subs(K, d(deps, 260, "K_foci")))


def amplitude_prime_274(deps) -> sp.Expr:
    """(274), A': (68) with F ↔ F', K' = (z' − z)/β1 (261)."""
    return sp.factor(d(deps, 68, "Ap").subs(K_prime, d(deps, 261, "Kp")))


def ratio_275(deps) -> sp.Expr:
    """(275): A/A' of (274)."""
    return sp.factor(d(deps, 274, "A") / d(deps, 274, "Ap"))


def ratio_276(deps) -> sp.Expr:
    """(276): (73) with a − a1 = ελ (256) and a + z − vλ = z − z' at its leading order in ε: by (33),
    (a + z − vλ)(a + z' − vλ) = −β1(a + wλ) = −β1ελ, so that a + z' − vλ = O(ε), vλ → a + z'.  β1 > 0 (17)."""
    expr = d(deps, 73, "ratio").subs(a1, a - eps * lam).subs(vl, a + zp)
    return sp.factor(expr.subs(beta1, beta1_positive))


# ---------------------------------------------------------------- n°89–90: (277), (279)
def shape_277(deps) -> sp.Expr:
    """(277): (77) with Y → 0 (Y = Kθ, K = O(ε) by (260): the pendulum not struck near F')."""
    return d(deps, 77, "y").subs(Y, 0)


def fatigue_279_I(deps) -> sp.Expr:
    """(279), first form: (78) T' = (mge/2I)(Yv + θw) with Y → 0."""
    return d(deps, 78, "T_I").subs(Y, 0)


def fatigue_279_M(deps) -> sp.Expr:
    """(279), second form: (78) T' = E(e/2)(Yv + θw)/M with Y → 0."""
    return d(deps, 78, "T_M").subs(Y, 0)
