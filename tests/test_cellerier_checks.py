"""Cellérier: every Result's independent check passes (full level, as make derive runs it)."""
import pytest

from pendsym import pipeline, registry

SPECS = registry.all_specs(["cellerier"])
CHECKED = sorted(i for i, s in SPECS.items() if s.check is not None)


@pytest.fixture(scope="module")
def built():
    return registry.build(memoirs=["cellerier"])


def test_every_result_has_a_check():
    assert sorted(SPECS) == CHECKED


@pytest.mark.slow
@pytest.mark.parametrize("rid", CHECKED)
def test_check_passes(built, rid):
    ev = pipeline.check(built[rid], "full")
    assert ev.passed, ev
