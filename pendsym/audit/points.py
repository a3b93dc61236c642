"""The points an audit measures a kernel on: random, hard, and found by an adversarial search.

Every draw is seeded by the kernel's name, so a rerun measures the same points.

- :func:`random_points`: uniform over the declared box (log-uniform for a geometric argument).
- :func:`hard_points`: the ends of each argument and the doubles just inside them, the corners,
  every decade of a geometric argument, each branch switch of the emitted code (read from its
  comparisons ``x < c``) with the doubles on either side, and, for every argument in which the
  derived form is a polynomial of degree ≥ 2, its real zeros and stationary points at random
  values of the other arguments (the vertex curve of a quadratic, the stationary points of a
  quartic skeleton: where a plain evaluation cancels most).
- :func:`climb`: a local search from a point that maximises the scaled error.
"""
from __future__ import annotations

import math
import random
import re
from typing import Callable, Sequence

import mpmath as mp
import sympy as sp

from ..result import KernelArg

POLY_POINTS = 400        # random values of the other arguments at which a polynomial's roots are found
SWITCH_POINTS = 24       # points at each side of each switch
ROOT_DPS = 60


def draw(a: KernelArg, rng: random.Random) -> float:
    if a.log and a.lo > 0:
        return math.exp(rng.uniform(math.log(a.lo), math.log(a.hi)))
    return rng.uniform(a.lo, a.hi)


def random_points(args: Sequence[KernelArg], seed: str, n: int) -> list[tuple]:
    rng = random.Random(seed + ":random")
    return [tuple(draw(a, rng) for a in args) for _ in range(n)]


def _ends(a: KernelArg) -> list[float]:
    vals = [a.lo, math.nextafter(a.lo, math.inf), a.hi, math.nextafter(a.hi, -math.inf)]
    if a.lo < 0 < a.hi:
        vals += [0.0, 5e-324, -5e-324, 1e-300, -1e-300, 1e-9, -1e-9]
    if a.log and a.lo > 0:
        vals += [10.0**e for e in range(math.ceil(math.log10(a.lo)), math.floor(math.log10(a.hi)) + 1)]
    return [v for v in vals if a.lo <= v <= a.hi]


def switches(code: str, names: Sequence[str]) -> dict[str, list[float]]:
    """{argument: [c, …]} of every comparison ``argument < c`` (or ``<=``, ``>``) in emitted code."""
    out: dict[str, list[float]] = {}
    for name, c in re.findall(r"\b(\w+) *[<>]=? *(-?[0-9.]+(?:e[-+]?[0-9]+)?)\b", code):
        if name in names:
            out.setdefault(name, []).append(float(c))
    return {k: sorted(set(v)) for k, v in out.items()}


