"""Haag 1935, chapter VII n°96 and chapter VIII n°103: the formulas as printed (OCR file 001, lines ~2435–2485
and ~2713–2717), with readings."""
from __future__ import annotations

import sympy as sp

from pendsym.result import Reading
from ..ch2_perturbations.derivation import J_w
from ..ch7_gravity.printed import READ_BETA
from ..ch7_gravity.symbols import eps
from ..symbols import G_2, M_lambda, R, U, U1, a, alpha_blade, alpha_rod, beta_t, lam, m, mb, u, wl
from .derivation import DT_T, dT_T

READ_K = Reading("ω_k, M_k (in dω_k and dε/ε)", "w_λ, M_λ: the subscript k is OCR for λ, ω for w (as (52), (57) "
                                               "and (270) have them)")
READ_294 = Reading("d(ΔT)/T", "the change of the weight's perturbation ΔT of (292) for a warming that changes the "
                              "period by dT, over T")


def inertia_291():
    return mb * lam**2 / (4 * m) * (3 * U1**2 + (U - 3 * U1) / u) / (R**2 * u**2 + lam**2 * U1**2)


def weight_292():
    return -mb / m * J_w / (eps * lam)


def weight_293():
    return -mb / (8 * m * eps) * (1 / u**2 - U1**2)


def dwl_warming():
    return alpha_blade * lam * (1 - wl**2 / M_lambda) + (beta_t + 4 * alpha_blade) * G_2


def depsilon():
    return (alpha_rod * a + alpha_blade * lam * (1 - wl**2 / M_lambda) + (beta_t + 4 * alpha_blade) * G_2) / (eps * lam)


def depsilon_minus2():
    return -2 * dT_T


def period_294():
    return 3 * DT_T * dT_T


def ratio_294():
    return -3 * mb * J_w / (m * eps * lam)


def inertia_319():
    return mb * lam**2 / (4 * m) * (3 - sp.sin(u) / u * (4 - sp.cos(u))) / (lam**2 + R**2 * u**2 * sp.sin(u) ** 2)


def weight_320():
    return -mb / (8 * m * eps) * (1 / u**2 - 1 / sp.sin(u) ** 2)
