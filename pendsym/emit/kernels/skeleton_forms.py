"""Skeleton forms beyond the vertex form (:data:`.rules.SKELETONS`), for issue #11.

- :func:`near_taylor_form`: a polynomial of degree ≥ 3 in one argument K (F of (170), a quartic)
  written about a centre c in K where that cancels less than the plain form;
- :func:`near_one_form`: a ratio N/D whose terms are shared (K of (36)) as 1 + (N − D)/D.

Each gives (skeleton, leaves) with new leaves, functions of the hard argument alone that get their
own stable forms (:func:`.leaves.stable_forms`), and chooses between its form and the plain one with
a :class:`.plan.Select`, as :func:`.rules.near_vertex_form` does.
"""
from __future__ import annotations

import math

import mpmath as mp
import sympy as sp

from .plan import Magnitude, Select

SHIFT_STEPS = 12        # candidate centres of the Taylor form in K: lo + (hi − lo)·i/12, i = 0 … 12
SHIFT_GRID = (160, 121)  # points of the hard argument (log-spaced) and of K on which the centre is chosen
SHIFT_GAIN = 0.75        # the Taylor form is offered when it lowers the estimated amplification by this factor


def polynomial_in(skeleton: sp.Expr, leaves: dict) -> tuple[sp.Symbol, sp.Poly] | None:
    """(K, the skeleton as a polynomial in K) of degree ≥ 3 whose coefficients are the hard argument's alone
    (a quartic such as F of (170)); None if no argument qualifies."""
    hard = set(leaves)
    for K in sorted(skeleton.free_symbols - hard, key=lambda s: s.name):
        try:
            poly = sp.Poly(skeleton, K)
        except sp.PolynomialError:
            continue
        if poly.degree() >= 3 and all(cf.free_symbols <= hard for cf in poly.all_coeffs()):
            return K, poly
    return None


def shifted_coefficients(poly: sp.Poly, c: sp.Rational) -> list:
    """[d_0 … d_n]: poly = Σ d_j (K − c)^j, each d_j = Σ_i C(i, j) a_i c^{i−j} (exact in the leaves)."""
    n = poly.degree()
    a = poly.all_coeffs()[::-1]
    return [sp.Add(*[sp.binomial(i, j) * a[i] * c ** (i - j) for i in range(j, n + 1)]) for j in range(n + 1)]


def _amplification(poly: sp.Poly, leaves: dict, x: sp.Symbol, hard, K_arg, centres) -> dict:
    """{centre: the largest, over a grid of (x, K), of min(plain, Taylor form about the centre) of
    Σ|terms|/|value| / max(1, κ_K)} (κ_K = |K ∂_K P|/|P| ≤ κ: at a stationary point in K, where
    the plain form cancels most, κ_K = 0); the plain form's alone under the key None."""
    fs = [sp.lambdify([x], cf.xreplace(leaves), modules="mpmath") for cf in poly.all_coeffs()[::-1]]
    n = poly.degree()
    nx, nk = SHIFT_GRID
    xs = [math.exp(math.log(hard.lo) + (math.log(hard.hi) - math.log(hard.lo)) * i / (nx - 1)) for i in range(nx)]
    Ks = [K_arg.lo + (K_arg.hi - K_arg.lo) * i / (nk - 1) for i in range(nk)]
    worst = {c: 0.0 for c in (None, *centres)}
    with mp.workdps(30):
        for xv in xs:
            try:
                a = [float(f(mp.mpf(xv))) for f in fs]
            except (ZeroDivisionError, OverflowError, ValueError):
                continue
            shifted = {c: [sum(math.comb(i, j) * a[i] * float(c) ** (i - j) for i in range(j, n + 1))
                           for j in range(n + 1)] for c in centres}
            for K in Ks:
                value = sum(a[i] * K**i for i in range(n + 1))
                slope = sum(i * a[i] * K ** (i - 1) for i in range(1, n + 1))
                if value == 0 or not math.isfinite(value):
                    continue
                scale = abs(value) * max(1.0, abs(K * slope / value))
                plain = sum(abs(a[i] * K**i) for i in range(n + 1)) / scale
                worst[None] = max(worst[None], plain)
                for c, d in shifted.items():
                    y = K - float(c)
                    taylor = (sum(abs(d[j] * y**j) for j in range(n + 1))
                              + sum(j * abs(d[j] * y**j) for j in range(1, n + 1))) / scale
                    worst[c] = max(worst[c], min(plain, taylor))
    return worst


