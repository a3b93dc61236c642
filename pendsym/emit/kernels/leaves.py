"""Stable-form synthesis in one hard argument: skeleton, leaves, and each leaf's pieces.

Forms such as 1/u² − 1/sh²u or 1 − 2 th(u/2)/u cancel catastrophically as u → 0, and sh u
overflows for large u.  The mechanism, for any memoir: the expression is split into a
skeleton in the other arguments whose coefficients ("leaves") are functions of the one hard
argument x alone (:func:`split_hard`); each leaf gets the piecewise form of least error on a
grid of x (:func:`leaf_form`), built from the named rules: the series below a switch and
the Taylor pieces between knots (:mod:`.series`), and a far form above (:data:`.rules.FAR_FORMS`).
The skeleton is kept, or put in vertex form (:data:`.rules.SKELETONS`).
"""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from typing import Callable, Sequence

import mpmath as mp
import sympy as sp

from ...result import KernelArg
from .measure import ulp_errors
from .plan import Grouped, Select
from .printing import KernelPy
from .rules import FAR_FORMS, PLAIN, SKELETONS, quadratic_vertex
from .series import KNOTS, SERIES, SWITCHES, TAYLOR

LEAF_POINTS = 400      # log-spaced grid on which a leaf's form is chosen
MIDDLE_STEP = 1 / 64   # and a grid of this step over [0.25, 21], where the pieces meet
LEAF_DPS = 120         # a leaf may lose 40 digits to cancellation at x = 1e-6
GOOD_ENOUGH = 1.0      # ulp: a leaf this accurate without Taylor pieces needs none (at 1.5 a far form
                       # measured 1.48 on the grid reached 3.3 between its points: F2 at u = 1.005)
PIECE_GAIN = 0.25      # ulp: a form with more pieces must gain more than this


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
    vx = quadratic_vertex(skeleton, leaves)
    if vx is None:
        return None
    return a.name, vx[0].name, sp.lambdify([x], vx[2].xreplace(leaves), modules="mpmath")


def leaf_grid(a: KernelArg) -> list[float]:
    """Log-spaced points over the domain, every 1/64 over [0.25, 21] (where the closed forms
    cancel and the Taylor pieces lie; a sparser grid missed errors of 3.5 ulp in leaves measured
    at 2), and each switch and knot with its neighbours."""
    n = LEAF_POINTS
    pts = [math.exp(math.log(a.lo) + (math.log(a.hi) - math.log(a.lo)) * i / (n - 1)) for i in range(n)]
    pts += [0.25 + MIDDLE_STEP * i for i in range(int(20.75 / MIDDLE_STEP) + 1)]
    for s in SWITCHES + KNOTS:
        pts += [math.nextafter(s, 0.0), s, s * (1 + 1e-3), s * (1 - 1e-3)]
    return sorted(v for v in set(pts) if a.lo <= v <= a.hi)


@dataclass(frozen=True)
class LeafForm:
    expr: sp.Expr
    desc: str            # how it is evaluated, for the docstring
    max_ulp: float       # measured on the leaf grid


@dataclass(frozen=True)
class _Grid:
    """The leaf grid and the leaf's true values on it (at LEAF_DPS)."""

    xs: tuple
    truth: tuple

    def errors(self, fn: Callable, lo: float = -math.inf, hi: float = math.inf) -> dict[int, float]:
        """{grid index: ulp error} of the double function fn on the grid points in [lo, hi)."""
        idx = [i for i, v in enumerate(self.xs) if lo <= v < hi]
        return dict(zip(idx, ulp_errors(fn, [self.xs[i] for i in idx], [self.truth[i] for i in idx])))

    def worst(self, errs: dict, lo: float = -math.inf, hi: float = math.inf, default=None) -> float:
        """The largest of errs on the grid points in [lo, hi)."""
        vals = [v for i, v in errs.items() if lo <= self.xs[i] < hi]
        return max(vals) if default is None else max(vals, default=default)


def _in_double(form: sp.Expr, x: sp.Symbol) -> Callable[[float], float]:
    return sp.lambdify([x], form, modules=["math", {"math": math}], printer=KernelPy)


def _taylor_candidates(piece: Callable, x, a, heads, below, ser_desc, fname, far, fe, grid: _Grid,
                       first: int) -> list:
    """The candidates series + Taylor pieces up to a knot + far form above, for each switch;
    a further piece is not tried once the far form above the last knot is no worse.
    piece(lo, hi): (form, {grid index: error}) of the Taylor piece on [lo, hi]."""
    cands = []
    knots = [k for k in KNOTS if k < a.hi]
    for s1 in below:
        ends, mids, worst = [s1], [], below[s1]
        for k in knots:
            form, pe = piece(ends[-1], k)
            ends.append(k)
            mids.append(form)
            worst = max(worst, max(pe.values(), default=0.0))
            above = grid.worst(fe, lo=k, default=0.0)
            pw = sp.Piecewise((heads[s1], x < s1), *[(f, x < e) for f, e in zip(mids, ends[1:])], (far, True))
            cands.append((max(worst, above), 2 + len(mids), first + len(cands), pw,
                          f"{ser_desc[s1]}, {TAYLOR.describe(ends)}, {fname} above"))
            if above <= worst:      # a further piece cannot lower the error
                break
    return cands


