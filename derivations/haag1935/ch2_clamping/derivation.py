"""Haag 1935, chapter II, n°31–35, eqs. (116)–(134): clamping errors, derived.

Pure SymPy, step by step as in the memoir, from the governing equations with the two assembly errors
(:func:`tilted_equations`: gravity at the angle i from the clamp's tangent Ox, G at the angle i' from the
tangent AT) and from the derived forms of n°26–30 (:mod:`..ch2_general.derivation`: the bracket of (104),
its version (109) with the isochronism terms, (107), and the classical formula (114)):

- n°31: (116), the ε of the errors, to the second order in i, i' (exact in θ); their first-order part
  leaves the bracket of (104) even in (θ, θ', θ'', Y): no first-order change of period.
- n°32: the equilibrium loads at first order, (23)–(24) solved for θ = j, β = h (117), and j' = i + j (118).
- n°33: the change of variables (119); the equations in θ1, β̃1 are chapter I's (25)–(26) (120); the
  principal oscillation (121), (122).
- n°34: the bracket of (104) with (116) along θ = j + θ1, Y = Kθ1 − i, θ'' = −n²θ1, kept to the terms
  linear in θ1 and quadratic in i, i', j: (123)–(129).
- n°35: the isochronism terms (106)–(109) at the same point, (130)–(132); the total f and Q1 (133), and
  ΔT/T by (114) (134).

Orders are counted by two markers: δ for i, i', j (and h, ΔX's part in them), τ for θ1, θ1', θ1''.  The
blade integrals are moments J(p, q) (:mod:`..ch2_common`); :func:`in_h` rewrites a combination of moments
in h (127), h' (132) and the F_n when it is one.
"""
from __future__ import annotations

import functools

import sympy as sp

from .. import ch1_model
from ..ch2_common import (H_moments, J, Y_ddot, Y_dot, alpha_ddot, beta1_var, dX, eps1, eps2, eps3, eps_lambda,
                          h_127, h_132, h_beta, i_clamp, i_prime, in_F, j_eq, psi_s, theta0, theta1)
from ..ch2_general import derivation as general
from ..symbols import (Fn, K, N, R, X, Y, a, a1, beta, beta_ddot, g, n_squared, theta, theta_ddot, theta_dot,
                       varphi1_s, vl, w0, wl, z, zp)

delta = sp.Symbol("delta", positive=True)      # order of i, i', j
tau = sp.Symbol("tau", positive=True)          # order of θ1 (and its derivatives)
theta1_dot = sp.Symbol("theta_1'", real=True)
ERRORS = {i_clamp: delta * i_clamp, i_prime: delta * i_prime}


def coefficient(expr: sp.Expr, marker: sp.Symbol, k: int) -> sp.Expr:
    """The coefficient of marker^k in the Taylor series of expr in marker."""
    return sp.expand(sp.series(expr, marker, 0, k + 1).removeO().coeff(marker, k))


def part(expr: sp.Expr, d: int, t: int) -> sp.Expr:
    """The δ^d τ^t part of an expression already written with the markers."""
    return coefficient(coefficient(sp.expand(expr), delta, d), tau, t)


# ================================================================ n°31: (116)
def tilted_equations() -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    """(4), (5), (6) with the errors, exactly, as expressions = 0 (divided by m): in the blade's axes gravity
    is g(cos i, −sin i) and x_G = α + a cos(θ + i'), y_G = β + a sin(θ + i'):
    α'' − aθ'²cos(θ+i') − aθ''sin(θ+i') − g(cos i − X), β'' + a(θ''cos(θ+i') − θ'²sin(θ+i')) + g(Y + sin i),
    R²θ''/g + N − a(Y cos(θ+i') − X sin(θ+i'))."""
    th = theta + i_prime
    e4 = alpha_ddot - a * theta_dot**2 * sp.cos(th) - a * theta_ddot * sp.sin(th) - g * (sp.cos(i_clamp) - X)
    e5 = beta_ddot + a * (theta_ddot * sp.cos(th) - theta_dot**2 * sp.sin(th)) + g * (Y + sp.sin(i_clamp))
    e6 = R**2 / g * theta_ddot + N - a * (Y * sp.cos(th) - X * sp.sin(th))
    return e4, e5, e6


def _no_errors(expr: sp.Expr) -> sp.Expr:
    return expr.subs({i_clamp: 0, i_prime: 0})


