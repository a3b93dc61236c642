"""Haag 1935, chapter VII, n°86, 88–90: (269), (274)–(277), (279) as printed (seed 001, lines ~2241–2335)."""
from __future__ import annotations

import sympy as sp

from pendsym.result import Reading

from ..ch3_uniform.launch_symbols import Q
from ..symbols import E, I_s, M_of_s, R, a, b, beta1, beta1_positive, e, lam, mg, s, theta, w, w0, z, zp
from .derivation_launch import T_g, T_gp
from .symbols import eps, l_syn

READ_MG_PRIME = Reading("Q/(mg') (274)", "Q/(mg): the prime is OCR residue (g' of (269) read too early)", certain=False)
READ_BARS = Reading("FF', BF', FB (overlined or not)", "algebraic distances along the rod: FF' = z' − z, "
                    "BF' = a + z' − b, FB = b − a − z (B at AB = b, F at GF = z, F' at GF' = z')")
READ_SHAPE = Reading("y = θ(x − a_0) (277)", "y = θ(w − w_0): the OCR renders w as x and w_0 as a_0 ((77) with Y → 0)")
READ_OMEGA = Reading("ω (279), eω/(2I), (e/2)(ω/M)", "w(s): the OCR renders w as ω; I, M of the section at s")


def g_difference_269():
    return l_syn * sp.pi**2 * (1 / T_gp**2 - 1 / T_g**2)


def amplitude_274():
    return Q / mg * (zp - z) * (a + zp - b) / (eps * lam)


def amplitude_prime_274():
    return Q / mg * beta1 * (b - a - z) / (zp - z)


def ratio_275():
    return (a + zp - b) / (b - a - z) * (zp - z) ** 2 / (eps * lam * beta1)


def ratio_276():
    return (a + zp - b) / (b - a - z) * R * (zp - z) / (zp * sp.sqrt(eps * lam * beta1_positive))


def shape_277():
    return theta * (w(s) - w0)


def fatigue_279_I():
    return theta * mg * e * w(s) / (2 * I_s)


def fatigue_279_M():
    return theta * E * e / 2 * w(s) / M_of_s(s)
