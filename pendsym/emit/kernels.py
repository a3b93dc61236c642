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

# ----------------------------------------------------------------- stable forms in one hard argument
#
# Forms such as 1/u² − 1/sh²u or 1 − 2 th(u/2)/u cancel catastrophically as u → 0, and
# sh u overflows for large u.  The mechanism, for any memoir: the expression is split into
# a skeleton in the other arguments whose coefficients ("leaves") are functions of the one
# hard argument x alone (:func:`split_hard`); each leaf gets a piecewise form chosen by
# measurement against 50-digit mpmath on a grid of x (:func:`leaf_form`): its Taylor
# (Laurent) series in x, generated exactly from the SymPy form (:func:`laurent`), below a
# switch point taken from SWITCHES, and above it the leaf as derived or rewritten in
# e^{−x/q} with expm1 (:func:`exp_form`), which neither overflows nor cancels at large x.

BOUND = 4.0    # ulp × max(1, condition number): the accuracy a kernel must hold
SWITCHES = (0.125, 0.25, 0.5, 1.0, 1.5)   # candidate switch points of a leaf (sampled by the tests)
SERIES_SPAN = 64                           # orders kept beyond the leading one
LEAF_POINTS = 160                          # log-spaced grid on which a leaf's form is chosen
MID_ENDS = (3.0, 4.0, 6.0)                 # candidate ends of a middle Taylor piece (from the last switch)
LEAF_DPS = 120                             # a leaf may lose 40 digits to cancellation at x = 1e-6
MID_TERMS = 48                             # terms of the middle Taylor piece


def hard_argument(expr: sp.Expr, args: Sequence[KernelArg]) -> KernelArg | None:
    """The argument that alone feeds every transcendental function of expr, if any.

    It must be sampled geometrically from lo > 0 (a near-zero cancellation is the problem
    the mechanism solves).
    """
    funcs = [f for f in expr.atoms(sp.Function) if f.free_symbols]
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
        others = sorted(e.free_symbols - {x}, key=lambda s: s.name)
        if not others:
            return leaf(e)
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


def exp_form(c: sp.Expr, x: sp.Symbol) -> sp.Expr | None:
    """c (exponentials or hyperbolic functions of rational multiples of x) as a rational
    function of E = e^{−x/q}, factored; each factor E^j − 1 is written with expm1."""
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

    def stable(p: sp.Expr) -> sp.Expr:
        cf, facs = sp.factor_list(p)
        out = cf
        for f, m in facs:
            terms = sp.Poly(f, E).terms() if f.free_symbols == {E} else None
            if terms and len(terms) == 2 and terms[1][0] == (0,) and terms[0][1] == -terms[1][1]:
                j = terms[0][0][0]          # c(E^j − 1) = c·expm1(−j x/q)
                f = terms[0][1] * expm1(-j * x / q)
            out *= f**m
        return out.subs(E, sp.exp(-x / q))
    return stable(num) / stable(den)


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
    n = LEAF_POINTS
    pts = [math.exp(math.log(a.lo) + (math.log(a.hi) - math.log(a.lo)) * i / (n - 1)) for i in range(n)]
    pts += [0.5 + 0.125 * i for i in range(64)]        # the middle range, where the far forms cancel
    for s in SWITCHES + MID_ENDS:
        pts += [math.nextafter(s, 0.0), s, s * (1 + 1e-3), s * (1 - 1e-3)]
    return sorted(v for v in set(pts) if a.lo <= v <= a.hi)


