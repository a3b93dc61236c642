"""Haag 1935, chapter I, n°1–4, eqs. (1)–(20): the equations of the blade and the functions v, w.

Pure SymPy, in the memoir's order: (4)–(6) from the kinematics of the centre of
gravity G of the rigid pendulum, (7) by differentiating (2) with (3), (8) by
linearising (7); (12)–(14) from the definitions (9)–(11); (15)–(16) and β1 by
the steps of :mod:`..ch1_model`; the inequalities of n°3 as the quantities the
memoir claims positive; the identities (20) of the symmetric blade (n°4).
"""
from __future__ import annotations

import sympy as sp

from .. import ch1_model
from ..ch1_model import ends
from ..ch1_model import beta1_def, wronskian_at_lambda  # noqa: F401  (17)/(22), (16): Results of this section
from ..symbols import (EI, M1, M2, M_of_s, M_s, N, R, X, Y, a, alpha, alpha_ddot, beta, beta1, beta_ddot,
                       epsilon, g, lam, m, mu, s, t, theta, theta_ddot, theta_dot, v, v0, v_s, vl, varphi, varphi1_s,
                       varphi2_s, w, w0, w_s, wl, x_of_s, y_of_s)


# ================================================================ n°1: (1)–(6)
def stiffness_ratio() -> sp.Expr:
    """(1): M = EI/(mg)."""
    return EI / (m * g)


def bending_moment() -> sp.Expr:
    """Right side of (2): N + (α − x)Y − (β − y)X, with x, y functions of s."""
    return N + (alpha - x_of_s(s)) * Y - (beta - y_of_s(s)) * X


def bending_law() -> sp.Expr:
    """(2), written as M dφ/ds − (right side) = 0."""
    return M_of_s(s) * varphi(s).diff(s) - bending_moment()


def slope_x() -> sp.Expr:
    """(3): dx/ds = cos φ."""
    return sp.cos(varphi(s))


def slope_y() -> sp.Expr:
    """(3): dy/ds = sin φ."""
    return sp.sin(varphi(s))


def G_coordinates():
    """x_G = α + a cos θ, y_G = β + a sin θ (AT passes through G, AG = a; n°1)."""
    alpha_t, beta_t, theta_t = (sp.Function(name)(t) for name in ("alpha", "beta", "theta"))
    return alpha_t, beta_t, theta_t, alpha_t + a * sp.cos(theta_t), beta_t + a * sp.sin(theta_t)


def _dot_symbols(expr, alpha_t, beta_t, theta_t):
    """α(t), β(t), θ(t) and their derivatives → the symbols α, β, θ, α'', β'', θ', θ''."""
    derivatives = {alpha_t.diff(t, 2): alpha_ddot, beta_t.diff(t, 2): beta_ddot, theta_t.diff(t, 2): theta_ddot,
                   theta_t.diff(t): theta_dot}
    return expr.subs(derivatives).subs({alpha_t: alpha, beta_t: beta, theta_t: theta})


def centre_of_gravity(axis: int) -> sp.Expr:
    """m x_G'' − (forces on Ox): (4) for axis 0, m y_G'' − (forces on Oy): (5) for axis 1.

    Forces on the pendulum: the weight mg along Ox (vertical, downwards), the reaction (−mgX, −mgY) at A.
    """
    alpha_t, beta_t, theta_t, x_G, y_G = G_coordinates()
    force = (m * g - m * g * X, -m * g * Y)[axis]
    return sp.expand(_dot_symbols(m * (x_G, y_G)[axis].diff(t, 2) - force, alpha_t, beta_t, theta_t))


def angular_momentum() -> sp.Expr:
    """(6): (R²/g)θ'' − (moment about G of −mgN and of (−mgX, −mgY) at A)/(mg)."""
    arm = (-a * sp.cos(theta), -a * sp.sin(theta))          # A − G
    force = (-m * g * X, -m * g * Y)
    moment = -m * g * N + arm[0] * force[1] - arm[1] * force[0]
    return sp.expand(R**2 / g * theta_ddot - moment / (m * g))


