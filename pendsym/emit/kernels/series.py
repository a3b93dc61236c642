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
import math
from dataclasses import dataclass
from typing import Callable, Sequence

import mpmath as mp
import sympy as sp

SWITCHES = (0.125, 0.25, 0.5, 1.0, 1.5)   # candidate switch points of a leaf (sampled by the tests)
KNOTS = (3.0, 5.5, 8.0, 10.5, 13.0, 15.5, 18.0, 20.5)   # ends of the middle Taylor pieces
SERIES_SPAN = 64                           # orders computed beyond the leading one
MID_TERMS = 48                             # terms computed of the middle Taylor piece
TRUNCATE = 2.0**-64                        # a term is kept unless the tail it starts is below this, relative
                                           # to the value, everywhere on the piece (1/2048 ulp)
TRUNCATE_GRID = 64                         # points of a piece on which the tail is bounded


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


def needed_terms(cs: Sequence, r: float, centred: bool = False) -> int:
    """The number of leading coefficients of Σ c_j y^j to keep on 0 ≤ y ≤ r (−r ≤ y ≤ r where
    `centred`): the fewest n with Σ_{j≥n} |c_j| |y|^j ≤ TRUNCATE·|Σ c_j y^j| at every point of a grid
    of the piece (at 40 digits).  The dropped tail then costs at most 1/2048 ulp: a series of 65
    terms needs ~11 below u = 0.125, ~40 below 1.5."""
    with mp.workdps(40):
        c = [mp.mpf(v) if not isinstance(v, sp.Basic) else mp.mpf(sp.N(v, 40)) for v in cs]
        ys = [mp.mpf(r) * i / TRUNCATE_GRID for i in range(1, TRUNCATE_GRID + 1)]
        if centred:
            ys += [-y for y in ys]
        need = 1
        for y in ys:
            terms = [cj * y**j for j, cj in enumerate(c)]
            total = abs(mp.fsum(terms))
            tail = mp.mpf(0)
            for j in range(len(c) - 1, 0, -1):          # the longest tail still below the tolerance
                tail += abs(terms[j])
                if tail > TRUNCATE * total:
                    need = max(need, j + 1)
                    break
    return need


@dataclass(frozen=True)
class EstrinTail:
    """The rule "Horner head, Estrin tail": Σ c_j w^j with its first `head` coefficients in Horner form and
    the rest by Estrin's scheme (pairs c_j + c_{j+1} w, then pairs of those in w², w⁴ …; each power one
    named product), where there are more than `longer` coefficients.

    A Horner chain of n terms is n dependent multiply–adds (~6 cycles each at -O2 without FMA: 48 terms,
    ~100 ns); Estrin's tree has log₂ n levels.  Its extra roundings are in the tail only, whose
    magnitude is below (ratio of the terms)^head of the value: with head = 5 and a ratio ≤ 0.45 (a
    Taylor piece at its ends), under 2 % of an ulp per ulp of the tail."""

    head: int = 5
    longer: int = 10

    @staticmethod
    def estrin(cs: Sequence[sp.Expr], w: sp.Expr) -> sp.Expr:
        """Σ cs[i] w^i by Estrin's scheme (w a named unit)."""
        from .plan import Grouped
        cs = list(cs)
        while len(cs) > 1:
            cs = [cs[i] + cs[i + 1] * w if i + 1 < len(cs) else cs[i] for i in range(0, len(cs), 2)]
            w = Grouped(w * w) if len(cs) > 1 else w
        return cs[0]

    def __call__(self, cs: Sequence[sp.Expr], w: sp.Expr) -> sp.Expr:
        """Σ cs[i] w^i (cs: SymPy numbers)."""
        cs = list(cs)
        if not cs:
            return sp.S.Zero
        if len(cs) <= self.longer:
            h = sp.S.Zero
            for c in reversed(cs):
                h = c + w * h
            return h
        h = self.estrin(cs[self.head:], w)
        for c in reversed(cs[: self.head]):
            h = c + w * h
        return h


HORNER = EstrinTail(head=10**9, longer=10**9)     # plain Horner (the form before session 11)
ESTRIN = EstrinTail()


