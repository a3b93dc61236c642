"""Rational forms for the uniform blade: the memoir's way of writing its results.

Haag writes every closed form of chapter III with U = th(u/2), U1 = 1/sh u,
U2 = 1/th u (160) and, along the blade, in the basis ch(jωs), sh(jωs).  Since
e^u = (1 + t)/(1 − t) with t = th(u/2), every exponential of a multiple of u is
rational in t: the functions here rewrite the derived expressions so, which
makes the comparison with the printed forms a cancellation, and integrate the
products of exponentials and powers that the definitions (79) of chapter I
give for a constant M.
"""
from __future__ import annotations

import functools

import sympy as sp
from sympy.functions.elementary.hyperbolic import HyperbolicFunction

from ..symbols import K, lam, s, u

TANH_HALF = sp.tanh(u / 2)                               # U of (160)
exp_half = sp.Symbol("Q", positive=True)                 # e^{u/2}
tanh_half = sp.Symbol("T_h", positive=True)              # th(u/2), as a symbol
reduced_abscissa = sp.Symbol("t", positive=True)         # ωs = us/λ, the variable of integration


def hyperbolic_to_exp(expr: sp.Expr) -> sp.Expr:
    """Hyperbolic functions rewritten as exponentials (powers are left alone)."""
    return expr.replace(lambda x: isinstance(x, HyperbolicFunction), lambda x: x.rewrite(sp.exp))


