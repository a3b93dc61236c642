"""derivations.cellerier.equation: the rigid body on a moving knife edge."""
import pytest
import sympy as sp

from derivations.cellerier import equation
from derivations.cellerier.symbols import C, g, h, l, m, mu_p, theta, thetad, thetadd, x1dd, x1s, y1dd, y1s
from pendsym import stages


def test_the_pressures_of_the_first_two_equations():
    P, Q = equation.pressures_exact()
    assert sp.simplify(P + m * (x1dd - h * sp.sin(theta) * thetadd - h * sp.cos(theta) * thetad**2)) == 0
    assert sp.simplify(Q + m * (y1dd + h * sp.cos(theta) * thetadd - h * sp.sin(theta) * thetad**2)) == 0


def test_the_pivot_position_cancels_from_the_moment_equation():
    acceleration = equation.theta_ddot()
    assert not acceleration.has(x1s) and not acceleration.has(y1s)
    assert sp.simplify(C * acceleration + m * g * h * sp.sin(theta) - equation.mu_prime_printed()) == 0
    assert sp.simplify(equation.mu_prime_derived({}) - equation.mu_prime_printed()) == 0


def test_body_sums_need_only_the_polar_moment():
    with pytest.raises(ValueError):
        equation.body_sum(equation.xi**3)
    assert equation.body_sum(equation.xi**2 + equation.eta**2) == C


def test_the_equation_in_l():
    built = stages.results(["cellerier.equation_l"])
    result = built["cellerier.equation_l"]
    assert sp.simplify(result.derived - (-g / l * sp.sin(theta) + mu_p / (m * h * l))) == 0


def test_newton_check_of_mu_prime():
    built = stages.results(["cellerier.mu_prime"])
    ev = stages.assessed(built["cellerier.mu_prime"])[1]
    assert ev.passed and ev.max_residual < 1e-20
