"""Haag 1935, chapter VI, n°68–77: the short blade, derived step by step from chapters I and III.

Each function takes the built dependencies (``deps``, by id) and returns a SymPy
expression: the series in λ/a of a result of chapter I (any M(s)) or of chapter III
(the uniform blade), by :mod:`.expansion`.  Nothing here is typed in from chapter VI.
Where Haag "neglects R² before a²", R is set to 0 (l = a) in the expanded form.
"""
from __future__ import annotations

import sympy as sp

from ..common import rid
from ..symbols import G_2, K, R, a, beta1, beta1_positive, g, k, lam, u, v0, vl, w0, wl, z, zp
from ..symbols import Fn, Gn, x_fork
from .expansion import F_2, leading, root_series, truncated

L_OF_A = a + R**2 / a          # (213)


def d(deps, eq: int, name: str) -> sp.Expr:
    return deps[rid(eq, name)].derived


# ---------------------------------------------------------------- n°68: (212)–(215)
def length_213(deps=None) -> sp.Expr:
    """(213): l = a + R²/a, the length of the synchronous pendulum about A (definition)."""
    return L_OF_A


def rhs_212(deps) -> sp.Expr:
    """(212): (30) rewritten as (z + a)(z − R²/a) = right member; the right member is
    (z + a)(z − R²/a) − [the monic quadratic (30)] (an exact rewriting)."""
    quadratic = d(deps, 30, "quadratic")
    return sp.factor(sp.expand((z + a) * (z - R**2 / a) - quadratic), z)


def reduced_212(deps) -> sp.Expr:
    """Right member of (212) over z, to the first order in λ/a ("d'après (18)")."""
    return truncated(sp.cancel(d(deps, 212, "rhs") / z), 1)


def z_214(deps) -> sp.Expr:
    """(214): the root z → R²/a of (30), to the first order in λ/a."""
    return root_series(d(deps, 30, "quadratic"), z, R**2 / a, 1)


def zp_215(deps) -> sp.Expr:
    """(215): the root z' → −a of (30), to the first order in λ/a."""
    return root_series(d(deps, 30, "quadratic").subs(z, zp), zp, -a, 1)


# ---------------------------------------------------------------- n°69: (216)–(220)
def K_216(deps) -> sp.Expr:
    """(216): K of (36) with z of (214), to the first order in λ/a."""
    return truncated(d(deps, 36, "K").subs(z, d(deps, 214, "z")), 1)


def n2_217(deps) -> sp.Expr:
    """(217): n² = −Kg/z' (34) with K of (216) and z' of (215), to the first order in λ/a."""
    return truncated(-d(deps, 216, "K") * g / d(deps, 215, "zp"), 1)


def dl_218(deps) -> sp.Expr:
    """(218): Δl = g/n² − l, n² of (217), to the first order in λ/a."""
    return truncated(g / d(deps, 217, "n2") - L_OF_A, 1)


def dl_219(deps) -> sp.Expr:
    """(219): (218) with R = 0 (l = a), β1 by (22) and w_λ = w_0 − v_λ by (16)."""
    expr = d(deps, 218, "dl").subs(R, 0)
    expr = expr.subs(beta1, d(deps, 22, "beta1"))
    expr = expr.subs(wl, sp.solve(sp.Eq(w0, d(deps, 16, "w0")), wl)[0])
    return sp.expand(expr)


def dl_220(deps) -> sp.Expr:
    """(220): (219) for the uniform blade, v_0 and w_0 of (159)."""
    expr = d(deps, 219, "dl").subs({v0: d(deps, 159, "v0"), w0: d(deps, 159, "w0")})
    return sp.simplify(expr)


def dl_thread_220(deps) -> sp.Expr:
    """n°69: Δl of (220) as u → ∞ (the thread, a rigid pendulum hung at O)."""
    return sp.limit(d(deps, 220, "dl"), u, sp.oo)


def u_root_220(deps) -> sp.Expr:
    """n°69: the u where Δl of (220) vanishes (sign change; mpmath findroot from u = 1)."""
    ratio = sp.simplify(d(deps, 220, "dl") / lam)
    return sp.nsolve(ratio, u, 1, prec=40)


