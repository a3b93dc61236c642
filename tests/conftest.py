"""Shared fixtures: the repository root, the generated directory, and the generated kernels of a memoir.

``emitted_kernels(memoir)`` gives the kernels exactly as emitted (generated/python/<memoir>.py imported,
generated/c/<memoir>.c compiled by :func:`pendsym.emit.kernels.compile_c`, ``cc -std=c99 -O2``), built once per
test session instead of once per test module: every kernel test module used to import the same 280 kB module
and compile the same 240 kB C file in a fixture of its own.  Under xdist the compiled library is shared by the
workers of one run (a lock file, the library named by the SHA-256 of the C text it was compiled from), so each
memoir's C is compiled once per run.

The test files are ordered by cost (``pytest_collection_modifyitems``): ``--dist loadfile`` hands whole files to
the workers in collection order, and with the costliest files first no worker is left alone with a long file at
the end of the run (longest job first).  The order changes which worker runs a file, never what it checks.
"""
from __future__ import annotations

import ctypes
import fcntl
import hashlib
import importlib.util
import os
import shutil
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

import pytest

from pendsym.emit import kernels as kn

ROOT = Path(__file__).resolve().parents[1]

# the costliest test files, run first (--dist loadfile hands whole files to the workers in this order): seconds of
# the full tier and of the quick tier ("not slow") per file, from session 10's profile of make test on a warm cache
# (pytest's per-test times on a loaded machine, scaled by that run's CPU/wall ratio, 0.089).  Every file not listed
# follows in its usual (alphabetical) order.  A stale or missing entry costs balance only, never a check.
COST = {
    "tests/test_scene_fuzz.py": (97, 19),
    "tests/test_nonlinear_blade.py": (78, 3),
    "tests/test_scene_gravity_meter_rhombus.py": (56, 0),
    "tests/test_solve_second_order.py": (55, 5),
    "tests/test_scene.py": (54, 54),
    "tests/test_perturbation.py": (38, 6),
    "tests/test_solve_nonpolynomial.py": (31, 3),
    "tests/test_solve_answer.py": (31, 1),
    "tests/test_scene_instruments.py": (24, 24),
    "tests/test_cli.py": (24, 15),
    "tests/test_haag1935_ch2_kernels.py": (21, 2),
    "tests/test_solve_drag.py": (21, 1),
    "tests/test_solve_lindstedt.py": (19, 1),
    "tests/test_solve_secular.py": (19, 0),
    "tests/test_haag1935_ch2_perturbations.py": (17, 17),
    "tests/test_audit.py": (16, 5),
    "tests/test_solve_variation.py": (16, 1),
    "tests/test_suspension.py": (15, 15),
    "tests/test_blade.py": (14, 5),
    "tests/test_haag1935_ch2_dissymmetry.py": (12, 12),
    "tests/test_scene_gravity_meter.py": (12, 1),
    "tests/test_haag1935_ch2_clamping.py": (9, 9),
    "tests/test_haag1935_ch7_dissymmetry.py": (9, 2),
    "tests/test_haag1935_ch7_clamping.py": (8, 6),
    "tests/test_thread_pendulum.py": (8, 6),
    "tests/test_codec.py": (8, 5),
    "tests/test_haag1935_ch9_kernels.py": (8, 1),
    "tests/test_finite_amplitude.py": (8, 0),
    "tests/test_haag1935_ch8_inverted.py": (7, 7),
    "tests/test_haag1935_figures.py": (6, 0),      # session 11: reads the derive's plots
    "tests/test_bench_blade.py": (7, 0),
    "tests/test_haag1935_ch2_general.py": (6, 6),
    "tests/test_haag1935_ch6_perturbations.py": (5, 5),
    "tests/test_kernels.py": (4, 0),               # session 11: reads the derive's accuracies
    "tests/test_haag1935_ch9_series.py": (5, 5),
    "tests/test_haag1935_ch9_rectangle.py": (4, 4),
    "tests/test_kernels_stable.py": (4, 4),
    "tests/test_plugin_memoir.py": (4, 4),
    "tests/test_solve_parse.py": (3, 3),
    "tests/test_scene_temperature.py": (3, 3),
    "tests/test_haag1935_ch4_kernels.py": (3, 3),
    "tests/test_haag1935_ch7_kernels.py": (3, 3),
    "tests/test_haag1935_ch4_thread.py": (3, 2),
    "tests/test_figure.py": (2, 2),
    "tests/test_haag1935_ch3_derivation.py": (2, 2),
    "tests/test_kernels_sharing.py": (2, 2),
}


