"""The near and middle pieces of a leaf c(x): its series at 0 below a switch, Taylor pieces
between knots.

Forms such as 1/u² − 1/sh²u or 1 − 2 th(u/2)/u cancel catastrophically as u → 0; their
Taylor (Laurent) series in x, generated exactly from the SymPy form (:func:`laurent`), does
not.  Between the switch and the far form, where every closed form still cancels, Taylor
pieces of width ≤ 2.5 about the middle of [lo, hi] are computed from the leaf by a Cauchy
integral (:func:`taylor_coeffs`).  :data:`SERIES` and :data:`TAYLOR` are the two named rules.
"""
from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Callable, Sequence

import mpmath as mp
import sympy as sp

SWITCHES = (0.125, 0.25, 0.5, 1.0, 1.5)   # candidate switch points of a leaf (sampled by the tests)
KNOTS = (3.0, 5.5, 8.0, 10.5, 13.0, 15.5, 18.0, 20.5)   # ends of the middle Taylor pieces
SERIES_SPAN = 64                           # orders kept beyond the leading one
MID_TERMS = 48                             # terms of the middle Taylor piece


@functools.lru_cache(maxsize=None)
def _atom_series(atom: sp.Expr, x: sp.Symbol, n: int) -> tuple | None:
    """Taylor coefficients 0..n−1 of one function of x at 0 (exact rationals), or None."""
    ser = sp.series(atom, x, 0, n).removeO()
    poly = ser.as_poly(x)
    if poly is None or not all(c.is_Rational for c in poly.coeffs()):
        return None
    out = [sp.Rational(0)] * n
    for (m,), c in poly.terms():
        out[m] = c
    return tuple(out)


def _mul(a: list, b: list, n: int) -> list:
    """The product of two truncated power series (n terms)."""
    out = [sp.Rational(0)] * n
    for i, ai in enumerate(a):
        if ai:
            for j in range(n - i):
                if b[j]:
                    out[i + j] += ai * b[j]
    return out


def _series_of_polynomial(p: sp.Expr, gens: tuple, series: dict, n: int) -> list | None:
    """The truncated power series (n terms) of a polynomial in x and functions of x, each
    function replaced by its series; None when p is not such a polynomial."""
    atoms = gens[1:]   # gens[0] is x itself
    poly = p.as_poly(*gens)
    if poly is None or not all(cf.is_Rational for cf in poly.coeffs()):
        return None
    total = [sp.Rational(0)] * n
    for mon, cf in poly.terms():
        term = [sp.Rational(0)] * n
        if mon[0] < n:
            term[mon[0]] = cf
        for f, k in zip(atoms, mon[1:]):
            for _ in range(k):
                term = _mul(term, series[f], n)
        total = [t + u for t, u in zip(total, term)]
    return total


def laurent(c: sp.Expr, x: sp.Symbol, span: int = SERIES_SPAN) -> tuple[int, list] | None:
    """(m, [a_0 … a_span]): c = x^m Σ a_j x^j near 0, exactly, or None.

    c is written as a ratio of polynomials in x and its functions of x; the series of each
    function is taken once (sp.series) and the polynomials are evaluated in truncated power
    series, so that a cancellation of any depth up to the extra orders is exact.
    """
    num, den = sp.fraction(sp.together(c))
    atoms = sorted({f for f in (num * den).atoms(sp.Function) if f.has(x)}, key=sp.default_sort_key)
    n = span + 1 + 24
    series = {}
    for f in atoms:
        s = _atom_series(f, x, n)
        if s is None:
            return None
        series[f] = list(s)
    gens = (x, *atoms)
    N, D = (_series_of_polynomial(p, gens, series, n) for p in (num, den))
    if N is None or D is None:
        return None
    vn = next((i for i, v in enumerate(N) if v), None)
    vd = next((i for i, v in enumerate(D) if v), None)
    if vd is None or vn is None or n - max(vn, vd) <= span:
        return None
    Nn, Dd = N[vn:], D[vd:]
    q: list = []
    for k in range(span + 1):
        acc = Nn[k] - sum(Dd[j] * q[k - j] for j in range(1, k + 1))
        q.append(acc / Dd[0])
    return vn - vd, q


def split_constant(c, rest: sp.Expr) -> sp.Expr:
    """c + rest, with c as the sum of two doubles hi + lo (hi = c rounded, lo = c − hi) evaluated
    as hi + (lo + rest): where c dominates a Horner sum, its rounding (½ ulp) is no longer an
    error, only the last addition's.  The parenthesis is a :class:`.plan.Grouped` unit."""
    from .plan import Grouped
    with mp.workdps(40):
        cm = mp.mpf(c) if not isinstance(c, sp.Basic) else mp.mpf(sp.N(c, 40))
        hi = float(mp.nstr(cm, 20))
        lo = cm - mp.mpf(hi)
    if lo == 0:
        return sp.Float(mp.nstr(cm, 20), 20) + rest
    return sp.Float(repr(hi), 17) + Grouped(sp.Float(mp.nstr(lo, 20), 20) + rest)


