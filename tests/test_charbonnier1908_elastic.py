"""derivations.charbonnier1908.elastic: n°24–26, the elastic thread."""
import sympy as sp

from derivations.charbonnier1908 import elastic
from derivations.charbonnier1908.symbols import DEFS, T, alpha, k, mu, t
from pendsym import stages


def test_the_second_order_length_is_the_printed_one():
    derived = elastic.ratio_derived({})
    assert sp.simplify(derived - elastic.ratio_printed().subs(DEFS)) == 0


def test_along_the_motion_and_its_rate():
    built = stages.results(["charbonnier1908.n25.rate"])
    along = built["charbonnier1908.n24.l_ratio_t"].derived
    assert sp.simplify(along - elastic.ratio_along_printed().subs(DEFS)) == 0
    assert sp.simplify(built["charbonnier1908.n25.rate"].derived - sp.diff(along, t)) == 0


def test_the_swing_is_longer_by_eleven_sixteenths():
    built = stages.results(["charbonnier1908.n26.dT"])
    dT = built["charbonnier1908.n26.dT"].derived
    assert sp.simplify(dT - sp.Rational(11, 16) * mu / (1 + mu) * alpha**2 * sp.pi / k) == 0
    assert elastic.N24.printed["dT"].has(T)
