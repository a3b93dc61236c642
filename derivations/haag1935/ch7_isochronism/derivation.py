"""Haag 1935, chapter VII, n°92–93 and n°97: chapter II's perturbation theory on the gravity pendulum, derived.

Every form comes from chapter II's derived Results and chapter VII's limit ε → 0, taken as dependencies:

- n°92, (281): the bracket of (104) (−Kf/n²) with its last two terms by (105), in the principal oscillation
  (Y = Kθ); the gravity pendulum's a = a1 + ελ (256) with a1 = −wλ, z' of (257) and K of (260), at ε → 0;
  the prefactor −n²/(K(z − z')) is −n²/(ελ) by (260) (K = ελ/(z − z')); then (81) at K = 0 and Mw'' = w (9).
- n°93, (282)–(284): (112) at ε → 0 gives Q'; (111) over Q = K(z − z') (45) with (260) gives the leading ΔT/T;
  C of (284) is what multiplies −θ0²G/16 there, G of (262); its other forms use (81) at K = 0 and
  wλ = w0 + ∫w' ds, F_n = ∫w'^n ds ((79) with φ2 = w' (11)).
- n°97: (141), (147), (149) with K = 0 in g_q (139) and Q = ελ = G2/G (260), (262).
"""
from __future__ import annotations

import sympy as sp

from ..ch2_common import J, eps_lambda, theta0
from ..ch7_gravity.symbols import C_s, eps
from ..common import rid
from ..symbols import G, G_2, Fn, K, M_of_s, Q, Y, a, lam, n_squared, s, theta, v, varphi2, w, w0, wl, z, zp

E_1, E_2 = sp.symbols("E_1 E_2")       # ∫ε'φ1 ds, ∫ε'φ2 ds of (104) (chapter II's names)
ACCELERATION = sp.Symbol("f/(z - z')", real=True)


def derived_of(deps, eq: int, name: str) -> sp.Basic:
    return deps[rid(eq, name)].derived


def near_critical(deps) -> dict:
    """(256): a = a1 + ελ, a1 = −wλ (41); K of (260) and z' of (257), to the first order in ε."""
    return {a: -wl + eps * lam, K: derived_of(deps, 260, "K"), zp: derived_of(deps, 257, "zp")}


def w_second(expr: sp.Expr, deps) -> sp.Expr:
    """w/M → w'' inside the integrals: (9) holds for w as for v (Mw'' = w, n°2)."""
    equation_9 = derived_of(deps, 9, "v").subs(v(s), w(s)).doit()        # M w'' − w
    w_dd = sp.solve(equation_9, w(s).diff(s, 2))[0]                       # w/M
    if sp.simplify(w_dd - w(s) / M_of_s(s)) != 0:
        raise ValueError(f"(9) does not give w'' = w/M: {w_dd}")
    return expr.replace(lambda e: isinstance(e, sp.Integral),
                        lambda e: sp.Integral(sp.powsimp(e.function.subs(w(s) / M_of_s(s), w(s).diff(s, 2))),
                                              *e.limits))


def G2_at_zero(deps) -> sp.Expr:
    """G2 = ∫(Kv + w)²/M ds (79) at K = 0, written ∫ww'' ds by (9)."""
    G79 = derived_of(deps, 79, "G").subs(sp.Symbol("n", integer=True, positive=True), 2).subs(K, 0)
    return w_second(sp.Integral(sp.powsimp(G79.function, force=True), *G79.limits), deps)


def F_at_zero(deps, n: int) -> sp.Expr:
    """F_n = ∫(Kφ1 + φ2)^n ds (79) at K = 0 with φ2 = w' (11)."""
    F79 = derived_of(deps, 79, "F").subs(sp.Symbol("n", integer=True, positive=True), n).subs(K, 0)
    phi2 = derived_of(deps, 11, "phi12")[1]
    return F79.replace(lambda e: e == varphi2(s), lambda e: phi2)


