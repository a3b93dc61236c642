"""derivations.charbonnier1908.general: the rebuilt formulas of n°8–9."""
import pytest
import sympy as sp

from derivations.charbonnier1908 import general
from derivations.charbonnier1908.common import rid
from derivations.charbonnier1908.symbols import E_c, E_s, alpha, eps, k, t
from pendsym import stages


@pytest.fixture(scope="module")
def built():
    return stages.results([rid(9, q) for q in ("dT", "dalpha", "dThalf", "dthetam")])


def test_theta_of_n08_solves_the_perturbed_equation(built):
    # θ'' + k²θ + εφ = 0 with E_s' = φ sin kt, E_c' = φ cos kt: differentiate the derived θ' once more
    th, dth = built[rid(8, "theta")].derived, built[rid(8, "dtheta")].derived
    primes = {sp.Derivative(general.Es_of_t(t), t): general.varphi_of_t * sp.sin(k * t),
              sp.Derivative(general.Ec_of_t(t), t): general.varphi_of_t * sp.cos(k * t)}
    ddth = sp.diff(dth, t).subs(primes)
    residual = sp.expand(ddth + k**2 * th + eps * general.varphi_of_t)
    assert sp.simplify(residual.subs(sp.Derivative(general.varphi_of_t, t), 0)) == 0


@pytest.mark.parametrize("quantity, expected", [
    ("dT", eps / (k**2 * alpha) * E_c(sp.pi)), ("dalpha", -eps / k * E_s(sp.pi)),
    ("dThalf", eps / (k**2 * alpha) * E_c(sp.pi / 2)), ("dthetam", -eps * E_s(sp.pi / 2))])
def test_the_event_formulas_of_n09(built, quantity, expected):
    assert sp.simplify(built[rid(9, quantity)].derived - expected) == 0


def test_to_phase_writes_the_argument_kt():
    assert general.to_phase(general.Es_of_t(sp.pi / k)) == E_s(sp.pi)
