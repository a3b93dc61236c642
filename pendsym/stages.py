"""The stages of ``make derive``, each a plain function; :mod:`pendsym.derive` is their spine.

plan → build → compare, check and form kernels (one pool) → measure C → emit → write.

Every stage that computes goes through the cache (:mod:`pendsym.cache`) under the
content keys of :mod:`pendsym.keys`, so a stage redoes only what changed; the
log says what was redone.
"""
from __future__ import annotations

import dataclasses
import functools
import os
import shutil
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Callable, Mapping

import sympy as sp

from . import build_stage, cache, figure, keys, pipeline, registry, schedule
from .emit import files, kernels as kn, latex
from .emit.kernels.compile import emitted_py
from .io import content_hash, write_atomic
from .result import Result, Spec

Log = Callable[[str], None]


class OutputError(ValueError):
    """The output directory cannot be written (reported in one line, before any work)."""


@dataclass(frozen=True)
class Plan:
    """What a derive covers: the memoirs, their Specs in dependency order, and each Result's key."""

    level: str
    memoirs: tuple[str, ...]
    specs: Mapping[str, Spec]
    order: tuple[str, ...]
    keys: Mapping[str, str]
    emitter: str
    sections: Mapping[str, str] = dataclasses.field(default_factory=dict)   # id → its section's module

    def key(self, kind: str, rid: str) -> str:
        return keys.digest((kind, self.level if kind == "assessed" else "", self.keys[rid]))


# ----------------------------------------------------------------- plan
def output_dir(out: Path | str) -> Path:
    """The output directory, checked writable before any work (created if missing)."""
    out = Path(out)
    if out.exists() and not out.is_dir():
        raise OutputError(f"--out {out}: not a directory")
    try:
        out.mkdir(parents=True, exist_ok=True)
        with tempfile.NamedTemporaryFile(dir=out, prefix=".probe-"):
            pass
    except OSError as exc:
        raise OutputError(f"--out {out}: cannot write there ({exc.strerror or exc})") from None
    return out


def tree_key(level: str) -> str:
    """The key of the whole tree (every source file, the versions, the level): no memoir imported."""
    return keys.tree_key(registry.packages(), level)


def unchanged(tree: str, out: Path) -> bool:
    """True when the last derive of this very tree wrote the files that ``out`` holds now."""
    manifest = cache.load(_manifest_key(tree, out))
    if manifest is cache.MISSING or not isinstance(manifest, dict):
        return False
    for rel, digest in manifest.items():
        path = out / rel
        if not path.is_file() or content_hash(path.read_text(encoding="utf-8")) != digest:
            return False
    return True


def _manifest_key(tree: str, out: Path) -> str:
    return keys.digest(("manifest", tree, str(out.resolve())))


def plan(level: str) -> Plan:
    specs = registry.all_specs()
    order = tuple(registry.closure(list(specs), specs))
    section = {s.id: sec.module for m in registry.memoirs().values() for sec in m.sections for s in sec.specs}
    roots = ("pendsym", *registry.packages())
    ks = keys.result_keys(section, {i: specs[i].deps for i in order}, order, roots)
    return Plan(level, tuple(registry.memoirs()), specs, order, ks, keys.emitter_hash(), section)


# ----------------------------------------------------------------- build (its own module)
build = build_stage.build


# ----------------------------------------------------------------- compare, check, form kernels
def _assess_job(job: tuple, level: str, keys_of: Mapping[str, str]) -> list:
    """A job of one worker: the comparison and check of each Result (cached), with the seconds
    each took and whether it was checked now."""
    out = []
    for r in job:
        start = time.monotonic()
        value, computed = cache.memo_fresh(keys_of[r.id], functools.partial(pipeline.assessed, r, level))
        out.append((value, time.monotonic() - start, computed))
    return out


def _kernel_job(result: Result, key: str):
    """(kernel or None, formed now?)."""
    return cache.memo_fresh(key, functools.partial(kn.kernel_of, result))


def _pool_job(job: tuple, level: str, keys_of: Mapping[str, str]):
    """One job of the pool: ("check", Results) or ("kernel", Result)."""
    kind, payload = job
    if kind == "check":
        return _assess_job(payload, level, keys_of)
    return _kernel_job(payload, keys_of[f"kernel:{payload.id}"])


