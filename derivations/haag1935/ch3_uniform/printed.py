"""Haag 1935, chapter III: the formulas as printed, transcribed from the OCR text, with their readings.

Each function returns one transcription in the memoir's own notation (U, U1, U2
of (160), ω of (156), c of (172), T of n°51 …); the definitions under which the
printed and the derived forms are compared follow the transcriptions.  Where the
text shows something else than what is transcribed, a :class:`Reading` says so.
"""
from __future__ import annotations

import sympy as sp

from pendsym.result import Reading

from .. import symbols
from ..symbols import (DEFS, K_OF_k, E, K, Fn, Gam, Gn, M, R, T, U, U1, U2, Y, a, a1, b, c, e, h, k, lam, mb, mg, n,
                       omega, s, theta, u, x0, xl, z, zp)
from .launch_symbols import (K_prime, Q, V, m, m_striking, n_parasitic, n_principal, restitution, stress_scale,
                             t, weight)

y = sp.Symbol("y", real=True)        # the variable of the integral of the footnote of (164)


# ================================================================ n°47: (156)–(161)
def omega_squared():
    return 12 * mg / (E * e**3 * h)


def u_of_blade():
    return 2 * lam / e * sp.sqrt(3 * mg / (E * e * h))


def v():
    return lam * sp.sinh(u / 2 - omega * s) / (u * sp.cosh(u / 2))


def w():
    return lam * sp.cosh(omega * s) / (u * sp.sinh(u))


def phi1():
    return 1 - sp.cosh(u / 2 - omega * s) / sp.cosh(u / 2)


def phi2():
    return sp.sinh(omega * s) / sp.sinh(u)


def v0():
    return lam * U / u


def v_lambda():
    return -lam * U / u


def w0():
    return lam / u * U1


def w_lambda():
    return lam / u * U2


def beta1():
    return lam * (1 - 2 * U / u)


def beta2():
    return lam * U / u


def zero():
    """An identity, printed as lhs = rhs, transcribed as lhs − rhs = 0 ((161), footnote of (166))."""
    return sp.S.Zero


# ================================================================ n°48: (162)–(166)
def first_integral_G():
    return M * K**2 - x0**2


def G_recurrence():
    return ((n - 1) * (x0**2 - M * K**2) / M**2 * Gn(n - 2)
            + ((1 - K) * xl ** (n - 1) + K * x0 ** (n - 1)) / M ** (n - 2))


def Gamma_recurrence():
    return ((n - 1) * U1 * (U1 + 2 * k * U) * Gam(n - 2)
            + (K * (U1 + K * U) ** (n - 1) + (1 - K) * (U1 + (1 - K) * U) ** (n - 1)) / u)


READ_BARS = Reading("|U_1 + (1-K)U|^{n-1}", "(U_1 + (1 − K)U)^{n−1}: bars are OCR for brackets")


def k_of_foci():
    return (a - a1) * (z - symbols.w0) / (a + z - symbols.vl) ** 2


def Gamma_integral():
    return sp.Integral((sp.cosh(y) / sp.sinh(u / 2) + (1 - 2 * K) * sp.sinh(y) / sp.cosh(u / 2)) ** n,
                       (y, -u / 2, u / 2)) / (2**n * u)


def Gamma1():
    return 1 / u


def Gamma2():
    return (U1**2 + U2 / u) / 2 + k * U * (U1 - 1 / u)


def Gamma3():
    return (sp.Rational(1, 3) + U1**2 - k * U**2) / u


def Gamma4():
    return (sp.Rational(3, 8) * U1**4 + sp.Rational(5, 8) / u * U1**2 * U2 + U2 / (4 * u)
            + k * U / 2 * (3 * U1**3 - (2 * U**2 + 3 * U1 * U2) / u)
            + k**2 * U**2 / 2 * (3 * U1**2 + (U - 3 * U1) / u))


def Gamma5():
    return ((U2**4 + 4 * U1**3 + sp.Rational(4, 3) * U1**2) / (5 * u)
            - k * U / u * (U**3 - 2 * U * U1**2 + sp.Rational(8, 3) * U1) + k**2 * U**4 / u)


READ_GAMMA5 = Reading("\\frac{1}{5u}(U_2^4 + 4U_1^3 + \\frac43 U_1^2)",
                      "transcribed as shown, 4U_1^3; the derivation gives 4U_1^4 (an exponent 4 read as 3 "
                      "by the OCR, or a misprint)", certain=False)


