"""``make derive``: every memoir through build → compare → verify → emit, into generated/."""
from __future__ import annotations

import importlib
import shutil
from pathlib import Path
from typing import Callable

import sympy as sp

from . import cache, parallel, pipeline, registry
from .emit import files, kernels as kn, latex
from .io import write_atomic


def memoir_meta(memoir: str):
    mod = importlib.import_module(registry.MEMOIRS[memoir])
    return getattr(mod, "TITLE", memoir), getattr(mod, "SECTIONS", ())


def emit_kernels(memoir: str, records, log) -> tuple[list[kn.Kernel], list[kn.Kernel]]:
    """(emitted, withheld): a kernel whose measured error exceeds kn.BOUND ulp × max(1, κ) in
    Python or C is not emitted; it is listed in the report with its measured figures."""
    if not getattr(importlib.import_module(registry.MEMOIRS[memoir]), "KERNELS_READY", True):
        log(f"{memoir}: kernels not emitted (the memoir says its stable forms are not ready)")
        return [], []
    results = {rec.result.id: rec.result for rec in records}
    wanted = [i for i, r in results.items() if r.spec.kernel is not None and kn.closed_form(r.derived)]
    ks = [k for k in parallel.per_result(results, wanted, cached_kernel) if k is not None]
    if ks and shutil.which("cc"):
        ks = kn.with_c_accuracy(ks, results, lambda kk: files.c_standalone(memoir, kk))
    held = [k for k in ks if not within_bound(k)]
    ks = [k for k in ks if within_bound(k)]
    log(f"{memoir}: {len(ks)} kernels" + (f", {len(held)} withheld over the bound: "
                                           + ", ".join(k.name for k in held) if held else ""))
    return ks, held


def within_bound(k: kn.Kernel) -> bool:
    """The kernel holds kn.BOUND ulp × max(1, κ) on its measured sample (Python and, if built, C)."""
    accs = [a for a in (k.py_accuracy, k.c_accuracy) if a is not None]
    return bool(accs) and all(a.max_scaled <= kn.BOUND for a in accs)


def cached_kernel(result) -> kn.Kernel | None:
    """kn.kernel_of, cached under the content hash of the Result and the code."""
    key = cache.key("kernel", result.id, sp.srepr(result.derived), repr(result.spec.kernel),
                    packages=("pendsym", registry.MEMOIRS[result.spec.memoir]))
    return cache.memo(key, lambda: kn.kernel_of(result))


def derive_all(out: Path, level: str = "full", log: Callable[[str], None] = print) -> list[Path]:
    out = Path(out)
    written: list[Path] = []
    all_records, all_kernels = [], {}
    built = {}
    for memoir in registry.MEMOIRS:
        built[memoir] = registry.build(memoirs=[memoir])
        log(f"{memoir}: {len(built[memoir])} results built")
    # one pass over the cores for every memoir's checks, the memoirs with the longest checks
    # first, so that short checks fill the tail; the records do not depend on the order
    order = sorted(registry.MEMOIRS, key=lambda m: SCHEDULE.index(m) if m in SCHEDULE else len(SCHEDULE))
    log(f"verifying {sum(map(len, built.values()))} results at level {level}")
    assessed = pipeline.assess([r for m in order for r in built[m].values()], level)
    by_id = {rec.result.id: rec for rec in assessed}
    for memoir in registry.MEMOIRS:
        records = [by_id[i] for i in built[memoir]]
        ks, held = emit_kernels(memoir, records, log)
        for k in ks:
            all_kernels.setdefault(k.result_id, []).append(k.name)
        title, sections = memoir_meta(memoir)
        outputs = {
            out / "python" / f"{memoir}.py": files.python_module(memoir, ks),
            out / "c" / f"{memoir}.c": files.c_source(memoir, ks),
            out / "c" / f"{memoir}.h": files.c_header(memoir, ks),
            out / "tex" / f"{memoir}.tex": latex.report(
                memoir, title, records, ks, bench_input(out, memoir), sections, held),
        }
        for path, text in outputs.items():
            write_atomic(path, text)
            written.append(path)
        all_records.extend(records)
    for path, text in pendulum_kernels(out).items():
        write_atomic(path, text)
        written.append(path)
    path = out / "results.json"
    write_atomic(path, pipeline.results_json(all_records, all_kernels))
    written.append(path)
    return written


# Memoirs whose checks take longest go first to the workers (a scheduling hint only).
SCHEDULE = ("cellerier", "haag1935", "charbonnier1908")


def bench_input(out: Path, memoir: str) -> str | None:
    """The benchmark table a report includes (relative to generated/tex), when make bench wrote one."""
    name = f"{memoir}-period.tex"
    return f"../bench/{name}" if (out / "bench" / name).exists() else None


def pendulum_kernels(out: Path) -> dict[Path, str]:
    """The memoir-independent exact swing time by the AGM (used by make bench and the tests)."""
    ctx = {"max_steps": 40, "tol": "4e-16", "pi": "3.14159265358979323846"}
    return {
        out / "c" / "pendulum.c": files.render("pendulum.c.j2", **ctx),
        out / "c" / "pendulum.h": files.render("pendulum.h.j2", **ctx),
        out / "python" / "pendulum.py": files.render("pendulum.py.j2", **ctx),
    }
