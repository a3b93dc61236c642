"""Named rewrite rules: small objects grouped in tuples, as in ``sympy.codegen.rewriting``.

Each rule is a frozen object with a name (the one a kernel's docstring shows) and a pure
rewrite; the choice of form (:mod:`.choice`) and the stable-form synthesis (:mod:`.leaves`)
walk the tuples in order, and measurement decides.

- :data:`REWRITES`: rewrites of a whole expression (factor, trigonometric bases, Horner…);
- :data:`NEAR_ZERO`: the series in t of a form that cancels as t → 0, used below a phase;
- :data:`FAR_FORMS`: the forms of a leaf c(x) (a function of the hard argument alone) for
  large x: as derived, in e^{−x/q} with expm1, or its limit plus an e^{−x} remainder;
- :data:`SKELETONS`: the forms of the skeleton around the leaves: plain, vertex form (a
  quadratic), Taylor form about a point in K (degree ≥ 3), or 1 + (N − D)/D (a ratio).

The series of a leaf below a switch and its Taylor pieces between knots (the near and
middle pieces, with SWITCHES and KNOTS) are the rules of :mod:`.series`.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable, Sequence

import sympy as sp
from sympy.codegen.cfunctions import expm1

from ...result import KernelArg
from .plan import Grouped, Magnitude, Select
from .skeleton_forms import near_one_form, near_taylor_form

# ----------------------------------------------------------------- whole-expression rewrites


@dataclass(frozen=True)
class Rewrite:
    """A named rewrite of a whole expression (a callable object, like ``ReplaceOptim``);
    `trig`: tried only on forms with sin or cos."""

    name: str
    apply: Callable[[sp.Expr], sp.Expr]
    trig: bool = False

    def __call__(self, e: sp.Expr) -> sp.Expr:
        return self.apply(e)


def _even_powers_in(e: sp.Expr, old, new) -> sp.Expr:
    """Even powers of old(y) → powers of (1 − new(y)²), then factor."""
    e = sp.expand(sp.expand_trig(e))
    e = e.replace(lambda x: x.is_Pow and x.base.func == old and x.exp.is_even and x.exp > 0,
                  lambda x: (1 - new(x.base.args[0]) ** 2) ** (x.exp // 2))
    return sp.factor(sp.expand(e))


def sin_basis(e: sp.Expr) -> sp.Expr:
    """Even powers of cos → powers of (1 − sin²), then factor (good near kt = 0)."""
    return _even_powers_in(e, sp.cos, sp.sin)


def cos_basis(e: sp.Expr) -> sp.Expr:
    """Even powers of sin → powers of (1 − cos²), then factor."""
    return _even_powers_in(e, sp.sin, sp.cos)


def half_angle(e: sp.Expr) -> sp.Expr:
    """1 − cos x cancels for small x: cos x = 1 − 2 sin²(x/2), then factor."""
    return sp.factor(sp.expand(e.replace(sp.cos, lambda x: 1 - 2 * sp.sin(x / 2) ** 2)))


def smaller_basis(e: sp.Expr) -> sp.Expr:
    """The sin basis where |sin φ| < |cos φ|, the cos basis elsewhere (one phase φ): each basis
    cancels only where its variable is near 1 (1 − s² as s → 1), so each is used where its
    variable is at most 1/√2, and a polynomial in s² then loses no digits away from its zeros."""
    phases = {f.args[0] for f in e.atoms(sp.sin, sp.cos)}
    if len(phases) != 1:
        raise ValueError("one phase is needed")
    (phi,) = phases
    return sp.Piecewise((sin_basis(e), Magnitude(sp.sin(phi)) < Magnitude(sp.cos(phi))), (cos_basis(e), True))


def _rounded_multiple(f: sp.Expr) -> bool:
    """sin(m·φ) or cos(m·φ) with m an integer ≥ 3 not a power of 2: m·φ is rounded, an error the
    inputs do not have (2φ, 4φ are exact)."""
    m, _ = f.args[0].as_coeff_Mul()
    return m.is_Integer and abs(m) >= 3 and (int(abs(m)) & (int(abs(m)) - 1)) != 0


def rounded_multiples(e: sp.Expr) -> int:
    """The number of sines and cosines of a form whose argument m·φ is rounded (:func:`_rounded_multiple`)."""
    return sum(1 for f in e.atoms(sp.sin, sp.cos) if _rounded_multiple(f))


def multiple_angles(e: sp.Expr) -> sp.Expr:
    """Each sin(m·φ), cos(m·φ) whose argument would be rounded (m ≥ 3, not a power of 2) written in
    sin φ and cos φ, and each sum in the phase's own symbols alone (the trigonometric part g(φ) of
    α k (α² q g(φ) + 32 sin φ)) in Horner form in sin φ; the grouping of the form in its other
    arguments is kept (expanding it too cancels more: n23_dtheta at t = 6.6, 4.8 against 2.7 ulp
    scaled on a box of 30,000 points, the as-derived form with sin 3kt 5.0)."""
    targets = [f for f in e.atoms(sp.sin, sp.cos) if _rounded_multiple(f)]
    if not targets:
        raise ValueError("no rounded multiple angle")
    e = e.xreplace({f: sp.expand_trig(f) for f in targets})
    phases = {f.args[0] for f in e.atoms(sp.sin, sp.cos)}
    if len(phases) != 1:
        raise ValueError("one phase is needed")
    (phi,) = phases
    S = sp.Dummy("S")
    own = phi.free_symbols

    def horner(n: sp.Expr) -> sp.Expr:
        cs = sp.Poly(sp.expand(n), S).all_coeffs()
        out = sp.S.Zero
        for c in cs:
            out = out * S + c
        return out
    e = e.xreplace({sp.sin(phi): S})
    e = e.replace(lambda n: n.is_Add and n.has(S) and n.free_symbols <= own | {S}, horner)
    return e.xreplace({S: sp.sin(phi)})


REWRITES: tuple[Rewrite, ...] = (
    Rewrite("as-derived", lambda e: e),
    Rewrite("factor", sp.factor),
    Rewrite("expand-trig", lambda e: sp.factor(sp.expand(sp.expand_trig(e))), trig=True),
    Rewrite("sin-basis", sin_basis, trig=True),
    Rewrite("cos-basis", cos_basis, trig=True),
    Rewrite("horner", lambda e: sp.horner(sp.expand(e)) if e.is_polynomial() else e),
    Rewrite("half-angle", half_angle, trig=True),
    Rewrite("smaller-basis", smaller_basis, trig=True),
    Rewrite("multiple-angles", multiple_angles, trig=True),
)

# ----------------------------------------------------------------- series near t = 0


@dataclass(frozen=True)
class SeriesNearZero:
    """The Taylor series in t of a form that cancels as t → 0 (kt − sin kt cos kt …), used
    where the phase k·t (t without k) is below `phase`.  With 44 orders kept, the truncation
    at k·t = 0.35 is below 2e-18 relative to a leading term of order ≤ 5.

    Below `tiny` (where the next order is 1e-300 of the leading one) only the leading term
    c·t^m is evaluated, as ((c·t)·t)…: c first, then one rounding per factor t, so that a
    subnormal t or a subnormal result loses nothing to an intermediate subnormal product
    (the plain series rounds α³·t to a subnormal first and then multiplies it by 1/k)."""

    name: str = "series-near-t=0"
    order: int = 44
    phase: sp.Rational = sp.Rational(7, 20)
    tiny: float = 1e-150

    def series(self, e: sp.Expr, args: Sequence[KernelArg]) -> tuple[sp.Expr, sp.Expr, sp.Expr] | None:
        """(series, phase, leading term), or None when t is not an argument from 0 or the series vanishes."""
        by = {x.name: x for x in e.free_symbols}
        if "t" not in by or not any(a.name == "t" and a.lo == 0 for a in args):
            return None
        t = by["t"]
        ser = sp.series(e, t, 0, self.order).removeO()
        if ser == 0:
            return None
        phase = by["k"] * t if "k" in by else t
        poly = sp.Poly(sp.expand(ser), t)
        (m,), c = poly.terms()[-1]                  # the lowest order
        lead = Grouped(sp.N(c, 20))
        for _ in range(m):
            lead = Grouped(lead * t)
        # rational coefficients become 20-digit floats (exact to double), so no huge integer literals
        return sp.horner(sp.N(sp.collect(sp.expand(ser), t), 20), wrt=t), phase, lead

    def __call__(self, form: sp.Expr, near: tuple) -> sp.Expr:
        """form, with the series (from :meth:`series`) below the phase and its leading term below `tiny`."""
        ser, phase, lead = near
        return sp.Piecewise((lead, phase < self.tiny), (ser, phase < self.phase), (form, True))


NEAR_ZERO = SeriesNearZero()


@dataclass(frozen=True)
class SmallFactorsLast:
    """The whole expression a product with a power b^n (n ≥ 2) of a factor b that vanishes as the hard argument x → 0
    (sin(α/2), x itself), evaluated as ((C·b)·b)…: the other factors first, then one rounding per
    factor b.  Evaluated as written, b^n is a subnormal (sin²(α/2) at α = 1e-156) whose rounding a
    large C then multiplies (F_max = 4ghm sin²(α/2)/l: 1.5e4 ulp).  Tried where the accepted domain
    of x would not reach 0 otherwise (:func:`.kernel.kernel_of`)."""

    name: str = "small-factors-last"

    @staticmethod
    def _small(f: sp.Expr, x: sp.Symbol) -> bool:
        return (f.is_Pow and f.exp.is_Integer and f.exp >= 2 and f.base.has(x)
                and f.base.subs(x, 0) == 0)

    def __call__(self, e: sp.Expr, x: sp.Symbol) -> sp.Expr:
        def last(m: sp.Expr) -> sp.Expr:
            out = sp.Mul(*[f for f in m.args if not self._small(f, x)])
            for f in sorted((f for f in m.args if self._small(f, x)), key=sp.default_sort_key):
                for _ in range(int(f.exp)):
                    out = Grouped(out * f.base)
            return out
        # the whole expression only (a product such as F_max): inside the Horner sums of a series,
        # every level has a factor x², and the nested units would only add roundings
        return last(e) if e.is_Mul and any(self._small(f, x) for f in e.args) else e


SMALL_LAST = SmallFactorsLast()

# ----------------------------------------------------------------- far forms of a leaf c(x)


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


@dataclass(frozen=True)
class FarForm:
    """A named form of a leaf c(x) for large x: `label` names it ({x}: the argument's name);
    `apply(c, x)` gives the form, or None where the rule does not apply."""

    label: str
    apply: Callable[[sp.Expr, sp.Symbol], sp.Expr | None]

    def name(self, x: str) -> str:
        return self.label.format(x=x)

    def __call__(self, c: sp.Expr, x: sp.Symbol) -> sp.Expr | None:
        return self.apply(c, x)


def one_exponential(form: sp.Expr | None, x: sp.Symbol) -> sp.Expr | None:
    """form (rational in e^{−x/q}, from :func:`exp_form` or :func:`asymptotic_form`) with every
    exp(−j x/q) written E^j and every expm1(−j x/q) written E^j − 1, E = e^{−x/q} one named unit:
    one libm call where the form made up to six (F of (170): 61 calls of exp and expm1 above its
    knots).  Where E^j ≤ ½, E^j − 1 loses nothing; the powers' roundings (j·½ ulp) count only in
    the terms they multiply, corrections of relative size E^j.  Measured like the other far forms
    (:func:`.leaves.leaf_form`); None when the form has no exponential of x or one that grows."""
    if form is None:
        return None
    calls = [f for f in form.atoms(sp.exp, expm1) if f.has(x)]
    ratios = [sp.simplify(f.args[0] / x) for f in calls]
    if not calls or not all(r.is_Rational and r < 0 for r in ratios):
        return None
    q = math.lcm(*[int(r.q) for r in ratios])
    E = Grouped(sp.exp(-x / q))

    def pw(j: int) -> sp.Expr:        # E^j; above E^8 through E² (the printers call pow() above the 8th power)
        return E**j if j <= 8 else Grouped(E**2) ** (j // 2) * E ** (j % 2)
    power = {f: int(-r * q) for f, r in zip(calls, ratios)}
    return form.xreplace({f: (pw(power[f]) if isinstance(f, sp.exp) else pw(power[f]) - 1) for f in calls})


FAR_FORMS: tuple[FarForm, ...] = (
    # session 11: first, so that where it is as accurate (within PIECE_GAIN) the single exponential wins.  Only
    # the remainder is written in E (its powers multiply a correction); the e^{-x} form in one exponential, whose
    # powers are whole factors, took F of (170) to 4.4 in the audit's numpy path (numpy's exp is 1–2 ulp off libm's)
    FarForm("limit in 1/{x} plus e^{{-{x}}} remainder in one exponential",
            lambda c, x: one_exponential(asymptotic_form(c, x), x)),
    FarForm("as derived", lambda c, x: c),
    FarForm("e^{{-{x}}} form", exp_form),
    FarForm("limit in 1/{x} plus e^{{-{x}}} remainder", asymptotic_form),
)

# ----------------------------------------------------------------- forms of the skeleton


def quadratic_vertex(skeleton: sp.Expr, leaves: dict) -> tuple | None:
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
    """The skeleton in vertex form P[a(K − c)² + aD] (:func:`quadratic_vertex`, A = P·a with a the part
    of A in the leaves), c and aD new leaves (on the vertex the value is then one leaf, not a
    product).  Near the vertex the three terms of the plain form cancel, and the rounding of
    its leaves is amplified by Σ|terms|/|value|, not by the condition number; in vertex form
    the cancellation is inside the leaf D, which gets its own stable form."""
    vx = quadratic_vertex(skeleton, leaves)
    if vx is None:
        return None
    K, A, c, D = vx
    P, a = A.as_independent(*leaves)          # A = P·a, a the part in the leaves: A(K − c)² + P·(aD)
    c_sym, e_sym = sp.Symbol(f"leaf_{len(leaves)}"), sp.Symbol(f"leaf_{len(leaves) + 1}")
    new = {**leaves, c_sym: sp.together(c.xreplace(leaves)), e_sym: sp.together((a * D).xreplace(leaves))}
    return P * (a * (K - c_sym) ** 2 + e_sym), new


@dataclass(frozen=True)
class SkeletonForm:
    """A named form of a skeleton and its leaves: `apply(skeleton, leaves)` gives
    (skeleton, leaves), or None where it does not apply; `label` is appended to the rule's name."""

    label: str
    apply: Callable[..., tuple[sp.Expr, dict] | None]
    with_args: bool = False      # apply(skeleton, leaves, args): the rule needs the kernel's declared domains

    def __call__(self, skeleton: sp.Expr, leaves: dict, args=()) -> tuple[sp.Expr, dict] | None:
        return self.apply(skeleton, leaves, args) if self.with_args else self.apply(skeleton, leaves)


def near_vertex_form(skeleton: sp.Expr, leaves: dict) -> tuple[sp.Expr, dict] | None:
    """The vertex form where it cancels less than the plain form, the plain form elsewhere.

    Near the vertex the plain form A K² + B K + C cancels; far from it (for instance when c
    grows like 1/x² and A(K − c)² and D are both huge) the vertex form cancels instead.  Each
    form's rounding is amplified by the sum of the magnitudes of its terms: |C| + |BK| + |AK²|
    for the plain form, |A|(K − c)² + 2|A (K − c) c| + |AD| for the vertex form (the middle
    term: the rounding of c), and the form with the smaller sum is evaluated.  Every leaf is
    evaluated first, for the test."""
    got = vertex_form(skeleton, leaves)
    vx = quadratic_vertex(skeleton, leaves)
    if got is None or vx is None:
        return None
    vform, new = got
    K, A = vx[0], vx[1]
    c_sym, e_sym = sp.Symbol(f"leaf_{len(leaves)}"), sp.Symbol(f"leaf_{len(leaves) + 1}")
    poly = sp.Poly(skeleton, K)
    plain_sum = sp.Add(*[Magnitude(cf * K**m) for (m,), cf in poly.terms()])
    P, a = A.as_independent(*leaves)
    vertex_sum = Magnitude(A * (K - c_sym) ** 2) + 2 * Magnitude(A * (K - c_sym) * c_sym) + Magnitude(P * e_sym)
    return Select(plain_sum - vertex_sum, vform, skeleton), new


PLAIN = SkeletonForm("", lambda skeleton, leaves: (skeleton, leaves))
VERTEX = SkeletonForm(", in vertex form", vertex_form)
NEAR_VERTEX = SkeletonForm(", in vertex form where it cancels less", near_vertex_form)
NEAR_TAYLOR = SkeletonForm(", about a point in K where it cancels less", near_taylor_form, with_args=True)
NEAR_ONE = SkeletonForm(", as 1 + (N − D)/D where that is over 1/2", near_one_form)
SKELETONS: tuple[SkeletonForm, ...] = (PLAIN, VERTEX, NEAR_VERTEX, NEAR_TAYLOR, NEAR_ONE)