def eq116() -> sp.Tuple:
    """(116): (ε1, ε2, ε3) of the errors — what (4), (5), (6) with i, i' hold beyond the same equations
    without them (1 − X + ε1 = 0 (88), β'' + aθ'' = g(−Y + ε2) (89), R²θ'' = g(−N + aY − aθX + ε3) (90)),
    to the second order in i, i'."""
    e4, e5, e6 = tilted_equations()
    out = []
    for expr, scale in ((e4, g), (e5, g), (e6, 1)):
        extra = -(expr - _no_errors(expr)) / scale
        series = sp.series(extra.subs(ERRORS, simultaneous=True), delta, 0, 3).removeO().subs(delta, 1)
        out.append(sp.expand(series))
    return sp.Tuple(*out)


def bracket_of_104(e1: sp.Expr, e2: sp.Expr, e3: sp.Expr, euler_half: sp.Expr | None = None) -> sp.Expr:
    """The bracket of (104) (derived, :func:`..ch2_general.derivation.eq104`) with no blade perturbation
    (∫ε'φ_i = 0, ε_λ = 0) and the given ε1, ε2, ε3; with ``euler_half``, ½(K∂H2/∂Y + ∂H2/∂θ) is replaced
    by it (the bracket is linear in ε1, whose coefficient is aθ + that half, in moments)."""
    E1, E2 = sp.symbols("E_1 E_2")
    br = sp.expand(general.eq104().subs({E1: 0, E2: 0, eps_lambda: 0}))
    c1, c2, c3 = (sp.expand(br.diff(e)) for e in (eps1, eps2, eps3))
    half = sp.expand(general.euler_operator(H_moments(2)) / 2)
    assert sp.expand(c1 - a * theta - half) == 0 and sp.expand(br - c1 * eps1 - c2 * eps2 - c3 * eps3) == 0
    if euler_half is not None:
        c1 = a * theta + euler_half
    return c1 * e1 + c2 * e2 + c3 * e3


def first_order_odd_part() -> sp.Expr:
    """n°31: the part of the bracket of (104), with the first-order ε of (116) (X = 1), that is odd in
    (θ, θ', θ'', Y) together: 0, so that its first harmonic along the oscillation vanishes."""
    e1, e2, e3 = (coefficient(e.subs(ERRORS, simultaneous=True), delta, 1) for e in eq116())
    br = bracket_of_104(e1, e2, e3).subs(X, 1)
    flip = {theta: -theta, theta_dot: -theta_dot, theta_ddot: -theta_ddot, Y: -Y}
    return sp.simplify((br - br.subs(flip, simultaneous=True)) / 2)


# ================================================================ n°32: (117), (118)
def equilibrium_loads() -> sp.Tuple:
    """n°32: X, Y, N at rest from the tilted (4)–(6), to the first order in i, i', θ (and Y, N): X = 1,
    Y = −i, N = a(Y − Xθ − i'X) with that Y."""
    rest = {alpha_ddot: 0, beta_ddot: 0, theta_ddot: 0, theta_dot: 0}
    e4, e5, e6 = (e.subs(rest) for e in tilted_equations())
    first = {i_clamp: delta * i_clamp, i_prime: delta * i_prime, theta: delta * theta, Y: delta * Y}
    X_rest = sp.solve(e4, X)[0]
    Y_rest = sp.solve(e5, Y)[0]
    N_rest = sp.solve(e6, N)[0]

    def lin(expr, order):
        return sp.expand(sp.series(expr.subs(first, simultaneous=True), delta, 0, order + 1).removeO().subs(delta, 1))
    X1, Y1 = lin(X_rest, 0), lin(Y_rest, 1)
    N1 = lin(N_rest, 1).subs(X, X1).subs(Y, Y1)
    return sp.Tuple(X1, Y1, sp.expand(N1))


@functools.lru_cache(maxsize=1)
def equilibrium_solution() -> dict:
    """(23) Y(β, θ) and (24) N(β, θ) equal to the loads of :func:`equilibrium_loads`: a linear system in β, θ."""
    _, Y1, N1 = equilibrium_loads()
    sol = sp.solve([sp.Eq(ch1_model.Y_of_end(), Y1), sp.Eq(ch1_model.N_of_end(), N1)], [beta, theta], dict=True)[0]
    return {k: sp.factor(v.subs(wl, -a1)) for k, v in sol.items()}        # wλ = −a1 (41)


def eq117_j() -> sp.Expr:
    """(117): j = θ at the equilibrium, with wλ = −a1 (41)."""
    return equilibrium_solution()[theta]


