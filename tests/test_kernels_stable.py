"""The piecewise stable forms of pendsym.emit.kernels (issue 3 §5), on Haag's uniform blade.

The naive printed form of β1 = λ(1 − 2U/u) (159) must really lose accuracy near u = 1e-6,
while the generated kernel holds 4 ulp × max(1, κ); the pieces must join within that bound.
"""
import math

import mpmath as mp
import pytest
import sympy as sp

from pendsym import registry, stages
from pendsym.emit import kernels as kn
from pendsym.result import KernelArg

U_ARG = KernelArg("u", 1e-6, 700.0)
u = sp.Symbol("u", positive=True)


@pytest.fixture(scope="module")
def beta1():
    """β1 (159) and its kernel as make derive forms them (from its cache when this very code formed them)."""
    r = stages.results(["haag1935.eq159.beta1"])["haag1935.eq159.beta1"]
    return r, stages.kernel(r)


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
    for s in kn.SWITCHES + kn.KNOTS:
        below, above = math.nextafter(s, 0.0), s
        acc = kn.measure(f, r.derived, k.args, [(1.3, below), (1.3, above)])
        assert acc.max_scaled <= kn.BOUND, (s, acc)
        assert abs(f(1.3, below) - f(1.3, above)) <= 8 * math.ulp(f(1.3, above)) + abs(f(1.3, above)) * 1e-15


def test_sampling_covers_1e6_the_switches_and_700():
    pts = kn.sample_points((KernelArg("lambda", 1e-3, 10.0), U_ARG), "x", pieces="u")
    us = {p[1] for p in pts}
    assert 1e-6 in us and 700.0 in us
    for s in kn.SWITCHES + kn.KNOTS:
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


@pytest.fixture(scope="module")
def haag_py(emitted_kernels):
    return emitted_kernels("haag1935").python


def test_K_kernel_holds_where_the_form_of_35_cancels(haag_py):
    """K through (36) and the stable root z: within the bound from u = 1e-6 to 700 and for short
    blades; the same K through (35), evaluated in double, loses everything as u → 0."""
    ids = ["haag1935.eq036.K_uniform", "haag1935.eq035.K_uniform", "haag1935.eq034.n2_z_uniform"]
    rs = stages.results(ids)
    r36, r35, rn2 = (rs[i] for i in ids)
    args = r36.spec.kernel.args
    pts = [(a, R, lam, uv) for uv in (1e-6, 1e-3, 0.7, 30.0, 700.0)
           for a, R, lam in ((0.9, 0.35, 0.05), (0.01, 2.0, 1e-3), (5.0, 1e-3, 10.0))]
    acc = kn.measure(haag_py.eq036_K_uniform, r36.derived, args, pts)
    assert acc.max_scaled <= kn.BOUND, acc
    acc_n2 = kn.measure(haag_py.eq034_n2_z_uniform, rn2.derived, rn2.spec.kernel.args, [p + (9.81,) for p in pts])
    assert acc_n2.max_scaled <= kn.BOUND, acc_n2
    naive = kn.measure(kn.py_callable(r35.derived, args), r36.derived, args, [(0.9, 0.35, 0.05, 1e-6)])
    assert naive.max_ulp > 1e6


def test_vertex_form_holds_on_the_vertex_curve_where_the_plain_form_does_not(haag_py):
    """I_λ (182) is quadratic in K; near its vertex the plain stable form amplifies the rounding of
    its leaves by Σ|terms|/|I| ≈ 60 at u = 1.5, beyond the condition number.  The generated kernel
    (vertex form) holds the bound on points of the vertex curve; the plain form does not."""
    rid = "haag1935.eq182.I"
    r = registry.build([rid])[rid]
    args = tuple(a for a in r.spec.kernel.args if a.name in {s.name for s in r.derived.free_symbols})
    on_curve = kn.vertex_points(r.derived, args, "test")
    assert len(on_curve) >= 3
    pts = on_curve + [(0.17, 1.5, -1.759221852784191, 0.91)]
    assert kn.measure(haag_py.eq182_I, r.derived, args, pts).max_scaled <= kn.BOUND
    plain = kn.stable_forms(r.derived, args, vertex=False)[0][1]
    assert kn.measure(kn.py_callable(plain, args), r.derived, args, pts).max_scaled > kn.BOUND
