"""Resonance is detected and said; the slow flow replaces a per-swing answer; it is checked by
its fitted order against the problem's own equation."""
import pytest
import sympy as sp

from pendsym.solve import from_dict, solve
from pendsym.solve import averaging, secular

PARAMETRIC = {"small": "eps", "k": "2", "phi": "eps*theta*cos(2*k*t)", "initial": {"value": "0.1"}}
FORCED = {"small": "eps", "k": "2", "phi": "-eps*cos(k*t)", "initial": {"value": "0.1"}}


@pytest.mark.parametrize("data, kind", [
    (PARAMETRIC, "parametric"),
    (FORCED, "forcing"),
    ({**FORCED, "phi": "-eps*cos((k + eps)*t)"}, "forcing"),
    ({**FORCED, "phi": "-eps*cos(2.05*t)"}, "forcing"),
    ({**FORCED, "phi": "-eps*cos(3*t)"}, "far"),
    ({**FORCED, "phi": "eps*theta**3"}, "none"),
    ({**PARAMETRIC, "phi": "eps*t*theta"}, "slow"),
])
def test_classification(data, kind):
    found = secular.classify(from_dict(data))
    assert found.kind == kind
    assert "\n" not in found.line
    assert found.resonant == (kind in ("parametric", "forcing"))


def test_parametric_slow_flow_grows_at_rate_eps_over_4k():
    """The classical instability rate of θ'' + k²θ + εθ cos 2kt is ε/(4k)."""
    flow = averaging.slow_flow(from_dict(PARAMETRIC))
    a, b = flow.variables
    eps = sp.Symbol("eps", positive=True)
    jac = sp.Matrix([[sp.diff(r, v) for v in (a, b)] for r in flow.rates])
    assert set(jac.eigenvals()) == {eps / 8, -eps / 8}


def test_forced_resonance_slow_flow_is_linear_growth():
    """θ'' + k²θ = ε cos kt grows like (ε t / 2k) sin kt: b' = ε/(2k)."""
    flow = averaging.slow_flow(from_dict(FORCED))
    eps = sp.Symbol("eps", positive=True)
    assert flow.rates == (0, eps / 4)


def test_resonance_gives_no_per_swing_answer():
    sol = solve(PARAMETRIC, verify=False)
    names = [a.name for a in sol.answers]
    assert not any("swing" in n or "Δ" in n for n in names)
    assert sol.finding.startswith("secular: parametric resonance")
    assert sol.verified is None and "NOT VERIFIED" in sol.report()


@pytest.mark.slow
@pytest.mark.parametrize("data", [PARAMETRIC, FORCED])
def test_slow_flow_fitted_order_one(data):
    sol = solve(data)
    ev = [a.evidence for a in sol.answers if a.evidence is not None]
    assert len(ev) == 1 and ev[0].passed and abs(ev[0].order - 1) < 0.35, ev
