"""Kernels: Python (math only) and C99 (libm only) functions for every closed form.

A Result whose Spec asks for a kernel is emitted from its derived form.  The
form is chosen among small named rewrite rules by measured accuracy in double
precision against 50-digit mpmath on a fixed, seeded sample of the declared
domain (its corners and hard points included); the printers subclass SymPy's
Python and C99 printers, and Jinja only lays out the files.
"""
from __future__ import annotations

import ctypes
import functools
import keyword
import math
import random
import re
import subprocess
from dataclasses import dataclass
from pathlib import Path
from typing import Callable, Sequence

import mpmath as mp
import sympy as sp
from sympy.codegen.cfunctions import expm1
from sympy.printing.c import C99CodePrinter
from sympy.printing.pycode import PythonCodePrinter

from ..result import KernelArg, Result

# ----------------------------------------------------------------- rewrite rules


def _sin_basis(e: sp.Expr) -> sp.Expr:
    """Even powers of cos → powers of (1 − sin²), then factor (good near kt = 0)."""
    e = sp.expand(sp.expand_trig(e))
    e = e.replace(lambda x: x.is_Pow and x.base.func == sp.cos and x.exp.is_even and x.exp > 0,
                  lambda x: (1 - sp.sin(x.base.args[0]) ** 2) ** (x.exp // 2))
    return sp.factor(sp.expand(e))


def _cos_basis(e: sp.Expr) -> sp.Expr:
    """Even powers of sin → powers of (1 − cos²), then factor."""
    e = sp.expand(sp.expand_trig(e))
    e = e.replace(lambda x: x.is_Pow and x.base.func == sp.sin and x.exp.is_even and x.exp > 0,
                  lambda x: (1 - sp.cos(x.base.args[0]) ** 2) ** (x.exp // 2))
    return sp.factor(sp.expand(e))


SERIES_ORDER = 44          # orders kept near a removable zero of the time argument
SERIES_PHASE = sp.Rational(7, 20)  # the series is used for k·t below this phase


def near_zero_series(e: sp.Expr, args: Sequence[KernelArg]) -> tuple[sp.Expr, sp.Expr] | None:
    """(series, phase): the Taylor series in t, to be used where the phase k·t is small.

    Forms such as kt − sin kt cos kt cancel as t → 0; their series does not.
    With 44 orders kept, the truncation at k·t = 0.35 is below 2e-18 relative
    to a leading term of order ≤ 5.
    """
    by = {x.name: x for x in e.free_symbols}
    if "t" not in by or not any(a.name == "t" and a.lo == 0 for a in args):
        return None
    t = by["t"]
    ser = sp.series(e, t, 0, SERIES_ORDER).removeO()
    if ser == 0:
        return None
    phase = by["k"] * t if "k" in by else t
    # rational coefficients become 20-digit floats (exact to double), so no huge integer literals
    return sp.horner(sp.N(sp.collect(sp.expand(ser), t), 20), wrt=t), phase


REWRITES: tuple[tuple[str, Callable[[sp.Expr], sp.Expr]], ...] = (
    ("as-derived", lambda e: e),
    ("factor", sp.factor),
    ("expand-trig", lambda e: sp.factor(sp.expand(sp.expand_trig(e)))),
    ("sin-basis", _sin_basis),
    ("cos-basis", _cos_basis),
    ("horner", lambda e: sp.horner(sp.expand(e)) if e.is_polynomial() else e),
    # 1 − cos x cancels for small x: cos x = 1 − 2 sin²(x/2)
    ("half-angle", lambda e: sp.factor(sp.expand(e.replace(sp.cos, lambda x: 1 - 2 * sp.sin(x / 2) ** 2)))),
)

TRIG_RULES = ("expand-trig", "sin-basis", "cos-basis", "half-angle")   # tried only on forms with sin or cos

# ----------------------------------------------------------------- stable forms in one hard argument
#
# Forms such as 1/u² − 1/sh²u or 1 − 2 th(u/2)/u cancel catastrophically as u → 0, and
# sh u overflows for large u.  The mechanism, for any memoir: the expression is split into
# a skeleton in the other arguments whose coefficients ("leaves") are functions of the one
# hard argument x alone (:func:`split_hard`); each leaf gets a piecewise form chosen by
# measurement against 50-digit mpmath on a grid of x (:func:`leaf_form`): its Taylor
# (Laurent) series in x, generated exactly from the SymPy form (:func:`laurent`), below a
# switch point taken from SWITCHES, then Taylor pieces of width ≤ 2.5 between KNOTS where
# every closed form still cancels (:func:`taylor_expr`), and above them the leaf as derived
# or rewritten in e^{−x/q} with expm1 (:func:`exp_form`), which neither overflows nor
# cancels at large x.

BOUND = 4.0    # ulp × max(1, condition number): the accuracy a kernel must hold
SWITCHES = (0.125, 0.25, 0.5, 1.0, 1.5)   # candidate switch points of a leaf (sampled by the tests)
SERIES_SPAN = 64                           # orders kept beyond the leading one
LEAF_POINTS = 160                          # log-spaced grid on which a leaf's form is chosen
KNOTS = (3.0, 5.5, 8.0, 10.5, 13.0, 15.5, 18.0, 20.5)   # ends of the middle Taylor pieces
LEAF_DPS = 120                             # a leaf may lose 40 digits to cancellation at x = 1e-6
MID_TERMS = 48                             # terms of the middle Taylor piece
GOOD_ENOUGH = 1.5                          # ulp: a leaf this accurate without Taylor pieces needs none


def hard_argument(expr: sp.Expr, args: Sequence[KernelArg]) -> KernelArg | None:
    """The argument that alone feeds every transcendental function of expr, if any.

    It must be sampled geometrically from lo > 0 (a near-zero cancellation is the problem
    the mechanism solves).
    """
    funcs = [f for f in expr.atoms(sp.Function) if f.free_symbols and not isinstance(f, sp.Piecewise)]
    names = {s.name for f in funcs for s in f.free_symbols}
    if len(names) != 1:
        return None
    (name,) = names
    arg = next((a for a in args if a.name == name), None)
    return arg if arg is not None and arg.log and arg.lo > 0 else None


def split_hard(e: sp.Expr, x: sp.Symbol) -> tuple[sp.Expr, dict[sp.Symbol, sp.Expr]]:
    """(skeleton, leaves): e = skeleton with each placeholder replaced by its leaf, a function of x alone.

    Polynomials in the other symbols are collected, so each leaf is a whole coefficient
    (cancellations inside it are then cured by its series); elsewhere the tree is walked,
    and the x-only terms of a sum, or factors of a product, are gathered into one leaf.
    """
    leaves: dict[sp.Expr, sp.Symbol] = {}

    def leaf(c: sp.Expr) -> sp.Expr:
        if c.is_number or c == x or (c.is_Pow and c.base == x and c.exp.is_Integer):
            return c
        if c not in leaves:
            leaves[c] = sp.Symbol(f"leaf_{len(leaves)}")
        return leaves[c]

    def walk(e: sp.Expr) -> sp.Expr:
        if not e.has(x):
            return e
        if isinstance(e, sp.Piecewise):         # branches and conditions walked alike
            return sp.Piecewise(*[(walk(ex), cond if cond in (sp.true, sp.false) else cond.func(*map(walk, cond.args)))
                                  for ex, cond in e.args])
        others = sorted(e.free_symbols - {x}, key=lambda s: s.name)
        if not others:
            return leaf(e)
        if e.is_Pow and e.exp.is_Integer:        # a power is kept: its expansion may cancel
            return walk(e.base) ** e.exp
        poly = e.as_poly(*others, domain="EX")
        if poly is not None:
            return sp.Add(*[sp.Mul(*[g**m for g, m in zip(others, mon)]) * leaf(sp.sympify(cf))
                            for mon, cf in poly.terms()])
        if e.is_Add or e.is_Mul:
            mine = [t for t in e.args if not (t.free_symbols - {x})]
            rest = [walk(t) for t in e.args if t.free_symbols - {x}]
            head = [leaf(e.func(*mine))] if mine else []
            return e.func(*head, *rest)
        if e.is_Pow:
            return walk(e.base) ** walk(e.exp)
        return e.func(*[walk(t) for t in e.args])

    skeleton = walk(e)
    return skeleton, {s: c for c, s in leaves.items()}


def _in_E(c: sp.Expr, x: sp.Symbol) -> tuple[sp.Expr, sp.Expr, sp.Symbol, int] | None:
    """(num, den, E, q): c = num/den, polynomials in E = e^{−x/q} (and x), or None when c is
    not a function of exponentials of rational multiples of x."""
    ex = c.rewrite(sp.exp)
    exps = [a for a in ex.atoms(sp.exp) if a.has(x)]
    ratios = [sp.simplify(a.args[0] / x) for a in exps]
    if not exps or not all(r.is_Rational for r in ratios):
        return None
    q = sp.ilcm(*[r.q for r in ratios])
    E = sp.Symbol("E_x", positive=True)
    ex = ex.replace(lambda a: isinstance(a, sp.exp) and a.has(x), lambda a: E ** (-sp.simplify(a.args[0] / x) * q))
    if any(f.has(x) for f in ex.atoms(sp.Function)):
        return None
    num, den = sp.fraction(sp.cancel(sp.together(ex)))
    return num, den, E, q


def _stable_in_E(p: sp.Expr, E: sp.Symbol, x: sp.Symbol, q: int) -> sp.Expr:
    """p (a polynomial in E) factored, each factor c(E^j − 1) written c·expm1(−j x/q), E = e^{−x/q}."""
    cf, facs = sp.factor_list(p)
    out = cf
    for f, m in facs:
        terms = sp.Poly(f, E).terms() if f.free_symbols == {E} else None
        if terms and len(terms) == 2 and terms[1][0] == (0,) and terms[0][1] == -terms[1][1]:
            j = terms[0][0][0]          # c(E^j − 1) = c·expm1(−j x/q)
            f = terms[0][1] * expm1(-j * x / q)
        out *= f**m
    return out.subs(E, sp.exp(-x / q))


def exp_form(c: sp.Expr, x: sp.Symbol) -> sp.Expr | None:
    """c (exponentials or hyperbolic functions of rational multiples of x) as a rational
    function of E = e^{−x/q}, factored; each factor E^j − 1 is written with expm1."""
    got = _in_E(c, x)
    if got is None:
        return None
    num, den, E, q = got
    return _stable_in_E(num, E, x, q) / _stable_in_E(den, E, x, q)


def asymptotic_form(c: sp.Expr, x: sp.Symbol) -> sp.Expr | None:
    """c = L(x) + R(x): L, the limit of the e^{−x/q} form as E = e^{−x/q} → 0 (a rational
    function of x, factored), and R = c − L, which carries a factor E^k (written as in
    :func:`exp_form`).  Where R ≪ L the error is L's alone: no power of an expm1 or of
    1 + E multiplies its rounding.  None when L or the denominator vanishes at E = 0."""
    got = _in_E(c, x)
    if got is None:
        return None
    num, den, E, q = got
    n0, d0 = num.subs(E, 0), den.subs(E, 0)
    if n0 == 0 or d0 == 0:
        return None
    rn, rd = sp.fraction(sp.cancel((num * d0 - n0 * den) / (den * d0)))
    return sp.factor(n0 / d0) + _stable_in_E(rn, E, x, q) / _stable_in_E(rd, E, x, q)


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
    out = [sp.Rational(0)] * n
    for i, ai in enumerate(a):
        if ai:
            for j in range(n - i):
                if b[j]:
                    out[i + j] += ai * b[j]
    return out


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

    def value(p: sp.Expr) -> list | None:
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
    N, D = value(num), value(den)
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


def series_expr(m: int, coeffs: list, x: sp.Symbol) -> sp.Expr:
    """x^m times the series in Horner form (in x² when the series is even), 20-digit coefficients."""
    while coeffs and coeffs[-1] == 0:
        coeffs = coeffs[:-1]
    even = all(c == 0 for c in coeffs[1::2])
    cs, w = (coeffs[::2], x**2) if even else (coeffs, x)
    h = sp.S.Zero
    for c in reversed(cs):
        h = sp.Float(sp.N(c, 20), 20) + w * h if c != 0 or h != 0 else h
    return x**m * h


def _leaf_grid(a: KernelArg) -> list[float]:
    """Log-spaced points over the domain, every 1/16 over [0.25, 21] (where the closed forms
    cancel and the Taylor pieces lie), and each switch and knot with its neighbours."""
    n = LEAF_POINTS
    pts = [math.exp(math.log(a.lo) + (math.log(a.hi) - math.log(a.lo)) * i / (n - 1)) for i in range(n)]
    pts += [0.25 + 0.0625 * i for i in range(333)]
    for s in SWITCHES + KNOTS:
        pts += [math.nextafter(s, 0.0), s, s * (1 + 1e-3), s * (1 - 1e-3)]
    return sorted(v for v in set(pts) if a.lo <= v <= a.hi)


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
    """x^m times the Taylor polynomial about c in Horner form, 20-digit coefficients."""
    h = sp.S.Zero
    dx = x - sp.Float(c, 17)
    for cf in reversed(cs):
        h = sp.Float(mp.nstr(cf, 20), 20) + dx * h
    return x**m * h


def _taylor_double(c: float, cs: list, m: int) -> Callable[[float], float]:
    """The Taylor piece evaluated in double exactly as its printed form is (the same roundings)."""
    fs = [float(mp.nstr(cf, 20)) for cf in reversed(cs)]

    def f(v: float) -> float:
        dx, h = v - c, fs[0]
        for cf in fs[1:]:
            h = cf + dx * h
        return v**m * h if m else h
    return f


def _ulp_errors(fn: Callable, xs: Sequence[float], truth: Sequence) -> list[float]:
    """The error of fn at each point in ulp of the true value (inf where it fails or overflows)."""
    out = []
    for xv, tv in zip(xs, truth):
        try:
            got = fn(xv)
        except (OverflowError, ZeroDivisionError, ValueError):
            got = math.nan
        if not math.isfinite(got):
            out.append(math.inf)
        elif abs(tv) < 1e-290:
            out.append(0.0)
        else:
            out.append(float(abs(mp.mpf(got) - tv) / mp.mpf(math.ulp(float(tv)))))
    return out


@dataclass(frozen=True)
class LeafForm:
    expr: sp.Expr
    desc: str            # how it is evaluated, for the docstring
    max_ulp: float       # measured on the leaf grid


def leaf_form(c: sp.Expr, x: sp.Symbol, a: KernelArg) -> LeafForm:
    """The leaf's piecewise form of least error on the leaf grid, among: a far form (c as
    derived, or its e^{−x} form) alone; the series below a switch and the far form above; and
    the series, Taylor pieces up to a knot, and the far form above.  Each piece is measured
    once on its own points; a form with more pieces must gain more than 0.25 ulp."""
    xs = _leaf_grid(a)
    inside = [s for s in SWITCHES if a.lo < s < a.hi]
    with mp.workdps(LEAF_DPS):
        ref = sp.lambdify([x], c, modules="mpmath")
        truth = [ref(mp.mpf(v)) for v in xs]

        def errors(fn, lo=-math.inf, hi=math.inf):
            """{grid index: ulp error} of the double function fn on the grid points in [lo, hi)."""
            idx = [i for i, v in enumerate(xs) if lo <= v < hi]
            return dict(zip(idx, _ulp_errors(fn, [xs[i] for i in idx], [truth[i] for i in idx])))

        def in_double(form):
            return sp.lambdify([x], form, modules="math")
        fars = [("as derived", c)]
        ef = exp_form(c, x)
        if ef is not None:
            fars.append((f"e^{{-{a.name}}} form", ef))
        af = asymptotic_form(c, x)
        if af is not None:
            fars.append((f"limit in 1/{a.name} plus e^{{-{a.name}}} remainder", af))
        far_err = {name: errors(in_double(f)) for name, f in fars}
        lau = laurent(c, x)
        m = lau[0] if lau else 0
        head = series_expr(lau[0], lau[1], x) if lau else None
        head_err = errors(in_double(head), hi=max(inside)) if lau and inside else {}
        below = {s1: max(v for i, v in head_err.items() if xs[i] < s1) for s1 in (inside if lau else ())}
        ser_desc = {s1: f"series (x^{m}·{SERIES_SPAN + 1} terms) for {a.name} < {s1:g}" for s1 in below}
        knots = [k for k in KNOTS if k < a.hi]
        pieces: dict = {}

        def piece(lo, hi):
            if (lo, hi) not in pieces:
                c0, cs = taylor_coeffs(ref, m, lo, hi)
                pieces[lo, hi] = (taylor_expr(c0, cs, m, x), errors(_taylor_double(c0, cs, m), lo, hi))
            return pieces[lo, hi]
        cands = []     # (error, number of pieces, order, form, description)
        for fname, far in fars:
            fe = far_err[fname]
            cands.append((max(fe.values()), 1, len(cands), far, fname))
            for s1 in below:
                err = max(below[s1], max(v for i, v in fe.items() if xs[i] >= s1))
                cands.append((err, 2, len(cands), sp.Piecewise((head, x < s1), (far, True)),
                              f"{ser_desc[s1]}, {fname} above"))
        for fname, far in (fars if below and min(cd[0] for cd in cands) > GOOD_ENOUGH else ()):
            fe = far_err[fname]
            for s1 in below:
                ends, mids, worst = [s1], [], below[s1]
                for k in knots:
                    form, pe = piece(ends[-1], k)
                    ends.append(k)
                    mids.append(form)
                    worst = max(worst, max(pe.values(), default=0.0))
                    above = max((v for i, v in fe.items() if xs[i] >= k), default=0.0)
                    err = max(worst, above)
                    spans = ", ".join(f"[{lo:g}, {hi:g}]" for lo, hi in zip(ends, ends[1:]))
                    pw = sp.Piecewise((head, x < s1), *[(f, x < e) for f, e in zip(mids, ends[1:])], (far, True))
                    cands.append((err, 2 + len(mids), len(cands), pw,
                                  f"{ser_desc[s1]}, Taylor ({MID_TERMS} terms) on {spans}, {fname} above"))
                    if above <= worst:      # a further piece cannot lower the error
                        break
    least = min(e for e, *_ in cands)
    err, _, _, form, desc = min((cd for cd in cands if cd[0] <= least + 0.25), key=lambda cd: cd[1:3])
    return LeafForm(form, desc, round(err, 2))


class Grouped(sp.Function):
    """A leaf evaluated as one parenthesised unit: its terms are not merged into the sum around
    it, so the order of operations its accuracy was measured with is the order of the kernel."""

    nargs = 1


def _vertex(skeleton: sp.Expr, leaves: dict) -> tuple | None:
    """(K, A, c, D): a skeleton quadratic in one argument K, A K² + B K + C with B/A and C/A
    functions of the hard argument alone (in the leaf symbols), as A[(K − c)² + D] with
    c = −B/(2A), D = C/A − c²; None if no argument qualifies."""
    hard = set(leaves)
    for K in sorted(skeleton.free_symbols - hard, key=lambda s: s.name):
        try:
            poly = sp.Poly(skeleton, K)
        except sp.PolynomialError:
            continue
        if poly.degree() != 2:
            continue
        A, B, C = poly.all_coeffs()
        r, q = sp.cancel(B / A), sp.cancel(C / A)
        if (r.free_symbols | q.free_symbols) <= hard:
            return K, A, -r / 2, q - r**2 / 4
    return None


def vertex_form(skeleton: sp.Expr, leaves: dict) -> tuple[sp.Expr, dict] | None:
    """The skeleton in vertex form P[a(K − c)² + aD] (:func:`_vertex`, A = P·a with a the part of A in
    the leaves), c and aD new leaves (on the vertex the value is then one leaf, not a product).

    Near the vertex the three terms of the plain form cancel, and the rounding of its leaves
    is amplified by Σ|terms|/|value|, not by the condition number; in vertex form the
    cancellation is inside the leaf D, which gets its own stable form."""
    vx = _vertex(skeleton, leaves)
    if vx is None:
        return None
    K, A, c, D = vx
    P, a = A.as_independent(*leaves)          # A = P·a, a the part in the leaves: A(K − c)² + P·(aD)
    c_sym, e_sym = sp.Symbol(f"leaf_{len(leaves)}"), sp.Symbol(f"leaf_{len(leaves) + 1}")
    new = {**leaves, c_sym: sp.together(c.xreplace(leaves)), e_sym: sp.together((a * D).xreplace(leaves))}
    return P * (a * (K - c_sym) ** 2 + e_sym), new


@functools.lru_cache(maxsize=256)
def hard_split(expr: sp.Expr, args: tuple[KernelArg, ...]) -> tuple | None:
    """(hard argument, its symbol, skeleton, leaves) of :func:`split_hard`, or None without a
    hard argument (the leaves' dict is shared: not to be modified)."""
    a = hard_argument(expr, args)
    if a is None:
        return None
    x = next(s for s in expr.free_symbols if s.name == a.name)
    return (a, x, *split_hard(expr, x))


@functools.lru_cache(maxsize=256)
def vertex_curve(expr: sp.Expr, args: tuple[KernelArg, ...]) -> tuple[str, str, Callable] | None:
    """(hard argument, K, c): where the kernel's skeleton is quadratic in K, the vertex K = c(x)
    as a function of the hard argument x (mpmath), for sampling; or None."""
    split = hard_split(expr, args)
    if split is None:
        return None
    a, x, skeleton, leaves = split
    vx = _vertex(skeleton, leaves)
    if vx is None:
        return None
    return a.name, vx[0].name, sp.lambdify([x], vx[2].xreplace(leaves), modules="mpmath")


def stable_forms(expr: sp.Expr, args: Sequence[KernelArg],
                 vertex: bool = True) -> list[tuple[str, sp.Expr, tuple[str, ...]]]:
    """[(label, form, notes)]: expr with every leaf of its hard argument in its measured best
    piecewise form (each one :class:`Grouped`); and, with `vertex`, when the skeleton is a
    quadratic in one argument, the same in vertex form (:func:`vertex_form`).  Empty without a
    hard argument."""
    split = hard_split(expr, tuple(args))
    if split is None:
        return []
    a, x, skeleton, leaves = split
    variants = [("", skeleton, leaves)]
    vx = vertex_form(skeleton, leaves) if vertex else None
    if vx is not None:
        variants.append((", in vertex form", *vx))
    forms: dict = {}
    out = []
    for label, skel, lv in variants:
        for sym in skel.free_symbols & set(lv):
            if lv[sym] not in forms:
                forms[lv[sym]] = leaf_form(lv[sym], x, a)
        used = sorted(skel.free_symbols & set(lv), key=lambda s: int(s.name.split("_")[1]))
        notes = tuple(f"{sp.sstr(lv[s])[:60]}: {forms[lv[s]].desc} ({forms[lv[s]].max_ulp:g} ulp)" for s in used)
        out.append((label, skel.xreplace({s: Grouped(forms[lv[s]].expr) for s in used}), notes))
    return out


# ----------------------------------------------------------------- printers


def _print_grouped(printer, expr) -> str:
    return "(" + printer._print(expr.args[0]) + ")"


class KernelC(C99CodePrinter):
    """C99 printer: small integer powers as products, no pow() for them; π as a literal
    (M_PI is POSIX, not C99); a Grouped leaf in parentheses."""

    _print_Grouped = _print_grouped

    def _print_Pi(self, expr):
        return "3.14159265358979323846264338327950288"

    def _print_Integer(self, expr):
        # a C integer literal overflows past 64 bits: print large ones as doubles
        return super()._print_Integer(expr) if abs(int(expr)) < 2**53 else repr(float(expr))

    def _print_Pow(self, expr):
        b, e = expr.as_base_exp()
        if e.is_Integer and 1 < abs(int(e)) <= 8:
            prod = "*".join([f"({self._print(b)})"] * abs(int(e)))
            return f"(1.0/({prod}))" if e < 0 else f"({prod})"
        return super()._print_Pow(expr)


class KernelPy(PythonCodePrinter):
    """Python printer for math-only kernels (no SymPy at import); a Grouped leaf in parentheses."""

    _print_Grouped = _print_grouped


@functools.lru_cache(maxsize=256)
def _plan(expr: sp.Expr) -> tuple:
    """The statements of a kernel, shared by the C and Python printers: a tuple of
    ("let", symbol, value) and ("if", symbol, ((condition, plan, value), …)), then the value.

    Common subexpressions are extracted (SymPy cse) only where they are always evaluated: each
    stable leaf (:class:`Grouped`) and each other Piecewise becomes an if-chain whose branches
    have their own subexpressions, so that no branch is evaluated outside its range (a series
    at u = 700 overflows, a far form may have a pole at small u)."""
    names = sp.numbered_symbols("x_")
    return _plan_of(expr, names)


def _always_evaluated(expr: sp.Basic, kind) -> set:
    """The subexpressions of type `kind` that expr evaluates on every path: the search does not
    enter the branches of a Piecewise or of an ITE (SymPy folds a Piecewise out of a condition
    into an ITE), only their conditions."""
    found, stack = set(), [expr]
    while stack:
        e = stack.pop()
        if isinstance(e, kind):
            found.add(e)
            continue
        if isinstance(e, sp.Piecewise):
            stack += [c for _, c in e.args]
        elif isinstance(e, sp.ITE):
            stack.append(e.args[0])
        else:
            stack += list(e.args)
    return found


def _plan_of(expr: sp.Expr, names) -> tuple:
    steps: list = []
    for kind in (Grouped, sp.Piecewise):           # the leaves first: a Piecewise may compare them
        named = {}
        for e in sorted(_always_evaluated(expr, kind), key=sp.default_sort_key):
            named[e] = next(names)
            steps += _assign(e.args[0] if kind is Grouped else e, named[e], names)
        expr = expr.xreplace(named)
    subs, (red,) = sp.cse([expr], symbols=names)
    steps += [("let", x, v) for x, v in subs]
    return tuple(steps), red


def _assign(value: sp.Expr, sym: sp.Symbol, names) -> list:
    """The steps that give sym its value: an if-chain for a Piecewise, else its own plan."""
    if isinstance(value, sp.Piecewise):
        return [("if", sym, tuple((cond, *_plan_of(branch, names)) for branch, cond in value.args))]
    plan, red = _plan_of(value, names)
    return [*plan, ("let", sym, red)]


def _lines(plan: tuple, printer, lang: str, indent: str = "") -> list[str]:
    out = []
    for kind, sym, data in plan:
        name = printer.doprint(sym)
        if kind == "let":
            out.append(f"{indent}{'const double ' if lang == 'c' else ''}{name} = {printer.doprint(data)}"
                       + (";" if lang == "c" else ""))
            continue
        if lang == "c":
            out.append(f"{indent}double {name};")
        for i, (cond, sub, red) in enumerate(data):
            last = i == len(data) - 1
            c = printer.doprint(cond)
            if lang == "c":
                head = f"if ({c}) {{" if i == 0 else "} else {" if last and cond == sp.true else f"}} else if ({c}) {{"
            else:
                head = f"if {c}:" if i == 0 else "else:" if last and cond == sp.true else f"elif {c}:"
            out.append(indent + head)
            out += _lines(sub, printer, lang, indent + "    ")
            out.append(f"{indent}    {name} = {printer.doprint(red)}" + (";" if lang == "c" else ""))
        if lang == "c":
            out.append(indent + "}")
    return out


def _body(expr: sp.Expr, printer, lang: str) -> tuple[list[str], str]:
    plan, red = _plan(expr)
    return _lines(plan, printer, lang), printer.doprint(red)


def identifier(name: str) -> str:
    """A C and Python identifier for a symbol's name (p' → p_prime)."""
    out = re.sub(r"\W", "_", name.replace("'", "_prime"))
    out = out if out[:1].isalpha() else "a_" + out
    return out + "_" if keyword.iskeyword(out) else out          # lambda → lambda_


def _printable(k: "Kernel") -> sp.Expr:
    """The kernel's expression with every argument renamed to its identifier."""
    by = {x.name: x for x in k.expr.free_symbols}
    return k.expr.xreplace({by[a.name]: sp.Symbol(identifier(a.name), real=True) for a in k.args if a.name in by})


def bodies(k: "Kernel") -> tuple:
    """((C lines, C return), (Python lines, Python return)) of a kernel (:func:`_plan`), printed
    where the kernel is formed (the slow part of the emission)."""
    e = _printable(k)
    return (_body(e, KernelC(), "c"), _body(e, KernelPy(settings={"fully_qualified_modules": True}), "py"))


def c_function(k: "Kernel") -> tuple[str, str]:
    """(prototype, definition) of a kernel in C99."""
    args = ", ".join(f"double {identifier(a.name)}" for a in k.args)
    proto = f"double {k.name}({args})"
    lines, ret = (k.bodies or bodies(k))[0]
    return proto, proto + "\n{\n" + "".join(f"    {ln}\n" for ln in lines) + f"    return {ret};\n}}\n"


def py_function(k: "Kernel") -> str:
    lines, ret = (k.bodies or bodies(k))[1]
    args = ", ".join(identifier(a.name) for a in k.args)
    doc = k.docstring().replace("\n", "\n    ")
    body = "".join(f"    {ln}\n" for ln in lines)
    return f'def {k.name}({args}):\n    """{doc}\n    """\n{body}    return {ret}\n'


# ----------------------------------------------------------------- kernels


@dataclass(frozen=True)
class Accuracy:
    points: int
    max_ulp: float           # largest error in units in the last place of the true value
    max_scaled: float        # largest error / max(1, condition number), in ulp
    worst_at: tuple          # the arguments of the largest scaled error


@dataclass(frozen=True)
class Naive:
    """The obvious double-precision evaluation of the printed formula, measured on the same points."""

    form: str                # "printed" or "as derived" (when the memoir prints none, or another function)
    accuracy: Accuracy
    fails: str               # where its scaled error exceeds BOUND, e.g. "u ≤ 0.03; u ≥ 700"


@dataclass(frozen=True)
class Kernel:
    name: str
    result_id: str
    args: tuple[KernelArg, ...]
    expr: sp.Expr
    rule: str
    doc: str
    ref: str
    py_accuracy: Accuracy | None = None
    c_accuracy: Accuracy | None = None
    notes: tuple[str, ...] = ()      # the pieces of a stable form, with their measured errors
    naive: Naive | None = None
    reference: tuple = ()            # (50-digit value, κ) at each sample point, for the C measurement
    bodies: tuple = ()               # the printed C and Python bodies (:func:`bodies`)

    def docstring(self) -> str:
        dom = "; ".join(f"{a.name} in [{a.lo:g}, {a.hi:g}] {a.unit}" for a in self.args)
        lines = [f"{self.doc} — {self.result_id} ({self.ref}).", f"Domain: {dom}.", f"Form: rewrite rule '{self.rule}'."]
        lines += [f"  {n}" for n in self.notes]
        for lang, acc in (("Python", self.py_accuracy), ("C", self.c_accuracy)):
            if acc:
                lines.append(f"Measured {lang} error on {acc.points} points: {acc.max_ulp:.3g} ulp, "
                             f"{acc.max_scaled:.3g} ulp × max(1, condition number).")
        if self.naive:
            nv = self.naive.accuracy
            lines.append(f"The naive {self.naive.form} form in double on the same points: {nv.max_ulp:.3g} ulp, "
                         f"{nv.max_scaled:.3g} ulp × max(1, condition number); beyond {BOUND:g} where {self.naive.fails}.")
        worst = max((a.max_ulp for a in (self.py_accuracy, self.c_accuracy) if a), default=0.0)
        if worst > 4:
            lines.append("Beyond 4 ulp only where the problem is ill-conditioned (near zeros of the function, "
                         "large arguments): the rounding of the inputs alone costs condition number × eps there.")
        return "\n".join(lines)


def kernel_name(result_id: str) -> str:
    return result_id.split(".", 1)[1].replace(".", "_")


def closed_form(expr: sp.Expr) -> bool:
    from sympy.core.function import AppliedUndef
    return not expr.has(sp.Integral) and not expr.atoms(AppliedUndef) and expr.free_symbols != set()


def _draw(a: KernelArg, rng: random.Random) -> float:
    """A seeded point of one argument's domain: log-uniform for a geometric one, else uniform."""
    if a.log and a.lo > 0:
        return math.exp(rng.uniform(math.log(a.lo), math.log(a.hi)))
    return rng.uniform(a.lo, a.hi)


def sample_points(args: Sequence[KernelArg], seed: str, n: int = 160, hard: bool = True,
                  pieces: str | None = None) -> list[tuple[float, ...]]:
    """Seeded points of the domain: its corners, hard points near 0, and random interior points;
    with `hard`, also every decade of a geometric argument, and every switch and knot of the
    stable forms for the argument named `pieces` (:func:`_hard_points`)."""
    rng = random.Random(seed)

    def special(a: KernelArg) -> list[float]:
        vals = [a.lo, a.hi]
        if a.lo <= 0 <= a.hi and not a.log:
            vals += [v for v in (1e-9, 1e-4, 0.5 * math.pi, math.pi, 3.0) if a.lo <= v <= a.hi]
        return vals
    pts = []
    corner_sets = [special(a) for a in args]
    for i in range(min(64, math.prod(len(c) for c in corner_sets))):
        idx, p = i, []
        for c in corner_sets:
            p.append(c[idx % len(c)])
            idx //= len(c)
        pts.append(tuple(p))
    pts += [tuple(_draw(a, rng) for a in args) for _ in range(n)]
    if hard:
        pts += _hard_points(args, random.Random(seed + ":hard"), pieces)
    return sorted(set(pts), key=pts.index)


def _hard_points(args: Sequence[KernelArg], rng: random.Random, pieces: str | None = None) -> list[tuple[float, ...]]:
    """For each geometric argument: its ends and their neighbours and every decade; for the
    argument `pieces`, also every candidate switch and knot of the stable forms (SWITCHES,
    KNOTS) with the doubles just below and above it; the other arguments drawn at random."""
    out = []
    for i, a in enumerate(args):
        if not (a.log and a.lo > 0):
            continue
        vals = [a.lo, a.lo * 2, a.hi / 2, a.hi]
        vals += [10.0**e for e in range(math.ceil(math.log10(a.lo)), math.floor(math.log10(a.hi)) + 1)]
        if a.name == pieces:
            vals += [v for s in SWITCHES + KNOTS if a.lo < s < a.hi
                     for v in (math.nextafter(s, 0.0), s, math.nextafter(s, math.inf))]
        for v in vals:
            p = [_draw(b, rng) for b in args]
            p[i] = v
            out.append(tuple(p))
    return out


VERTEX_POINTS = 32     # sample points on the vertex curve of a quadratic skeleton


def kernel_sample(expr: sp.Expr, args: Sequence[KernelArg], seed: str) -> list[tuple[float, ...]]:
    """The sample a kernel of expr is measured on: with the switches and knots of its hard
    argument, and, where its skeleton is quadratic in an argument K, points on the vertex
    curve K = c(x) (:func:`vertex_curve`), where the plain form cancels most."""
    return list(_kernel_sample(expr, tuple(args), seed))


@functools.lru_cache(maxsize=256)
def _kernel_sample(expr: sp.Expr, args: tuple[KernelArg, ...], seed: str) -> tuple:
    hard = hard_argument(expr, args)
    pts = sample_points(args, seed, pieces=hard.name if hard is not None else None)
    pts += vertex_points(expr, args, seed)
    return tuple(sorted(set(pts), key=pts.index))


@functools.lru_cache(maxsize=256)
def vertex_points(expr: sp.Expr, args: tuple[KernelArg, ...], seed: str) -> list[tuple[float, ...]]:
    """Seeded points on the vertex curve K = c(x) inside the domain (:func:`vertex_curve`), if any."""
    curve = vertex_curve(expr, args)
    if curve is None:
        return []
    xname, kname, c = curve
    rng = random.Random(seed + ":vertex")
    ix, ik = [a.name for a in args].index(xname), [a.name for a in args].index(kname)
    out = []
    for _ in range(VERTEX_POINTS):
        p = [_draw(a, rng) for a in args]
        with mp.workdps(LEAF_DPS):       # c cancels like the leaves do as x → 0
            try:
                kv = float(c(mp.mpf(p[ix])))
            except ZeroDivisionError:
                continue
        if args[ik].lo <= kv <= args[ik].hi:
            p[ik] = kv
            out.append(tuple(p))
    return out


def _reference(expr: sp.Expr, syms) -> tuple[Callable, Callable]:
    """(f, κ): the expression in mpmath, and its condition number Σ|x_i ∂f/∂x_i|/|f|.

    The partial derivatives are forward differences at 80 digits with a relative step of
    1e-35 (truncation and rounding both ~1e-35 relative): as good as the symbolic derivative
    for a condition number, and far cheaper for the large kernels (K, n² of the suspension)."""
    f = sp.lambdify(syms, expr, modules="mpmath")

    def cond(*xs):
        v = f(*xs)
        if v == 0:
            return mp.inf
        with mp.workdps(80):
            xs = [mp.mpf(x) for x in xs]
            here, total = f(*xs), mp.mpf(0)
            for i, x in enumerate(xs):
                if x == 0:
                    continue
                h = abs(x) * mp.mpf(10) ** -35
                up = list(xs)
                up[i] = x + h
                total += abs(x * (f(*up) - here) / h)
        return total / abs(v)
    return f, cond


@functools.lru_cache(maxsize=64)
def _reference_of(expr: sp.Expr, syms: tuple) -> tuple[Callable, Callable]:
    return _reference(expr, list(syms))


@functools.lru_cache(maxsize=100_000)
def _truth_at(expr: sp.Expr, syms: tuple, p: tuple) -> tuple:
    """(50-digit value, condition number) of expr at the point p; every candidate form of a
    kernel is measured on the same points, so each is computed once."""
    f, cond = _reference_of(expr, syms)
    with mp.workdps(50):
        xs = [mp.mpf(x) for x in p]
        true = f(*xs)
        try:
            kappa = float(cond(*xs)) if true != 0 else math.inf
        except (ZeroDivisionError, OverflowError, ValueError):
            kappa = math.inf
        return true, kappa


def references(expr: sp.Expr, args: Sequence[KernelArg], points) -> tuple:
    """(50-digit value, κ) of expr at each point."""
    by = {s.name: s for s in expr.free_symbols}
    syms = tuple(by.get(a.name, sp.Symbol(a.name)) for a in args)
    return tuple(_truth_at(expr, syms, tuple(p)) for p in points)


def _errors(fn: Callable[..., float], expr: sp.Expr, args: Sequence[KernelArg], points, truths=None):
    """(point, ulp error, ulp error / max(1, κ)) at each point, against 50-digit mpmath of expr
    (or the given (value, κ) of each point); a non-finite value or an exception (overflow)
    counts as an infinite error."""
    truths = truths or references(expr, args, points)
    with mp.workdps(50):
        for p, (true, kappa) in zip(points, truths):
            try:
                got = fn(*p)
            except (OverflowError, ZeroDivisionError, ValueError):
                got = math.nan
            if not math.isfinite(got):
                yield p, math.inf, math.inf
            elif true == 0:
                err_ulp = 0.0 if got == 0 else abs(got) / math.ulp(0.0)
                yield p, err_ulp, 0.0 if abs(got) < 1e-300 else math.inf
            else:
                err_ulp = float(abs(mp.mpf(got) - true) / mp.mpf(math.ulp(float(true))))
                yield p, err_ulp, err_ulp / max(1.0, kappa)


def measure(fn: Callable[..., float], expr: sp.Expr, args: Sequence[KernelArg], points, truths=None) -> Accuracy:
    """ulp error of a double kernel against 50-digit mpmath of expr at the points."""
    worst_ulp = worst_scaled = 0.0
    worst_at: tuple = ()
    for p, err_ulp, scaled in _errors(fn, expr, args, points, truths):
        if not math.isfinite(err_ulp):
            return Accuracy(len(points), math.inf, math.inf, p)
        worst_ulp = max(worst_ulp, err_ulp)
        if scaled > worst_scaled:
            worst_scaled, worst_at = scaled, p
    return Accuracy(len(points), round(worst_ulp, 2), round(worst_scaled, 2), worst_at)


def measure_naive(expr_naive: sp.Expr, form: str, truth: sp.Expr, args: Sequence[KernelArg], points,
                  along: int = 0) -> Naive:
    """The naive form's accuracy on the points, and the ranges of argument number `along`
    where its scaled error exceeds BOUND (runs of consecutive failing points)."""
    errs = list(_errors(py_callable(expr_naive, args), truth, args, points))
    fin = [e for e in errs if math.isfinite(e[1])]
    worst = max(fin, key=lambda e: e[2], default=None)
    inf_any = len(fin) < len(errs)
    acc = Accuracy(len(points), math.inf if inf_any else round(max(e[1] for e in errs), 2),
                   math.inf if inf_any else round(worst[2], 2),
                   next((e[0] for e in errs if not math.isfinite(e[1])), worst[0] if worst else ()))
    runs, cur = [], None
    for p, _, scaled in sorted(errs, key=lambda e: e[0][along]):
        if scaled > BOUND:
            cur = [p[along], p[along]] if cur is None else [cur[0], p[along]]
        elif cur is not None:
            runs.append(cur)
            cur = None
    if cur is not None:
        runs.append(cur)
    name = args[along].name
    fails = "; ".join(f"{name} = {lo:.3g}" if lo == hi else f"{name} in [{lo:.3g}, {hi:.3g}]" for lo, hi in runs)
    return Naive(form, acc, fails or "nowhere on the sample")


def py_callable(expr: sp.Expr, args: Sequence[KernelArg]) -> Callable[..., float]:
    return _py_callable(expr, tuple(args))


@functools.lru_cache(maxsize=256)
def _py_callable(expr: sp.Expr, args: tuple[KernelArg, ...]) -> Callable[..., float]:
    by = {s.name: s for s in expr.free_symbols}
    syms = [by.get(a.name, sp.Symbol(a.name)) for a in args]
    return sp.lambdify(syms, expr, modules=["math", {"math": math}], printer=KernelPy)


def choose_form(expr: sp.Expr, args: Sequence[KernelArg], seed: str) -> tuple[str, sp.Expr, Accuracy, tuple[str, ...]]:
    """(rule, form, accuracy, notes): the rewrite rule whose Python evaluation is the most
    accurate (ties: rule order); when none holds BOUND and one argument alone feeds the
    transcendental functions, the piecewise stable forms of :func:`stable_forms` compete."""
    pts = sample_points(args, seed, 60, hard=False)   # the rules are ranked as before the stable forms
    best = None
    ser = near_zero_series(expr, args)
    trig = expr.has(sp.sin, sp.cos)
    for name, rule in REWRITES:
        if name in TRIG_RULES and not trig:
            continue
        try:
            cand = rule(expr)
        except Exception:  # a rule that does not apply is skipped
            continue
        if (name != "as-derived" and cand == expr) or not _same_numerically(cand, expr, args, seed):
            continue          # (a rule that changes nothing would only tie with the derived form)
        variants = [(name, cand)]
        if ser is not None:
            variants.append((name + "+series-near-t=0",
                             sp.Piecewise((ser[0], ser[1] < SERIES_PHASE), (cand, True))))
        for vname, v in variants:
            acc = measure(py_callable(v, args), expr, args, pts)
            if best is None or acc.max_scaled < best[2].max_scaled:
                best = (vname, v, acc, ())
    full = kernel_sample(expr, args, seed)
    # decided on the full sample: the hard points of the stable pieces are there
    on_full = measure(py_callable(best[1], args), expr, args, full)
    if best[2].max_scaled > BOUND or on_full.max_scaled > BOUND:
        best = (best[0], best[1], on_full, best[3])
        # the vertex form competes where the vertex lies inside the domain
        for label, form, notes in stable_forms(expr, args, vertex=bool(vertex_points(expr, tuple(args), seed))):
            acc = measure(py_callable(form, args), expr, args, full)
            if acc.max_scaled < best[2].max_scaled:
                hard = hard_argument(expr, args).name
                best = (f"piecewise in {hard}: series below a switch, e^(-{hard}) or derived form above{label}",
                        form, acc, notes)
    return best


def _same_numerically(a, b, args, seed) -> bool:
    """A rewrite must not change the function: compare at 8 interior points in double."""
    fa, fb = (py_callable(x, args) for x in (a, b))
    for p in sample_points(args, seed, 8, hard=False)[-8:]:
        va, vb = fa(*p), fb(*p)
        if abs(va - vb) > 1e-9 * max(1.0, abs(vb)):
            return False
    return True


def kernel_of(result: Result) -> Kernel | None:
    spec = result.spec
    if spec.kernel is None or not closed_form(result.derived):
        return None
    names = {a.name for a in spec.kernel.args}
    if not {s.name for s in result.derived.free_symbols} <= names:
        missing = {s.name for s in result.derived.free_symbols} - names
        raise ValueError(f"{result.id}: kernel arguments miss {sorted(missing)}")
    args = tuple(a for a in spec.kernel.args if a.name in {s.name for s in result.derived.free_symbols})
    name = kernel_name(result.id)
    rule, expr, acc, notes = choose_form(result.derived, args, name)
    k = Kernel(name, result.id, args, expr, rule, spec.kernel.doc or spec.title, spec.source.ref(), notes=notes)
    pts = kernel_sample(result.derived, args, name)
    truths = references(result.derived, args, pts)
    k = Kernel(**{**k.__dict__, "bodies": bodies(k)})
    full = measure(emitted_py(k), result.derived, args, pts, truths)      # the code as emitted
    form, naive_expr = naive_form(result, args)
    hard = hard_argument(result.derived, args)
    along = args.index(hard) if hard is not None else 0
    naive = measure_naive(naive_expr, form, result.derived, args, pts, along)
    return Kernel(**{**k.__dict__, "py_accuracy": full, "naive": naive, "reference": truths})


def emitted_py(k: Kernel) -> Callable[..., float]:
    """The kernel's Python function exactly as emitted (:func:`py_function`), compiled here: the
    accuracy reported is that of the generated code, whose subexpressions and branches may round
    differently from the single expression the forms were ranked with."""
    namespace = {"math": math}
    exec(compile(py_function(k), f"<kernel {k.name}>", "exec"), namespace)   # our own generated code
    return namespace[k.name]


def naive_form(result: Result, args: Sequence[KernelArg]) -> tuple[str, sp.Expr]:
    """("printed", the printed formula with its symbols read the obvious way in double), when it is
    the same function as the derived one (checked at three points at 50 digits); otherwise
    ("as derived", the derived form evaluated as it stands)."""
    names = {a.name for a in args}
    if result.printed is not None:
        defs = result.spec.kernel.naive_defs or result.spec.defs
        pv = result.printed.subs(dict(defs), simultaneous=True)
        if {s.name for s in pv.free_symbols} <= names and _same_function(pv, result.derived, args):
            return "printed", pv
    return "as derived", result.derived


def _same_function(a: sp.Expr, b: sp.Expr, args: Sequence[KernelArg]) -> bool:
    fa, fb = (sp.lambdify([sp.Symbol(x.name, **_assumptions(e, x.name)) for x in args], e, modules="mpmath")
              for e in (a, b))
    with mp.workdps(50):
        for p in sample_points(args, "same", 3, hard=False)[-3:]:
            va, vb = fa(*[mp.mpf(v) for v in p]), fb(*[mp.mpf(v) for v in p])
            if abs(va - vb) > mp.mpf(10) ** -30 * max(1, abs(vb)):
                return False
    return True


def _assumptions(e: sp.Expr, name: str) -> dict:
    s = next((x for x in e.free_symbols if x.name == name), None)
    return s.assumptions0 if s is not None else {}


# ----------------------------------------------------------------- C compilation (tests, derive)


def compile_c(c_text: str, workdir: Path) -> ctypes.CDLL:
    """Compile one C file into a shared library with the system compiler and load it."""
    src = workdir / "k.c"
    lib = workdir / "k.so"
    src.write_text(c_text)
    done = subprocess.run(["cc", "-std=c99", "-O2", "-fPIC", "-shared", "-o", str(lib), str(src), "-lm"],
                          capture_output=True, text=True)
    if done.returncode:
        raise RuntimeError(f"cc failed: {done.stderr.strip()[:2000]}")
    return ctypes.CDLL(str(lib))


def c_callable(lib: ctypes.CDLL, k: Kernel) -> Callable[..., float]:
    fn = getattr(lib, k.name)
    fn.restype = ctypes.c_double
    fn.argtypes = [ctypes.c_double] * len(k.args)
    return fn


def c_accuracy(lib: ctypes.CDLL, k: Kernel, result: Result) -> Accuracy:
    """The accuracy of one compiled C kernel on its sample."""
    return measure(c_callable(lib, k), result.derived, k.args, kernel_sample(result.derived, k.args, k.name),
                   k.reference or None)
