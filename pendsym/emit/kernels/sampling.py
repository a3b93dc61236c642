"""Sampling: the seeded points a kernel is measured on.

Random points of the declared domain (log-uniform for a geometric argument), its corners,
and the hard points: near 0, every decade of a geometric argument, each switch and knot
of the stable pieces with the doubles on either side, and points on the vertex curve of a
quadratic skeleton, where the plain form cancels most.  Seeds are the kernel's name, so a
rerun draws the same points.
"""
from __future__ import annotations

import functools
import math
import random
from typing import Sequence

import mpmath as mp
import sympy as sp

from ...result import KernelArg
from .leaves import LEAF_DPS, hard_argument, vertex_curve
from .series import KNOTS, SWITCHES

VERTEX_POINTS = 32     # sample points on the vertex curve of a quadratic skeleton
CORNERS = 64           # at most this many corners of the domain
TINY = (5e-324, 1.5e-323, 2.5e-322, 4.4e-320, 1e-315, 1e-310, 1e-300, 1e-160, 1e-30)   # values of a linear argument from 0 (subnormal results)
PHASE_POINTS = 6       # points at each multiple of π/2 of a trigonometric argument
PHASE_SHIFTS = (0.0, 1e-12, -1e-12, 1e-7, -1e-7, 1e-3, -1e-3)   # relative offsets from it


def draw(a: KernelArg, rng: random.Random) -> float:
    """A seeded point of one argument's domain: log-uniform for a geometric one, else uniform."""
    if a.log and a.lo > 0:
        return math.exp(rng.uniform(math.log(a.lo), math.log(a.hi)))
    return rng.uniform(a.lo, a.hi)


def _special(a: KernelArg) -> list[float]:
    """An argument's ends, and for a linear argument through 0 its points near 0, π/2, π, 3."""
    vals = [a.lo, a.hi]
    if a.lo <= 0 <= a.hi and not a.log:
        vals += [v for v in (1e-9, 1e-4, 0.5 * math.pi, math.pi, 3.0) if a.lo <= v <= a.hi]
    return vals


def _corners(args: Sequence[KernelArg]) -> list[tuple[float, ...]]:
    """Up to CORNERS combinations of the special values of the arguments."""
    corner_sets = [_special(a) for a in args]
    pts = []
    for i in range(min(CORNERS, math.prod(len(c) for c in corner_sets))):
        idx, p = i, []
        for c in corner_sets:
            p.append(c[idx % len(c)])
            idx //= len(c)
        pts.append(tuple(p))
    return pts


def sample_points(args: Sequence[KernelArg], seed: str, n: int = 160, hard: bool = True,
                  pieces: str | None = None) -> list[tuple[float, ...]]:
    """Seeded points of the domain: its corners, hard points near 0, and random interior points;
    with `hard`, also every decade of a geometric argument, and every switch and knot of the
    stable forms for the argument named `pieces` (:func:`hard_points`)."""
    rng = random.Random(seed)
    pts = _corners(args)
    pts += [tuple(draw(a, rng) for a in args) for _ in range(n)]
    if hard:
        pts += hard_points(args, random.Random(seed + ":hard"), pieces)
    return sorted(set(pts), key=pts.index)


def hard_points(args: Sequence[KernelArg], rng: random.Random, pieces: str | None = None) -> list[tuple[float, ...]]:
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
            if not a.lo <= v <= a.hi:        # 2·lo and hi/2 lie outside a range narrower than a factor 2
                continue
            p = [draw(b, rng) for b in args]
            p[i] = v
            out.append(tuple(p))
    return out


def kernel_sample(expr: sp.Expr, args: Sequence[KernelArg], seed: str) -> list[tuple[float, ...]]:
    """The sample a kernel of expr is measured on: with the switches and knots of its hard
    argument, and, where its skeleton is quadratic in an argument K, points on the vertex
    curve K = c(x) (:func:`vertex_points`), where the plain form cancels most."""
    return list(_kernel_sample(expr, tuple(args), seed))


@functools.lru_cache(maxsize=256)
def _kernel_sample(expr: sp.Expr, args: tuple[KernelArg, ...], seed: str) -> tuple:
    hard = hard_argument(expr, args)
    pts = sample_points(args, seed, pieces=hard.name if hard is not None else None)
    pts += vertex_points(expr, args, seed)
    pts += tiny_points(args, seed) + phase_points(expr, args, seed)
    return tuple(sorted(set(pts), key=pts.index))


def tiny_points(args: Sequence[KernelArg], seed: str) -> list[tuple[float, ...]]:
    """For a linear argument from 0 (such as t): the values TINY, down to the smallest subnormal,
    the other arguments drawn at random or at their largest magnitude (a form evaluated there
    rounds subnormal intermediates, such as k·t, and a large factor then multiplies the error)."""
    rng = random.Random(seed + ":tiny")
    out = []
    for i, a in enumerate(args):
        if a.log or a.lo != 0:
            continue
        for v in TINY:
            # at random, and with the others at their largest magnitude (the largest subnormal result)
            for p in ([draw(b, rng) for b in args], [b.hi if abs(b.hi) >= abs(b.lo) else b.lo for b in args],
                      [0.9373 * (b.hi if abs(b.hi) >= abs(b.lo) else b.lo) for b in args],
                      [0.7071 * (b.hi if abs(b.hi) >= abs(b.lo) else b.lo) for b in args]):
                p[i] = v
                out.append(tuple(p))
    return out


def phase_points(expr: sp.Expr, args: Sequence[KernelArg], seed: str) -> list[tuple[float, ...]]:
    """Where the argument φ of a sin or cos is near a multiple m·π/2 (a zero of sin or cos, where
    1 ± cos φ or a polynomial in sin² cancels): for each argument x in which φ = x·r is linear,
    x = m·(π/2)/r·(1 + δ) for the shifts δ of PHASE_SHIFTS, the other arguments at random."""
    rng = random.Random(seed + ":phase")
    by = {s.name: s for s in expr.free_symbols}
    phases = {f.args[0] for f in expr.atoms(sp.sin, sp.cos)}
    out = []
    for phi in sorted(phases, key=sp.default_sort_key):
        for i, a in enumerate(args):
            x = by.get(a.name)
            if x is None or not phi.has(x) or sp.diff(phi, x, 2) != 0 or (phi - sp.diff(phi, x) * x) != 0:
                continue
            rate = sp.lambdify([by[b.name] for b in args if b.name in by], sp.diff(phi, x), modules="math")
            names = [b.name for b in args if b.name in by]
            for _ in range(PHASE_POINTS):
                p = [draw(b, rng) for b in args]
                try:
                    r = float(rate(*[p[j] for j, b in enumerate(args) if b.name in names]))
                except (ZeroDivisionError, ValueError, OverflowError):
                    continue
                if r == 0:
                    continue
                ms = [m for m in range(1, 400) if a.lo <= m * (math.pi / 2) / r <= a.hi]
                if not ms:
                    continue
                m = rng.choice(ms[:4] + ms[-2:])
                for d in PHASE_SHIFTS:
                    v = m * (math.pi / 2) / r * (1 + d)
                    if a.lo <= v <= a.hi:
                        q = list(p)
                        q[i] = v
                        out.append(tuple(q))
    return out


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
        p = [draw(a, rng) for a in args]
        with mp.workdps(LEAF_DPS):       # c cancels like the leaves do as x → 0
            try:
                kv = float(c(mp.mpf(p[ix])))
            except ZeroDivisionError:
                continue
        if args[ik].lo <= kv <= args[ik].hi:
            p[ik] = kv
            out.append(tuple(p))
    return out
