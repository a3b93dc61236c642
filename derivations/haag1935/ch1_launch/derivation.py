"""Haag 1935, chapter I, n°16–20, eqs. (64)–(76): the principal oscillation and the launching.

Pure SymPy, from the chapter's relations as derived in :mod:`..ch1_model` ((23),
(24), (27), (31), (35), (36)) and from the mechanics the text states: the
principal and parasitic oscillations (n°16), the statics of n°18, the impulses of
n°19–20 (solved by SymPy), the amplitudes of y'' = −n²y (dsolve).  A step that
uses other Results takes them as ``deps`` (by id).
"""
from __future__ import annotations

import functools

import sympy as sp

from .. import ch1_model
from ..ch1_model import K_of_z, K_of_zp, Y_of_end, vieta          # (36), (35), (23), (31)–(32)
from ..common import rid
from ..symbols import (K, K_prime, M_of_s, N, Q_B, R, V, V_after, X, Y, a, a1, a_minus_a1, b, beta, beta1,
                       beta1_positive, beta_dot0, g, h_restitution, m, m_striking, mg, n_parasitic, n_principal, s,
                       theta, theta_dot0, v, v_F, v_Fp, varphi1, varphi2, vl, w, wl, z, zp)

time = sp.Symbol("t", nonnegative=True)          # time after the blow (n°19)


# ================================================================ the foci (n°7–8) seen from K


@functools.lru_cache(maxsize=None)
def zp_of_K() -> sp.Expr:
    """z' from (35) K = −(a + z' − vλ)/β1 (K as derived by ch1_model.K_of_zp)."""
    return sp.solve(sp.Eq(K, K_of_zp()), zp)[0]


@functools.lru_cache(maxsize=None)
def z_of_K() -> sp.Expr:
    """z from (36) K = (a + wλ)/(a + z − vλ)."""
    return sp.solve(sp.Eq(K, K_of_z()), z)[0]


def swap(expr: sp.Expr) -> sp.Expr:
    """Exchange the foci: z ↔ z', K → K' (n°16: the parasitic vibration)."""
    return expr.subs({z: zp, zp: z, K: K_prime}, simultaneous=True)


def focus_ordinate(zz) -> sp.Expr:
    """y = β + (a + z)θ (27) at the focus z."""
    return beta + (a + zz) * theta


# ================================================================ n°16: (64)–(66)
def beta_principal_64(deps):
    """F' fixed: y = 0 in (27) with z → z': solve for β (64)."""
    return sp.solve(sp.Eq(focus_ordinate(zp), 0), beta)[0]


def Y_principal_65(deps):
    """Y of (23) with β of (64), z' eliminated by (35): (65)."""
    Yv = Y_of_end().subs(beta, deps[rid(64, "beta")].derived)
    return sp.factor(sp.simplify(Yv.subs(zp, zp_of_K())))


def Y_parasitic_66(deps):
    """The parasitic vibration (F fixed): β = −(a + z)θ in (23), z eliminated by (35) with z, z' swapped."""
    beta_par = sp.solve(sp.Eq(focus_ordinate(z), 0), beta)[0]
    Yv = Y_of_end().subs(beta, beta_par)
    return sp.factor(sp.simplify(Yv.subs(z, swap(zp_of_K()))))


def phi_principal_66(deps):
    """φ = Yφ1 + θφ2 (13) with Y = Kθ (65)."""
    return sp.factor(Y * varphi1(s) + theta * varphi2(s)).subs(Y, deps[rid(65, "Y")].derived).factor()


def dphi_principal_66(deps):
    """φ' = (Yv + θw)/M (14) with Y = Kθ (65)."""
    return sp.factor((Y * v(s) + theta * w(s)) / M_of_s(s)).subs(Y, deps[rid(65, "Y")].derived).factor()


