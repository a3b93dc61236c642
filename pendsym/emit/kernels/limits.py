"""The accepted domain of a kernel: its declared box, down to 0 for the hard argument where
the form as emitted gives the limit there, and up to +inf where its limit at +∞ is finite.

A geometric argument (``log=True``, lo > 0) such as u is declared from lo = 1e-6, but many
kernels have a finite limit as u → 0 (v_0 → λ/2, β_1 → 0) and a caller may pass u = 1e-300
or u = 0.  The emitted code is tried there (:data:`TINY`) at seeded values of the other
arguments, against the derived form at enough digits for its cancellation (:func:`ref_dps`);
where it holds the bound at every such point, the accepted domain of that argument reaches
down to 0 (the deep audit then samples (0, lo) as well); elsewhere below lo is a domain error.

Above hi (u = 700: e^{−u} < 1e-304) the same rule gives +∞ (for u, the thread): where the derived form
has a finite limit as the hard argument x → ∞, the kernel evaluates above hi its **far form**
(:func:`far_form`: the exponentially small terms dropped, the rest written in 1/x, so that x = inf
gives the limit), and the accepted domain reaches up to +inf if the emitted code holds the bound at
every value of :data:`far_values` (the reference at +inf: the derived form at LIMIT_FAR[1], or 0 where
it falls by 1e-30 from LIMIT_FAR[0]).  Where the far form fails there (it may overflow in double inside a root,
λ⁴/u⁴ at u = 1e80, where its value is the limit already), a third region is tried: above U_flat
(:func:`flat_form`: where the far form's first correction is below 2⁻⁶⁰ relative) the limit itself, free of x.
"""
from __future__ import annotations

import math
import random
import sys
from typing import Sequence

import mpmath as mp
import sympy as sp

from ...result import KernelArg
from .leaves import hard_argument
from .rules import _in_E
from .measure import BOUND, ref_dps

# 0, subnormals, then every third decade and a seeded point inside each (a sparser list let through
# F at u = 2.8e-65 and F_max at α = 1.2e-157: the accepted domain must be measured as densely as the audit)
TINY = (0.0, 5e-324, 1e-320, 1e-310) + tuple(m * 10.0 ** -k for k in range(306, 6, -3) for m in (1.0, 2.8))
TRIES = 4             # seeded values of the other arguments at each tiny value
LIMIT_AT = (1e-40, 1e-80)   # the limit at 0: the derived form at 1e-80, or 0 where it falls by 1e-30 from 1e-40
LIMIT_FAR = (1e40, 1e80)    # the limit at +inf: the derived form at 1e80, or 0 where it falls by 1e-30 from 1e40
FAR_DIGITS = 3              # more digits of the reference per decade of x above 1: the derived form at x = 1e60 may
                            # cancel like x³ (Γ2 at u = 1e60 was refused against a 50-digit reference)
FAR_DECADES = (3, 4, 5, 6, 8, 10, 12, 15, 16, 17, 20, 30, 40, 60, 80, 100, 150, 200, 250, 300, 308)


def far_values(hi: float) -> tuple[float, ...]:
    """The values above hi tried (and sampled by make audit): the double after hi, a few just above it,
    every listed decade (each also at 2.8×), the largest double and +inf."""
    vals = [math.nextafter(hi, math.inf), hi * (1 + 1e-9), hi * 1.01, hi * 1.07, hi * 1.5, hi * 2]
    vals += [m * 10.0 ** k for k in FAR_DECADES for m in (1.0, 2.8) if m * 10.0 ** k < math.inf]
    return tuple(sorted({v for v in vals if hi < v < math.inf})) + (sys.float_info.max, math.inf)


