"""Haag 1935, chapter I, n°2–8: the first approximation for any M(s), derived step by step.

Small pure functions shared by the chapter I sections (ch1_blade, ch1_motion,
ch1_variations, ch1_launch) and by chapter III.  Each returns SymPy objects
derived from the memoir's governing equations (2)–(6) and the definitions
(9)–(14); nothing here is typed in from a result.  v, w are abstract functions
of s (any M(s) > 0); their end values are the symbols v0, vλ, w0, wλ of
:mod:`.symbols`.

Notation (:mod:`.symbols`): (β, θ) the end position of the blade (n°1), Y, N the
end loads (reaction mgY, couple mgN), β'' and θ'' the accelerations, z = GF the
abscissa of a focus on the rod measured from G (n°7), n² its angular frequency
squared.
"""
from __future__ import annotations

import functools

import sympy as sp

from .symbols import (M_of_s, N, R, X, Y, a, beta, beta1, beta_ddot, epsilon, g, lam, n_squared, s, theta,
                      theta_ddot, theta_dot, v, v0, vl, w, w0, wl, z, zp)

END_VALUES = {v(0): v0, v(lam): vl, w(0): w0, w(lam): wl}


def ends(expr: sp.Expr) -> sp.Expr:
    """Replace v(0), v(λ), w(0), w(λ) by the symbols v0, vλ, w0, wλ."""
    return expr.subs(END_VALUES)


# ---------------------------------------------------------------- n°3: (15), (16)
@functools.lru_cache(maxsize=1)
def wronskian_derivative() -> sp.Expr:
    """d/ds(v w' − w v') with v'' = v/M, w'' = w/M (9): identically 0 (n°3, before (15))."""
    expr = sp.diff(v(s) * w(s).diff(s) - w(s) * v(s).diff(s), s)
    return sp.simplify(expr.subs({v(s).diff(s, 2): v(s) / M_of_s(s), w(s).diff(s, 2): w(s) / M_of_s(s)}))


def wronskian_constant() -> sp.Expr:
    """v w' − w v' at s = 0 with v'_0 = −1, w'_0 = 0 (10): the constant of (15)."""
    return ends(v(0) * 0 - w(0) * (-1))


def wronskian_at_lambda() -> sp.Expr:
    """v w' − w v' at s = λ with v'_λ = −1, w'_λ = 1 (10): vλ + wλ, equal to w0 by (15) — this is (16)."""
    return ends(v(lam) * 1 - w(lam) * (-1))


# ---------------------------------------------------------------- n°5: (21)–(24)
@functools.lru_cache(maxsize=1)
def beta_integral() -> sp.Expr:
    """β = ∫_0^λ φ ds with φ = Yφ1 + θφ2 (13), φ1 = 1 + v', φ2 = w' (11): (21) with (22) unreduced."""
    phi = Y * (1 + v(s).diff(s)) + theta * w(s).diff(s)
    return sp.expand(ends(sp.integrate(phi, (s, 0, lam))))


def beta1_def() -> sp.Expr:
    """β1 = coefficient of Y in (21): λ + vλ − v0 (22)."""
    return beta_integral().coeff(Y)


def beta2_def() -> sp.Expr:
    """β2 = coefficient of θ in (21), reduced by (16) (w0 = vλ + wλ): −vλ (22)."""
    return sp.expand(beta_integral().coeff(theta).subs(w0, wronskian_at_lambda()))


@functools.lru_cache(maxsize=1)
def Y_of_end() -> sp.Expr:
    """Y from β = Yβ1 + θβ2 (21), β2 = −vλ (22): (23)."""
    return sp.solve(sp.Eq(beta, Y * beta1 + theta * beta2_def()), Y)[0]


@functools.lru_cache(maxsize=1)
def N_of_end() -> sp.Expr:
    """N = M_λ φ'_λ = Y vλ + θ wλ ((2) at s = λ with (14)), Y by (23): (24)."""
    phi_p = (Y * v(lam) + theta * w(lam)) / M_of_s(lam)              # (14) at s = λ
    return sp.expand(ends(M_of_s(lam) * phi_p).subs(Y, Y_of_end()))


# ---------------------------------------------------------------- n°6: (25)–(26)
def newton_euler() -> tuple[sp.Expr, sp.Expr]:
    """(5) and (6) written as expression = 0, with α'' = 0 (α = λ to the second order)."""
    e5 = beta_ddot - a * theta_dot**2 * sp.sin(theta) + a * theta_ddot * sp.cos(theta) + g * Y
    e6 = R**2 / g * theta_ddot + N - a * (Y * sp.cos(theta) - X * sp.sin(theta))
    return e5, e6


