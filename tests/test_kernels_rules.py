"""pendsym.emit.kernels.rules and .series: named rule objects in tuples, each keeping the
function and curing the cancellation it is named for."""
import dataclasses
import math

import mpmath as mp
import pytest
import sympy as sp

from pendsym.emit import kernels as kn
from pendsym.emit.kernels import rules, skeleton_forms
from pendsym.emit.kernels.measure import ref_dps, reference
from pendsym.result import KernelArg

x, t, k = sp.symbols("x t k", positive=True)
u = sp.Symbol("u", positive=True)


def _ulp(got: float, true) -> float:
    return float(abs(mp.mpf(got) - true) / mp.mpf(math.ulp(float(true))))


def test_rewrites_are_named_frozen_objects_in_order():
    names = [r.name for r in kn.REWRITES]
    assert names == ["as-derived", "factor", "expand-trig", "sin-basis", "cos-basis", "horner", "half-angle",
                     "smaller-basis", "multiple-angles"]
    assert {r.name for r in kn.REWRITES if r.trig} == {"expand-trig", "sin-basis", "cos-basis", "half-angle", "smaller-basis",
                                                        "multiple-angles"}
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
    assert [r.name("u") for r in kn.FAR_FORMS] == [
        "limit in 1/u plus e^{-u} remainder in one exponential",
        "as derived", "e^{-u} form", "limit in 1/u plus e^{-u} remainder"]
    c = 1 - 2 * sp.tanh(u / 2) / u
    assert kn.FAR_FORMS[1](c, u) == c
    with mp.workdps(50):
        for r in kn.FAR_FORMS[:1] + kn.FAR_FORMS[2:]:
            form = r(c, u)
            assert form is not None and not form.has(sp.tanh), r.label
            f = sp.lambdify([u], form.replace(lambda e: isinstance(e, kn.Grouped), lambda e: e.args[0]), modules="math")
            for v in (3.0, 30.0, 700.0):
                true = 1 - 2 * mp.tanh(mp.mpf(v) / 2) / v
                assert _ulp(f(v), true) <= 4, (r.label, v)


def test_one_exponential_calls_exp_once():
    c = sp.tanh(u / 2) ** 2 / u**2 - 1 / (u**2 * sp.cosh(u / 2) ** 2)     # E = e^{−u/2}: E², (E² + 1)², E ± 1
    form = rules.one_exponential(kn.exp_form(c, u), u)
    assert form is not None and len(form.atoms(sp.exp)) == 1 and not form.has(sp.sinh, sp.tanh)
    assert not any(type(f).__name__ == "expm1" for f in form.atoms(sp.Function))
    f = sp.lambdify([u], form.replace(lambda e: isinstance(e, kn.Grouped), lambda e: e.args[0]), modules="math")
    with mp.workdps(50):
        for v in (6.0, 40.0, 600.0):
            x = mp.mpf(v)
            assert _ulp(f(v), mp.tanh(x / 2) ** 2 / x**2 - 1 / (x**2 * mp.cosh(x / 2) ** 2)) <= 4, v


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


def _as_expr(form: sp.Expr) -> sp.Expr:
    """A skeleton form with its Select read in both branches: (the Select's test, form if > 0, form else)."""
    sel = next(iter(form.atoms(rules.Select)))
    return sel.args[0], form.xreplace({sel: sel.args[1]}), form.xreplace({sel: sel.args[2]})


def test_taylor_form_in_K_keeps_the_quartic_and_picks_a_centre_where_it_cancels():
    """(Issue #11, F of (170).)  A quartic in K about a centre c: the same function, c among the domain's
    thirteenths, the new leaves the exact Taylor coefficients; offered only for degree ≥ 3 and where it gains."""
    K = sp.Symbol("K")
    ls = sp.symbols("leaf_0:5")
    # a quartic whose terms cancel near K = −1 for u ≈ 1 (its value there ≪ the sum of its terms)
    leaves = {ls[0]: 1 + u, ls[1]: 4 + 4 * u, ls[2]: 6 + 6 * u, ls[3]: 4 + 4 * u, ls[4]: 1 + u + u**3 / 100}
    skeleton = sum(ls[4 - i] * K**i for i in range(5))
    args = (KernelArg("u", 0.5, 2.0), KernelArg("K", -3.0, 3.0, log=False))
    got = skeleton_forms.near_taylor_form(skeleton, leaves, args)
    assert got is not None
    form, new = got
    test, taylor, plain = _as_expr(form)
    assert plain == skeleton and len(new) > len(leaves)
    for kv in (-sp.Rational(3, 2), -1, sp.Rational(1, 5)):
        for uv in (sp.Rational(3, 5), sp.Rational(7, 4)):
            at = {K: kv, u: uv}
            assert abs(sp.N((taylor.xreplace(new) - skeleton.xreplace(leaves)).subs(at), 30)) < 1e-25
    # near K = −1 the Taylor form is the one evaluated (its terms' magnitudes are the smaller)
    assert sp.N(test.xreplace(new).subs({K: -1, u: 1}).replace(rules.Magnitude, abs)) > 0
    assert skeleton_forms.near_taylor_form(ls[0] * K**2 + ls[1] * K + ls[2], leaves, args) is None      # a quadratic: vertex form


