"""The build stage of ``make derive``: every Result's forms (derived and printed), over two cores.

Each section is a job of a dependency graph (sections that depend on each other both ways are one job); the
jobs run here and in one forked helper (:func:`pendsym.schedule.over_dag`), each from the cache under the
Result's content key or built anew.  :mod:`pendsym.stages` hands this stage on as ``stages.build``.
"""
from __future__ import annotations

import functools
import os
import time
from typing import TYPE_CHECKING, Callable, Mapping

import sympy as sp

from . import cache, codec, registry, schedule
from .result import Result, Spec

if TYPE_CHECKING:
    from .stages import Log, Plan


def _forms(spec: Spec, built: Mapping[str, Result]) -> tuple[sp.Basic, sp.Basic | None]:
    r = registry.build_one(spec, built)
    return r.derived, r.printed


def build_ids(pl: Plan, ids: list[str], built: dict, keep: bool = True,
               between: Callable[[], None] = lambda: None) -> list[str]:
    """Results of ids (dependencies first) into ``built``, their forms from the cache or built here
    (and stored, if ``keep``); the ids built anew.  ``between()`` is called after each one."""
    fresh = []
    for rid in ids:
        spec = pl.specs[rid]
        (derived, printed), computed = cache.memo_fresh(pl.key("built", rid), functools.partial(_forms, spec, built),
                                                        keep)
        built[rid] = Result(spec=spec, derived=derived, printed=printed, deps={d: built[d] for d in spec.deps})
        if computed:
            fresh.append(rid)
        between()
    return fresh


def _chapter(pl: Plan, rid: str) -> str:
    """The sub-package of its memoir that a Result's section lives in (the section itself when it is a
    module of the memoir's package): the affinity of the build's jobs."""
    memoir = pl.specs[rid].memoir
    modules = {pl.sections[i] for i in pl.order if pl.specs[i].memoir == memoir}
    prefix = os.path.commonprefix([m + "." for m in modules]).rpartition(".")[0]
    rest = pl.sections[rid][len(prefix):].lstrip(".")
    return f"{prefix}.{rest.split('.')[0]}" if rest else pl.sections[rid]


def build(pl: Plan, log: Log) -> dict[str, Result]:
    """Every Result.  Each section is a job (sections that depend on each other both ways are one); the
    jobs run on two cores, here and in a forked helper, each once the jobs it depends on are done: the
    longest chain of work first, and a core keeps to the chapter it works in (its derivation caches stay
    warm).  The helper is sent the forms it lacks and sends back those it built (as codec data, so
    that each tree is rebuilt identically)."""
    start, cpu = time.monotonic(), time.process_time()
    group = {i: pl.sections.get(i, pl.specs[i].memoir) for i in pl.order}
    jobs, after = schedule.dag_jobs(pl.order, group, {i: pl.specs[i].deps for i in pl.order})
    chapters = _chapters(pl)
    rank = schedule.critical_rank(jobs, after, lambda j: len(jobs[j]))
    built: dict[str, Result] = {}
    fresh: list[str] = []
    helper_has: set[str] = set()
    helper_cpu = [0.0]

    def pick(ready: list, last: str | None) -> str:
        return max(ready, key=lambda j: (last is not None and chapters[j] == chapters[last], rank[j]))

    def here(job: str, poll: Callable[[], None]) -> None:
        fresh.extend(build_ids(pl, list(jobs[job]), built, between=poll))

    def send(job: str):
        needed = sorted({d for i in jobs[job] for d in pl.specs[i].deps} - set(jobs[job]) - helper_has,
                        key=pl.order.index)
        helper_has.update(needed)
        return codec.encode({d: (built[d].derived, built[d].printed) for d in needed})

    def receive(job: str, value) -> None:
        forms, fresh_there, seconds = value
        for rid, (derived, printed) in codec.decode(forms).items():
            built[rid] = Result(spec=pl.specs[rid], derived=derived, printed=printed,
                                deps={d: built[d] for d in pl.specs[rid].deps})
        fresh.extend(fresh_there)
        helper_cpu[0] += seconds
        helper_has.update(jobs[job])

    where = schedule.over_dag(list(jobs), after, here, functools.partial(_build_there, pl, jobs, {}), send,
                              receive, pick)
    n_there = sum(len(jobs[j]) for j, w in where.items() if w == "there")
    log(f"built {len(built)} results ({len(fresh)} derived anew) in {time.monotonic() - start:.0f} s: "
        f"{len(built) - n_there} here ({time.process_time() - cpu:.0f} s CPU), "
        f"{n_there} in the helper ({helper_cpu[0]:.0f} s CPU)")
    return _rewire(pl, built)


def _chapters(pl: Plan) -> dict[str, str]:
    """{first id of a section: its chapter} for every section (the names of the build's jobs)."""
    memo: dict[str, str] = {}
    out: dict[str, str] = {}
    for i in pl.order:
        sec = pl.sections.get(i, pl.specs[i].memoir)
        if sec not in memo:
            memo[sec] = _chapter(pl, i) if i in pl.sections else sec
        out[sec] = memo[sec]
    return out


def _build_there(pl: Plan, jobs: Mapping[str, tuple], built: dict, job: str, payload) -> tuple:
    """In the build helper: a job's Results, given the forms of its dependencies that the helper lacks
    (``built`` is the helper's own, kept from job to job); (their forms as codec data, the ids built
    anew, the CPU seconds it took)."""
    cpu = time.process_time()
    for rid, (derived, printed) in codec.decode(payload).items():
        built[rid] = Result(spec=pl.specs[rid], derived=derived, printed=printed,
                            deps={d: built[d] for d in pl.specs[rid].deps if d in built})
    fresh = build_ids(pl, list(jobs[job]), built)
    forms = codec.encode({i: (built[i].derived, built[i].printed) for i in jobs[job]})
    return forms, fresh, time.process_time() - cpu


def _rewire(pl: Plan, built: dict[str, Result]) -> dict[str, Result]:
    """Results in plan order, each wired to its built dependencies."""
    out: dict[str, Result] = {}
    for rid in pl.order:
        r = built[rid]
        out[rid] = Result(spec=r.spec, derived=r.derived, printed=r.printed, deps={d: out[d] for d in r.spec.deps})
    return out
