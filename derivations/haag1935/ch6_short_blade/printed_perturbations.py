"""Haag 1935, chapter VI, n°74 and n°79: the formulas as printed (seed 001, lines ~1989–2095), with their
readings.  U, U1, U2 are th(u/2), 1/sh u, 1/th u (160), applied with :data:`..symbols.DEFS`."""
from __future__ import annotations

import sympy as sp

from pendsym.result import Reading

from ..ch3_uniform.launch_symbols import V, m, m_striking, n_parasitic, restitution, stress_scale
from ..symbols import DEFS, U, U1, U2, R, a, b, beta1, beta1_positive, g, lam, u, v0, w0, z
from .derivation_perturbations import F_HAAG, THETA, theta_0
from .expansion import F_2

READ_BF = Reading("U a·BF, UR·BF (234), no bar", "BF = a + z − b, the distance from the point struck B (AB = b) "
                  "to the focus F (GF = z), positive when B lies between A and F")
READ_NU_OMEGA = Reading("ν_0, ω_0 (242)", "v_0, w_0: the OCR renders v, w as ν, ω")


def fatigue_233():
    return stress_scale * (1 + restitution) * V / ((a - b) ** 2 + R**2 * (1 + m / m_striking)) * THETA


def theta_234():
    return U * a * (a + z - b) / (beta1 * n_parasitic)


def theta_234_g():
    return U * R * (a + z - b) / sp.sqrt(beta1_positive * g)


# the defs are applied simultaneously: Θ's own U is written th(u/2) here
THETA_DEFINITION = ((THETA, theta_234().subs(dict(DEFS))),)


# ---------------------------------------------------------------- n°79: (242)–(245)
def ratio_242():
    return 1 + (-5 * lam + 5 * v0 - w0 + 8 * F_2 - F_HAAG) / a


def F_243():
    return (-42 * U + 22 * U1 + 3 * U2 * U1**2) / (8 * u) + 3 * (1 - U1**2 - U1**4 / 8)


def dT_244():
    return theta_0**2 / 16 + theta_0**2 / 16 * lam / a * (-7 * U / (4 * u) + U1 / (4 * u) - U1**2
                                                           - 3 * U2 * U1**2 / (8 * u) + sp.Rational(3, 8) * U1**4)


def dT_245():
    return theta_0**2 / 16 * (1 - 7 * lam / (4 * a * u))


# ---------------------------------------------------------------- n°78: (241)
def f_241():
    from ..ch2_common import eps1, eps2, eps3
    from ..symbols import n_squared, theta
    return n_squared * (a * eps2 - a * eps1 * theta + eps3)