def series_expr(m: int, coeffs: list, x: sp.Symbol, scheme: EstrinTail = HORNER) -> sp.Expr:
    """x^m times the series (in x² when the series is even) evaluated by `scheme`, 20-digit
    coefficients; the constant term split in two doubles (:func:`split_constant`)."""
    from .plan import Grouped
    while coeffs and coeffs[-1] == 0:
        coeffs = coeffs[:-1]
    even = all(c == 0 for c in coeffs[1::2])
    cs, w = (coeffs[::2], x**2) if even else (coeffs, x)
    if scheme is not HORNER and len(cs) - 1 > scheme.longer and even:
        w = Grouped(w)                 # x² named once: the tail's powers are products of it
    rest = [sp.Float(sp.N(c, 20), 20) if c != 0 else sp.S.Zero for c in cs[1:]]
    while rest and rest[-1] == 0:
        rest = rest[:-1]
    h = scheme(rest, w)
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


def taylor_expr(c: float, cs: list, m: int, x: sp.Symbol, scheme: EstrinTail = HORNER) -> sp.Expr:
    """x^m times the Taylor polynomial about c evaluated by `scheme`, 20-digit coefficients, the constant
    term split in two doubles (:func:`split_constant`)."""
    from .plan import Grouped
    dx = x - sp.Float(c, 17)
    if scheme is not HORNER and len(cs) - 1 > scheme.longer:
        dx = Grouped(dx)               # x − c named once
    h = scheme([sp.Float(mp.nstr(cf, 20), 20) for cf in cs[1:]], dx)
    return x**m * split_constant(cs[0], dx * h)


def taylor_double(c: float, cs: list, m: int) -> Callable[[float], float]:
    """The Taylor piece in Horner form evaluated in double exactly as its printed form is (the same
    roundings)."""
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
    """The rule "series below a switch": the leaf's Laurent series, `span` + 1 terms computed; with
    `scheme` other than Horner (session 11), :meth:`below` keeps only the terms the switch needs
    (:func:`needed_terms`) and evaluates them by `scheme`."""

    span: int = SERIES_SPAN
    scheme: EstrinTail = HORNER

    def __call__(self, c: sp.Expr, x: sp.Symbol) -> tuple[int, sp.Expr] | None:
        """(m, form): the series x^m Σ a_j x^j in Horner form, or None."""
        lau = laurent(c, x, self.span)
        return None if lau is None else (lau[0], series_expr(lau[0], lau[1], x))

    def coefficients(self, c: sp.Expr, x: sp.Symbol) -> tuple[int, list] | None:
        """(m, [a_0 … a_span]) of :func:`laurent`, or None."""
        return laurent(c, x, self.span)

    def below(self, m: int, coeffs: list, x: sp.Symbol, switch: float) -> tuple[sp.Expr, int]:
        """(form, terms): the series truncated for 0 < x < switch, evaluated by `scheme`."""
        n = needed_terms(coeffs, switch) if self.scheme is not HORNER else len(coeffs)
        return series_expr(m, list(coeffs[:n]), x, self.scheme), n

    def describe(self, m: int, x: str, switch: float, terms: int | None = None) -> str:
        return f"series (x^{m}·{self.span + 1 if terms is None else terms} terms) for {x} < {switch:g}"


@dataclass(frozen=True)
class TaylorPieces:
    """The rule "Taylor pieces between knots", `terms` terms each computed; with `scheme` other than
    Horner (session 11), only the terms the piece needs (:func:`needed_terms`), evaluated by `scheme`."""

    terms: int = MID_TERMS
    scheme: EstrinTail = HORNER

    def __call__(self, ref: Callable, m: int, lo: float, hi: float, x: sp.Symbol) -> tuple[sp.Expr, Callable]:
        """(form, the same in double) of the piece on [lo, hi]."""
        c0, cs = taylor_coeffs(ref, m, lo, hi, self.terms)
        if self.scheme is HORNER:
            return taylor_expr(c0, cs, m, x), taylor_double(c0, cs, m)
        cs = cs[: needed_terms(cs, (hi - lo) / 2, centred=True)]
        form = taylor_expr(c0, cs, m, x, self.scheme)
        from .printing import KernelPy
        return form, sp.lambdify([x], form, modules=["math", {"math": math}], printer=KernelPy)

    def describe(self, ends: Sequence[float]) -> str:
        spans = ", ".join(f"[{lo:g}, {hi:g}]" for lo, hi in zip(ends, ends[1:]))
        if self.scheme is not HORNER:
            return f"Taylor (the terms of {self.terms} each piece needs, Estrin tail) on {spans}"
        return f"Taylor ({self.terms} terms) on {spans}"


SERIES = SeriesBelow(scheme=ESTRIN)
TAYLOR = TaylorPieces(scheme=ESTRIN)
