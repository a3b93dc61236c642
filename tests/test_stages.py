"""pendsym.stages: the output is validated before any work; the summary names every failure."""
import pytest

from pendsym import stages
from pendsym.pipeline import Record
from pendsym.result import Evidence, Result, Source, Spec


@pytest.mark.parametrize("make", [
    lambda tmp: tmp / "file",                 # a file, not a directory
    lambda tmp: tmp / "ro" / "sub",           # under a directory that cannot be written
])
def test_output_dir_refuses_what_cannot_be_written(tmp_path, make):
    (tmp_path / "file").write_text("x")
    (tmp_path / "ro").mkdir(mode=0o500)
    target = make(tmp_path)
    import os
    if os.geteuid() == 0 and target.parent.name == "ro":
        pytest.skip("root writes everywhere")
    with pytest.raises(stages.OutputError):
        stages.output_dir(target)


def test_output_dir_under_proc_is_refused():
    with pytest.raises(stages.OutputError):
        stages.output_dir("/proc/pendsym-x")


def _record(rid, passed, definition=False):
    spec = Spec(id=rid, title=rid, source=Source("m", "n°1"), lhs="x", derive=lambda d: 0, definition=definition)
    ev = Evidence(kind="value", passed=passed, truth="model", max_residual=0.5)
    return Record(Result(spec=spec, derived=0), "match", "", ev)


def test_summary_counts_and_names_failures():
    recs = [_record("m.a", True), _record("m.b", False), _record("m.c", True, definition=True)]
    lines = stages.summary(recs)
    assert lines[0].startswith("3 results: 1 verified, 1 failed, 1 definitions")
    assert len(lines) == 2 and lines[1].startswith("FAILED m.b")
    assert [r.result.id for r in stages.failures(recs)] == ["m.b"]


def test_results_and_assessed_are_make_derives_own_work(tmp_path, monkeypatch):
    """A test reads what make derive computed (same keys), and computes it when it is missing."""
    monkeypatch.setenv("PENDSYM_CACHE", str(tmp_path / "cache"))
    rid = "cellerier.mu_prime"
    first = stages.results([rid])
    assert rid in first and all(d in first for d in first[rid].spec.deps)
    entries = sorted(p for p in (tmp_path / "cache").rglob("*") if p.is_file())
    assert entries, "the built forms were not cached"
    again = stages.results([rid])
    assert again[rid].derived == first[rid].derived
    (how, evidence) = stages.assessed(first[rid])
    assert how == stages.assessed(again[rid])[0]
    assert evidence is None or evidence.passed
    assert len(sorted(p for p in (tmp_path / "cache").rglob("*") if p.is_file())) > len(entries)
