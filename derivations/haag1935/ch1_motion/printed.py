"""Haag 1935, chapter I, n°5–9: the formulas (21)–(41) as printed, with their OCR readings.

The conditions (28)–(30), (32) are written as the expression the text sets to 0,
the inequalities (38)–(41) as the quantity it claims positive.
"""
from __future__ import annotations

from pendsym.result import Reading
from ..symbols import K, R, Y, a, beta, beta1, beta2, g, lam, n_squared, theta, v0, vl, w0, wl, z, zp

READ_29 = Reading("b_1 w_λ (in the line before (28))", "β1 wλ")


# ---------------------------------------------------------------- n°5
def eq21():
    return Y * beta1 + theta * beta2


def eq22_beta1():
    return lam + vl - v0


def eq22_beta2():
    return wl - w0


def eq22_beta2_vl():
    return -vl


def eq23():
    return (beta + theta * vl) / beta1


def eq24_N_Y():
    return Y * vl + theta * wl


def eq24():
    return (beta * vl + theta * (vl**2 + beta1 * wl)) / beta1


# ---------------------------------------------------------------- n°6
def eq25():
    """(25) as printed: g(β2θ − β)/β1."""
    return g * (beta2 * theta - beta) / beta1


def eq26():
    """(26) as printed: g[β(a − vλ) − θ(a(λ − v0) + vλ² + β1wλ)]/β1."""
    return g * (beta * (a - vl) - theta * (a * (lam - v0) + vl**2 + beta1 * wl)) / beta1


# ---------------------------------------------------------------- n°7
def eq27():
    return beta + (a + z) * theta


def eq28():
    return n_squared / g * beta1 - (1 - z / R**2 * (a - vl))


def eq29():
    return n_squared / g * (a + z) * beta1 - (-beta2 + z / R**2 * (a * (lam - v0) + vl**2 + beta1 * wl))


def eq30():
    return z**2 + z * (a**2 + a * lam - R**2 - a * (v0 + vl) + vl**2 + beta1 * wl) / (a - vl) - R**2


def eq31():
    return -R**2


def eq32():
    return (a - vl) * (z + zp) + a**2 + a * lam - R**2 - a * (v0 + vl) + vl**2 + beta1 * wl


def eq33():
    return -beta1 * (a + wl)


# ---------------------------------------------------------------- n°8
def eq34():
    return -K * g / zp


def eq35():
    return -(a + zp - vl) / beta1


def eq36():
    return (a + wl) / (a + z - vl)


def eq37():
    return -(a + wl) / beta1


# ---------------------------------------------------------------- n°9
def eq38():
    return -(a + zp - vl)


def eq39():
    return a + z - vl


def eq40():
    return a + wl


def eq41():
    return -wl


def eq41_below_vl():
    return vl - (-wl)
