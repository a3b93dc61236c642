"""Haag 1935, chapter II, n°26–30: the formulas (88)–(114) as printed, with their OCR readings.

The OCR of this chapter is rough: z' comes out as ε', ε1 as ε4, H2 as H4, ε as s, g/z' as σ'/σ'.  Each
reading is recorded; where two readings are possible it is marked uncertain.  The blade integrals are
written in moments (:mod:`..ch2_common`), as the derivation holds them: H_n by (103).
"""
from __future__ import annotations

import sympy as sp

from pendsym.result import Reading
from ..ch2_common import (F_110, H_moments, Q, Qp, Y_ddot, Y_dot, alpha_ddot, dN, dX, dY, eps1, eps2, eps3,
                          eps_bar, eps_blade, eps_lambda, theta0)
from ..symbols import (K, M_of_s, N, X, Y, a, beta1, g, lam, n_squared, s, theta, theta_ddot, theta_dot, v,
                       v0, varphi1, varphi2, vl, w, w0, z, zp)
from ..symbols import Fn

READ_ZP = Reading("ε' (in ε2ε' of (104) and the line before)", "z' (the OCR renders z' as ε')")
READ_EPS1_AS_4 = Reading("ε4 (in ½ε4(K∂H2/∂Y + ∂H2/∂θ))", "ε1 (ε_bar = φε1 + ε' gives ε1∫φ(Kφ1 + φ2) ds)")
READ_EPS_PRIME = Reading("ε'_4 (in ∫ε'_4(Kφ1 + φ2) ds), ε4 in (106)",
                         "ε' = dε/ds, the increment of d(Mφ')/ds (the derivative of the moment increment mgε)",
                         certain=False)
READ_EPS_LAMBDA = Reading("ε_{iλ}", "ε_λ, the increment of the couple at A (ε at s = λ)", certain=False)
READ_94 = Reading("ε = φε1 + ε'_1, ε'_1 = dε1/ds (94)",
                  "ε_bar = φε1 + ε', ε' = dε/ds: the right side of (93), with ε the moment increment of n°26",
                  certain=False)
READ_H4 = Reading("½ε4(K∂H4/∂Y + ∂H4/∂θ) in (109)", "½ε1(K∂H2/∂Y + ∂H2/∂θ), as in (104)")
READ_107 = Reading("(Y'∂H2/∂Y + θ'∂H2/∂θ)²", "the operator (Y'∂/∂Y + θ'∂/∂θ) applied twice to H2 (a symbolic square)",
                   certain=False)
READ_108 = Reading("∫ε'_4(Kφ1 + φ1) ds and (1/24)(K∂H/∂Y + ∂H/∂θ) in the line before (108)",
                   "∫ε'(Kφ1 + φ2) ds (φ1 for φ2 is a misprint or a misreading)", certain=False)
READ_101 = Reading("∫_0^λ s ds in the line before (101)", "∫_0^λ ε ds (the OCR renders ε as s)")
READ_SIGMA = Reading("σ'/σ' (first line of n°28)", "g/z'", certain=False)


# ---------------------------------------------------------------- n°26
def eq88():
    return 1 - X + eps1


def eq89():
    return g * (-Y + eps2)


def eq90():
    return g * (-N + a * Y - a * theta * X + eps3)


def eq91():
    return g * (-dY + eps2 + (dN - a * dY + a * theta * dX - eps3) / zp)


# ---------------------------------------------------------------- n°27
def eq92():
    return eps1


def eq93():
    """(93): the right side of d(Mx')/ds − x = ε − ΔY (ε of (94), here ε_bar)."""
    return eps_bar - dY


def eq94():
    return sp.Symbol("varphi", real=True) * eps1 + eps_blade


def eq101():
    """(101) solved for ΔY: β1ΔY = ∫ε_barφ1 ds (I_1)."""
    return sp.Symbol("I_1") / beta1


def eq102():
    return sp.Symbol("I_2") + vl * dY - eps_lambda


def eq103():
    n = sp.Symbol("n", integer=True, positive=True)
    return sp.Integral((Y * varphi1(s) + theta * varphi2(s)) ** n, (s, 0, lam))


# ---------------------------------------------------------------- n°28
def _euler(expr):
    return K * sp.diff(expr, Y) + sp.diff(expr, theta)


def eq104():
    """(104): the bracket of f = −(n²/K)[…], ∫ε'φ1, ∫ε'φ2 kept as E_1, E_2."""
    E1, E2 = sp.symbols("E_1 E_2")
    return (eps2 * zp + a * theta * eps1 - eps3 + eps1 / 2 * _euler(H_moments(2)) + (K * E1 + E2) - eps_lambda)


def eq105():
    """(105): −∫ε(Kv + w)/M ds for the last two terms of (104) (ε the moment increment, ε(s))."""
    eps_f = sp.Function("epsilon")
    return -sp.Integral(eps_f(s) * (K * v(s) + w(s)) / M_of_s(s), (s, 0, lam))


# ---------------------------------------------------------------- n°29
def eq106():
    ph = sp.Symbol("varphi", real=True)
    return sp.Tuple(a * (theta * theta_ddot + theta_dot**2) - alpha_ddot,
                    a * (theta * theta_dot**2 + theta**2 * theta_ddot / 2),
                    a * theta**2 / 6 * (theta - 3 * Y),
                    ph**2 / 6 * (3 * Y - ph))