def test_one_plus_form_keeps_the_ratio_and_gathers_the_leaves():
    """(Issue #11, K of (36).)  (a + λ w)/(a + λ v + z) as 1 + (λ(w − v) − z)/(a + λ v + z), w − v one new leaf
    (simplified in exponentials: 1/(u th u) − th(u/2)/u = 1/(u sh u)), used where 1 + q ≥ ½."""
    a, lam, zz = sp.symbols("a lambda z", positive=True)
    w, v = sp.symbols("leaf_0 leaf_1")
    leaves = {w: 1 / (u * sp.tanh(u)), v: sp.tanh(u / 2) / u}
    skeleton = (a + lam * w) / (a + lam * v + zz)
    form, new = skeleton_forms.near_one_form(skeleton, leaves)
    test, near_one, plain = _as_expr(form)
    assert plain == skeleton and set(new.values()) - set(leaves.values()) == {1 / (u * sp.sinh(u))}
    at = {a: sp.Rational(1, 30), lam: 9, zz: sp.Rational(1, 10**5), u: sp.Rational(3, 2)}
    assert abs(sp.N((near_one.xreplace(new) - skeleton.xreplace(leaves)).subs(at), 30)) < 1e-25
    assert sp.N(test.xreplace(new).subs(at)) > 0
    assert skeleton_forms.near_one_form(a * lam * w / (a + lam * v), leaves) is None      # nothing shared: no rewrite


def _scaled(f, e, syms, p):
    """ulp / max(1, κ) of the double function f at p against the expression e (the contract's κ)."""
    ref, cond = reference(e, list(syms))
    with mp.workdps(ref_dps(p)):
        true = ref(*[mp.mpf(v) for v in p])
        return _ulp(f(*p), true) / max(1.0, float(cond(*[mp.mpf(v) for v in p])))


def test_the_leading_term_below_tiny_t_loses_nothing_to_subnormal_products():
    """make audit found E_c of Charbonnier's n°21 at 33.8 scaled at t = 2.5e-323 (α³·t rounded to a
    subnormal, then multiplied by 1/k); the series' leading term, c first, holds the bound there."""
    alpha = sp.Symbol("alpha", positive=True)
    e = -alpha**3 * (3 * k * t + 2 * sp.sin(2 * k * t) + sp.sin(4 * k * t) / 4) / (8 * k)
    args = (KernelArg("alpha", 1e-3, 3.0, log=False), KernelArg("k", 0.1, 10.0), KernelArg("t", 0.0, 10.0, log=False))
    near = kn.NEAR_ZERO.series(e, args)
    plain = kn.py_callable(next(r for r in kn.REWRITES if r.name == "expand-trig")(e), args)   # as emitted before
    stable = kn.py_callable(kn.NEAR_ZERO(e, near), args)
    pts = [(3.0, 0.1, 2.47033e-323), (2.9373, 9.373, 1.5e-323), (2.7, 0.37, 4.4e-320), (1.3, 3.3, 1e-300)]
    assert max(_scaled(plain, e, (alpha, k, t), p) for p in pts) > 4            # the failure it cures
    for p in pts:
        assert _scaled(stable, e, (alpha, k, t), p) <= 1.0, p


