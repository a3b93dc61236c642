"""Haag 1935, chapter IV, n°58–63: the thread, derived step by step (pure SymPy).

n°58 takes the limits u → ∞ of chapter III's derived forms (the dependencies, by id);
n°59–63 start from the Cartesian positions of the thread's end A and of G, as the memoir
does in (186)–(187), and follow its reductions.  Each ``derive`` takes the built
dependencies by id; none reads a printed form.
"""
from __future__ import annotations

import sympy as sp

from .. import ch1_model
from ..common import rid
from ..symbols import K, Gam, R, a, beta1, g, lam, m, mb, n, theta, theta_ddot, theta_dot, u, v0, vl, wl, z, zp
from .symbols import psi, psi_ddot, psi_dot, theta0, time

U_HALF = sp.Symbol("T_h", positive=True)       # th(u/2) while the limit is taken


def derived_of(deps, eq: int, name: str) -> sp.Expr:
    return deps[rid(eq, name)].derived


def at_infinity(expr: sp.Expr) -> sp.Expr:
    """lim u → ∞ of a derived form of chapter III."""
    return sp.simplify(sp.limit(sp.sympify(expr).rewrite(sp.exp), u, sp.oo))


# ================================================================ n°58: the limits
def ends_limits(deps) -> sp.Tuple:
    """n°58: lim of v0, vλ, w0, wλ, β1, β2 of (159) and U, U1, U2 of (160)."""
    names = [(159, "v0"), (159, "vl"), (159, "w0"), (159, "wl"), (159, "beta1"), (159, "beta2"),
             (160, "U"), (160, "U1"), (160, "U2")]
    return sp.Tuple(*(at_infinity(derived_of(deps, eq, name)) for eq, name in names))


def F_limits(deps) -> sp.Tuple:
    """n°58: lim of F_1/λ (168), F_2/λ (169) and F/λ = (4KF_3 − F_4)/λ (170)."""
    return sp.Tuple(*(at_infinity(derived_of(deps, eq, name)) for eq, name in
                      ((168, "F1"), (169, "F2"), (170, "F"))))


def G_asymptotic(deps) -> sp.Expr:
    """(184): from the recurrence (164), n Γ_n = A Γ_{n−2} + B with A → 0 (a factor 1 − th²(u/2)) and
    Γ_{n−2} = O(1/u) (166): n u Γ_n → lim u B; then G_n = λ(u/λ)^{n−2} Γ_n (163)."""
    recurrence = derived_of(deps, 164, "recurrence").subs(sp.tanh(u / 2), U_HALF)
    A = recurrence.coeff(Gam(n - 2))
    B = sp.expand(recurrence - A * Gam(n - 2))
    if sp.simplify(A.subs(U_HALF, 1)) != 0:
        raise ValueError("the coefficient of Γ_{n−2} does not vanish as u → ∞")
    u_times_B = sp.simplify(sp.expand(u * B))
    if u in u_times_B.free_symbols:
        raise ValueError("u B depends on u other than through th(u/2)")
    n_u_Gamma = sp.simplify(u_times_B.subs(U_HALF, 1))
    n_u_Gamma = sp.powsimp(sp.expand_power_base(sp.expand(n_u_Gamma), force=True), force=True)
    return sp.powsimp(lam * (u / lam) ** (n - 2) / u, force=True) * n_u_Gamma / n


def I_J_limits(deps) -> sp.Tuple:
    """(185): lim of I_λ (182) and J (183)."""
    return sp.Tuple(at_infinity(derived_of(deps, 182, "I")), at_infinity(derived_of(deps, 183, "J")))


SIGMA = sp.Symbol("sigma", positive=True)       # s = σλ, 0 < σ < 1
P_SMALL, Q_SMALL, W_SMALL = sp.symbols("p q w_u", positive=True)   # e^{−σu}, e^{−(1−σ)u}, 1/u


