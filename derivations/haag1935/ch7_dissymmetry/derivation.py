"""Haag 1935, chapter VII, n°98, eqs. (295)–(301): the dissymmetric blade of the gravity pendulum, derived.

n°98 specialises chapter II's (154) (derived, :mod:`..ch2_dissymmetry`) to the gravity pendulum and adds the
clamping perturbation (286).  Everything is taken from derived Results:

- the limit ε → 0 of chapter VII (a = a1 + ελ (256), a1 = −wλ (41)) with K = ελ/(z − z') (260, derived), so that
  Q = K(z − z') (45) is ελ and G2 = Gελ (262, derived);
- i of (117) (derived) at i' = 0: i = −jελ/(a − vλ), of order ε (Haag's (290), "i négligeable devant j");
- B = g1 − AK (n°45, proven) with K → 0, and g1(ε) = εG2 for a constant modulus excess (140, derived);
- (286) is rebuilt here from chapter II's (133), (132), (134) (derived) and the definition (284) of C, not taken
  from chapter VII's clamping package (built at the same time): see :func:`eq286`.

The modulus excess ε of n°44 (ΔE = εE on the right, θ > 0) is the Symbol ``varepsilon_E`` here: Haag writes ε,
and warns (footnote of (295)) not to confuse it with the sensitivity ε of (256).

The extremes are found by SymPy: D = d[(295)]/dφ1 is solved for φ1, the roots are mapped by (153), the one that
is a stationary point in j is classified by the second derivative.  (296)–(301) follow Haag's steps with the
derived coefficients.
"""
from __future__ import annotations

import functools

import sympy as sp

from ..ch2_common import J, i_clamp, i_prime, j_eq, theta0
from ..ch2_dissymmetry.derivation import A_d, B_d, eps_E as eps_E_fn, phi1
from ..ch2_perturbations.derivation import g_fn
from ..ch7_gravity.symbols import C_s, eps
from ..common import rid
from ..symbols import Fn, G, G_2, Gn, K, a1, lam, s, wl, z, zp

eps_E = sp.Symbol("varepsilon_E", real=True)   # ΔE/E, constant (n°44, n°98): the ε of (295)–(301)
alpha_a = sp.Symbol("alpha", real=True)        # the angle of (296)
beta_a = sp.Symbol("beta", real=True)          # sin β = sin α/(2π − 1) (n°98)
gamma_a = sp.Symbol("gamma", real=True)        # (299)
D_s = sp.Symbol("D", real=True)                # d[bracket of (295)]/dφ1


def _by_name(expr: sp.Expr, name: str) -> sp.Symbol | None:
    """The free symbol of expr called ``name`` (chapters use the same name with different assumptions)."""
    return next((x for x in expr.free_symbols if x.name == name), None)


def _sub_named(expr: sp.Expr, table: dict) -> sp.Expr:
    """Substitute by symbol name: {name: value}."""
    rep = {x: table[x.name] for x in expr.free_symbols if x.name in table}
    return expr.subs(rep, simultaneous=True)


def derived_of(deps, eq: int, name: str) -> sp.Expr:
    return deps[rid(eq, name)].derived


def i_of_j(deps) -> sp.Expr:
    """(117) (derived) at i' = 0 solved for i, a = a1 + ελ (256): i = −jελ/(a − vλ), of order ε ((290))."""
    j117 = derived_of(deps, 117, "j").subs(i_prime, 0)
    i = sp.solve(sp.Eq(j_eq, j117), i_clamp)[0]
    return sp.simplify(_sub_named(i, {"a": a1 + eps * lam}))


def _K_gravity(deps) -> sp.Expr:
    """K = ελ/(z − z') (260, derived second form)."""
    return derived_of(deps, 260, "K_foci")


def _leading(expr: sp.Expr, power: int) -> sp.Expr:
    """The coefficient of ε^power of expr as ε → 0 (its principal part when it starts there)."""
    return sp.simplify(sp.limit(sp.simplify(expr / eps**power), eps, 0))


