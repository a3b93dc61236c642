"""``make derive``: every memoir through build → compare → verify → emit, into generated/."""
from __future__ import annotations

import importlib
import multiprocessing
import shutil
import tempfile
import time
from pathlib import Path
from typing import Callable

import sympy as sp

from . import cache, parallel, pipeline, registry
from .emit import files, kernels as kn, latex
from .io import write_atomic
from .result import Result


def memoir_meta(memoir: str):
    m = registry.memoir(memoir)
    return m.title, tuple((h.ids, h.title) for h in m.report_headings())


def kernel_ids(memoir: str, results) -> list[str]:
    """The Results of a memoir that ask for a kernel and have a closed form (none if the memoir
    says its kernels are not ready)."""
    if not registry.memoir(memoir).kernels:
        return []
    return [i for i, r in results.items() if r.spec.kernel is not None and kn.closed_form(r.derived)]


def c_measured(kernels: dict[str, list], built, workdir: Path) -> dict[str, list]:
    """Each memoir's kernels with the accuracy of their compiled C, measured over the cores
    (one shared library per memoir, compiled once; the forked workers inherit it)."""
    if not shutil.which("cc"):
        return kernels
    jobs = {}
    for memoir, ks in kernels.items():
        if ks:
            d = workdir / memoir
            d.mkdir(parents=True, exist_ok=True)
            lib = kn.compile_c(files.c_standalone(memoir, ks), d)
            jobs.update({f"{memoir}:{k.name}": (lib, k, built[memoir][k.result_id]) for k in ks})
    acc = dict(zip(jobs, parallel.per_result(jobs, list(jobs), _c_job)))
    return {m: [kn.Kernel(**{**k.__dict__, "c_accuracy": acc[f"{m}:{k.name}"]}) for k in ks]
            for m, ks in kernels.items()}


def _c_job(job):
    lib, k, result = job
    return kn.c_accuracy(lib, k, result)


def split_kernels(memoir: str, ks: list, log) -> tuple[list[kn.Kernel], list[kn.Kernel]]:
    """(emitted, withheld): a kernel whose measured error exceeds kn.BOUND ulp × max(1, κ) in
    Python or C is not emitted; the report lists it with its figures."""
    held = [k for k in ks if not within_bound(k)]
    ks = [k for k in ks if within_bound(k)]
    log(f"{memoir}: {len(ks)} kernels" + (f", {len(held)} withheld over the bound: "
                                           + ", ".join(k.name for k in held) if held else ""))
    return ks, held


def within_bound(k: kn.Kernel) -> bool:
    """The kernel holds kn.BOUND ulp × max(1, κ) on its measured sample (Python and, if built, C)."""
    accs = [a for a in (k.py_accuracy, k.c_accuracy) if a is not None]
    return bool(accs) and all(a.max_scaled <= kn.BOUND for a in accs)


def _forms(memoirs) -> dict:
    """{memoir: {id: (derived, printed)}}: the built forms, plain SymPy (picklable)."""
    return {m: {i: (r.derived, r.printed) for i, r in registry.build(memoirs=[m]).items()} for m in memoirs}


def _assemble(memoir: str, forms: dict) -> dict:
    """Results of a memoir from forms built elsewhere, wired to their dependencies."""
    specs = registry.all_specs([memoir])
    out: dict = {}
    for rid in registry.closure(list(forms), specs):
        spec = specs[rid]
        derived, printed = forms[rid]
        out[rid] = Result(spec=spec, derived=derived, printed=printed, deps={d: out[d] for d in spec.deps})
    return out


def build_all() -> dict[str, dict]:
    """Every memoir built; with two cores, BUILD_IN_PARENT is built here (its caches stay warm for
    the forked checks) while a forked process builds the others and sends back their forms."""
    memoirs = list(registry.memoirs())
    BUILD_IN_PARENT = max(memoirs, key=lambda m: len(registry.memoir(m).specs))
    others = [m for m in memoirs if m != BUILD_IN_PARENT]
    if (parallel.workers() < 2 or BUILD_IN_PARENT not in memoirs
            or "fork" not in multiprocessing.get_all_start_methods()):
        return {m: registry.build(memoirs=[m]) for m in memoirs}
    with multiprocessing.get_context("fork").Pool(1) as pool:
        pending = pool.apply_async(_forms, (others,))
        here = registry.build(memoirs=[BUILD_IN_PARENT])
        forms = pending.get()
    built = {m: _assemble(m, forms[m]) for m in others}
    built[BUILD_IN_PARENT] = here
    return {m: built[m] for m in memoirs}