def inner_limit(expr: sp.Expr) -> sp.Expr:
    """lim u → ∞ at s = σλ, 0 < σ < 1: every e^{(c0 + c1σ)u} is written (pq)^{−c0}p^{−c1} with
    p = e^{−σu}, q = e^{−(1−σ)u} (pq = e^{−u}), u = 1/w; the rational function of p, q, w is then
    taken at p = q = w = 0, which all tend to zero."""
    s_symbol = next(x for x in expr.free_symbols if x.name == "s")
    expr = sp.expand(sp.sympify(expr).rewrite(sp.exp).subs(s_symbol, SIGMA * lam))

    def power(arg):
        arg = sp.expand(arg)
        c = sp.Poly(arg, u).all_coeffs()
        if len(c) != 2 or c[1] != 0:
            raise ValueError(f"exponent {arg} is not linear in u")
        slope = sp.Poly(c[0], SIGMA)
        c1 = slope.coeff_monomial(SIGMA)
        c0 = slope.coeff_monomial(1)
        return (P_SMALL * Q_SMALL) ** (-c0) * P_SMALL ** (-c1)
    rational = sp.cancel(sp.powsimp(expr.replace(sp.exp, power), force=True).subs(u, 1 / W_SMALL))
    numerator, denominator = sp.fraction(rational)
    at_zero = {P_SMALL: 0, Q_SMALL: 0, W_SMALL: 0}
    if denominator.subs(at_zero) == 0:
        raise ValueError("the limit is not read off at p = q = w = 0")
    return sp.simplify(numerator.subs(at_zero) / denominator.subs(at_zero))


def along_limits(deps) -> sp.Tuple:
    """n°58: lim of v, w (157) and φ1, φ2 (158) at an inner point s = σλ, 0 < σ < 1."""
    return sp.Tuple(*(inner_limit(derived_of(deps, eq, name)) for eq, name in
                      ((157, "v"), (157, "w"), (158, "phi1"), (158, "phi2"))))


def shape_limit(deps) -> sp.Expr:
    """n°59: y = (λ/u)·ωy of (171) as u → ∞ at an inner point s = σλ: Yσλ = Ys, a straight line."""
    omega_y = derived_of(deps, 171, "shape")
    s_symbol = next(x for x in omega_y.free_symbols if x.name == "s")
    return inner_limit(lam / u * omega_y).subs(SIGMA, s_symbol / lam)


def footnote_limits(deps) -> sp.Tuple:
    """Footnote of (192): P_λ = (Kvλ + wλ)²/M (59) with (159), M = λ²/u² (156), and ∫P ds = G_2 (79)
    by (184) with n = 2, as u → ∞."""
    P_lambda = (K * derived_of(deps, 159, "vl") + derived_of(deps, 159, "wl")) ** 2 / (lam**2 / u**2)
    G2 = derived_of(deps, 184, "Gn").subs(n, 2)
    return sp.Tuple(sp.factor(at_infinity(P_lambda)), sp.limit(G2, u, sp.oo))


def Q_thread(deps) -> sp.Expr:
    """(197): Q = a − a1 + K²β1 (45) with a1 → 0 (n°59) and β1 → λ (n°58)."""
    return a - derived_of(deps, 41, "thread") + K**2 * derived_of(deps, 184, "ends")[4]


def end_stress_limits(deps) -> sp.Tuple:
    """n°59: T'_0/√(3ET) = YΓ_0 and T'_λ/√(3ET) = YΓ_λ of (175)–(177) as u → ∞."""
    Y = sp.Symbol("Y", real=True)
    return sp.Tuple(at_infinity(Y * derived_of(deps, 177, "Gamma0")), at_infinity(Y * derived_of(deps, 177, "Gammal")))


# ================================================================ n°59: the direct study (186)–(193)
def positions() -> tuple:
    """A = λ(sin ψ, −cos ψ), G = A + a(sin θ, −cos θ), y upward."""
    xA, yA = lam * sp.sin(psi), -lam * sp.cos(psi)
    return xA, yA, xA + a * sp.sin(theta), yA - a * sp.cos(theta)


def velocity_G() -> tuple:
    """dG/dt with θ = θ(t), ψ = ψ(t)."""
    th, ps = sp.Function("th")(time), sp.Function("ps")(time)
    _xA, _yA, xG, yG = (c.subs({theta: th, psi: ps}) for c in positions())
    back = {th.diff(time): theta_dot, ps.diff(time): psi_dot}
    return tuple(sp.diff(c, time).subs(back).subs({th: theta, ps: psi}) for c in (xG, yG))


def kinetic(_deps) -> sp.Expr:
    """(186): 2T = m|v_G|² + mR²θ'² (König), the thread massless."""
    vx, vy = velocity_G()
    return sp.factor_terms(sp.simplify(m * (vx**2 + vy**2) + m * R**2 * theta_dot**2))


def force_function(_deps) -> sp.Expr:
    """(187): U = −m g y_G (the work of the weight)."""
    return sp.expand(-m * g * positions()[3])


SMALL = sp.Symbol("epsilon_s", positive=True)