def accepted_domain(expr: sp.Expr, args: Sequence[KernelArg], seed: str, form: sp.Expr) -> tuple:
    """((lo, hi), …) of each argument: the declared range, with lo = 0 for the hard argument where
    the emitted form holds the bound at every tiny value (0 included: there the reference is the
    derived form at LIMIT_AT, where the even or finite limit is reached)."""
    dom = [(a.lo, a.hi) for a in args]
    hard = hard_argument(expr, args)
    if hard is None:
        return tuple(dom)
    from .compile import emitted_py          # (compile imports this module's users)
    i = list(args).index(hard)
    dom[i] = (0.0, hard.hi)
    fn = emitted_py(seed, args, form, tuple(dom))
    syms = [next(s for s in expr.free_symbols if s.name == a.name) for a in args]
    f = sp.lambdify(syms, expr, modules="mpmath", cse=True)
    rng = random.Random(seed + ":limits")
    for x in TINY:
        for _ in range(TRIES):
            p = [rng.uniform(a.lo, a.hi) if not a.log else math.exp(rng.uniform(math.log(a.lo), math.log(a.hi)))
                 for a in args]
            p[i] = x
            at = list(p)
            at[i] = x if x > 0 else LIMIT_AT[1]
            if not _holds(fn, f, p, at, zero=x == 0 and _vanishes(f, p, i)):
                return tuple((a.lo, a.hi) for a in args)
    return tuple(dom)


def _vanishes(f, p: list, i: int, at_points: tuple = LIMIT_AT) -> bool:
    """The derived form tends to 0 as argument i → 0 (it falls by 1e-30 from 1e-40 to 1e-80), or,
    with LIMIT_FAR, as it → +∞."""
    values = []
    for x in at_points:
        at = list(p)
        at[i] = x
        with mp.workdps(far_dps(at)):
            values.append(abs(f(*[mp.mpf(v) for v in at])))
    return values[1] <= mp.mpf(10) ** -30 * values[0]


def far_dps(p) -> int:
    """Digits for the derived form at p: :func:`ref_dps`, plus FAR_DIGITS for each decade of its largest finite
    coordinate above 1."""
    big = max((abs(v) for v in p if math.isfinite(v)), default=1.0)
    return ref_dps(p) + FAR_DIGITS * max(0, math.ceil(math.log10(max(big, 1.0))))


def _holds(fn, f, p: list, at: list, zero: bool = False) -> bool:
    """The kernel at p holds the bound against the derived form at `at` (with `zero`: the limit
    is 0, and the kernel must give below 1e-300 in magnitude)."""
    try:
        got = float(fn(*p))
    except (ValueError, OverflowError, ZeroDivisionError):
        return False
    if zero:
        return math.isfinite(got) and abs(got) < 1e-300
    with mp.workdps(far_dps(at)):
        xs = [mp.mpf(v) for v in at]
        true = f(*xs)
        if not math.isfinite(got) or not mp.isfinite(true):
            return False
        if true == 0:
            return abs(got) < 1e-300
        # in ulp of the true value, a subnormal one included (ulp 5e-324, as make audit measures it):
        # "below 1e-300 passes" let through F_max at α = 1e-156, 1.5e4 ulp (the subnormal sin²(α/2)
        # times 4ghm/l); no κ here: its forward differences are taken at fewer digits than such points need
        return abs(mp.mpf(got) - true) <= BOUND * mp.mpf(math.ulp(float(true)))


# ----------------------------------------------------------------- above hi: the limit at +inf
def _leading(p: sp.Expr, E: sp.Symbol) -> tuple[int, sp.Expr]:
    """(k, c): the lowest power E^k of the polynomial p in E, and its coefficient."""
    poly = sp.Poly(p, E)
    k = min(m for (m,), _ in poly.terms())
    return k, sp.expand(poly.as_expr().coeff(E, k)) if k else sp.expand(p.subs(E, 0))


def _cancelled(e: sp.Expr, t: sp.Symbol) -> sp.Expr:
    """e with each maximal part rational in t cancelled to P(t)/Q(t) (roots, Piecewise and functions
    are kept as units, each normalised inside), so that t = 0 gives a value where e has one."""
    units: dict = {}

    def hide(n):
        if n.is_Atom or not n.has(t):
            return n
        if isinstance(n, sp.Piecewise):
            d = sp.Dummy()
            units[d] = sp.Piecewise(*[(_cancelled(b, t), c if c in (sp.true, sp.false)
                                       else c.func(*[_cancelled(a, t) for a in c.args])) for b, c in n.args])
            return d
        if (n.is_Pow and not n.exp.is_Integer) or isinstance(n, sp.Function):
            d = sp.Dummy()
            units[d] = n.func(*[_cancelled(a, t) for a in n.args])
            return d
        return n.func(*[hide(a) for a in n.args])
    return sp.cancel(hide(e)).xreplace(units)


