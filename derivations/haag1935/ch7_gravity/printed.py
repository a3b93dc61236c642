"""Haag 1935, chapter VII, n°82–91: the formulas as printed (OCR file 001, lines ~2143–2330), with readings."""
from __future__ import annotations

import sympy as sp

from pendsym.result import Reading
from ..symbols import U1 as U1s, U2 as U2s
from ..symbols import (E, G_2, M_lambda, R, T, W_over_mg, a, a1, alpha_blade, alpha_rod, beta1, beta_t, e, g, h, lam, m,
                      omega, s, theta, u, v0, vl, w0, wl, z, zp)
from .symbols import a_r, eps, eps_p, l_syn

U1, U2 = 1 / sp.sinh(u), 1 / sp.tanh(u)
READ_V1 = Reading("z + a − v_1", "z + a − v_λ: the subscript 1 is OCR for λ", certain=False)
READ_ALPHA0 = Reading("α_0", "w_0 (in the unnumbered Q at z'): OCR for ω_0")
READ_GPRIME = Reading("g'", "g: the prime is OCR residue (n'², or the g' of (269) read too early)", certain=False)
READ_E2 = Reading("E e^2 h", "E e^2 h kept as printed; (156) gives I = e^3h/12, so e^3 is expected", certain=False)


def eq255():
    return (a - a1) * (z**2 + R**2) / (z * (z + a - vl))


def eq256():
    return eps * lam


def eq257():
    return w0 * (1 + eps_p)


def eq258():
    return eps * lam * (beta1 * w0 - w0**2 - R**2) / (w0 * (w0**2 + R**2))


def eq258_ends():
    return eps * lam * (lam - v0 - wl - R**2 / w0) / (w0**2 + R**2)


def eq259():
    return -R**2 / w0 * (1 - eps_p)


def eq260():
    return -eps * lam * w0 / (w0**2 + R**2)


def eq260_foci():
    return eps * lam / (z - zp)


def eq261():
    return (zp - z) / beta1


def eq262():
    return G_2 / (eps * lam)


def eq262_energy():
    return 2 * W_over_mg / (lam * eps)


def eq263():
    return (U1**2 + U2 / u) / (2 * eps)


def eq264():
    return 1 / (eps * u**2)


def eq264_distance():
    return -a_r / (a_r - a1)


def eq265():
    return eps * g * lam / (R**2 + w0**2)


def eq266():
    return g / beta1 * (1 + w0**2 / R**2)


def eq267():
    return g * eps * lam / (R**2 + a_r**2)


def eq267_l():
    return g * eps * lam / (a_r * l_syn)


def eq267_expanded():
    return g / l_syn + g * lam / (a_r * l_syn * u**2)


def eq268():
    return g / l_syn + E * e**2 * h / (12 * m * a_r * l_syn * lam)


def suppleness_91():
    return sp.Integer(-1)


def C_285():
    return sp.Rational(3, 4) * (2 * U2 + U2 * U1**2 - u * U1**4) / (U2 + u * U1**2)


def C_285_exponential():
    return sp.Rational(3, 8) * (sp.sinh(4 * u) - 4 * u) / (sp.sinh(u) ** 2 * (sp.sinh(2 * u) + 2 * u))


READ_BETA = Reading("β (n°87)", "β_t: the thermo-elastic coefficient β of n°14, not the ordinate β of A")
READ_EPS = Reading("ϵ", "ε of (256)")


def eq270():
    return (alpha_rod * wl + alpha_blade * (-lam + lam * wl**2 / M_lambda - 4 * G_2) - beta_t * G_2) / (2 * eps * lam)


def eq271():
    return beta_t + alpha_blade * (4 + lam / G_2 * (1 - wl**2 / M_lambda)) - alpha_rod * wl / G_2


def eq272():
    """With Haag's symbols U1, U2 (compared under chapter III's definitions (160), rational in th(u/2))."""
    return beta_t + 2 * (alpha_blade * (u * U1s**2 + 2 * U2s) - alpha_rod * U2s) / (u * U1s**2 + U2s)


def eq273():
    return beta_t + 3 * alpha_blade - alpha_rod


READ_X = Reading("x (ω x, ch ω x)", "s: x = s to the first order (n°2); the memoir writes x in (77)")
# n°51: T = mg/(eh); with (156), mg = EIu²/λ², I = e³h/12: T = Ee²u²/(12λ²); ω = u/λ
FATIGUE_DEFS = ((T, E * e**2 * u**2 / (12 * lam**2)), (omega, u / lam))


def eq278():
    return theta / sp.sinh(u) * (sp.cosh(omega * s) - 1)


def eq280():
    return theta * sp.sqrt(3 * E * T) * sp.cosh(omega * s) / sp.sinh(u)
