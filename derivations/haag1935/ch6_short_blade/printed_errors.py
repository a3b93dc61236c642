"""Haag 1935, chapter VI, n°80–81: the formulas as printed (seed 001, lines ~2096–2145), with their readings.
U, U1, U2 are th(u/2), 1/sh u, 1/th u (160), applied with :data:`..symbols.DEFS`."""
from __future__ import annotations

import sympy as sp

from pendsym.result import Reading

from ..ch2_common import h_127, h_132, i_clamp as i, i_prime, j_eq as j
from ..symbols import U, U1, U2, Fn, a, lam, m, mb, u, v0, w0, wl

READ_W_LAMBDA = Reading("ω_1 (246)", "w_λ: j + i + i' = (iw_0 + i'w_λ)/a from (117) with a1 = −w_λ (41); the OCR renders "
                        "v, w as ν, ω and the index λ as 1 (λ and 1 alike in the scan)")
READ_NU = Reading("ν_0 (248)", "v_0: the OCR renders v as ν")
READ_LAMBDA_CUBE = Reading("\"négligeant toujours λ^3 et R^2 devant a^2\" (before (248))",
                           "λ²: as everywhere in the chapter (\"toujours\"); it does not enter the formula")
READ_M_PRIME = Reading("m' (251)–(254)", "the mass of the blade (n°56: (182), (183)), not the striking mass of n°20")


def sum_246():
    return (i * w0 + i_prime * wl) / a


def sum_247():
    return lam / (a * u) * (i * U1 + i_prime * U2)


def Q1_248():
    return i**2 / 2 * (v0 - lam) - h_127 * i + i**2 / 4 * Fn(2) - h_132 / 48


def dT_249():
    return lam / (16 * a) * (
        i**2 * ((2 * U1 - 3 * U - 3 * U * U1**2) / u - 4 * U * U1 + U1**2 - 3 * U * U1**3)
        + i * j * ((U1 - 4 * U - 3 * U * U1**2) / u - 4 * U * U1 + 2 * U1**2 - 3 * U * U1**3)
        + j**2 / 2 * (-U2 * (4 + 3 * U1**2) / u + 6 * U1**2 + 3 * U1**4))


def dT_250():
    return -lam / (16 * a * u) * (3 * i**2 + 4 * i * j + 2 * j**2)


def inertia_251():
    return mb / (2 * m) * lam**2 / a**2 * (sp.Rational(1, 3) - U2 / u + 1 / u**2 + (U - 3 * U1) / (2 * u**3)
                                           + 3 * U1**2 / (2 * u**2))


def inertia_252():
    return mb / (2 * m) * lam**2 / a**2 * (sp.Rational(1, 3) - 1 / u + 1 / u**2 + 1 / (2 * u**3))


def weight_253():
    return -mb / (8 * m) * lam / a * (2 - 6 * U2 / u + 7 / u**2 - U1**2)


def weight_254():
    return -mb / (8 * m) * lam / a * (2 - 6 / u + 7 / u**2)
