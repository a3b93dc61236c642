"""Haag 1935, chapter IX, n°107–110: the rhombus blade for a small hole, w and G_2 as series in k.

Not in the memoir: a form for k → 0, where the Bessel form (343)–(346) subtracts large, nearly equal terms
(x_0, x_1 ~ 2ω/k; G_2 cancels terms of order 1/k), so that in double precision it loses about log10(1/k)
digits.  Here (9) for the inverted blade, (1 + k|s|) f'' + ω²f = 0 on −λ/2 ≤ s ≤ λ/2 (M0 = 1/ω², footnote
(2) of n°107), is expanded as f = Σ k^n f_n: f_0'' + ω²f_0 = 0 with the conditions of n°4, and
f_n'' + ω²f_n = −|s| f_{n−1}'' with f_n'(±λ/2) = 0, each half solved by ``dsolve`` and joined at s = 0
(f, f' continuous).  G_2 = ω² ∫ w²/(1 + k|s|) ds is expanded in the same powers and integrated by SymPy.
"""
from __future__ import annotations

import functools

import sympy as sp

from ..symbols import lam, omega
from .rhombus_derivation import k

sigma = sp.Symbol("s", real=True)
f = sp.Function("f")


def _half(rhs: sp.Expr, tag: str) -> sp.Expr:
    """The general solution of f'' + ω²f = rhs on one half, its constants named C_tag1, C_tag2.  The factors of
    rhs free of s stand as symbols while ``dsolve`` runs (it is fast on σ^i·cos, σ^i·sin with plain factors)."""
    groups: dict = {}
    for term in sp.Add.make_args(sp.expand(rhs)):
        factor, shape = term.as_independent(sigma, as_Add=False)
        groups[shape] = groups.get(shape, 0) + factor
    stand = {shape: sp.Symbol(f"q_{tag}_{i}") for i, shape in enumerate(groups)}
    generic = sum((stand[shape] * shape for shape in groups), sp.Integer(0))
    sol = sp.dsolve(f(sigma).diff(sigma, 2) + omega**2 * f(sigma) - generic, f(sigma)).rhs
    C1, C2 = sorted(sol.free_symbols - {sigma, omega, lam} - set(stand.values()), key=lambda c: c.name)
    sol = sol.subs({stand[shape]: value for shape, value in groups.items()})
    return sol.subs({C1: sp.Symbol(f"C_{tag}1"), C2: sp.Symbol(f"C_{tag}2")})


@functools.lru_cache(maxsize=None)
def terms(top: int, bottom: int, order: int) -> tuple:
    """((f_n on s < 0, f_n on s > 0) for n = 0 … order) for the conditions f'(−λ/2) = top, f'(λ/2) = bottom."""
    out = []
    for n in range(order + 1):
        if n == 0:
            rhs_left = rhs_right = sp.Integer(0)
            slopes = (top, bottom)
        else:
            left_prev, right_prev = out[-1]
            rhs_left = sigma * left_prev.diff(sigma, 2)            # −|s| f'' with |s| = −s
            rhs_right = -sigma * right_prev.diff(sigma, 2)
            slopes = (0, 0)
        left, right = _half(rhs_left, f"L{n}"), _half(rhs_right, f"R{n}")
        unknowns = sorted((left.free_symbols | right.free_symbols) - {sigma, omega, lam}, key=lambda c: c.name)
        eqs = [left.diff(sigma).subs(sigma, -lam / 2) - slopes[0], right.diff(sigma).subs(sigma, lam / 2) - slopes[1],
               (left - right).subs(sigma, 0), (left - right).diff(sigma).subs(sigma, 0)]
        sol = sp.solve(eqs, unknowns, dict=True)[0]
        out.append((left.subs(sol), right.subs(sol)))
    return tuple(out)


def end_series(name: str, order: int = 1) -> sp.Expr:
    """v_0, w_0 (at s = −λ/2) or w_λ (at s = λ/2) to O(k^{order+1})."""
    top, bottom = (-1, -1) if name == "v0" else (0, 1)
    at_left = name in ("v0", "w0")
    return (sum(k**n * (pair[0].subs(sigma, -lam / 2) if at_left else pair[1].subs(sigma, lam / 2))
                           for n, pair in enumerate(terms(top, bottom, order))))


def G2_series(order: int = 1) -> sp.Expr:
    """G_2 = ω² ∫ w²/(1 + k|s|) ds to O(k^{order+1}), each coefficient integrated by SymPy."""
    pairs = terms(0, 1, order)
    left = sum(k**n * p[0] for n, p in enumerate(pairs))
    right = sum(k**n * p[1] for n, p in enumerate(pairs))
    weight_left = sum((k * sigma) ** j for j in range(order + 1))          # 1/(1 − ks), s < 0
    weight_right = sum((-k * sigma) ** j for j in range(order + 1))        # 1/(1 + ks), s > 0
    total = sp.Integer(0)
    for half, weight, lo, hi in ((left, weight_left, -lam / 2, 0), (right, weight_right, 0, lam / 2)):
        integrand = sp.expand(half**2 * weight)
        for n in range(order + 1):
            coeff = integrand.coeff(k, n)
            total += k**n * sp.integrate(sp.expand(sp.expand_trig(coeff)), (sigma, lo, hi))
    return one_form(omega**2 * total)


def one_form(expr: sp.Expr) -> sp.Expr:
    """The one form of a rational function of ω, λ, k, sin(λω/2), cos(λω/2) (for the G_2 of n°110 in k).

    The form ``integrate`` returns follows the state SymPy's caches were left in by what the process
    computed before (a derive that finds other Results in its cache builds this one in another state),
    so the form is fixed here from the value alone: over the fixed denominator (sin·cos·ω)^8,
    the numerator reduced by cos² = 1 − sin² is unique; the common powers of sin and ω are cancelled."""
    half = lam * omega / 2
    sin_h, cos_h = sp.Dummy("sin_h"), sp.Dummy("cos_h")
    numerator, denominator = sp.fraction(sp.together(expr.subs({sp.sin(half): sin_h, sp.cos(half): cos_h})))
    fixed = (sin_h * cos_h * omega) ** 8
    over = sp.cancel(fixed / denominator)
    if not over.is_polynomial(sin_h, cos_h, omega):
        raise ValueError(f"not over a power of sin·cos·ω: {denominator}")
    reduced = sp.rem(sp.expand(numerator * over), cos_h**2 + sin_h**2 - 1, cos_h)
    (p_sin, p_omega), reduced = sp.Poly(reduced, sin_h, omega).terms_gcd()
    form = sp.collect(sp.expand(reduced.as_expr()), k) / (sin_h ** (8 - p_sin) * cos_h**8 * omega ** (8 - p_omega))
    return form.subs({sin_h: sp.sin(half), cos_h: sp.cos(half)})
