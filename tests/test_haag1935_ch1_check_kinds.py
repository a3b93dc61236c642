"""The check kinds of derivations/haag1935/check_kinds.py on small forms: each passes the right formula and
rejects a wrong one."""
import mpmath as mp
import pytest
import sympy as sp

from derivations.haag1935 import check_kinds, profiles
from derivations.haag1935.check_kinds import Components, Fails, OnShotBlade, TupleDefinition, Vanishes
from derivations.haag1935.common import rid, src
from derivations.haag1935.symbols import M_of_s, lam, s, w
from pendsym.checks import Point
from pendsym.result import Result, Spec

x, y = sp.symbols("x y", real=True)


def result(derived, printed=None) -> Result:
    spec = Spec(rid(999, "test"), "a test form", src("n°0", None), "f", lambda deps: derived,
                printed=None if printed is None else (lambda: printed))
    return Result(spec, derived, printed)


def test_tuple_definition_compares_each_component():
    assert TupleDefinition()(result(sp.Tuple(x, 2 * x), sp.Tuple(x, x + x)), "quick").passed
    assert not TupleDefinition()(result(sp.Tuple(x, 2 * x), sp.Tuple(x, 3 * x)), "quick").passed


def test_components_compare_each_component_with_its_truth():
    def points(truths):
        return lambda level, dps: [(0, Point("first", {"x": mp.mpf(3)}, truths[0], 1)),
                                   (1, Point("second", {"x": mp.mpf(3)}, truths[1], 1))]
    form = sp.Tuple(x, 2 * x)
    ev = Components("x and 2x", points((3, 6)))(result(form, form), "quick")
    assert ev.passed and ev.printed_agrees and ev.max_residual == 0
    assert not Components("x and 2x", points((3, 7)))(result(form), "quick").passed


def test_vanishes_is_relative_to_the_terms_of_the_form():
    def points(env):
        return lambda level, dps: [("p", env)]
    form = x**2 - y**2
    ev = Vanishes("x = y", points({"x": mp.mpf(5), "y": mp.mpf(5)}))(result(form, (x - y) * (x + y)), "quick")
    assert ev.passed and ev.printed_agrees
    assert not Vanishes("x = y", points({"x": mp.mpf(5), "y": mp.mpf("5.001")}))(result(form), "quick").passed


def test_fails_wants_a_counterexample():
    def points(truth):
        return lambda level, dps: [Point("p", {"x": mp.mpf(2)}, truth, abs(truth))]
    assert Fails("x ≠ 3", points(mp.mpf(3)))(result(x), "quick").passed
    assert not Fails("x = 2", points(mp.mpf(2)))(result(x), "quick").passed


def test_terms_scale_sums_the_moduli_of_the_terms():
    assert check_kinds.terms_scale(x - y, {"x": mp.mpf(2), "y": mp.mpf(-3)}) == 5


@pytest.mark.slow
def test_on_shot_blade_integrates_and_differentiates_on_the_blade():
    """(19) ∫ w/M ds = 1 and w'(λ) = 1 (10) on the shot uniform blade; a wrong truth fails."""
    shot = profiles.shot_blade("uniform")
    with mp.workdps(40):
        length = profiles.as_mpf(shot.blade.length)

    def points(truth):
        return lambda level, dps: [(Point("λ", {"lambda": length}, truth, 1), shot, None, length)]
    form = sp.Integral(w(s) / M_of_s(s), (s, 0, lam)) * w(s).diff(s)      # 1 · 1
    ev = OnShotBlade("(19) times (10)", points(mp.mpf(1)))(result(form, form), "quick")
    assert ev.passed and ev.printed_agrees and ev.max_residual < 1e-30
    assert not OnShotBlade("(19) times (10)", points(mp.mpf("1.001")))(result(form), "quick").passed
