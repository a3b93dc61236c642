"""derivations.charbonnier1908.variable_length: n°27–35, the growing pendulum."""
import mpmath as mp
import pytest
import sympy as sp

from derivations.charbonnier1908 import variable_length
from derivations.charbonnier1908.symbols import a, alpha, k, l0, t
from pendsym import checks, stages

LAW = "charbonnier1908.n27.l"


@pytest.fixture(scope="module")
def built():
    return stages.results([LAW, "charbonnier1908.n28.eom", "charbonnier1908.n35.curve", "charbonnier1908.n35.tangent_E"])


def test_n27_states_the_law_as_a_definition(built):
    spec = built[LAW].spec
    assert spec.definition and isinstance(spec.check, checks.Definition)
    assert (spec.source.para, spec.source.page) == ("n°27", 233)
    assert built[LAW].derived == l0 * (1 + a * t)
    ev = stages.assessed(built[LAW])[1]
    assert ev.kind == "definition" and ev.passed


def test_the_law_feeds_the_equation_of_n28_and_the_length_at_C(built):
    assert LAW in built["charbonnier1908.n28.eom"].spec.deps
    assert built["charbonnier1908.n35.l_C"].derived == l0 * (1 + 2 * sp.pi * a / k)


def test_the_curve_of_C_and_the_slope_at_E(built):
    omega = sp.Symbol("omega", positive=True)
    curve = built["charbonnier1908.n35.curve"].derived
    assert sp.simplify(curve - (l0 + sp.Rational(4, 3) * l0 * sp.log(alpha / omega))) == 0
    assert sp.simplify(curve - variable_length.PRINTED["curve"]) != 0       # the memoir's 2/3 is a slip
    assert sp.simplify(built["charbonnier1908.n35.tangent_E"].derived - a / (k * alpha)) == 0


def test_the_first_point_C_of_the_integrated_model():
    (length, angle), = variable_length.C_points(mp.mpf("1e-3"), 20, 1)
    with mp.workdps(20):
        assert abs(length - (1 + 2 * mp.mpf("1e-3") * mp.pi / mp.mpf("1.3"))) < mp.mpf("1e-4")
        assert angle < mp.mpf("0.3")                       # the amplitude shrinks as the cable grows