def leaf_form(c: sp.Expr, x: sp.Symbol, a: KernelArg) -> LeafForm:
    """The leaf's piecewise form of least error on the leaf grid, among: a far form (c as
    derived, or its e^{−x} form) alone; the series below a switch and the far form above; and
    the series, Taylor pieces up to a knot, and the far form above.  Each piece is measured
    once on its own points; a form with more pieces must gain more than PIECE_GAIN ulp."""
    xs = leaf_grid(a)
    inside = [s for s in SWITCHES if a.lo < s < a.hi]
    with mp.workdps(LEAF_DPS):
        ref = sp.lambdify([x], c, modules="mpmath", cse=True)
        grid = _Grid(tuple(xs), tuple(ref(mp.mpf(v)) for v in xs))
        fars = [(rule.name(a.name), f) for rule in FAR_FORMS if (f := rule(c, x)) is not None]
        far_err = {name: grid.errors(_in_double(f, x)) for name, f in fars}
        lau = SERIES.coefficients(c, x)
        m = lau[0] if lau else 0
        heads, below, ser_desc = {}, {}, {}
        for s1 in (inside if lau else ()):
            # the series truncated for x < s1 (the terms it needs there), measured below s1
            heads[s1], terms = SERIES.below(m, lau[1], x, s1)
            below[s1] = grid.worst(grid.errors(_in_double(heads[s1], x), hi=s1), hi=s1)
            ser_desc[s1] = SERIES.describe(m, a.name, s1, terms)
        cands = []     # (error, number of pieces, order, form, description)
        pieces: dict = {}

        def piece(lo, hi):
            if (lo, hi) not in pieces:
                form, dbl = TAYLOR(ref, m, lo, hi, x)
                pieces[lo, hi] = (form, grid.errors(dbl, lo, hi))
            return pieces[lo, hi]
        for fname, far in fars:
            fe = far_err[fname]
            cands.append((max(fe.values()), 1, len(cands), far, fname))
            for s1 in below:
                err = max(below[s1], grid.worst(fe, lo=s1))
                cands.append((err, 2, len(cands), sp.Piecewise((heads[s1], x < s1), (far, True)),
                              f"{ser_desc[s1]}, {fname} above"))
        for fname, far in (fars if below and min(cd[0] for cd in cands) > GOOD_ENOUGH else ()):
            cands += _taylor_candidates(piece, x, a, heads, below, ser_desc, fname, far, far_err[fname], grid,
                                        len(cands))
    least = min(e for e, *_ in cands)
    err, _, _, form, desc = min((cd for cd in cands if cd[0] <= least + PIECE_GAIN), key=lambda cd: cd[1:3])
    return LeafForm(form, desc, round(err, 2))


def conditions_as_selects(skeleton: sp.Expr, leaves: dict) -> sp.Expr:
    """Each two-way Piecewise of the skeleton whose condition d > 0 (or d < 0) holds leaves written
    as a :class:`.plan.Select` on d.

    In a Piecewise condition SymPy folds the piecewise leaves out (piecewise_fold), so the kernel
    recomputed every leaf inline in the test and again in the branch (K of (36): the root z's
    test on the sign of p, 20 KB of C, ~1/2 of its time).  A Select's argument is not folded: its
    leaves are named once, before the test (:mod:`.plan`), and each branch still evaluates only
    its own expression.  The test is the same comparison in double (d > 0 or −d > 0)."""
    hard = set(leaves)

    def select(pw: sp.Piecewise) -> sp.Expr:
        if len(pw.args) != 2 or pw.args[1].cond != sp.true:
            return pw
        (b, cond), (c, _) = pw.args
        if not (cond.free_symbols & hard) or not isinstance(cond, (sp.StrictGreaterThan, sp.StrictLessThan)):
            return pw
        if cond.rhs == 0:
            d = cond.lhs if isinstance(cond, sp.StrictGreaterThan) else -cond.lhs
        elif cond.lhs == 0:
            d = cond.rhs if isinstance(cond, sp.StrictLessThan) else -cond.rhs
        else:
            return pw
        return Select(d, b, c)
    return skeleton.replace(lambda e: isinstance(e, sp.Piecewise), select)


def stable_forms(expr: sp.Expr, args: Sequence[KernelArg],
                 vertex: bool = True) -> list[tuple[str, sp.Expr, tuple[str, ...]]]:
    """[(label, form, notes)]: expr with every leaf of its hard argument in its measured best
    piecewise form (each one :class:`Grouped`); and, with `vertex`, when the skeleton is a
    quadratic in one argument, the same in vertex form, everywhere or near the vertex only
    (:data:`.rules.SKELETONS`).  Empty without
    a hard argument."""
    split = hard_split(expr, tuple(args))
    if split is None:
        return []
    a, x, skeleton, leaves = split
    variants = [(rule.label, got) for rule in (SKELETONS if vertex else (PLAIN,))
                if (got := rule(skeleton, leaves, tuple(args))) is not None]
    forms: dict = {}
    out = []
    for label, (skel, lv) in variants:
        used = sorted(skel.free_symbols & set(lv), key=lambda s: int(s.name.split("_")[1]))
        for s in used:
            if lv[s] not in forms:
                forms[lv[s]] = leaf_form(lv[s], x, a)
        notes = tuple(f"{sp.sstr(lv[s])[:60]}: {forms[lv[s]].desc} ({forms[lv[s]].max_ulp:g} ulp)" for s in used)
        skel = conditions_as_selects(skel, lv)
        out.append((label, skel.xreplace({s: Grouped(forms[lv[s]].expr) for s in used}), notes))
    return out