# ---------------------------------------------------------------- n°92: (281)
def f_281(deps) -> sp.Expr:
    """(281): f/(z − z') of (104) for the gravity pendulum as ε → 0."""
    bracket = sp.expand(derived_of(deps, 104, "f"))                  # −(K/n²) f
    last_two = derived_of(deps, 105, "parts")                         # K E_1 + E_2 − ε_λ = −∫ε(Kv + w)/M ds
    bracket = sp.expand(bracket.subs(E_2, last_two - K * E_1 + eps_lambda))
    bracket = bracket.subs(Y, K * theta)                              # the principal oscillation (n°29)
    limit = sp.expand(bracket.subs(near_critical(deps)).subs(eps, 0).doit())
    # at K = 0, J(0, n) = ∫φ2^n ds = F_n (79); F2 = wλ − G2 by (81) at K = 0
    F2 = (derived_of(deps, 81, "F2G2") - G_2).subs(K, 0)
    limit = limit.xreplace({J(0, 2): F2})
    if limit.atoms(J):
        raise ValueError(f"moments left at K = 0: {limit.atoms(J)}")
    limit = w_second(sp.expand(limit), deps).subs(G_2, G2_at_zero(deps))
    prefactor = sp.simplify(-n_squared / (derived_of(deps, 260, "K_foci") * (z - zp)))   # K(z − z') = ελ
    return prefactor * sp.collect(limit, sp.symbols("epsilon_1 epsilon_2 epsilon_3", real=True))


# ---------------------------------------------------------------- n°93: Q', (282)–(284)
def Qp_limit(deps) -> sp.Expr:
    """n°93: Q' of (112) as ε → 0 (a = a1 + ελ, a1 = −wλ, K of (260), z' of (257)): F4 − wλ."""
    return sp.expand(sp.limit(derived_of(deps, 112, "Qp").subs(near_critical(deps)), eps, 0))


def F4_282(deps) -> sp.Expr:
    """(282): F4 = ∫w'^4 ds, (79) at K = 0."""
    return F_at_zero(deps, 4)


def dT_leading(deps) -> sp.Expr:
    """ΔT/T of (111) at its leading order in ε: K = ελ/(z − z') (260) makes Q = K(z − z') = ελ; a, z' as in
    :func:`near_critical`."""
    dT = derived_of(deps, 111, "dT")
    at = near_critical(deps)
    at[K] = derived_of(deps, 260, "K_foci")
    expr = sp.together(dT.subs(at))
    return sp.factor(sp.limit(expr * eps, eps, 0)) / eps


def C_284(deps) -> sp.Expr:
    """(284), first form: C = −16(ΔT/T)/(θ0²G) with the leading ΔT/T and G = G2/(ελ) (262)."""
    return sp.factor(sp.simplify(-16 * dT_leading(deps) / (theta0**2 * derived_of(deps, 262, "G"))))


def dT_283(deps) -> sp.Expr:
    """(283): the leading ΔT/T written with G (262) and C (284): G2 = ελG, then F4 from (284)."""
    G2_of_G = sp.solve(sp.Eq(G, derived_of(deps, 262, "G")), G_2)[0]
    F4_of_C = sp.solve(sp.Eq(C_s, derived_of(deps, 284, "C")), Fn(4))[0]
    return sp.factor(sp.simplify(dT_leading(deps).subs(Fn(4), F4_of_C).subs(G_2, G2_of_G)))


def C_284_F2(deps) -> sp.Expr:
    """(284), second form: G2 = wλ − F2 by (81) at K = 0."""
    G2 = sp.solve(sp.Eq(Fn(2) + G_2, derived_of(deps, 81, "F2G2").subs(K, 0)), G_2)[0]
    return derived_of(deps, 284, "C").subs(G_2, G2)


def C_284_integrals(deps) -> sp.Expr:
    """(284), third form: wλ = w0 + ∫_0^λ w' ds, F_n = ∫w'^n ds ((282), (79)); numerator and denominator each
    one integral, its integrand factored by w'."""
    C = derived_of(deps, 284, "C_F2")
    slope = w(s).diff(s)
    num, den = sp.fraction(sp.together(C))
    total = {wl: w0 + sp.Integral(slope, (s, 0, lam)), Fn(2): F_at_zero(deps, 2), Fn(4): F_at_zero(deps, 4)}

    def one_integral(expr):
        expr = sp.expand(expr.xreplace(total))
        inside = sum((t for t in sp.Add.make_args(expr) if t.has(sp.Integral)), sp.S.Zero)
        integrand = sum((sp.Mul(*[f.function if isinstance(f, sp.Integral) else f for f in sp.Mul.make_args(t)])
                         for t in sp.Add.make_args(inside)), sp.S.Zero)
        factored = slope * sp.factor(sp.cancel(integrand / slope))
        return expr - inside + sp.Integral(factored, (s, 0, lam))
    return one_integral(num) / one_integral(den)