def check_and_form(pl: Plan, built: Mapping[str, Result], log: Log,
                   progress: Callable[[int, int], None] | None = None) -> tuple[list[pipeline.Record], dict[str, list]]:
    """Stages 2–3 for every Result (printed ≡ derived?, the independent check, then the chains) and
    the kernels' stable forms (chosen and measured in Python), in one pool of workers: the checks
    first (the costliest memoirs first, each group of shared truths in one worker), then the kernels,
    so that no core idles while the last checks run.  Only what changed is computed anew."""
    start = time.monotonic()
    keys_of = {i: pl.key("assessed", i) for i in pl.order}
    by_cost = sorted(pl.memoirs, key=lambda m: -registry.memoir(m).cost)
    ordered = [i for m in by_cost for i in pl.order if pl.specs[i].memoir == m]
    groups = [g for m in pl.memoirs for g in registry.memoir(m).check_groups()]
    jobs = {job[0]: ("check", tuple(built[i] for i in job)) for job in schedule.jobs_by_affinity(ordered, groups)}
    kernel_ids_ = kernel_ids(pl, built)
    keys_of.update({f"kernel:{i}": kernel_key(built[i], pl.emitter) for i in kernel_ids_})
    jobs.update({f"kernel:{i}": ("kernel", built[i]) for i in by_size(kernel_ids_, built)})
    done_ids: list[int] = [0]

    def tick(first: str) -> None:
        kind, payload = jobs[first]
        if kind == "check":
            done_ids[0] += len(payload)
            if progress:
                progress(done_ids[0], len(pl.order))
    outs = dict(zip(jobs, schedule.per_result(jobs, list(jobs), functools.partial(
        _pool_job, level=pl.level, keys_of=keys_of), progress=tick)))
    records = _records(pl, built, {first: outs[first] for first, (kind, _) in jobs.items() if kind == "check"},
                       jobs, log)
    formed = _formed(pl, [(i, outs[f"kernel:{i}"]) for i in kernel_ids_], log)
    log(f"checks and kernel forms took {time.monotonic() - start:.0f} s")
    return records, formed


def by_size(ids: list[str], built: Mapping[str, Result]) -> list[str]:
    """The kernels to form, the largest derived form first (ties in the order of ``ids``): the pool ends on its
    kernels, and a kernel's forming time grows with its form (session 12, the 81 kernels formed one by one under
    load: 529 s of CPU, 0.1 s for forms of ~100 characters of srepr, 20–53 s for F, K, n², Γ4, I, J at 1,700–12,300;
    correlation 0.74), so that the last jobs are short ones and no core idles long while the other ends a long
    one (longest job first: a two-worker list schedule of those times ends with one worker idle 9 s in the plan's
    order, 1 s in this one)."""
    size = {i: len(sp.srepr(built[i].derived)) for i in ids}
    return sorted(ids, key=lambda i: -size[i])


def _records(pl: Plan, built: Mapping[str, Result], outs: Mapping[str, list], jobs: Mapping[str, tuple],
             log: Log) -> list[pipeline.Record]:
    runs = {r.id: run for first, out in outs.items() for r, run in zip(jobs[first][1], out)}
    done = {i: value for i, (value, _, _) in runs.items()}
    took = {i: seconds for i, (_, seconds, computed) in runs.items() if computed}
    todo = [i for i in pl.order if i in took]
    records = [pipeline.Record(built[i], *done[i][0], done[i][1]) for i in pl.order]
    log(f"checked {len(todo)} results anew ({len(pl.order) - len(todo)} from the cache)"
        + (f": {_sections(pl, todo)}" if todo else ""))
    if todo:
        slow = sorted(took.items(), key=lambda kv: -kv[1])[:5]
        log(f"  {sum(took.values()):.0f} s of checks; slowest: " + ", ".join(f"{i} {t:.0f} s" for i, t in slow))
    return pipeline.fill_chains(records)


def _formed(pl: Plan, outs: list, log: Log) -> dict[str, list]:
    """Each memoir's kernels, from (id, (kernel or None, formed now?))."""
    formed = {m: [] for m in pl.memoirs}
    for i, (k, _) in outs:
        if k is not None:
            formed[pl.specs[i].memoir].append(k)
    log(f"formed {len(outs)} kernels ({sum(1 for _, (_, computed) in outs if computed)} anew)")
    return formed


def assess(results, level: str = "full", run_checks: bool = True) -> list[pipeline.Record]:
    """Compare each Result (and run its check, uncached) over the cores; then fill the chains.
    For a few Results (``pendsym derive ID``, the tests); a derive goes through check_and_form."""
    results = list(results)
    by_id = {r.id: r for r in results}
    fn = functools.partial(pipeline.assessed, level=level) if run_checks else _compared
    done = schedule.per_result(by_id, [r.id for r in results], fn)
    records = [pipeline.Record(r, status, how, ev) for r, ((status, how), ev) in zip(results, done)]
    return pipeline.fill_chains(records) if run_checks else records


