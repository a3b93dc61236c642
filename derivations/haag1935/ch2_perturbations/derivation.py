"""Haag 1935, chapter II, n°36–39, eqs. (135)–(143): the blade's inertia and weight, Le Rolland's moment law.

Pure SymPy, from the general formula of n°28: only the moment increment mgε(s) of the blade's equation (7)
is perturbed, so (104) keeps its last two terms, which (105) turns into f = (n²/K)∫ε(Kv + w)/M ds
(:func:`..ch2_general.derivation.eq105`).  Each section finds ε(s):

- n°36, the inertia of the blade: the horizontal momentum of the part below s changes the shear, the shear
  changes d(Mφ')/ds; ε(λ) = 0.  In the principal oscillation ÿ = −n²y, y = θ∫_0^s(Kφ1 + φ2) (13).
- n°37, its weight: the tension at s grows by the weight of the blade below s; ε(λ) = 0; s − x = ½∫φ² from
  x' = cos φ (3).
- n°38–39, the law EIc(1 + a_q c^q) (137): ε is the moment beyond Mc, with c = φ' = θ(Kv + w)/M in the
  principal oscillation ((9), (13)); i_q of (142)–(143) by the Wallis recurrence solved by rsolve.

n°40–42 (internal friction) are in :mod:`.derivation_friction`.

The order of the nested integrals is changed by :func:`swap` (the triangle x < y), the integrations by parts
are proved by :func:`parts_identity` and :func:`slope_identity`, and ΔT/T follows from f by the classical
formula (114) (:func:`..ch2_general.derivation.eq114_relative`), as for (111).
"""
from __future__ import annotations

import sympy as sp

from pendsym import wallis
from ..ch2_common import eps_lambda, theta0
from ..ch2_general import derivation as general
from ..symbols import (G_2, Gn, K, M_of_s, Q, a, alpha_blade, alpha_rod, beta1, beta_t, epsilon_of_s, g, lam, m, mb,
                       n_squared, s, theta, v, varphi1, varphi2, w, wl, y_of_s, z, zp)

mu = sp.Function("mu")                         # linear density μ(s) of the blade (n°36)
y_dd = sp.Function("yddot")                    # d²y/dt² at the point of abscissa s (n°36)
s1, s2 = sp.symbols("s_1 s_2", real=True)   # Haag's s', s'' (variables of integration)
I_lambda = sp.Symbol("I_lambda", positive=True)   # moment of inertia of the blade for θ = 1 (n°36)
J_w = sp.Symbol("J", positive=True)            # J of n°37
q = sp.Symbol("q", integer=True, nonnegative=True)   # rank of the corrective term (137)
a_q = sp.Function("a")                         # a_q (137), a function of s in general: a(q, s)
c_curv = sp.Symbol("c", real=True)             # curvature c = 1/ρ (137)
g_fn = sp.Function("g")                        # g_q(x) of (139): g(q, x)
i_fn = sp.Function("i")                        # i_q of (141): i(q)
dE_E = sp.Symbol("dE/E", real=True)            # ΔE/E of n°39
phi = sp.Symbol("phi", real=True)              # the phase of the principal oscillation (n°29)


# ================================================================ tools
def psi(x):
    """Kφ1 + φ2 at x, φ1 = 1 + v', φ2 = w' (11): the slope of the blade for θ = 1 in the principal oscillation."""
    return K * (1 + v(x).diff(x)) + w(x).diff(x)


def slope_rate(x):
    """(Kv + w)/M at x: dψ/ds by (9) (Mv'' = v, Mw'' = w)."""
    return (K * v(x) + w(x)) / M_of_s(x)


def ordinate(x):
    """y for θ = 1: ∫_0^x (Kφ1 + φ2) ds'' (y' = φ, (13) with Y = Kθ)."""
    return sp.Integral(psi(s2), (s2, 0, x))


def split_inner(integral: sp.Integral) -> tuple:
    """(h, inner limits, outer limits) of ∫dx ∫dy h, written nested (c(x)·∫h dy) or flattened (two limits)."""
    if len(integral.limits) == 2:
        inner_lim, outer_lim = integral.limits
        return integral.function, inner_lim, outer_lim
    outer_lim, = integral.limits
    inner = [f for f in sp.Mul.make_args(integral.function) if isinstance(f, sp.Integral)]
    if len(inner) != 1 or len(inner[0].limits) != 1:
        raise ValueError("a double integral is needed")
    c = integral.function / inner[0]
    return c * inner[0].function, inner[0].limits[0], outer_lim