def linearized(expr: sp.Expr, extra: tuple = ()) -> sp.Expr:
    """First-order part in ε of expr with θ, θ', θ'', β'', Y, N (and the ``extra`` quantities) of
    order ε and X = 1 + O(ε²) (n°2)."""
    small = {x: epsilon * x for x in (theta, theta_dot, theta_ddot, beta_ddot, Y, N, *extra)}
    small[X] = 1 + epsilon**2 * X
    return sp.expand(sp.series(expr.subs(small, simultaneous=True), epsilon, 0, 2).removeO().coeff(epsilon))


@functools.lru_cache(maxsize=1)
def motion() -> tuple[sp.Expr, sp.Expr]:
    """(β'' + aθ'', R²θ'') as functions of β, θ: (5), (6) linearised, Y by (23), N by (24) → (25), (26)."""
    e5, e6 = (linearized(e) for e in newton_euler())
    loads = {Y: Y_of_end(), N: N_of_end()}
    acc = sp.solve([e5, e6], [beta_ddot, theta_ddot], dict=True)[0]
    lhs25 = sp.simplify((acc[beta_ddot] + a * acc[theta_ddot]).subs(loads))
    lhs26 = sp.simplify((R**2 * acc[theta_ddot]).subs(loads))
    return lhs25, lhs26


# ---------------------------------------------------------------- n°7: (27)–(33)
@functools.lru_cache(maxsize=1)
def focal_conditions() -> tuple[sp.Expr, sp.Expr]:
    """y = β + (a + z)θ (27) and y'' = −n²y for all β, θ: the coefficients of β and θ → (28), (29).

    Returned as the two expressions that must vanish, divided so that they read
    (n²/g)β1 − [1 − z(a − vλ)/R²] and (n²/g)(a + z)β1 − [−β2 + z(…)/R²].
    """
    r25, r26 = motion()
    theta_acc = r26 / R**2
    beta_acc = r25 - a * theta_acc
    y_acc = beta_acc + (a + z) * theta_acc                         # y'' of (27)
    resid = sp.expand(y_acc + n_squared * (beta + (a + z) * theta))
    c_beta = sp.expand(resid.coeff(beta) * beta1 / g)
    c_theta = sp.expand(-resid.coeff(theta) * beta1 / g)
    return c_beta, c_theta


@functools.lru_cache(maxsize=1)
def foci_quadratic() -> sp.Poly:
    """Eliminate n² between (28) and (29): the monic quadratic in z of (30)."""
    c28, c29 = focal_conditions()
    n_squared_of_z = sp.solve(c28, n_squared)[0]
    num = sp.numer(sp.together(c29.subs(n_squared, n_squared_of_z)))
    return sp.Poly(sp.expand(num), z).monic()


@functools.lru_cache(maxsize=1)
def vieta() -> tuple[sp.Expr, sp.Expr]:
    """(z z', z + z') of the two roots of (30): (31), (32)."""
    c = foci_quadratic().all_coeffs()
    return sp.simplify(c[2]), sp.simplify(-c[1])


@functools.lru_cache(maxsize=1)
def n2_of_focus() -> sp.Expr:
    """n² from (28) with z = −R²/z' (31): the form −Kg/z' of (34) with K unreduced."""
    c28, _ = focal_conditions()
    return sp.simplify(sp.solve(c28, n_squared)[0].subs(z, -R**2 / zp))


@functools.lru_cache(maxsize=1)
def K_of_zp() -> sp.Expr:
    """K defined by n² = −Kg/z' (34): K = −n² z'/g → (35)."""
    return sp.simplify(-n2_of_focus() * zp / g)


@functools.lru_cache(maxsize=1)
def product_shifted() -> sp.Expr:
    """(a + z − vλ)(a + z' − vλ) expanded with the Vieta relations (31), (32): (33)."""
    prod, total = vieta()
    z1, z2 = sp.symbols("z_1 z_2")
    expr = sp.expand((a + z1 - vl) * (a + z2 - vl))
    expr = expr.subs(z1 * z2, prod)
    expr = sp.expand(expr).subs(z1, total - z2)
    return sp.factor(sp.expand(expr))


@functools.lru_cache(maxsize=1)
def K_of_z() -> sp.Expr:
    """K of (35) rewritten by (33): (36)."""
    k35 = K_of_zp()
    # a + z' − vλ = (33)/(a + z − vλ)
    return sp.simplify(k35.subs(zp, vl - a + product_shifted() / (a + z - vl)))