def alpha_H2():
    return lam - H_moments(2) / 2


def eq107():
    H2 = H_moments(2)
    first = Y_ddot * sp.diff(H2, Y) + theta_ddot * sp.diff(H2, theta)
    second = (Y_dot**2 * sp.diff(H2, Y, 2) + 2 * Y_dot * theta_dot * sp.diff(H2, Y, theta)
              + theta_dot**2 * sp.diff(H2, theta, 2))
    return sp.expand(first + second)


def eq108():
    """(108): H = 4YH3 − H4, in moments."""
    return 4 * Y * H_moments(3) - H_moments(4)


def identity_108():
    """The claim before (108): (K/6)H3 + ∫ε'(Kφ1 + φ2) ds − (1/24)(K∂H/∂Y + ∂H/∂θ) = 0."""
    return sp.S.Zero


def eq109():
    """(109): the bracket of f = −(n²/K)[…]."""
    return (a / (2 * g) * (2 * a + zp) * theta**2 * theta_ddot + a / g * (a + zp) * theta * theta_dot**2
            - a / g * theta * alpha_ddot + eps1 / 2 * _euler(H_moments(2)) + a * theta**2 / 6 * (3 * Y - theta)
            + _euler(eq108()) / 24)


def euler_H2():
    return 2 * theta * Fn(2)


def euler_H():
    return 4 * theta**3 * F_110


def eq110():
    return 4 * K * Fn(3) - Fn(4)


def eq111():
    return Qp / Q * theta0**2 / 16


def eq112():
    return a * (1 - 4 * K) - 4 * K / zp * (a + Fn(2)) ** 2 - F_110


def eq114_relative():
    """(114) ΔT = (1/(n³θ0))∫F cos φ dφ, divided by T = 2π/n; C = ∫F cos φ dφ."""
    n = sp.sqrt(n_squared)
    return sp.Symbol("C") / (n**3 * theta0) * n / (2 * sp.pi)


DEFS_111 = ((Qp, eq112().subs(F_110, eq110())), (Q, K * (z - zp)))     # applied at once (simultaneous)
DEFS_112 = ((F_110, eq110()),)
DEF_EPS1 = ((eps1, eq106()[0] / g),)


# ---------------------------------------------------------------- n°27: (95)–(100), Haag's variation of constants
READ_98_W = Reading("A = −(1/w0)∫ε'w' ds = ε0 − εw'/w0 + … in (98) (ω for w)",
                    "A = −(1/w0)∫ε'w ds = ε0 − εw/w0 + (1/w0)∫εφ2 ds: the variation of constants of y'' − y/M = ε' "
                    "gives A' = −ε'w/w0 (the primes on w are the OCR's)", certain=False)
READ_97_Y = Reading("y = Mx' (n°27)", "a new function y(s), not the ordinate y(s) of the blade (3)")


def _variation():
    from . import variation          # (kept local: variation.py is the derivation of these steps)
    return variation


def eq95():
    vr = _variation()
    return vr.y_f(s).diff(s) - vr.eps_f(s) + dY


def eq96():
    return M_of_s(s) * _variation().eps_f(s).diff(s)


def eq98_integrals():
    vr = _variation()
    sg, ef = vr.sigma, vr.eps_f
    return sp.Tuple(-1 / w0 * sp.Integral(ef(sg).diff(sg) * w(sg), (sg, 0, s)),
                    1 / w0 * sp.Integral(ef(sg).diff(sg) * v(sg), (sg, 0, s)))


def eq98():
    vr = _variation()
    sg, ef = vr.sigma, vr.eps_f
    return sp.Tuple(vr.eps0 - ef(s) * w(s) / w0 + 1 / w0 * sp.Integral(ef(sg) * varphi2(sg), (sg, 0, s)),
                    -vr.eps0 * v0 / w0 + ef(s) * v(s) / w0 + 1 / w0 * sp.Integral(ef(sg) * (1 - varphi1(sg)), (sg, 0, s)))


def eq97():
    vr = _variation()
    A, B = eq98_integrals()
    return A * v(s) + B * w(s) + vr.C * v(s) + vr.Cp * w(s)


def eq99():
    return dY - _variation().eps0


def eq100():
    vr = _variation()
    return -vr.A_l + vr.B_l - vr.C + vr.Cp


# ---------------------------------------------------------------- n°30: (113), (115)
READ_115_EPS = Reading("β = (1 + ε)^p(1 + ε')^q − 1 (n°30)",
                       "ε' defined by θ' = θ1'(1 + ε'), not dε/dt", certain=False)


def eq113():
    vr = _variation()
    return theta0 * sp.cos(vr.phi) * (1 + vr.eps_30)


def eq115():
    vr = _variation()
    n = sp.sqrt(n_squared)
    integrand = vr.A_30 * vr.theta1_30**vr.p_30 * vr.theta1p_30**vr.q_30 * (1 + vr.beta_30 + vr.alpha_30)
    return sp.Integral(integrand * sp.cos(vr.phi), (vr.phi, 0, 2 * sp.pi)) / (n**3 * theta0)


def beta_30():
    vr = _variation()
    return vr.p_30 * vr.eps_30 + vr.q_30 * vr.eps_30p
