"""Haag 1935, chapter II, n°26–30, eqs. (88)–(114): the general perturbation theory, derived.

Pure SymPy, from chapter I's governing equations (2)–(7) (:func:`..ch1_model.newton_euler`, the loads
(23)–(24), the focal conditions (28)–(31), K of (34)–(35)) kept to the next order:

- n°26: the exact (4)–(6) minus their first approximation define ε1, ε2, ε3 ((88)–(90)); the perturbing
  acceleration f = y'' + n²y of the canonical variable y = β + (a + z)θ (27) is (91) once the first-order
  terms vanish on the focal conditions.
- n°27: the blade's correction x obeys (93); (101), (102) follow here from two Green identities, with
  φ1 = 1 + v' and φ2 = w', (9)–(10) (Haag integrates (93) by variation of constants, (95)–(100): the
  same two relations; those intermediate steps are not rebuilt).
- n°28–29: (104), the neglected terms (106) as series of the exact equations, α = λ − ½H2 and (107),
  (108)–(110), the principal oscillation (Y = Kθ, θ'' = −n²θ) and the change of period by the classical
  formula (114), giving (111), (112).

The blade integrals are handled in moments (:mod:`..ch2_common`).
"""
from __future__ import annotations

import functools

import sympy as sp

from .. import ch1_model
from ..ch2_common import (H_moments, Y_ddot, Y_dot, alpha_ddot, blade_integral, dN, dX, dY, eps1, eps2, eps3,
                          eps_blade, eps_lambda, in_F, phi_s, theta0)
from ..symbols import (K, M_of_s, N, R, X, Y, a, beta, beta1, beta_ddot, g, lam, n_squared, s, theta, theta_ddot,
                       theta_dot, v, varphi1_s, varphi2_s, w, z, zp)

small = sp.Symbol("delta", positive=True)          # order counter: θ, θ', θ'', β, Y, N, φ ~ δ


# ================================================================ n°26: (88)–(91)
def exact_4() -> sp.Expr:
    """(4) as expression = 0 (divided by m): α'' − aθ'²cos θ − aθ''sin θ − g(1 − X)."""
    return alpha_ddot - a * theta_dot**2 * sp.cos(theta) - a * theta_ddot * sp.sin(theta) - g * (1 - X)


def perturbations() -> dict:
    """gε1, gε2, ε3: what the exact (4), (5), (6) hold beyond 1 − X = 0, β'' + aθ'' = −gY,
    R²θ'' = g(−N + aY − aθX) — (88)–(90) with no perturbing force, exactly (n°29 expands them)."""
    e5, e6 = ch1_model.newton_euler()
    # (4): 1 − X + ε1 = 0 with 1 − X = (α'' − aθ'²cos θ − aθ''sin θ)/g
    g_eps1 = sp.expand(-(exact_4() + g * (1 - X)))
    # (5): β'' + aθ'' + gY − gε2 = 0 and e5 = 0
    g_eps2 = sp.expand((beta_ddot + a * theta_ddot + g * Y) - e5)
    # (6): R²θ''/g + N − aY + aθX − ε3 = 0 and e6 = 0
    eps_3 = sp.expand((R**2 / g * theta_ddot + N - a * Y + a * theta * X) - e6)
    return {"g_eps1": g_eps1, "g_eps2": g_eps2, "eps3": eps_3}


def eq88() -> sp.Expr:
    """(88): 1 − X + ε1 (= 0): −(4)/g at the first approximation (α'' = θ' = θ'' = 0), plus ε1."""
    first = sp.expand(-exact_4().subs({alpha_ddot: 0, theta_dot: 0, theta_ddot: 0}) / g)
    return first + eps1


def eq89() -> sp.Expr:
    """(89): the right side of β'' + aθ'' = g(−Y + ε2): the linearised (5) plus gε2."""
    e5 = ch1_model.linearized(ch1_model.newton_euler()[0])
    return sp.expand(beta_ddot + a * theta_ddot - e5 + g * eps2)