def eq286(deps) -> sp.Expr:
    """(286) rebuilt: ΔT/T of the clamping errors (134) (derived) at i' = 0, i of (117), K = ελ/(z − z')
    (260), h' of (132) (derived) at the same point, a = −wλ + ελ (256); the principal part in ε, with the
    moment J(0, 4) = ∫φ2⁴ = F4 at K = 0 (79), C·G2 = wλ − F4 ((284), a definition) and G2 = Gελ (262)."""
    K_g = _K_gravity(deps)
    i = i_of_j(deps)
    hp = derived_of(deps, 132, "hp").subs({K: K_g, i_clamp: i}, simultaneous=True)
    dT = derived_of(deps, 134, "dT").subs(i_prime, 0)
    dT = _sub_named(dT, {"h'": hp, "K": K_g, "i": i, "a": -wl + eps * lam})
    lead = _leading(dT, -1) / eps
    from ..ch2_common import F_moments
    if sp.simplify(F_moments(4).subs(K, 0) - J(0, 4)) != 0:
        raise ValueError("F4 at K = 0 is not J(0, 4)")
    lead = lead.subs(J(0, 4), Fn(4))
    lead = lead.subs(Fn(4), wl - C_s * G_2)                          # (284): C G2 = wλ − F4
    G2_of_G = sp.solve(sp.Eq(G, derived_of(deps, 262, "G")), G_2)[0]  # (262): G = G2/(ελ)
    return sp.factor(sp.simplify(lead.subs(G_2, G2_of_G)))


def eq154_gravity(deps) -> sp.Expr:
    """(154) (derived) for the gravity pendulum: i of (117) (order ε), B = g1 − AK (n°45), K = ελ/(z − z') (260),
    Q = K(z − z') (45) = ελ, G2 = Gελ (262); principal part in ε (of order 1/ε, like G)."""
    dT = derived_of(deps, 154, "dT")
    if derived_of(deps, 155, "AK_B") != 0:
        raise ValueError("AK + B ≠ g1")
    g1 = g_fn(1, eps_E_fn(s))
    dT = dT.subs(B_d, g1 - A_d * K)
    K_g = _K_gravity(deps)
    dT = _sub_named(dT, {"i": i_of_j(deps), "K": K_g, "Q": K_g * (z - zp)})
    lead = _leading(dT, -1) / eps
    G2_of_G = sp.solve(sp.Eq(G, derived_of(deps, 262, "G")), G_2)[0]
    return sp.expand(lead.subs(eps, G_2 / (lam * G)).subs(G_2, G2_of_G))


def eq295_sum(deps) -> sp.Expr:
    """The line before (295): (4/G)ΔT/T = (4/G)[(154) + (286)], in j and φ1 (g1/G2 kept)."""
    g1 = g_fn(1, eps_E_fn(s))
    total = sp.expand(4 / G * (eq154_gravity(deps) + eq286(deps)))
    G2_of_G = sp.solve(sp.Eq(G, derived_of(deps, 262, "G")), G_2)[0]
    ratio = sp.Symbol("r")
    total = sp.expand(total.subs(g1, ratio * G2_of_G))
    return sp.collect(total, ratio).subs(ratio, g1 / G_2)


def _double_angle(expr: sp.Expr) -> sp.Expr:
    """sin φ1 cos φ1 → ½ sin 2φ1, sin²φ1 → ½(1 − cos 2φ1) (Haag's form)."""
    return sp.expand(sp.expand(expr).subs(sp.sin(phi1) ** 2, (1 - sp.cos(2 * phi1)) / 2)
                     .subs(sp.sin(phi1) * sp.cos(phi1), sp.sin(2 * phi1) / 2))