def to_order(expr: sp.Expr, order: int, variables=(theta, psi, theta_dot, psi_dot)) -> sp.Expr:
    """expr with every variable scaled by ε, expanded to ε^order (then ε = 1)."""
    scaled = expr.subs({x: SMALL * x for x in variables}, simultaneous=True)
    return sp.expand(sp.series(scaled, SMALL, 0, order + 1).removeO().subs(SMALL, 1))


def kinetic_quadratic(deps) -> sp.Expr:
    """(188): (186) to the second order."""
    return sp.factor_terms(to_order(derived_of(deps, 186, "T"), 2))


def force_quadratic(deps) -> sp.Expr:
    """(189): (187) to the second order, its constant mg(λ + a) dropped."""
    expr = to_order(derived_of(deps, 187, "U"), 2)
    return sp.factor_terms(sp.expand(expr - expr.subs({theta: 0, psi: 0})))


def lagrange(two_T: sp.Expr, U: sp.Expr, coordinate, speed, acceleration, others) -> sp.Expr:
    """d/dt ∂T/∂q' − ∂T/∂q − ∂U/∂q for T = ½·two_T (the equation = 0)."""
    q_of_t = {c: sp.Function(f"q{i}")(time) for i, (c, _s, _a) in enumerate(others)}
    sub = {}
    for c, s_, _a in others:
        sub[c] = q_of_t[c]
        sub[s_] = q_of_t[c].diff(time)
    L_T = (two_T / 2).subs(sub, simultaneous=True)
    L_U = U.subs(sub, simultaneous=True)
    qc = q_of_t[coordinate]
    expr = sp.diff(sp.diff(L_T, qc.diff(time)), time) - sp.diff(L_T, qc) - sp.diff(L_U, qc)
    back = {}
    for c, s_, acc in others:
        back[q_of_t[c].diff(time, 2)] = acc
    expr = expr.subs(back)
    back = {q_of_t[c].diff(time): s_ for c, s_, _a in others}
    expr = expr.subs(back)
    return sp.expand(expr.subs({q_of_t[c]: c for c, _s, _a in others}))


COORDINATES = ((theta, theta_dot, theta_ddot), (psi, psi_dot, psi_ddot))


def linear_equations(deps) -> sp.Tuple:
    """(190): Lagrange's equations of (188), (189), divided by m (θ) and by mλ (ψ)."""
    two_T, U = derived_of(deps, 188, "T"), derived_of(deps, 189, "U")
    e_theta = lagrange(two_T, U, theta, theta_dot, theta_ddot, COORDINATES)
    e_psi = lagrange(two_T, U, psi, psi_dot, psi_ddot, COORDINATES)
    return sp.Tuple(sp.expand(e_theta / m), sp.expand(e_psi / (m * lam)))


def combination(deps) -> sp.Expr:
    """(191): the first (190) minus a times the second."""
    first, second = derived_of(deps, 190, "motion")
    return sp.expand(first - a * second)


def foci_thread(deps) -> sp.Expr:
    """n°59: the quadratic (30) of chapter I with the limits v0, vλ, wλ → 0, β1 → λ (n°58)."""
    ends = derived_of(deps, 184, "ends")
    limits = {v0: ends[0], vl: ends[1], wl: ends[3], beta1: ends[4]}
    return sp.simplify(ch1_model.foci_quadratic().as_expr().subs(limits))


def critical_distance(deps) -> sp.Expr:
    """n°59: a1 = −wλ (41) at the limit."""
    return -derived_of(deps, 184, "ends")[3]


def K_thread(deps) -> sp.Expr:
    """(193): K of (35), −(a + z' − vλ)/β1, at the limit vλ → 0, β1 → λ."""
    ends = derived_of(deps, 184, "ends")
    return ch1_model.K_of_zp().subs({vl: ends[1], beta1: ends[4]})


def n2_thread(deps) -> sp.Expr:
    """n² = −Kg/z' (34) with K of (193) and z' the negative root of the thread's (30)."""
    return n2_of(derived_of(deps, 30, "thread"), derived_of(deps, 193, "K"))


def negative_root(quadratic: sp.Expr) -> sp.Expr:
    """The root z' < 0 of a monic z² + bz + c with c = −R² < 0: −b/2 − √(b²/4 − c)."""
    _one, b, c = sp.Poly(quadratic, z).all_coeffs()
    return -b / 2 - sp.sqrt(b**2 / 4 - c)


def positive_root(quadratic: sp.Expr) -> sp.Expr:
    _one, b, c = sp.Poly(quadratic, z).all_coeffs()
    return -b / 2 + sp.sqrt(b**2 / 4 - c)