def far_form(expr: sp.Expr, x: sp.Symbol) -> sp.Expr | None:
    """The form of expr for large x (above the declared hi, where e^{−x} < 1e-304): the exponentially
    small terms dropped, written in 1/x so that x = inf gives the limit; None where that is not possible.

    A rational function of E = e^{−x/q} and x (:func:`.rules._in_E`) keeps the leading terms of its
    numerator and denominator, c(x)·E^k (k < 0: it grows, no finite limit); otherwise th and coth of
    c·x (c > 0) are 1.  The rest is written in t = 1/x, cancelled (:func:`_cancelled`), and t = 1/x."""
    got = _far_rest(expr, x)
    if got is None:
        return None
    rest, t, decay = got
    return _in_reciprocal(rest, t, x) * decay


def _far_rest(expr: sp.Expr, x: sp.Symbol) -> tuple | None:
    """(rest, t, decay): :func:`far_form` before t = 1/x, rest(t) cancelled in t = 1/x, times decay
    (e^{−k·x/q} where the form is exponentially small, else 1); None where there is no far form."""
    t = sp.Dummy("t", positive=True)
    got = _in_E(expr, x)
    if got is not None:
        num, den, E, q = got
        (a, n_a), (b, d_b) = _leading(sp.expand(num), E), _leading(sp.expand(den), E)
        if a < b:
            return None
        return _cancelled((n_a / d_b).subs(x, 1 / t), t), t, (sp.exp(-(a - b) * x / q) if a > b else sp.Integer(1))
    hyper = [f for f in expr.atoms(sp.Function) if f.has(x) and not isinstance(f, sp.Piecewise)]
    if not hyper or any(not isinstance(f, (sp.tanh, sp.coth)) or not (f.args[0] / x).is_positive for f in hyper):
        return None
    rest = expr.xreplace({f: sp.Integer(1) for f in hyper}).subs(x, 1 / t)
    return _cancelled(rest, t), t, sp.Integer(1)


FLAT_BITS = 60        # above U_flat every 1/x correction of the far form is below 2⁻⁶⁰ relative: the limit itself
FLAT_SAMPLES = 64     # seeded points of the other arguments (and the box's corners) for U_flat's ratio |c_1/c_0|


def flat_form(expr: sp.Expr, args: Sequence[KernelArg], x: sp.Symbol, seed: str) -> tuple | None:
    """(U_flat, limit): the limit at x = +inf (the far form at t = 1/x = 0, free of x), and the x above which the
    far form's first correction c_1·t (rest(t) = c_0 + c_1 t + O(t²)) is below 2^−FLAT_BITS of c_0, with c_1/c_0
    at its largest over the box's corners and FLAT_SAMPLES seeded points of the other arguments, times 2¹⁰,
    rounded up to a power of 10.  Above U_flat the far form in double may overflow inside a root (λ⁴/u⁴ at
    u = 1e80 in Python) where its value is the limit already.  None where the far form decays exponentially,
    its limit or first correction is not finite, or U_flat would not be finite."""
    got = _far_rest(expr, x)
    if got is None or got[2] != 1:
        return None
    rest, t, _ = got
    limit, first = rest.subs(t, 0), sp.diff(rest, t).subs(t, 0)
    if limit.has(x) or first.has(x) or limit.has(t) or first.has(t):
        return None
    others = [a for a in args if a.name != x.name]
    syms = [next(s for s in expr.free_symbols if s.name == a.name) for a in others]
    ratio = sp.lambdify(syms, first / limit, modules="mpmath")
    rng = random.Random(seed + ":flat")
    corners = [[(a.lo, a.hi)[(k >> j) & 1] for j, a in enumerate(others)] for k in range(2 ** len(others))]
    seeded = [[rng.uniform(a.lo, a.hi) if not a.log else math.exp(rng.uniform(math.log(a.lo), math.log(a.hi)))
               for a in others] for _ in range(FLAT_SAMPLES)]
    worst = mp.mpf(0)
    with mp.workdps(50):
        for p in corners + seeded:
            try:
                r = abs(ratio(*[mp.mpf(v) for v in p]))
            except (ZeroDivisionError, ValueError):
                return None
            if not mp.isfinite(r):
                return None
            worst = max(worst, r)
        bound = worst * mp.mpf(2) ** (FLAT_BITS + 10)
        if bound == 0:
            return None
        u_flat = 10.0 ** max(0, int(mp.ceil(mp.log10(bound))))
    return (u_flat, limit) if math.isfinite(u_flat) else None


