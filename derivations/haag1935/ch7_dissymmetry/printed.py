"""Haag 1935, chapter VII, n°98: the formulas (295)–(301) as printed, with their OCR readings.

Every printed form is transcribed as the OCR shows it, except where a Reading says otherwise.  (2π − 1) appears six
times ((295), D, (296), the definition of β, the line before (300), (300)): it is the memoir's, not the OCR's (see
:data:`READ_2PI`).
"""
from __future__ import annotations

import sympy as sp

from pendsym.result import Reading
from ..ch2_common import j_eq, theta0
from ..ch2_dissymmetry.derivation import eps_E as eps_E_fn, phi1
from ..ch2_perturbations.derivation import g_fn
from ..ch7_gravity.symbols import C_s
from ..symbols import G, G_2, s
from .derivation import alpha_a, beta_a, eps_E, gamma_a

G1 = g_fn(1, eps_E_fn(s))
TWO_PI_1 = 2 * sp.pi - 1

READ_EPS = Reading("ε in (295)–(301)", "ε_E = ΔE/E of n°44, constant (the footnote of (295): not the ε of (256)); "
                   "g_1(ε)/G_2 when ε varies along the blade")
READ_2PI = Reading("(2π − 1) in (295), D, (296), sin β, sin(2γ − α), (300)",
                   "as printed: it is what the line before (295) gives when its last term, −4j cos φ1/θ0, lacks the "
                   "1/π of (154); the same factor six times, so the memoir's (the derivation has 1 in its place)")
READ_300_G = Reading("G in (300), ε = (Gπ/2)θ0² …", "C: (296), from which (300) is drawn, has C, and so has (301), its "
                     "limit for γ small (an OCR confusion of C and G, or a misprint)", certain=False)
READ_LINE_295 = Reading("−4j cos φ1/θ0, the last term of the line before (295)",
                        "as printed, without the 1/π of (154) (the OCR gives the line whole; every later formula's "
                        "(2π − 1) is what this line gives, so the memoir's)")
READ_ALPHA_BETA = Reading("α, β in (297), (298)", "α of (296) (printed), β in (0, α) with sin β = sin α/(2π − 1)")

# the printed α and β as functions of ε, C, θ0 (the definitions of n°98)
TAN_ALPHA = 2 * eps_E * TWO_PI_1 / (C_s * theta0**2 * sp.pi)
ALPHA_DEF = sp.atan(TAN_ALPHA)
BETA_DEF = sp.asin(sp.sin(ALPHA_DEF) / TWO_PI_1)
DEFS_AB = ((alpha_a, ALPHA_DEF), (beta_a, BETA_DEF))


def eq295_sum():
    """The line before (295)."""
    return -C_s * j_eq**2 + G1 / G_2 * (-1 + (2 * phi1 - sp.sin(2 * phi1)) / sp.pi
                                        - 4 * j_eq * sp.cos(phi1) / theta0)


def eq295():
    return G / 4 * (2 * eps_E / sp.pi * phi1 + eps_E / sp.pi * TWO_PI_1 * sp.sin(2 * phi1)
                    + C_s * theta0**2 / 2 * sp.cos(2 * phi1) - eps_E - C_s * theta0**2 / 2)


def eq296_D():
    return (2 * eps_E / sp.pi + 2 * eps_E / sp.pi * TWO_PI_1 * sp.cos(2 * phi1)
            - C_s * theta0**2 * sp.sin(2 * phi1))


def eq296():
    """(296): tang α."""
    return TAN_ALPHA


def eq296_D_alpha():
    return C_s * theta0**2 / sp.cos(alpha_a) * (sp.sin(alpha_a) / TWO_PI_1 - sp.sin(2 * phi1 - alpha_a))


def sin_beta():
    return sp.sin(alpha_a) / TWO_PI_1


def eq297():
    return -theta0 * sp.sin((alpha_a + beta_a) / 2)


def eq298():
    return theta0 * sp.cos((alpha_a - beta_a) / 2)


def eq299():
    return theta0 * sp.sin(gamma_a) + j_eq


def eq300_relation():
    return sp.sin(2 * gamma_a - alpha_a) - sp.sin(alpha_a) / TWO_PI_1


def eq300():
    """(300), G read as C (:data:`READ_300_G`)."""
    return C_s * sp.pi / 2 * theta0**2 * sp.sin(2 * gamma_a) / (1 + TWO_PI_1 * sp.cos(2 * gamma_a))


def eq301():
    return -C_s / 2 * j_eq * theta0
