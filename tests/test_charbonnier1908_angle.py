"""derivations.charbonnier1908.angle: n°18–20, φ(θ), the monomial θ^m and J_m."""
import pytest
import sympy as sp

from derivations.charbonnier1908 import angle
from derivations.charbonnier1908.common import rid
from derivations.charbonnier1908.symbols import alpha, k, m, y
from pendsym import checks, stages


@pytest.fixture(scope="module")
def built():
    return stages.results([rid(18, "Es_theta"), rid(20, "theorem"), rid(20, "dT"), rid(19, "dalpha")])


def test_monomial_E_s_for_m_2_is_the_printed_form():
    derived = angle.Es_monomial({}).subs(m, 2)
    assert sp.simplify(derived - angle.PRINTED["Es"].subs(m, 2)) == 0


def test_J_m_at_pi_closed_form_and_even_reflection():
    assert angle.J_pi_closed({}).subs(m, 3) == 3 * sp.pi / 8
    assert angle.J_even_zero({}) == -1
    assert angle.J_pi_induction({}) == 0


def test_amplitude_and_duration_never_change_together(built):
    assert built[rid(20, "theorem")].derived == sp.Tuple(0, 0)


def test_monomial_changes(built):
    eps = sp.Symbol("epsilon", real=True)
    dT = built[rid(20, "dT")].derived.subs(m, 3)
    assert sp.simplify(dT + eps * alpha**2 / k**3 * 3 * sp.pi / 8) == 0
    dalpha = built[rid(19, "dalpha")].derived.subs(m, 2)
    assert sp.simplify(dalpha + 2 * eps * alpha**2 / (3 * k**2)) == 0


def test_n18_check_passes_on_the_derived_form(built):
    result = built[rid(18, "Es_theta")]
    assert result.spec.check is angle.n18_check and stages.assessed(result)[1].passed


def test_proof_of_can_fail():
    proof = angle.proof_of(0)
    assert proof.holds(sp.sin(y) ** 2 + sp.cos(y) ** 2 - 1)
    assert not proof.holds(sp.sin(y))


def test_monomial_order_check_takes_one_check_per_m():
    assert isinstance(angle.RECURRENCE_CHECK, checks.All)
    assert len(angle.monomial_order_check("dT", (1, 3, 5)).checks) == 3