def _package(memoir: str) -> str:
    """The package of a memoir's derivations (whose source its cache keys cover)."""
    return registry.memoir(memoir).sections[0].module.rsplit(".", 1)[0]


def _job(jobs):
    """A unit of work for a core: a list of ("check", level, Result) or ("kernel", None, Result),
    run in turn (checks with an affinity share their integrations)."""
    out = []
    for kind, level, result in jobs:
        if kind == "kernel":
            out.append(cached_kernel(result))
        else:
            out.append(pipeline.assessed(result, level))
    return out


def affinity(memoir: str) -> tuple[tuple[str, ...], ...]:
    """Groups of Results whose checks are best run in one worker (a scheduling hint only)."""
    return registry.memoir(memoir).affinity


def check_jobs(memoir: str, results, level: str) -> dict[str, list]:
    """One job per Result, except the affinity groups, each one job (keyed by its first id)."""
    groups = {i: g for g in affinity(memoir) for i in g if all(x in results for x in g)}
    jobs = {}
    for i, r in results.items():
        g = groups.get(i)
        if g is None:
            jobs[f"check:{i}"] = [("check", level, r)]
        elif i == g[0]:
            jobs[f"check:{i}"] = [("check", level, results[x]) for x in g]
    return jobs


def cached_kernel(result) -> kn.Kernel | None:
    """kn.kernel_of, cached under the content hash of the Result and the code."""
    key = cache.key("kernel", result.id, sp.srepr(result.derived), repr(result.spec.kernel),
                    packages=("pendsym", _package(result.spec.memoir)))
    return cache.memo(key, lambda: kn.kernel_of(result))


def derive_all(out: Path, level: str = "full", log: Callable[[str], None] = print) -> list[Path]:
    out = Path(out)
    written: list[Path] = []
    all_records, all_kernels = [], {}
    start = time.monotonic()
    built = build_all()
    for memoir in registry.memoirs():
        log(f"{memoir}: {len(built[memoir])} results built")
    log(f"built in {time.monotonic() - start:.0f} s")
    # one pass over the cores for every check and every kernel form, the longest first so that
    # short ones fill the tail; each result is deterministic, so the order changes nothing
    order = sorted(registry.memoirs(), key=lambda m: -registry.memoir(m).cost)
    wanted = {m: kernel_ids(m, built[m]) for m in registry.memoirs()}
    jobs = {}
    for m in order[:-1]:
        jobs.update(check_jobs(m, built[m], level))
    jobs.update({f"kernel:{i}": [("kernel", None, built[m][i])] for m in order for i in wanted[m]})
    jobs.update(check_jobs(order[-1], built[order[-1]], level))
    log(f"verifying {sum(map(len, built.values()))} results at level {level}, "
        f"forming {sum(map(len, wanted.values()))} kernels")
    done = {}
    for key, outs in zip(jobs, parallel.per_result(jobs, list(jobs), _job)):
        for (kind, _, r), o in zip(jobs[key], outs):
            done[f"{kind}:{r.id}"] = o
    formed = {m: [k for k in (done[f"kernel:{i}"] for i in wanted[m]) if k is not None] for m in registry.memoirs()}
    log(f"verified and formed at {time.monotonic() - start:.0f} s")
    with tempfile.TemporaryDirectory() as tmp:
        formed = c_measured(formed, built, Path(tmp))
    log(f"C kernels measured at {time.monotonic() - start:.0f} s")
    for memoir in registry.memoirs():
        records = [pipeline.Record(r, *done[f"check:{i}"][0], done[f"check:{i}"][1]) for i, r in built[memoir].items()]
        ks, held = split_kernels(memoir, formed[memoir], log)
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
