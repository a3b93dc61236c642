"""A memoir is a plug-in: a toy package that lives in the tests is discovered, derived and checked
with no edit to pendsym/ (issue 9, point 1)."""
import json

import pytest
import sympy as sp

from pendsym import derive, pipeline, registry
from pendsym.result import Result


@pytest.fixture()
def toy(monkeypatch, tmp_path):
    monkeypatch.setenv("PENDSYM_MEMOIR_PACKAGES", "toy_memoirs")
    monkeypatch.setenv("PENDSYM_CACHE", str(tmp_path / "cache"))
    return tmp_path


def test_the_toy_is_discovered(toy):
    assert list(registry.memoirs()) == ["toy"]
    assert [s.id for s in registry.memoir_specs("toy")] == ["toy.T0", "toy.T"]


def test_the_toy_derives_and_checks(toy):
    outcome = derive.derive_all(toy / "out", level="quick", log=lambda m: None)
    assert outcome.failed == ()
    data = json.loads((toy / "out" / "results.json").read_text())["results"]
    by_id = {r["id"]: r for r in data}
    assert by_id["toy.T0"]["status"] == "match" and by_id["toy.T0"]["verified"]
    assert by_id["toy.T"]["evidence"]["kind"] == "order"
    assert abs(by_id["toy.T"]["evidence"]["order"] - 4) < 0.3
    assert (toy / "out" / "tex" / "toy.tex").exists()
    again = derive.derive_all(toy / "out", level="quick", log=lambda m: None)
    assert again.nothing_changed


def test_a_wrong_formula_fails_its_check(toy):
    right = registry.build(["toy.T"])["toy.T"]
    wrong = Result(spec=right.spec, derived=right.derived * sp.Rational(1001, 1000), printed=None, deps=right.deps)
    assert pipeline.check(right, "quick").passed
    assert not pipeline.check(wrong, "quick").passed
