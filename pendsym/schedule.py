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


def _call_indexed(job: tuple[int, str]) -> tuple[int, object]:
    k, rid = job
    return k, _call(rid)


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
        # progress runs here, in the main thread, not as a pool callback: a callback that raises (a progress
        # line written to a closed pipe) kills the pool's result thread, and the derive would wait forever
        done: dict[int, object] = {}
        for k, value in pool.imap_unordered(_call_indexed, enumerate(ids)):
            done[k] = value
            if progress:
                progress(ids[k])
        out = [done[k] for k in range(len(ids))]
    except BaseException:
        if pool is not None:
            pool.terminate()    # Ctrl-C or a failed job: no worker outlives this call
        raise
    pool.close()
    pool.join()
    return out


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


# ----------------------------------------------------------------- a DAG of jobs, here and in one helper
def dag_jobs(order: Sequence[str], group: Mapping[str, str],
             deps: Mapping[str, Sequence[str]]) -> tuple[dict[str, tuple[str, ...]], dict[str, frozenset]]:
    """The jobs of a DAG of items: the items of one group (``group[item]``) are one job, and groups that
    depend on each other both ways (a cycle between groups) are merged into one.  Returns
    ({job: its items in ``order``}, {job: the jobs it waits for}), the jobs in an order that puts each after
    those it waits for (ties by their first item in ``order``).  ``order`` must put every item after its deps."""
    first = {}
    for i in order:
        first.setdefault(group[i], len(first))
    after_g: dict[str, set] = {g: set() for g in first}
    for i in order:
        after_g[group[i]].update(group[d] for d in deps[i] if group[d] != group[i])
    comp = _strong_components(list(first), after_g)
    name = {g: min(comp[g], key=first.__getitem__) for g in first}
    after: dict[str, set] = {}
    for g, ds in after_g.items():
        after.setdefault(name[g], set()).update(name[d] for d in ds if name[d] != name[g])
    items: dict[str, list] = {}
    for i in order:
        items.setdefault(name[group[i]], []).append(i)
    placed: list[str] = []
    done: set = set()
    pending = sorted(items, key=lambda j: order.index(items[j][0]))
    while pending:                          # Kahn's algorithm, ties by the first item's place
        j = next(j for j in pending if after[j] <= done)
        pending.remove(j)
        placed.append(j)
        done.add(j)
    return {j: tuple(items[j]) for j in placed}, {j: frozenset(after[j]) for j in placed}


def _strong_components(nodes: list, edges: Mapping[str, set]) -> dict[str, frozenset]:
    """Each node's strongly connected component (Tarjan, iterative)."""
    index: dict = {}
    low: dict = {}
    stack: list = []
    on_stack: set = set()
    out: dict = {}
    for root in nodes:
        if root in index:
            continue
        work = [(root, iter(sorted(edges[root])))]
        index[root] = low[root] = len(index)
        stack.append(root)
        on_stack.add(root)
        while work:
            v, it = work[-1]
            w = next(it, None)
            if w is not None:
                if w not in index:
                    index[w] = low[w] = len(index)
                    stack.append(w)
                    on_stack.add(w)
                    work.append((w, iter(sorted(edges[w]))))
                elif w in on_stack:
                    low[v] = min(low[v], index[w])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[v])
            if low[v] == index[v]:
                members = []
                while True:
                    w = stack.pop()
                    on_stack.discard(w)
                    members.append(w)
                    if w == v:
                        break
                comp = frozenset(members)
                out.update((w, comp) for w in members)
    return out


def critical_rank(jobs: Mapping[str, Sequence[str]], after: Mapping[str, frozenset],
                  weight: Callable[[str], float]) -> dict[str, float]:
    """Each job's weight plus the heaviest chain of the jobs that wait for it (its priority in a list
    schedule: the longest remaining path starts first)."""
    waiting: dict[str, list] = {j: [] for j in jobs}
    for j, ds in after.items():
        for d in ds:
            waiting[d].append(j)
    rank: dict[str, float] = {}
    for j in reversed(list(jobs)):
        rank[j] = weight(j) + max((rank[k] for k in waiting[j]), default=0.0)
    return rank


def over_dag(jobs: Sequence[str], after: Mapping[str, frozenset], here: Callable[[str, Callable[[], None]], None],
             there: Callable[[str, object], object], send: Callable[[str], object],
             receive: Callable[[str, object], None], pick: Callable[[list, str | None], str]) -> dict[str, str]:
    """Run a DAG of jobs on two cores: in this process and in one forked helper, each job as soon as the
    jobs it waits for are done.

    ``here(job, poll)`` runs a job in this process and calls ``poll()`` between its steps (the helper's
    reply is then taken, and the helper given its next job, without waiting for this job to end);
    ``there(job, payload)`` runs in the helper (forked at the start, it keeps its state from job to job)
    and returns a plain value; ``send(job)`` makes the payload in this process when the job goes to the
    helper (what it lacks), and ``receive(job, value)`` takes the helper's value here.
    ``pick(ready, last)`` chooses among the ready jobs for a core whose last job was ``last``.
    Without fork (or with PENDSYM_WORKERS=1) every job runs here, in the order of ``jobs``.
    Returns {job: "here" | "there"}."""
    where: dict[str, str] = {}
    if not can_fork():
        for j in jobs:
            here(j, lambda: None)
            where[j] = "here"
        return where
    ctx = multiprocessing.get_context("fork")
    conn, child_end = ctx.Pipe(duplex=True)
    parent = os.getpid()

    def serve():
        _die_with_parent(parent)
        _ignore_sigint()
        conn.close()
        while True:
            msg = child_end.recv()
            if msg is None:
                return
            try:
                child_end.send((True, there(*msg)))
            except BaseException as exc:  # reported in the parent
                child_end.send((False, f"{type(exc).__name__}: {exc}"))
                return
    proc = ctx.Process(target=serve, daemon=True)
    with _sigint_held():
        proc.start()
    child_end.close()
    done: set = set()
    started: set = set()
    state = {"there": None, "last_there": None, "last_here": None}

    def ready() -> list:
        return [j for j in jobs if j not in started and after[j] <= done]

    def dispatch() -> None:
        if state["there"] is None:
            r = ready()
            if r:
                j = pick(r, state["last_there"])
                started.add(j)
                conn.send((j, send(j)))
                state["there"] = j

    def collect(block: bool) -> None:
        j = state["there"]
        if j is None or not (block or conn.poll()):
            return
        try:
            ok, value = conn.recv()
        except EOFError:
            raise RuntimeError("the build helper died") from None
        if not ok:
            raise RuntimeError(f"the build helper failed on {j}: {value}")
        receive(j, value)
        done.add(j)
        where[j] = "there"
        state["there"], state["last_there"] = None, j
        dispatch()

    try:
        while len(done) < len(jobs):
            dispatch()
            r = ready()
            if r:
                j = pick(r, state["last_here"])
                started.add(j)
                here(j, lambda: collect(False))
                done.add(j)
                where[j] = "here"
                state["last_here"] = j
            elif state["there"] is not None:
                collect(True)
            else:
                raise RuntimeError("no job can start: the jobs wait for each other")
        conn.send(None)
        proc.join()
    except BaseException:
        proc.kill()         # Ctrl-C or a failed job: the helper does not outlive this call
        proc.join()
        raise
    finally:
        conn.close()
    return where
