"""The piecewise stable forms of pendsym.emit.kernels (issue 3 §5), on Haag's uniform blade.

The naive printed form of β1 = λ(1 − 2U/u) (159) must really lose accuracy near u = 1e-6,
while the generated kernel holds 4 ulp × max(1, κ); the pieces must join within that bound.
"""
import math

import mpmath as mp
import pytest
import sympy as sp

from pendsym import registry
from pendsym.emit import kernels as kn
from pendsym.result import KernelArg

U_ARG = KernelArg("u", 1e-6, 700.0)
u = sp.Symbol("u", positive=True)


@pytest.fixture(scope="module")
def beta1():
    r = registry.build(["haag1935.eq159.beta1"])["haag1935.eq159.beta1"]
    return r, kn.kernel_of(r)


def test_naive_beta1_loses_more_than_1e6_ulp_near_u_1e6_and_the_kernel_holds(beta1):
    r, k = beta1
    pts = [(1.3, v) for v in (1e-6, 3e-6, 1e-5)]
    naive = kn.measure(kn.py_callable(kn.naive_form(r, k.args)[1], k.args), r.derived, k.args, pts)
    stable = kn.measure(kn.py_callable(k.expr, k.args), r.derived, k.args, pts)
    assert naive.max_ulp > 1e6
    assert stable.max_scaled <= kn.BOUND
    assert k.naive.form == "printed" and k.naive.accuracy.max_scaled > 1e6


def test_the_pieces_join_within_the_bound_at_every_switch(beta1):
    r, k = beta1
    f = kn.py_callable(k.expr, k.args)
    for s in kn.SWITCHES + kn.MID_ENDS:
        below, above = math.nextafter(s, 0.0), s
        acc = kn.measure(f, r.derived, k.args, [(1.3, below), (1.3, above)])
        assert acc.max_scaled <= kn.BOUND, (s, acc)
        assert abs(f(1.3, below) - f(1.3, above)) <= 8 * math.ulp(f(1.3, above)) + abs(f(1.3, above)) * 1e-15


def test_sampling_covers_1e6_the_switches_and_700():
    pts = kn.sample_points((KernelArg("lambda", 1e-3, 10.0), U_ARG), "x")
    us = {p[1] for p in pts}
    assert 1e-6 in us and 700.0 in us
    for s in kn.SWITCHES + kn.MID_ENDS:
        assert {math.nextafter(s, 0.0), s, math.nextafter(s, math.inf)} <= us


def test_laurent_series_is_the_sympy_series():
    c = 1 / u**2 - 1 / sp.sinh(u) ** 2
    m, cs = kn.laurent(c, u, span=12)
    ref = sp.series(c, u, 0, 13 + m).removeO()
    assert sp.expand(ref - sum(cf * u ** (m + j) for j, cf in enumerate(cs))) == 0


def test_exp_form_does_not_overflow_at_700_and_keeps_its_value():
    c = u / sp.sinh(u) ** 2 + 1 / sp.tanh(u / 2)
    ef = kn.exp_form(c, u)
    f = sp.lambdify([u], ef, modules="math")
    with mp.workdps(50):
        for v in (0.3, 20.0, 700.0):
            true = mp.mpf(v) / mp.sinh(v) ** 2 + 1 / mp.tanh(mp.mpf(v) / 2)
            assert abs(f(v) - true) <= 4 * math.ulp(float(true))
    with pytest.raises(OverflowError):
        sp.lambdify([u], c, modules="math")(700.0)


def test_split_hard_keeps_the_function():
    K = sp.Symbol("K")
    e = K**2 * (1 - 2 * sp.tanh(u / 2) / u) + K * sp.tanh(u / 2) + 1 / u**2 - 1 / sp.sinh(u) ** 2
    skel, leaves = kn.split_hard(e, u)
    assert len(leaves) == 3 and not skel.has(sp.tanh)
    assert sp.simplify(skel.xreplace(leaves) - e) == 0