def _compared(result: Result):
    return pipeline.compare(result), None


# ----------------------------------------------------------------- the same work, for a few Results
@functools.lru_cache(maxsize=2)
def plan_of(level: str = "full") -> Plan:
    """The plan of a derive at ``level`` (computed once per process)."""
    return plan(level)


def results(ids=None, level: str = "full", memoirs=None) -> dict[str, Result]:
    """The Results of ``ids`` (or of whole ``memoirs``, or all) and their closure, built as ``make derive``
    builds them: each form from the cache when this very code built it before (its key covers the
    sources it depends on), built here otherwise, and stored only under the string-hash seed a
    derive runs with (a SymPy form can follow it: see ``pendsym.cli``)."""
    pl = plan_of(level)
    if ids is None:
        ids = [i for i in pl.order if memoirs is None or pl.specs[i].memoir in set(memoirs)]
    built: dict[str, Result] = {}
    build_stage.build_ids(pl, registry.closure(list(ids), pl.specs), built, keep=os.environ.get("PYTHONHASHSEED") == "0")
    return built


def assessed(result: Result, level: str = "full") -> tuple[tuple[str, str], object]:
    """((comparison, how), evidence) of one Result, as ``make derive`` assesses it: from the cache
    when this very code assessed it before, computed (and cached) here otherwise."""
    pl = plan_of(level)
    return cache.memo(pl.key("assessed", result.id), functools.partial(pipeline.assessed, result, level))


def kernel(result: Result, level: str = "full") -> kn.Kernel | None:
    """The kernel of one Result, as ``make derive`` forms it: from the cache when these very emitters
    formed it from these very forms before (:func:`kernel_key`), formed here otherwise (and stored only
    under the string-hash seed a derive runs with, as :func:`results` does)."""
    return cache.memo_fresh(kernel_key(result, plan_of(level).emitter), functools.partial(kn.kernel_of, result),
                            os.environ.get("PYTHONHASHSEED") == "0")[0]


def _sections(pl: Plan, ids: list[str]) -> str:
    """The sections the ids belong to, with their counts."""
    wanted = set(ids)
    count: dict[str, int] = {}
    for m in pl.memoirs:
        for sec in registry.memoir(m).sections:
            n = len(wanted.intersection(sec.ids))
            if n:
                count[sec.module] = n
    return ", ".join(f"{mod} ({n})" for mod, n in count.items())


# ----------------------------------------------------------------- kernels
def kernel_ids(pl: Plan, built: Mapping[str, Result]) -> list[str]:
    """The Results that ask for a kernel and have a closed form (in memoirs whose kernels are ready)."""
    return [i for i in pl.order if pl.specs[i].kernel is not None and registry.memoir(pl.specs[i].memoir).kernels
            and kn.closed_form(built[i].derived)]


def kernel_key(result: Result, emitter: str) -> str:
    """A kernel depends on the Result's forms and declarations only (not on the code that derived or
    checks them): its key is their content, with the kernel emitters' source."""
    spec = result.spec
    return keys.digest(("kernel", keys.FORMAT, *keys.versions(), result.id, sp.srepr(result.derived),
                        sp.srepr(result.printed), repr(spec.kernel), sp.srepr(sp.Tuple(*(sp.Tuple(*d) for d in spec.defs))),
                        spec.title, spec.source.ref(), emitter))


def _c_key(result: Result, pl: Plan) -> str:
    return keys.digest(("c", kernel_key(result, pl.emitter)))


def _c_job(job):
    lib, k, result = job
    return kn.c_accuracy(lib, k, result)


def measure_c(pl: Plan, built: Mapping[str, Result], formed: dict[str, list], log: Log) -> dict[str, list]:
    """The accuracy of each kernel's compiled C, measured on the emitted code (cached per kernel;
    a memoir's kernels are compiled only when one of them is not in the cache)."""
    if not shutil.which("cc"):
        return formed
    start = time.monotonic()
    accuracy = {k.result_id: cache.load(_c_key(built[k.result_id], pl)) for ks in formed.values() for k in ks}
    with tempfile.TemporaryDirectory() as tmp:
        jobs = {}
        for memoir, ks in formed.items():
            missing = [k for k in ks if accuracy[k.result_id] is cache.MISSING]
            if missing:
                d = Path(tmp) / memoir
                d.mkdir()
                lib = kn.compile_c(files.c_standalone(memoir, ks), d)
                jobs.update({k.result_id: (lib, k, built[k.result_id]) for k in missing})
        for rid, acc in zip(jobs, schedule.per_result(jobs, list(jobs), _c_job)):
            cache.store(_c_key(built[rid], pl), acc)
            accuracy[rid] = acc
    out = {memoir: [dataclasses.replace(k, c_accuracy=accuracy[k.result_id]) for k in ks]
           for memoir, ks in formed.items()}
    log(f"measured {len(jobs)} C kernels anew in {time.monotonic() - start:.0f} s")
    return out