def test_the_smaller_basis_holds_where_the_sin_and_the_cos_bases_cancel():
    """E_s of n°22/n°26, (c·sin² − 2)·sin²/(4k): the cos basis cancels at kt = π (make audit: 2.3e6
    and 4.7e6 scaled), the sin basis loses 5–6 ulp where sin² ≈ 1; the smaller basis holds both."""
    for c in (5, 15):
        e = (c * sp.sin(k * t) ** 2 - 2) * sp.sin(k * t) ** 2 / (4 * k)
        args = (KernelArg("k", 0.1, 10.0), KernelArg("t", 0.0, 10.0, log=False))
        rule = next(r for r in kn.REWRITES if r.name == "smaller-basis")
        f = kn.py_callable(rule(e), args)
        cos_basis = kn.py_callable(next(r for r in kn.REWRITES if r.name == "cos-basis")(e), args)
        pts = [(1.85553, 3.3862), (0.345164, 9.10173), (6.41701, 3.18107), (0.364141, 3.95485),
               (1.0, math.pi * (1 + 1e-9)), (2.0, 3 * math.pi / 4)]
        assert max(_scaled(cos_basis, e, (k, t), p) for p in pts) > 1e3
        for p in pts:
            assert _scaled(f, e, (k, t), p) <= 4, (c, p)


def test_the_sample_holds_subnormal_t_and_the_zeros_of_sin_and_cos():
    e = (5 * sp.sin(k * t) ** 2 - 2) * sp.sin(k * t) ** 2 / (4 * k)
    args = (KernelArg("k", 0.1, 10.0), KernelArg("t", 0.0, 10.0, log=False))
    pts = kn.kernel_sample(e, args, "probe")
    assert any(0 < p[1] < 1e-320 for p in pts)
    near_pi = [p for p in pts if 0 < abs(p[0] * p[1] / math.pi - round(p[0] * p[1] / math.pi)) < 1e-11
               and round(p[0] * p[1] / math.pi) > 0]
    assert near_pi, "no point near k·t = mπ"


def test_a_split_constant_is_two_doubles_whose_sum_is_the_constant():
    from pendsym.emit.kernels import series
    c = sp.Rational(1, 3)
    form = series.split_constant(c, sp.Symbol("x") * 0 + sp.Symbol("r"))
    hi, rest = form.as_independent(sp.Symbol("r"))
    lo = rest.args[0].as_independent(sp.Symbol("r"))[0]
    assert float(hi) == 1 / 3 and float(lo) != 0
    with mp.workdps(40):
        assert abs(mp.mpf(float(hi)) + mp.mpf(float(lo)) - mp.mpf(1) / 3) < mp.mpf(10) ** -32


def test_multiple_angles_expands_only_rounded_multiples_and_keeps_the_grouping():
    from pendsym.emit.kernels.rules import multiple_angles, rounded_multiples
    alpha, k, t, q = sp.symbols("alpha k t q", real=True)
    s, c = sp.sin(k * t), sp.cos(k * t)
    e = alpha * k * (alpha**2 * q * (4 * k * t * c + 9 * s - 15 * sp.sin(3 * k * t)) + 32 * s) / 32
    got = multiple_angles(e)
    assert rounded_multiples(e) == 1 and rounded_multiples(got) == 0
    assert got == alpha * k * (alpha**2 * q * (4 * k * t * c + (60 * s**2 - 36) * s) + 32 * s) / 32
    assert rounded_multiples(sp.sin(2 * k * t) + sp.cos(4 * k * t)) == 0        # 2kt, 4kt are exact
    with pytest.raises(ValueError):
        multiple_angles(sp.sin(2 * k * t) * s)


def test_small_factors_last_multiplies_the_vanishing_factor_one_at_a_time():
    from pendsym.emit.kernels.plan import Grouped
    from pendsym.emit.kernels.rules import SMALL_LAST
    g, h, m, l, alpha = sp.symbols("g h m l alpha", positive=True)
    s = sp.sin(alpha / 2)
    got = SMALL_LAST(4 * g * h * m * s**2 / l, alpha)
    assert got == Grouped(Grouped(4 * g * h * m * s / l) * s)
    assert SMALL_LAST(g * sp.cos(alpha) ** 2, alpha) == g * sp.cos(alpha) ** 2    # cos does not vanish at 0
    args = tuple(KernelArg(x.name, 0.0, 100.0) for x in (g, h, m, l, alpha))
    f = kn.emitted_py("F_max", args, got)          # as printed: ((C·s)·s), no subnormal s²
    p = (9.3, 0.054, 12.8, 0.1856, 1e-156)
    with mp.workdps(400):
        true = 2 * p[0] * p[1] * p[2] * (1 - mp.cos(mp.mpf(p[4]))) / p[3]
        assert abs(f(*p) - true) <= 4 * math.ulp(float(true))
        assert abs(4 * p[0] * p[1] * p[2] * math.sin(p[4] / 2) ** 2 / p[3] - true) > 4 * math.ulp(float(true))