# ================================================================ n°18: (67)–(69)
def static_equations():
    """Projection on Oy and moment about B (AB = b) of the forces on the pendulum, linearised, /mg (n°18).

    Weight mg at G (AG = a) along Ox, couple −mgN, force (−mgX, −mgY) at A, Q ⊥ rod at B.
    """
    u = sp.Matrix([sp.cos(theta), sp.sin(theta)])
    perp = sp.Matrix([-sp.sin(theta), sp.cos(theta)])
    forces = [((a - b) * u, sp.Matrix([1, 0])), (-b * u, sp.Matrix([-X, -Y])), (sp.zeros(2, 1), Q_B / mg * perp)]
    proj = sum((f[1] for _, f in forces), sp.S.Zero)
    moment = sum((rv[0] * f[1] - rv[1] * f[0] for rv, f in forces), sp.S.Zero) - N
    return ch1_model.linearized(proj, (Q_B,)), ch1_model.linearized(moment, (Q_B,))


@functools.lru_cache(maxsize=None)
def static_solution() -> dict:
    """(β0, θ0) from the two equations of n°18 with Y by (23), N by (24), wλ = −a1 (41)."""
    e1, e2 = static_equations()
    loads = {Y: Y_of_end(), N: ch1_model.N_of_end()}
    sol = sp.solve([e1.subs(loads), e2.subs(loads)], [beta, theta], dict=True)[0]
    return {k: sp.factor(v_.subs(wl, -a1)) for k, v_ in sol.items()}


def theta0_67(deps):
    return static_solution()[theta]


def beta0_67(deps):
    return sp.collect(sp.expand(static_solution()[beta]), Q_B / mg, sp.factor)


def A_static_68(deps):
    """A = y(0) of (27) at F with (67); z by (36), then β1 by (35): (68)."""
    y0 = focus_ordinate(z).subs({beta: deps[rid(67, "beta0")].derived, theta: deps[rid(67, "theta0")].derived})
    y0 = sp.cancel(y0.subs(a1, -wl).subs(z, z_of_K()))
    b1 = sp.solve(sp.Eq(K, K_of_zp()), beta1)[0]
    return sp.factor(y0.subs(beta1, b1))


def Ap_static_68(deps):
    """A' = y(0) of (27) at F' with (67); z' by (36) and β1 by (35), foci exchanged."""
    y0 = focus_ordinate(zp).subs({beta: deps[rid(67, "beta0")].derived, theta: deps[rid(67, "theta0")].derived})
    y0 = sp.cancel(y0.subs(a1, -wl).subs(zp, swap(z_of_K())))
    b1 = sp.solve(sp.Eq(K_prime, swap(K_of_zp())), beta1)[0]
    return sp.factor(y0.subs(beta1, b1))


def ratio_static_69(deps):
    """A/A' from (68) and its analogue, K by (36), K' by (35) with the foci exchanged, wλ = −a1 (41)."""
    ratio = deps[rid(68, "A")].derived / deps[rid(68, "Ap")].derived
    ratio = ratio.subs({K: K_of_z(), K_prime: swap(K_of_zp())}).subs(wl, -a1)
    return sp.factor(ratio)


# ================================================================ n°19–20: (70)–(76)
def angular_momentum_B() -> sp.Expr:
    """Angular momentum /m about B (AB = b) of the rigid pendulum at θ = 0: (r_G − r_B) × v_G + R²θ'."""
    u = sp.Matrix([sp.cos(theta), sp.sin(theta)])
    rGB = (a - b) * u
    vG = sp.Matrix([0, beta_dot0]) + a * theta_dot0 * sp.Matrix([-sp.sin(theta), sp.cos(theta)])
    return sp.expand((rGB[0] * vG[1] - rGB[1] * vG[0] + R**2 * theta_dot0).subs(theta, 0))


def momentum_70(deps):
    """(70): the angular momentum about B is zero after the blow (zero before, impulse through B)."""
    return sp.factor_terms(angular_momentum_B())


def R2_by_foci() -> sp.Expr:
    """R² = −zz' from (31)."""
    prod, _ = vieta()
    R2 = sp.Symbol("R2")
    return sp.solve(sp.Eq(z * zp, prod.subs(R**2, R2)), R2)[0]


def z_by_zp() -> sp.Expr:
    """z = −R²/z' from (31)."""
    prod, _ = vieta()
    return sp.solve(sp.Eq(z * zp, prod), z)[0]