def n2_of(quadratic: sp.Expr, K_of_zp: sp.Expr) -> sp.Expr:
    """n² = −Kg/z' (34) at the negative root of the quadratic."""
    negative = negative_root(quadratic)
    return sp.simplify(-K_of_zp.subs(zp, negative) * g / negative)


def thread_defs() -> tuple:
    """K and z of the thread in terms of a, R, λ (the (30) and (35) of chapter I with the limits of
    n°58): the definitions under which (192) is compared."""
    quadratic = ch1_model.foci_quadratic().as_expr().subs({v0: 0, vl: 0, wl: 0, beta1: lam})
    K_value = ch1_model.K_of_zp().subs({vl: 0, beta1: lam}).subs(zp, negative_root(quadratic))
    return ((K, K_value), (z, positive_root(quadratic)))


def period_differentials(deps) -> sp.Tuple:
    """(192): 2Q dT/T with T = 2π/n, n² of (34) for the thread, Q of (197):
    the coefficients of dR/R, da and dλ."""
    n2 = derived_of(deps, 192, "n2")
    log_T = -sp.log(n2) / 2
    Q = derived_of(deps, 197, "Q")
    return sp.Tuple(*(2 * Q * c for c in (R * sp.diff(log_T, R), sp.diff(log_T, a), sp.diff(log_T, lam))))


def period_differentials_of_58(deps) -> sp.Tuple:
    """n°59: (58) of chapter I at the limit u → ∞: vλ, wλ, β1 of (159), M_λ = λ²/u² (156); its integral
    ∫εP ds is bounded by max|ε|·G_2, and G_2 → 0 (footnote of (192)). Returned as 2Q times the
    coefficients of dR/R, da, dλ, Q = a + wλ + K²β1 (45) at the same limit."""
    from ..symbols import M_lambda, da, dlambda, dlog_R
    if derived_of(deps, 192, "footnote")[1] != 0:
        raise ValueError("G_2 does not vanish at the limit")
    expr = derived_of(deps, 58, "dT").replace(lambda x: isinstance(x, sp.Integral), lambda x: sp.S.Zero)
    ends = {vl: derived_of(deps, 159, "vl"), wl: derived_of(deps, 159, "wl"), beta1: derived_of(deps, 159, "beta1"),
            M_lambda: lam**2 / u**2}
    Q = a + wl + K**2 * beta1
    scaled = sp.expand(sp.simplify((2 * Q * expr).subs(ends, simultaneous=True)))
    return sp.Tuple(*(at_infinity(sp.simplify(scaled.coeff(d))) for d in (dlog_R, da, dlambda)))


def period_differentials_of_44(deps) -> sp.Tuple:
    """n°59: (44) of chapter I at the limit u → ∞.  A change dλ at fixed M changes the ends (159) by
    dv = (∂v/∂λ)_M dλ with u = λ/√M; da and dR leave them alone.  Returned as 2Q times the
    coefficients of dR/R, da, dλ, Q = a + wλ + K²β1 (45) at the limit."""
    from ..symbols import da, dlambda, dlog_R, dv0, dvl, dwl, omega
    ends = {vl: derived_of(deps, 159, "vl"), wl: derived_of(deps, 159, "wl"), beta1: derived_of(deps, 159, "beta1")}
    differentials = {}
    for symbol, name in ((dv0, "v0"), (dvl, "vl"), (dwl, "wl")):
        at_fixed_M = derived_of(deps, 159, name).subs(u, lam * omega)
        differentials[symbol] = sp.diff(at_fixed_M, lam).subs(omega, u / lam) * dlambda
    Q = a + wl + K**2 * beta1
    expr = (2 * Q * derived_of(deps, 44, "dT")).subs(differentials).subs(ends, simultaneous=True)
    scaled = sp.expand(sp.simplify(expr))
    return sp.Tuple(*(at_infinity(sp.simplify(scaled.coeff(d))) for d in (dlog_R, da, dlambda)))


def sensitivity(deps) -> sp.Expr:
    """n°59, (62): G = 2(dT/T)/(dg/g) for the thread, from its n²."""
    return sp.simplify(2 * g * sp.diff(-sp.log(derived_of(deps, 192, "n2")) / 2, g))


# ================================================================ n°60: isochronism (194)–(196)
def on_principal_mode(expr: sp.Expr) -> sp.Expr:
    """ψ = Kθ (193) in an energy of (186)–(187)."""
    return expr.subs({psi: K * theta, psi_dot: K * theta_dot})


def kinetic_quartic(deps) -> sp.Expr:
    """n°60: (186) with ψ = Kθ, to the fourth order."""
    return sp.factor_terms(sp.collect(to_order(on_principal_mode(derived_of(deps, 186, "T")), 4,
                                               (theta, theta_dot)), theta_dot**2))


