"""Equations of motion of the simple pendulum, derived, not transcribed.

The general equation (the perturbation memoir's n°2, formula (1)) for a pendulum of variable
length l(t) is   θ'' + (2/l)(dl/dt) θ' + (g/l) s(θ) = 0,   with s(θ) = sin θ,
or s(θ) = θ in the linearized form the memoir uses for its examples.  Writing
it as θ'' + k²θ + P = 0 with k² = g/l0 defines the perturbing term P, which is
expanded here to its lowest order in a small parameter.
"""
from __future__ import annotations

from typing import Mapping

import sympy as sp


def length_rate(l: sp.Expr, theta: sp.Symbol, dtheta: sp.Symbol, t: sp.Symbol, k: sp.Expr) -> sp.Expr:
    """dl/dt for l(θ, θ', t), with θ'' replaced by its leading value −k²θ.

    The replacement is exact to the first order kept in P, because dl/dt is
    itself of the order of the perturbation.
    """
    return sp.diff(l, t) + sp.diff(l, theta) * dtheta + sp.diff(l, dtheta) * (-k**2 * theta)


def perturbing_term(l: sp.Expr, theta: sp.Symbol, dtheta: sp.Symbol, t: sp.Symbol, k: sp.Expr,
                    l0: sp.Expr, restoring: sp.Expr | None = None) -> sp.Expr:
    """P = (2/l)(dl/dt)θ' + (g/l) s(θ) − k²θ with g = k² l0 (exact before any expansion)."""
    s = theta if restoring is None else restoring
    return 2 / l * length_rate(l, theta, dtheta, t, k) * dtheta + k**2 * l0 / l * s - k**2 * theta


def lowest_order(expr: sp.Expr, small: sp.Symbol, scale: Mapping[sp.Symbol, sp.Expr], order: int) -> sp.Expr:
    """Series of expr after ``scale`` (e.g. θ → δθ), truncated at small**order, then small → 1.

    With scale = {θ: δθ, θ': δθ'} and order 3 it keeps the cubic terms in the
    amplitude; with scale = {} and small = a it keeps the first order in a.
    """
    scaled = expr.subs(dict(scale), simultaneous=True)
    ser = sp.series(scaled, small, 0, order + 1).removeO()
    return sp.expand(sp.simplify(ser.subs(small, 1) if scale else ser))


def exact_rhs(l: sp.Expr, theta: sp.Symbol, dtheta: sp.Symbol, t: sp.Symbol, g: sp.Expr,
              params: tuple[sp.Symbol, ...], restoring: sp.Expr | None = None):
    """The governing model θ'' + (2/l)(dl/dt)θ' + (g/l)s(θ) = 0 as an mpmath right-hand side.

    dl/dt keeps θ'' exactly (l may depend on θ'), and the equation, linear in
    θ'', is solved for it symbolically.  No expansion is made: this is the
    model a truth integration uses.  Returns rhs(params)(t, [θ, θ']).
    """
    dd = sp.Symbol("thetaddot")
    s = sp.sin(theta) if restoring is None else restoring
    ldot = sp.diff(l, t) + sp.diff(l, theta) * dtheta + sp.diff(l, dtheta) * dd
    eq = dd + 2 / l * ldot * dtheta + g / l * s
    sol = sp.solve(eq, dd)
    if len(sol) != 1:
        raise ValueError("the equation of motion is not linear in theta''")
    acc = sp.lambdify((t, theta, dtheta) + tuple(params), sol[0], modules="mpmath")

    def bind(*values):
        return lambda tt, y: [y[1], acc(tt, y[0], y[1], *values)]
    return bind