def S_p_leading():
    return sp.Tuple(*[x for q in range(1, 7) for x in (2, 2 * q + 1)])


def Gamma_leading():
    return sp.Tuple(*[U ** (2 * q) / u * (-1) ** q for q in (1, 2)])


# ================================================================ n°49: (167)–(170)
def first_integral_F():
    return (K * U + U1) ** 2


def F_recurrence():
    return (2 * n - 1) * K * Fn(n - 1) - (n - 1) * (K * U + U1) ** 2 * Fn(n - 2) + lam / u * (U2 - K * U)


def F0():
    return lam


def F1():
    return U / u + K * (1 - 2 * U / u)


def F2():
    return (U2 / u - U1**2) / 2 + K * U * (1 / u - U1) + K**2 * (1 + U * U1 - 3 * U / u)


def F_in_F1_F2():
    return (3 * Fn(2) * (2 * K**2 * (3 - U * U1) + 2 * K * U * U1 + U1**2)
            - 6 * Fn(1) * K * (K * U + U1) ** 2 + lam / u * (U2 - K * U) * (3 * K - 1))


def F():
    return ((U2 / u * (3 * U1**2 - 2) - 3 * U1**3) / 8
            + K / 2 * ((2 * U2 + U1 - 3 * U * U1**2) / u - 3 * U * U1**3)
            + 3 * K**2 / 2 * (U / u * (1 + 3 * U1**2) + 3 * U1**2 * (U * U1 - 1))
            + 3 * K**3 * U * ((1 + U * U1) / u + U1 * (U * U1 - 2))
            + 3 * K**4 * (-U / (2 * u) * (7 + U * U1) + 1 + 2 * U * U1 - U**2 * U1**2 / 2))


READ_F = Reading("\\frac18[\\frac{U_2}{u}(3U_1^2 - 2) - 3U_1^3]",
                 "transcribed as shown, −3U_1^3; the derivation gives −3U_1^4 (the same exponent "
                 "slip as in Γ_5 of (166): OCR or misprint)", certain=False)


# ================================================================ n°50: (30), (171)–(174)
def foci_combination():
    return lam**2 / u**2 * (u * U2 - 1)


READ_FOCI_COMBINATION = Reading("v_λ^2 + β_1 v_λ", "v_λ² + β1 w_λ, the combination of (30)", certain=False)


def shape():
    return Y * (omega * s - sp.sinh(omega * s) + c * (sp.cosh(omega * s) - 1))


READ_SHAPE = Reading("ωx, sh ωx, ch ωx", "s for x (the memoir replaces s by x, (77))")


def c_of_shape():
    return U + U1 * theta / Y


READ_C = Reading("θ/\\bar{Y}", "θ/Y")


def c_principal():
    return U + U1 / K


def c_static():
    return (a * U + b * U1 + lam / u) / (a - a1)


# ================================================================ n°51–53: (175)–(179)
def bending_stress():
    return sp.sqrt(3 * E * T) * Y * (c * sp.cosh(omega * s) - sp.sinh(omega * s))


def fatigue_Gamma():
    return c * sp.cosh(omega * s) - sp.sinh(omega * s)


READ_FATIGUE_GAMMA = Reading("cchωs − shωs", "c ch ωs − sh ωs")


def fatigue_Gamma_0():
    return c


def fatigue_Gamma_lambda():
    return c * sp.cosh(u) - sp.sinh(u)


READ_FATIGUE_GAMMA_LAMBDA = Reading("cchu − shu", "c ch u − sh u")


def static_difference():
    return ((2 * a - b) * U + lam / u) / (a - a1)


def static_sum():
    return (b * (U1 + U2) + lam / u) / (a - a1)


def principal_stress():
    return theta * sp.sqrt(3 * E * T) * (K * sp.sinh(u / 2 - omega * s) / sp.cosh(u / 2) + U1 * sp.cosh(omega * s))


def C0():
    return K * U + U1


def C_lambda():
    return U2 - K * U


# ================================================================ n°54: (180)–(181)
def static_launch_T0():
    return stress_scale * Q / weight * ((U + U1 / K) * (b - a - zp) * sp.cos(n_principal * t)
                                        - (U + U1 / K) * (b - a - z) * sp.cos(n_parasitic * t)) / (z - zp)


