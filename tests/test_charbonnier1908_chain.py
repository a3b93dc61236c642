"""derivations.charbonnier1908.chain: an Example in, its Specs and checks out."""
import mpmath as mp
import pytest
import sympy as sp

from derivations.charbonnier1908 import chain
from derivations.charbonnier1908.angle_examples import N21, N22, N23
from derivations.charbonnier1908.elastic import N24
from derivations.charbonnier1908.symbols import alpha, k, q, theta
from derivations.charbonnier1908.variable_length import N27
from pendsym import checks, stages


def test_ids_and_sources_follow_the_paragraph_of_each_quantity():
    assert N21.id("dT") == "charbonnier1908.n21.dT"
    assert N24.id("eps") == "charbonnier1908.n25.eps" and N24.id("Es") == "charbonnier1908.n26.Es"
    assert (N27.src("dthetam").para, N27.src("dthetam").page) == ("n°34", 237)
    assert N27.src("Es").page == 234                                   # the default page


def test_perturbing_terms_from_the_length_laws():
    assert sp.simplify(chain.eom(N21, {}) + k**2 * theta**3 / 6) == 0           # the second term of sin θ
    P = chain.eom(N23, {})
    assert sp.simplify(chain.eps_derived(P, N23) + q * k**2 * alpha**3) == 0     # n°22's ε with −4β/9 → q


def test_expected_orders():
    assert chain.expected_order(N21, "dT") == 4          # P is cubic in the amplitude
    assert chain.expected_order(N21, "theta") == 5
    assert chain.expected_order(N27, "dT") == 2          # first order in a


def test_an_example_with_a_rate_is_checked_in_the_rate():
    order = chain.order_check_of(N27, "dT")
    assert isinstance(order, checks.Order) and order.param == "a"
    assert ("alpha", "0.3") in order.params
    values = order.values("quick")
    assert len(values) == 4 and abs(values[-1] - mp.mpf("3e-3")) < 1e-15


def test_the_specs_of_an_example():
    ids = {s.id.rsplit(".", 1)[1] for s in chain.specs(N21)}
    assert ids == set(chain.QUANTITIES)
    assert not {"dThalf", "dthetam"} & {s.id.rsplit(".", 1)[1] for s in chain.specs(N22)}


@pytest.fixture(scope="module")
def built():
    return stages.results([N21.id("Es"), N22.id("Es")])


def test_quadrature_check_sides_with_the_derived_E_s(built):
    ev = stages.assessed(built[N21.id("Es")])[1]
    assert ev.passed and ev.printed_agrees is True and ev.kind == "quadrature"
    ev = stages.assessed(built[N22.id("Es")])[1]   # n°22's printed E_s is wrong
    assert ev.passed and ev.printed_agrees is False