def vF_71(deps):
    """Velocity of F: d/dt of (27) at t = 0, β'0 from (70), R² = −zz' (31): (71)."""
    bsol = sp.solve(deps[rid(70, "momentum")].derived, beta_dot0)[0]
    vel = (beta_dot0 + (a + z) * theta_dot0).subs(beta_dot0, bsol)
    return sp.factor(vel.subs(R**2, R2_by_foci()))


def amplitude_of(v_init, freq) -> sp.Expr:
    """Amplitude of y'' = −n²y, y(0) = 0, y'(0) = v_init (dsolve): the coefficient of sin(nt)."""
    yf = sp.Function("y")
    sol = sp.dsolve(yf(time).diff(time, 2) + freq**2 * yf(time), yf(time),
                    ics={yf(0): 0, yf(time).diff(time).subs(time, 0): v_init})
    return sp.simplify(sol.rhs.coeff(sp.sin(freq * time)))


def A_blow_72(deps):
    return amplitude_of(v_F, n_principal)


def Ap_blow_72(deps):
    return amplitude_of(v_Fp, n_parasitic)


def bare_z(expr: sp.Expr) -> sp.Expr:
    """Replace the bare factor z of a product (numerator or denominator) by −R²/z' (31)."""
    num, den = sp.fraction(sp.factor(expr))
    swap_f = lambda part: sp.Mul(*[z_by_zp() ** f.exp if (f.is_Pow and f.base == z) else
                                   (z_by_zp() if f == z else f) for f in sp.Mul.make_args(part)])
    return swap_f(num) / swap_f(den)


def ratio_blow_73(deps):
    """A/A' = (v_F/v_F')(n'/n) by (72); v_F by (71) and its analogue (foci exchanged); n² = −Kg/z' (34),
    n'² = −K'g/z; the bare factors z of the ratios replaced by −R²/z' (31); K by (36), K' by (35)
    with the foci exchanged, wλ = −a1 (41); the square root taken with z' < 0, a + z − vλ > 0 (39),
    β1 > 0 (17), a − a1 > 0 (40)."""
    v1 = deps[rid(71, "vF")].derived
    vr = bare_z(sp.cancel(v1 / swap(v1)))
    n2 = -K * g / zp                                   # (34)
    fr = bare_z(sp.cancel(swap(n2) / n2))              # n'²/n²
    fr = sp.factor(fr.subs({K: K_of_z(), K_prime: swap(K_of_zp())}).subs(wl, -a1))
    p39, zeta = sp.Symbol("p39", positive=True), sp.Symbol("zeta", positive=True)
    fr = fr.subs(beta1, beta1_positive).subs(a1, a - a_minus_a1).subs(zp, -zeta).subs(z, p39 - a + vl)
    root = sp.sqrt(sp.factor(fr)).subs({zeta: -zp, p39: a + z - vl, a_minus_a1: a - a1, beta1_positive: beta1})
    ratio = deps[rid(72, "A")].derived / deps[rid(72, "Ap")].derived
    return sp.factor(ratio.subs({v_F: 1, v_Fp: 1, n_principal: 1, n_parasitic: 1}) * vr * root)


def impulse_equations():
    """The restitution law, the momentum of the system pendulum + m' (printed before (74)), and (70)."""
    restitution = -V_after + beta_dot0 + b * theta_dot0 - h_restitution * V
    momentum = m * (beta_dot0 + a * theta_dot0) + m_striking * V_after - m_striking * V
    return restitution, momentum


@functools.lru_cache(maxsize=None)
def impulse_solution(momentum: sp.Expr) -> dict:
    """sp.solve of the two equations printed before (74) and (70) for β'0, θ'0, V'."""
    e1, e2 = impulse_equations()
    return sp.solve([e1, e2, momentum], [beta_dot0, theta_dot0, V_after], dict=True)[0]


def theta_dot0_74(deps):
    return sp.factor(impulse_solution(deps[rid(70, "momentum")].derived)[theta_dot0])


def V_after_75(deps):
    return sp.factor(impulse_solution(deps[rid(70, "momentum")].derived)[V_after])


def vF_mass_76(deps):
    """(71) with θ'0 of (74): (76)."""
    return sp.factor(deps[rid(71, "vF")].derived.subs(theta_dot0, deps[rid(74, "theta0")].derived))