def eq295(deps) -> sp.Expr:
    """(295): the line before with j = −θ0 sin φ1 (153) and g1(ε) = εG2 for ε constant ((140) derived at q = 1,
    x = ε, G(2) = G2), in double angles."""
    g140 = derived_of(deps, 140, "g")
    q_s, x_s = _by_name(g140, "q"), _by_name(g140, "x")
    g1 = g140.subs({q_s: 1, x_s: eps_E}).subs(Gn(2), G_2)
    expr = derived_of(deps, 295, "sum").subs(g_fn(1, eps_E_fn(s)), g1).subs(j_eq, -theta0 * sp.sin(phi1))
    return sp.expand(G / 4 * _double_angle(expr))


def bracket(dT295: sp.Expr) -> sp.Expr:
    """The bracket of (295): (4/G)ΔT/T."""
    return sp.expand(4 * dT295 / G)


def eq296_D(deps) -> sp.Expr:
    """D, the derivative of the bracket of (295) in φ1 (the line after (295))."""
    return sp.expand(sp.diff(bracket(derived_of(deps, 295, "dT")), phi1))


def _harmonic(D: sp.Expr) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    """D = c0 + c1 cos 2φ1 + c2 sin 2φ1: (c0, c1, c2), checked."""
    c1, c2 = D.coeff(sp.cos(2 * phi1)), D.coeff(sp.sin(2 * phi1))
    c0 = sp.expand(D - c1 * sp.cos(2 * phi1) - c2 * sp.sin(2 * phi1))
    if c0.has(phi1) or c1.has(phi1) or c2.has(phi1):
        raise ValueError(f"D is not c0 + c1 cos 2φ1 + c2 sin 2φ1: {D}")
    return c0, c1, c2


def eq296(deps) -> sp.Expr:
    """(296): tan α such that c1 cos 2φ1 + c2 sin 2φ1 = (Cθ0²/cos α)(−sin(2φ1 − α)) with Cθ0² = −c2 > 0:
    tan α = c1/(−c2)."""
    _, c1, c2 = _harmonic(derived_of(deps, 296, "D"))
    return sp.simplify(c1 / (-c2))


def eq296_D_alpha(deps) -> sp.Expr:
    """The second form of D: (Cθ0²/cos α)[k sin α − sin(2φ1 − α)], k = c0/c1 (the ratio of the constant to the
    cos 2φ1 coefficient; k sin α = c0 cos α/(Cθ0²)), with tan α of (296)."""
    c0, c1, c2 = _harmonic(derived_of(deps, 296, "D"))
    k = sp.simplify(c0 / c1)
    form = -c2 / sp.cos(alpha_a) * (k * sp.sin(alpha_a) - sp.sin(2 * phi1 - alpha_a))
    # check the rewriting: with α = atan(tan α), form − D = 0
    check = sp.simplify(sp.expand_trig(form.subs(alpha_a, sp.atan(eq296(deps)))) - derived_of(deps, 296, "D"))
    if check != 0:
        raise ValueError(f"the second form of D does not hold: {check}")
    return form


def sin_beta(deps) -> sp.Expr:
    """n°98: sin β = k sin α, k of :func:`eq296_D_alpha` (the root of D's bracket)."""
    form = derived_of(deps, 296, "D_alpha")
    inner = sp.expand(form * sp.cos(alpha_a) / C_s / theta0**2)
    k_sin = inner + sp.sin(2 * phi1 - alpha_a)
    return sp.simplify(k_sin)


