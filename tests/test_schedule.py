"""pendsym.schedule: forked workers give the same answers, in the same order, as a serial run."""
from pendsym import schedule


def _square(x):
    return x * x


def test_per_result_matches_serial(monkeypatch):
    data = {f"r{i}": i for i in range(7)}
    ids = sorted(data, reverse=True)
    monkeypatch.setenv("PENDSYM_WORKERS", "2")
    par = schedule.per_result(data, ids, _square)
    monkeypatch.setenv("PENDSYM_WORKERS", "1")
    ser = schedule.per_result(data, ids, _square)
    assert par == ser == [data[i] ** 2 for i in ids]


def test_a_progress_that_raises_ends_the_call_with_its_error(monkeypatch):
    """progress runs in the caller's thread: when it raises (a progress line written to a closed pipe), the
    error reaches the caller.  As a pool callback it killed the pool's result thread and the call waited
    forever (a derive piped into a reader that went away hung)."""
    import threading

    def broken(_rid):
        raise BrokenPipeError("the reader went away")
    monkeypatch.setenv("PENDSYM_WORKERS", "2")
    data = {f"r{i}": i for i in range(5)}
    outcome = []

    def run():
        try:
            schedule.per_result(data, list(data), _square, progress=broken)
        except BrokenPipeError as exc:
            outcome.append(exc)
    worker = threading.Thread(target=run, daemon=True)
    worker.start()
    worker.join(timeout=30)
    assert not worker.is_alive() and len(outcome) == 1


def test_progress_names_every_id_once(monkeypatch):
    monkeypatch.setenv("PENDSYM_WORKERS", "2")
    data = {f"r{i}": i for i in range(9)}
    seen = []
    assert schedule.per_result(data, list(data), _square, progress=seen.append) == [i * i for i in range(9)]
    assert sorted(seen) == sorted(data)


def test_workers_env(monkeypatch):
    monkeypatch.setenv("PENDSYM_WORKERS", "3")
    assert schedule.workers() == 3
    monkeypatch.setenv("PENDSYM_WORKERS", "0")
    assert schedule.workers() == 1


def test_affinity_groups_run_as_one_job_in_order():
    ids = ["a", "b", "c", "d", "e"]
    jobs = schedule.jobs_by_affinity(ids, [("b", "d"), ("c", "zz")])
    assert jobs == [("a",), ("b", "d"), ("c",), ("e",)]     # a group with an absent member is split


def test_overlapping_groups_are_one_job_and_no_id_runs_twice():
    ids = ["a", "b", "c", "d", "e"]
    jobs = schedule.jobs_by_affinity(ids, [("d", "b"), ("e", "d"), ("a",)])
    assert jobs == [("a",), ("b", "d", "e"), ("c",)]
    assert sorted(i for job in jobs for i in job) == ids


def test_dag_jobs_group_items_and_merge_groups_that_wait_for_each_other():
    # a1 → b1 → a2: groups a and b depend on each other, so they are one job; c waits for it
    order = ["a1", "b1", "a2", "c1", "d1"]
    group = {"a1": "a", "b1": "b", "a2": "a", "c1": "c", "d1": "d"}
    deps = {"a1": (), "b1": ("a1",), "a2": ("b1",), "c1": ("a2",), "d1": ()}
    jobs, after = schedule.dag_jobs(order, group, deps)
    assert jobs == {"a": ("a1", "b1", "a2"), "c": ("c1",), "d": ("d1",)}
    assert after == {"a": frozenset(), "c": frozenset({"a"}), "d": frozenset()}


def test_dag_jobs_order_puts_each_job_after_those_it_waits_for():
    order = ["x1", "y1", "z1", "y2"]
    group = {"x1": "x", "y1": "y", "z1": "z", "y2": "y"}
    deps = {"x1": (), "y1": (), "z1": ("x1",), "y2": ("z1",)}
    jobs, after = schedule.dag_jobs(order, group, deps)
    names = list(jobs)
    assert names == ["x", "z", "y"] and after["y"] == {"z"} and after["z"] == {"x"}


def test_critical_rank_is_the_heaviest_chain_from_a_job():
    jobs = {"a": (), "b": (), "c": (), "d": ()}
    after = {"a": frozenset(), "b": frozenset({"a"}), "c": frozenset({"a"}), "d": frozenset({"c"})}
    weight = {"a": 1.0, "b": 10.0, "c": 2.0, "d": 3.0}
    rank = schedule.critical_rank(jobs, after, weight.__getitem__)
    assert rank == {"a": 11.0, "b": 10.0, "c": 5.0, "d": 3.0}


def _dag_run(monkeypatch, workers: str, fail_there: str | None = None):
    """A DAG a → (b, c) → d whose jobs add up what they are sent: every job sees its dependencies' values,
    wherever they ran."""
    monkeypatch.setenv("PENDSYM_WORKERS", workers)
    jobs = ["a", "b", "c", "d"]
    after = {"a": frozenset(), "b": frozenset({"a"}), "c": frozenset({"a"}), "d": frozenset({"b", "c"})}
    value = {"a": 1, "b": 10, "c": 100, "d": 1000}
    here_values: dict = {}
    log: list = []

    def total(job, known):
        return value[job] + sum(known[d] for d in after[job])

    def here(job, poll):
        here_values[job] = total(job, here_values)
        poll()

    def there(job, payload):
        if job == fail_there:
            raise ValueError("no")
        return total(job, payload)

    def send(job):
        return {d: here_values[d] for d in after[job]}

    def receive(job, v):
        here_values[job] = v

    def pick(ready, last):
        log.append((tuple(ready), last))
        return ready[0]
    where = schedule.over_dag(jobs, after, here, there, send, receive, pick)
    return here_values, where


def test_over_dag_gives_the_serial_values_on_two_cores(monkeypatch):
    serial, where1 = _dag_run(monkeypatch, "1")
    parallel, where2 = _dag_run(monkeypatch, "2")
    assert serial == parallel == {"a": 1, "b": 11, "c": 101, "d": 1112}
    assert set(where1.values()) == {"here"}
    assert "there" in where2.values() and set(where2) == {"a", "b", "c", "d"}


def test_over_dag_reports_the_helpers_failure(monkeypatch):
    import pytest
    with pytest.raises(RuntimeError, match="ValueError: no"):
        _dag_run(monkeypatch, "2", fail_there="a")


def test_kernels_are_formed_largest_form_first():
    """stages.by_size: the pool's last jobs (its kernels) go largest derived form first, ties in the given order."""
    from types import SimpleNamespace

    import sympy as sp

    from pendsym import stages
    x, y = sp.symbols("x y")
    forms = {"small": x, "large": sp.sin(x) * sp.exp(y) + x**3, "tie_a": x + y, "tie_b": x * y + 0}
    built = {i: SimpleNamespace(derived=f) for i, f in forms.items()}
    got = stages.by_size(["small", "tie_a", "large", "tie_b"], built)
    assert got[0] == "large" and got[-1] == "small"
    assert sorted(got) == sorted(forms)
    sizes = [len(sp.srepr(forms[i])) for i in got]
    assert sizes == sorted(sizes, reverse=True)