def within_bound(k: kn.Kernel) -> bool:
    """The kernel holds kn.BOUND ulp × max(1, κ) on its measured sample (Python and, if built, C)."""
    accs = [a for a in (k.py_accuracy, k.c_accuracy) if a is not None]
    return bool(accs) and all(a.max_scaled <= kn.BOUND for a in accs)


# ----------------------------------------------------------------- figures
def _figure_job(job) -> figure.Plot:
    fig, results, ks, key = job
    drawn = {k.result_id: (emitted_py(k.name, k.args, k.expr, k.domain), [a.name for a in k.args]) for k in ks}
    return cache.memo(key, functools.partial(figure.sample, fig, results, drawn))


def _figure_job_of(pl: Plan, fig, built: Mapping[str, Result], emitted: Mapping[str, kn.Kernel]):
    """(figure, its Results, the kernels it draws, its cache key), or None when a Result it cites is not built."""
    if not all(i in built for i in fig.cites):
        return None
    ks = [emitted[c.result] for c in fig.curves if c.source == "kernel" and c.result in emitted]
    key = figure.figure_key(fig, pl.keys, {k.result_id: sp.srepr(k.expr) for k in ks}, ("pendsym", *registry.packages()))
    return fig, {i: built[i] for i in fig.cites}, ks, key


def sample_figures(pl: Plan, built: Mapping[str, Result], formed: dict[str, list], log: Log) -> dict[str, list]:
    """Each memoir's figures, sampled (cached under :func:`pendsym.figure.figure_key`; the kernels drawn
    are those emitted, within the bound): {memoir: [(Figure, Plot)]}."""
    start = time.monotonic()
    jobs, fresh = {}, []
    for memoir in pl.memoirs:
        emitted = {k.result_id: k for k in formed.get(memoir, []) if within_bound(k)}
        for fig in registry.memoir(memoir).figures:
            job = _figure_job_of(pl, fig, built, emitted)
            if job is None:
                continue
            if cache.load(job[3]) is cache.MISSING:
                fresh.append(fig.id)
            jobs[fig.id] = job
    plots = dict(zip(jobs, schedule.per_result(jobs, list(jobs), _figure_job)))
    if jobs:
        log(f"sampled {len(jobs)} figures ({len(fresh)} anew) in {time.monotonic() - start:.0f} s"
            + (": " + ", ".join(f"{i} {plots[i].seconds:.1f} s CPU" for i in fresh) if fresh else ""))
    out: dict[str, list] = {m: [] for m in pl.memoirs}
    for fig, *_ in jobs.values():
        out[fig.memoir].append((fig, plots[fig.id]))
    return out


def figure_plots(memoir: str, level: str = "full") -> dict[str, tuple]:
    """{figure id: (Figure, Plot)} of a memoir's figures as ``make derive`` samples them: from the cache under
    the derive's key (the Results cited built as :func:`results` builds them, the kernels drawn those the derive
    emits: :func:`emitted_kernel`), sampled here otherwise (and stored only under the string-hash seed 0)."""
    pl = plan_of(level)
    figs = registry.memoir(memoir).figures
    built = results(ids=[i for f in figs for i in f.cites], level=level)
    emitted = {}
    for f in figs:
        for c in f.curves:
            if c.source == "kernel" and c.result in built and c.result not in emitted:
                k = emitted_kernel(built[c.result], level)
                if k is not None:
                    emitted[c.result] = k
    keep = os.environ.get("PYTHONHASHSEED") == "0"
    out = {}
    for f in figs:
        job = _figure_job_of(pl, f, built, emitted)
        fig, results_, ks, key = job
        drawn = {k.result_id: (emitted_py(k.name, k.args, k.expr, k.domain), [a.name for a in k.args]) for k in ks}
        out[f.id] = (f, cache.memo_fresh(key, functools.partial(figure.sample, fig, results_, drawn), keep)[0])
    return out


def c_accuracy(result: Result, level: str = "full") -> kn.Accuracy | None:
    """The accuracy of a Result's kernel in C as ``make derive`` measured it on the emitted code (from the cache
    under the derive's key), or None when no derive measured it."""
    acc = cache.load(_c_key(result, plan_of(level)))
    return None if acc is cache.MISSING else acc


