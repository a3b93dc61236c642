"""``make derive``: the spine.  Every stage is a plain function of :mod:`pendsym.stages`;
scheduling and forking live in :mod:`pendsym.schedule`, content keys in :mod:`pendsym.keys`."""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Callable

from . import stages
from .stages import within_bound  # noqa: F401  (the kernel bound, part of the public API)


@dataclass(frozen=True)
class Outcome:
    """What a derive did: the files it wrote (none when nothing changed) and its failed checks."""

    written: tuple[Path, ...]
    failed: tuple[str, ...]
    summary: tuple[str, ...]
    nothing_changed: bool = False


def derive_all(out: Path, level: str = "full", log: Callable[[str], None] = print,
               progress: Callable[[int, int], None] | None = None) -> Outcome:
    out = stages.output_dir(out)                                   # checked before any work
    tree = stages.tree_key(level)
    if stages.unchanged(tree, out):
        return Outcome((), (), ("nothing changed",), nothing_changed=True)
    plan = stages.plan(level)
    built = stages.build(plan, log)                                # build (forms cached per Result)
    records, formed = stages.check_and_form(plan, built, log, progress)  # compare → check → chains,
    #                                                                and stable forms measured in Python
    formed = stages.measure_c(plan, built, formed, log)            # the emitted C, measured
    plots = stages.sample_figures(plan, built, formed, log)        # the reports' figures
    texts = stages.emit(plan, records, formed, out, log, plots)    # kernels, reports, results.json
    failed = tuple(r.result.id for r in stages.failures(records))
    written = stages.write(texts, tree, out, remember=not failed)  # a failure is never "nothing changed"
    return Outcome(tuple(written), failed, tuple(stages.summary(records)))
