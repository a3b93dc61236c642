"""The array path of a generated Python kernel against its scalar path (pendsym/emit/kernels/arrays.py).

Read from the emitted code only (a kernel's accepted domain from its guard, its branch switches
from its comparisons), so that it serves the audit, the bench and the tests alike:

- :func:`domain` and :func:`points`: random points of the accepted domain (log-uniform for a
  positive argument spanning three decades or more) and its hard points (ends, the doubles
  just inside them, 0 and the smallest subnormal where accepted, +inf where accepted, each
  switch and the doubles on either side);
- :func:`compare`: the array path on all the points at once against the scalar path point by
  point: how many differ, and the largest difference in ulp of the scalar value and relative;
- :func:`ns_per_element`: the array path's time per element on random points (min, median);
- :func:`figures`: for ``make audit``, the same comparison on the audit's points, with the array
  path's scaled error where the two differ.
"""
from __future__ import annotations

import math
import re
import statistics
import time
from typing import Callable, Sequence

import numpy

GUARD = re.compile(r"if not (\S+) <= (\w+) <= (\S+):")
SWITCH = re.compile(r"\((\w+) [<>]=? (-?[0-9][0-9.e+-]*)\)")
ARRAY_POINTS = 10**6
PROBE = 10**3          # elements of the call that sizes a timed array to a budget (and the fewest timed)
REPEATS = 5


def function_text(code: str, name: str) -> str:
    """The scalar function `name` of a generated module's text (its guard and its branches)."""
    m = re.search(rf"^def {re.escape(name)}\(.*?(?=^def |\Z)", code, re.S | re.M)
    return m.group(0) if m else ""


def _number(text: str) -> float:
    return {"math.inf": math.inf, "-math.inf": -math.inf}.get(text) if "inf" in text else float(text)


def domain(code: str, name: str) -> list[tuple[str, float, float]]:
    """(argument, lo, hi) of each argument of kernel `name`, read from its guard, in order."""
    return [(x, _number(lo), _number(hi)) for lo, x, hi in GUARD.findall(function_text(code, name))]


def _draw(lo: float, hi: float, rng: numpy.random.Generator, n: int, log: bool | None = None) -> numpy.ndarray:
    """n values in [lo, hi] (hi = inf: up to 1e3), log-uniform where `log` (default: lo > 0 and
    three decades or more)."""
    top = min(hi, max(1e3, 10 * lo) if lo > 0 else 1e3) if hi == math.inf else hi
    if log if log is not None else (lo > 0 and top / lo >= 1e3):
        return numpy.exp(rng.uniform(math.log(lo), math.log(top), n))
    return rng.uniform(lo, top, n)


def random_points(dom: Sequence[tuple], n: int, seed: str) -> numpy.ndarray:
    """n random points of the domain, one row each (seeded by `seed`); dom: (argument, lo, hi) or
    (argument, lo, hi, log) of each argument."""
    rng = numpy.random.default_rng(list(seed.encode()))
    return numpy.column_stack([_draw(d[1], d[2], rng, n, d[3] if len(d) > 3 else None) for d in dom])


def hard_values(code: str, name: str, x: str, lo: float, hi: float) -> list[float]:
    """The hard values of argument x: its ends and the doubles inside them, 0 and the smallest
    subnormal where accepted, +inf where accepted, and each switch on x with its neighbours."""
    out = [lo, math.nextafter(lo, math.inf)]
    if hi != math.inf:
        out += [hi, math.nextafter(hi, -math.inf)]
    else:
        out += [math.inf, 1e300, 1e20]
    if lo == 0.0:
        out += [5e-324, 1e-310, 1e-300, 1e-160]
    for var, value in SWITCH.findall(function_text(code, name)):
        if var == x and lo <= float(value) <= hi:
            v = float(value)
            out += [math.nextafter(v, -math.inf), v, math.nextafter(v, math.inf)]
    return sorted({v for v in out if lo <= v <= hi})


def points(code: str, name: str, n: int, seed: str = "") -> numpy.ndarray:
    """n random points of kernel `name`'s accepted domain, then its hard points (each hard value of
    one argument, the others at random)."""
    dom = domain(code, name)
    rows = [random_points(dom, n, seed or name)]
    rng = numpy.random.default_rng(list((seed or name).encode()) + [1])
    for i, (x, lo, hi) in enumerate(dom):
        vals = hard_values(code, name, x, lo, hi)
        block = numpy.column_stack([_draw(a, b, rng, len(vals)) for _, a, b in dom])
        block[:, i] = vals
        rows.append(block)
    return numpy.vstack(rows)


