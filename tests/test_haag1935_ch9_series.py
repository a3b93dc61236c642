"""Haag 1935, chapter IX: the rhombus hole as a series in k (ch9_holes.rhombus_series)."""
import mpmath as mp
import sympy as sp

from derivations.haag1935.ch9_holes import limits, rhombus_series as series, rhombus_truth as truth
from pendsym import verify


def test_zeroth_order_is_the_uniform_blade():
    for name in ("v0", "w0", "wl"):
        assert verify.numeric_difference(series.end_series(name, 0), limits.uniform(name), name) < 1e-40


def test_first_order_beats_zeroth_order_against_the_shot():
    case = ("1/2", "1/1000", "6/5")
    sol = truth.shot(*case, 30)
    env = truth.environment(*case)
    with mp.workdps(40):
        G2 = truth.G2(sol)
        first = abs(verify.value_at(series.G2_series(1), env) - G2)
        zeroth = abs(verify.value_at(series.G2_series(1).subs(series.k, 0), env) - G2)
    assert first < mp.mpf("1e-6") < zeroth
    assert first < zeroth * mp.mpf("1e-2")


def test_series_is_polynomial_in_k():
    assert sp.Poly(sp.expand(series.end_series("w0", 1)), series.k).degree() == 1


def test_the_G2_series_has_one_form_whatever_was_computed_before():
    """integrate's form follows the state of SymPy's caches; the Result's form must not (a derive that
    finds other Results in its cache computes this one after different work)."""
    first = series.G2_series(1)
    series.end_series("w0", 1), series.end_series("v0", 1)
    series.terms.cache_clear()
    assert sp.srepr(series.G2_series(1)) == sp.srepr(first)
    assert series.one_form(first) == first