def force_quartic(deps) -> sp.Expr:
    """n°60: (187) with ψ = Kθ, to the fourth order, its constant dropped."""
    expr = to_order(on_principal_mode(derived_of(deps, 187, "U")), 4, (theta, theta_dot))
    return sp.collect(sp.expand(expr - expr.subs(theta, 0)), theta)


def reduced_equation(deps) -> sp.Expr:
    """(194): Lagrange's equation of the reduced energies, over m, as θ''[…] − … − (right side)."""
    two_T, U = derived_of(deps, 194, "T4"), derived_of(deps, 194, "U4")
    eq = lagrange(two_T, U, theta, theta_dot, theta_ddot, (COORDINATES[0],))
    return sp.expand(eq / m)


def perturbing_acceleration(deps) -> sp.Expr:
    """(195): θ'' + n²θ to the fifth order, with θ'' from (194) and n² = g(a + λK²)/[R² + (a + λK)²]."""
    eq = derived_of(deps, 194, "equation")
    acc = sp.solve(eq, theta_ddot)[0]
    n2 = g * (a + lam * K**2) / (R**2 + (a + lam * K) ** 2)
    return sp.factor_terms(sp.collect(to_order(acc + n2 * theta, 3, (theta, theta_dot)), [theta, theta_dot]))


def isochronism(deps) -> sp.Expr:
    """(196): ΔT/T from (195) by the first harmonic (n°29): θ = θ0 cos τ, θ' = −nθ0 sin τ,
    n² ≈ n_0² − (1/πθ0)∫Δθ'' cos τ dτ, ΔT/T = −Δn/n; then the denominator g(a + λK²)/n² with
    n² = −Kg/z' (34)."""
    tau = sp.Symbol("tau", real=True)
    nn = sp.Symbol("n_s", positive=True)
    delta = derived_of(deps, 195, "acceleration")
    n2 = g * (a + lam * K**2) / (R**2 + (a + lam * K) ** 2)
    motion = {theta: theta0 * sp.cos(tau), theta_dot: -nn * theta0 * sp.sin(tau)}
    first = sp.integrate(sp.expand(delta.subs(motion) * sp.cos(tau)), (tau, 0, 2 * sp.pi)) / (sp.pi * theta0)
    ratio = sp.expand(first.subs(nn**2, n2) / (2 * n2))          # ΔT/T = −Δ(n²)/(2n²) with Δ(n²) = −first
    # R² + (a + λK)² = g(a + λK²)/n² = −z'(a + λK²)/K by (34)
    return sp.factor(sp.simplify(ratio.subs(R**2, -zp * (a + lam * K**2) / K - (a + lam * K) ** 2)))


# ================================================================ n°62–63: the thread's inertia and weight
def inertia_acceleration(_deps) -> sp.Expr:
    """n°62: adding m'λ²ψ'²/3 = m'λ²K²θ'²/3 to 2T: the mass m[R² + (a + λK)²] grows by that much;
    θ'' = −n²θ·(1 − δ) gives Δθ'' = n²θ δ with δ = (m'λ²K²/3)/(m[R² + (a + λK)²]), the bracket
    = −z'(a + λK²)/K by (34)."""
    extra = mb * lam**2 * K**2 / 3
    bracket = -zp * (a + lam * K**2) / K
    n2 = sp.Symbol("n^2", positive=True)
    return sp.simplify(n2 * theta * extra / (m * bracket))


def inertia_period(deps) -> sp.Expr:
    """n°62: ΔT/T = (Δθ'')/(2n²θ) for Δθ'' proportional to θ."""
    n2 = sp.Symbol("n^2", positive=True)
    return sp.simplify(derived_of(deps, 135, "thread_acceleration") / (2 * n2 * theta))


def weight_acceleration(_deps) -> sp.Expr:
    """n°63: adding −m'gλψ²/4 = −m'gλK²θ²/4 to U: the stiffness mg(a + λK²) grows by m'gλK²/2;
    Δθ'' = −n²θ·(m'gλK²/2)/(mg(a + λK²))."""
    n2 = sp.Symbol("n^2", positive=True)
    return sp.simplify(-n2 * theta * (mb * g * lam * K**2 / 2) / (m * g * (a + lam * K**2)))


def weight_period(deps) -> sp.Expr:
    """n°63: ΔT/T = (Δθ'')/(2n²θ)."""
    n2 = sp.Symbol("n^2", positive=True)
    return sp.simplify(derived_of(deps, 136, "thread_acceleration") / (2 * n2 * theta))
