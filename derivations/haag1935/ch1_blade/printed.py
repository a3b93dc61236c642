"""Haag 1935, chapter I, n°1–4: the formulas (1)–(20) as printed, with their OCR readings.

Each function returns the transcription of the text (the OCR's ν, ω read as v, w:
:data:`..common.READ_VW`).  The inequalities of n°3 are written as the quantity
the text claims positive (``v0 > 0`` is ``v0``).
"""
from __future__ import annotations

import sympy as sp

from pendsym.result import Reading
from ..symbols import (EI, M1, M2, M_of_s, M_s, N, R, X, Y, a, alpha, alpha_ddot, beta, beta1, beta_ddot, g, lam,
                       m, mu, s, theta, theta_ddot, theta_dot, v, v0, v_s, varphi, varphi1_s, varphi2_s, vl, w, w0,
                       w_s, wl, x_of_s, y_of_s)

READ_4 = Reading("mαθ'^2 cos θ − mαθ'' sin θ", "m a θ'² cos θ − m a θ'' sin θ (a = AG, not α)")
READ_5 = Reading("mαθ'^2 sin θ + mαθ'' cos θ", "m a θ'² sin θ + m a θ'' cos θ (a, not α)")

# test functions under which forms holding arbitrary functions of s are compared (verify.compare_forms)
INSTANCES = tuple(tuple((f, sp.Lambda(s, e)) for f, e in zip((varphi, x_of_s, y_of_s, M_of_s, v, w), exprs))
                  for exprs in ((sp.sin(s) / 3 + s**2, 1 + s / 2, s**3 - s, 2 + sp.cos(s), sp.exp(s / 3) - 1, s**2 + 3),
                                (s / 5 - s**3, sp.cos(s), sp.sin(2 * s), 1 + s**2, 2 - s, sp.exp(-s))))


# ---------------------------------------------------------------- n°1
def eq1():
    return EI / (m * g)


def eq2():
    return M_of_s(s) * varphi(s).diff(s) - (N + (alpha - x_of_s(s)) * Y - (beta - y_of_s(s)) * X)


def eq3_dx():
    return sp.cos(varphi(s))


def eq3_dy():
    return sp.sin(varphi(s))


def eq4():
    return m * alpha_ddot - m * a * theta_dot**2 * sp.cos(theta) - m * a * theta_ddot * sp.sin(theta) - m * g * (1 - X)


def eq5():
    return m * beta_ddot - m * a * theta_dot**2 * sp.sin(theta) + m * a * theta_ddot * sp.cos(theta) + m * g * Y


def eq6():
    return R**2 / g * theta_ddot - (-N + a * (Y * sp.cos(theta) - X * sp.sin(theta)))


# ---------------------------------------------------------------- n°2
def eq7():
    return X * sp.sin(varphi(s)) - Y * sp.cos(varphi(s))


def eq8():
    return varphi(s) - Y


def eq9():
    return M_of_s(s) * v(s).diff(s, 2) - v(s)


def eq10():
    return sp.Tuple(-1, -1, 0, 1)


def eq11():
    return sp.Tuple(1 + v(s).diff(s), w(s).diff(s))


def eq12():
    return sp.Tuple(0, 0, 0, 1)


def eq13():
    return Y * varphi1_s + theta * varphi2_s


def eq13_satisfies8():
    """'On vérifie aisément que cette fonction satisfait à l'équation (8)': the residual of (8) is 0."""
    return sp.S.Zero


def eq13_ends():
    return sp.Tuple(0, theta)


def eq14():
    return (Y * v_s + theta * w_s) / M_s


# ---------------------------------------------------------------- n°3
def eq15():
    return w0


def eq16():
    return vl + wl


def eq17_v0():
    return v0


def eq17_w0():
    return w0


def eq17_wl_gt_w0():
    return wl - w0


def eq17_beta1():
    return lam + vl - v0


def eq17_vl():
    return -vl


def eq17_beta1_lt():
    return lam - (lam + vl - v0)


def eq17_v0_lt():
    return lam - v0


def eq17_vl_gt():
    return lam + vl


def eq18_integral():
    return v0 / w0 - vl / wl


def eq18_step0():
    return v0 / w0 - vl / wl - lam * w0 / wl**2


def eq18_first():
    return -lam * vl * (1 + w0 / wl) - (beta1 * wl + vl**2)


def eq18_second():
    return -2 * lam * vl - (-lam * vl * (1 + w0 / wl))


def eq18_third():
    return 2 * lam**2 - (-2 * lam * vl)


def eq19_unit():
    return sp.S.One


def eq19_M1():
    return lam * wl - M1


def eq19_M2():
    return M2 - lam * w0


def eq19_lower():
    return M1 - lam * w0 / mu


def eq19_upper():
    return lam * mu * wl - M2


# ---------------------------------------------------------------- n°4
def eq20_vl():
    return -v0


def eq20_beta1():
    return lam - 2 * v0


def eq20_wl():
    return w0 + v0