def formed_kernel(result: Result, level: str = "full") -> kn.Kernel | None:
    """The kernel ``make derive`` formed for a Result, with the accuracy it measured in Python (from the cache
    under the derive's key; never formed here), or None when no derive formed one."""
    k = cache.load(kernel_key(result, plan_of(level).emitter))
    return k if isinstance(k, kn.Kernel) else None


def emitted_kernel(result: Result, level: str = "full") -> kn.Kernel | None:
    """The kernel ``make derive`` emits for a Result (with the accuracies it measured), or None: no kernel asked
    for, not a closed form, or over the bound."""
    spec = result.spec
    if spec.kernel is None or not registry.memoir(spec.memoir).kernels or not kn.closed_form(result.derived):
        return None
    k = kernel(result, level)
    if k is None:
        return None
    k = dataclasses.replace(k, c_accuracy=c_accuracy(result, level))
    return k if within_bound(k) else None


# ----------------------------------------------------------------- emit and write
def emit(pl: Plan, records: list[pipeline.Record], formed: dict[str, list], out: Path, log: Log,
         figures: Mapping[str, list] | None = None) -> dict[Path, str]:
    """Every generated file's text: per memoir its kernels (those within the bound), its report;
    the memoir-independent swing-time kernels; results.json."""
    texts: dict[Path, str] = {}
    names: dict[str, list[str]] = {}
    for memoir in pl.memoirs:
        m = registry.memoir(memoir)
        ks = [k for k in formed[memoir] if within_bound(k)]
        held = [k for k in formed[memoir] if not within_bound(k)]
        log(f"{memoir}: {len(ks)} kernels" + (f", {len(held)} withheld over the bound: "
                                               + ", ".join(k.name for k in held) if held else ""))
        for k in ks:
            names.setdefault(k.result_id, []).append(k.name)
        recs = [r for r in records if r.result.spec.memoir == memoir]
        headings = tuple((h.ids, h.title) for h in m.report_headings())
        texts.update({
            out / "python" / f"{memoir}.py": files.python_module(memoir, ks),
            out / "c" / f"{memoir}.c": files.c_source(memoir, ks),
            out / "c" / f"{memoir}.h": files.c_header(memoir, ks),
            out / "tex" / f"{memoir}.tex": latex.report(memoir, m.title, recs, ks, bench_input(out, memoir),
                                                       headings, held, figures=(figures or {}).get(memoir, ())),
        })
    texts.update(pendulum_kernels(out))
    texts[out / "results.json"] = pipeline.results_json(records, names)
    return texts


def bench_input(out: Path, memoir: str) -> str | None:
    """The benchmark table a report includes (relative to generated/tex), when make bench wrote one."""
    name = f"{memoir}-period.tex"
    return f"../bench/{name}" if (out / "bench" / name).exists() else None


def pendulum_kernels(out: Path) -> dict[Path, str]:
    """The memoir-independent exact swing time by the AGM (used by make bench and the tests)."""
    ctx = {"pi": "3.14159265358979323846"}
    return {
        out / "c" / "pendulum.c": files.render("pendulum.c.j2", **ctx),
        out / "c" / "pendulum.h": files.render("pendulum.h.j2", **ctx),
        out / "python" / "pendulum.py": files.render("pendulum.py.j2", **ctx),
    }


def write(texts: Mapping[Path, str], tree: str, out: Path, remember: bool = True) -> list[Path]:
    """Write every file (atomically, only if changed); with ``remember``, note what this tree wrote
    (so that the next derive of the same tree has nothing to do)."""
    for path, text in texts.items():
        write_atomic(path, text)
    if remember:
            cache.store(_manifest_key(tree, out),
                    {str(p.relative_to(out)): content_hash(t) for p, t in sorted(texts.items())})
    return list(texts)


def failures(records: list[pipeline.Record]) -> list[pipeline.Record]:
    """The Results whose independent check failed."""
    return [r for r in records if r.evidence is not None and not r.evidence.passed]


def summary(records: list[pipeline.Record]) -> list[str]:
    """The closing lines of a derive: counts, then one line per failed check."""
    defs = sum(1 for r in records if r.result.spec.definition)
    verified = sum(1 for r in records if r.verified)
    failed = failures(records)
    lines = [f"{len(records)} results: {verified} verified, {len(failed)} failed, {defs} definitions, "
             f"{len(records) - verified - len(failed) - defs} without a check"]
    lines += [f"FAILED {r.result.id}: {r.evidence.truth[:80]} (largest residual {r.evidence.max_residual})"
              for r in failed]
    return lines
