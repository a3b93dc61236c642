"""Haag 1935, chapter VI, n°74 and n°79: the fatigue after a blow (233)–(234) and the isochronism
error of the short blade (242)–(245), derived step by step from chapters I–III.

Each function takes the built dependencies (``deps``, by id) and returns a SymPy expression: the
series in λ/a (:mod:`.expansion`) of a derived result of chapter II or III.  Nothing here is typed
in from chapter VI.
"""
from __future__ import annotations

import sympy as sp

from ..ch3_uniform.launch_symbols import K_prime, n_parasitic, stress_scale, t
from ..ch3_uniform.launch_symbols import V, m, m_striking, restitution
from ..common import rid
from ..symbols import DEFS, K, R, U, U1, U2, a, b, beta1, beta1_positive, g, lam, u, v0, vl, w0, wl, z, zp
from ..symbols import Fn, Q as Q_symbol
from .expansion import F_2, leading, truncated

THETA = sp.Symbol("Theta", real=True)          # Θ of (234)
F_HAAG = sp.Symbol("F", real=True)             # F = H(K, 1) = 4KF_3 − F_4 of (110), a length
Q_PRIME = sp.Symbol("Q'", real=True)           # Q' of (112)
theta_0 = sp.Symbol("theta_0", positive=True)  # amplitude of the principal oscillation (111)
SHOCK_DENOMINATOR = (a - b) ** 2 + R**2 * (1 + m / m_striking)


def d(deps, eq: int, name: str) -> sp.Expr:
    return deps[rid(eq, name)].derived


# ---------------------------------------------------------------- n°74: (233)–(234)
def parasitic_amplitude(deps, at: str) -> sp.Expr:
    """The coefficient of sin n't in T'_0 (at = "T0") or T'_λ ("Tl") of (181), with K' of (224), z of (214)
    and z' of (215), at its leading order in λ/a."""
    coefficient = sp.expand(d(deps, 181, at)).coeff(sp.sin(n_parasitic * t))
    coefficient = coefficient.subs(K_prime, d(deps, 224, "Kp"))
    coefficient = coefficient.subs({z: d(deps, 214, "z"), zp: d(deps, 215, "zp")}, simultaneous=True)
    return leading(coefficient)


def focal_distance() -> sp.Expr:
    """BF = a + z − b (B at AB = b, F at GF = z), the distance of the point struck to the focus F."""
    return a + z - b


def fatigue_233(deps) -> sp.Expr:
    """(233): the largest fatigue after a blow, the amplitude of the parasitic (sin n't) term of (181) at
    its leading order in λ/a; a(a + R²/a − b) is written a·BF, R²/a being z at its leading order (214).
    Both formulas (181) give it (T'_λ with the opposite sign: "simultanément aux deux encastrements")."""
    at_O, at_A = parasitic_amplitude(deps, "T0"), parasitic_amplitude(deps, "Tl")
    if sp.simplify(at_O + at_A) != 0:
        raise ValueError("the parasitic amplitudes of T'_0 and T'_λ differ")
    leading_focus = leading(d(deps, 214, "z"))                                                 # R²/a
    rest = sp.factor(sp.simplify(at_O / (a + leading_focus - b)))
    if sp.simplify(rest * SHOCK_DENOMINATOR).has(b):
        raise ValueError("the amplitude is not proportional to BF")
    return rest * focal_distance()


def theta_234(deps) -> sp.Expr:
    """(234), first form: Θ = (233) over √(3ET)(1 + h)V/((a − b)² + R²(1 + m/m'))."""
    factor = stress_scale * (1 + restitution) * V / SHOCK_DENOMINATOR
    return sp.factor(sp.simplify(d(deps, 233, "Tprime") / factor))


def theta_234_g(deps) -> sp.Expr:
    """(234), second form: n' of (225) with R² neglected before a² (l = a, as from (219) on); β1 > 0 (17)."""
    n2p = d(deps, 225, "np2")
    n2p = sp.limit(n2p * R**2, R, 0) / R**2
    expr = d(deps, 234, "Theta").subs(n_parasitic, sp.sqrt(n2p.subs(beta1, beta1_positive)))
    return sp.simplify(expr.subs(beta1, beta1_positive))


# ---------------------------------------------------------------- n°79: (242)–(245)
def first_order(expr: sp.Expr) -> sp.Expr:
    """The series of expr in λ/a to the first order, F (110) counted as a length of the blade like F_2."""
    from .expansion import DELTA, scaled, tidy
    series = sp.series(scaled(expr, (F_HAAG,)), DELTA, 0, 2).removeO()
    return tidy(sp.expand(series).subs(DELTA, 1))


