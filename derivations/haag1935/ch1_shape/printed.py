"""Haag 1935, chapter I, n°21–25: the formulas (77)–(87) as printed, with their OCR readings."""
from __future__ import annotations

import sympy as sp

from pendsym.result import Reading
from ..symbols import (E, Fn, Gn, I_s, K, L, M_of_s, Y, a, alpha, beta, beta1, c_axis, e, lam, mg, n, r, s, theta, v,
                       v0, varphi1, varphi2, w, w0, wl, x_fork, zp)

READ_81 = Reading("α_λ", "w_λ (ω_λ): F2 + G2 = K²β1 + wλ by the integration by parts of n°23", certain=True)
READ_85 = Reading("F^2/2", "F_2/2 (the integral F_2 of (79)); cf. the text: 'la formule (85)'", certain=True)
READ_86 = Reading("(α + z')", "(a + z'): AG = a; the OCR confuses a and α in the definition of A", certain=True)


# ---------------------------------------------------------------- n°21–22
def eq77():
    return Y * (s + v(s) - v0) + theta * (w(s) - w0)


def eq78_M():
    return E * e / 2 * (Y * v(s) + theta * w(s)) / M_of_s(s)


def eq78_I():
    return mg * e / (2 * I_s) * (Y * v(s) + theta * w(s))


# ---------------------------------------------------------------- n°23
def eq79_F():
    return sp.Integral((K * varphi1(s) + varphi2(s)) ** n, (s, 0, lam))


def eq79_G():
    return sp.Integral((K * v(s) + w(s)) ** n / M_of_s(s) ** (n - 1), (s, 0, lam))


def eq80_Wp():
    return mg * theta**2 / 2 * (a + Fn(2))


def eq80_W():
    return mg * theta**2 / 2 * Gn(2)


def eq80_S():
    return (a + Fn(2)) / Gn(2)


def eq81():
    return K**2 * beta1 + wl


def eq82():
    return (a + wl + K**2 * beta1) / Gn(2) - 1


# ---------------------------------------------------------------- n°24–25
def eq83():
    return lam + a + zp


def eq84():
    return (r**2 + 2 * r * ((alpha - c_axis) * sp.cos(theta) + beta * sp.sin(theta))
            + (alpha - c_axis) ** 2 + beta**2 - L**2)


def eq85():
    return lam - Fn(2) / 2 * theta**2


def eq86_A():
    """A, defined by r² + 2r(λ − c) + (λ − c)² − L² = Aθ² (to the fourth order)."""
    return r * (lam - c_axis + Fn(2) + 2 * (a + zp)) - (a + zp) ** 2 + (lam - c_axis) * Fn(2)


def eq86_r():
    return L + c_axis - lam + theta**2 / (2 * L) * eq86_A().subs(r, L + c_axis - lam)


def eq87():
    """Printed as an equation = 0, with λ − c = x and r = L + c − λ."""
    return (L - x_fork) * (x_fork + Fn(2) + 2 * (a + zp)) - (a + zp) ** 2 + x_fork * Fn(2)