def eq90() -> sp.Expr:
    """(90): the right side of R²θ'' = g(−N + aY − aθX + ε3): (6) to the first order in θ, X kept, plus gε3."""
    e6 = ch1_model.newton_euler()[1]
    e6_first = sp.expand(e6.subs({sp.cos(theta): 1, sp.sin(theta): theta}))
    return sp.expand(R**2 * theta_ddot - g * e6_first + g * eps3)


@functools.lru_cache(maxsize=1)
def canonical_acceleration() -> tuple[sp.Expr, sp.Expr]:
    """f = y'' + n²y (27) with β'' + aθ'' and θ'' from (89), (90) and the loads Y + ΔY, N + ΔN,
    X = 1 + ΔX, Y and N of the first approximation (23), (24).

    Returns (first-order part, remainder): the first is linear in β, θ; the second holds ΔX, ΔY, ΔN, ε."""
    Yl, Nl = ch1_model.Y_of_end(), ch1_model.N_of_end()
    acc_lin = -g * (Y + dY) + g * eps2                                    # β'' + aθ'' (89)
    th_acc = g * (-(N + dN) + a * (Y + dY) - a * theta * (1 + dX) + eps3) / R**2   # θ'' (90)
    f = acc_lin + z * th_acc + n_squared * (beta + (a + z) * theta)
    f = sp.expand(f.subs({Y: Yl, N: Nl}))
    corr = (dX, dY, dN, eps2, eps3)
    first = sum(t for t in sp.Add.make_args(f) if not t.has(*corr))
    return sp.expand(first), sp.expand(f - first)


def first_order_vanishes() -> sp.Expr:
    """n°26: the first-order part of f with n² from (28) and z a root of (30): identically 0."""
    first, _ = canonical_acceleration()
    c28, _ = ch1_model.focal_conditions()
    n2 = sp.solve(c28, n_squared)[0]
    expr = sp.together(first.subs(n_squared, n2))
    num = sp.expand(sp.numer(expr))
    quad = ch1_model.foci_quadratic().as_expr()
    return sp.expand(sp.rem(sp.Poly(num, z), sp.Poly(quad, z)).as_expr())


def eq91() -> sp.Expr:
    """(91): the remainder of f with z/R² = −1/z' (31: zz' = −R²)."""
    _, rest = canonical_acceleration()
    return sp.expand(rest.subs(z, -R**2 / zp))


# ================================================================ n°27: (92)–(102)
def eq92() -> sp.Expr:
    """(92): ΔX from (88) with X = 1 + ΔX."""
    return sp.solve(eq88().subs(X, 1 + dX), dX)[0]


def blade_cubic() -> sp.Expr:
    """X sin φ − Y cos φ − (Xφ − Y) to the third order in φ, Y (X = 1): the ε' of (106)."""
    ph, Yv = sp.symbols("phi Y_", real=True)
    expr = (sp.sin(small * ph) - sp.cos(small * ph) * small * Yv) - (small * ph - small * Yv)
    return sp.expand(sp.series(expr, small, 0, 4).removeO().subs(small, 1)), ph, Yv


def eq93() -> sp.Expr:
    """(93): (7) with φ + x, X = 1 + ΔX, Y + ΔY, minus its first approximation (Mφ')' = φ − Y, kept to
    the order of ΔX, ΔY, x (products of corrections dropped): the right side of (Mx')' − x."""
    xf, phf = sp.Function("x"), sp.Function("varphi")
    lhs = sp.diff(M_of_s(s) * (phf(s) + small * xf(s)).diff(s), s)
    rhs = (1 + small * dX) * (phf(s) + small * xf(s)) - Y - small * dY + small * eps_blade
    first = sp.diff(M_of_s(s) * phf(s).diff(s), s) - (phf(s) - Y)
    eq = sp.expand(lhs - rhs - first)
    second = sp.expand(eq.coeff(small, 1))
    # (Mx')' − x − (φΔX + ε' − ΔY) = 0
    return sp.expand(-(second - sp.diff(M_of_s(s) * xf(s).diff(s), s) + xf(s)))


