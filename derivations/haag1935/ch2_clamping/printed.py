"""Haag 1935, chapter II, n°31–35: the formulas (116)–(134) as printed, with their OCR readings.

Haag uses the letter h twice (the equilibrium β of (117), and ½(K∂H2/∂Y + ∂H2/∂θ) at Y = −i, θ = j of (127))
and β1 twice (the constant of (22), and β − h of (119)); they are kept apart here as h_β and tilde β1.
"""
from __future__ import annotations

import sympy as sp

from pendsym.result import Reading
from ..ch2_common import (H_moments, Q1, dX, h_127, h_132, h_beta, i_clamp as i, i_prime as ip, j_eq as j, theta1,
                          beta1_var)
from ..symbols import Fn, K, X, Y, a, a1, beta1, g, n_squared, theta, theta_ddot, theta_dot, vl, w0, z, zp

READ_H_TWICE = Reading("h in (117) and h in (126)–(133)",
                       "two quantities: β at the equilibrium (117), written h_β here, and "
                       "½(K∂H2/∂Y + ∂H2/∂θ) at Y = −i, θ = j (127), written h")
READ_BETA1 = Reading("β1 in (119) and (121)", "β − h, the new variable (tilde β1 in the formulas), not the β1 = λ + vλ − v0 of (22)")
READ_129_THETA1 = Reading("(129) f = (n²/2K)[…] with no factor θ1",
                          "f = (n²/2K)[…]θ1: the factor θ1 of (123)–(128), Δf and f = (2Q1/K)n²θ1",
                          certain=False)
READ_129_2 = Reading("− aKi'(i' + 2j) in (129)",
                     "as printed; the derivation, and (133) as printed, need − 2aKi'(i' + 2j): a lost factor 2 "
                     "(the OCR or the memoir)", certain=False)
READ_DELTA_F = Reading("(2K/z')(aj + h)(ai' − aj − h) in Δf (n°35)",
                       "as printed; the derivation, and (133) as printed, need −(2K/z')(aj + h)(ai' + aj + h): "
                       "a lost minus sign before ai' (the OCR or the memoir)", certain=False)
READ_J_PRIME = Reading("j' = i + j, 'l'angle que fait le pendule avec la verticale' (118)",
                       "the angle of the tangent AT (the rod's axis) with the vertical; the line AG makes j' + i'",
                       certain=False)


# ---------------------------------------------------------------- n°31
def eq116():
    c, s = sp.cos(theta), sp.sin(theta)
    e1 = (-i**2 / 2 + a / g * ip * (theta_ddot * c - theta_dot**2 * s)
          - a / (2 * g) * ip**2 * (theta_ddot * s + theta_dot**2 * c))
    e2 = (-i + a / g * ip * (theta_ddot * s + theta_dot**2 * c)
          + a / (2 * g) * ip**2 * (theta_ddot * c - theta_dot**2 * s))
    e3 = -a * ip * (X * c + Y * s) + a / 2 * ip**2 * (X * s - Y * c)
    return sp.Tuple(e1, e2, e3)


# ---------------------------------------------------------------- n°32
def loads():
    """X = 1, Y = −i, N = a(Y − Xθ − i'X) = −a(θ + i + i')."""
    return sp.Tuple(1, -i, -a * (theta + i + ip))


def eq117_j():
    return -((a - vl) * i + a * ip) / (a - a1)


def eq117_h():
    return -beta1 * i - vl * j


def eq118():
    return (w0 * i - a * ip) / (a - a1)


# ---------------------------------------------------------------- n°33
def eq119():
    return sp.Tuple(j + theta1, h_beta + beta1_var)


def eq121():
    return -(a + zp) * theta1


def eq122():
    return K * theta1 - i


# ---------------------------------------------------------------- n°34
def eq123():
    return sp.Tuple(theta1 * (K * a / zp * ip * j - i**2 / 2), K * a / (2 * zp) * ip * (ip + 2 * j) * theta1)


def eq124():
    return a * theta1 / 2 * ((1 - K) * (ip**2 + 2 * ip * j) + 2 * i * ip) - a * ip * dX


def eq125():
    return K * a / zp * ip * theta1


def eq126():
    return theta1 * Fn(2) + h_127


def eq127():
    """h = ½(K∂H2/∂Y + ∂H2/∂θ) at Y = −i, θ = j, H2 in moments."""
    H2 = H_moments(2)
    return ((K * H2.diff(Y) + H2.diff(theta)) / 2).subs({Y: -i, theta: j}, simultaneous=True)


def eq128():
    return theta1 * (-i**2 / 2 * Fn(2) + K * a / zp * ip * h_127)


def eq129():
    return n_squared / (2 * K) * (a * (i + ip)**2 + 2 * a * ip * j - a * K * ip * (ip + 2 * j)
                                  - 2 * a * K / zp * ip * (a * ip + a * j + h_127) + i**2 * Fn(2)) * theta1


# ---------------------------------------------------------------- n°35
def eq130():
    return n_squared * theta1 * h_127


def eps1_isochronism():
    return K / zp * (a * j + h_127) * theta1


def eq131():
    return K * a / zp * ip * (a * j + h_127) * theta1


def isochronism_bracket():
    """The five first terms of (109) at Y = Kθ1 − i, θ = θ1 + j, and the last one (h'/24)θ1."""
    return (K * theta1 / zp * ((a * j + h_127)**2 + a * zp / 2 * j**2) + a * theta1 / 2 * (K * j**2 - j**2 - 2 * i * j)
            + h_132 / 24 * theta1)


def eq132():
    """h' = [K²∂²H/∂Y² + 2K∂²H/∂Y∂θ + ∂²H/∂θ²] at Y = −i, θ = j, H = 4YH3 − H4 (108) in moments."""
    H = 4 * Y * H_moments(3) - H_moments(4)
    return (K**2 * H.diff(Y, 2) + 2 * K * H.diff(Y, theta) + H.diff(theta, 2)).subs({Y: -i, theta: j},
                                                                                    simultaneous=True)


def delta_f():
    return n_squared / (2 * K) * theta1 * (a * (j**2 + 2 * i * j - 2 * K * j**2)
                                           + 2 * K / zp * (a * j + h_127) * (a * ip - a * j - h_127) - h_132 / 12)


def eq133():
    return (a / 4 * (i + ip + j)**2 - a * K / 2 * (ip + j)**2 - K / (2 * zp) * (a * ip + a * j + h_127)**2
            + i**2 / 4 * Fn(2) - h_132 / 48)


def q1_from_parts():
    """Q1 = Kf/(2n²θ1) with f = (129) + Δf, both as printed ("En ajoutant ceci à (129)")."""
    return sp.expand(K * (eq129() + delta_f()) / (2 * n_squared * theta1))


def eq134():
    return Q1 / sp.Symbol("Q", positive=True)


DEFS_134 = ((Q1, eq133()), (sp.Symbol("Q", positive=True), K * (z - zp)))