def as_phi(expr: sp.Expr) -> sp.Expr:
    """The slopes written as Haag writes them: 1 + v' = φ1, w' = φ2 (11)."""
    def rewrite(d):
        fn, (x, k) = d.expr, d.variable_count[0]
        if k == 1 and fn == v(x):
            return varphi1(x) - 1
        if k == 1 and fn == w(x):
            return varphi2(x)
        return d
    return sp.expand(expr.replace(lambda e: isinstance(e, sp.Derivative), rewrite)) \
        if not expr.has(sp.Integral) else expr.replace(lambda e: isinstance(e, sp.Derivative), rewrite)


def swap(integral: sp.Integral) -> sp.Integral:
    """Fubini on a triangle: ∫_L^H dx ∫_x^H dy h = ∫_L^H dy ∫_L^y dx h, and ∫_L^H dx ∫_L^x dy h = ∫_L^H dy ∫_y^H dx h
    (a factor of the outer integrand goes inside).  Returned flattened: Integral(h, (x, …), (y, L, H))."""
    if not isinstance(integral, sp.Integral):
        k, integral = _single_integral(integral)
        return k * swap(integral)
    h, (y, lo, hi), (x, L, H) = split_inner(integral)
    if lo == x and hi == H:
        return sp.Integral(h, (x, L, y), (y, L, H))
    if lo == L and hi == x:
        return sp.Integral(h, (x, y, H), (y, L, H))
    raise ValueError(f"not a triangle: {(x, L, H)}, {(y, lo, hi)}")


def pull_out(integral: sp.Integral) -> sp.Expr:
    """∫c·h dx = c∫h dx for the factors c free of x (the innermost variable); a double integral becomes
    ∫ c(y)·(∫h dx) dy."""
    if not isinstance(integral, sp.Integral):
        k, integral = _single_integral(integral)
        return k * pull_out(integral)
    h, inner_lim = integral.function, integral.limits[0]
    x = inner_lim[0]
    free, bound = [], []
    for f in sp.Mul.make_args(sp.factor_terms(h)):
        (bound if f.has(x) else free).append(f)
    inner = sp.Mul(*free) * sp.Integral(sp.Mul(*bound), inner_lim)
    for lim in integral.limits[1:]:
        inner = sp.Integral(inner, lim)
    return inner


def inner_doit(integral: sp.Integral) -> sp.Integral:
    """∫(∫h dx)dy with the inner integral done by SymPy."""
    h, inner_lim, outer_lim = split_inner(integral)
    return sp.Integral(sp.Integral(h, inner_lim).doit(), outer_lim)


def replace_inner(expr: sp.Expr, lhs: sp.Integral, rhs: sp.Expr) -> sp.Expr:
    """Replace each integral k·lhs (same limits, integrand a constant k times lhs's) by k·rhs."""
    var = lhs.limits[0][0]
    out = {}
    for e in expr.atoms(sp.Integral):
        if e.limits == lhs.limits:
            k = sp.cancel(e.function / lhs.function)
            if not k.has(var):
                out[e] = k * rhs
    if not out:
        raise ValueError(f"no integral {lhs} in {expr}")
    return expr.xreplace(out)


def f_of_moment(eps_of) -> sp.Expr:
    """f = −(n²/K)·[the last two terms of (104)], by (105), for the moment increment ε(s) = eps_of(s) with
    ε(λ) = 0: ∫ε'(Kφ1 + φ2) ds − ε_λ = −∫ε(Kv + w)/M ds."""
    last = general.eq105().subs(eps_lambda, 0)
    last = last.replace(epsilon_of_s, eps_of)
    return -n_squared / K * last


def period_of(f_over_theta: sp.Expr) -> sp.Expr:
    """ΔT/T for f = cθ by (114): the perturbation of θ'' is f/(z − z') (y = (z − z')θ), θ = θ0 cos φ."""
    Phi = f_over_theta * theta0 * sp.cos(phi) / (z - zp)
    C = sp.integrate(Phi * sp.cos(phi), (phi, 0, 2 * sp.pi))
    return sp.simplify(general.eq114_relative().subs(sp.Symbol("C"), C))