@functools.lru_cache(maxsize=4)
def _stationary_phases(D: sp.Expr) -> tuple:
    """The roots of D = 0 in φ1 on [−π/2, π/2], by SymPy: D in sin φ1, cos φ1 (expand_trig) is factored; a factor
    cos φ1 gives ±π/2; a factor linear in (sin φ1, cos φ1) is divided by cos φ1 and solved for tan φ1."""
    sn, cs, tn = sp.symbols("sn cs tn", real=True)
    poly = sp.factor(sp.expand(sp.expand_trig(D)).subs({sp.sin(phi1): sn, sp.cos(phi1): cs}))
    roots = []
    for factor, _ in sp.factor_list(sp.numer(sp.together(poly)), sn, cs)[1]:
        if not factor.has(sn) and not factor.has(cs):
            continue
        if sp.simplify(factor - cs) == 0:
            roots += [-sp.pi / 2, sp.pi / 2]
            continue
        if sp.Poly(factor, sn, cs).total_degree() != 1 or sp.Poly(factor, sn, cs).TC() != 0:
            raise ValueError(f"a factor of D not linear in sin φ1, cos φ1: {factor}")
        for t in sp.solve(sp.expand(factor.subs(sn, tn * cs) / cs), tn):
            roots.append(sp.atan(t))
    return tuple(roots)


def _dT_in_j(deps) -> sp.Expr:
    """(295) as a function of j: φ1 = asin(−j/θ0) (153)."""
    return derived_of(deps, 295, "dT").subs(phi1, sp.asin(-j_eq / theta0))


def stationary_in_j(deps) -> tuple:
    """The roots of D = 0 mapped to j by (153), with d(ΔT/T)/dj = D·dφ1/dj, dφ1/dj = −1/(θ0 cos φ1): a root with
    cos φ1 = 0 (φ1 = ±π/2, j = ∓θ0) is the end of the range |j| ≤ θ0, not a stationary point in j.
    Returns ((j, d²(ΔT/T)/dj² there), …) for the stationary points in j."""
    D = derived_of(deps, 296, "D")
    f = _dT_in_j(deps)
    out = []
    for root in _stationary_phases(D):
        if sp.simplify(sp.cos(root)) == 0:
            continue
        j_val = sp.simplify(-theta0 * sp.sin(root))
        d1 = sp.simplify(sp.expand_trig(sp.diff(f, j_eq).subs(j_eq, j_val)))
        if d1 != 0:
            raise ValueError(f"φ1 = {root} is not stationary in j")
        out.append((j_val, sp.simplify(sp.diff(f, j_eq, 2).subs(j_eq, j_val))))
    return tuple(out)


def eq297(deps) -> sp.Expr:
    """(297): the j where ΔT/T is maximum: the stationary point in j with a negative second derivative."""
    maxima = [jv for jv, d2 in stationary_in_j(deps) if _sign_at_positive(d2) < 0]
    if len(maxima) != 1:
        raise ValueError(f"not one maximum: {maxima}")
    return maxima[0]


def _sign_at_positive(expr: sp.Expr) -> int:
    """The sign of expr for every ε_E, C, G, θ0 > 0 (decided by SymPy with positive stand-ins)."""
    pos = {eps_E: sp.Symbol("e_p", positive=True), G: sp.Symbol("G_p", positive=True)}
    e = sp.simplify(expr.subs(pos))
    if e.is_negative:
        return -1
    if e.is_positive:
        return 1
    raise ValueError(f"sign undecided: {e}")


def eq298(deps) -> sp.Expr:
    """(298): the j where ΔT/T is minimum on |j| ≤ θ0.  The stationary points in j are (297) only (a maximum);
    (295) decreases from it to j = θ0 (dΔT/dj < 0 there: :func:`slope_at_end`), so the minimum over the range of
    (295) is its end, j = θ0 — where Haag's second root (α − β)/2 − π/2 falls when β = α (derived :func:`sin_beta`)."""
    if any(_sign_at_positive(d2) > 0 for _, d2 in stationary_in_j(deps)):
        raise ValueError("a stationary minimum exists")
    if _sign_at_positive(slope_at_end(deps)) >= 0:
        raise ValueError("(295) does not decrease at j = θ0")
    return theta0


