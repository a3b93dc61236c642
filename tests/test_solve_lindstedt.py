"""Lindstedt–Poincaré against the issue's coefficients (independent of this code) and against
the problem's own equation integrated by mpmath, with the fitted order."""

import pytest
import sympy as sp

from pendsym.solve import from_dict, solve
from pendsym.solve import frequency

eps = sp.Symbol("eps", positive=True)


def duffing(**over):
    data = {"variable": "u", "small": "eps", "phi": "eps*u**3", "order": 3,
            "initial": {"value": "A"}, "parameters": {"A": 0.5}}
    data.update(over)
    return from_dict(data)


def test_duffing_order_3_frequency():
    ans = frequency.solve(duffing())
    A = sp.Symbol("A", real=True)
    want = 1 + 3 * eps * A**2 / 8 - 21 * eps**2 * A**4 / 256 + 81 * eps**3 * A**6 / 2048
    assert sp.expand(ans.omega - want) == 0


def test_pendulum_period_to_alpha_10():
    pr = from_dict({"small": "alpha", "phi": "sin(theta) - theta", "order": 10, "initial": {"value": "alpha"}})
    ans = frequency.solve(pr)
    al = sp.Symbol("alpha", positive=True)
    coeffs = [sp.Rational(1, 16), sp.Rational(11, 3072), sp.Rational(173, 737280),
              sp.Rational(22931, 1321205760), sp.Rational(1319183, 951268147200)]
    want = 2 * sp.pi * (1 + sum(c * al**(2 * i + 2) for i, c in enumerate(coeffs)))
    assert sp.expand(ans.period - want) == 0


def test_k_not_one_is_not_one():
    """u'' + 4u + εu³: ω starts at 2 (a peer returns ω = 2 for the whole series)."""
    ans = frequency.solve(from_dict({"variable": "u", "small": "eps", "k": "2", "phi": "eps*u**3", "order": 2,
                                     "initial": {"value": "A"}, "parameters": {"A": 0.5}}))
    A = sp.Symbol("A", real=True)
    assert sp.expand(ans.omega.coeff(eps, 1) - 3 * A**2 / 16) == 0


@pytest.mark.slow
@pytest.mark.parametrize("over, order", [
    ({}, 4),
    ({"k": "2", "order": 2}, 3),
    ({"order": 2, "initial": {"value": "A", "velocity": "B"}, "parameters": {"A": 0.5, "B": 0.3}}, 3),
])
def test_duffing_family_fitted_order_against_integration(over, order):
    sol = solve(duffing(**over))
    ev = sol.answers[0].evidence
    assert ev.passed and abs(ev.order - order) < 0.35, ev
    assert sol.verified


@pytest.mark.slow
def test_a_wrong_frequency_fails_the_check():
    """The check can fail: ω without its ε³ term has residual order 3, not 4."""
    from pendsym.solve import verify as truth
    pr = duffing()
    ans = frequency.solve(pr)
    wrong = sp.expand(ans.omega - ans.omega.coeff(eps, 3) * eps**3)
    f = sp.lambdify(eps, wrong.subs(pr.values()), modules="mpmath")
    ev = truth.fitted(pr, truth=truth.frequency_truth(pr), answer=f, expected=4, what="ω")
    assert not ev.passed and abs(ev.order - 3) < 0.35


def test_damping_is_not_a_frequency():
    pr = from_dict({"small": "eps", "phi": "eps*dtheta", "order": 2, "initial": {"value": "1"},
                    "method": "lindstedt"})
    from pendsym.solve import ProblemError
    with pytest.raises(ProblemError, match="not removable by a frequency"):
        solve(pr, verify=False)


@pytest.mark.slow
def test_pendulum_period_fitted_order_12_against_integration():
    from pathlib import Path
    sol = solve(Path(__file__).resolve().parents[1] / "problems" / "pendulum.toml")
    ev = sol.answers[0].evidence
    assert ev.passed and abs(ev.order - 12) < 0.35, ev