# ================================================================ n°36: the inertia of the blade
def inertia_moment() -> sp.Expr:
    """n°36 (n°26): ε(s) of the blade's inertia.  The horizontal momentum of the part below s makes the shear
    mgY(s) = mgY − ∫_s^λ μÿ ds', so d(Mφ')/ds = φ − Y(s) holds ε' = (1/mg)∫_s^λ μÿ ds'; with ε(λ) = 0,
    ε(s) = −∫_s^λ ε' dt, the order changed: −(1/mg)∫_s^λ μ(s')ÿ(s')(s' − s) ds'."""
    t = sp.Symbol("t", real=True)
    eps_prime = sp.Integral(mu(s1) * y_dd(s1), (s1, t, lam)) / (m * g)
    inner = inner_doit(swap(sp.Integral(eps_prime, (t, s, lam))))
    return -pull_out(sp.Integral(sp.expand(inner.function), inner.limits[0]))


def inertia_moment_principal() -> sp.Expr:
    """n°36: ε in the principal oscillation, ÿ = −n²y, y = θ∫_0^s'(Kφ1 + φ2) (first approximation),
    g = −n²z'/K (34)."""
    eps = inertia_moment().replace(y_dd, lambda x: -n_squared * theta * ordinate(x)).subs(g, -n_squared * zp / K)
    c, integral = _single_integral(eps)
    c2, integral = _single_integral(pull_out(integral))
    return sp.simplify(c * c2) * integral


def parts_identity() -> sp.Tuple:
    """n°36: ∫_0^s' (Kv + w)/M (s' − s) ds − ∫_0^s' (Kφ1 + φ2) ds: its second derivative in s' (by (9)), its
    value and its first derivative at s' = 0 (by (10): Kφ1 + φ2 = 0 at s = 0) — all 0, so it vanishes."""
    diff = sp.Integral(slope_rate(s) * (s1 - s), (s, 0, s1)) - sp.Integral(psi(s), (s, 0, s1))
    second = sp.diff(diff, s1, 2).doit()
    second = second.subs({v(s1).diff(s1, 2): v(s1) / M_of_s(s1), w(s1).diff(s1, 2): w(s1) / M_of_s(s1)})
    ends10 = {sp.Subs(v(s1).diff(s1), s1, 0): -1, sp.Subs(w(s1).diff(s1), s1, 0): 0}
    first_at_0 = sp.diff(diff, s1).doit().subs(s1, 0).subs(ends10)
    value_at_0 = diff.subs(s1, 0).doit()
    return sp.Tuple(sp.simplify(second), sp.simplify(first_at_0), sp.simplify(value_at_0))


def _single_integral(f: sp.Expr) -> tuple[sp.Expr, sp.Integral]:
    """f = c·∫…: (c, the integral)."""
    integrals = [e for e in sp.Mul.make_args(f) if isinstance(e, sp.Integral)]
    if len(integrals) != 1:
        raise ValueError(f"not c·∫…: {f}")
    return f / integrals[0], integrals[0]


def _as(expr: sp.Expr, definition: sp.Integral, symbol: sp.Symbol) -> sp.Expr:
    """expr = k·∫h (k free of the variable) with ∫h the definition: k·symbol."""
    c, integral = _single_integral(pull_out(expr) if isinstance(expr, sp.Integral) else expr)
    ratio = sp.simplify(integral.function / definition.function)
    if integral.limits != definition.limits or ratio.has(*[lim[0] for lim in integral.limits]):
        raise ValueError(f"{integral} is not a multiple of {definition}")
    return c * ratio * symbol


def I_lambda_def() -> sp.Integral:
    """n°36: I_λ = ∫_0^λ μy² ds, y for θ = 1 (the moment of inertia of the blade about Ox)."""
    return sp.Integral(mu(s1) * ordinate(s1) ** 2, (s1, 0, lam))


def inertia_f() -> sp.Expr:
    """n°36: f of (104)–(105) with ε of the inertia: the order of ∫ds∫ds' changed (0 < s < s' < λ), the inner
    integral reduced by :func:`parts_identity`, ∫μy² ds = I_λ (y for θ = 1)."""
    f = f_of_moment(lambda x: inertia_moment_principal().subs(s, x))
    c, integral = _single_integral(f)
    swapped = pull_out(swap(pull_out(integral)))
    reduced = replace_inner(swapped, sp.Integral(slope_rate(s) * (s1 - s), (s, 0, s1)), ordinate(s1))
    return sp.simplify(c * _as(reduced, I_lambda_def(), I_lambda))


