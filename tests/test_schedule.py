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


def test_background_value_and_failure(monkeypatch):
    monkeypatch.setenv("PENDSYM_WORKERS", "2")
    assert schedule.in_background(_square, 7)() == 49
    import pytest
    with pytest.raises(RuntimeError, match="ZeroDivisionError"):
        schedule.in_background(lambda: 1 / 0)()
