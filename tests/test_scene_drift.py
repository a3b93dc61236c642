"""derivations/charbonnier1908/scene_drift.py: the growing length's swing, the model of truth.py."""
import mpmath as mp
import pytest
import sympy as sp

from derivations.charbonnier1908 import scene_drift, truth
from derivations.charbonnier1908.symbols import a, dtheta, k, l0, t, theta


def test_the_right_hand_side_is_truths_governing_model():
    law, restoring, params = truth.LAWS["growing"]
    assert params == (a,) and restoring == theta
    dd = scene_drift.theta_ddot(t, theta, dtheta, k, a)
    ldot = sp.diff(law, t) + sp.diff(law, theta) * dtheta       # l does not involve θ'
    residual = dd + 2 / law * ldot * dtheta + k**2 * l0 / law * theta
    assert sp.simplify(residual) == 0


@pytest.mark.slow
def test_the_swing_time_is_truths():
    T = scene_drift.swing_time("0.05", "3.1", 20, "0.002")
    with mp.workdps(20):
        want = truth.swing("growing", "0.05", "3.1", 20, a="0.002").T
        assert abs(T - want) < mp.mpf(10) ** -18 * want
