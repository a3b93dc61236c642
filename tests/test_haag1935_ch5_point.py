"""Haag 1935, chapter V (point pendulum, point mass, equal periods, beats): table, derivations, checks."""
import pytest
import sympy as sp

from derivations.haag1935 import MEMOIR, ch5_point
from derivations.haag1935.ch5_point import printed
from derivations.haag1935.symbols import R, v0, w0
from pendsym import checks, stages, verify

P = "haag1935"
IDS = tuple(spec.id for spec in ch5_point.specs())
ENGINE_KINDS = (checks.Values, checks.Order, checks.Inequality, checks.Proof, checks.Chain, checks.Definition,
                checks.All)


def test_ids_are_unique_and_registered():
    assert len(IDS) == len(set(IDS)) == 17
    headed = {i for heading in MEMOIR.report_headings() if heading.title.startswith("Chapter V.") for i in heading.ids}
    assert headed == set(IDS)


def test_every_check_is_a_declaration_of_the_engine():
    for spec in ch5_point.specs():
        assert isinstance(spec.check, ENGINE_KINDS), spec.id
        parts = spec.check.checks if isinstance(spec.check, checks.All) else (spec.check,)
        assert all(isinstance(part, ENGINE_KINDS) for part in parts), spec.id


@pytest.fixture(scope="module")
def built():
    return stages.results(IDS)


@pytest.mark.slow
@pytest.mark.parametrize("rid", ["eq198.roots", "eq199.n2p", "eq200.n2", "eq200.thread", "eq201.n2", "eq201.elastic",
                                 "eq202.a0", "eq206.n0", "eq208.quadratic", "eq209.n2", "eq209.F", "eq210.f",
                                 "eq211.rho", "eq198.dR"])
def test_printed_matches_derived(built, rid):
    r = built[f"{P}.{rid}"]
    assert verify.compare_forms(r.printed_value, r.derived_value, r.id)[0] == "match"


@pytest.mark.slow
@pytest.mark.parametrize("rid, fix", [
    ("eq203.motion", lambda expr: expr.subs(sp.Symbol("v_0", real=True), sp.Symbol("w_0", real=True))),
    ("eq205.R0", lambda expr: expr.subs(sp.Symbol("v_0", positive=True), sp.Symbol("w_0", positive=True))),
    ("eq207.rho", lambda expr: expr.xreplace({R**2: -R**2}))])
def test_discrepancies_the_eigenproblem_decides(built, rid, fix):
    """(204)–(205) print ν0 where w0 is derived; (207) prints +R² where (30) has −R²."""
    r = built[f"{P}.{rid}"]
    assert verify.compare_forms(r.printed_value, r.derived_value, r.id)[0] == "discrepancy"
    ev = stages.assessed(r)[1]
    assert ev.passed and ev.printed_agrees is False
    assert verify.compare_forms(fix(r.printed_value), r.derived_value, r.id)[0] == "match"


@pytest.mark.slow
def test_all_checks_pass_quick(built):
    own = [built[i] for i in IDS if not isinstance(built[i].spec.check, checks.Chain)]
    failed = [r.id for r in own if not stages.assessed(r)[1].passed]
    assert failed == []


@pytest.mark.slow
def test_beat_frequency_is_checked_in_the_time_domain(built):
    r = built[f"{P}.eq210.f"]
    ev = stages.assessed(r)[1]
    assert "time domain" in ev.truth and ev.passed and abs(ev.order - 2) < 0.3


def test_printed_204_reads_v0():
    assert printed.decoupled_motion()[1].has(v0) and not printed.decoupled_motion()[1].has(w0)