def ratio_242(deps) -> sp.Expr:
    """(242): Q'/Q, Q' of (112) with F_4 = 4KF_3 − F (110), K of (216), z' of (215), Q of (221), to the first
    order in λ/a with R = 0 (λ², R² neglected before a²); β1 by (22) and w_λ = w_0 − v_λ by (16)."""
    F4 = sp.solve(sp.Eq(F_HAAG, d(deps, 110, "F")), Fn(4))[0]
    Q_prime = d(deps, 112, "Qp").subs(Fn(4), F4).subs(Fn(2), F_2)
    Q_prime = Q_prime.subs({K: d(deps, 216, "K"), zp: d(deps, 215, "zp")}, simultaneous=True).subs(R, 0)
    Q = d(deps, 221, "Q")
    expr = first_order(Q_prime / Q)
    if expr.has(Fn(3)):
        raise ValueError("F_3 is left in Q'/Q")
    expr = expr.subs(beta1, d(deps, 22, "beta1"))
    expr = expr.subs(wl, sp.solve(sp.Eq(w0, d(deps, 16, "w0")), wl)[0])
    return sp.collect(sp.expand(expr), a)


def F_243(deps) -> sp.Expr:
    """(243): F/λ of the uniform blade, (170) at K = 1."""
    return sp.simplify(d(deps, 170, "F").subs(K, 1))


def dT_244(deps) -> sp.Expr:
    """(244): ΔT/T = (Q'/Q)θ0²/16 (111) with Q'/Q of (242) for the uniform blade: v_0, w_0 of (159),
    F_2 = λ·(239), F = λ·(243).  The factor θ0²/16 is read off (111) over (112)/(45)."""
    factor = sp.simplify(d(deps, 111, "dT") * d(deps, 45, "Q") / d(deps, 112, "Qp"))
    if factor.free_symbols != {theta_0}:
        raise ValueError(f"(111) is not (Q'/Q)·{factor}")
    ratio = d(deps, 242, "ratio").subs({v0: d(deps, 159, "v0"), w0: d(deps, 159, "w0"),
                                        F_2: lam * d(deps, 239, "F2"), F_HAAG: lam * d(deps, 243, "F")})
    return factor * (1 + sp.simplify(sp.expand(ratio) - 1))


def exponentially_small_dropped(expr: sp.Expr) -> sp.Expr:
    """expr with th(u/2) = (1 − q)/(1 + q), q = e^{−u}, at q = 0 (the thin blade, u > 4: the terms in e^{−u}
    are dropped, the powers of 1/u kept)."""
    q = sp.Symbol("q", positive=True)
    half = (1 - q) / (1 + q)                       # th(u/2)
    table = {sp.tanh(u / 2): half, sp.tanh(u): 2 * half / (1 + half**2), sp.sinh(u): 2 * half / (1 - half**2),
             sp.cosh(u): (1 + half**2) / (1 - half**2)}
    expr = sp.sympify(expr).subs(table)
    if expr.has(sp.tanh, sp.sinh, sp.cosh, sp.exp):
        raise ValueError("a hyperbolic function of u is left")
    return sp.expand(sp.limit(expr, q, 0))


def dT_245(deps) -> sp.Expr:
    """(245): (244) for u > 4, the terms in e^{−u} dropped."""
    return exponentially_small_dropped(d(deps, 244, "dT"))


# ---------------------------------------------------------------- n°78: (241)
def f_241(deps) -> sp.Expr:
    """(241): f = −(n²/K)[bracket of (104)] for a perturbation proper (forces on the pendulum only: no increment
    ε(s) of the blade's moment, so E_1 = E_2 = ε_λ = 0), K of (216), z' of (215), R = 0, the blade's moments
    J(i, j) = ∫φ1^iφ2^j ds counted as lengths of the blade: the leading term in λ/a ("en négligeant λ devant a")."""
    from ..ch2_common import J, eps_lambda
    from ..symbols import n_squared
    from .expansion import DELTA
    bracket = d(deps, 104, "f").subs({sp.Symbol("E_1"): 0, sp.Symbol("E_2"): 0, eps_lambda: 0})
    moments = sorted(bracket.atoms(J), key=sp.default_sort_key)
    bracket = bracket.subs({moment: DELTA * moment for moment in moments}, simultaneous=True)
    bracket = bracket.subs({K: d(deps, 216, "K"), zp: d(deps, 215, "zp")}, simultaneous=True).subs(R, 0)
    f = -n_squared / K * bracket
    f = f.subs(K, d(deps, 216, "K").subs(R, 0))
    return sp.expand(leading(f).subs(DELTA, 1))