def eq94() -> sp.Expr:
    """(94): ε_bar = φε1 + ε' (by (92))."""
    from ..symbols import varphi
    return sp.expand(eq93().subs(dY, 0).subs(dX, eq92()).subs(varphi(s), sp.Symbol("varphi", real=True)))


@functools.lru_cache(maxsize=1)
def green_identities() -> tuple[sp.Expr, sp.Expr]:
    """For ψ = φ1 = 1 + v' and ψ = φ2 = w': [(Mx')' − x]ψ − d/ds[Mx'ψ − Mψ'x] − x[(Mψ')' − ψ] (≡ 0), and
    (Mψ')' − ψ with Mv'' = v, Mw'' = w (9): −1 for φ1, 0 for φ2."""
    xf = sp.Function("x")
    out = []
    for psi in (1 + v(s).diff(s), w(s).diff(s)):
        identity = sp.expand((sp.diff(M_of_s(s) * xf(s).diff(s), s) - xf(s)) * psi
                             - sp.diff(M_of_s(s) * xf(s).diff(s) * psi - M_of_s(s) * psi.diff(s) * xf(s), s)
                             - xf(s) * (sp.diff(M_of_s(s) * psi.diff(s), s) - psi))
        assert sp.simplify(identity) == 0
        adjoint = sp.diff(M_of_s(s) * psi.diff(s), s) - psi
        adjoint = adjoint.subs({v(s).diff(s, 2): v(s) / M_of_s(s), w(s).diff(s, 2): w(s) / M_of_s(s)})
        adjoint = sp.simplify(adjoint.doit().subs({v(s).diff(s, 2): v(s) / M_of_s(s),
                                                    w(s).diff(s, 2): w(s) / M_of_s(s)}))
        out.append(adjoint)
    return tuple(out)


def Delta_Y(beta_cubic: sp.Expr = sp.S.Zero) -> sp.Expr:
    """(101): ∫(93)·φ1 ds = [Mx'φ1 − Mφ1'x]_0^λ − ∫x ds; x(0) = x(λ) = 0, φ1(0) = φ1(λ) = 0 (10), and
    ∫x ds = ``beta_cubic`` (0 in n°27, ∫φ³/6 ds in n°29, β being given): ΔY∫φ1 = ∫ε_barφ1 + ∫x.
    ∫φ1 ds = β1 (22); ∫ε_barφ1 ds is kept as the symbol I_1."""
    adj1, _ = green_identities()
    I1 = sp.Symbol("I_1")                      # ∫ε_barφ1 ds
    int_phi1 = ch1_model.beta1_def()           # ∫φ1 ds = λ + vλ − v0
    # ∫(ε_bar − ΔY)φ1 = boundary (0) + adj1·∫x
    eq = sp.Eq(I1 - dY * beta1, adj1 * beta_cubic)
    assert sp.simplify(int_phi1 - (lam + ch1_model.ends(v(lam)) - ch1_model.ends(v(0)))) == 0
    return sp.solve(eq, dY)[0]


def Delta_N() -> sp.Expr:
    """(102): ∫(93)·φ2 ds = [Mx'φ2 − Mφ2'x]_0^λ = M_λx'_λ (φ2(0) = 0, φ2(λ) = 1), (Mφ2')' − φ2 = 0, and
    M_λx'_λ = ΔN + ε_λ ((2) at s = λ); ∫φ2 = −vλ ((22) reduced by (16)); ∫ε_barφ2 ds kept as I_2."""
    _, adj2 = green_identities()
    assert adj2 == 0
    I2 = sp.Symbol("I_2")
    int_phi2 = ch1_model.beta2_def()           # ∫φ2 ds = wλ − w0 = −vλ
    return sp.solve(sp.Eq(I2 - dY * int_phi2, dN + eps_lambda), dN)[0]