def taylor_expr(ref: Callable, m: int, lo: float, hi: float, x: sp.Symbol, terms: int = MID_TERMS) -> sp.Expr:
    """x^m times the Taylor polynomial of x^{−m}·leaf about the middle of [lo, hi], in Horner form.

    The coefficients are computed from the leaf's own SymPy form (evaluated by mpmath at 40
    digits) by the Cauchy integral on a circle of radius 1.3·(hi − lo)/2 (a 128-point
    trapezoidal rule), so the few digits the leaf loses to cancellation there cost nothing.
    """
    c, r, n = (lo + hi) / 2, 1.3 * (hi - lo) / 2, 128
    with mp.workdps(40):
        g = [ref(c + r * mp.expjpi(mp.mpf(2 * j) / n)) / (c + r * mp.expjpi(mp.mpf(2 * j) / n)) ** m
             for j in range(n)]
        cs = [mp.re(mp.fsum(g[j] * mp.expjpi(mp.mpf(-2 * j * k) / n) for j in range(n))) / n / mp.mpf(r) ** k
              for k in range(terms)]
    h = sp.S.Zero
    dx = x - sp.Float(c, 17)
    for cf in reversed(cs):
        h = sp.Float(mp.nstr(cf, 20), 20) + dx * h
    return x**m * h


def _max_ulp(fn: Callable, xs: Sequence[float], truth: Sequence) -> float:
    worst = 0.0
    for xv, tv in zip(xs, truth):
        try:
            got = fn(xv)
        except (OverflowError, ZeroDivisionError, ValueError):
            return math.inf
        if not math.isfinite(got):
            return math.inf
        if abs(tv) < 1e-290:
            continue
        worst = max(worst, float(abs(mp.mpf(got) - tv) / mp.mpf(math.ulp(float(tv)))))
    return worst


@dataclass(frozen=True)
class LeafForm:
    expr: sp.Expr
    desc: str            # how it is evaluated, for the docstring
    max_ulp: float       # measured on the leaf grid
    switch: float | None


def leaf_form(c: sp.Expr, x: sp.Symbol, a: KernelArg) -> LeafForm:
    """The most accurate of: c as derived, its e^{−x} form, and either with the series below a switch."""
    xs = _leaf_grid(a)
    with mp.workdps(LEAF_DPS):
        ref = sp.lambdify([x], c, modules="mpmath")
        truth = [ref(mp.mpf(v)) for v in xs]
        fars = [("as derived", c)]
        ef = exp_form(c, x)
        if ef is not None:
            fars.append(("e^{-%s} form" % a.name, ef))
        lau = laurent(c, x)
        best: LeafForm | None = None

        def consider(desc, form, sw):
            nonlocal best
            err = _max_ulp(sp.lambdify([x], form, modules="math"), xs, truth)
            if best is None or err < best.max_ulp:
                best = LeafForm(form, desc, round(err, 2), sw)
        for fname, far in fars:
            consider(fname, far, None)
            if lau is None:
                continue
            ser = series_expr(lau[0], lau[1], x)
            for s in SWITCHES:
                if a.lo < s < a.hi:
                    consider(f"series (x^{lau[0]}·{SERIES_SPAN + 1} terms) for {a.name} < {s:g}, {fname} above",
                             sp.Piecewise((ser, x < s), (far, True)), s)
        if best.max_ulp > 2 and lau is not None and best.switch is not None:
            # a middle Taylor piece from the last switch, where the far form still cancels
            s1 = max(w for w in SWITCHES if a.lo < w < a.hi)
            head = series_expr(lau[0], lau[1], x)
            far_desc = best.desc.split(", ")[-1].replace(" above", "")
            far = best.expr.args[-1][0]
            for s2 in MID_ENDS:
                if s1 < s2 < a.hi:
                    mid = taylor_expr(ref, lau[0], s1, s2, x)
                    consider(f"series for {a.name} < {s1:g}, Taylor ({MID_TERMS} terms) about {(s1 + s2) / 2:g} "
                             f"below {s2:g}, {far_desc} above",
                             sp.Piecewise((head, x < s1), (mid, x < s2), (far, True)), s1)
    return best


def stable_form(expr: sp.Expr, args: Sequence[KernelArg]) -> tuple[sp.Expr, tuple[str, ...]] | None:
    """expr with every leaf of its hard argument in its measured best piecewise form, and notes."""
    a = hard_argument(expr, args)
    if a is None:
        return None
    x = next(s for s in expr.free_symbols if s.name == a.name)
    skeleton, leaves = split_hard(expr, x)
    forms = {s: leaf_form(c, x, a) for s, c in leaves.items()}
    notes = tuple(f"{sp.sstr(leaves[s])[:60]}: {f.desc} ({f.max_ulp:g} ulp)" for s, f in forms.items())
    return skeleton.xreplace({s: f.expr for s, f in forms.items()}), notes


