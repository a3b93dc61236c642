"""derivations.cellerier.static_support: δ = Kmgh/(2l²) for the static support."""
import sympy as sp

from derivations.cellerier import static_support
from derivations.cellerier.symbols import K, alpha, g, h, l, m, theta
from pendsym import checks, stages


def test_delta_static_and_its_steps():
    built = stages.results(["cellerier.delta_static"])
    assert sp.simplify(built["cellerier.delta_static"].derived - K * m * g * h / (2 * l**2)) == 0
    assert sp.simplify(built["cellerier.y1dd"].derived - static_support.PRINTED["y1dd"]) == 0
    assert built["cellerier.Q_leading"].derived == m * g * h / l * theta


def test_first_degree_can_fail():
    assert static_support.is_first_degree(m * g * h / l * theta)
    assert not static_support.is_first_degree(theta + theta * alpha)


def test_the_radical_error_for_two_degrees():
    built = stages.results(["cellerier.radical_error"])
    assert abs(float(built["cellerier.radical_error"].derived) - 1.5230e-4) < 1e-7


def test_sin_theta_check_passes():
    built = stages.results(["cellerier.sin_theta"])
    assert stages.assessed(built["cellerier.sin_theta"])[1].passed


def test_delta_static_check_fits_in_K():
    assert isinstance(static_support.DELTA_STATIC_CHECK, checks.Order)
    assert static_support.DELTA_STATIC_CHECK.param == "K" and static_support.DELTA_STATIC_CHECK.expected == 2