def eq135() -> sp.Expr:
    """(135): ΔT/T from f = −(n²/(mz'))θI_λ by (114)."""
    return period_of(sp.cancel(inertia_f() / theta))


# ================================================================ n°37: the weight of the blade
def weight_moment() -> sp.Expr:
    """n°37: ε(s) of the blade's weight.  The tension at s is mg + g∫_s^λ μ ds' (the weight of the blade below
    s), so d(Mφ')/ds = X(s)φ − Y holds ε' = (1/m)φ(s)∫_s^λ μ ds'; with ε(λ) = 0 and φ = dy/ds,
    ε(s) = −∫_s^λ ε' dt = −(1/m)∫_s^λ μ(s')(y(s') − y(s)) ds'."""
    t = sp.Symbol("t", real=True)
    eps_prime = y_of_s(t).diff(t) * sp.Integral(mu(s1), (s1, t, lam)) / m
    inner = inner_doit(swap(sp.Integral(eps_prime, (t, s, lam))))
    return -pull_out(sp.Integral(sp.expand(inner.function), inner.limits[0]))


def slope_identity() -> sp.Tuple:
    """n°37: ∫_0^s'' (Kv + w)/M ds − (Kφ1 + φ2)(s''): its derivative (by (9)) and its value at 0 (by (10))."""
    diff = sp.Integral(slope_rate(s), (s, 0, s2)) - psi(s2)
    d = sp.diff(diff, s2).doit().subs({v(s2).diff(s2, 2): v(s2) / M_of_s(s2), w(s2).diff(s2, 2): w(s2) / M_of_s(s2)})
    at0 = diff.subs(s2, 0).doit().subs({sp.Subs(v(s2).diff(s2), s2, 0): -1, sp.Subs(w(s2).diff(s2), s2, 0): 0})
    return sp.Tuple(sp.simplify(d), sp.simplify(at0))


def s_minus_x(at=s) -> sp.Integral:
    """n°37: s − x = ∫_0^s (1 − cos φ) ds'' (x' = cos φ (3)) to the second order: ½∫_0^s φ² ds'', θ = 1."""
    ph = sp.Symbol("varphi_", real=True)
    small = sp.series(1 - sp.cos(ph), ph, 0, 4).removeO()
    return sp.Integral(small.subs(ph, psi(s2)), (s2, 0, at))


def J_def() -> sp.Expr:
    """n°37: J = (1/m')∫_0^λ μ(s − x) ds for θ = 1 (φ = Kφ1 + φ2)."""
    return sp.Integral(mu(s1) * s_minus_x(s1), (s1, 0, lam)) / mb


def weight_f() -> sp.Expr:
    """n°37: f of (104)–(105) with ε of the weight, y(s') − y(s) = ∫_s^s' φ ds'', φ = θ(Kφ1 + φ2) (principal
    oscillation): the order of the three integrals changed (0 < s < s'' < s' < λ), ∫_0^s''(Kv + w)/M ds =
    Kφ1'' + φ2'' (:func:`slope_identity`), ∫_0^s' (Kφ1'' + φ2'')² ds'' = 2(s' − x') (:func:`s_minus_x`) and
    ∫μ(s − x) ds = m'J."""
    rise = sp.Integral(theta * psi(s2), (s2, s, s1))
    eps = weight_moment().replace(lambda e: isinstance(e, sp.Integral) and e.has(y_of_s),
                                  lambda e: e.func(e.function.subs(y_of_s(s1), y_of_s(s) + rise), *e.limits))
    if eps.has(y_of_s):
        raise ValueError(f"y(s') − y(s) not found in {eps}")
    f = f_of_moment(lambda x: eps.subs(s, x))
    c, integral = _single_integral(f)
    # s < s' first: ∫_0^λ ds' μ(s') ∫_0^s' ds (Kv + w)/M ∫_s^s' φ ds''
    c2, outer = _single_integral(pull_out(swap(pull_out(integral))))
    inner, = [e for e in sp.Mul.make_args(outer.function) if isinstance(e, sp.Integral)]
    # then s < s'' inside: ∫_0^s' ds'' φ(s'') ∫_0^s'' (Kv + w)/M ds
    swapped = pull_out(swap(pull_out(inner)))
    swapped = replace_inner(swapped, sp.Integral(slope_rate(s), (s, 0, s2)), psi(s2))
    # ∫_0^s' (Kφ1'' + φ2'')² ds'' = 2(s' − x') (θ = 1)
    swapped = replace_inner(swapped, sp.Integral(psi(s2) ** 2, (s2, 0, s1)), 2 * s_minus_x(s1))
    outer = outer.xreplace({inner: swapped})
    return sp.simplify(c * c2 * _as(outer, mb * J_def(), mb * J_w))