def series_expr(m: int, coeffs: list, x: sp.Symbol) -> sp.Expr:
    """x^m times the series in Horner form (in x² when the series is even), 20-digit coefficients;
    the constant term split in two doubles (:func:`split_constant`)."""
    while coeffs and coeffs[-1] == 0:
        coeffs = coeffs[:-1]
    even = all(c == 0 for c in coeffs[1::2])
    cs, w = (coeffs[::2], x**2) if even else (coeffs, x)
    h = sp.S.Zero
    for c in reversed(cs[1:]):
        h = sp.Float(sp.N(c, 20), 20) + w * h if c != 0 or h != 0 else h
    h = split_constant(cs[0], w * h) if cs and cs[0] != 0 and h != 0 else (
        sp.Float(sp.N(cs[0], 20), 20) + w * h if cs and cs[0] != 0 else w * h)
    return x**m * h


def taylor_coeffs(ref: Callable, m: int, lo: float, hi: float, terms: int = MID_TERMS) -> tuple[float, list]:
    """(centre, coefficients): the Taylor coefficients of x^{−m}·leaf about the middle of [lo, hi].

    They are computed from the leaf's own SymPy form (evaluated by mpmath at 40 digits) by the
    Cauchy integral on a circle of radius 1.3·(hi − lo)/2 (a 128-point trapezoidal rule; the
    leaf is real, so half the circle suffices), and the digits the leaf loses to cancellation
    there cost nothing.  The leaves here are functions of th(x/2), sh x…, analytic at distance
    ≥ π from the real axis: a piece of width ≤ 2.5 keeps the circle clear of the poles and the
    48 terms converge.
    """
    c, r, n = (lo + hi) / 2, 1.3 * (hi - lo) / 2, 128
    with mp.workdps(40):
        roots = [mp.expjpi(mp.mpf(2 * j) / n) for j in range(n)]      # e^{2πij/n}
        g = [mp.mpc(ref(c + r * w) / (c + r * w) ** m) for w in roots[: n // 2 + 1]]
        gr, gi = [v.real for v in g[1: n // 2]], [v.imag for v in g[1: n // 2]]
        cs = []
        for k in range(terms):
            # Re Σ g_j e^{−2πijk/n} over the upper half circle, the lower half by symmetry
            ws = [roots[j * k % n] for j in range(1, n // 2)]
            inner = mp.fdot(gr, [w.real for w in ws]) + mp.fdot(gi, [w.imag for w in ws])
            cs.append((g[0].real + (-1) ** k * g[n // 2].real + 2 * inner) / n / mp.mpf(r) ** k)
    return c, cs


def taylor_expr(c: float, cs: list, m: int, x: sp.Symbol) -> sp.Expr:
    """x^m times the Taylor polynomial about c in Horner form, 20-digit coefficients, the constant
    term split in two doubles (:func:`split_constant`)."""
    h = sp.S.Zero
    dx = x - sp.Float(c, 17)
    for cf in reversed(cs[1:]):
        h = sp.Float(mp.nstr(cf, 20), 20) + dx * h
    return x**m * split_constant(cs[0], dx * h)


def taylor_double(c: float, cs: list, m: int) -> Callable[[float], float]:
    """The Taylor piece evaluated in double exactly as its printed form is (the same roundings)."""
    fs = [float(mp.nstr(cf, 20)) for cf in reversed(cs[1:])]
    with mp.workdps(40):
        hi = float(mp.nstr(cs[0], 20))
        lo = float(mp.nstr(cs[0] - mp.mpf(hi), 20))

    def f(v: float) -> float:
        dx, h = v - c, fs[0]
        for cf in fs[1:]:
            h = cf + dx * h
        h = hi + (lo + dx * h)
        return v**m * h if m else h
    return f


@dataclass(frozen=True)
class SeriesBelow:
    """The rule "series below a switch": the leaf's Laurent series, `span` + 1 terms."""

    span: int = SERIES_SPAN

    def __call__(self, c: sp.Expr, x: sp.Symbol) -> tuple[int, sp.Expr] | None:
        """(m, form): the series x^m Σ a_j x^j in Horner form, or None."""
        lau = laurent(c, x, self.span)
        return None if lau is None else (lau[0], series_expr(lau[0], lau[1], x))

    def describe(self, m: int, x: str, switch: float) -> str:
        return f"series (x^{m}·{self.span + 1} terms) for {x} < {switch:g}"


@dataclass(frozen=True)
class TaylorPieces:
    """The rule "Taylor pieces between knots", `terms` terms each."""

    terms: int = MID_TERMS

    def __call__(self, ref: Callable, m: int, lo: float, hi: float, x: sp.Symbol) -> tuple[sp.Expr, Callable]:
        """(form, the same in double) of the piece on [lo, hi]."""
        c0, cs = taylor_coeffs(ref, m, lo, hi, self.terms)
        return taylor_expr(c0, cs, m, x), taylor_double(c0, cs, m)

    def describe(self, ends: Sequence[float]) -> str:
        spans = ", ".join(f"[{lo:g}, {hi:g}]" for lo, hi in zip(ends, ends[1:]))
        return f"Taylor ({self.terms} terms) on {spans}"


SERIES = SeriesBelow()
TAYLOR = TaylorPieces()
