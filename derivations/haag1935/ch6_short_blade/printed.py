"""Haag 1935, chapter VI, n°68–77: the formulas as printed (seed 001, lines ~1835–2060), with their readings.

The OCR writes Haag's v, w as ν, ω (:data:`..common.READ_VW`); U, U1, U2 are th(u/2), 1/sh u,
1/th u (160), applied with :data:`..symbols.DEFS`; l = a + R²/a (213) is applied as a
definition before the comparison.
"""
from __future__ import annotations

import sympy as sp

from pendsym.result import Reading

from ..symbols import DEFS, G_2, R, U, U1, U2, a, beta1, beta1_positive, g, lam, u, v0, vl, w0, wl, z, zp
from .expansion import F_2, l

L_DEFINITION = ((l, a + R**2 / a),)
DEFINITIONS = L_DEFINITION + DEFS

READ_V2 = Reading("−F_2 − 2v_2 + 2(a/l)β1", "v_λ: the OCR reads the index λ as 2 (a + z' = v_λ − (a/l)β1 by (215))")
READ_OMEGA_LAMBDA = Reading("ω_λ (217), (218)", "w_λ: the OCR renders w as ω")


def rhs_212():
    return z * (-a * beta1 + l * vl - (beta1 * wl + vl**2)) / (a - vl)


def length_213():
    return a + R**2 / a


def reduced_212():
    return -beta1 + l / a * vl


def z_214():
    return R**2 / a - R**2 / (a**2 + R**2) * (beta1 - l / a * vl)


def zp_215():
    return -a + (vl - a / l * beta1)


def K_216():
    return a / l * (1 + wl / a + vl / l + R**2 / (a * l) * (beta1 / l - vl / a))


def n2_217():
    return g / l * (1 + wl / a + 2 * vl / l - beta1 * a / l**2)


def dl_218():
    return -l / a * wl - 2 * vl + beta1 * a / l


def dl_219():
    return lam - v0 - w0


def dl_220():
    return lam * (1 - U2 / u)


def u_root_220():
    return sp.Rational(6, 5)


def Q_221():
    return a + wl + beta1


def Q_221_ends():
    return a + lam + w0 - v0


def Kp_224():
    return -l / beta1


def np2_225():
    return g * a * l / (beta1 * R**2)


def ratio_226():
    return l / R * sp.sqrt(a / beta1_positive)


def bound_226():
    return l / R * sp.sqrt(a / beta1_positive) - l / R * sp.sqrt(a / lam)


def S_235():
    return a / G_2


def S_uniform_235():
    return 2 * a / (lam * (U1**2 + U2 / u))


def S_sh_235():
    return 2 * a / lam * u * sp.sinh(u) ** 2 / (u + sp.sinh(u) * sp.cosh(u))


def u_factor_235():
    return u * sp.sinh(u) ** 2 / (u + sp.sinh(u) * sp.cosh(u))


def factor_236():
    return sp.sinh(u) ** 2 / (u + sp.sinh(u) * sp.cosh(u))


def value_236():
    return sp.Rational(993, 1000)


def OFp_237_l():
    return lam + vl - a / l * beta1


def OFp_237():
    return v0


def x_238_root():
    return -F_2 - 2 * (a + zp)


def x_238():
    return -F_2 - 2 * vl + 2 * a / l * beta1


def F2_239():
    return 1 - 2 * U / u + U2 / (2 * u) - U1**2 / 2


def x_240():
    return lam * (1 - U2 / (2 * u) + U1**2 / 2)


def c_240():
    return lam / 2 * (U2 / u - U1**2)


def c_thin_240():
    return lam / (2 * u)


def OFp_thin_237():
    return lam / u


# ---------------------------------------------------------------- n°70–71 (temperature, launches)
def dT_222():
    from ..symbols import G_2, M_lambda, alpha_blade, alpha_rod, beta_t
    return (alpha_rod * (1 - (lam - w0 - v0) / a) + alpha_blade * lam / a * (1 + w0**2 / M_lambda - 4 * G_2 / lam)
            - beta_t * G_2 / a)


def dT_223():
    from ..symbols import alpha_blade, alpha_rod, beta_t
    return alpha_rod / 2 + lam / (2 * a) * (-alpha_rod * (1 - U2 / u) + alpha_blade * (1 - U1**2 - 2 * U2 / u)
                                            - beta_t / 2 * (U1 + U2 / u))


def focal_ratio():
    from ..symbols import b
    return (b - a - z) / (b - a - zp)


def ratio_227():
    return -focal_ratio() * a * beta1 / l**2


def ratio_228():
    return -focal_ratio() * a**2 / (l * R) * sp.sqrt(beta1_positive / a)


def ratio_228_227():
    return l / R * sp.sqrt(a / beta1_positive)


READ_BETA_T = Reading("β (thermo-elastic coefficient)", "β_t, not the ordinate β of A")
READ_222 = Reading("dT/T = α'(1 − …) + α(λ/a)(…) − βG_2/a", "transcribed as shown: the derivation from (60) gives "
                   "half of it (the leading term α'/2, as (223) prints); a ½ (or a 2 on the left) may be lost in "
                   "the OCR", certain=False)
READ_223 = Reading("−(β/2)(U_1 + U_2/u)", "transcribed as shown: G_2 = λ(U_1² + U_2/u)/2 (235) gives U_1²; the "
                   "exponent may be lost in the OCR", certain=False)
READ_BARS = Reading("FB/F'B (overlined)", "algebraic distances: FB = b − a − z, F'B = b − a − z'")


def dl_thread():
    return lam


def fatigue_232():
    from ..symbols import E, T
    from .derivation import THETA_0
    return sp.sqrt(3 * E * T) * U2 * THETA_0


def P_bound_70():
    from ..symbols import M_lambda, mu
    return mu * w0 / lam - w0**2 / M_lambda


def G2_bound_70():
    from ..symbols import mu
    return mu * (v0 + wl) ** 2 / w0 - G_2


def fatigue_229(at: str):
    from ..ch3_uniform.launch_symbols import stress_scale, weight
    from ..symbols import b
    from .derivation import Q_POSITIVE as Q
    coefficient = U2 if at == "T0" else U1
    return lambda: (stress_scale * Q / weight * (coefficient * sp.Abs(b - a - zp) + U * sp.Abs(b - a - z))
                    / sp.Abs(z - zp))


def fatigue_by_attack(case: str):
    from ..ch3_uniform.launch_symbols import stress_scale
    from ..symbols import b
    from .derivation import THETA_0
    if case == "between":
        return lambda: stress_scale * THETA_0 * (U1 + U * a / b)
    return lambda: stress_scale * THETA_0 * (U + U2 - U * a / b)