def eq136() -> sp.Expr:
    """(136): ΔT/T from f = −(2m'J/(Km))n²θ by (114), then Q = K(z − z') (45)."""
    return sp.simplify(period_of(sp.cancel(weight_f() / theta)).subs(z, Q / K + zp))


# ================================================================ n°38–39: the moment law (137)
def law_moment() -> sp.Expr:
    """n°38: ε = −M a_q c^{q+1}: the moment EIc(1 + a_q c^q) (137), over mg, minus Mc (so that the blade's
    equation keeps d(Mφ')/ds on its left: ε is what the law adds)."""
    moment = M_of_s(s) * c_curv * (1 + a_q(q, s) * c_curv**q)
    return sp.powsimp(sp.expand(M_of_s(s) * c_curv - moment))


def eq138() -> sp.Expr:
    """(138): f_q by (104)–(105) with ε of :func:`law_moment`, c = dφ/ds = θ(Kv + w)/M (principal oscillation,
    (9), (13)): −(n²/K)θ^{q+1}g_{q+1}(a_q), the integral recognised as g_{q+1} (139)."""
    eps = law_moment().subs(c_curv, theta * slope_rate(s))
    f = f_of_moment(lambda x: eps.subs(s, x))
    integral = [e for e in sp.Mul.make_args(f) if isinstance(e, sp.Integral)][0]
    body = sp.powsimp(sp.expand_power_base(sp.powsimp(integral.function, force=True), force=True),
                      force=True, combine="exp")
    consts = [x for x in sp.Mul.make_args(body) if not x.has(s)]
    rest = sp.Mul(*[x for x in sp.Mul.make_args(body) if x.has(s)])
    target = eq139().function.subs(q, q + 1).subs(sp.Symbol("x"), a_q(q, s))
    if sp.simplify(sp.powsimp(rest / target, force=True)) != 1:
        raise ValueError(f"the integrand is not that of g_(q+1): {rest}")
    return sp.powsimp((f / integral) * sp.Mul(*consts) * g_fn(q + 1, a_q(q, s)), force=True)


def eq139() -> sp.Integral:
    """(139): g_q(x) = ∫_0^λ (Kv + w)^{q+1}x/M^q ds (a definition)."""
    x = sp.Symbol("x")
    return sp.Integral((K * v(s) + w(s)) ** (q + 1) * x / M_of_s(s) ** q, (s, 0, lam))


def eq140() -> sp.Expr:
    """(140): g_q for x constant: x out of the integral, the rest G_{q+1} of (79) (∫(Kv + w)^n/M^{n−1} ds)."""
    x = sp.Symbol("x")
    G_integrand = lambda n: (K * v(s) + w(s)) ** n / M_of_s(s) ** (n - 1)
    integral = pull_out(eq139())
    const, rest = integral.as_independent(sp.Integral)
    if sp.simplify(rest.function / G_integrand(q + 1)) != 1:
        raise ValueError("not G_(q+1)")
    return const * Gn(q + 1)


def eq141() -> sp.Expr:
    """(141): ΔT/T when c^q is taken in absolute value: f = −(n²/K)θ|θ|^q g_{q+1}(a_q) (138); along
    θ = θ0 cos φ, ∫_0^{2π}|cos φ|^q cos²φ dφ = 4∫_0^{π/2}cos^{q+2}φ dφ = 2π i_{q+2} (four equal quarters),
    i_q = (2/π)∫_0^{π/2}cos^q φ dφ; then Q = K(z − z') (45)."""
    f_per = eq138() / theta**(q + 1)                     # −(n²/K)g_{q+1}
    quarter = sp.Integral(sp.cos(phi) ** (q + 2), (phi, 0, sp.pi / 2))
    i_def = 2 / sp.pi * quarter
    C = f_per * theta0 ** (q + 1) / (z - zp) * 4 * quarter
    rel = general.eq114_relative().subs(sp.Symbol("C"), C)
    rel = rel.xreplace({quarter: i_fn(q + 2) / (i_def / quarter)})
    return sp.simplify(sp.simplify(rel).subs(z, Q / K + zp))


