"""``make audit``: every generated kernel measured as a user would call it, hunting for its worst case.

For each kernel listed in ``generated/results.json``:

1. the emitted C (``generated/c/<memoir>.c`` compiled with ``cc -std=c99 -O2``, its own
   translation unit) and the emitted Python (``generated/python/<memoir>.py`` imported) are
   evaluated on at least :data:`POINTS` points: the hard points and random points of
   :mod:`.points`, then an adversarial local search (:func:`.points.climb`) from the worst
   points found, which climbs the scaled error ulp / max(1, κ);
2. the reference is the Result's *derived* form in mpmath at 50 digits, 8 more per decade the
   smallest argument lies below 1 (:func:`pendsym.emit.kernels.limits.ref_dps`), and
   every point whose error exceeds the bound is confirmed with :data:`CONFIRM_DIGITS` more;
   κ is the condition number of :func:`pendsym.emit.kernels.measure.reference` (computed where
   the error in ulp could exceed the scaled error already found: scaled ≤ ulp);
3. the C time per call is measured on random points of the domain (min and median of 5 runs);
4. the Python kernel is called once more on numpy arrays of every point of its audit (its array
   path, :mod:`.arrays`): where it departs from the scalar path bitwise (numpy's SIMD exp, tanh …
   against libm's), by how many ulp, and its scaled error there; and its time per element on up
   to 10**6 random points.

It writes ``<out>/audit.json`` and ``<out>/audit.md`` and exits 1 when a kernel is over
:data:`pendsym.emit.kernels.BOUND` in either language.  Seeds are the kernels' names.
"""
from __future__ import annotations

import argparse
import ctypes
import heapq
import json
import math
import random
import re
import shutil
import sys
import tempfile
import time
from errno import EDOM
from dataclasses import dataclass
from pathlib import Path
from typing import Callable, Sequence

import mpmath as mp
import sympy as sp
from mpmath import libmp

from .. import pipeline, schedule, stages
from ..emit import kernels as kn
from ..emit.kernels.limits import LIMIT_FAR, far_dps, far_values, ref_dps
from ..emit.kernels.measure import reference
from ..result import KernelArg
from . import arrays as ar
from . import points as pt
from .code import _load_py, c_function, c_ns, compile_memoir, numpy_ns
from .reference import fast_reference

LIMIT_AT = 1e-80         # the reference at 0 of an argument accepted down to 0: the form here
POINTS = 20_000          # points per kernel, the search included
CLIMB_STARTS = 8         # the worst points the search starts from
CLIMB_BUDGET = 1_200     # evaluations of the search, over its starts
CONFIRM_DIGITS = 60      # more digits for a point whose error exceeds the bound
TINY_POINTS = 64         # points in (0, lo) of an argument accepted down to 0 (each needs up to 2,600 digits)


@dataclass(frozen=True)
class Job:
    name: str
    memoir: str
    result_id: str
    args: tuple[KernelArg, ...]
    expr: sp.Expr
    syms: tuple
    py: Callable
    c: Callable
    code: str               # the emitted Python function (for its branch switches)
    domain: tuple = ()      # the accepted [lo, hi] of each argument (read from the emitted guard)


def _arguments(result) -> tuple[tuple[KernelArg, ...], tuple]:
    by = {s.name: s for s in result.derived.free_symbols}
    args = tuple(a for a in result.spec.kernel.args if a.name in by)
    return args, tuple(by[a.name] for a in args)


