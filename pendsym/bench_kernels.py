"""``make bench``: speed against error for every generated kernel of a memoir (issue #11, point 6).

For each kernel listed in ``generated/results.json``, on random, non-repeating points drawn from
its declared domain (log-uniform for a geometric argument; seeded by the kernel's name):

  * the naive printed form in double, where the memoir prints the formula (the same function as
    the derived one: :func:`pendsym.emit.kernels.naive_form`), printed to C by the kernels' printer
    with the kernel's guard, in its own translation unit;
  * the stable C kernel, ``generated/c/<memoir>.c`` compiled in its own translation unit, called
    from a timing loop in another (as a user links it: no inlining across);
  * the Python kernel, per call; the same kernel on numpy arrays, per element;
  * scipy, where scipy.special has the function (none of the kernels so far is one);
  * mpmath at 15 digits (the derived form, ``lambdify(..., "mpmath")``), per call.

Times are the minimum and the median of :data:`REPEATS` runs (wall clock, this machine, its load
noted).  Errors are the largest error in ulp of the 50-digit value of the derived form over
:data:`ERROR_POINTS` random points, the same points for every method.
"""
from __future__ import annotations

import argparse
import ctypes
import json
import math
import statistics
import subprocess
import tempfile
import time
from pathlib import Path
from typing import Callable, Sequence

import mpmath as mp
import numpy
import sympy as sp

from . import pipeline, stages
from .audit import arrays as ar
from .audit import points as pt
from .audit.code import TIMING_PREAMBLE, c_loop, c_time
from .audit.run import _arguments, _load_py
from .emit import kernels as kn
from .emit.kernels.compile import CC
from .emit.kernels.measure import ref_dps
from .io import write_atomic

TIME_POINTS = 4096        # random points of a C timing run
PY_POINTS = 1000          # random points of a Python timing run
ARRAY_POINTS = 10**6      # elements of a numpy timing run (fewer for a heavy kernel: ARRAY_BUDGET)
ARRAY_BUDGET = 0.25       # seconds a numpy timing call may take
MP_POINTS = 40            # random points of an mpmath timing run
ERROR_POINTS = 100        # random points of the error columns
REPEATS = 5


def _prototyped_loop(fname: str, n: int) -> str:
    """The timing loop of fname with its prototype (the memoir's header is not included: the naive
    forms are in no header)."""
    return f"double {fname}({', '.join(['double'] * n)});\n" + c_loop(fname, n)


def naive_c(name: str, args, expr: sp.Expr) -> str:
    """The naive form as a C function named ``<name>_naive`` (with the kernel's guard), or '' where
    the C printer cannot print it."""
    try:
        return kn.definition(kn.kernel_function(f"{name}_naive", args, expr), "c")
    except Exception:  # SymPy's C printer raises its own kinds for a function C99 lacks
        return ""


def compile_units(units: Sequence[str], work: Path) -> ctypes.CDLL:
    """Each text its own translation unit, into one shared library."""
    paths = []
    for i, text in enumerate(units):
        paths.append(work / f"unit{i}.c")
        paths[-1].write_text(text)
    lib = work / "bench_kernels.so"
    done = subprocess.run([*CC, "-o", str(lib), *map(str, paths), "-lm"], capture_output=True, text=True)
    if done.returncode:
        raise RuntimeError(f"cc failed: {done.stderr.strip()[:2000]}")
    return ctypes.CDLL(str(lib))


def call_time(fn: Callable, pts: Sequence[tuple], repeats: int = REPEATS) -> tuple[float, float]:
    """(min, median) ns per call of a Python callable over `repeats` passes over the points."""
    runs = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        for p in pts:
            fn(*p)
        runs.append((time.perf_counter() - t0) * 1e9 / len(pts))
    return round(min(runs), 1), round(statistics.median(runs), 1)


def values(fn: Callable, pts: Sequence[tuple]) -> list[float]:
    """fn at each point (NaN where it raises)."""
    out = []
    for p in pts:
        try:
            out.append(float(fn(*p)))
        except (ValueError, ZeroDivisionError, OverflowError):
            out.append(math.nan)
    return out


def max_ulp(got: Sequence[float], truths: Sequence) -> float:
    """The largest error in ulp of the true value (inf where a value is not finite)."""
    worst = 0.0
    for v, t in zip(got, truths):
        if not math.isfinite(v):
            return math.inf
        if abs(t) < 1e-300:
            err = 0.0 if abs(v) < 1e-300 else math.inf
        else:
            err = float(abs(mp.mpf(v) - t)) / math.ulp(float(t))
        worst = max(worst, err)
    return round(worst, 2)