def odd_terms_vanish() -> sp.Expr:
    """n°38: a term of odd rank q in algebraic value: f ∝ θ^{q+1}, and ∫_0^{2π}cos^{q+1}φ cos φ dφ = 0 for
    q + 2 odd: cos^{q+2}(π − φ) = −cos^{q+2}φ, so the half-periods cancel (pendsym.wallis.parity_reflection)."""
    n = sp.Symbol("n", integer=True, nonnegative=True)
    y = sp.Symbol("y", real=True)
    # cos^{q+2} with q = 2n + 1: the Wallis integrand cos^{m+1} with m = q + 1 = 2n + 2
    return sp.simplify(wallis.parity_reflection(2 * n + 2, y))


def eq139_q0() -> sp.Expr:
    """n°39: (141) with q = 0, a_0 = ΔE/E constant: i_2 of (142), g_1 = a_0G_2 (140)."""
    rel = eq141().subs(q, 0)
    i2 = eq142().subs(q, 2)
    g1 = eq140().subs(q, 1).subs(sp.Symbol("x"), dE_E)
    return sp.simplify(rel.subs(i_fn(2), i2).subs(g_fn(1, a_q(0, s)), g1).subs(Gn(2), G_2))


def same_as_60(dT60: sp.Expr) -> sp.Expr:
    """n°39: (60) with α = α' = 0, β = ΔE/E, minus the derived n°39, with Q = a − a1 + K²β1 = a + wλ + K²β1
    ((45), a1 = −wλ (41)), the form in which (60) is derived."""
    expr = dT60.subs({alpha_blade: 0, alpha_rod: 0, beta_t: dE_E})
    return sp.simplify(expr - eq139_q0().subs(Q, a + wl + K**2 * beta1))


def i_recurrence() -> sp.Expr:
    """n°38: q·i_q = (q − 1)·i_{q−2}: d/dφ[sin φ cos^{q−1}φ] = q cos^q φ − (q − 1)cos^{q−2}φ
    (:func:`pendsym.wallis.recurrence_defect` with m = q − 1 is 0), integrated over [0, π/2], where
    sin φ cos^{q−1}φ vanishes at both ends (q ≥ 2).  Returns the boundary term for q = 2n + 2 (0)."""
    y = sp.Symbol("y", real=True)
    m_ = sp.Symbol("m")
    if sp.simplify(wallis.recurrence_defect(m_, y).subs(m_, q - 1)) != 0:
        raise ValueError("the Wallis recurrence does not hold")
    n = sp.Symbol("n", integer=True, nonnegative=True)
    ends = sp.sin(y) * sp.cos(y) ** (2 * n + 1)
    return sp.simplify(ends.subs(y, sp.pi / 2) - ends.subs(y, 0))


def _i_by_parity(parity: int) -> sp.Expr:
    """i_q for q = 2n + parity: the recurrence solved by SymPy's rsolve from i_0 = 1 or i_1 = 2/π (the
    definition (2/π)∫_0^{π/2}cos^q φ dφ integrated by SymPy), written back in q."""
    n = sp.Symbol("n", integer=True, nonnegative=True)
    h = sp.Function("h")
    if i_recurrence() != 0:
        raise ValueError("boundary term")
    start = sp.integrate(2 / sp.pi * sp.cos(phi) ** parity, (phi, 0, sp.pi / 2))
    qq = 2 * n + parity
    # q i_q = (q − 1) i_{q−2} at q = 2(n + 1) + parity
    rec = (qq + 2) * h(n + 1) - (qq + 1) * h(n)
    sol = sp.rsolve(rec, h(n), {h(0): start})
    return sol.subs(n, (q - parity) / 2)


def eq142() -> sp.Expr:
    """(142): i_q for q even."""
    return _i_by_parity(0)


def eq143() -> sp.Expr:
    """(143): i_q for q odd."""
    return _i_by_parity(1)
