"""Haag 1935, chapter II, n°44–45: the formulas (151)–(155) as printed, with their OCR readings."""
from __future__ import annotations

import sympy as sp

from pendsym.result import Reading
from ..ch2_common import i_clamp, j_eq, theta0, theta1
from ..ch2_perturbations.derivation import g_fn
from ..symbols import K, M_of_s, Q, a, lam, n_squared, s, v, vl, w, wl, z
from .derivation import A_d, B_d, C_j, eps_E, phi1

G1 = g_fn(1, eps_E(s))
READ_EPS4 = Reading("ε_4 (first lines of n°44), ε_i (the line before (151))",
                    "ε_4, the moment increment of the blade's equation (the ε of (105)); ε (no index) is ΔE/E",
                    certain=False)
READ_DPHI = Reading("dω/ds (the line after ε_4)", "dφ/ds (the blade's slope φ; (14) gives M dφ/ds)")
READ_NU = Reading("ν, ω in (151)–(152)", "v, w (chapter I's functions)")
READ_152 = Reading("∫_0^λ in (152)", "as printed (the blade's integrals)")
READ_LIMITS = Reading("∫_{−φ1}^{π−φ1} before (154)",
                      "∫_{φ1}^{π−φ1}: the half-period where θ = j + θ1 > 0 (θ0 sin φ > −j = θ0 sin φ1); over "
                      "(−φ1, π − φ1), a length π, ∫sin²φ = π/2 and (154) would have no term in φ1",
                      certain=False)


def eps_along():
    """n°44: ε_i = −ε[θ1(Kv + w) + wj − vi]."""
    return -eps_E(s) * (theta1 * (K * v(s) + w(s)) + w(s) * j_eq - v(s) * i_clamp)


def eq151():
    return -n_squared / K * (theta1 * G1 - A_d * i_clamp + B_d * j_eq)


def eq152():
    common = (K * v(s) + w(s)) * eps_E(s) / M_of_s(s)
    return sp.Tuple(sp.Integral(v(s) * common, (s, 0, lam)), sp.Integral(w(s) * common, (s, 0, lam)))


def half_derivatives():
    """n°44: A = ½∂g_1/∂K, B = ½∂g_1/∂(homogeneity): the differences are 0."""
    return sp.Tuple(0, 0)


def eq153():
    return theta0 * sp.sin(phi1) + j_eq


def eq154():
    return -G1 / (4 * Q) + (G1 * (2 * phi1 - sp.sin(2 * phi1))
                            + 4 * (A_d * i_clamp - B_d * j_eq) / theta0 * sp.cos(phi1)) / (4 * sp.pi * Q)


def i_of_j():
    return -j_eq * (a + wl) / (a - vl)


def identity_AK_B():
    """AK + B = g_1: the difference, 0."""
    return sp.S.Zero


def eq155():
    return (2 * C_j * theta0**2 - G1 + 2 * phi1 * G1 / sp.pi
            + sp.sin(2 * phi1) / sp.pi * (G1 + 2 * A_d * K * z / (a - vl)) - 2 * C_j * theta0**2 * sp.cos(2 * phi1))
