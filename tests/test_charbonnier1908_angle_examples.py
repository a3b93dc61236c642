"""derivations.charbonnier1908.angle_examples: n°21–23."""
import sympy as sp

from derivations.charbonnier1908 import angle_examples
from derivations.charbonnier1908.symbols import beta, l0, theta, y
from pendsym import stages


def test_J3_by_the_recurrence_is_the_printed_one():
    assert sp.simplify(angle_examples.J3_derived({}) - angle_examples.J3_printed()) == 0
    assert sp.simplify(sp.diff(angle_examples.J3_derived({}), y) - sp.cos(y) ** 4) == 0


def test_the_winding_thread_length_is_free_of_A1():
    length = angle_examples.winding_length({})
    assert not length.has(angle_examples.A1)
    assert sp.simplify(length - l0 * (1 - sp.Rational(4, 9) * beta * theta**2)) == 0


def test_winding_length_check_passes():
    built = stages.results(["charbonnier1908.n22.l"])
    ev = stages.assessed(built["charbonnier1908.n22.l"])[1]
    assert ev.passed and abs(ev.order - 3) < 0.3


def test_isochronous_curve():
    built = stages.results(["charbonnier1908.n23.q"])
    assert built["charbonnier1908.n23.q"].derived == sp.Rational(1, 2)
