"""Haag 1935, chapter V: the formulas as printed (OCR text of n°64–67), with their readings."""
from __future__ import annotations

import sympy as sp

from pendsym.result import Reading

from ..symbols import E, R, a, beta, beta1, e, g, h, lam, m, theta, u, v0, vl, w0, wl, z, zp
from .symbols import F0, R0, a0, eps, n0, rho

READ_V0_IN_204 = Reading("R²θ'' = −gν0θ; R0 = √(β1ν0)",
                         "as shown, ν0 = v0 (the OCR's ν for Haag's v); the derivation gives w0, which (211)'s "
                         "√(β1/ω0) also needs", certain=False)
READ_PLUS_R2 = Reading("a² + λa + R² − a(ν0 + νλ) + νλ² + β1ωλ = 2ρεR²",
                       "as shown (+R²); (30) has −R² and only −R² turns (30) into (208)", certain=False)
BETA1_DEF = ((beta1, lam + vl - v0),)            # (22)
# R0 = √(β1·…) is compared where its radicand is positive (β1, v0, w0 > 0 on every blade of chapter III)
POSITIVE_ENDS = tuple((sym, sp.Symbol(sym.name, positive=True)) for sym in (beta1, v0, w0))
FOCUS_NUMERATOR = a**2 + lam * a - a * (v0 + vl) + vl**2 + beta1 * wl


def roots_at_R_zero():
    return sp.Tuple(0, -FOCUS_NUMERATOR / (a - vl))


def parasitic_n2():
    return g * FOCUS_NUMERATOR / (R**2 * beta1)


def point_mass_n2():
    return g / lam * u * sp.cosh(u) / (u * sp.cosh(u) - sp.sinh(u))


def point_mass_thread():
    return g / lam


def point_mass_stiff():
    return 3 * g / (lam * u**2)


def point_mass_stiff_elastic():
    return E * e**3 * h / (4 * lam**3 * m)


def critical_a():
    return vl


def decoupled_motion():
    """(203), (204): the right sides of β'' + aθ'' and R²θ''."""
    return sp.Tuple(-g / beta1 * (beta + a * theta), -g * v0 * theta)


def equal_period_radius():
    return sp.sqrt(beta1 * v0)


def synchronous_n2():
    return g / beta1


def rho_of():
    """ρ from the second (207) with the first, εR = a − vλ."""
    return (a**2 + lam * a + R**2 - a * (v0 + vl) + vl**2 + beta1 * wl) / (2 * (a - vl) * R)


def beat_quadratic():
    return z**2 + 2 * rho * R * z - R**2


def beat_n2():
    return n0**2 * (1 - eps * z / R)


def beat_frequencies():
    return sp.Tuple(F0 * (1 - eps * z / (2 * R)), F0 * (1 - eps * zp / (2 * R)))


def beat_frequency():
    return eps * F0 * sp.sqrt(1 + rho**2)


_BETA1_POSITIVE = sp.Symbol(beta1.name, positive=True)
FREQUENCY_DEFS = ((F0, sp.sqrt(g / _BETA1_POSITIVE) / (2 * sp.pi)), (n0, sp.sqrt(g / _BETA1_POSITIVE)),
                  (beta1, _BETA1_POSITIVE))


def rho_near_equal_periods():
    """(211), ω0 read as w0."""
    return (R0 - R) / (a - a0) + sp.sqrt(beta1 / w0) / 2


_POSITIVE = {sym: sp.Symbol(sym.name, positive=True) for sym in (beta1, w0)}
RHO_211_DEFS = ((R0, sp.sqrt(_POSITIVE[beta1] * _POSITIVE[w0])), (beta1, _POSITIVE[beta1]), (w0, _POSITIVE[w0]))


def first_term_of_58():
    """n°64: "dans la formule (58), il faut supprimer le premier terme du second membre"."""
    return sp.S.Zero
