"""Haag 1935, chapter VII, n°92–93 and n°97: the formulas as printed (OCR file 001, lines ~2351–2385, 2487–2489),
with their readings."""
from __future__ import annotations

import sympy as sp

from pendsym.result import Reading
from ..ch2_common import eps1, eps2, eps3, theta0
from ..ch7_gravity.symbols import C_s, eps
from ..symbols import G, G_2, Fn, epsilon_of_s, lam, n_squared, s, theta, w, w0, wl

READ_EPS_I = Reading("ε_4 (in ∫_0^λ ε_4 w'' ds of (281))",
                     "ε(s), the increment of the bending moment (mgε_i of n°26, printed ε_4 or ε_i in (104))")
READ_F1 = Reading("Q' = a − F = F_1 − w_1 and (282) F_1 = ∫_0^λ w'^4 ds",
                  "F_4 − w_λ and F_4 = ∫w'^4 ds: F of (110) is −F4 at K = 0, F4 = (79) with n = 4; w_1 is w_λ "
                  "(a = a1 = −wλ)", certain=False)
READ_OMEGA = Reading("ω_λ, ω_0, ω' in (284)", "w_λ, w_0, w' (the OCR renders Haag's w as ω, READ_VW); ω = u/λ of "
                     "(156) is not meant")
READ_SQUARE = Reading("ω'(1 − ω'^2) in the numerator of (284)'s last form",
                      "kept as printed: w'(1 − w'^3) is what the first forms give (wλ − F4 = w0 + ∫(w' − w'^4) ds); "
                      "a superscript 3 read as 2 by the OCR, or a misprint", certain=False)


def f_281():
    """(281): f/(z − z') = −(n²/(ελ))(ε2w0 − ε3 − ε1θ∫ww'' ds − ∫εw'' ds)."""
    w_dd = w(s).diff(s, 2)
    return -n_squared / (eps * lam) * (eps2 * w0 - eps3 - eps1 * theta * sp.Integral(w(s) * w_dd, (s, 0, lam))
                                       - sp.Integral(epsilon_of_s(s) * w_dd, (s, 0, lam)))


def Qp_93():
    """n°93: Q' = a − F = F4 − wλ (the last form)."""
    return Fn(4) - wl


def F4_282():
    return sp.Integral(w(s).diff(s) ** 4, (s, 0, lam))


def dT_283():
    return -theta0**2 / 16 * G * C_s


def C_284():
    return (wl - Fn(4)) / G_2


def C_284_F2():
    return (wl - Fn(4)) / (wl - Fn(2))


def C_284_integrals():
    """As printed: the numerator's integrand w'(1 − w'^2) (see READ_SQUARE)."""
    slope = w(s).diff(s)
    return (w0 + sp.Integral(slope * (1 - slope**2), (s, 0, lam))) / (w0 + sp.Integral(slope * (1 - slope), (s, 0, lam)))


def C_minus_one():
    slope = w(s).diff(s)
    return sp.Integral(slope**2 * (1 - slope**2), (s, 0, lam)) / G_2
