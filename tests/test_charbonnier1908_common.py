"""derivations.charbonnier1908.common: ids, sources, the values of an order check, printed data."""
import mpmath as mp
import sympy as sp

from derivations.charbonnier1908 import common


def test_ids_carry_the_two_digit_paragraph():
    assert common.rid(8, "theta") == "charbonnier1908.n08.theta"
    assert common.rid(27, "l") == "charbonnier1908.n27.l"


def test_source_names_paragraph_and_page():
    source = common.src("n°21 3°", 224)
    assert (source.memoir, source.para, source.page) == ("charbonnier1908", "n°21 3°", 224)
    assert source.ref() == "n°21 3°, p. 224"


def test_geometric_values_follow_the_level():
    quick, full = common.Geometric("1e-4", "1e-2")("quick"), common.Geometric("1e-4", "1e-2")("full")
    assert (len(quick), len(full)) == (4, 6)
    assert abs(quick[0] / mp.mpf("1e-4") - 1) < 1e-14 and abs(quick[-1] / mp.mpf("1e-2") - 1) < 1e-14
    assert abs(quick[1] / quick[0] - quick[3] / quick[2]) < 1e-12          # a geometric progression


def test_printed_data_is_given_back_unchanged():
    x = sp.Symbol("x")
    assert common.printed(x**2 + 1)() == x**2 + 1