# ================================================================ n°2: (7)–(14)
def differentiated_bending() -> sp.Expr:
    """(7): d/ds of the right side of (2), with (3) x' = cos φ, y' = sin φ."""
    derivative = bending_moment().diff(s)
    return sp.expand(derivative.subs({x_of_s(s).diff(s): sp.cos(varphi(s)), y_of_s(s).diff(s): sp.sin(varphi(s))}))


def linearised_bending() -> sp.Expr:
    """(8): (7) to the first order, φ, Y of order ε, X = 1 + O(ε²) (n°2)."""
    rhs = differentiated_bending().subs({varphi(s): epsilon * varphi(s), Y: epsilon * Y, X: 1 + epsilon**2 * X})
    return sp.expand(sp.series(rhs, epsilon, 0, 2).removeO().coeff(epsilon))


def equation_of_v() -> sp.Expr:
    """(9): M v'' − v = 0."""
    return M_of_s(s) * v(s).diff(s, 2) - v(s)


# (10): the end slopes of v and w
BC10 = {v(s).diff(s).subs(s, 0): -1, v(s).diff(s).subs(s, lam): -1,
        w(s).diff(s).subs(s, 0): 0, w(s).diff(s).subs(s, lam): 1}


def end_slopes() -> sp.Tuple:
    """(10): (v'_0, v'_λ, w'_0, w'_λ)."""
    return sp.Tuple(*BC10.values())


def phi1_phi2() -> sp.Tuple:
    """(11): φ1 = 1 + v', φ2 = w'."""
    return sp.Tuple(1 + v(s).diff(s), w(s).diff(s))


def phi_of_s() -> sp.Expr:
    """(13): φ = Yφ1 + θφ2 with φ1 = 1 + v', φ2 = w' (11)."""
    return Y * (1 + v(s).diff(s)) + theta * w(s).diff(s)


def phi_solution() -> sp.Expr:
    """(13) with the values φ1, φ2 at a point s."""
    return Y * varphi1_s + theta * varphi2_s


def reduce9(expr: sp.Expr) -> sp.Expr:
    """Replace v'', w'' by v/M, w/M (9)."""
    return expr.subs({v(s).diff(s, 2): v(s) / M_of_s(s), w(s).diff(s, 2): w(s) / M_of_s(s)})


def phi_prime() -> sp.Expr:
    """(14): φ' from (13), (11) and (9)."""
    return sp.factor(reduce9(phi_of_s().diff(s)))


def phi_prime_at_point() -> sp.Expr:
    """(14) with the values v_s, w_s, M_s of v, w, M at a point s."""
    return phi_prime().subs({v(s): v_s, w(s): w_s, M_of_s(s): M_s})


def eq8_residual() -> sp.Expr:
    """d/ds(Mφ') − (φ − Y) for φ of (13): identically 0 by (9), (11), whatever Y and θ."""
    lhs = reduce9((M_of_s(s) * phi_prime()).diff(s))
    rhs = linearised_bending().subs(varphi(s), phi_of_s())
    return sp.simplify(lhs - rhs)


def phi_ends() -> sp.Tuple:
    """(φ_0, φ_λ) of (13) with (10)."""
    phi = phi_of_s()
    return sp.Tuple(*(phi.subs(s, end).subs(BC10) for end in (0, lam)))


def phi_end_values() -> sp.Tuple:
    """(12): (φ10, φ1λ, φ20, φ2λ) from (11) with (10)."""
    phi1, phi2 = 1 + v(s).diff(s), w(s).diff(s)
    return sp.Tuple(*(f.subs(s, end).subs(BC10) for f in (phi1, phi2) for end in (0, lam)))


# ================================================================ n°3: (15)–(19)
def wronskian() -> sp.Expr:
    """(15): v w' − w v' = w0 (constant by ch1_model.wronskian_derivative, its value at s = 0)."""
    return ch1_model.wronskian_constant()