# ================================================================ n°28: (104)
def eq104_bracket(beta_cubic: sp.Expr = sp.S.Zero) -> sp.Expr:
    """(104): f = −(n²/K)[…]: (91) with ΔX (92), ΔY (101), ΔN (102), a + z' − vλ = −Kβ1 (35) and
    g/z' = −n²/K (34); returns the bracket, with ∫ε_barφ1 = I_1, ∫ε_barφ2 = I_2."""
    from ..symbols import vl
    f = eq91().subs({dN: Delta_N()}).subs({dY: Delta_Y(beta_cubic), dX: eq92()})
    f = sp.expand(f.subs(vl, a + zp + K * beta1))          # (35)
    bracket = sp.expand(f * zp / g)                        # f = (g/z')[…]
    return bracket


def eq104() -> sp.Expr:
    """(104): the bracket with ε_bar = φε1 + ε' (94): ∫ε_barφ_i = ε1∫φφ_i + E_i, E_i = ∫ε'φ_i ds, φ = Yφ1 + θφ2
    (13) in moments."""
    E1, E2 = sp.symbols("E_1 E_2")
    I1 = eps1 * blade_integral(phi_s * varphi1_s) + E1
    I2 = eps1 * blade_integral(phi_s * varphi2_s) + E2
    return sp.expand(eq104_bracket().subs({sp.Symbol("I_1"): I1, sp.Symbol("I_2"): I2}))


def eq105() -> sp.Expr:
    """(105): ∫ε'ψ ds − ε_λ with ψ = Kφ1 + φ2, integrated by parts: [εψ]_0^λ − ∫εψ' ds − ε_λ, with
    ψ' = (Kv + w)/M by (9) and ψ(0) = 0, ψ(λ) = 1 by (10)."""
    eps_f = sp.Function("epsilon")
    psi = K * (1 + v(s).diff(s)) + w(s).diff(s)
    psi_p = sp.expand(psi.diff(s).subs({v(s).diff(s, 2): v(s) / M_of_s(s), w(s).diff(s, 2): w(s) / M_of_s(s)}))
    ends10 = {v(s).diff(s): -1}                              # v'(0) = v'(λ) = −1
    psi_0 = psi.subs(ends10).subs(w(s).diff(s), 0)           # w'(0) = 0
    psi_l = psi.subs(ends10).subs(w(s).diff(s), 1)           # w'(λ) = 1
    boundary = eps_lambda * psi_l - eps_f(0) * psi_0
    return sp.expand(boundary - eps_lambda) - sp.Integral(sp.factor(eps_f(s) * psi_p), (s, 0, lam))


# ================================================================ n°29: (106)–(112)
def series3(expr: sp.Expr, scale: dict) -> sp.Expr:
    """expr to the third order in δ after ``scale`` (θ → δθ …), δ → 1."""
    scaled = expr.subs({k: small * k for k in scale}, simultaneous=True)
    return sp.expand(sp.series(scaled, small, 0, 4).removeO().subs(small, 1))


@functools.lru_cache(maxsize=1)
def eq106() -> sp.Tuple:
    """(106): (gε1, gε2, ε3, ε') — the exact terms of (4), (5), (6), (7) beyond the first approximation,
    to the third order in θ, θ', θ'', Y, φ (α'' kept as second order; X = 1 + O(2) in ε3)."""
    p = perturbations()
    order = (theta, theta_dot, theta_ddot, Y, N)
    g1 = series3(p["g_eps1"], order)          # (α'' is not scaled: it is already of the second order)
    g1 = sp.expand(g1.subs(X, 1))
    g2 = series3(p["g_eps2"], order)
    e3 = series3(p["eps3"].subs(X, 1), order)
    cubic, ph, Yv = blade_cubic()
    return sp.Tuple(g1, g2, e3, cubic.subs({ph: sp.Symbol("varphi", real=True), Yv: Y}))


def H_103() -> sp.Integral:
    """(103): H_n = ∫(Yφ1 + θφ2)^n ds, φ = Yφ1 + θφ2 of (13) raised to the power n."""
    from ..symbols import varphi1, varphi2
    nn = sp.Symbol("n", integer=True, positive=True)
    return sp.Integral((Y * varphi1(s) + theta * varphi2(s)) ** nn, (s, 0, lam))