def static_launch_T_lambda():
    return stress_scale * Q / weight * ((U2 / K - U) * (b - a - zp) * sp.cos(n_principal * t)
                                        - (U2 / K - U) * (b - a - z) * sp.cos(n_parasitic * t)) / (z - zp)


READ_K_PRIME_T0 = Reading(
    "(U + U_1/K)(b − a − z) cos n't, second term",
    "transcribed as shown, with K; the derivation (n°54: the parasitic vibration has Y = K'θ) gives K' "
    "there, and the memoir's own general formula before (180) has K'U + U_1: a prime probably lost in the OCR",
    certain=False)
READ_K_PRIME_T_LAMBDA = Reading("(U_2/K − U)(b − a − z) cos n't, second term", READ_K_PRIME_T0.read_as,
                                certain=False)


def shock_factor():
    """√(3ET)(1 + h)V/((a − b)² + R²(1 + m/m')), the factor of both stresses (181)."""
    return stress_scale * (1 + restitution) * V / ((a - b) ** 2 + R**2 * (1 + m / m_striking))


def shock_launch_T0():
    return shock_factor() * ((K * U + U1) * (b * z - a * z + R**2) * sp.sin(n_principal * t) / n_principal
                             - (K_prime * U + U1) * (b * zp - a * zp + R**2) * sp.sin(n_parasitic * t)
                             / n_parasitic) / (z - zp)


def shock_launch_T_lambda():
    return shock_factor() * ((U2 - K * U) * (b * z - a * z + R**2) * sp.sin(n_principal * t) / n_principal
                             - (U2 - K_prime * U) * (b * zp - a * zp + R**2) * sp.sin(n_parasitic * t)
                             / n_parasitic) / (z - zp)


# ================================================================ n°56–57: (182)–(183)
def inertia():
    return mb * lam**2 / u**2 * (K**2 * (u**2 / 3 - 1 - u * U + 5 * U / u - 3 * U * U1)
                                 + K * (2 - 5 * U / u - u * U1 + 3 * U * U1)
                                 + sp.Rational(3, 2) * U1**2 + (U - 3 * U1) / (2 * u))


def inertia_auxiliary():
    return lam / u * (k * (u - 2 * U) - U1)


def s_minus_x():
    return (K**2 / 2 * (s * (sp.cosh(u) + 2) / (sp.cosh(u) + 1)
                        + 2 * lam / u * sp.sinh(u / 2 - omega * s) / sp.cosh(u / 2)
                        + lam / (2 * u) * sp.sinh(2 * omega * s - u) / (sp.cosh(u) + 1)
                        - 3 * lam / (2 * u) * U)
            - K * (s / (2 * (sp.cosh(u) + 1)) + 3 * lam / (4 * u) * U1
                   - lam / u * U1 * sp.cosh(omega * s)
                   + lam / (4 * u) * U1 * sp.cosh(2 * omega * s - u / 2) / sp.cosh(u / 2))
            - U1**2 / 4 * (s - lam / (2 * u) * sp.sinh(2 * omega * s)))


def J():
    return (lam / 8 * (1 / u**2 - U1**2)
            - K * lam / 4 * (1 / (sp.cosh(u) + 1) + 3 / u * (U1 - 1 / u))
            + K**2 * lam / 4 * ((sp.cosh(u) + 2) / (sp.cosh(u) + 1) - 3 * U / u))


# ================================================================ the definitions the printed forms use
DEFINITIONS = DEFS                                 # ω, M of (156); U, U1, U2 of (160)
DEFINITIONS_WITH_k = DEFS + K_OF_k                 # … and k = K(1 − K) of (165)
_TANH_FORMS = dict(DEFS)
C_DEFINITION = (c, (U + U1 * theta / Y).subs(_TANH_FORMS, simultaneous=True))           # (172)
T_DEFINITION = (T, E * e**2 * u**2 / (12 * lam**2))                                     # T = mg/(eh), (156)
X0_DEFINITION = (x0, (K * lam * U / u + lam * U1 / u).subs(_TANH_FORMS, simultaneous=True))   # x_0 = Kv_0 + w_0
A1_DEFINITION = (a1, -lam / u * _TANH_FORMS[U2])                                        # a1 = −w_λ (41)
