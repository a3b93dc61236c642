"""Cellérier: every Result's independent check passes (quick level)."""
import pytest

from pendsym import registry

RESULTS = registry.build(memoirs=["cellerier"])
CHECKED = sorted(r for r, res in RESULTS.items() if res.spec.check is not None)


@pytest.mark.slow
@pytest.mark.parametrize("rid", CHECKED)
def test_check_passes(rid):
    res = RESULTS[rid]
    ev = res.spec.check(res, "quick")
    assert ev.passed, ev