# ---------------------------------------------------------------- n°71: (224)–(226)
def swap_foci(expr: sp.Expr) -> sp.Expr:
    """z ↔ z' (the parasitic vibration: its focus is F, n°8)."""
    return expr.subs({z: zp, zp: z}, simultaneous=True)


def Kp_224(deps) -> sp.Expr:
    """(224): K' = (35) with z ↔ z', z of (214): its leading term in λ/a."""
    return leading(swap_foci(d(deps, 35, "K")).subs(z, d(deps, 214, "z")))


def np2_225(deps) -> sp.Expr:
    """(225): n'² = −K'g/z ((34) with z ↔ z'), K' of (224), z of (214): the leading term."""
    return leading(-d(deps, 224, "Kp") * g / d(deps, 214, "z"))


def ratio_226(deps) -> sp.Expr:
    """(226): n'/n = √(n'²/n²), n'² of (225), n² of (217): the leading term (β1 > 0 (17), so that the
    square root splits)."""
    expr = leading(d(deps, 225, "np2") / d(deps, 217, "n2"))
    return sp.sqrt(expr.subs(beta1, beta1_positive))


def bound_226(deps) -> sp.Expr:
    """(226): n'/n − (l/R)√(a/λ), which the memoir says positive (β1 < λ)."""
    return d(deps, 226, "ratio") - L_OF_A / R * sp.sqrt(a / lam)


# ---------------------------------------------------------------- n°76: (235)–(236)
def S_235(deps) -> sp.Expr:
    """(235): the suppleness (82) S = (a + w_λ + K²β1)/G_2 − 1, its leading term in λ/a."""
    return leading(d(deps, 82, "S").subs(Gn(2), G_2))


def G2_uniform(deps) -> sp.Expr:
    """G_2 = λΓ_2 ((163) with n = 2) of the uniform blade, Γ_2 of (166) at K = 1 (k = 0)."""
    return lam * d(deps, 166, "Gamma2").subs({k: 0, K: 1})


def S_uniform_235(deps) -> sp.Expr:
    """(235), second and third forms: S = a/G_2 with G_2 of the uniform blade at K = 1."""
    return sp.factor(sp.cancel(d(deps, 235, "S").subs(G_2, G2_uniform(deps))))


def u_factor_235(deps) -> sp.Expr:
    """(235): S·λ/(2a), the factor of the uniform blade's suppleness that depends only on u."""
    return sp.simplify(d(deps, 235, "S_uniform") * lam / (2 * a))


def factor_236(deps) -> sp.Expr:
    """(236): S for a given u, over its value (2a/λ)·u: the factor that depends only on u."""
    return sp.simplify(d(deps, 235, "S_uniform") * lam / (2 * a * u))


def value_236(deps) -> sp.Expr:
    """n°76: the factor (236) at u = 4."""
    return sp.N(d(deps, 236, "factor").subs(u, 4), 40)


def growing(expr_deps_id: tuple[int, str]):
    """d/du of a Result (its derived form): positive if the function increases (n°76)."""
    def derive(deps):
        return sp.simplify(sp.diff(d(deps, *expr_deps_id), u))
    return derive


# ---------------------------------------------------------------- n°77: (237)–(240)
def OFp_237_l(deps) -> sp.Expr:
    """n°77: OF' of (83) with z' of (215)."""
    return sp.expand(d(deps, 83, "OFp").subs(zp, d(deps, 215, "zp")))


def OFp_237(deps) -> sp.Expr:
    """(237): the same with l = a (R = 0) and β1 of (22)."""
    return sp.expand(d(deps, 237, "OFp_l").subs(R, 0).subs(beta1, d(deps, 22, "beta1")))


def x_238_root(deps) -> sp.Expr:
    """(238), first form: the small root of (87) in x (F_2, x and a + z' of the order of λ, L of the
    order of a), to the first order in λ/L."""
    shift = sp.Symbol("a+z'", real=True)
    equation = d(deps, 87, "optimum").subs(Fn(2), F_2).subs(zp, shift - a)
    return root_series(equation, x_fork, 0, 1, extra=(shift,)).subs(shift, a + zp)


def x_238(deps) -> sp.Expr:
    """(238), second form: the first form with z' of (215)."""
    return sp.expand(d(deps, 238, "x_root").subs(zp, d(deps, 215, "zp")))


def F2_239(deps) -> sp.Expr:
    """(239): F_2/λ of (169) at K = 1."""
    return sp.simplify(d(deps, 169, "F2").subs(K, 1))


