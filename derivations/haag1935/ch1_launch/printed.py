"""Haag 1935, chapter I, n°16–20: the formulas (64)–(76) as printed, with their OCR readings.

The text writes v_0, v'_0 for the velocities of the foci F, F' after the blow (not the end
value v0 of n°2): here ``v_F``, ``v_F'``.
"""
from __future__ import annotations

import sympy as sp

from pendsym.result import Reading
from ..symbols import (K, K_prime, M_of_s, Q_B, R, V, a, a1, b, beta1, beta_dot0, h_restitution, m, m_striking, mg,
                       n_parasitic, n_principal, s, theta, theta_dot0, v, v_F, v_Fp, varphi1, varphi2, vl, w, z, zp)

READ_FOCUS_VELOCITY = Reading("ν_0, v_0, v'_0 (velocity of F, F')", "v_F, v_F': the velocities of the foci after the "
                              "blow, not the end value v_0 of n°2")
READ_69 = Reading("ν_1", "v_λ (the OCR's subscript 1 for λ); with v_λ the formula follows from (68), (35), (36)",
                  certain=False)
READ_73 = (Reading("\\sqrt{\\beta_1} (a - a_1)", "√(β1(a − a1)): the OCR closes the radical after β1; read so, the "
                   "ratio is dimensionless (as printed it has the dimension length^(−1/2)) and equals the derivation",
                   certain=False),
           Reading("BF", "BF = a + z − b (AF = a + z)"))
READ_75 = Reading("(a − b)² + R²(1 + h m/m′) in the denominator",
                  "as printed; the derivation and (74) have R²(1 + m/m′): an h misplaced from the numerator's h m/m′, "
                  "by the OCR or in the memoir", certain=False)


# the lengths of the figure of n°18–20 (AB = b, AG = a, AF = a + z, AF' = a + z')
def F_prime_B():
    return b - a - zp


def F_B():
    return b - a - z


def blow_denominator():
    """(a − b)² + R²(1 + m/m'), the denominator of (74) and (76)."""
    return (a - b) ** 2 + R**2 * (1 + m / m_striking)


# ---------------------------------------------------------------- n°16
def eq64():
    """Printed as β + (a + z')θ = 0, solved for β."""
    return -(a + zp) * theta


def eq65():
    return K * theta


def eq66_phi():
    return theta * (K * varphi1(s) + varphi2(s))


def eq66_dphi():
    return theta * (K * v(s) + w(s)) / M_of_s(s)


def eq66_parasitic():
    return K_prime * theta


# ---------------------------------------------------------------- n°18
def eq67_theta0():
    return Q_B / mg * (b - vl) / (a - a1)


def eq67_beta0():
    return Q_B / mg * (beta1 - vl * (b - vl) / (a - a1))


def eq68_A():
    return Q_B / (K * mg) * F_prime_B()


def eq68_Ap():
    return Q_B / (K_prime * mg) * F_B()


def eq69():
    return -(F_prime_B() / F_B()) * (a + z - vl) ** 2 / (beta1 * (a - a1))


# ---------------------------------------------------------------- n°19–20
def eq70():
    """Printed as an equation = 0."""
    return (beta_dot0 + a * theta_dot0) * (a - b) + R**2 * theta_dot0


def eq71():
    return theta_dot0 * z * (a + zp - b) / (a - b)


def eq72_A():
    return v_F / n_principal


def eq72_Ap():
    return v_Fp / n_parasitic


def eq73():
    return (a + z - vl) * R * (a + zp - b) / (zp * sp.sqrt(beta1 * (a - a1)) * (a + z - b))


def eq74():
    return (1 + h_restitution) * V * (b - a) / blow_denominator()


def eq75():
    return V * ((a - b) ** 2 + R**2 * (1 - h_restitution * m / m_striking)) / (
        (a - b) ** 2 + R**2 * (1 + h_restitution * m / m_striking))


def eq76():
    return (1 + h_restitution) * V * z * F_prime_B() / blow_denominator()