def H_108() -> sp.Expr:
    """(108): H = 4YH3 − H4 (the combination whose (K∂/∂Y + ∂/∂θ)/24 is the n°29 term), in moments."""
    return sp.expand(4 * Y * H_moments(3) - H_moments(4))


def alpha_of_H2() -> sp.Expr:
    """α = ∫cos φ ds = λ − ½∫φ² ds = λ − ½H2 (n°29, from (3)), H2 in moments."""
    ph = sp.Symbol("varphi", real=True)
    integrand = sp.series(sp.cos(small * ph), small, 0, 3).removeO().subs(small, 1)
    integrand = integrand.subs(ph, phi_s)
    return lam * 1 + blade_integral(integrand - 1)


def eq107() -> sp.Expr:
    """(107): −2α'' with Y(t), θ(t): d²/dt² of H2(Y, θ) (α = λ − ½H2)."""
    tt = sp.Symbol("t")
    Yf, thf = sp.Function("Yf")(tt), sp.Function("thf")(tt)
    alpha = alpha_of_H2().subs({Y: Yf, theta: thf}, simultaneous=True)
    acc = sp.diff(alpha, tt, 2)
    rep = {Yf.diff(tt, 2): Y_ddot, thf.diff(tt, 2): theta_ddot, Yf.diff(tt): Y_dot, thf.diff(tt): theta_dot,
           Yf: Y, thf: theta}
    for k in sorted(rep, key=lambda e: -sp.count_ops(e)):
        acc = acc.subs(k, rep[k])
    return sp.expand(-2 * acc)


def H_def_108() -> sp.Expr:
    """(108) as the text uses it: the combination (K/6)H3 + ∫ε'(Kφ1 + φ2) ds of n°29 (ε' of (106)),
    in moments."""
    _, _, _, cubic = eq106()
    cubic = cubic.subs(sp.Symbol("varphi", real=True), phi_s)
    return sp.expand(K / 6 * H_moments(3) + blade_integral(cubic * (K * varphi1_s + varphi2_s)))


def euler_operator(expr: sp.Expr) -> sp.Expr:
    """K ∂/∂Y + ∂/∂θ (n°28–29)."""
    return sp.expand(K * sp.diff(expr, Y) + sp.diff(expr, theta))


def eq109_bracket() -> sp.Expr:
    """(109): the bracket of (104) with the ε of (106), ε_λ = 0, and the term (K/6)H3 of n°29 (∫x ds =
    ∫φ³/6 ds in (101)); ∫ε_barφ_i with ε_bar = φε1 + ε' in moments."""
    g1, g2, e3, cubic = eq106()
    cubic = cubic.subs(sp.Symbol("varphi", real=True), phi_s)
    I1 = blade_integral((phi_s * eps1 + cubic) * varphi1_s)
    I2 = blade_integral((phi_s * eps1 + cubic) * varphi2_s)
    beta_cubic = blade_integral(phi_s**3 / 6)
    br = eq104_bracket(beta_cubic).subs({sp.Symbol("I_1"): I1, sp.Symbol("I_2"): I2, eps_lambda: 0})
    return sp.expand(br.subs({eps2: g2 / g, eps3: e3}))        # ε1 stays: (109) writes it


def principal(expr: sp.Expr) -> sp.Expr:
    """The principal oscillation (n°29): Y = Kθ, Y' = Kθ', Y'' = Kθ'', θ'' = −n²θ, ε1 from (106) with
    α'' of (107), moments in F_n, n²/g = −K/z' (34)."""
    g1 = eq106()[0]
    alpha_dd = sp.solve(sp.Eq(-2 * alpha_ddot, eq107()), alpha_ddot)[0]
    e = expr.subs(eps1, g1 / g).subs(alpha_ddot, alpha_dd)
    e = e.subs({Y_ddot: K * theta_ddot, Y_dot: K * theta_dot}).subs(Y, K * theta)
    e = e.subs(theta_ddot, -n_squared * theta)
    e = in_F(e)
    return sp.expand(e.subs(n_squared, -K * g / zp))


