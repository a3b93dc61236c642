"""Haag 1935, chapter I, n°5–9, eqs. (21)–(41): end loads, equations of motion, foci, periods, existence.

Pure SymPy.  The steps (21)–(36) are derived once in :mod:`..ch1_model` (shared with
the later sections and chapter III); here are the forms this section states beside
them: the unreduced β2 of (22), the couple of (24) from (14), the sum relation (32),
KK' (37), the quantities that n°9 claims positive, and the critical distance (41).
"""
from __future__ import annotations

import sympy as sp

from ..ch1_blade.derivation import phi_prime
# the steps of n°5–8 (Results of this section) are derived in ch1_model
from ..ch1_model import (K_of_z, K_of_zp, N_of_end, Y_of_end, beta1_def, beta2_def, beta_integral, ends,  # noqa: F401
                         foci_quadratic, focal_conditions, motion, n2_of_focus, product_shifted, vieta,
                         wronskian_at_lambda)
from ..symbols import M_of_s, a, beta, beta1, lam, s, theta, vl, z, zp


# ================================================================ n°5: (21)–(24)
def beta2_unreduced() -> sp.Expr:
    """(22): β2 = coefficient of θ in (21), before (16) reduces it."""
    return beta_integral().coeff(theta)


def end_couple() -> sp.Expr:
    """(24): N = M_λ φ'_λ with φ' of (14)."""
    return ends(M_of_s(lam) * phi_prime().subs(s, lam))


# ================================================================ n°6: (25)–(26)
def motion_25() -> sp.Expr:
    """(25): β'' + aθ'', (5) and (6) linearised with Y by (23), N by (24)."""
    return motion()[0]


def motion_26() -> sp.Expr:
    """(26): R²θ''."""
    return motion()[1]


# ================================================================ n°7: (27)–(33)
def focal_ordinate() -> sp.Expr:
    """(27): y = β + (a + z)θ, the ordinate of the point of the rod at GF = z."""
    return beta + (a + z) * theta


def focal_28() -> sp.Expr:
    """(28): the coefficient of β in y'' + n²y = 0."""
    return focal_conditions()[0]


def focal_29() -> sp.Expr:
    """(29): the coefficient of θ, written as (n²/g)(a + z)β1 + β2 − (z/R²)[…]."""
    return sp.expand(-focal_conditions()[1])


def quadratic_30() -> sp.Expr:
    """(30): n² eliminated between (28) and (29), monic in z."""
    return foci_quadratic().as_expr()


def product_31() -> sp.Expr:
    """(31): zz' from Vieta."""
    return vieta()[0]


def sum_relation() -> sp.Expr:
    """(32): (a − vλ)(z + z') + … = (a − vλ) times (z + z' − the Vieta sum of (30))."""
    return sp.expand(sp.cancel((a - vl) * (z + zp - vieta()[1])))


# ================================================================ n°8: (34)–(37)
def K_product() -> sp.Expr:
    """(37): KK' with K of (35) and K' by exchanging z and z'; the product of (33) substituted."""
    k35 = K_of_zp()
    kk = sp.factor(k35 * k35.subs(zp, z))
    assert sp.expand(kk * beta1**2 - (a + z - vl) * (a + zp - vl)) == 0
    return sp.cancel(product_shifted() / beta1**2)


# ================================================================ n°9: (38)–(41)
def upper_38() -> sp.Expr:
    """(38): −(a + z' − vλ) = β1K (35), positive with K > 0 and β1 > 0."""
    return sp.expand(K_of_zp() * beta1)


def lower_39() -> sp.Expr:
    """(39): a + z − vλ = −β1K' (K' of (35) with z' → z), positive with K' < 0."""
    return sp.expand(-K_of_zp().subs(zp, z) * beta1)


def a_plus_wl_40() -> sp.Expr:
    """(40): a + wλ = −(38)·(39)/β1 by (33)."""
    return sp.cancel(-product_shifted() / beta1)


def critical_distance() -> sp.Expr:
    """(41): a where the right side of (33) vanishes (K, K' change sign)."""
    return sp.solve(product_shifted(), a)[0]
