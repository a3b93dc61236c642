"""``make bench``: speed against error for the swing time of the simple pendulum.

The swing time (one swing, T = π/k at small amplitude) of θ'' + k² sin θ = 0 from rest at
−α, for α from 10⁻³ to 3 rad, by:
  * a memoir's small-amplitude formula, π/k + ΔT(α, k), from the generated kernel its Memoir names as
    ``swing_correction`` (Python and C);
  * the exact swing time π/(k·AGM(1, cos α/2)) (generated C and Python kernels);
  * the same Python kernel on a numpy array of 10⁶ random amplitudes, beside scipy.special.ellipk
    on the same array (per element, min and median of 5 calls);
  * mpmath's ellipk, 2K(sin² α/2)/k at 15 digits;
  * mpmath odefun integration of the ODE at 15, 20 and 30 digits.
The reference is ellipk at 50 digits.  Then every generated kernel of every memoir
(:mod:`pendsym.bench_kernels`: naive printed form, C, Python, numpy, scipy, mpmath).  Timings are wall-clock per evaluation
on this machine (ctypes call overhead included for C); they are not
reproducible to the byte, so make derive never writes them.
"""
from __future__ import annotations

import argparse
import ctypes
import importlib.util
import json
import math
import os
import random
import statistics
import subprocess
import tempfile
import time
from pathlib import Path

import mpmath as mp
import numpy
import scipy.special

from . import bench_kernels, registry
from .io import write_atomic

ALPHAS = [10 ** (-3 + 3.4771 * i / 23) for i in range(24)]   # 1e-3 … 3
K = 1.0


def reference(alpha: float) -> mp.mpf:
    with mp.workdps(50):
        return 2 * mp.ellipk(mp.sin(mp.mpf(alpha) / 2) ** 2) / K


def _timed(fn, alphas, repeat: int) -> tuple[float, list[float]]:
    vals = [fn(a) for a in alphas]
    t0 = time.perf_counter()
    for _ in range(repeat):
        for a in alphas:
            fn(a)
    return (time.perf_counter() - t0) / (repeat * len(alphas)), vals


