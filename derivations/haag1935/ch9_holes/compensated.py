"""Compensated arithmetic written as SymPy forms, for the supplied kernels of chapter IX (issue #14).

A value is a pair :class:`Pair` (hi, lo): hi a double the kernel computes with one rounding per operation, lo a
first-order correction (the exact rounding errors of the operations that made hi, carried along in plain double
arithmetic), so that hi + lo holds about twice the digits of hi.  The errors are error-free transformations:

* a sum by Knuth's two-sum (s = a + b, b' = s − a, e = (a − (s − b')) + (b − b'); e is exactly a + b − s);
* a product, quotient or square root by the exact residual that the helper :class:`QuotientLow` computes
  (``fma`` in C, Dekker's exact product in Python): QuotientLow(p, a, b) = (p − ab)/b, so the error of p = fl(ab)
  is −b·QuotientLow(p, a, b), that of q = fl(a/b) is QuotientLow(a, b, q)·b, that of r = fl(√a) is
  QuotientLow(a, r, r)·r (Dekker 1971; Ogita, Rump, Oishi 2005 for the summation).

Every hi is wrapped in ``UnevaluatedExpr``: SymPy would otherwise merge (a + b) + c into one sum of three terms,
whose printed order is not the one the two-sum's error refers to; the emitter prints each wrapped operation as one
parenthesised operation (SymPy's cse names those used twice).  No helper of the emitter is added: the forms use
``quotient_low`` only.
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from pendsym.emit.kernels.plan import Grouped, Select
from pendsym.emit.kernels.supplied import QuotientLow

_wrap = sp.UnevaluatedExpr


@dataclass(frozen=True)
class Pair:
    """hi + lo: hi a double as the kernel computes it, lo the first-order correction (SymPy expressions)."""

    hi: sp.Expr
    lo: sp.Expr = sp.Integer(0)

    def value(self) -> sp.Expr:
        """hi + lo, the value the kernel returns: lo summed first (wrapped, or SymPy would add its terms to hi one by
        one), then one rounding."""
        return self.hi + _wrap(self.lo)


def exact(x: sp.Expr) -> Pair:
    """A double known exactly (an argument, a call's result, an exact product like 2q)."""
    return Pair(x)


def constant(value) -> Pair:
    """A real constant (an mpmath or SymPy number) as the double nearest it plus the rounding error, both Floats."""
    hi = float(value)
    lo = float(sp.Float(value, 40) - sp.Float(hi, 40))
    return Pair(sp.Float(hi, 17), sp.Float(lo, 17) if lo else sp.Integer(0))


def add(a: Pair, b: Pair) -> Pair:
    """a + b: hi by one addition, its exact error by Knuth's two-sum, plus the two lows."""
    s = _wrap(a.hi + b.hi)
    b_virtual = _wrap(s - a.hi)
    error = _wrap(a.hi - _wrap(s - b_virtual)) + _wrap(b.hi - b_virtual)
    return Pair(s, error + a.lo + b.lo)


def mul(a: Pair, b: Pair) -> Pair:
    """a·b: hi by one product; ab − fl(ab) = −b·QuotientLow(fl(ab), a, b); the lows to first order."""
    p = _wrap(a.hi * b.hi)
    return Pair(p, b.hi * (a.lo - QuotientLow(p, b.hi, a.hi)) + a.hi * b.lo)


def square(a: Pair) -> Pair:
    """a²: :func:`mul` with itself (one product, its exact error)."""
    return mul(a, a)


def div(a: Pair, b: Pair) -> Pair:
    """a/b: hi by one quotient; a/b − fl(a/b) = QuotientLow(a, b, fl(a/b)) exactly up to the last division; the
    lows to first order, (a_lo − q·b_lo)/b."""
    quotient = _wrap(a.hi / b.hi)
    return Pair(quotient, QuotientLow(a.hi, b.hi, quotient) + (a.lo - quotient * b.lo) / b.hi)


def root(a: Pair) -> Pair:
    """√a: hi by sqrt; √(a_hi + a_lo) − r = (a_hi − r² + a_lo)/(2r) to first order, a_hi − r² = r·QuotientLow(a_hi, r, r)."""
    r = _wrap(sp.sqrt(a.hi))
    return Pair(r, (QuotientLow(a.hi, r, r) + a.lo / r) / 2)


def total(terms: list[Pair]) -> Pair:
    """Σ terms, left to right, each addition by :func:`add` (compensated: the result is as if summed in twice the
    precision, for terms of one sign)."""
    out = terms[0]
    for t in terms[1:]:
        out = add(out, t)
    return out


def _power_of_two(r: sp.Rational) -> bool:
    """r = ±2^k: a product by it is exact (no underflow in the kernels' ranges)."""
    p, q = abs(r.p), r.q
    return (p & (p - 1)) == 0 and (q & (q - 1)) == 0


def number(r: sp.Number) -> Pair:
    """A SymPy number: exact when it is a double that products keep exact (±2^k, a small integer), else :func:`constant`."""
    if isinstance(r, sp.Integer) and abs(int(r)) < 2**53 or isinstance(r, sp.Rational) and _power_of_two(r):
        return exact(r)
    return constant(r)


def scale(a: Pair, r: sp.Rational) -> Pair:
    """a·r for r = ±2^k: exact, hi and lo both scaled."""
    return Pair(_wrap(a.hi * r), a.lo * r)


def convert(expr: sp.Expr, env: dict, memo: dict | None = None) -> Pair:
    """The Pair of a SymPy expression, each operation compensated: symbols from ``env`` (Pairs; others exact), sums by
    :func:`total`, products by :func:`mul` (factors ±2^k by :func:`scale`, negative powers by one :func:`div`), sin and
    cos of a Pair to first order in its low part (their own rounding is libm's), a Piecewise of two pieces by
    :func:`_choice`.  Each subexpression is converted once (``memo``), so that a part the
    expression uses twice is one value in the kernel."""
    memo = {} if memo is None else memo
    if expr in memo:
        return memo[expr]
    go = lambda e: convert(e, env, memo)        # noqa: E731
    if isinstance(expr, sp.Symbol):
        out = env.get(expr, exact(expr))
    elif isinstance(expr, sp.Number):
        out = number(expr)
    elif isinstance(expr, sp.Add):
        out = total([go(a) for a in expr.args])
    elif isinstance(expr, sp.Mul):
        coeff, rest = expr.as_coeff_Mul()
        num, den = [], []
        for f in sp.Mul.make_args(rest):
            base, power = f.as_base_exp()
            if isinstance(power, sp.Integer) and power < 0:
                den.append(go(base**-power))
            else:
                num.append(go(f))
        out = num[0] if num else exact(sp.Integer(1))
        for f in num[1:]:
            out = mul(out, f)
        if den:
            d = den[0]
            for f in den[1:]:
                d = mul(d, f)
            out = div(out, d)
        if coeff != 1:
            out = scale(out, coeff) if isinstance(coeff, sp.Rational) and _power_of_two(coeff) else mul(number(coeff), out)
    elif isinstance(expr, sp.Pow) and isinstance(expr.exp, sp.Integer):
        n = int(expr.exp)
        base = go(expr.base)
        if n < 0:
            out = div(exact(sp.Integer(1)), go(expr.base ** -n))
        else:
            out = base
            for _ in range(n - 1):
                out = mul(out, base) if out is not base else square(base)
    elif isinstance(expr, sp.Pow) and expr.exp == sp.Rational(1, 2):
        out = root(go(expr.base))
    elif isinstance(expr, (sp.sin, sp.cos)):
        a = go(expr.args[0])
        s, c = sp.sin(a.hi), sp.cos(a.hi)
        out = Pair(s, c * a.lo) if isinstance(expr, sp.sin) else Pair(c, -s * a.lo)
    elif isinstance(expr, sp.Piecewise):
        out = _choice(expr, go)
    elif isinstance(expr, Grouped):
        out = go(expr.args[0])
    else:
        raise ValueError(f"no compensated form of {type(expr).__name__}: {expr}")
    memo[expr] = out
    return out


def _choice(expr: sp.Piecewise, go) -> Pair:
    """A Piecewise ((e_1, l < r), (e_2, True)) (or >, ≤, ≥) as Select(d, ·, ·) of the two branches' his and of their
    lows, d = r − l (the first branch where d > 0).  Both branches are computed, in the kernel's one scope: a
    Piecewise would put the hi and the lo of a branch in two if-chains, each with its own common subexpressions,
    where one quotient may be a/b in one and a·(1/b) in the other, and the low part would then correct another hi
    than the one returned (measured: 1.07 ulp where the form holds 0.5).  So each branch must be finite wherever
    the other is taken (an error is not raised for this: the caller's form must be safe on its whole box)."""
    if len(expr.args) != 2 or expr.args[1][1] is not sp.true:
        raise ValueError(f"only a Piecewise of two pieces, the second for True: {expr}")
    (first, cond), (second, _) = expr.args
    if isinstance(cond, (sp.StrictLessThan, sp.LessThan)):
        d = cond.rhs - cond.lhs
    elif isinstance(cond, (sp.StrictGreaterThan, sp.GreaterThan)):
        d = cond.lhs - cond.rhs
    else:
        raise ValueError(f"no compensated choice on {cond}")
    a, b = go(first), go(second)
    return Pair(Select(d, a.hi, b.hi), Select(d, a.lo, b.lo))