def scalar_values(fn: Callable, pts: numpy.ndarray) -> numpy.ndarray:
    return numpy.array([fn(*map(float, p)) for p in pts])


def compare(fn: Callable, pts: numpy.ndarray) -> dict:
    """The array path on all points against the scalar path: the points where they differ (NaN
    compared equal to NaN), the largest difference in ulp of the scalar value, and where."""
    scalar = scalar_values(fn, pts)
    array = fn(*[numpy.ascontiguousarray(c) for c in pts.T])
    same = (array == scalar) | (numpy.isnan(array) & numpy.isnan(scalar))
    same &= numpy.signbit(array) == numpy.signbit(scalar)
    worst, rel, at = 0.0, 0.0, None
    for i in numpy.flatnonzero(~same):
        a, s = float(array[i]), float(scalar[i])
        d = abs(a - s) / math.ulp(max(abs(a), abs(s))) if math.isfinite(s) and math.isfinite(a) else math.inf
        rel = max(rel, abs(a - s) / abs(s) if s != 0 and math.isfinite(d) else math.inf)
        if d > worst:
            worst, at = d, [float(v) for v in pts[i]]
    return {"points": len(pts), "differ": int((~same).sum()), "max_ulp": worst, "max_rel": rel, "at": at}


def ns_per_element(fn: Callable, dom: Sequence[tuple], seed: str, n: int = ARRAY_POINTS,
                   repeats: int = REPEATS, budget: float | None = None) -> tuple[float, float, int]:
    """(min, median, elements) ns per element of the array path over `repeats` calls on random
    points: n of them, or with a `budget` (seconds a call) as many as fit in it, at most n and at
    least PROBE (a heavy kernel is timed on fewer elements; the figure per element grows with the
    array: at 10**6 the temporaries outgrow the caches)."""
    if budget is not None:
        probe = [numpy.ascontiguousarray(c) for c in random_points(dom, PROBE, seed + ":probe").T]
        fn(*probe)
        t0 = time.perf_counter()
        fn(*probe)
        n = int(min(n, max(PROBE, budget * PROBE / max(time.perf_counter() - t0, 1e-9))))
    cols = [numpy.ascontiguousarray(c) for c in random_points(dom, n, seed + ":numpy").T]
    fn(*cols)
    runs = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn(*cols)
        runs.append((time.perf_counter() - t0) * 1e9 / n)
    return round(min(runs), 1), round(statistics.median(runs), 1), n


def figures(py: Callable, judge, rows: Sequence[tuple], bound: float) -> dict:
    """For the audit (`judge`: its Judge; `rows`: its rows, (max scaled, point, Python ulp, C ulp, κ, …)):
    the array path (the Python kernel `py` called on numpy arrays) on every point at once,
    against the scalar path: the points where the two differ and by how many ulp at most; its
    scaled error where they differ (the scalar one plus the difference, an upper bound, unless that
    could exceed the bound: then against the reference)."""
    pts = numpy.array([r[1] for r in rows], dtype=float)
    known = getattr(judge, "py_values", {})
    scalar = numpy.array([known[r[1]] if r[1] in known else judge._call(py, r[1]) for r in rows])
    array = py(*[numpy.ascontiguousarray(c) for c in pts.T])
    same = (array == scalar) | (numpy.isnan(array) & numpy.isnan(scalar))
    worst_diff, worst = 0.0, 0.0
    for i in numpy.flatnonzero(~same):
        r, a, s = rows[i], float(array[i]), float(scalar[i])
        diff = abs(a - s) / math.ulp(max(abs(a), abs(s))) if math.isfinite(a) and math.isfinite(s) else math.inf
        worst_diff = max(worst_diff, diff)
        m = max(1.0, r[4]) if not math.isnan(r[4]) else 1.0
        scaled = (r[2] + diff) / m
        if scaled > bound:                       # measured: the array value against the reference
            k = judge.kappa(r[1]) if math.isnan(r[4]) else r[4]
            scaled = judge.ulp(a, judge.truth(r[1])) / max(1.0, k if not math.isnan(k) else 1.0)
        worst = max(worst, scaled)
    py_worst = max((r[5] for r in rows), default=0.0)
    return {"points": len(rows), "differ": int((~same).sum()), "max_diff_ulp": round(worst_diff, 3),
            "worst_scaled": round(max(worst, py_worst), 3)}