def _load_py(path: Path):
    spec = importlib.util.spec_from_file_location(path.stem, path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


POSIX = "#define _POSIX_C_SOURCE 199309L\n"   # clock_gettime under -std=c99
C_LOOP = r"""
#include <time.h>
double SWING_CORRECTION(double, double);
double swing_time_agm(double, double);
double loop_ns(int which, const double *alphas, int n, long reps, double k)
{
    volatile double sink = 0.0;
    struct timespec a, b;
    clock_gettime(CLOCK_MONOTONIC, &a);
    for (long r = 0; r < reps; ++r)
        for (int i = 0; i < n; ++i)
            sink += which ? swing_time_agm(alphas[i], k) : 3.14159265358979323846 / k + SWING_CORRECTION(alphas[i], k);
    clock_gettime(CLOCK_MONOTONIC, &b);
    (void)sink;
    return ((b.tv_sec - a.tv_sec) * 1e9 + (b.tv_nsec - a.tv_nsec)) / ((double)reps * n);
}
"""


TIME_POINTS = 4096     # random, non-repeating amplitudes of a timing run (seeded)
ARRAY_POINTS = 10**6   # amplitudes of a numpy timing run
TIME_REPEATS = 5


def timing_alphas() -> list[float]:
    rng = random.Random("swing-time")
    return [rng.uniform(1e-3, 3.0) for _ in range(TIME_POINTS)]


def c_loop_time(lib, which: int) -> tuple[float, float]:
    """(min, median) seconds per evaluation of a C kernel over TIME_REPEATS runs, timed inside C
    (no ctypes overhead) on TIME_POINTS random amplitudes (a repeating handful lets the branch
    predictor learn a data-dependent loop)."""
    alphas = timing_alphas()
    arr = (ctypes.c_double * len(alphas))(*alphas)
    f = lib.loop_ns
    f.restype = ctypes.c_double
    f.argtypes = [ctypes.c_int, ctypes.POINTER(ctypes.c_double), ctypes.c_int, ctypes.c_long, ctypes.c_double]
    f(which, arr, len(alphas), 20, K)
    runs = [f(which, arr, len(alphas), 200, K) * 1e-9 for _ in range(TIME_REPEATS)]
    return min(runs), statistics.median(runs)


def array_time(fn) -> tuple[float, float]:
    """(min, median) seconds per element of fn on ARRAY_POINTS random amplitudes (seeded), over
    TIME_REPEATS calls."""
    arr = numpy.random.default_rng(20261124).uniform(1e-3, 3.0, ARRAY_POINTS)
    fn(arr)
    runs = []
    for _ in range(TIME_REPEATS):
        t0 = time.perf_counter()
        fn(arr)
        runs.append((time.perf_counter() - t0) / ARRAY_POINTS)
    return min(runs), statistics.median(runs)


def load() -> str:
    """The load averages when the figures were taken (the machine may be shared)."""
    return " ".join(f"{v:.2f}" for v in os.getloadavg())


def compile_apart(kernels: str, loop: str, workdir: Path) -> ctypes.CDLL:
    """The kernels and the timing loop, each its own translation unit (as a user links them: no
    inlining across), into one shared library."""
    (workdir / "kernels.c").write_text(kernels)
    (workdir / "loop.c").write_text(loop)
    lib = workdir / "bench.so"
    subprocess.run(["cc", "-std=c99", "-O2", "-fPIC", "-shared", "-o", str(lib), str(workdir / "kernels.c"),
                    str(workdir / "loop.c"), "-lm"], check=True, capture_output=True)
    return ctypes.CDLL(str(lib))


def swing_memoir() -> tuple[str, str]:
    """(memoir key, kernel name) of the first memoir that names a swing-time correction kernel."""
    for key, memoir in registry.memoirs().items():
        if memoir.swing_correction:
            return key, memoir.swing_correction
    raise SystemExit("pendsym-bench: no memoir names a swing_correction kernel")


def methods(generated: Path, workdir: Path):
    memoir, name = swing_memoir()
    ch = _load_py(generated / "python" / f"{memoir}.py")
    per = _load_py(generated / "python" / "pendulum.py")
    lib = compile_apart((generated / "c" / f"{memoir}.c").read_text().replace(f'#include "{memoir}.h"', "")
                        + (generated / "c" / "pendulum.c").read_text().replace('#include "pendulum.h"', ""),
                        POSIX + C_LOOP.replace("SWING_CORRECTION", name), workdir)
    c_dT = getattr(lib, name)
    c_T = lib.swing_time_agm
    for f in (c_dT, c_T):
        f.restype = ctypes.c_double
        f.argtypes = [ctypes.c_double, ctypes.c_double]

    def ode(dps):
        def run(a):
            with mp.workdps(dps):
                f = mp.odefun(lambda t, y: [y[1], -K**2 * mp.sin(y[0])], 0, [-mp.mpf(a), mp.mpf(0)])
                return float(mp.findroot(lambda t: f(t)[1], mp.pi / K * (1 + a * a / 16)))
        return run

    def ellipk15(a):
        with mp.workdps(15):
            return float(2 * mp.ellipk(mp.sin(mp.mpf(a) / 2) ** 2) / K)
    def agm_numpy(arr):
        return per.swing_time_agm(arr, K)

    def scipy_ellipk(arr):
        return 2 * scipy.special.ellipk(numpy.sin(arr / 2) ** 2) / K
    return [
        ("exact, AGM, numpy kernel (array of 1e6)", agm_numpy, ("array",), ALPHAS),
        ("scipy.special.ellipk (array of 1e6)", scipy_ellipk, ("array",), ALPHAS),
        ("memoir T(1+α²/16), C kernel", lambda a: math.pi / K + c_dT(a, K), ("C", lib, 0), ALPHAS),
        ("memoir T(1+α²/16), Python kernel", lambda a: math.pi / K + getattr(ch, name)(a, K), 20000, ALPHAS),
        ("exact, AGM, C kernel", lambda a: c_T(a, K), ("C", lib, 1), ALPHAS),
        ("exact, AGM, Python kernel", lambda a: per.swing_time_agm(a, K), 5000, ALPHAS),
        ("mpmath ellipk (15 digits)", ellipk15, 200, ALPHAS),
        ("mpmath odefun, 15 digits", ode(15), 1, ALPHAS[::6]),
        ("mpmath odefun, 20 digits", ode(20), 1, ALPHAS[::6]),
        ("mpmath odefun, 30 digits", ode(30), 1, ALPHAS[::6]),
    ]


def run(generated: Path) -> list[dict]:
    rows = []
    with tempfile.TemporaryDirectory() as d:
        for name, fn, repeat, alphas in methods(generated, Path(d)):
            median = None
            if repeat == ("array",):             # numpy: one call on ARRAY_POINTS random amplitudes
                (per_eval, median), vals = array_time(fn), [float(v) for v in fn(numpy.array(alphas))]
            elif isinstance(repeat, tuple):       # a C kernel: values through ctypes, time inside C
                (per_eval, median), vals = c_loop_time(repeat[1], repeat[2]), [fn(a) for a in alphas]
            else:
                per_eval, vals = _timed(fn, alphas, repeat)
            errs = [float(abs(mp.mpf(v) - reference(a)) / reference(a)) for a, v in zip(alphas, vals)]
            worst = max(range(len(errs)), key=errs.__getitem__)
            rows.append({"method": name, "seconds_per_eval": per_eval, "median_seconds_per_eval": median, "load": load(),
                         "max_rel_error": errs[worst],
                         "worst_alpha": alphas[worst], "alphas": len(alphas),
                         "errors": [[a, e] for a, e in zip(alphas, errs)]})
    return rows


def _tex(name: str) -> str:
    return name.replace("α", r"$\alpha$").replace("²", "$^2$")


def tex_table(rows: list[dict]) -> str:
    lines = [r"\begin{center}", r"\begin{tabular}{lrrr}", r"\toprule",
             r"method & time per evaluation & largest relative error & at $\alpha$ \\", r"\midrule"]
    for r in rows:
        name = _tex(r["method"])
        err = max(r["max_rel_error"], 1e-17)
        lines.append(f"{name} & {r['seconds_per_eval'] * 1e6:.3g} $\\mu$s & {err:.2g} & {r['worst_alpha']:.3g} \\\\")
    lines += [r"\bottomrule", r"\end{tabular}", r"\end{center}", "",
              r"\begin{center}\begin{tikzpicture}\begin{loglogaxis}[width=11cm,height=6cm,"
              r"xlabel={time per evaluation (s)},ylabel={largest relative error over $10^{-3}\le\alpha\le3$},"
              r"legend style={font=\tiny,at={(1.02,0.5)},anchor=west}]"]
    for i, r in enumerate(rows):
        err = max(r["max_rel_error"], 1e-17)
        lines.append(f"\\addplot+[only marks] coordinates {{({r['seconds_per_eval']:.4g},{err:.3g})}};")
        lines.append(f"\\addlegendentry{{{_tex(r['method'])}}}")
    lines += [r"\end{loglogaxis}\end{tikzpicture}\end{center}", "",
              r"\begin{center}\begin{tikzpicture}\begin{loglogaxis}[width=11cm,height=6cm,xlabel={$\alpha$ (rad)},"
              r"ylabel={relative error},legend style={font=\tiny,at={(1.02,0.5)},anchor=west}]"]
    for r in rows:
        if r["alphas"] == len(ALPHAS) and "Python" not in r["method"]:
            pts = " ".join(f"({a:.4g},{max(e, 1e-17):.3g})" for a, e in r["errors"])
            lines.append(f"\\addplot coordinates {{{pts}}};")
            lines.append(f"\\addlegendentry{{{_tex(r['method'])}}}")
    lines += [r"\end{loglogaxis}\end{tikzpicture}\end{center}",
              "Errors below $10^{-17}$ are shown as $10^{-17}$. The reference is mpmath ellipk at 50 digits; "
              "the swing time is one swing, $T=\\pi/k$ for small $\\alpha$, here with $k=1$. C kernels are "
              "timed in a C loop of their own translation unit on 4096 random amplitudes (the least of 5 runs); Python and mpmath per call; the ODE integrations on 4 of the 24 amplitudes.", ""]
    return "\n".join(lines)


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="pendsym-bench")
    p.add_argument("--out", default="generated/bench")
    p.add_argument("--generated", default="generated")
    args = p.parse_args(argv)
    rows = run(Path(args.generated))
    out = Path(args.out)
    memoir, _ = swing_memoir()
    write_atomic(out / f"{memoir}-period.json", json.dumps(rows, indent=1) + "\n")
    write_atomic(out / f"{memoir}-period.tex", tex_table(rows))
    print(f"load averages (1, 5, 15 min) when measured: {rows[0]['load']}")
    for r in rows:
        med = f" (median {r['median_seconds_per_eval'] * 1e9:.1f} ns)" if r.get("median_seconds_per_eval") else ""
        print(f"{r['method']:<44} {r['seconds_per_eval'] * 1e9:12.1f} ns{med}  max rel err {r['max_rel_error']:.2e}")
    return bench_kernels.main(["--out", args.out, "--generated", args.generated])   # every kernel of every memoir


if __name__ == "__main__":
    raise SystemExit(main())
