"""Haag 1935, chapter VI: the bookkeeping of the short blade (λ/a small), written once.

Every length of the blade (λ, v_0, v_λ, w_0, w_λ, β1, F_2, G_2 …) is of the order of λ and
M (a square of a length) of the order of λ²; a, R, b, L are of the order of a.  A
bookkeeping parameter δ multiplies each quantity by its order (δ for a length of the blade,
δ² for M); a series in δ, truncated and taken at δ = 1, is then the series in λ/a that
Haag writes "en négligeant λ²/a² devant l'unité".  Small pure functions returning SymPy
objects; nothing here knows a result of the chapter.
"""
from __future__ import annotations

import sympy as sp

from ..symbols import G_2, M_lambda, beta1, beta1_positive, lam, v0, vl, w0, wl

DELTA = sp.Symbol("delta", positive=True)     # order of λ/a (bookkeeping; set to 1 at the end)
l = sp.Symbol("l", positive=True)              # the length of the synchronous pendulum (213)
F_2 = sp.Symbol("F_2", real=True)              # F_2 of (79) for the principal oscillation (a length)

BLADE_LENGTHS = (lam, v0, vl, w0, wl, beta1, beta1_positive, G_2, F_2)
BLADE_SQUARES = (M_lambda,)


def scaled(expr: sp.Expr, extra: tuple = ()) -> sp.Expr:
    """expr with each blade quantity (and each of the ``extra`` lengths) multiplied by its order in δ
    (lengths δ, M δ²)."""
    table = {q: DELTA * q for q in BLADE_LENGTHS + tuple(extra)}
    table.update({q: DELTA**2 * q for q in BLADE_SQUARES})
    return sp.sympify(expr).subs(table, simultaneous=True)


def truncated(expr: sp.Expr, order: int = 1) -> sp.Expr:
    """The series of expr in λ/a up to (λ/a)^order included, at δ = 1 (expr itself unscaled)."""
    series = sp.series(scaled(expr), DELTA, 0, order + 1).removeO()
    return tidy(sp.expand(series).subs(DELTA, 1))


def tidy(expr: sp.Expr) -> sp.Expr:
    """expr collected on the blade's quantities, each coefficient factored (for reading; the same value)."""
    return sp.collect(sp.expand(expr), BLADE_LENGTHS + BLADE_SQUARES, sp.factor)


def leading(expr: sp.Expr, extra: tuple = ()) -> sp.Expr:
    """The leading term of expr in λ/a, at δ = 1: its power p of δ from SymPy's leading term, its
    coefficient as the limit of expr/δ^p as δ → 0 (exact)."""
    expr = scaled(expr, extra)
    _, power = expr.as_leading_term(DELTA).as_coeff_exponent(DELTA)
    coefficient = sp.limit(expr / DELTA**power, DELTA, 0)
    if coefficient == 0 or coefficient.has(sp.oo, -sp.oo, sp.zoo, sp.nan):
        raise ValueError(f"no leading term of order {power} for {expr}")
    return sp.factor(sp.simplify(coefficient))


def root_series(equation: sp.Expr, var: sp.Symbol, start: sp.Expr, order: int = 1, extra: tuple = ()) -> sp.Expr:
    """The root of equation = 0 in var that tends to ``start`` as λ/a → 0, to (λ/a)^order included:
    var = start + Σ δ^k c_k, the c_k solved order by order (each from a linear equation)."""
    numerator = sp.numer(sp.together(scaled(equation, extra)))
    coefficients = sp.symbols(f"c1:{order + 1}")
    trial = start + sum(DELTA ** (k + 1) * c for k, c in enumerate(coefficients))
    expansion = sp.expand(sp.series(numerator.subs(var, trial), DELTA, 0, order + 1).removeO())
    if sp.simplify(expansion.coeff(DELTA, 0)) != 0:
        raise ValueError(f"{start} is not a root of the equation at λ/a = 0")
    solved = {}
    for k, c in enumerate(coefficients, start=1):
        term = expansion.coeff(DELTA, k).subs(solved)
        solved[c] = sp.simplify(sp.solve(term, c)[0])
    return tidy(trial.subs(solved).subs(DELTA, 1))

