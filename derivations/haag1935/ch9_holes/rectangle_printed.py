"""Haag 1935, chapter IX, n°104–106: the rectangular hole's formulas as printed, with their OCR readings.

D is a symbol, replaced by its definition (328) before comparison (``DEFS``).
"""
from __future__ import annotations

import sympy as sp

from pendsym.result import Reading

from ..symbols import lam, omega
from .rectangle_derivation import A, A1, A2, B, B1, B2, omega_p, p, s, s0, s1

D = sp.Symbol("D", real=True)
Wp = omega_p
c0, S0 = sp.cos(omega * s0), sp.sin(omega * s0)
cp, sp_ = sp.cos(Wp * p), sp.sin(Wp * p)
R1 = lam - s1                                    # λ − s_1

READ_LAMBDA = Reading("Λ, Λ', Λ'' (after (324), in (325))", "A, A', A'' (the OCR renders A as Λ)")
READ_G2 = Reading("G_2 = ∫_0^λ ω²/M ds (n°105)", "G_2 = ∫_0^λ w²/M ds with M in absolute value (the OCR renders w as ω)")


def definition() -> tuple:
    return ((D, D_definition()),)


def piece_321():
    return A * sp.cos(omega * s) + B * sp.sin(omega * s)


def piece_322():
    return A1 * sp.cos(Wp * (s - s0)) + B1 * sp.sin(Wp * (s - s0))


def piece_324():
    return A2 * sp.cos(omega * (s - s1)) + B2 * sp.sin(omega * (s - s1))


def A2_of_A1():
    return A1 * cp + B1 * sp_


def B2_of_A1():
    return Wp / omega * (-A1 * sp_ + B1 * cp)


def A1_323():
    return A * c0 + B * S0


def B1_323():
    return omega / Wp * (-A * S0 + B * c0)


def A2_325():
    return A * (c0 * cp - omega / Wp * S0 * sp_) + B * (S0 * cp + omega / Wp * c0 * sp_)


def B2_325():
    return -A * (S0 * cp + Wp / omega * c0 * sp_) + B * (c0 * cp - Wp / omega * S0 * sp_)


def B_326():
    return -1 / omega


def A_327():
    return (-cp * sp.cos(omega * (lam - p))
            + sp_ * (omega / Wp * c0 * sp.sin(omega * R1) + Wp / omega * S0 * sp.cos(omega * R1)) + 1) / (omega * D)


def D_definition():
    return cp * sp.sin(omega * (lam - p)) + sp_ * (-omega / Wp * S0 * sp.sin(omega * R1) + Wp / omega * c0 * sp.cos(omega * R1))


def v0_329():
    return A_327()


def vl_329():
    return (cp * sp.cos(omega * (lam - p))
            - sp_ * (omega / Wp * S0 * sp.cos(omega * R1) + Wp / omega * c0 * sp.sin(omega * R1)) - 1) / (omega * D)


def v0_330():
    return (1 / omega * (-cp * sp.cos(omega * (lam - p)) + (omega / Wp + Wp / omega) * sp_ * S0 * c0 + 1)
            / (cp * sp.sin(omega * (lam - p)) + sp_ * (Wp / omega * c0**2 - omega / Wp * S0**2)))


def A_331():
    return -1 / (omega * D)


def w0_332():
    return -1 / (omega * D)


def wl_332():
    return (-cp * sp.cos(omega * (lam - p))
            + sp_ * (omega / Wp * S0 * sp.cos(omega * R1) + Wp / omega * c0 * sp.sin(omega * R1))) / (omega * D)


def G2_333():
    """(333) as printed, divided by 2D²."""
    rhs = (s0 + p * (Wp**2 / omega**2 * c0**2 + S0**2)
           + R1 * (cp**2 + (Wp / omega - omega / Wp) * sp.sin(2 * Wp * p) * sp.sin(2 * omega * s0) / 2
                   + sp_**2 * (Wp**2 / omega**2 * c0**2 + omega**2 / Wp**2 * S0**2))
           + (sp.sin(2 * omega * (lam - p)) * cp**2 - sp_**2 * sp.sin(2 * omega * s0) * sp.cos(2 * omega * R1))
           / (2 * omega)
           + sp.sin(2 * Wp * p) / (4 * Wp) * (sp.cos(2 * omega * (lam - p)) - sp.cos(2 * omega * R1))
           + Wp * sp.sin(2 * Wp * p) / (4 * omega**2) * (sp.cos(2 * omega * (lam - p)) + sp.cos(2 * omega * R1))
           + sp_**2 * sp.sin(2 * omega * R1) / (2 * omega) * (omega**2 / Wp**2 * S0**2 - Wp**2 / omega**2 * c0**2))
    return rhs / (2 * D**2)