def C_minus_one(deps) -> sp.Expr:
    """n°93: C − 1 from (284)'s first form, wλ = F2 + G2 by (81) at K = 0, F_n = ∫w'^n ds."""
    C = derived_of(deps, 284, "C")
    wl_of = sp.solve(sp.Eq(Fn(2) + G_2, derived_of(deps, 81, "F2G2").subs(K, 0)), wl)[0]
    numerator = sp.expand((C - 1) * G_2).subs(wl, wl_of)
    slope = w(s).diff(s)
    integrand = sp.expand(numerator.subs({Fn(2): slope**2, Fn(4): slope**4}))
    if sp.expand(F_at_zero(deps, 2).function - slope**2) != 0 or sp.expand(F_at_zero(deps, 4).function - slope**4) != 0:
        raise ValueError("F2, F4 at K = 0 are not ∫w'², ∫w'^4")
    return sp.Integral(sp.factor(integrand), (s, 0, lam)) / G_2


def integrand_nonnegative(expr: sp.Expr) -> bool:
    """n°93: the integrand of C − 1 is ≥ 0 where 0 ≤ w' ≤ 1 (n°3): its minimum over [0, 1] in w' is 0."""
    integral, = expr.atoms(sp.Integral)
    x = sp.Symbol("x", real=True)
    body = integral.function.subs(w(s).diff(s), x)
    return bool(body.free_symbols == {x} and sp.minimum(body, x, sp.Interval(0, 1)) >= 0)


# ---------------------------------------------------------------- n°97: (141), (147), (149) ∝ G
def _g_at_zero(deps, expr: sp.Expr, g_fn) -> sp.Expr:
    """g_q(x) of (139) with K = 0 for each g(q, x) of expr."""
    g139 = derived_of(deps, 139, "g")
    q, x = sp.Symbol("q", integer=True, nonnegative=True), sp.Symbol("x")

    def at_zero(call):
        order, argument = call.args
        body = g139.subs(K, 0).subs(q, order).subs(x, argument)
        return sp.Integral(sp.powsimp(body.function, force=True), *body.limits)
    return expr.replace(lambda e: isinstance(e, sp.Function) and e.func == g_fn, at_zero)


def proportional_to_G(deps, eq: int, name: str) -> sp.Expr:
    """n°97: (141), (147) or (149) with K = 0 in (139) and Q = K(z − z') = ελ (260), ελ = G2/G (262)."""
    from ..ch2_perturbations.derivation import g_fn
    expr = _g_at_zero(deps, derived_of(deps, eq, name), g_fn)
    Q_value = sp.simplify(derived_of(deps, 45, "Q").subs(K, derived_of(deps, 260, "K_foci")))     # ελ
    eps_of_G = sp.solve(sp.Eq(G, derived_of(deps, 262, "G")), eps)[0]
    return sp.powsimp(expr.subs(Q, Q_value).subs(eps, eps_of_G))


def law_97(deps) -> sp.Expr:
    """n°97: (141), the term a_q|c|^q of Le Rolland's law, on the gravity pendulum."""
    return proportional_to_G(deps, 141, "dT")


def friction_97(deps) -> sp.Expr:
    """n°97: (147), ΔT/T of internal friction, on the gravity pendulum."""
    return proportional_to_G(deps, 147, "dT")


def damping_97(deps) -> sp.Expr:
    """n°97: (149), Δθ0 per period of internal friction, on the gravity pendulum."""
    return proportional_to_G(deps, 149, "amplitude")


def over_G_free(expr: sp.Expr) -> bool:
    """n°97: the form is G times a factor of the blade alone (no ε, a, R, z, z', K, Q)."""
    factor = sp.cancel(expr / G)
    return not factor.has(G, eps, a, z, zp, K, Q) and not factor.has(sp.Symbol("R", positive=True))