# ----------------------------------------------------------------- printers


class KernelC(C99CodePrinter):
    """C99 printer: small integer powers as products, no pow() for them; π as a literal
    (M_PI is POSIX, not C99)."""

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
    """Python printer for math-only kernels (no SymPy at import)."""


@functools.lru_cache(maxsize=256)
def _cse(expr: sp.Expr) -> tuple:
    """Common subexpressions of a kernel (the C, header and Python printers share them)."""
    subs, (red,) = sp.cse([expr], symbols=sp.numbered_symbols("x_"), optimizations="basic")
    return tuple(subs), red


def _body(expr: sp.Expr, printer, decl: str, end: str) -> tuple[list[str], str]:
    subs, red = _cse(expr)
    lines = [f"{decl}{printer.doprint(s)} = {printer.doprint(v)}{end}" for s, v in subs]
    return lines, printer.doprint(red)


def identifier(name: str) -> str:
    """A C and Python identifier for a symbol's name (p' → p_prime)."""
    out = re.sub(r"\W", "_", name.replace("'", "_prime"))
    out = out if out[:1].isalpha() else "a_" + out
    return out + "_" if keyword.iskeyword(out) else out          # lambda → lambda_


def _printable(k: "Kernel") -> sp.Expr:
    """The kernel's expression with every argument renamed to its identifier."""
    by = {x.name: x for x in k.expr.free_symbols}
    return k.expr.xreplace({by[a.name]: sp.Symbol(identifier(a.name), real=True) for a in k.args if a.name in by})


def c_function(k: "Kernel") -> tuple[str, str]:
    """(prototype, definition) of a kernel in C99."""
    pr = KernelC()
    args = ", ".join(f"double {identifier(a.name)}" for a in k.args)
    proto = f"double {k.name}({args})"
    lines, ret = _body(_printable(k), pr, "const double ", ";")
    return proto, proto + "\n{\n" + "".join(f"    {ln}\n" for ln in lines) + f"    return {ret};\n}}\n"


def py_function(k: "Kernel") -> str:
    pr = KernelPy(settings={"fully_qualified_modules": True})
    lines, ret = _body(_printable(k), pr, "", "")
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


def sample_points(args: Sequence[KernelArg], seed: str, n: int = 160, hard: bool = True) -> list[tuple[float, ...]]:
    """Seeded points of the domain: its corners, hard points near 0, and random interior points;
    with `hard`, also every decade and candidate switch of a geometric argument (:func:`_hard_points`)."""
    rng = random.Random(seed)

    def draw(a: KernelArg) -> float:
        if a.log and a.lo > 0:
            return math.exp(rng.uniform(math.log(a.lo), math.log(a.hi)))
        return rng.uniform(a.lo, a.hi)

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
    pts += [tuple(draw(a) for a in args) for _ in range(n)]
    if hard:
        pts += _hard_points(args, random.Random(seed + ":hard"))
    return sorted(set(pts), key=pts.index)


def _hard_points(args: Sequence[KernelArg], rng: random.Random) -> list[tuple[float, ...]]:
    """For each geometric argument: its ends and their neighbours, every decade, and every
    candidate switch of the stable forms (SWITCHES) with the doubles just below and above it,
    the other arguments drawn at random."""
    def draw(a: KernelArg) -> float:
        if a.log and a.lo > 0:
            return math.exp(rng.uniform(math.log(a.lo), math.log(a.hi)))
        return rng.uniform(a.lo, a.hi)
    out = []
    for i, a in enumerate(args):
        if not (a.log and a.lo > 0):
            continue
        vals = [a.lo, a.lo * 2, a.hi / 2, a.hi]
        vals += [10.0**e for e in range(math.ceil(math.log10(a.lo)), math.floor(math.log10(a.hi)) + 1)]
        vals += [v for s in SWITCHES + MID_ENDS if a.lo < s < a.hi
                 for v in (math.nextafter(s, 0.0), s, math.nextafter(s, math.inf))]
        for v in vals:
            p = [draw(b) for b in args]
            p[i] = v
            out.append(tuple(p))
    return out


