"""Haag 1935, chapter II, n°36–43: the formulas (135)–(150) as printed, with their OCR readings.

Haag's moment increment of the blade's equation (7) (the ε of (105)) comes out of the OCR as ε_1, ε_i, s_1,
ε_s or ε_4; it is read as ε, the ε(s) of (105), everywhere here.  Nested integrals are written with Haag's
variables s, s', s'' (μ' = μ(s'), φ1'' = φ1(s'') …).
"""
from __future__ import annotations

import sympy as sp

from pendsym.result import Reading
from ..ch2_common import theta0
from ..symbols import G_2, Gn, K, M_of_s, Q, g, lam, m, mb, n_squared, s, theta, v, w, x_of_s, y_of_s, z, zp
from ..symbols import varphi1, varphi2
from .derivation import I_lambda, J_w, a_q, c_curv, dE_E, g_fn, i_fn, mu, q, s1, s2, y_dd
from .derivation_experiment import A150, A150p, B150, B150p, C150, C150p, a00, ap00, b00, bp00, p_first
from .derivation_friction import a_f, ap_f, b_f, bp_f, c_rate, n_freq, p_f, theta_dot


def ordinate(x):
    """y for θ = 1: ∫_0^x (Kφ1'' + φ2'') ds''."""
    return sp.Integral(K * varphi1(s2) + varphi2(s2), (s2, 0, x))

READ_EPS = Reading("ε_1, s_1, ε_s, ε_i (the blade's moment increment in n°36–38)",
                   "ε, the moment increment mgε(s) of the blade's equation (7), the ε of (105) (perhaps Haag's ε_4)",
                   certain=False)
READ_LIMITS_36 = Reading("∫_0^λ μ' (d²y'/dt²)(s' − s) ds' (mgε_1, n°36)",
                         "∫_s^λ: the elements below s (the region s < s' < λ of the next line)")
READ_G0 = Reading("g'_0 at the end of (141)", "θ0^q (the OCR renders θ0^q as g'_0; the dimension of a_q c^q asks for "
                  "θ0^q, and n°39 with q = 0 has no factor; at q = 2 the exact blade with the law asks for θ0² too: "
                  "the printed form's residual falls as θ0⁴)", certain=False)
READ_139 = Reading("∫_0^1 in (139)", "∫_0^λ (the blade's integrals run from 0 to λ)")
READ_F_36 = Reading("f = −(n²/(mz'))θ∭(Kv + w)/M μ'(Kφ1'' + φ2'')(s' − s) ds ds' ds''",
                    "f = −(n²/(mz'))θI_λ: the triple integral, which Haag reduces in the next lines to ∫μy² ds = I_λ")
READ_WEIGHT_M = Reading("mε_s = −∫_s^λ μ'(y' − y) ds'",
                        "ε = −(1/m)∫_s^λ μ(s')(y(s') − y(s)) ds' (the moment of the weights gμ' over mg)")


# ---------------------------------------------------------------- n°36
def inertia_moment():
    """mgε = −∫_s^λ μ'(d²y'/dt²)(s' − s) ds'."""
    return -sp.Integral(mu(s1) * y_dd(s1) * (s1 - s), (s1, s, lam)) / (m * g)


def inertia_moment_principal():
    """ε = −(K/(mz'))θ∬μ'(Kφ1'' + φ2'')(s' − s) ds' ds''  (0 < s'' < s', s < s' < λ)."""
    return -K / (m * zp) * theta * sp.Integral(mu(s1) * (s1 - s) * ordinate(s1), (s1, s, lam))


def parts_identity():
    """∫_0^s' (Kv + w)/M (s' − s) ds = ∫_0^s' (Kφ1 + φ2) ds, as (second derivative, slope and value at 0) of the
    difference."""
    return sp.Tuple(0, 0, 0)


def I_lambda_def():
    """I_λ = ∫_0^λ μy² ds, y the ordinate for θ = 1."""
    return sp.Integral(mu(s1) * ordinate(s1) ** 2, (s1, 0, lam))


def inertia_f():
    return -n_squared / (m * zp) * theta * I_lambda


def eq135():
    return -I_lambda / (2 * m * zp * (z - zp))


def eq135_Q():
    return -K * I_lambda / (2 * m * Q * zp)


# ---------------------------------------------------------------- n°37
def weight_moment():
    """mε_s = −∫_s^λ μ'(y' − y) ds'."""
    return -sp.Integral(mu(s1) * (y_of_s(s1) - y_of_s(s)), (s1, s, lam)) / m


def slope_identity():
    """∫_0^s'' (Kv + w)/M ds = Kφ1'' + φ2'': (derivative, value at 0) of the difference."""
    return sp.Tuple(0, 0)


def J_def():
    """J = (1/m')∫_0^λ μ(s − x) ds, for θ = 1."""
    return sp.Integral(mu(s1) * (s1 - x_of_s(s1)), (s1, 0, lam)) / mb


# s − x = ½∫_0^s φ''² ds'' (the line before J: ∫_0^s' φ''² ds'' = 2(s' − x')), θ = 1
DEFS_J = ((x_of_s(s1), s1 - sp.Integral((K * varphi1(s2) + varphi2(s2)) ** 2, (s2, 0, s1)) / 2),)