def x_240(deps) -> sp.Expr:
    """n°77: x of (238) for the uniform blade with R = 0 (l = a): F_2 of (239), v_λ, β1 of (159)."""
    expr = d(deps, 238, "x").subs(R, 0).subs(F_2, lam * d(deps, 239, "F2"))
    return sp.simplify(expr.subs({vl: d(deps, 159, "vl"), beta1: d(deps, 159, "beta1")}))


def c_240(deps) -> sp.Expr:
    """(240): c = λ − x."""
    return sp.simplify(lam - d(deps, 240, "x"))


def thin_limit(eq: int, name: str):
    """n°77, u > 4: the leading term of a Result as u → ∞ (th(u/2) → 1, 1/sh u → 0)."""
    def derive(deps):
        expr = d(deps, eq, name).rewrite(sp.exp)
        q = sp.Symbol("q", positive=True)            # q = e^{−u}
        expr = sp.simplify(expr.subs(sp.exp(-u), q).subs(sp.exp(u), 1 / q))
        return sp.simplify(sp.series(expr, q, 0, 1).removeO())
    return derive


# ---------------------------------------------------------------- n°70: (221)
def Q_221(deps) -> sp.Expr:
    """(221): Q = K(z − z') (45) with K, z, z' of (216), (214), (215), to the first order in λ/a,
    with R = 0."""
    expr = d(deps, 45, "Q").subs({K: d(deps, 216, "K"), z: d(deps, 214, "z"), zp: d(deps, 215, "zp")})
    return sp.expand(truncated(expr, 1).subs(R, 0))


def Q_221_ends(deps) -> sp.Expr:
    """(221), second form: β1 by (22), w_λ = w_0 − v_λ by (16)."""
    expr = d(deps, 221, "Q").subs(beta1, d(deps, 22, "beta1"))
    return sp.expand(expr.subs(wl, sp.solve(sp.Eq(w0, d(deps, 16, "w0")), wl)[0]))


# ---------------------------------------------------------------- n°70: (222)–(223)
def dT_222(deps) -> sp.Expr:
    """(222): dT/T per degree (60) with K of (216), to the first order in λ/a (M_λ of the order of λ²,
    G_2 of λ), with R = 0; β1 by (22), w_λ = w_0 − v_λ by (16)."""
    expr = d(deps, 60, "dT").subs(K, d(deps, 216, "K"))
    expr = truncated(expr, 1).subs(R, 0)
    expr = expr.subs(beta1, d(deps, 22, "beta1"))
    return sp.expand(expr.subs(wl, sp.solve(sp.Eq(w0, d(deps, 16, "w0")), wl)[0]))


def dT_223(deps) -> sp.Expr:
    """(223): (222) for the uniform blade: v_0, w_0 of (159), M_λ = λ²/u² (156), G_2 = λΓ_2 at K = 1 (166)."""
    from ..symbols import M_lambda
    expr = d(deps, 222, "dT").subs({v0: d(deps, 159, "v0"), w0: d(deps, 159, "w0"), M_lambda: lam**2 / u**2,
                                    G_2: G2_uniform(deps)})
    return sp.expand(expr)


# ---------------------------------------------------------------- n°71: (227)–(228)
def focal_ratio() -> sp.Expr:
    """FB/F'B = (b − a − z)/(b − a − z'): the foci at AF = a + z, AF' = a + z' (n°7), B at AB = b."""
    from ..symbols import b
    return (b - a - z) / (b - a - zp)


def amplitude_ratio(eq: int):
    """A'/A = 1/(A/A') of (69) (eq = 69, static release) or (73) (eq = 73, blow), a1 = −w_λ (41), with the
    factor FB/F'B kept and the rest (free of b) at its leading order in λ/a, z, z' of (214), (215)."""
    def derive(deps):
        rest = sp.simplify(1 / d(deps, eq, "ratio") / focal_ratio())
        rest = rest.subs(a1_symbol(), d(deps, 41, "a1")).subs({z: d(deps, 214, "z"), zp: d(deps, 215, "zp")},
                                                               simultaneous=True)
        rest = leading(rest)
        return focal_ratio() * (rest.subs(beta1, beta1_positive) if rest.has(sp.sqrt(beta1)) else rest)
    return derive