class Judge:
    """The scaled error of a kernel's Python and C at a point, against the derived form."""

    def __init__(self, job: Job):
        self.job = job
        probe = tuple(math.sqrt(a.lo * a.hi) if a.log and a.lo > 0 else (a.lo + a.hi) / 2 for a in job.args)
        self.f, self.cond, self.engine = fast_reference(job.expr, job.syms, probe)
        self.py_values: dict[tuple, float] = {}     # the scalar Python kernel's value at each point measured

    def truth(self, p: tuple, extra: int = 0):
        at = [v if v != 0 or not self.zero_limit(i) else LIMIT_AT for i, v in enumerate(p)]
        far = [i for i, v in enumerate(at) if v == math.inf]           # accepted up to +inf: the limit there
        beyond = any(v > a.hi for v, a in zip(at, self.job.args))      # above hi: digits for the form's cancellation
        with mp.workdps((far_dps([LIMIT_FAR[1] if v == math.inf else v for v in at]) if beyond else ref_dps(at)) + extra):
            if far:
                lo_at, hi_at = list(at), list(at)
                for i in far:
                    lo_at[i], hi_at[i] = LIMIT_FAR
                try:
                    v0, v1 = (abs(self.f(*[mp.mpf(x) for x in q])) for q in (lo_at, hi_at))
                except (ZeroDivisionError, ValueError, OverflowError):
                    return mp.nan
                if v1 <= mp.mpf(10) ** -30 * v0:
                    return mp.mpf(0)
                at = hi_at
            if any(v != w for v, w in zip(p, at)) and not far and self._vanishes(at):
                return mp.mpf(0)
            p = at
            try:
                return self.f(*[mp.mpf(x) for x in p])
            except (ZeroDivisionError, ValueError, OverflowError):
                return mp.nan

    def zero_limit(self, i: int) -> bool:
        """Argument i is accepted down to 0 (there the reference is the limit)."""
        return i < len(self.job.domain) and self.job.domain[i][0] == 0 < self.job.args[i].lo

    def _vanishes(self, at) -> bool:
        """The derived form at LIMIT_AT is below 1e-300: its limit is taken as 0."""
        return abs(self.f(*[mp.mpf(v) for v in at])) < mp.mpf(10) ** -300

    def kappa(self, p: tuple) -> float:
        if any(v == math.inf for v in p):       # the limit at +inf: its κ in the other arguments, at LIMIT_FAR
            p = tuple(LIMIT_FAR[1] if v == math.inf else v for v in p)
        beyond = any(v > a.hi for v, a in zip(p, self.job.args))
        with mp.workdps(far_dps(p) if beyond else ref_dps(p)):
            try:
                return float(self.cond(*[mp.mpf(x) for x in p]))
            except (ZeroDivisionError, ValueError, OverflowError):
                return math.inf

    @staticmethod
    def _call(fn, p) -> float:
        try:
            v = float(fn(*p))
        except (OverflowError, ZeroDivisionError, ValueError):
            return math.nan
        return v

    @staticmethod
    def ulp(got: float, true) -> float:
        return Judge._ulp(got, Judge.split(true))

    @staticmethod
    def split(true) -> tuple | None:
        """The true value as hi + lo in doubles (hi = true rounded, lo = the rest rounded; None where
        true is not finite; (0, None) where it is 0), so that an error in ulp costs two double operations."""
        if not mp.isfinite(true):
            return None
        if true == 0:
            return 0.0, None
        hi = float(true)
        return hi, libmp.to_float(libmp.mpf_sub(true._mpf_, libmp.from_float(hi), 0))  # (exact)

    @staticmethod
    def _ulp(got: float, parts: tuple | None) -> float:
        """|got − true| / ulp(true): got − hi is exact where got is within a factor 2 of true (Sterbenz),
        and the error is rounded once, to ~1e-16 of itself."""
        if not math.isfinite(got) or parts is None:
            return math.inf
        hi, lo = parts
        if lo is None:
            return 0.0 if abs(got) < 1e-300 else math.inf
        return abs((got - hi) - lo) / math.ulp(hi)

    def errors(self, p: tuple, extra: int = 0) -> tuple[float, float]:
        """(Python ulp, C ulp) at p."""
        parts = self.split(self.truth(p, extra))
        py = self.py_values[p] = self._call(self.job.py, p)
        return self._ulp(py, parts), self._ulp(self._call(self.job.c, p), parts)

    def scaled(self, p: tuple, floor: float = -1.0, known: tuple | None = None) -> tuple[float, float, float, float, float]:
        """(Python ulp, C ulp, κ, Python scaled, C scaled); κ only where the error could beat `floor`
        (else NaN, and the scaled errors are the ulp errors, an upper bound).  A scaled error over
        the bound is confirmed with CONFIRM_DIGITS more digits in the reference (`known`: the errors
        at p, already measured)."""
        e_py, e_c = known or self.errors(p)
        if max(e_py, e_c) <= max(floor, 1.0):
            return e_py, e_c, math.nan, e_py, e_c
        k = self.kappa(p)
        m = max(1.0, k) if not math.isnan(k) else 1.0
        if max(e_py, e_c) / m > kn.BOUND:
            e_py, e_c = self.errors(p, CONFIRM_DIGITS)
        return e_py, e_c, k, e_py / m, e_c / m


