"""Haag 1935, chapter VIII, n°100–103: the formulas as printed (OCR file 001, lines ~2561–2719)."""
from __future__ import annotations

import sympy as sp

from pendsym.result import Reading
from ..symbols import T, E, omega, s, theta, a, alpha_blade, alpha_rod, beta_t, e, h, lam, u
from ..symbols import beta1 as beta_1
from ..symbols import wl as w_lambda
from ..ch7_gravity.symbols import eps

READ_313 = Reading("v_λ = −λ/(u tang u) (third)", "w_λ: the third formula of (313) is w_λ (OCR or misprint)",
                   certain=False)
READ_COMMA = Reading("4,49 − π = 1,35; 32,7P", "decimal commas: 4.49, 1.35, 32.7")


def beta1():
    return lam * (1 - 2 * sp.tan(u / 2) / u)


def a1():
    return lam / (u * sp.tan(u))


def windows():
    return sp.Tuple(2 * sp.Symbol("x_1"), 3 * sp.pi, sp.pi)


def x1_numbers():
    return sp.Tuple(sp.Rational(449, 100), sp.Rational(135, 100))


def weights():
    return sp.Tuple(sp.Rational(327, 10), 36, 4)


def v0():
    return lam / u * sp.tan(u / 2)


def w0():
    return -lam / (u * sp.sin(u))


def wl():
    return -lam / (u * sp.tan(u))


def G():
    return (1 / sp.sin(u) ** 2 + sp.cot(u) / u) / (2 * eps)


def C():
    return sp.Rational(3, 8) * (4 * u - sp.sin(4 * u)) / (sp.sin(u) ** 2 * (2 * u + sp.sin(2 * u)))


def dg():
    return beta_t + 2 * (2 * alpha_blade * (u + sp.sin(2 * u)) - alpha_rod * sp.sin(2 * u)) / (2 * u + sp.sin(2 * u))


def existence():
    """(304), (305): β1 < 0 and a + wλ < 0 (the quantities claimed negative)."""
    return sp.Tuple(beta_1, a + w_lambda)


def weight():
    return sp.pi**2 * E * e**3 * h / (48 * lam**2)


def shape():
    return theta / sp.sin(u) * (1 - sp.cos(omega * s))


def fatigue():
    """n°103: (280) with ch ωs → cos ωs, sh u → sin u, T → |T|."""
    return theta * sp.sqrt(3 * E * T) * sp.cos(omega * s) / sp.sin(u)


# ================================================================ n°100–102: (302), (303), (306), (308), (312)
def signs_302():
    """(302) K < 0, K' > 0, written as the quantities claimed negative, (K, −K')."""
    from ..symbols import K, K_prime
    return sp.Tuple(K, -K_prime)


def signs_303():
    """(303) a + z' − vλ < 0, a + z − vλ > 0, written (a + z' − vλ, −(a + z − vλ)) < 0."""
    from ..symbols import vl, z, zp
    return sp.Tuple(a + zp - vl, -(a + z - vl))


def sign_306():
    return w_lambda


def inequality_308():
    return sp.tan(u / 2) - u / 2


def distance_312():
    return eps * lam


READ_NU = Reading("ν_λ, ω_λ (303), (306)", "v_λ, w_λ: the OCR renders v, w as ν, ω")