def ratio_integral() -> sp.Expr:
    """Before (18): ∫_0^λ w0/w² ds = −[v/w]_0^λ, since d/ds(v/w) = −w0/w² by (15)."""
    wr = v(s) * w(s).diff(s) - w(s) * v(s).diff(s)         # = w0 by (15)
    if sp.expand(sp.diff(v(s) / w(s), s) * w(s) ** 2 + wr) != 0:
        raise ValueError("d/ds(v/w) is not −(vw' − wv')/w²")
    return ends(v(0) / w(0) - v(lam) / w(lam))


def unit_integral() -> sp.Expr:
    """(19): ∫ w/M ds = ∫ w'' ds = w'_λ − w'_0 = 1 by (9), (10)."""
    return (w(s).diff(s).subs(s, lam) - w(s).diff(s).subs(s, 0)).subs(BC10)


# (17): v0 > 0, w0 > 0, wλ > w0, β1 > 0, vλ < 0, β1 < λ, v0 < λ, −vλ < λ — the quantities claimed positive
def v0_positive() -> sp.Expr:
    return ends(v(0))


def w0_positive() -> sp.Expr:
    return ends(w(0))


def wl_minus_w0() -> sp.Expr:
    return ends(w(lam) - w(0))


def minus_vl() -> sp.Expr:
    return -ends(v(lam))


def lam_minus_beta1() -> sp.Expr:
    """λ − β1 with β1 = λ + vλ − v0 (17)."""
    return sp.expand(lam - ch1_model.beta1_def())


def lam_minus_v0() -> sp.Expr:
    return lam - ends(v(0))


def lam_plus_vl() -> sp.Expr:
    return lam + ends(v(lam))


# (18): from the integral before (18), w² ≤ wλ² on [0, λ] (w increases)
def step0_of_18() -> sp.Expr:
    """v0/w0 − vλ/wλ − λw0/wλ² > 0."""
    return ratio_integral() - lam * w0 / wl**2


def first_of_18() -> sp.Expr:
    """The inequality before (18) times w0wλ, with β1 of (17)."""
    return sp.expand((ratio_integral() - lam * w0 / wl**2) * w0 * wl).subs(v0, lam + vl - beta1)


def second_of_18() -> sp.Expr:
    """−λvλ(1 + w0/wλ) < −2λvλ."""
    return sp.factor(-2 * lam * vl + lam * vl * (1 + w0 / wl))


def third_of_18() -> sp.Expr:
    """−2λvλ < 2λ²."""
    return sp.factor(2 * lam**2 + 2 * lam * vl)


# (19): from ∫ w/M ds = 1 with M1 ≤ M ≤ M2 and w0 ≤ w ≤ wλ
def M1_below() -> sp.Expr:
    """M1 < λwλ."""
    return lam * wl - M1


def M2_above() -> sp.Expr:
    """M2 > λw0."""
    return M2 - lam * w0


def lower_of_19() -> sp.Expr:
    """λw0/μ < M1 (μ = M2/M1): (M2 − λw0)/μ."""
    return sp.expand((M2 - lam * w0) / mu)


def upper_of_19() -> sp.Expr:
    """M2 < λμwλ: μ(λwλ − M1)."""
    return sp.expand(mu * (lam * wl - M1))


# ================================================================ n°4: (20), the symmetric blade
def symmetric_vl() -> sp.Expr:
    """v odd in s − λ/2 (n°4): v(λ − σ) = −v(σ) at σ = 0 gives vλ = −v0."""
    sigma = sp.Symbol("sigma")
    return ends((-v(sigma)).subs(sigma, 0))


def symmetric_beta1() -> sp.Expr:
    """β1 = λ + vλ − v0 (17) with vλ = −v0."""
    return sp.expand(ch1_model.beta1_def().subs(vl, symmetric_vl()))


def symmetric_wl() -> sp.Expr:
    """(16) vλ + wλ = w0 with vλ = −v0."""
    return sp.solve(sp.Eq(ch1_model.wronskian_at_lambda().subs(vl, symmetric_vl()), w0), wl)[0]
