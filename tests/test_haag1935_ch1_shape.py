"""Haag 1935, chapter I, n°21–25 (eqs. (77)–(87)): statuses found by hand, the fork's glide, checks that can fail."""
import dataclasses
import functools

import mpmath as mp
import pytest
import sympy as sp

from derivations.haag1935 import ch1_shape
from derivations.haag1935.ch1_shape import truth
from derivations.haag1935.common import rid
from derivations.haag1935.symbols import x_fork
from pendsym import pipeline, stages, verify

IDS = [spec.id for spec in ch1_shape.specs()]


@functools.lru_cache(maxsize=1)
def built():
    return stages.results(IDS)


def test_ids_cover_77_to_87_and_the_orders_of_64_and_85():
    assert len(IDS) == 18 and {int(i.split(".")[1][2:]) for i in IDS} == set(range(77, 88)) | {64}
    assert set(ch1_shape.ORBIT_RESULTS) <= set(IDS)


@pytest.mark.slow
def test_all_results_match():
    assert [i for i in IDS if pipeline.compare(built()[i])[0] != "match"] == []


@pytest.mark.slow
@pytest.mark.parametrize("eq, name", [(77, "y"), (81, "F2G2"), (84, "geometry"), (86, "A"), (87, "optimum"),
                                      (64, "third_order"), (85, "fourth_order")])
def test_checks_pass(eq, name):
    ev = stages.assessed(built()[rid(eq, name)])[1]
    assert ev.passed, ev
    assert ev.printed_agrees is True


@pytest.mark.slow
@pytest.mark.parametrize("eq, name, wrong", [
    (80, "W", lambda d: d * (1 + sp.Rational(1, 10**20))),
    (86, "A", lambda d: d * sp.Rational(1001, 1000)),           # a wrong A leaves a residual of the second order
    (87, "optimum", lambda d: d.subs(x_fork, x_fork + sp.Rational(1, 100))),   # another axis: glide of order 2
    # on the exact orbit: a θ² coefficient 0.1 % off leaves a residual of order 2, a slope 0.1 % off of order 1
    (85, "fourth_order", lambda d: d.subs(sp.Symbol("lambda", positive=True), 0) * sp.Rational(1001, 1000)
     + sp.Symbol("lambda", positive=True)),
    (64, "third_order", lambda d: d * sp.Rational(1001, 1000)),
])
def test_a_wrong_formula_fails(eq, name, wrong):
    r = built()[rid(eq, name)]
    assert not pipeline.check(dataclasses.replace(r, derived=wrong(r.derived)), "quick").passed


@pytest.mark.slow
def test_off_the_optimum_the_glide_is_of_the_second_order():
    """Away from the root of (87) the glide of the fork is of the second order (the truth can tell)."""
    with mp.workdps(40):
        env = truth.fork_env("tapered", "clock")
        model = truth.fork_model("tapered", "clock", 30)
        c_v = env["lambda"] - mp.mpf("0.05")
        r0 = truth.root84(mp.mpf(0), c_v, env["L"], model)
        thetas = [mp.mpf("1e-3"), mp.mpf("1e-2")]
        glide = [truth.root84(t, c_v, env["L"], model) - r0 for t in thetas]
        assert abs(verify.fit_order(thetas, glide) - 2) < 0.1