def eq117_h() -> sp.Expr:
    """(117): h = β at the equilibrium, from (23) with Y = −i: β = β1Y − β2θ... i.e. −β1 i − vλ j."""
    _, Y1, _ = equilibrium_loads()
    return sp.expand(sp.solve(sp.Eq(ch1_model.Y_of_end(), Y1), beta)[0].subs(theta, j_eq))


def eq118() -> sp.Expr:
    """(118): j' = i + j, with vλ = w0 − wλ (16) and wλ = −a1 (41)."""
    jp = i_clamp + eq117_j()
    return sp.factor(sp.expand(sp.together(jp.subs(vl, w0 + a1))))


# ================================================================ n°33: (119)–(122)
def eq119() -> sp.Tuple:
    """(119): θ = j + θ1, β = h + β̃1."""
    return sp.Tuple(j_eq + theta1, h_beta + beta1_var)


def eq120_residual() -> sp.Tuple:
    """(120): (25), (26) with the perturbation of the errors at the first order (gε2 = −gi, gε3 = −gai',
    the parts of (116) free of θ), at θ = j + θ1, β = h + β̃1 (j, h of (117)), minus (25), (26) in (β̃1, θ1):
    (0, 0), so that the motion about the new equilibrium is chapter I's, θ1'' = −n²θ1 for the principal one."""
    e1, e2, e3 = (coefficient(e.subs(ERRORS, simultaneous=True), delta, 1).subs(
        {theta: 0, theta_dot: 0, theta_ddot: 0, X: 1, Y: 0}) for e in eq116())
    r25, r26 = ch1_model.motion()
    j, h = equilibrium_solution()[theta], equilibrium_solution()[beta]
    shifted = {beta: h + beta1_var, theta: j + theta1}
    plain = {beta: beta1_var, theta: theta1}
    out = (r25.subs(shifted, simultaneous=True) + g * e2 - r25.subs(plain, simultaneous=True),
           r26.subs(shifted, simultaneous=True) + g * e3 - r26.subs(plain, simultaneous=True))
    return sp.Tuple(*(sp.simplify(x.subs(wl, -a1)) for x in out))


def eq121() -> sp.Expr:
    """(121): β̃1 in the principal oscillation: (26) in (β̃1, θ1) with R²θ1'' = −n²R²θ1, n² of (34) (n²
    with z = −R²/z'), solved for β̃1; R² eliminated by the quadratic (30) for the focus z'."""
    _, r26 = ch1_model.motion()
    n2 = ch1_model.n2_of_focus()
    sol = sp.solve(sp.Eq(r26.subs({beta: beta1_var, theta: theta1}), -n2 * R**2 * theta1), beta1_var)[0]
    # (30) holds for both foci: its monic quadratic in z, at z = z', gives R² in terms of z'
    quad = ch1_model.foci_quadratic().as_expr().subs(z, zp)
    R2 = sp.solve(quad, R**2)
    if R2:
        return sp.factor(sp.simplify(sol.subs(R**2, R2[0])))
    return sp.factor(sol)


def eq122() -> sp.Expr:
    """(122): Y of (23) at θ = j + θ1, β = h + β̃1 with h of (117) (in j), β̃1 of (121), and z' from (35)."""
    Yv = ch1_model.Y_of_end().subs({beta: eq117_h() + eq121(), theta: j_eq + theta1}, simultaneous=True)
    zp_of_K = sp.solve(sp.Eq(ch1_model.K_of_zp(), K), zp)[0]
    return sp.expand(sp.simplify(Yv.subs(zp, zp_of_K)))


# ================================================================ n°34: (123)–(129)
def along() -> dict:
    """The principal oscillation about the equilibrium, with the markers: θ = j + θ1, Y = Kθ1 − i (122),
    θ'' = −n²θ1 (120), θ' = θ1', the errors and j of order δ, θ1 of order τ; n² = −Kg/z' (34)."""
    return {theta: delta * j_eq + tau * theta1, Y: K * tau * theta1 - delta * i_clamp,
            theta_ddot: K * g / zp * tau * theta1, theta_dot: tau * theta1_dot,
            i_clamp: delta * i_clamp, i_prime: delta * i_prime}


def _marked(expr: sp.Expr) -> sp.Expr:
    return expr.subs(along(), simultaneous=True)


@functools.lru_cache(maxsize=1)
def errors_marked() -> tuple:
    """(116) along the oscillation, X = 1 + ΔX with ΔX of order τδ (its symbol kept)."""
    return tuple(_marked(e).subs(X, 1 + tau * delta * dX) for e in eq116())


