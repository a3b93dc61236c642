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

# the costliest test files (seconds of one run, measured in session 10 on a warm cache), run first; every file not
# listed follows in its usual (alphabetical) order.  A stale entry only costs balance, never a check.
COSTLIEST_FIRST = ()


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
    """The costliest files first (a stable sort: within a file, and among the other files, the order is kept)."""
    rank = {name: i for i, name in enumerate(COSTLIEST_FIRST)}
    items.sort(key=lambda item: rank.get(item.nodeid.split("::", 1)[0], len(rank)))