def weight_f():
    return -2 * mb * J_w / (K * m) * n_squared * theta


def eq136():
    return -mb * J_w / (m * Q)


# ---------------------------------------------------------------- n°38–39
def law_moment():
    """ε_i = −Ma_q(dφ/ds)^{q+1} (c = dφ/ds)."""
    return -M_of_s(s) * a_q(q, s) * c_curv ** (q + 1)


def eq138():
    return -n_squared / K * theta ** (q + 1) * g_fn(q + 1, a_q(q, s))


def eq139():
    x = sp.Symbol("x")
    return sp.Integral((K * v(s) + w(s)) ** (q + 1) / M_of_s(s) ** q * x, (s, 0, lam))


def eq140():
    return sp.Symbol("x") * Gn(q + 1)


def eq141():
    return -i_fn(q + 2) * g_fn(q + 1, a_q(q, s)) / Q * theta0 ** q


def odd_terms():
    """n°38: the odd terms in algebraic value do not change T (the half-periods cancel: the reflection φ → π − φ
    changes the sign of cos^{q+2})."""
    return sp.Integer(-1)


def eq142():
    """i_q = 1·3·5…(q − 1)/(2·4·6…q), q even."""
    return sp.factorial2(q - 1) / sp.factorial2(q)


def eq143():
    """i_q = (2/π)·2·4·6…(q − 1)/(3·5·7…q), q odd."""
    return 2 / sp.pi * sp.factorial2(q - 1) / sp.factorial2(q)


def young():
    """n°39: ΔT/T = −(G2/(2Q))ΔE/E."""
    return -G_2 / (2 * Q) * dE_E


# ---------------------------------------------------------------- n°40–42

READ_147_I = Reading("i_{p+1,q} in (147), i_{p,q+1} in (149)", "as printed; i_mn = i_nm (the text's definition)")
READ_BETA = Reading("élancement négative (n°40)", "élongation négative (a negative swing)")


def friction_moment():
    """(144): the moment diminished by M a_pq c^p c'^q (one term)."""
    return -M_of_s(s) * a_f * c_curv ** p_f * c_rate ** q


def eq146():
    return -n_squared / K * g_fn(p_f + q, a_f) * theta ** p_f * theta_dot ** q


def eq147():
    return n_freq ** q / (4 * Q) * g_fn(p_f + q, b_f + bp_f - a_f - ap_f) * i_fn(p_f + 1, q) * theta0 ** (p_f + q - 1)


def eq149():
    return -sp.pi / 2 * n_freq ** q / Q * g_fn(p_f + q, a_f + b_f + ap_f + bp_f) * i_fn(p_f, q + 1) * theta0 ** (p_f + q)


def i_symmetric():
    """i_mn = i_nm (the text's definition of i_mn)."""
    return sp.Integer(0)


def first_line_149():
    return sp.Symbol("I_f") / (n_freq ** 2 * (z - zp) * theta0)


# g_q(x) of (139) is linear in x: g(b + b' − a − a') = (b + b' − a − a')g(1) for constant coefficients
DEFS_147 = ((g_fn(p_f + q, b_f + bp_f - a_f - ap_f), (b_f + bp_f - a_f - ap_f) * g_fn(p_f + q, 1)),)
DEFS_149 = ((g_fn(p_f + q, a_f + b_f + ap_f + bp_f), (a_f + b_f + ap_f + bp_f) * g_fn(p_f + q, 1)),)


# ---------------------------------------------------------------- (145), n°43 (150)

READ_145 = Reading("M(ΣΣ b_pq c^p c'^q), c' in absolute value: a diminution of the absolute value of the moment (145)",
                   "ε = +M b_pq c^p|c'|^q for θ > 0, θ' < 0: the text gives the magnitude; the sign is n°41's "
                   "replacement a → −b (the outgoing (144) is ε = −M a c^p c'^q)", certain=False)
READ_ALPHA = Reading("a_pq = b_pq + b'_pq − a_pq − a'_pq (n°43)", "α_pq = … (the OCR renders α_pq as a_pq; the text "
                     "names α_pq, β_pq and α_00 next)")


def eq145():
    return M_of_s(s) * b_f * c_curv ** p_f * sp.Abs(c_rate) ** q


def alpha_beta():
    return sp.Tuple(b_f + bp_f - a_f - ap_f, b_f + bp_f + a_f + ap_f)


def no_dissymmetry():
    """n°43: 'impossible de déceler une dissymétrie': (147), (149) unchanged by moving friction across."""
    return sp.Tuple(0, 0)


def eq150_period():
    return A150 / theta0 + B150 * theta0 ** (p_first - 1) + C150 * theta0 ** p_first


def eq150_amplitude():
    return A150p + B150p * theta0 ** p_first + C150p * theta0 ** (p_first + 1)


def alpha00():
    """a_00 + a'_00 = b_00 + b'_00, as the difference."""
    return a00 + ap00 - b00 - bp00