def eq123() -> sp.Tuple:
    """(123): (θε1, ε2), their parts linear in θ1 and quadratic in i, i', j."""
    e1, e2, _ = errors_marked()
    theta_m = delta * j_eq + tau * theta1
    return sp.Tuple(part(theta_m * e1, 2, 1), part(e2, 2, 1))


def eq124() -> sp.Expr:
    """(124): ε3, the part linear in θ1 and quadratic in i, i', j, ΔX kept."""
    return part(errors_marked()[2], 2, 1).subs(tau * delta * dX, dX)


def eq125() -> sp.Expr:
    """(125): ΔX = ε1 (92) reduced to its part linear in θ1 and in i, j."""
    return part(errors_marked()[0], 1, 1)


def half_euler_H2_marked() -> sp.Expr:
    """½(K∂H2/∂Y + ∂H2/∂θ) (moments) along the oscillation."""
    return _marked(sp.expand(general.euler_operator(H_moments(2)) / 2))


def eq127() -> sp.Expr:
    """(127): h = ½(K∂H2/∂Y + ∂H2/∂θ) at Y = −i, θ = j, in moments."""
    return sp.expand((general.euler_operator(H_moments(2)) / 2).subs({Y: -i_clamp, theta: j_eq}, simultaneous=True))


def eq126() -> sp.Expr:
    """(126): ½(K∂H2/∂Y + ∂H2/∂θ) along the oscillation: its θ1 part in F_n, plus h (127)."""
    marked = half_euler_H2_marked()
    rest = sp.expand(marked - part(marked, 0, 1) * tau - part(marked, 1, 0) * delta)
    assert rest == 0 and sp.expand(part(marked, 1, 0) - eq127()) == 0
    return in_F(part(marked, 0, 1)) + h_127


def eq128() -> sp.Expr:
    """(128): ε1 times (126), the part linear in θ1 and quadratic in i, i', j (h of order δ)."""
    e1 = errors_marked()[0]
    return part(e1 * (tau * (eq126() - h_127) + delta * h_127), 2, 1)


def clamping_bracket() -> sp.Expr:
    """The bracket of (104) with (116) along the oscillation, ΔX = (125), ½(K∂H2/∂Y + ∂H2/∂θ) = (126); the
    part linear in θ1 and quadratic in i, i', j."""
    e1, e2, e3 = errors_marked()
    euler_half = tau * (eq126() - h_127) + delta * h_127
    br = _marked(bracket_of_104(sp.Symbol("E1"), sp.Symbol("E2"), sp.Symbol("E3"), euler_half=sp.Symbol("U")))
    br = br.subs({sp.Symbol("E1"): e1, sp.Symbol("E2"): e2, sp.Symbol("E3"): e3, sp.Symbol("U"): euler_half})
    return part(br.subs(dX, eq125()), 2, 1)        # ΔX (marked τδ in X = 1 + τδΔX) is (125)


@functools.lru_cache(maxsize=1)
def eq129() -> sp.Expr:
    """(129): f = −(n²/K)·(the bracket of :func:`clamping_bracket`)."""
    return sp.expand(-n_squared / K * clamping_bracket())


# ================================================================ n°35: (130)–(134)
def alpha_dd_marked() -> sp.Expr:
    """α'' from (107) along the oscillation (Y'' = Kθ1'', Y' = Kθ1', θ1'' = −n²θ1), in moments."""
    acc = sp.solve(sp.Eq(-2 * alpha_ddot, general.eq107()), alpha_ddot)[0]
    rep = {Y_ddot: K * theta_ddot, Y_dot: K * theta_dot}
    return _marked(acc.subs(rep))


def eq130() -> sp.Expr:
    """(130): α'' linear in θ1 and in i, j, with n² restored (θ1'' = −n²θ1); moments as h (127)."""
    alpha_dd = part(alpha_dd_marked(), 1, 1)
    return in_h(alpha_dd.subs(g, -n_squared * zp / K))


def eps1_isochronism() -> sp.Expr:
    """ε1 of (106) along the oscillation (α'' of (107)), linear in θ1 and in i, j: (K/z')(aj + h)θ1."""
    g1 = general.eq106()[0]
    e1 = _marked(g1).subs(alpha_ddot, alpha_dd_marked()) / g
    return in_h(part(e1, 1, 1))