def _slope_in_phi(deps) -> sp.Expr:
    """d(ΔT/T)/dj of (295) written in φ1: the chain rule through φ1 = asin(−j/θ0) (153), then j = −θ0 sin φ1 and
    √(1 − sin²φ1) = cos φ1 (φ1 in (−π/2, π/2))."""
    slope = sp.diff(_dT_in_j(deps), j_eq).subs(j_eq, -theta0 * sp.sin(phi1))
    return sp.simplify(slope.subs(sp.sqrt(1 - sp.sin(phi1) ** 2), sp.cos(phi1)))


def slope_at_end(deps) -> sp.Expr:
    """d(ΔT/T)/dj of (295) as j → θ0 from below (φ1 → −π/2 from above)."""
    return sp.simplify(sp.limit(_slope_in_phi(deps), phi1, -sp.pi / 2, dir="+"))


def slope_at_vertical(deps) -> sp.Expr:
    """d(ΔT/T)/dj of (295) at j = 0: its sign is opposite to that of ε_E (the side of the larger modulus is
    opposite to the side towards which the equilibrium must be moved for T to grow)."""
    return sp.simplify(sp.diff(_dT_in_j(deps), j_eq).subs(j_eq, 0))


def jmax_small_dissymmetry(deps) -> sp.Expr:
    """n°98, "ε small against θ0": (297)/θ0 at ε_E = xCθ0² as x → 0 (leading term), and at ε_E = xθ0 as
    θ0 → 0 (ε_E/θ0 = x fixed): returned as (leading term in x at fixed ε_E/(Cθ0²), limit at fixed ε_E/θ0)."""
    x = sp.Symbol("x", positive=True)
    ratio = derived_of(deps, 297, "j_max") / theta0
    small_ratio = sp.series(ratio.subs(eps_E, x * C_s * theta0**2), x, 0, 2).removeO()
    fixed_over_theta0 = sp.limit(ratio.subs(eps_E, x * theta0), theta0, 0)
    return sp.Tuple(sp.simplify(small_ratio), fixed_over_theta0)


def jmax_large_dissymmetry(deps) -> sp.Expr:
    """n°98, "dissymétrie très accentuée": (297)/θ0 as ε_E/(Cθ0²) → ∞."""
    x = sp.Symbol("x", positive=True)
    return sp.limit((derived_of(deps, 297, "j_max") / theta0).subs(eps_E, x * C_s * theta0**2), x, sp.oo)


def eq299() -> sp.Expr:
    """(299): γ defined by sin γ = −j/θ0, in (−π/2, π/2) (a definition): θ0 sin γ + j."""
    return theta0 * sp.sin(gamma_a) + j_eq


def eq300_relation(deps) -> sp.Expr:
    """The line before (300): D = 0 at φ1 = γ written with α (second form of D): sin(2γ − α) − k sin α."""
    return sp.expand(sp.sin(2 * gamma_a - alpha_a) - derived_of(deps, 296, "sin_beta"))


def eq300(deps) -> sp.Expr:
    """(300): D = 0 at φ1 = γ (the measured maximum) solved for ε_E by SymPy."""
    D = derived_of(deps, 296, "D").subs(phi1, gamma_a)
    sol = sp.solve(sp.Eq(D, 0), eps_E)
    if len(sol) != 1:
        raise ValueError(f"not one ε: {sol}")
    return sp.simplify(sol[0])


def eq301(deps) -> sp.Expr:
    """(301): (300) for γ small with sin γ = −j/θ0 (299): the first term of the series in j."""
    expr = derived_of(deps, 300, "eps").subs(gamma_a, sp.asin(-j_eq / theta0))
    return sp.series(expr, j_eq, 0, 2).removeO()


def sense_free_of_G(deps) -> sp.Expr:
    """n°98: (295)/G: free of G (the sensitivity enters as a constant factor), so the sign of dT/dj is G's."""
    return sp.simplify(sp.diff(derived_of(deps, 295, "dT") / G, G))
