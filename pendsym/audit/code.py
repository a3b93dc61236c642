"""The emitted code of ``make audit``, loaded as a user would call it, and timed: each memoir's C file
compiled in its own translation unit with a timing unit apart (C ns/call), its Python module imported,
the Python kernel's array path on numpy arrays (ns/element).  Used by :mod:`.run`."""
from __future__ import annotations

import ctypes
import importlib.util
import statistics
import subprocess
from pathlib import Path
from typing import Callable, Sequence

from ..emit.kernels.compile import CC
from . import arrays as ar
from . import points as pt

TIME_POINTS = 4096       # random points of a timing run
TIME_REPEATS = 5
TIMING_PREAMBLE = "#define _POSIX_C_SOURCE 199309L\n#include <time.h>"      # clock_gettime in C99


def _load_py(path: Path):
    spec = importlib.util.spec_from_file_location(f"audited_{path.stem}", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def c_loop(name: str, n: int) -> str:
    """The C timing loop of the function ``name`` of n doubles over an array of points, as
    ``double time_<name>(const double *x, long n, long reps)``: ns per call (the function itself is
    declared before it, by the memoir's header or a prototype)."""
    call = ", ".join(f"x[{n}*i+{j}]" for j in range(n))
    return f"""double time_{name}(const double *x, long n, long reps)
{{
    volatile double sink = 0.0;
    double acc = 0.0;
    struct timespec a, b;
    clock_gettime(CLOCK_MONOTONIC, &a);
    for (long r = 0; r < reps; ++r)
        for (long i = 0; i < n; ++i)
            acc += {name}({call});
    clock_gettime(CLOCK_MONOTONIC, &b);
    sink = acc;
    (void)sink;
    return ((b.tv_sec - a.tv_sec) * 1e9 + (b.tv_nsec - a.tv_nsec)) / ((double)reps * n);
}}
"""


def timing_source(memoir: str, kernels: Sequence[tuple[str, int]]) -> str:
    """A translation unit apart from the kernels' that times each of them on an array of points."""
    return "\n".join([TIMING_PREAMBLE, f'#include "{memoir}.h"', "", *(c_loop(name, n) for name, n in kernels)])


def compile_memoir(generated: Path, memoir: str, kernels: Sequence[tuple[str, int]], work: Path) -> ctypes.CDLL:
    """generated/c/<memoir>.c and a timing unit, each its own translation unit, into one library."""
    timing = work / f"{memoir}_timing.c"
    timing.write_text(timing_source(memoir, kernels))
    lib = work / f"lib{memoir}.so"
    done = subprocess.run([*CC, "-I", str(generated / "c"), "-o", str(lib), str(generated / "c" / f"{memoir}.c"),
                           str(timing), "-lm"], capture_output=True, text=True)
    if done.returncode:
        raise RuntimeError(f"cc failed on {memoir}: {done.stderr.strip()[:2000]}")
    return ctypes.CDLL(str(lib), use_errno=True)


def c_function(lib: ctypes.CDLL, name: str, n: int) -> Callable:
    fn = getattr(lib, name)
    fn.restype = ctypes.c_double
    fn.argtypes = [ctypes.c_double] * n
    return fn


def c_time(lib: ctypes.CDLL, name: str, pts: Sequence[tuple], repeats: int = TIME_REPEATS) -> tuple[float, float]:
    """(min, median) ns per call of the C function ``name`` in its timing loop (:func:`c_loop`) over the
    points, in ``repeats`` runs of about 2 ms each after a warm-up."""
    flat = (ctypes.c_double * (len(pts) * len(pts[0])))(*[v for p in pts for v in p])
    fn = getattr(lib, f"time_{name}")
    fn.restype = ctypes.c_double
    fn.argtypes = [ctypes.c_void_p, ctypes.c_long, ctypes.c_long]
    fn(flat, len(pts), 2)                                   # warm up, and the reps for ~2 ms
    reps = max(1, int(2e6 / max(1.0, fn(flat, len(pts), 1) * len(pts))))
    runs = [fn(flat, len(pts), reps) for _ in range(repeats)]
    return round(min(runs), 1), round(statistics.median(runs), 1)


def c_ns(lib: ctypes.CDLL, job) -> tuple[float, float]:
    """(min, median) ns per call of the C kernel over TIME_REPEATS runs on random points of its domain."""
    return c_time(lib, job.name, pt.random_points(job.args, job.name + ":time", TIME_POINTS))


NUMPY_BUDGET = 0.03      # seconds a numpy timing call may take (10**6 elements, or fewer for a heavy kernel)


def numpy_ns(job) -> tuple[float, float, int]:
    """(min, median, elements) ns per element of the Python kernel on numpy arrays of up to
    ar.ARRAY_POINTS random points of its declared domain (log-uniform for a geometric argument),
    over ar.REPEATS calls."""
    return ar.ns_per_element(job.py, [(a.name, a.lo, a.hi, a.log) for a in job.args], job.name,
                             budget=NUMPY_BUDGET)