def accepted(code: str, name: str, args: Sequence[KernelArg]) -> tuple:
    """The accepted [lo, hi] of each argument, read from the guard of the emitted Python function
    ``if not lo <= x <= hi:`` (the declared range where it has none)."""
    m = re.search(rf"^def {re.escape(name)}\(.*?(?=^def |\Z)", code, re.S | re.M)
    text = m.group(0) if m else ""
    out = []
    for a in args:
        g = re.search(rf"if not (\S+) <= {re.escape(kn.identifier(a.name))} <= (\S+):", text)
        out.append((_number(g.group(1)), _number(g.group(2))) if g else (a.lo, a.hi))
    return tuple(out)


def _number(text: str) -> float:
    """A bound of the guard: a float literal, or math.inf (an argument accepted up to +inf)."""
    return math.inf if text == "math.inf" else -math.inf if text == "-math.inf" else float(text)


def outside(job: Job, errno_of: Callable[[], int]) -> list[str]:
    """The documented behaviour outside the accepted domain, tried at NaN, ±inf and the doubles
    just outside each end of each argument: ValueError naming the argument in Python, NaN with
    errno = EDOM in C.  Returns the departures from it."""
    bad = []
    inside = tuple((lo + hi) / 2 if not a.log else math.sqrt(max(lo, a.lo) * min(hi, a.hi))
                   for a, (lo, hi) in zip(job.args, job.domain))
    for i, (lo, hi) in enumerate(job.domain):
        for v in (math.nan, math.inf, -math.inf, math.nextafter(lo, -math.inf), math.nextafter(hi, math.inf)):
            if lo <= v <= hi:
                continue
            p = list(inside)
            p[i] = v
            name = kn.identifier(job.args[i].name)
            try:
                job.py(*p)
                bad.append(f"Python {name} = {v!r}: no error")
            except ValueError as exc:
                if f"{name} = " not in str(exc) or "domain" not in str(exc):
                    bad.append(f"Python {name} = {v!r}: {exc}")
            except Exception as exc:  # any other exception is a departure
                bad.append(f"Python {name} = {v!r}: {type(exc).__name__}")
            ctypes.set_errno(0)
            got = job.c(*p)
            if not math.isnan(got) or errno_of() != EDOM:
                bad.append(f"C {name} = {v!r}: {got!r}, errno {errno_of()}")
    return bad


def tiny_points(job: Job, rng_seed: str) -> list[tuple]:
    """For an argument accepted down to 0: 0, the smallest subnormal, and points log-uniform in (0, lo)."""
    rng = random.Random(rng_seed + ":tiny")
    out = []
    for i, (a, (lo, _)) in enumerate(zip(job.args, job.domain)):
        if not lo < a.lo:
            continue
        vals = [0.0, 5e-324, 1e-310, 1e-300, 1e-160, 1e-150, math.nextafter(a.lo, 0.0)]
        vals += [math.exp(rng.uniform(math.log(5e-324), math.log(a.lo))) for _ in range(TINY_POINTS)]
        for v in vals:
            p = [pt.draw(b, rng) for b in job.args]
            p[i] = v
            out.append(tuple(p))
    return out


def far_points(job: Job, rng_seed: str) -> list[tuple]:
    """For an argument accepted up to +inf: the values of :func:`limits.far_values` (+inf included) and
    points log-uniform in (hi, 1e300), the other arguments at random."""
    rng = random.Random(rng_seed + ":far")
    out = []
    for i, (a, (_, hi)) in enumerate(zip(job.args, job.domain)):
        if not hi > a.hi:
            continue
        vals = list(far_values(a.hi)) + [math.exp(rng.uniform(math.log(a.hi), math.log(1e300))) for _ in range(TINY_POINTS)]
        for v in vals:
            p = [pt.draw(b, rng) for b in job.args]
            p[i] = v
            out.append(tuple(p))
    return out


