"""Scheduling and forking: independent per-Result work (builds, checks, kernel forms) over the cores.

Workers are forked after the Results are built, so they inherit them instead of
rebuilding; only ids go to a worker and only plain records (forms, Evidence,
Kernel) come back.  The work of each Result is deterministic, so the output does
not depend on which worker did it.  ``PENDSYM_WORKERS=1`` runs serially.
A worker dies with its parent (Linux's parent-death signal): a killed derive
leaves no orphan behind.
"""
from __future__ import annotations

import contextlib
import ctypes
import multiprocessing
import os
import signal
from typing import Callable, Mapping, Sequence

_INHERITED: dict = {}   # set once in each forked worker by _adopt; never in the parent
PR_SET_PDEATHSIG = 1


def _die_with_parent(parent: int) -> None:
    """Ask the kernel to kill this worker when its parent dies (Linux); elsewhere a no-op."""
    try:
        libc = ctypes.CDLL(None, use_errno=True)
        libc.prctl(PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
    except (OSError, AttributeError):
        return
    if os.getppid() != parent:     # the parent died before the request took effect
        os._exit(1)


@contextlib.contextmanager
def _sigint_held():
    """SIGINT blocked while workers are forked: they are born with it blocked and unblock it only once
    they ignore it (:func:`_ignore_sigint`), so a Ctrl-C that arrives as they start reaches the parent
    alone, when this block ends, and never kills a worker half-started."""
    old = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT})
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, old)


def _ignore_sigint() -> None:
    """In a worker: Ctrl-C is the parent's to report (a pending one is discarded with SIG_IGN)."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT})


def _adopt(parent: int, results, fn) -> None:
    _die_with_parent(parent)
    _ignore_sigint()
    _INHERITED["results"], _INHERITED["fn"] = results, fn


def _call(rid: str):
    return _INHERITED["fn"](_INHERITED["results"][rid])


def workers() -> int:
    env = os.environ.get("PENDSYM_WORKERS")
    return max(1, int(env)) if env else max(1, min(2, os.cpu_count() or 1))


def can_fork() -> bool:
    return workers() > 1 and "fork" in multiprocessing.get_all_start_methods()


def per_result(results: Mapping[str, object], ids: Sequence[str], fn: Callable,
               progress: Callable[[str], None] | None = None) -> list:
    """[fn(results[i]) for i in ids], over forked workers when there are several cores.

    ``progress(id)`` is called in the parent as each one finishes (in completion order)."""
    if not can_fork() or len(ids) < 2:
        out = []
        for i in ids:
            out.append(fn(results[i]))
            if progress:
                progress(i)
        return out
    ctx = multiprocessing.get_context("fork")
    pool = None
    try:
        with _sigint_held():
            pool = ctx.Pool(workers(), initializer=_adopt, initargs=(os.getpid(), results, fn))
        pending = [pool.apply_async(_call, (i,), callback=(lambda _v, i=i: progress(i)) if progress else None)
                   for i in ids]
        out = [p.get() for p in pending]
    except BaseException:
        if pool is not None:
            pool.terminate()    # Ctrl-C or a failed job: no worker outlives this call
        raise
    pool.close()
    pool.join()
    return out


def in_background(fn: Callable, *args):
    """Run fn(*args) in one forked process while the caller works; returns a getter for the value
    (or, without fork, computes it at once).  The arguments are inherited through the fork, not
    pickled; only the value comes back."""
    if not can_fork():
        value = fn(*args)
        return lambda: value
    ctx = multiprocessing.get_context("fork")
    receive, send = ctx.Pipe(duplex=False)
    parent = os.getpid()

    def child():
        _die_with_parent(parent)
        _ignore_sigint()
        try:
            send.send((True, fn(*args)))
        except BaseException as exc:  # reported in the parent
            send.send((False, f"{type(exc).__name__}: {exc}"))
    proc = ctx.Process(target=child, daemon=True)
    with _sigint_held():
        proc.start()
    send.close()

    def get():
        try:
            ok, value = receive.recv()
        except EOFError:
            raise RuntimeError("the background build died") from None
        finally:
            proc.join()
        if not ok:
            raise RuntimeError(f"the background build failed: {value}")
        return value
    return get


def jobs_by_affinity(ids: Sequence[str], groups: Sequence[Sequence[str]]) -> list[tuple[str, ...]]:
    """One job per id, except each affinity group whose members are all present, which is one job
    (its checks share computations in one worker); groups that overlap are one job.  Keeps the
    order of ``ids``."""
    present = set(ids)
    group_of: dict[str, set] = {}
    for g in groups:
        if not all(x in present for x in g):
            continue
        merged = set(g).union(*(group_of.get(x, ()) for x in g))
        for x in merged:
            group_of[x] = merged
    out, placed = [], set()
    for i in ids:
        if i in placed:
            continue
        members = group_of.get(i, {i})
        job = tuple(x for x in ids if x in members)
        placed.update(job)
        out.append(job)
    return out