@pytest.fixture(scope="session")
def root() -> Path:
    return ROOT


@pytest.fixture(scope="session")
def generated() -> Path:
    return ROOT / "generated"


@dataclass(frozen=True)
class Emitted:
    """One memoir's generated kernels: the imported Python module and the loaded C library (None without cc)."""
    python: object
    c: ctypes.CDLL | None

    def functions(self, name: str, nargs: int) -> dict[str, Callable[..., float]]:
        """{"Python": f, "C": f} of the kernel ``name`` of ``nargs`` double arguments ("C" only with a compiler).
        The C function is a fresh ctypes pointer (``lib[name]``), so no module's declaration leaks into another's."""
        out = {"Python": getattr(self.python, name)}
        if self.c is not None:
            fn = self.c[name]
            fn.restype, fn.argtypes = ctypes.c_double, [ctypes.c_double] * nargs
            out["C"] = fn
        return out


def c_source(generated: Path, memoir: str) -> str:
    """The memoir's generated C with the pendulum's AGM swing time, as one file (the headers inlined away)."""
    text = (generated / "c" / f"{memoir}.c").read_text().replace(f'#include "{memoir}.h"', "")
    return text + (generated / "c" / "pendulum.c").read_text().replace('#include "pendulum.h"', "")


def _shared_dir(tmp_path_factory) -> Path:
    """A directory all the xdist workers of this run share (the parent of their base temp), else this run's."""
    base = tmp_path_factory.getbasetemp()
    shared = (base.parent if os.environ.get("PYTEST_XDIST_WORKER") else base) / "compiled-kernels"
    shared.mkdir(exist_ok=True)
    return shared


def compiled(text: str, shared: Path) -> ctypes.CDLL:
    """``text`` compiled by kn.compile_c once per run: the first worker to ask compiles it under a lock, the
    others load the same library (named by the text's SHA-256, so a library is only ever loaded for its text)."""
    digest = hashlib.sha256(text.encode()).hexdigest()[:20]
    lib = shared / f"{digest}.so"
    with open(shared / f"{digest}.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if not lib.exists():
            work = shared / f"{digest}.{os.getpid()}"
            work.mkdir()
            kn.compile_c(text, work)
            os.replace(work / "k.so", lib)
    return ctypes.CDLL(str(lib))


@pytest.fixture(scope="session")
def emitted_kernels(generated, tmp_path_factory) -> Callable[[str], Emitted]:
    """memoir → :class:`Emitted`, each memoir imported and compiled once per session."""
    made: dict[str, Emitted] = {}

    def get(memoir: str) -> Emitted:
        if memoir not in made:
            spec = importlib.util.spec_from_file_location(f"emitted_{memoir}", generated / "python" / f"{memoir}.py")
            module = importlib.util.module_from_spec(spec)
            spec.loader.exec_module(module)
            lib = compiled(c_source(generated, memoir), _shared_dir(tmp_path_factory)) if shutil.which("cc") else None
            made[memoir] = Emitted(module, lib)
        return made[memoir]
    return get


def pytest_collection_modifyitems(session, config, items):
    """The costliest files of the tier first (a stable sort: within a file, and among the files of equal cost, the
    order is kept; a file's tests stay together)."""
    quick = "not slow" in (config.option.markexpr or "")
    items.sort(key=lambda item: -COST.get(item.nodeid.split("::", 1)[0], (0, 0))[quick])
