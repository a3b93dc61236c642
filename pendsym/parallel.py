"""Run independent per-Result work (checks, kernel forms) on the machine's cores.

Workers are forked after the Results are built, so they inherit them instead
of rebuilding; only ids go to a worker and only plain records (Evidence,
Kernel) come back.  The work of each Result is deterministic, so the output
does not depend on which worker did it.  PENDSYM_WORKERS=1 runs serially.
"""
from __future__ import annotations

import multiprocessing
import os
from concurrent.futures import ProcessPoolExecutor
from typing import Callable, Mapping, Sequence

_INHERITED: dict = {}   # set once in each forked worker by _adopt; never in the parent


def _adopt(results, fn):
    _INHERITED["results"], _INHERITED["fn"] = results, fn


def _call(rid: str):
    return _INHERITED["fn"](_INHERITED["results"][rid])


def workers() -> int:
    env = os.environ.get("PENDSYM_WORKERS")
    return max(1, int(env)) if env else max(1, min(2, os.cpu_count() or 1))


def per_result(results: Mapping[str, object], ids: Sequence[str], fn: Callable) -> list:
    """[fn(results[i]) for i in ids], over forked workers when there are several cores."""
    n = workers()
    if n == 1 or len(ids) < 2 or "fork" not in multiprocessing.get_all_start_methods():
        return [fn(results[i]) for i in ids]
    ctx = multiprocessing.get_context("fork")
    with ProcessPoolExecutor(max_workers=n, mp_context=ctx, initializer=_adopt, initargs=(results, fn)) as ex:
        return list(ex.map(_call, ids, chunksize=1))