def _reference(expr: sp.Expr, syms) -> tuple[Callable, Callable]:
    f = sp.lambdify(syms, expr, modules="mpmath")
    grads = [sp.lambdify(syms, sp.diff(expr, s), modules="mpmath") for s in syms]

    def cond(*xs):
        v = f(*xs)
        if v == 0:
            return mp.inf
        return sum(abs(x * g(*xs)) for x, g in zip(xs, grads)) / abs(v)
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


def _errors(fn: Callable[..., float], expr: sp.Expr, args: Sequence[KernelArg], points):
    """(point, ulp error, ulp error / max(1, κ)) at each point, against 50-digit mpmath of expr;
    a non-finite value or an exception (overflow) counts as an infinite error."""
    by = {s.name: s for s in expr.free_symbols}
    syms = tuple(by.get(a.name, sp.Symbol(a.name)) for a in args)
    with mp.workdps(50):
        for p in points:
            true, kappa = _truth_at(expr, syms, tuple(p))
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


def measure(fn: Callable[..., float], expr: sp.Expr, args: Sequence[KernelArg], points) -> Accuracy:
    """ulp error of a double kernel against 50-digit mpmath of expr at the points."""
    worst_ulp = worst_scaled = 0.0
    worst_at: tuple = ()
    for p, err_ulp, scaled in _errors(fn, expr, args, points):
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
    by = {s.name: s for s in expr.free_symbols}
    syms = [by.get(a.name, sp.Symbol(a.name)) for a in args]
    return sp.lambdify(syms, expr, modules="math")


def choose_form(expr: sp.Expr, args: Sequence[KernelArg], seed: str) -> tuple[str, sp.Expr, Accuracy, tuple[str, ...]]:
    """(rule, form, accuracy, notes): the rewrite rule whose Python evaluation is the most
    accurate (ties: rule order); when none holds BOUND and one argument alone feeds the
    transcendental functions, the piecewise stable form of :func:`stable_form` competes."""
    pts = sample_points(args, seed, 60, hard=False)   # the rules are ranked as before the stable forms
    best = None
    ser = near_zero_series(expr, args)
    for name, rule in REWRITES:
        try:
            cand = rule(expr)
        except Exception:  # a rule that does not apply is skipped
            continue
        if not _same_numerically(cand, expr, args, seed):
            continue
        variants = [(name, cand)]
        if ser is not None:
            variants.append((name + "+series-near-t=0",
                             sp.Piecewise((ser[0], ser[1] < SERIES_PHASE), (cand, True))))
        for vname, v in variants:
            acc = measure(py_callable(v, args), expr, args, pts)
            if best is None or acc.max_scaled < best[2].max_scaled:
                best = (vname, v, acc, ())
    if best[2].max_scaled > BOUND:
        stable = stable_form(expr, args)
        if stable is not None:
            # decided on the full sample: the hard points of the stable pieces are there
            full = sample_points(args, seed)
            acc = measure(py_callable(stable[0], args), expr, args, full)
            if acc.max_scaled < measure(py_callable(best[1], args), expr, args, full).max_scaled:
                hard = hard_argument(expr, args).name
                best = (f"piecewise in {hard}: series below a switch, e^(-{hard}) or derived form above",
                        stable[0], acc, stable[1])
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
    pts = sample_points(args, name)
    full = measure(py_callable(expr, args), result.derived, args, pts)
    form, naive_expr = naive_form(result, args)
    hard = hard_argument(result.derived, args)
    along = args.index(hard) if hard is not None else 0
    naive = measure_naive(naive_expr, form, result.derived, args, pts, along)
    return Kernel(**{**k.__dict__, "py_accuracy": full, "naive": naive})


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
    return measure(c_callable(lib, k), result.derived, k.args, sample_points(k.args, k.name))
