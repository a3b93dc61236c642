"""derivations.cellerier.practical: δ from a test force and the worked example."""
import sympy as sp

from derivations.cellerier import practical
from derivations.cellerier.symbols import eps
from pendsym import checks, stages


def test_the_worked_example():
    built = stages.results(["cellerier.eps_bound"])
    assert sp.simplify(built["cellerier.delta_practical"].derived - practical.PRINTED["delta_practical"]) == 0
    assert sp.simplify(built["cellerier.example_delta"].derived - eps / 3) == 0
    assert sp.simplify(built["cellerier.g_error"].derived - 2 * eps / 3) == 0
    assert built["cellerier.eps_bound"].derived == sp.Rational(3, 200)


def test_the_example_is_checked_in_epsilon():
    assert isinstance(practical.EXAMPLE_CHECK, checks.Order) and practical.EXAMPLE_CHECK.param == "epsilon"
