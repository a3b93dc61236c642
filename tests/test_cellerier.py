"""Cellérier, the memoir as a whole: every Result is located in the text, the finding on F, the
definitions, and every check passes at full level (as make derive runs it)."""
import pytest

from derivations.cellerier import common
from pendsym import checks, pipeline, registry, stages

SPECS = registry.all_specs(["cellerier"])
CHECKED = sorted(i for i, s in SPECS.items() if s.check is not None)
INCIPITS = {f"« {words} … »" for words in common.PARAGRAPHS.values()}


@pytest.fixture(scope="module")
def built():
    return stages.results(memoirs=["cellerier"])


def test_every_result_has_a_check():
    assert sorted(SPECS) == CHECKED


def test_every_result_stands_under_a_paragraph_of_the_text_and_quotes_it():
    for spec in SPECS.values():
        assert spec.source.para in INCIPITS, spec.id
        assert spec.source.page is None, spec.id          # the OCR text shows no page number
        assert spec.source.quote and "(p. " not in spec.source.quote, spec.id


def test_every_paragraph_of_the_table_holds_a_result():
    assert {s.source.para for s in SPECS.values()} == INCIPITS


def test_the_definitions():
    assert {i for i, s in SPECS.items() if s.definition} == {"cellerier.rho_cn"}
    assert isinstance(SPECS["cellerier.rho_cn"].check, checks.Definition)


def test_the_only_discrepancy_is_the_sign_of_F(built):
    statuses = {r.id: pipeline.compare(r)[0] for r in built.values()}
    assert sorted(i for i, s in statuses.items() if s == "discrepancy") == ["cellerier.F"]


@pytest.mark.slow
@pytest.mark.parametrize("rid", [i for i in CHECKED if not isinstance(SPECS[i].check, checks.Chain)])
def test_check_passes(built, rid):
    ev = stages.assessed(built[rid])[1]
    assert ev.passed, ev


@pytest.mark.slow
@pytest.mark.parametrize("rid", [i for i in CHECKED if isinstance(SPECS[i].check, checks.Chain)])
def test_a_step_passes_through_the_results_it_feeds(built, rid):
    chain = SPECS[rid].check
    assert stages.assessed(built[rid])[1] is None          # a step has no check of its own
    ev = checks.chained(chain, {d: stages.assessed(built[d])[1] for d in chain.downstream})
    assert ev.kind == "chain" and ev.passed, ev