@functools.lru_cache(maxsize=1)
def f_principal() -> sp.Expr:
    """f = −(n²/K)·(109) in the principal oscillation: a polynomial A n²θ³ + B θθ'² (n°29)."""
    return sp.expand(-n_squared / K * principal(eq109_bracket()))


def eq114_relative() -> sp.Expr:
    """(114) as ΔT/T for θ'' + n²θ = Φ(θ, θ'): the first harmonic of Φ along θ = θ0 cos φ, θ' = −nθ0 sin φ,
    ΔT/T = (1/(2πn²θ0)) ∫_0^{2π} Φ cos φ dφ (Lindstedt: ω² = n² − (1/(πθ0))∫Φ cos φ dφ)."""
    ph, om2, Phi = sp.symbols("phi omega2 Phi")
    # θ = θ0 cos φ, φ = ωt, θ'' = −ω²θ: −ω²θ + n²θ = Φ → the cos φ component: (n² − ω²)πθ0 = ∫Φ cos φ
    c = sp.Symbol("C")                          # ∫Φ cos φ dφ
    omega2 = sp.solve(sp.Eq((n_squared - om2) * sp.pi * theta0, c), om2)[0]
    rel = sp.series(sp.sqrt(n_squared / omega2) - 1, c, 0, 2).removeO()   # T/T0 − 1 = n/ω − 1
    return sp.expand(rel)


@functools.lru_cache(maxsize=1)
def delta_T_over_T() -> sp.Expr:
    """(111) before Q, Q': ΔT/T of the principal oscillation from f (n°29) by (114), the perturbation of θ''
    being f/(z − z') (y = (z − z')θ)."""
    ph = sp.Symbol("phi")
    n = sp.sqrt(n_squared)
    Phi = f_principal() / (z - zp)
    along = Phi.subs({theta: theta0 * sp.cos(ph), theta_dot: -n * theta0 * sp.sin(ph)}, simultaneous=True)
    C = sp.integrate(sp.expand(along * sp.cos(ph)), (ph, 0, 2 * sp.pi))
    return sp.simplify(eq114_relative().subs(sp.Symbol("C"), C).subs(n_squared, -K * g / zp))


def eq111() -> sp.Expr:
    """(111): ΔT/T written over Q = K(z − z') (45): the derived value."""
    return sp.factor(delta_T_over_T())


def eq112() -> sp.Expr:
    """(112): Q' defined by ΔT/T = (Q'/Q)θ0²/16 (111), Q = K(z − z') (45)."""
    return sp.expand(sp.simplify(delta_T_over_T() * 16 * K * (z - zp) / theta0**2))


def A_and_B() -> tuple[sp.Expr, sp.Expr]:
    """(A, B) of f = An²θ³ + Bθθ'² (n°29)."""
    f = f_principal()
    poly = sp.Poly(f, theta, theta_dot)
    return sp.expand(poly.coeff_monomial(theta**3) / n_squared), sp.expand(poly.coeff_monomial(theta * theta_dot**2))


def F_110_derived() -> sp.Expr:
    """(110): H(K, 1) with H = 4YH3 − H4 (108), in the F_n."""
    Hk = 4 * K * H_moments(3, K, 1) - H_moments(4, K, 1)
    return in_F(Hk)


# Euler identities (n°29)
def euler_H2() -> sp.Expr:
    """(K∂/∂Y + ∂/∂θ)H2 at Y = Kθ, in F_n: 2θF2."""
    return in_F(euler_operator(H_moments(2)).subs(Y, K * theta))


def euler_H() -> sp.Expr:
    """(K∂/∂Y + ∂/∂θ)(4YH3 − H4) at Y = Kθ, in F_n: 4θ³F."""
    return in_F(euler_operator(4 * Y * H_moments(3) - H_moments(4)).subs(Y, K * theta))


def identity_108() -> sp.Expr:
    """n°29: (K/6)H3 + ∫ε'(Kφ1 + φ2) − (1/24)(K∂/∂Y + ∂/∂θ)(4YH3 − H4), in moments: 0."""
    return sp.expand(H_def_108() - euler_operator(4 * Y * H_moments(3) - H_moments(4)) / 24)
