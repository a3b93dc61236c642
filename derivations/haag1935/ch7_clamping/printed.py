"""Haag 1935, chapter VII, n°94–95 (seed 001, lines ~2387–2433) and chapter VIII, n°103 (lines ~2671–2711): the
clamping errors as printed, with their OCR readings.  U, U1, U2 are th(u/2), 1/sh u, 1/th u (160), applied with
:data:`..symbols.DEFS`; F(n) is F_n at K = 0 (K → 0 with ε, (260))."""
from __future__ import annotations

import sympy as sp

from pendsym.result import Reading
from ..ch2_common import h_132, i_clamp as i, i_prime as ip, j_eq as j
from ..symbols import G, G_2, U, U1, U2, Fn, a, lam, u, w0, wl
from ..ch7_gravity.symbols import C_s, eps
from .derivation import A_p

A0, A1, A2 = A_p[:3]

READ_F1 = Reading("Q1 = j²(a + F_1)/4 (n°95)",
                  "F_4 (at K = 0): the second form −(j²/4)CG2, 'd'après (284)', needs a + F_4 = −(wλ − F_4) = −CG2 "
                  "(a ≈ a1 = −wλ); F_1 gives another number (the OCR, or the memoir's misprint)", certain=False)
READ_PI = Reading("(∂²Π/∂θ²)_{Y=−i, θ=j} before (287)",
                  "H = 4YH_3 − H_4 of (108): the letter read Π is H (h' of (132) at K = 0)", certain=False)
READ_ALPHA_LAMBDA = Reading("−αλ(i + i' + j)² in (288)",
                            "−w_λ(i + i' + j)²: the OCR renders ω_λ as αλ (4Q1 = a(i + i' + j)² + … just before, with "
                            "a ≈ a1 = −wλ (41))")
READ_318_IJ = Reading("− 3 tang(u/2)/(u sin³u), the last term of the ij bracket of (318)",
                      "as printed; (289)'s −3UU1³ (no 1/u) with u → iu gives −3 tang(u/2)/sin³u, as in the i² bracket: a "
                      "stray u (the OCR or the memoir)", certain=False)
READ_EPS_318 = Reading("1/(4ε) in (318)", "ε of (312), a1 − a = ελ > 0: (289) with u → iu and ε → −ε")


# ---------------------------------------------------------------- n°94–95
def Q1_286():
    """Q1 = j²(a + F_4)/4 (printed F_1, :data:`READ_F1`)."""
    return j**2 * (a + Fn(4)) / 4


def Q1_286_C():
    return -j**2 / 4 * C_s * G_2


def dT_286():
    return -j**2 / 4 * G * C_s


def hp_287():
    return 12 * A0 * j**2 - 6 * A1 * i * j + 2 * A2 * i**2


def Q1_288():
    """4Q1."""
    return a * (i + ip + j) ** 2 + i**2 * Fn(2) - h_132 / 12


def dT_288():
    return (-wl * (i + ip + j) ** 2 + i**2 * Fn(2) - A0 * j**2 + A1 * i * j / 2 - A2 * i**2 / 6) / (4 * eps * lam)


def dT_289():
    return 1 / (4 * eps) * (-U2 / u * (i + ip + j) ** 2
                            + i**2 / 4 * ((U1 + U2 - 3 * U * U1**2) / u + U1**2 - 3 * U * U1**3)
                            + i * j / 4 * ((2 * U2 + U1 - 3 * U * U1**2) / u - 3 * U * U1**3)
                            + j**2 / 8 * ((2 * U2 - 3 * U2 * U1**2) / u + 3 * U1**4))


def i_290():
    return eps * lam / w0 * j


# ---------------------------------------------------------------- n°103
def dT_318():
    s, c, t = sp.sin(u), sp.cos(u), sp.tan(u / 2)
    return 1 / (4 * eps) * (-sp.cot(u) / u * (i + ip + j) ** 2
                            + i**2 / 4 * (sp.cot(u / 2) / u - 3 * t / (u * s**2) + 1 / s**2 - 3 * t / s**3)
                            + i * j / 4 * ((1 + 2 * c) / (u * s) - 3 * t / (u * s**2) - 3 * t / (u * s**3))
                            + j**2 / 8 * (c * (2 * s**2 + 3) / (u * s**3) - 3 / s**4))