def near_taylor_form(skeleton: sp.Expr, leaves: dict, args=()) -> tuple[sp.Expr, dict] | None:
    """A skeleton of degree n ≥ 3 in K (:func:`polynomial_in`) written about a centre c in K,
    Σ d_j (K − c)^j, where that cancels less than the plain form Σ a_j K^j, the plain form elsewhere.

    Near a stationary point in K the plain form's terms cancel (F of (170): terms up to 2.5 for a
    value −0.92 at u = 1.306, K = −2.836, where ∂F/∂K = 0 and κ = 1.9: 7.1 ulp/κ in the audit),
    and the rounding of its leaves is amplified by Σ|a_j K^j|/|F|.  The d_j = Σ_i C(i, j) a_i c^{i−j}
    are new leaves, functions of the hard argument alone with their own stable forms, so the
    cancellation moves into them.  c is the exact rational, among lo + (hi − lo)·i/12, whose form
    has the least largest amplification on a grid of (x, K) (:func:`_amplification`); it is
    offered only where it lowers the plain form's by SHIFT_GAIN.  As in :func:`near_vertex_form`,
    the kernel compares the sums of the magnitudes of the terms, Σ|a_j K^j| with
    Σ|d_j y^j| + Σ j|d_j y^j| (y = K − c; the second sum: the rounding of y), and evaluates the
    form with the smaller."""
    got = polynomial_in(skeleton, leaves)
    by = {a.name: a for a in args}
    if got is None:
        return None
    K, poly = got
    (x,) = set().union(*(v.free_symbols for v in leaves.values()))
    if K.name not in by or x.name not in by:
        return None
    K_arg, hard = by[K.name], by[x.name]
    centres = [sp.nsimplify(K_arg.lo + (K_arg.hi - K_arg.lo) * sp.Rational(i, SHIFT_STEPS))
               for i in range(SHIFT_STEPS + 1)]
    centres = [c for c in centres if c != 0]
    worst = _amplification(poly, leaves, x, hard, K_arg, centres)
    c = min(centres, key=lambda v: (worst[v], abs(v)))
    if not worst[c] < SHIFT_GAIN * worst[None]:
        return None
    new = dict(leaves)
    y = K - c
    form, tsum = sp.S.Zero, sp.S.Zero
    for j, d in enumerate(shifted_coefficients(poly, c)):
        if d.free_symbols:
            sym = sp.Symbol(f"leaf_{len(new)}")
            new[sym] = sp.together(d.xreplace(leaves))
            d = sym
        form += d * y**j
        tsum += Magnitude(d * y**j) + (j * Magnitude(d * y**j) if j else 0)
    plain_sum = sp.Add(*[Magnitude(cf * K**m) for (m,), cf in poly.terms()])
    return Select(plain_sum - tsum, form, skeleton), new


def _simplest(c: sp.Expr) -> sp.Expr:
    """c as one fraction, or simplified in exponentials where that is shorter: λ/(u th u) − λ th(u/2)/u is
    λ/(u sh u), whose leaf (and its 120-digit reference on the leaf grid) then does not cancel as u grows
    (the difference loses every digit of 120 above u ≈ 270)."""
    together = sp.together(c)
    if sp.count_ops(c) > 40:
        return together
    simple = sp.simplify(c.rewrite(sp.exp))
    return simple if sp.count_ops(simple) < sp.count_ops(together) else together


def _leaf_groups(e: sp.Expr, leaves: dict) -> tuple[sp.Expr, dict]:
    """e (a sum) with the terms that differ only in their leaf factors gathered into one new leaf
    each: λ·leaf_w − λ·leaf_v → λ·leaf_n, leaf_n the leaves' combination (w_λ − v_0 = w_0 for
    K of (36)), which gets its own stable form (its cancellation is then the leaf's)."""
    hard = set(leaves)
    groups: dict = {}
    for t in sp.Add.make_args(sp.expand(e, deep=False)):
        mine = [f for f in sp.Mul.make_args(t) if f.free_symbols <= hard]       # numbers and leaves
        rest = [f for f in sp.Mul.make_args(t) if not f.free_symbols <= hard]
        groups.setdefault(sp.Mul(*rest), []).append(sp.Mul(*mine))
    new, out = dict(leaves), sp.S.Zero
    for rest, parts in groups.items():
        if len(parts) > 1:
            sym = sp.Symbol(f"leaf_{len(new)}")
            new[sym] = _simplest(sp.Add(*parts).xreplace(leaves))
            out += rest * sym
        else:
            out += rest * parts[0]
    return out, new


def near_one_form(skeleton: sp.Expr, leaves: dict) -> tuple[sp.Expr, dict] | None:
    """A ratio N/D whose numerator and denominator share terms, as 1 + (N − D)/D where that is at
    least ½ (N/D elsewhere), N − D with its leaves gathered (:func:`_leaf_groups`).

    K of (36) is (a + w_λ)/(a + v_0 + z): no term cancels, but each of the eight roundings of
    the leaves, products and sums counts in full (4.05 ulp in the audit).  In
    1 + (w_0 − z)/(a + v_0 + z) they are scaled by |K − 1|/K, and the common a is gone;
    where K < ½ the sum 1 + q would cancel, and N/D is kept."""
    num, den = sp.fraction(skeleton)
    if den == 1 or not den.is_Add or not num.is_Add:
        return None
    # expanded at the top only: a Piecewise (K's root z) is kept whole, the unit K and n² share
    terms = lambda x: len(sp.Add.make_args(sp.expand(x, deep=False)))     # noqa: E731
    diff = sp.expand(num - den, deep=False)
    if terms(diff) >= terms(num) + terms(den):
        return None
    diff, new = _leaf_groups(diff, leaves)
    q = diff / den
    return Select(q + sp.Rational(1, 2), 1 + q, skeleton), new