def bench_kernel(name: str, result, mod, lib, has_naive: bool, work_seed: str = "") -> dict:
    """One kernel's row: each method's (min, median) time and its largest error in ulp."""
    args, syms = _arguments(result)
    seed = name + ":bench" + work_seed
    pts = pt.random_points(args, seed, TIME_POINTS)
    err_pts = pts[:ERROR_POINTS]
    f50 = sp.lambdify(syms, result.derived, modules="mpmath", cse=True)
    truths = []
    for p in err_pts:
        with mp.workdps(ref_dps(p)):
            truths.append(f50(*[mp.mpf(v) for v in p]))
    py = getattr(mod, name)

    def mp15(*p):
        with mp.workdps(15):
            return float(f50(*[mp.mpf(v) for v in p]))
    c_fn = getattr(lib, name)
    c_fn.restype, c_fn.argtypes = ctypes.c_double, [ctypes.c_double] * len(args)
    methods = {}
    if has_naive:
        naive = getattr(lib, f"{name}_naive")
        naive.restype, naive.argtypes = ctypes.c_double, [ctypes.c_double] * len(args)
        methods["naive printed form, C double"] = (c_time(lib, f"{name}_naive", pts, REPEATS), max_ulp(values(naive, err_pts), truths))
    methods["stable C kernel"] = (c_time(lib, name, pts, REPEATS), max_ulp(values(c_fn, err_pts), truths))
    methods["Python kernel"] = (call_time(py, pts[:PY_POINTS]), max_ulp(values(py, err_pts), truths))
    *array_ns, elements = ar.ns_per_element(py, [(a.name, a.lo, a.hi, a.log) for a in args], seed,
                                            n=ARRAY_POINTS, repeats=REPEATS, budget=ARRAY_BUDGET)
    methods[f"numpy kernel, per element of {elements:.0e}"] = (tuple(array_ns), max_ulp([float(v) for v in py(*[numpy.array(c) for c in zip(*err_pts)])], truths))
    methods["mpmath, 15 digits"] = (call_time(mp15, pts[:MP_POINTS]), max_ulp(values(mp15, err_pts), truths))
    return {"kernel": name, "result": result.spec.id, "args": [a.name for a in args],
            "domain": [[a.lo, a.hi] for a in args], "scipy": None,
            "methods": {k: {"ns": list(t), "max_ulp": e} for k, (t, e) in methods.items()}}


def run(generated: Path, memoirs: Sequence[str] = ()) -> dict[str, list[dict]]:
    listed = pipeline.load_results_json(generated / "results.json")
    built = stages.build(stages.plan("full"), lambda _msg: None)
    by_memoir: dict[str, list] = {}
    for rid, rec in listed.items():
        if not memoirs or rec["memoir"] in memoirs:
            by_memoir.setdefault(rec["memoir"], []).extend((name, rid) for name in rec["kernels"])
    out = {}
    for memoir, names in by_memoir.items():
        mod = _load_py(generated / "python" / f"{memoir}.py")
        units = [(generated / "c" / f"{memoir}.c").read_text().replace(f'#include "{memoir}.h"', "")]
        loops, naive = [TIMING_PREAMBLE], {}
        for name, rid in names:
            args, _ = _arguments(built[rid])
            form, expr = kn.naive_form(built[rid], args)
            text = naive_c(name, args, expr) if form == "printed" else ""
            if text:
                units.append("#include <errno.h>\n#include <math.h>\n" + text)
                loops.append(_prototyped_loop(f"{name}_naive", len(args)))
                naive[name] = True
            loops.append(_prototyped_loop(name, len(args)))
        units.append("\n".join(loops))
        with tempfile.TemporaryDirectory() as tmp:
            lib = compile_units(units, Path(tmp))
            out[memoir] = [bench_kernel(name, built[rid], mod, lib, naive.get(name, False)) for name, rid in names]
    return out


def table(rows: Sequence[dict]) -> str:
    """The markdown table: one row per kernel and method."""
    lines = [f"| kernel | method | ns (min, median) | max error in ulp ({ERROR_POINTS} random points; not divided by κ) |",
             "|---|---|---:|---:|"]
    for r in rows:
        for method, m in r["methods"].items():
            lines.append(f"| `{r['kernel']}` | {method} | {m['ns'][0]:.3g}, {m['ns'][1]:.3g} | {m['max_ulp']:.3g} |")
        lines.append(f"| `{r['kernel']}` | scipy | — (no scipy.special function) | |")
    return "\n".join(lines) + "\n"


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="python -m pendsym.bench_kernels", description=__doc__.split("\n")[0])
    p.add_argument("--out", default="generated/bench")
    p.add_argument("--generated", default="generated")
    p.add_argument("--memoir", nargs="*", default=(), help="memoirs (default: every memoir with kernels)")
    ns = p.parse_args(argv)
    t0 = time.monotonic()
    rows = run(Path(ns.generated), ns.memoir)
    out = Path(ns.out)
    load = " ".join(f"{v:.2f}" for v in __import__("os").getloadavg())
    for memoir, rs in rows.items():
        write_atomic(out / f"{memoir}-kernels.json", json.dumps({"load": load, "kernels": rs}, indent=1) + "\n")
        write_atomic(out / f"{memoir}-kernels.md", table(rs))
    print(f"bench_kernels: {sum(len(r) for r in rows.values())} kernels in {time.monotonic() - t0:.0f} s "
          f"(load {load}); written to {out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