def a1_symbol():
    from ..symbols import a1
    return a1


def ratio_228_227(deps) -> sp.Expr:
    """n°71: (228) over (227)."""
    ratio = d(deps, 228, "ratio") / d(deps, 227, "ratio")
    return sp.simplify(ratio.subs(beta1, beta1_positive))


# ---------------------------------------------------------------- n°73, 75: (232)
THETA_0 = sp.Symbol("theta_0", positive=True)     # amplitude θ0 of the principal oscillation


def fatigue_232(deps) -> sp.Expr:
    """(232): T' of the principal oscillation (178) at the fixed clamp s = 0, K = 1 (n°75: "K est voisin de
    l'unité"), amplitude θ0."""
    from ..symbols import s, theta
    return sp.simplify(d(deps, 178, "Tprime").subs({s: 0, K: 1, theta: THETA_0}))


# ---------------------------------------------------------------- n°70: the orders of P_λ and G_2
def P_bound_70(deps) -> sp.Expr:
    """n°70: μw_0/λ − P_λ, P_λ = (59) at s = λ with K = 1 and v_λ + w_λ = w_0 (16); the memoir says it positive."""
    from ..ch1_model import ends
    from ..symbols import M_lambda, M_of_s, mu, s
    P = ends(d(deps, 59, "P").subs(K, 1).subs(s, lam)).subs(M_of_s(lam), M_lambda)
    P = sp.simplify(P.subs(wl, sp.solve(sp.Eq(w0, d(deps, 16, "w0")), wl)[0]))
    return mu * w0 / lam - P


def G2_bound_70(deps) -> sp.Expr:
    """n°70: (μ/(λw_0))∫_0^λ (v_0 + w_λ)² ds − G_2, which the memoir says positive."""
    from ..symbols import mu, s
    return sp.simplify(mu / (lam * w0) * sp.integrate((v0 + wl) ** 2, (s, 0, lam))) - G_2


# ---------------------------------------------------------------- n°73: (229)
Q_FORCE = sp.Symbol("Q", real=True)               # the force of the static launch (n°18), as chapter III has it
Q_POSITIVE = sp.Symbol("Q", positive=True)        # … taken positive, as Haag does when he takes the maximum
def fatigue_229(at: str):
    """(229): the largest T'_0 (at = "T0") or T'_λ ("Tl") of (180) after release from the static deviation:
    K = 1, 1/K' = 0 (224), the principal term at t = 0 and the parasitic one at n't = 0 or π, so that the two
    amplitudes add in absolute value."""
    def derive(deps):
        from ..symbols import mg
        n, n_prime, t, K_prime = (sp.Symbol(name, **assumption) for name, assumption in (
            ("n", {"positive": True}), ("n'", {"positive": True}), ("t", {"real": True}), ("K'", {"real": True})))
        expr = sp.expand(d(deps, 180, at).subs(Q_FORCE, Q_POSITIVE))
        principal = expr.coeff(sp.cos(n * t)).subs(K, 1)
        parasitic = sp.limit(expr.coeff(sp.cos(n_prime * t)), K_prime, sp.oo)
        return sp.Abs(sp.factor(principal)) + sp.Abs(sp.factor(parasitic))
    return derive


def fatigue_by_attack(case: str):
    """(230) (case "between": B between F' and F) or (231) ("below": B below F): the first (229) with θ0 of
    (67) (a1 = −w_λ (41)) at its leading order in λ/a, F' at A (z' = −a) and F at G (z = 0, R² ≪ a²); each
    distance taken with the sign of its case (b = a/2, or 3a/2, for the sign only)."""
    def derive(deps):
        from ..symbols import b
        theta0 = leading(d(deps, 67, "theta0").subs(a1_symbol(), d(deps, 41, "a1")).subs(Q_FORCE, Q_POSITIVE))
        force = sp.solve(sp.Eq(THETA_0, theta0), Q_POSITIVE)[0]
        expr = d(deps, 229, "T0").subs({z: 0, zp: -a})
        sample = {a: 1, b: sp.Rational(1, 2) if case == "between" else sp.Rational(3, 2)}
        expr = expr.replace(sp.Abs, lambda x: x * sp.sign(x.subs(sample).subs(Q_POSITIVE, 1)))
        return sp.simplify(expr.subs(Q_POSITIVE, force))
    return derive
