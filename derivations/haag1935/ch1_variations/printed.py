"""Haag 1935, chapter I, n°10–15: the formulas (42)–(63) as printed, with their OCR readings.

dz'/z', dR/R and dg/g are log-differentials (symbols ``dz'/z'``, ``dR/R``, ``dg/g``);
(42) is printed as 2dT/T = …, transcribed here as dT/T.
"""
from __future__ import annotations

import sympy as sp

from pendsym.result import Reading
from ..symbols import (G, G_2, K, M_lambda, M_of_s, P_lambda, Q, W_over_mg, a, a1, alpha_blade, alpha_rod, beta1,
                       beta_t, da, dbeta1, dlambda, dlog_g, dlog_R, dlog_zp, dv0, dvl, dwl, epsilon_of_s, lam, s, t,
                       v, v0, vl, w, w0, wl, z, zp)

READ_43 = Reading("−da − dv_λ + K(da − dv_λ)", "transcribed as shown; the derivation gives −da − dw_λ for the first "
                  "pair, and (44), which Haag draws from (43), carries −dw_λ: OCR (ω read as v) or misprint",
                  certain=False)
READ_44 = Reading("dω_λ", "dw_λ")
READ_51 = Reading("dv0/dλ = −v0 w0/Mλ, dw0/dλ = −w0 w0/Mλ",
                  "printed as shown; (49) at s = 0 gives −vλw0/Mλ and −wλw0/Mλ: the λ subscript of the first "
                  "factor may have been lost by the OCR", certain=False)
READ_60 = Reading("β (thermo-elastic coefficient)", "β_t, not the ordinate β of A")

# test functions under which forms holding arbitrary functions of s are compared (verify.compare_forms)
INSTANCES = (((v, sp.Lambda(s, 1 + s**2 / 3)), (w, sp.Lambda(s, 2 - s)), (M_of_s, sp.Lambda(s, 1 + s / 2)),
              (epsilon_of_s, sp.Lambda(s, s + sp.Rational(1, 3)))),
             ((v, sp.Lambda(s, sp.exp(-s))), (w, sp.Lambda(s, sp.cosh(s))), (M_of_s, sp.Lambda(s, 2 + s**2)),
              (epsilon_of_s, sp.Lambda(s, 1 - s / 3))))


def P_integral():
    """∫_0^λ εP ds, P = (Kv + w)²/M (59)."""
    return sp.Integral(epsilon_of_s(s) * (K * v(s) + w(s)) ** 2 / M_of_s(s), (s, 0, lam))


def _A(upper):
    return sp.Integral(epsilon_of_s(t) * w(t) * v(t).diff(t, 2), (t, 0, upper)) / w0


def _B(upper):
    return -sp.Integral(epsilon_of_s(t) * v(t) * v(t).diff(t, 2), (t, 0, upper)) / w0


# ---------------------------------------------------------------- n°10
def eq42():
    return (-dlog_zp * (a - vl) / (K * beta1) + (da - dvl + K * dbeta1) / (K * beta1)) / 2


def eq43():
    return (dlog_zp * K * (a - vl) / (a - a1) + (-da - dvl + K * (da - dvl) + 2 * K * z * dlog_R) / (a - a1)) / 2


def eq44():
    return (2 * K * z * dlog_R + (2 * K - 1) * da + K**2 * (dlambda - dv0) + K * (K - 2) * dvl - dwl) / (2 * Q)


def eq45():
    return K * (z - zp)


# ---------------------------------------------------------------- n°11
def eq47():
    return sp.S.Zero


def eq48():
    return -vl / M_lambda


def eq49():
    return -vl / M_lambda * w(s)


def eq50():
    return -wl / M_lambda * w(s)


def eq51_dv0():
    return -v0 * w0 / M_lambda


def eq51_dw0():
    return -w0 * w0 / M_lambda


def eq52_dvl():
    return -1 - vl * wl / M_lambda


def eq52_dwl():
    return 1 - wl**2 / M_lambda


# ---------------------------------------------------------------- n°12
def eq53():
    return -epsilon_of_s(s) * M_of_s(s) * v(s).diff(s, 2)


def eq55_A():
    return _A(s)


def eq55_B():
    return _B(s)


def eq54():
    """(54) with (55) written out: x = Av + (B + A_λ − B_λ)w."""
    return _A(s) * v(s) + (_B(s) + _A(lam) - _B(lam)) * w(s)


def eq56_dv0():
    return sp.Integral(epsilon_of_s(s) / M_of_s(s) * (v(s) + w(s)) * v(s), (s, 0, lam))


def eq56_dw0():
    return sp.Integral(epsilon_of_s(s) / M_of_s(s) * (v(s) + w(s)) * w(s), (s, 0, lam))


def eq57_dvl():
    return sp.Integral(epsilon_of_s(s) / M_of_s(s) * w(s) * v(s), (s, 0, lam))


def eq57_dwl():
    return sp.Integral(epsilon_of_s(s) / M_of_s(s) * w(s) ** 2, (s, 0, lam))


# ---------------------------------------------------------------- n°13–15
def eq58():
    return (2 * K * z * dlog_R + (2 * K - 1) * (da + dlambda) + P_lambda * dlambda - P_integral()) / (2 * Q)


def eq60():
    return (2 * K * z * alpha_rod + (2 * K - 1) * (alpha_rod * a + alpha_blade * lam) + alpha_blade * lam * P_lambda
            - (beta_t + 4 * alpha_blade) * G_2) / (2 * Q)


def eq61():
    return dlog_g * G / 2


def eq62():
    return -1 + G_2 / Q


def eq63():
    return -1 + 2 * W_over_mg / Q