def hard_points(args: Sequence[KernelArg], params: Sequence[str], code: str, expr: sp.Expr,
                syms: Sequence[sp.Symbol], seed: str) -> list[tuple]:
    """The hard points of a kernel (see the module's docstring); `params`: the identifiers of the
    arguments in the emitted code, `syms`: their symbols in the derived form."""
    rng = random.Random(seed + ":hard")
    pts: list[tuple] = []
    ends = [_ends(a) for a in args]
    for i in range(min(256, math.prod(len(e) for e in ends))):      # corners
        idx, p = i, []
        for e in ends:
            p.append(e[idx % len(e)])
            idx //= len(e)
        pts.append(tuple(p))
    for i, e in enumerate(ends):                                     # each end, the others at random
        for v in e:
            for _ in range(4):
                p = [draw(a, rng) for a in args]
                p[i] = v
                pts.append(tuple(p))
    for name, cs in switches(code, params).items():                  # branch switches
        i = list(params).index(name)
        a = args[i]
        for c in cs:
            near = [c, math.nextafter(c, -math.inf), math.nextafter(c, math.inf), c * (1 - 1e-9), c * (1 + 1e-9)]
            for v in near:
                if not a.lo <= v <= a.hi:
                    continue
                for _ in range(SWITCH_POINTS // len(near) + 1):
                    p = [draw(b, rng) for b in args]
                    p[i] = v
                    pts.append(tuple(p))
    pts += polynomial_points(args, expr, syms, rng)
    return pts


def polynomial_points(args: Sequence[KernelArg], expr: sp.Expr, syms: Sequence[sp.Symbol],
                      rng: random.Random) -> list[tuple]:
    """For each argument X in which expr is a polynomial of degree ≥ 2: at random values of the
    other arguments, the real zeros of P and of P' = dP/dX inside X's range, each with the
    doubles beside it."""
    out = []
    for i, (a, X) in enumerate(zip(args, syms)):
        try:
            poly = sp.Poly(expr, X)
        except sp.PolynomialError:
            continue
        if poly.degree() < 2 or any(c.has(X) for c in poly.all_coeffs()):
            continue
        others = [s for j, s in enumerate(syms) if j != i]
        coeffs = [sp.lambdify(others, c, modules="mpmath") for c in poly.all_coeffs()]
        for _ in range(POLY_POINTS):
            p = [draw(b, rng) for b in args]
            with mp.workdps(ROOT_DPS):
                try:
                    cs = [mp.mpf(c(*[mp.mpf(p[j]) for j in range(len(args)) if j != i])) for c in coeffs]
                    n = len(cs) - 1
                    dcs = [c * (n - k) for k, c in enumerate(cs[:-1])]
                    roots = []
                    for q in (cs, dcs):
                        while len(q) > 2 and q[0] == 0:
                            q = q[1:]
                        roots += real_roots(q) if len(q) > 2 else (
                            [-q[1] / q[0]] if len(q) == 2 and q[0] != 0 else [])
                except (ZeroDivisionError, ValueError, TypeError):
                    continue
            for r in roots:
                v = float(r)
                for w in (v, math.nextafter(v, -math.inf), math.nextafter(v, math.inf)):
                    if a.lo <= w <= a.hi:
                        q = list(p)
                        q[i] = w
                        out.append(tuple(q))
    return out


NEWTON_STEPS = 12        # polishing steps of a double root estimate at ROOT_DPS
NEAR_REAL = 1e-6         # |Im r| / max(1, |r|) of an estimate worth polishing on the real line


def real_roots(cs: Sequence) -> list:
    """The real roots of the polynomial Σ cs[k] X^(n−k) (mpmath numbers, at the working precision):
    the eigenvalues of its companion matrix in double (numpy.roots) near the real line, each polished
    by Newton's method at the working precision (a step below 1e-40 of the root).  Where an estimate near
    the line does not converge so (a cluster of roots: a near-double root, a complex pair close to the
    line), mpmath's polyroots decides, as before session 11: its roots within 1e-30 of the line.  The
    same real roots, at a tenth to a hundredth of polyroots' cost where the roots are simple."""
    import numpy
    scale = max(abs(c) for c in cs)
    if scale == 0 or not mp.isfinite(scale):
        return []
    try:
        est = numpy.roots([float(c / scale) for c in cs])
    except (numpy.linalg.LinAlgError, ValueError):
        est = numpy.array([numpy.nan])
    out = []
    for r in est if numpy.isfinite(est).all() else ():
        if abs(r.imag) > NEAR_REAL * max(1.0, abs(r)):
            continue
        x = _newton(cs, mp.mpf(float(r.real)))
        x = x if x is not None else _newton(cs, mp.mpf(float(r.real)), 2)       # a double root
        if x is None:
            break                       # a cluster: polyroots decides
        out.append(x)
    else:
        if numpy.isfinite(est).all():
            return out
    try:
        roots = mp.polyroots(cs, maxsteps=200, extraprec=200)
    except (mp.libmp.NoConvergence, ZeroDivisionError, ValueError):
        return []
    return [mp.re(r) for r in roots if abs(mp.im(r)) <= 1e-30 * max(1, abs(r))]


def _newton(cs: Sequence, x, multiplicity: int = 1):
    """A root of Σ cs[k] X^(n−k) by Newton's method from x (for a root of that multiplicity), or None
    where it does not converge in NEWTON_STEPS to a step below 1e-40 of the root, or where the
    polynomial is not 0 there to 1e-40 of the sum of its terms' magnitudes (a complex pair near the line)."""
    for _ in range(NEWTON_STEPS):
        v, d = mp.polyval(cs, x, derivative=True)
        if v == 0:
            return x
        if d == 0:
            break
        step = multiplicity * v / d
        x -= step
        if abs(step) <= mp.mpf(10) ** -40 * max(1, abs(x)):
            size = mp.polyval([abs(c) for c in cs], abs(x))
            return x if abs(mp.polyval(cs, x)) <= mp.mpf(10) ** -40 * size else None
    return None


def _move(p: tuple, args: Sequence[KernelArg], rng: random.Random, scale: float) -> tuple:
    """p moved at random by a relative step `scale` of each argument's range (log range for a
    geometric one), in one coordinate or in all; kept inside the box."""
    q = list(p)
    coords = [rng.randrange(len(p))] if rng.random() < 0.5 else range(len(p))
    for i in coords:
        a = args[i]
        step = rng.gauss(0.0, 1.0) * scale
        if a.log and a.lo > 0:
            v = q[i] * math.exp(step * math.log(a.hi / a.lo))
        else:
            v = q[i] + step * (a.hi - a.lo)
        if scale < 1e-13:                      # a few ulp
            v = q[i]
            for _ in range(rng.randint(1, 4)):
                v = math.nextafter(v, math.inf if rng.random() < 0.5 else -math.inf)
        q[i] = min(max(v, a.lo), a.hi)
    return tuple(q)


SCALES = (3e-2, 3e-3, 3e-4, 3e-5, 1e-6, 1e-8, 1e-11, 1e-16)


def climb_length(budget: int) -> int:
    """The number of points :func:`climb` tries with a budget."""
    return max(1, budget // len(SCALES)) * len(SCALES)


def climb(start: tuple, value: float, score: Callable[[tuple, float], float], args: Sequence[KernelArg],
          seed: str, budget: int) -> tuple[tuple, float, list[tuple]]:
    """A local search from `start` (scaled error `value`) that climbs the scaled error: random steps
    at decreasing scales, kept when they raise it. score(p, floor) gives the scaled error at p
    (or anything ≤ floor when it cannot beat it).  Returns (best point, its value, points tried)."""
    rng = random.Random(f"{seed}:climb:{start}")
    best, best_v, tried = start, value, []
    per = max(1, budget // len(SCALES))
    for scale in SCALES:
        for _ in range(per):
            q = _move(best, args, rng, scale)
            tried.append(q)
            v = score(q, best_v)
            if v > best_v:
                best, best_v = q, v
    return best, best_v, tried
