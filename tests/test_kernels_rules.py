"""pendsym.emit.kernels.rules and .series: named rule objects in tuples, each keeping the
function and curing the cancellation it is named for."""
import dataclasses
import math

import mpmath as mp
import sympy as sp

from pendsym.emit import kernels as kn
from pendsym.emit.kernels import rules
from pendsym.result import KernelArg

x, t, k = sp.symbols("x t k", positive=True)
u = sp.Symbol("u", positive=True)


def _ulp(got: float, true) -> float:
    return float(abs(mp.mpf(got) - true) / mp.mpf(math.ulp(float(true))))


def test_rewrites_are_named_frozen_objects_in_order():
    names = [r.name for r in kn.REWRITES]
    assert names == ["as-derived", "factor", "expand-trig", "sin-basis", "cos-basis", "horner", "half-angle"]
    assert {r.name for r in kn.REWRITES if r.trig} == {"expand-trig", "sin-basis", "cos-basis", "half-angle"}
    for r in kn.REWRITES:
        assert dataclasses.is_dataclass(r) and r.__dataclass_params__.frozen and callable(r)


def test_half_angle_cures_one_minus_cos():
    rule = next(r for r in kn.REWRITES if r.name == "half-angle")
    e = (1 - sp.cos(x)) / x**2
    f = sp.lambdify([x], rule(e), modules="math")
    with mp.workdps(50):
        true = (1 - mp.cos(mp.mpf(1e-5))) / mp.mpf(1e-5) ** 2
        assert _ulp(f(1e-5), true) <= 4
        assert _ulp(sp.lambdify([x], e, modules="math")(1e-5), true) > 1e6   # the cancellation it cures


def test_series_near_zero_holds_where_the_form_cancels():
    e = (k * t - sp.sin(k * t) * sp.cos(k * t)) / k**3
    near = kn.NEAR_ZERO.series(e, (KernelArg("t", 0.0, 10.0, log=False), KernelArg("k", 0.1, 2.0)))
    assert near is not None and near[1] == k * t
    f = sp.lambdify([t, k], kn.NEAR_ZERO(e, near), modules="math")
    with mp.workdps(50):
        for tv in (1e-6, 1e-3, 0.3):
            kv, tm = mp.mpf(0.7), mp.mpf(tv)
            true = (kv * tm - mp.sin(kv * tm) * mp.cos(kv * tm)) / kv**3
            assert _ulp(f(tv, 0.7), true) <= 4, tv
    assert kn.NEAR_ZERO.series(e, (KernelArg("t", 1.0, 10.0), KernelArg("k", 0.1, 2.0))) is None


def test_far_forms_are_named_for_their_argument_and_keep_the_leaf():
    assert [r.name("u") for r in kn.FAR_FORMS] == ["as derived", "e^{-u} form", "limit in 1/u plus e^{-u} remainder"]
    c = 1 - 2 * sp.tanh(u / 2) / u
    assert kn.FAR_FORMS[0](c, u) == c
    with mp.workdps(50):
        for r in kn.FAR_FORMS[1:]:
            form = r(c, u)
            assert form is not None and not form.has(sp.tanh), r.label
            f = sp.lambdify([u], form, modules="math")
            for v in (30.0, 700.0):
                true = 1 - 2 * mp.tanh(mp.mpf(v) / 2) / v
                assert _ulp(f(v), true) <= 4, (r.label, v)


def test_vertex_form_keeps_the_skeleton_and_adds_two_leaves():
    K = sp.Symbol("K")
    a, b, c = sp.symbols("leaf_0 leaf_1 leaf_2")
    leaves = {a: 1 - 2 * sp.tanh(u / 2) / u, b: sp.tanh(u / 2), c: 1 / u**2 - 1 / sp.sinh(u) ** 2}
    skeleton = 3 * a * K**2 + b * K + c
    assert kn.SKELETONS[0](skeleton, leaves) == (skeleton, leaves)
    vskel, vleaves = rules.vertex_form(skeleton, leaves)
    assert len(vleaves) == 5
    diff = vskel.xreplace(vleaves) - skeleton.xreplace(leaves)
    assert all(abs(sp.N(diff.subs({K: kv, u: uv}), 30)) < 1e-25 for kv in (-sp.Rational(3, 2), sp.Rational(1, 5), 2)
               for uv in (sp.Rational(3, 10), sp.Rational(5, 2)))