def audit_one(job: Job, points: int | None = None) -> dict:
    """The audit of one kernel (run in a worker): its figures and its worst point (`points`: at
    least so many, the search included; POINTS unless given, fewer only for a quick measure)."""
    start = time.process_time()
    points = POINTS if points is None else points
    judge = Judge(job)
    params = [kn.identifier(a.name) for a in job.args]
    hard = (pt.hard_points(job.args, params, job.code, job.expr, job.syms, job.name) + tiny_points(job, job.name)
            + far_points(job, job.name))
    climbs = CLIMB_STARTS * pt.climb_length(CLIMB_BUDGET // CLIMB_STARTS)
    pts = list(dict.fromkeys(hard))
    seen = set(pts)
    pts += [p for p in dict.fromkeys(pt.random_points(job.args, job.name, max(0, points - len(pts) - climbs)))
            if p not in seen]
    rows = []                                   # (max scaled, point, py ulp, c ulp, κ, py scaled, c scaled)
    first = [(p, judge.errors(p)) for p in pts]
    # κ in decreasing order of the ulp error, until no further point can enter the worst few
    first.sort(key=lambda r: -max(r[1]))
    worst: list = []
    top: list = []                              # a heap of the CLIMB_STARTS largest scaled errors
    for p, (e_py, e_c) in first:
        floor = top[0] if len(top) >= CLIMB_STARTS else -1.0
        if max(e_py, e_c) <= max(floor, 1.0) and max(e_py, e_c) <= kn.BOUND:
            rows.append((max(e_py, e_c), p, e_py, e_c, math.nan, e_py, e_c))
            continue
        row = judge.scaled(p, known=(e_py, e_c))
        rows.append((max(row[3], row[4]), p, *row))
        worst.append(rows[-1])
        heapq.heappush(top, rows[-1][0])
        if len(top) > CLIMB_STARTS:
            heapq.heappop(top)
    tried = len(pts)
    starts = sorted(worst or rows, key=lambda r: -r[0])[:CLIMB_STARTS]
    for r in starts:
        def score(q, floor):
            row = judge.scaled(q, floor)
            rows.append((max(row[3], row[4]), q, *row))
            return rows[-1][0]
        _, _, seen = pt.climb(r[1], r[0], score, job.args, job.name, CLIMB_BUDGET // max(1, len(starts)))
        tried += len(seen)
    top = max(rows, key=lambda r: (r[0], -sum(r[1])))
    check = reference_check(judge, top)
    fails_py = sum(1 for r in rows if r[5] > kn.BOUND)
    fails_c = sum(1 for r in rows if r[6] > kn.BOUND)
    worst_py = max(rows, key=lambda r: r[5])
    worst_c = max(rows, key=lambda r: r[6])
    return {
        "kernel": job.name, "memoir": job.memoir, "result": job.result_id, "points": tried,
        "args": [a.name for a in job.args],
        "domain": [[a.lo, a.hi] for a in job.args],
        "worst_scaled": round(top[0], 3), "worst_at": list(top[1]),
        "kappa_there": None if math.isnan(top[4]) else top[4],
        "python": {"worst_scaled": round(worst_py[5], 3), "at": list(worst_py[1]),
                   "worst_ulp": round(max(r[2] for r in rows), 3), "over_bound": fails_py},
        "c": {"worst_scaled": round(worst_c[6], 3), "at": list(worst_c[1]),
              "worst_ulp": round(max(r[3] for r in rows), 3), "over_bound": fails_c},
        "domain_accepted": [list(d) for d in job.domain],
        "outside": outside(job, ctypes.get_errno),
        "numpy": ar.figures(job.py, judge, rows, kn.BOUND) if f"return _{job.name}_array(" in job.code else None,
        "reference": check,
        "cpu_s": round(time.process_time() - start, 1),
    }


CHECK_DIGITS = 20        # more digits of the mpmath reference that confirms the worst point


def reference_check(judge: Judge, top: tuple) -> dict:
    """The worst point's errors again against mpmath's own form (:func:`reference`) at CHECK_DIGITS more
    digits: an independent evaluation of the reference, which must agree to 1e-6 ulp."""
    again = Judge.__new__(Judge)
    again.job, again.engine, again.py_values = judge.job, "mpmath", {}
    again.f, again.cond = reference(judge.job.expr, list(judge.job.syms))
    e_py, e_c = again.errors(top[1], CHECK_DIGITS)
    agrees = all((a == b) or abs(a - b) <= 1e-6 * max(1.0, abs(b)) for a, b in ((e_py, top[2]), (e_c, top[3])))
    return {"engine": judge.engine, "checked_with": f"mpmath, +{CHECK_DIGITS} digits", "agrees": agrees}


def jobs(generated: Path, work: Path, only: Sequence[str] = ()) -> tuple[dict[str, Job], dict[str, ctypes.CDLL]]:
    """The kernels listed in results.json, with their emitted Python and C loaded, and the
    derived forms of their Results (from the cache of make derive)."""
    listed = pipeline.load_results_json(generated / "results.json")
    pl = stages.plan("full")
    built = stages.build(pl, lambda _msg: None)
    by_memoir: dict[str, list] = {}
    for rid, rec in listed.items():
        for name in rec["kernels"]:
            if only and name not in only:
                continue
            by_memoir.setdefault(rec["memoir"], []).append((name, rid))
    out, libs = {}, {}
    for memoir, names in by_memoir.items():
        mod = _load_py(generated / "python" / f"{memoir}.py")
        arity = {name: len(_arguments(built[rid])[0]) for name, rid in names}
        libs[memoir] = lib = compile_memoir(generated, memoir, list(arity.items()), work)
        text = (generated / "python" / f"{memoir}.py").read_text()
        for name, rid in names:
            args, syms = _arguments(built[rid])
            out[name] = Job(name, memoir, rid, args, built[rid].derived, syms, getattr(mod, name),
                            c_function(lib, name, len(args)), text, accepted(text, name, args))
    return out, libs


def cost(job: Job) -> tuple:
    """The order in which kernels go to the workers, the costliest first (so that the last to finish is a
    cheap one): the forms with a function MPFR lacks (Bessel's: an Arb or mpmath reference), then by size."""
    special = bool(job.expr.atoms(sp.besselj, sp.bessely, sp.besseli, sp.besselk))
    return special, sp.count_ops(job.expr) * len(job.args)


# ----------------------------------------------------------------- report
def _fmt_point(job_args: Sequence[str], p: Sequence[float]) -> str:
    return ", ".join(f"{a} = {v:.6g}" for a, v in zip(job_args, p))


def table(rows: Sequence[dict]) -> str:
    lines = ["| kernel | points | worst ulp/max(1, κ) (Python, C) | where | C ns/call (min, median) | numpy ns/element |",
             "|---|---:|---:|---|---:|---:|"]
    for r in rows:
        ns = r.get("c_ns")
        lines.append(f"| `{r['kernel']}` | {r['points']} | {r['python']['worst_scaled']:.3g}, {r['c']['worst_scaled']:.3g} "
                     f"| {_fmt_point(r['args'], r['worst_at'])} | "
                     f"{f'{ns[0]:.0f}, {ns[1]:.0f}' if ns else '—'} | {_numpy_cell(r)} |")
    return "\n".join(lines) + "\n"


def _numpy_cell(r: dict) -> str:
    """numpy ns/element (min, median), and where the array path departs from the scalar path bitwise
    (numpy's SIMD exp, tanh … against libm's) the points and the largest difference in ulp."""
    ns, nf = r.get("numpy_ns"), r.get("numpy") or {}
    cell = f"{ns[0]:.0f}, {ns[1]:.0f}" + (f" (on {ns[2]:.0e})" if len(ns) > 2 and ns[2] < ar.ARRAY_POINTS else "") if ns else "—"
    return cell + (f" ({nf['differ']} pts ≤ {nf['max_diff_ulp']:.3g} ulp from scalar)" if nf.get("differ") else "")


def over(rows: Sequence[dict]) -> list[dict]:
    """The kernels over the bound in either language, or departing from the behaviour outside the domain."""
    return [r for r in rows if r["python"]["worst_scaled"] > kn.BOUND or r["c"]["worst_scaled"] > kn.BOUND
            or r.get("outside") or (r.get("numpy") or {}).get("worst_scaled", 0.0) > kn.BOUND
            or not r.get("reference", {}).get("agrees", True)]


def main(argv: Sequence[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m pendsym.audit", description=__doc__.split("\n")[0])
    ap.add_argument("--generated", default="generated")
    ap.add_argument("--out", default="generated/audit")
    ap.add_argument("--only", nargs="*", default=(), help="kernel names (default: every kernel)")
    ap.add_argument("--no-timing", action="store_true")
    ns = ap.parse_args(argv)
    if not shutil.which("cc"):
        print("audit: no C compiler (cc)", file=sys.stderr)
        return 2
    t0, c0 = time.monotonic(), time.process_time()
    generated, out = Path(ns.generated), Path(ns.out)
    with tempfile.TemporaryDirectory() as tmp:
        todo, libs = jobs(generated, Path(tmp), ns.only)
        ids = sorted(todo, key=lambda n: cost(todo[n]), reverse=True)

        def measure(job: Job) -> dict:
            """The audit of one kernel, then its timings (in the same worker: the kernels' timings are
            spread over the cores like their audits)."""
            row = audit_one(job)
            if not ns.no_timing:
                start = time.process_time()
                row["c_ns"] = list(c_ns(libs[job.memoir], job))
                row["numpy_ns"] = list(numpy_ns(job)) if row.get("numpy") else None
                row["timing_cpu_s"] = round(time.process_time() - start, 1)
            return row
        results = dict(zip(ids, schedule.per_result(todo, ids, measure)))
        rows = [results[n] for n in todo]
    out.mkdir(parents=True, exist_ok=True)
    (out / "audit.json").write_text(json.dumps({"bound": kn.BOUND, "kernels": rows}, indent=1) + "\n")
    (out / "audit.md").write_text(table(rows))
    bad = over(rows)
    cpu = time.process_time() - c0 + sum(r["cpu_s"] + r.get("timing_cpu_s", 0.0) for r in rows) * (schedule.can_fork())
    print(f"audit: {len(rows)} kernels, {sum(r['points'] for r in rows)} points, "
          f"{time.monotonic() - t0:.0f} s wall, ~{cpu:.0f} s CPU; written to {out}")
    for r in bad:
        print(f"OVER THE BOUND {r['kernel']}: Python {r['python']['worst_scaled']:.3g} "
              f"({r['python']['over_bound']} points), C {r['c']['worst_scaled']:.3g} ({r['c']['over_bound']} points), "
              f"numpy {(r.get('numpy') or {}).get('worst_scaled', math.nan):.3g} "
              f"at {_fmt_point(r['args'], r['worst_at'])}" + (f"; outside the domain: {r['outside'][:3]}" if r.get("outside") else "")
              + ("" if r.get("reference", {}).get("agrees", True) else "; the mpmath check of the reference disagrees"))
    print(summary(rows, bad))
    return 1 if bad else 0


def summary(rows: Sequence[dict], bad: Sequence[dict]) -> str:
    """The audit's last line: its verdict, one line."""
    if bad:
        return (f"audit: FAILED: {len(bad)} of {len(rows)} kernels over {kn.BOUND:g} ulp × max(1, κ) or off the "
                f"contract: {', '.join(r['kernel'] for r in bad)}")
    worst = max(rows, key=lambda r: r["worst_scaled"], default=None)
    return (f"audit: passed: {len(rows)} kernels within {kn.BOUND:g} ulp × max(1, κ)"
            + (f" (worst {worst['worst_scaled']:.3g}, {worst['kernel']})" if worst else ""))
