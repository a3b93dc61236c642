"""Haag 1935, chapter IX, n°107–110: the rhombus hole's formulas as printed, with their OCR readings.

Y_n is Haag's (Neumann's, Jahnke–Emde) second-kind function, :func:`.rhombus_derivation.neumann_Y`; D, D',
D_1, D'_1 are symbols, replaced by their definitions (338), (341), (344) before comparison (``DEFS``).
The OCR of n°108–110 is poor: each place where the text shows something else than what is transcribed
is a :class:`Reading`; a sign or a letter that the derivation contradicts is transcribed as shown.
"""
from __future__ import annotations

import sympy as sp

from pendsym.result import Reading

from ..symbols import omega
from .rhombus_derivation import (A1, A2, B1, B2, D_definitions, D_symbols, J, M0, V, Y, eps, half_symbols, k,
                                 sigma, x, x0, x1)

D, Dp, D1, D1p = D_symbols()
DEFS = D_definitions()
w0, wl, y0, y0p, z0, z0p = half_symbols()

READ_Y = Reading("Y_1, Y_0 (“fonctions de Bessel et de Neumann”, Jahnke–Emde)",
                 "Neumann's Y_n = (π/2)Y_n(today) + (ln 2 − γ)J_n: the normalisation of the Wronskian 1/x that "
                 "Haag quotes (footnote of n°110); today's Y_n would give 2/(πx)")
READ_EPS_337 = Reading("ε = ±1 … “− ou +, suivant que … s > 0 ou s < 0” (n°107)",
                       "the ε of (337) is minus the sign of s, while the ε of dv/ds = ε(dv/dx)2ω²/(kx) is the "
                       "sign of s; both are transcribed with Haag's meaning")
READ_MIDDLE = Reading("A''J_0(x_0) + B''Y_0(x_0) = −A'J_0(x_0) + B'Y_0(x_0)",
                      "transcribed as shown; continuity of dw/ds, whose dx/ds changes sign at s = 0, gives "
                      "−(A'J_0 + B'Y_0), and (339) as printed follows only from that (a lost parenthesis?)",
                      certain=False)
READ_VK = Reading("v_0 = −v_k", "v_0 = −v_λ (λ read as k)")
READ_W0 = Reading("w_0 = −(k/(4ω²x_0)) DD'/DD'", "w_0 = −k/(4ω²x_0DD') (the OCR doubled the denominator DD' "
                  "into a fraction)", certain=False)
READ_WK = Reading("w_k", "w_λ (λ read as k)")
READ_OMEGA_W = Reading("ω_0, ω_λ, ω²/M (n°110)", "w_0, w_λ, w²/M: the OCR renders w as ω")
READ_Y0 = Reading("y_0 = z_0 = … = k/(4ω²D), y'_0 = −z'_0 = … = k/(4ω²D)",
                  "transcribed as shown; (340) gives y_0 = k/(4ω²D') and y'_0 = k/(4ω²D): a prime lost on the first "
                  "(the final G_2 has 1/D² + 1/D'², as with y_0 = k/(4ω²D'))", certain=False)
READ_346_X = Reading("2x_0² D D' D_1 D'_1 in (346)",
                     "transcribed as shown; Haag's own previous line with (343), (345) gives 2x_1², so x_0 may be an "
                     "OCR or printer's slip for x_1", certain=False)


# ================================================================ n°107
def stiffness():
    return M0 * (1 + k * sp.Abs(sigma))


def omega_squared():
    return 1 / M0


def x_of_s():
    return 2 * omega / k * sp.sqrt(1 + k * sp.Abs(sigma))


def bessel_equation():
    return V(x).diff(x, 2) - V(x).diff(x) / x + V(x)


def general_solution():
    A, B = sp.symbols("A B", real=True)
    return x * (A * J(1, x) + B * Y(1, x))


def slope_in_x():
    A, B = sp.symbols("A B", real=True)
    return x * (A * J(0, x) + B * Y(0, x))


def ds_factor():
    return eps * 2 * omega**2 / (k * x)


def v_constant_A():
    return eps * k / (2 * omega**2) * Y(1, x0) / D


def v_constant_B():
    return -eps * k / (2 * omega**2) * J(1, x0) / D


def D_definition():
    return Y(1, x0) * J(0, x1) - Y(0, x1) * J(1, x0)


def wronskian():
    return 1 / x


# ================================================================ n°108
def middle_slope():
    """The right side of n°108's second middle condition, as shown."""
    return -A1 * J(0, x0) + B1 * Y(0, x0)


def continuation_A2():
    return A1 * x0 * (J(1, x0) * Y(0, x0) + J(0, x0) * Y(1, x0)) + 2 * B1 * x0 * Y(0, x0) * Y(1, x0)


def continuation_B2():
    return -2 * A1 * x0 * J(0, x0) * J(1, x0) - B1 * x0 * (J(1, x0) * Y(0, x0) + J(0, x0) * Y(1, x0))


def w_constant_A1():
    return -k / (4 * omega**2 * x0) * Y(0, x1) / (D * Dp)


def w_constant_B1():
    return k / (4 * omega**2 * x0) * J(0, x1) / (D * Dp)


def D_prime_definition():
    return Y(0, x0) * J(0, x1) - Y(0, x1) * J(0, x0)


def w_constant_A2():
    return k / (4 * omega**2) * (Y(0, x0) / Dp + Y(1, x0) / D)


def w_constant_B2():
    return -k / (4 * omega**2) * (J(0, x0) / Dp + J(1, x0) / D)


# ================================================================ n°109
def v0():
    return k * x1 / (2 * omega**2) * D1 / D


def vl():
    return -k * x1 / (2 * omega**2) * D1 / D


def w0_end():
    return -k / (4 * omega**2 * x0 * D * Dp)


def wl_end():
    return k * x1 / (4 * omega**2) * (D1p / Dp + D1 / D)


def D1_definition():
    return Y(1, x0) * J(1, x1) - J(1, x0) * Y(1, x1)


def D1_prime_definition():
    return Y(0, x0) * J(1, x1) - Y(1, x1) * J(0, x0)


def identity_345():
    return 1 / (x0 * x1)


# ================================================================ n°110
def jacobian_in_x():
    """From G_2 = ∫ w²/M ds = (2ω²/k) ∫ (y² + z²)/x dx: the factor of w²/x."""
    return 2 * omega**2 / (k * x)


def integral_identity():
    val, der = sp.symbols("v v'", real=True)
    return (val**2 + der**2) / 2 - val * der / x


def half_integral_y():
    return w0**2 / 2 - (y0**2 + y0p**2) / 2 + y0 * y0p / x0


def half_integral_z():
    return (wl**2 + 1) / 2 - (z0**2 + z0p**2) / 2 + z0 * z0p / x0


def middle_value():
    return k / (4 * omega**2 * D)


def middle_slope_value():
    return k / (4 * omega**2 * D)


def G2_intermediate():
    return omega**2 / k * (w0**2 + wl**2 + 1 - 2 * wl / x1) - k / (8 * omega**2) * (1 / D**2 + 1 / Dp**2)


def G2_346():
    return (k / (8 * omega**2 * D**2 * Dp**2) * (1 / x0**2 + 2 * x0**2 * D * Dp * D1 * D1p - D**2 - Dp**2)
            + omega**2 / k - (D1 / D + D1p / Dp) / 2)


__all__ = ["A2", "B2", "DEFS"]