def eq131() -> sp.Expr:
    """(131): the increase of −Kf/n² from ΔX + ε1 of (106) in ε3 (the −ε3 of the bracket)."""
    e3 = errors_marked()[2]
    e3_more = sp.expand(e3.subs(dX, dX + eps1_isochronism()) - e3)
    br = _marked(bracket_of_104(0, 0, sp.Symbol("E3"))).subs(sp.Symbol("E3"), e3_more)
    return part(br, 2, 1)


@functools.lru_cache(maxsize=1)
def isochronism_bracket() -> sp.Expr:
    """The bracket of (109) (derived, with (K/6)H3) with ε1 of (106) and α'' of (107), along the oscillation
    about the tilted equilibrium: the part linear in θ1 and quadratic in i, j, in moments."""
    g1 = general.eq106()[0]
    br = general.eq109_bracket().subs(eps1, g1 / g).subs(alpha_ddot, sp.Symbol("A2"))
    marked = _marked(br).subs(sp.Symbol("A2"), alpha_dd_marked())
    return part(marked, 2, 1)


def eq132() -> sp.Expr:
    """(132): h' = (K²∂²/∂Y² + 2K∂²/∂Y∂θ + ∂²/∂θ²)H at Y = −i, θ = j, H = 4YH3 − H4 (108), in moments."""
    H = general.H_108()
    op = K**2 * H.diff(Y, 2) + 2 * K * H.diff(Y, theta) + H.diff(theta, 2)
    return sp.expand(op.subs({Y: -i_clamp, theta: j_eq}, simultaneous=True))


@functools.lru_cache(maxsize=1)
def eq132_delta_f() -> sp.Expr:
    """Δf of n°35: (131) and the isochronism bracket, times −n²/K, in h, h', F2."""
    return sp.expand(-n_squared / K * (eq131() + in_h(isochronism_bracket())))


def f_total() -> sp.Expr:
    """f of n°35: (129) + Δf."""
    return sp.expand(eq129() + eq132_delta_f())


def eq133() -> sp.Expr:
    """(133): Q1 defined by f = (2Q1/K)n²θ1."""
    return sp.expand(K * f_total() / (2 * n_squared * theta1))


def eq134() -> sp.Expr:
    """(134): ΔT/T of f by (114): the perturbation of θ1'' is f/(z − z'), θ1 = θ0 cos φ; over Q = K(z − z')."""
    ph = sp.Symbol("phi")
    Phi = f_total() / (z - zp)
    C = sp.integrate(sp.expand(Phi.subs(theta1, theta0 * sp.cos(ph)) * sp.cos(ph)), (ph, 0, 2 * sp.pi))
    return sp.factor(sp.simplify(general.eq114_relative().subs(sp.Symbol("C"), C)))


# ================================================================ moments in h, h', F_n
def in_h(expr: sp.Expr) -> sp.Expr:
    """A polynomial in the moments J(p, q) rewritten in h (127), h' (132) and the F_n, when it is one.

    In the basis L(p, q) = ∫φ1^p ψ^q ds (ψ = Kφ1 + φ2), h = −(i + Kj)L(1, 1) + jF2 and h' holds L(2, 2)
    with the coefficient −12(i + Kj)²: both are solved for those moments, the rest must be F_n = L(0, n);
    raises if a moment with p > 0 remains."""
    L = sp.Function("L")
    expr = sp.expand(expr)
    moments = sorted(expr.atoms(J) | eq127().atoms(J) | eq132().atoms(J), key=sp.srepr)

    def to_L(e):
        rep = {}
        for mom in moments:
            p, q = (int(x) for x in mom.args)
            poly = sp.Poly(sp.expand(varphi1_s**p * (psi_s - K * varphi1_s) ** q), varphi1_s, psi_s)
            rep[mom] = sum(c * L(pp, qq) for (pp, qq), c in poly.terms())
        return sp.expand(e.xreplace(rep))
    h_L, hp_L, ex_L = to_L(eq127()), to_L(eq132()), to_L(expr)
    s11 = sp.solve(sp.Eq(h_L, h_127), L(1, 1))[0]
    s22 = sp.solve(sp.Eq(hp_L.subs(L(1, 1), s11), h_132), L(2, 2))[0]
    out = sp.expand(sp.cancel(ex_L.subs(L(2, 2), s22).subs(L(1, 1), s11)))
    rest = [x for x in out.atoms(L) if int(x.args[0]) != 0]
    if rest or not sp.denom(sp.together(out)).free_symbols <= {K, zp}:
        raise ValueError(f"not a function of h, h', F_n: {rest}")
    return sp.expand(out.xreplace({x: Fn(int(x.args[1])) for x in out.atoms(L)}))