def in_tanh_half(expr: sp.Expr) -> sp.Expr:
    """expr (exponentials or hyperbolic functions of multiples of u) as a rational function of th(u/2).

    e^u = (1 + t)/(1 − t) with t = th(u/2): sh u, ch u, th u are rational in t.
    The result is written in the symbol :data:`tanh_half`.
    """
    ex = hyperbolic_to_exp(expr)
    ex = ex.replace(lambda x: isinstance(x, sp.exp) and sp.simplify(x.args[0] / u).is_number,
                    lambda x: exp_half ** (2 * sp.simplify(x.args[0] / u)))
    if ex.has(u) and any(a.has(u) for a in ex.atoms(sp.exp)):
        raise ValueError(f"exponentials not proportional to u: {[x for x in ex.atoms(sp.exp) if x.has(u)]}")
    numerator, denominator = sp.fraction(sp.cancel(sp.together(ex)))
    exp_u = sp.Symbol("P_q", positive=True)           # e^u = Q²
    parts = []
    for part in (numerator, denominator):
        try:
            poly = sp.Poly(part, exp_half)
        except sp.PolynomialError:
            poly = None
        if poly is None or any(m[0] % 2 for m in poly.monoms()):
            return sp.cancel(sp.together(ex).subs(exp_half, sp.sqrt((1 + tanh_half) / (1 - tanh_half))))
        parts.append(sum(cf * exp_u ** (m[0] // 2) for m, cf in poly.terms()))
    exp_u_in_tanh = (1 + tanh_half) / (1 - tanh_half)
    return sp.cancel(sp.together(parts[0].subs(exp_u, exp_u_in_tanh)) /
                     sp.together(parts[1].subs(exp_u, exp_u_in_tanh)))


def with_tanh_half_symbol(expr: sp.Expr) -> sp.Expr:
    """expr rational in th(u/2) (the symbol :data:`tanh_half`), not cancelled: th(u/2) replaced by the
    symbol when it is expr's only function of u (expr is then rational in it as it stands), else
    :func:`in_tanh_half`.  Substituting into the uncancelled form and cancelling once is much cheaper
    than cancelling the substitution into :func:`in_tanh_half`'s expanded form, and gives the same
    rational function (the recurrences (164), (167))."""
    functions_of_u = {f for f in expr.atoms(sp.Function) if f.has(u)}
    if functions_of_u <= {TANH_HALF} and not any(p.exp.has(u) for p in expr.atoms(sp.Pow)):
        return expr.subs(TANH_HALF, tanh_half)
    return in_tanh_half(expr)


def from_tanh_half(expr: sp.Expr) -> sp.Expr:
    """A rational function of :data:`tanh_half`, factored and written back with th(u/2)."""
    return sp.factor(expr).subs(tanh_half, TANH_HALF)


def tanh_half_form(expr: sp.Expr) -> sp.Expr:
    """expr rewritten rational in th(u/2) and factored: the form the comparisons start from."""
    return from_tanh_half(in_tanh_half(expr))


def polynomial_in_K(expr: sp.Expr) -> sp.Expr:
    """expr as a polynomial in K, each coefficient rational in th(u/2) (written with tanh)."""
    ex = in_tanh_half(expr)
    numerator, denominator = sp.fraction(sp.cancel(ex))
    poly = sp.Poly(sp.expand(numerator), K)
    return sum(from_tanh_half(sp.cancel(cf / denominator)) * K**m[0] for m, cf in poly.terms())


def in_hyperbolic_basis(expr: sp.Expr) -> sp.Expr:
    """expr (exponentials of multiples of ωs = us/λ and of u, powers of s) in the basis ch(jωs), sh(jωs),
    with coefficients rational in th(u/2): the memoir's way of writing functions of s."""
    power = sp.Symbol("Z_s", positive=True)     # e^{ωs}
    omega_s = sp.Symbol("w_s", positive=True)   # ωs

    def split(x):
        exponent = sp.expand(x.args[0])
        alpha = sp.expand(exponent.coeff(s) * lam / u)
        beta = sp.expand(exponent - exponent.coeff(s) * s)
        if beta.has(s) or not alpha.is_integer:
            raise ValueError(f"exponent not linear in ωs: {exponent}")
        return power**alpha * sp.exp(beta)
    in_powers = hyperbolic_to_exp(expr).replace(lambda x: isinstance(x, sp.exp) and x.has(s), split)
    in_powers = in_powers.subs(s, lam * omega_s / u)
    numerator, denominator = sp.fraction(sp.cancel(sp.together(in_powers)))
    den_poly = sp.Poly(denominator, power)
    if len(den_poly.terms()) != 1:
        raise ValueError("denominator depends on s")
    (den_power,), den_coeff = den_poly.terms()[0]
    coeffs: dict[int, sp.Expr] = {}
    for (j,), cf in sp.Poly(sp.expand(numerator), power).terms():
        coeffs[j - den_power] = coeffs.get(j - den_power, 0) + cf / den_coeff
    out = sp.S.Zero
    for j in sorted({abs(j) for j in coeffs}):
        plus, minus = coeffs.get(j, 0), coeffs.get(-j, 0)
        if j == 0:
            out += _polynomial_in_omega_s(plus, omega_s)
            continue
        out += (_polynomial_in_omega_s(plus + minus, omega_s) * sp.cosh(j * omega_s)
                + _polynomial_in_omega_s(plus - minus, omega_s) * sp.sinh(j * omega_s))
    return out.subs(omega_s, u * s / lam)


def _polynomial_in_omega_s(coefficient, omega_s):
    """A coefficient: polynomial in ωs with coefficients rational in th(u/2)."""
    poly = sp.Poly(sp.expand(coefficient), omega_s)
    return sum(tanh_half_form(c) * omega_s**m for (m,), c in poly.terms())


# ---------------------------------------------------------------- integration along the blade
@functools.lru_cache(maxsize=None)
def _basic_integral(m: int, alpha: sp.Expr, upper: sp.Expr) -> sp.Expr:
    """∫_0^upper t^m e^{αt} dt (α a number)."""
    t = reduced_abscissa
    return sp.integrate(t**m * sp.exp(alpha * t), (t, 0, upper))


def integrate_exp_poly(f: sp.Expr, upper: sp.Expr) -> sp.Expr:
    """∫_0^upper f dt (t = :data:`reduced_abscissa`) for f a sum of c·t^m·e^{αt + β}, α an integer:
    term by term.

    Every e^{αt + β} is written Z^α e^β with a symbol Z; f must then be a
    polynomial in t, Z, 1/Z whose coefficients are free of t.
    """
    t = reduced_abscissa
    power = sp.Symbol("Z_t", positive=True)

    def split(x):
        exponent = sp.expand(x.args[0])
        alpha = exponent.coeff(t)
        beta = sp.expand(exponent - alpha * t)
        if beta.has(t) or not alpha.is_integer:
            raise ValueError(f"exponent not linear in t: {exponent}")
        return power**alpha * sp.exp(beta)
    in_powers = sp.expand(f).replace(lambda x: isinstance(x, sp.exp) and x.has(t), split)
    numerator, denominator = sp.fraction(sp.cancel(sp.together(in_powers)))
    den_poly = sp.Poly(denominator, power, t)
    if len(den_poly.terms()) != 1:
        raise ValueError(f"denominator depends on t: {denominator}")
    (den_power, den_t), den_coeff = den_poly.terms()[0]
    if den_t:
        raise ValueError("t in the denominator")
    total = sp.S.Zero
    for (jz, jt), cf in sp.Poly(sp.expand(numerator), power, t).terms():
        total += cf / den_coeff * _basic_integral(int(jt), sp.Integer(jz - den_power), upper)
    return total


def integrate_along_blade(expr_s: sp.Expr, upper: sp.Expr | None = None) -> sp.Expr:
    """∫_0^{upper or λ} expr ds for an expression in e^{±us/λ} and s (substitution s = λt/u).

    Only the hyperbolic functions of s are rewritten as exponentials: those of u alone (th(u/2) in the
    coefficients of (183)) stay whole, which keeps the cancellation small (the value is the same)."""
    of_s = expr_s.replace(lambda x: isinstance(x, HyperbolicFunction) and x.has(s), lambda x: x.rewrite(sp.exp))
    f = of_s.subs(s, lam * reduced_abscissa / u)
    top = u if upper is None else sp.expand(u * upper / lam)
    return integrate_exp_poly(f, top) * lam / u