def _in_reciprocal(e: sp.Expr, t: sp.Symbol, x: sp.Symbol) -> sp.Expr:
    """e (P(t)/Q(t)) with P and Q in Horner form in t, then t = 1/x: each level divides by x once, so no power
    x^n is formed (x³ overflows above 5.6e102: I_λ's far form as 1/u³ failed at u = 1e150)."""
    num, den = sp.fraction(e)
    nested = []
    for p in (num, den):
        try:
            nested.append(sp.horner(sp.expand(p), wrt=t) if p.has(t) and sp.Poly(p, t).degree() > 1 else p)
        except sp.PolynomialError:
            nested.append(p)
    return (nested[0] / nested[1]).subs(t, 1 / x)


def beyond(expr: sp.Expr, args: Sequence[KernelArg], seed: str, form: sp.Expr, domain: tuple) -> tuple | None:
    """(form, domain) reaching up to +inf for the hard argument: form below its declared hi and
    :func:`far_form` above it, where the emitted code holds the bound at every value of
    :func:`far_values` (at +inf against the derived form's limit); None elsewhere."""
    hard = hard_argument(expr, args)
    if hard is None:
        return None
    x = next(s for s in expr.free_symbols if s.name == hard.name)
    far = far_form(expr, x)
    if far is None:
        return None
    from .compile import emitted_py          # (compile imports this module's users)
    i = list(args).index(hard)
    dom = list(domain)
    dom[i] = (dom[i][0], math.inf)
    dom = tuple(dom)
    whole = sp.Piecewise((far, x > hard.hi), (form, True))
    if _far_holds(emitted_py(seed, args, whole, dom), expr, args, i, seed, hard.hi):
        return whole, dom
    # the far form may overflow in double where its corrections are already below the last bit (K, n²: λ⁴/u⁴ in a
    # root): above U_flat the limit itself (issue #13)
    flat = flat_form(expr, args, x, seed)
    if flat is None or not flat[0] > hard.hi:
        return None
    u_flat, limit = flat
    # the far form as it is, then with each root's radicand factored (sqrt(P(x)/x⁴) → sqrt(P(x))/x²: P's powers of x
    # are finite below U_flat; K of (36) at u = 1400 was 4.24 ulp as it is, within 2.6 so): the first that holds
    for near in (far, _roots_factored(far)):
        whole = sp.Piecewise((limit, x > u_flat), (near, x > hard.hi), (form, True))
        if _far_holds(emitted_py(seed, args, whole, dom), expr, args, i, seed, hard.hi):
            return whole, dom
    return None


def _roots_factored(e: sp.Expr) -> sp.Expr:
    """e with the radicand of each square root factored (:func:`sympy.factor`)."""
    return e.replace(lambda n: n.is_Pow and n.exp == sp.Rational(1, 2), lambda n: sp.sqrt(sp.factor(n.base)))


def _far_holds(fn, expr: sp.Expr, args: Sequence[KernelArg], i: int, seed: str, hi: float) -> bool:
    """The emitted fn holds the bound at every value of :func:`far_values` of argument i (4 seeded points of the
    others at each; at +inf against the derived form's limit)."""
    syms = [next(s for s in expr.free_symbols if s.name == a.name) for a in args]
    f = sp.lambdify(syms, expr, modules="mpmath", cse=True)
    rng = random.Random(seed + ":far")
    for v in far_values(hi):
        for _ in range(TRIES):
            p = [rng.uniform(a.lo, a.hi) if not a.log else math.exp(rng.uniform(math.log(a.lo), math.log(a.hi)))
                 for a in args]
            p[i] = v
            at = list(p)
            at[i] = v if v < math.inf else LIMIT_FAR[1]
            if not _holds(fn, f, p, at, zero=v == math.inf and _vanishes(f, p, i, LIMIT_FAR)):
                return False
    return True
