"""Haag 1935, chapter IV: the formulas as printed (OCR text of n°58–63), with their readings."""
from __future__ import annotations

import sympy as sp

from pendsym.result import Reading

from ..symbols import K, R, a, g, lam, m, mb, n, theta, theta_ddot, theta_dot, u, zp
from .symbols import psi, psi_ddot, psi_dot, theta0

READ_M_BRACKET = Reading("2T = m(R² + a²)θ'² + λ²ψ'² + 2aλψ'θ'",
                         "2T = m[(R² + a²)θ'² + λ²ψ'² + 2aλψ'θ'] (the bracket of (186); the OCR lost it)",
                         certain=False)
READ_ALPHA = Reading("gαθ", "gaθ: the OCR renders a as α in (190) and (191)")
READ_PHI2 = Reading("Pour s = λ, φ_1 reste constamment égal à un", "φ_2 (the sentence is about φ_2)")
READ_G_EXPONENT = Reading("(u/λ)^{n−1}", "as shown; the derivation and the blade give (u/λ)^{n−3}, and the "
                          "memoir's own next remark (G_2 → 0) needs n − 3", certain=False)
READ_K2 = Reading("−(m'/m) λ²K²/(3z'(a + λK²)) n²θ",
                  "as shown: the first form, m'λ²K²n²θ/(−3m(z'/K)(a + λK²)), carries K³; so does the model",
                  certain=False)


def ends():
    """n°58: ν0, νλ, ω0, ωλ, β2, U1 → 0; β1 → λ; U, U2 → 1 (in the order v0, vλ, w0, wλ, β1, β2, U, U1, U2)."""
    return sp.Tuple(0, 0, 0, 0, lam, 0, 1, 0, 1)


def F_limits():
    """n°58: F_n → K^n λ, for F_1/λ, F_2/λ; and F = 4KF_3 − F_4 → 3K⁴λ."""
    return sp.Tuple(K, K**2, 4 * K * K**3 - K**4)


def G_asymptotic():
    return (K**n + (1 - K) ** n) / n * (u / lam) ** (n - 1)


def I_J():
    return sp.Tuple(mb * K**2 * lam**2 / 3, K**2 * lam / 4)


def end_stresses():
    """n°59: T'_0 = √(3ET)Y, T'_λ = √(3ET)(θ − Y), over √(3ET)."""
    Y = sp.Symbol("Y", real=True)
    return sp.Tuple(Y, theta - Y)


def kinetic():
    return m * ((R**2 + a**2) * theta_dot**2 + lam**2 * psi_dot**2 + 2 * a * lam * psi_dot * theta_dot * sp.cos(theta - psi))


def force_function():
    return m * g * (lam * sp.cos(psi) + a * sp.cos(theta))


def kinetic_quadratic():
    return m * ((R**2 + a**2) * theta_dot**2 + lam**2 * psi_dot**2 + 2 * a * lam * psi_dot * theta_dot)


def force_quadratic():
    return -m * g / 2 * (lam * psi**2 + a * theta**2)


def linear_equations():
    return sp.Tuple((R**2 + a**2) * theta_ddot + a * lam * psi_ddot + g * a * theta,
                    a * theta_ddot + lam * psi_ddot + g * psi)


def combination():
    return R**2 * theta_ddot + g * a * (theta - psi)


def critical_distance():
    return sp.S.Zero


def K_thread():
    return -(a + zp) / lam


def period_differentials():
    """(192): 2Q dT/T = 2Kz dR/R + (2K − 1)da + K²dλ: the coefficients of dR/R, da, dλ."""
    z = sp.Symbol("z", real=True)
    return sp.Tuple(2 * K * z, 2 * K - 1, K**2)


def sensitivity():
    return sp.Integer(-1)


def kinetic_quartic():
    return m * (R**2 + (a + lam * K) ** 2 - a * lam * K * (1 - K) ** 2 * theta**2) * theta_dot**2


def force_quartic():
    return -m * g * theta**2 / 2 * (lam * K**2 + a) + m * g * theta**4 / 24 * (lam * K**4 + a)


def reduced_equation():
    """(194) as left side − right side."""
    return (theta_ddot * (R**2 + (a + lam * K) ** 2 - a * lam * K * (1 - K) ** 2 * theta**2)
            - a * lam * K * (1 - K) ** 2 * theta * theta_dot**2
            - (-g * (a + lam * K**2) * theta + g / 6 * (a + lam * K**4) * theta**3))


# n² of (195): the pulsation of the linear part of (194), g(a + λK²)/[R² + (a + λK)²] ((34) for the thread)
LINEAR_N2 = ((sp.Symbol("n^2", positive=True), g * (a + lam * K**2) / ((a + lam * K) ** 2 + R**2)),)


def perturbing_acceleration():
    n2 = sp.Symbol("n^2", positive=True)
    return ((a * lam * K * (1 - K) ** 2 * theta * theta_dot**2 + g / 6 * (a + lam * K**4) * theta**3
             - n2 * a * lam * K * (1 - K) ** 2 * theta**3) / ((a + lam * K) ** 2 + R**2))


def isochronism():
    return theta0**2 / 16 * (a + lam * K**4 + 4 * a * lam / zp * K**2 * (K - 1) ** 2) / (a + lam * K**2)


def inertia_acceleration():
    n2 = sp.Symbol("n^2", positive=True)
    return -(mb / m) * lam**2 * K**2 / (3 * zp * (a + lam * K**2)) * n2 * theta


def inertia_period():
    return -(mb / m) * lam**2 * K**2 / (6 * zp * (a + lam * K**2))


def weight_acceleration():
    n2 = sp.Symbol("n^2", positive=True)
    return -(mb / m) * lam * K**2 / (2 * (a + lam * K**2)) * n2 * theta


def weight_period():
    return -(mb / m) * lam * K**2 / (4 * (a + lam * K**2))


def along():
    """n°58: v, w → 0 and φ1 → 1, φ2 → 0 at s inside (0, λ)."""
    return sp.Tuple(0, 0, 1, 0)


def shape():
    Y = sp.Symbol("Y", real=True)
    return Y * sp.Symbol("s", real=True)


def footnote():
    """Footnote of (192): P_λ → (1 − K)², the integral of (58) → 0."""
    return sp.Tuple((1 - K) ** 2, 0)


def Q_thread():
    return a + lam * K**2
