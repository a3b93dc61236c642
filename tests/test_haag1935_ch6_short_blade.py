"""Haag 1935, chapter VI (the short blade): expansion, derivation, printed forms and the eigenproblem truth."""
import dataclasses

import mpmath as mp
import pytest
import sympy as sp

from derivations.haag1935 import ch6_short_blade
from derivations.haag1935.ch6_short_blade import expansion, printed, truth
from derivations.haag1935.common import rid
from derivations.haag1935.symbols import DEFS, R, a, lam, u, v0, vl, w0, z
from pendsym import checks, stages
from pendsym.result import Result

L_OF_A = ((expansion.l, a + R**2 / a),)


@pytest.fixture(scope="module")
def built():
    return stages.results([spec.id for spec in ch6_short_blade.specs()])


# ---------------------------------------------------------------- expansion
def test_root_series_of_a_known_quadratic():
    """(z − 1)(z + 2) + δ·λz = 0: the root near 1 is 1 − λ/3 to the first order."""
    root = expansion.root_series((z - 1) * (z + 2) + lam * z, z, 1, 1)
    assert sp.simplify(root - (1 - lam / 3)) == 0


def test_root_series_refuses_a_non_root():
    with pytest.raises(ValueError):
        expansion.root_series((z - 1) * (z + 2) + lam * z, z, 3, 1)


def test_truncated_keeps_the_first_order_only():
    assert expansion.truncated(a / (a - vl), 1) == 1 + vl / a
    assert expansion.leading(a / (a - vl)) == 1


# ---------------------------------------------------------------- printed ≡ derived
@pytest.mark.slow
@pytest.mark.parametrize("eq, name", [(212, "rhs"), (212, "reduced"), (214, "z"), (215, "zp"), (216, "K"),
                                      (217, "n2"), (218, "dl"), (224, "Kp"), (225, "np2"), (237, "OFp_l"),
                                      (238, "x")])
def test_series_forms_equal_the_printed_ones(built, eq, name):
    result = built[rid(eq, name)]
    assert sp.simplify(result.derived - result.spec.printed().subs(L_OF_A)) == 0


@pytest.mark.slow
def test_length_correction_of_ordinary_pendulums(built):
    """(219) is λ − v_0 − w_0, and (220) equals λ(1 − coth u/u)."""
    assert sp.expand(built[rid(219, "dl")].derived - (lam - v0 - w0)) == 0
    difference = built[rid(220, "dl")].derived - lam * (1 - sp.coth(u) / u)
    assert sp.simplify(difference.rewrite(sp.exp)) == 0


@pytest.mark.slow
def test_zero_of_the_length_correction_is_rounded_in_the_text(built):
    """u th u = 1 at 1.19968 (mpmath, independent of the derivation): "1,2 environ" is it to one decimal."""
    root = mp.findroot(lambda x: x * mp.tanh(x) - 1, 1.2)
    derived = built[rid(220, "u_root")].derived
    assert abs(float(derived) - float(root)) < 1e-25
    assert round(float(derived), 1) == 1.2 and derived != printed.u_root_220()


@pytest.mark.slow
def test_value_at_u_4_is_truncated_in_the_text(built):
    """sh²4/(4 + sh 4 ch 4) = 0.99399…: the printed 0,993 is truncated (rounded would be 0,994)."""
    value = float(built[rid(236, "value")].derived)
    exact = float(mp.sinh(4) ** 2 / (4 + mp.sinh(4) * mp.cosh(4)))
    assert abs(value - exact) < 1e-15
    assert int(value * 1000) / 1000 == 0.993 and round(value, 3) == 0.994


@pytest.mark.slow
def test_thin_blade_limits(built):
    assert sp.simplify(built[rid(240, "c_thin")].derived - lam / (2 * u)) == 0
    assert sp.simplify(built[rid(237, "OFp_thin")].derived - lam / u) == 0


@pytest.mark.slow
def test_uniform_forms_match_under_the_definitions(built):
    for eq, name in ((239, "F2"), (240, "x"), (240, "c"), (235, "S_uniform")):
        result = built[rid(eq, name)]
        difference = (result.derived - result.spec.printed()).subs(dict(DEFS)).subs(L_OF_A)
        assert abs(sp.N(difference.subs({u: sp.Rational(7, 3), lam: sp.Rational(1, 10), a: 2}), 30)) < 1e-25


# ---------------------------------------------------------------- the truth
def test_modes_of_the_short_pendulum_approach_the_rigid_one():
    """As λ/a → 0 the principal n² tends to g/l and the upper focus to A (z' → −a)."""
    env = truth.state("tapered", truth.RATIO, "1e-4", 30)
    assert abs(env["n^2"] * env["l"] / env["g"] - 1) < 1e-3
    assert abs(env["z'"] / env["a"] + 1) < 1e-3


@pytest.mark.slow
def test_order_checks_pass_for_the_derived_forms(built):
    for eq, name in ((214, "z"), (217, "n2"), (219, "dl"), (225, "np2")):
        result = built[rid(eq, name)]
        assert checks.run(result.spec.check, result, "quick").passed, (eq, name)


@pytest.mark.slow
def test_order_check_fails_without_the_first_order_term(built):
    """z = R²/a alone (the rigid pendulum's focus) misses the O(λ/a) term: its residual is of the first order."""
    result = built[rid(214, "z")]
    wrong = Result(result.spec, R**2 / a, None)
    evidence = checks.run(result.spec.check, wrong, "quick")
    assert not evidence.passed and abs(evidence.order - 1) < 0.3


@pytest.mark.slow
def test_length_correction_fails_with_a_sign_error(built):
    """Δl = λ + v_0 − w_0 (a wrong sign) does not converge to the truth: its residual is of order 0."""
    result = built[rid(219, "dl")]
    wrong = dataclasses.replace(Result(result.spec, lam + v0 - w0, None))
    assert not checks.run(result.spec.check, wrong, "quick").passed


# ---------------------------------------------------------------- n°70–71: temperature, launches
@pytest.mark.slow
def test_temperature_formula_is_twice_the_derived_one(built):
    """(222) as printed is 2 × the first-order (60): its leading term α' where T ∝ √(l/g) gives α'/2."""
    from derivations.haag1935.symbols import alpha_rod
    result = built[rid(222, "dT")]
    assert sp.simplify(result.spec.printed() - 2 * result.derived) == 0
    assert sp.limit(result.derived, a, sp.oo) == alpha_rod / 2


@pytest.mark.slow
def test_uniform_temperature_differs_in_the_beta_term_only(built):
    """(223): printed − derived = (λβ/4a)(U_1² − U_1): only the thermo-elastic term differs."""
    from derivations.haag1935.symbols import U1, alpha_blade, alpha_rod, beta_t
    result = built[rid(223, "dT")]
    difference = (result.spec.printed() - result.derived).subs(dict(DEFS))
    expected = (lam * beta_t / (4 * a) * (U1**2 - U1)).subs(dict(DEFS))
    at = {u: sp.Rational(7, 3), lam: sp.Rational(1, 10), a: 2, beta_t: sp.Rational(-3, 10000),
          alpha_blade: sp.Rational(11, 10**6), alpha_rod: sp.Rational(9, 10**6)}
    assert abs(sp.N((difference - expected).subs(at), 30)) < 1e-30
    assert abs(sp.N(difference.subs(at), 30)) > 1e-8


@pytest.mark.slow
def test_launch_ratios_keep_the_focal_factor(built):
    from derivations.haag1935.ch6_short_blade import derivation
    for eq in (227, 228):
        result = built[rid(eq, "ratio")]
        assert sp.simplify(result.derived - result.spec.printed().subs(L_OF_A)) == 0
        assert sp.simplify(result.derived / derivation.focal_ratio()).free_symbols.isdisjoint({z, sp.Symbol("b")})


@pytest.mark.slow
def test_printed_temperature_fails_its_order_check(built):
    """The check that passes the derived (222) fails the printed one (a residual of order 0)."""
    result = built[rid(222, "dT")]
    evidence = checks.run(result.spec.check.checks[0], result, "quick")
    assert evidence.passed and evidence.printed_agrees is False and abs(evidence.printed_order) < 0.3


@pytest.mark.slow
def test_fatigue_at_the_clamp_is_U2(built):
    """(232): (178) at s = 0, K = 1 is √(3ET)(U + U_1)θ0 = √(3ET)U_2θ0 (161), T = Ee²u²/(12λ²)."""
    from derivations.haag1935.symbols import E, e
    from derivations.haag1935.ch6_short_blade.derivation import THETA_0
    derived = built[rid(232, "Tprime")].derived
    expected = sp.sqrt(3 * E * E * e**2 * u**2 / (12 * lam**2)) * sp.coth(u) * THETA_0
    at = {E: 2, e: sp.Rational(3, 10), u: sp.Rational(5, 2), lam: sp.Rational(1, 10), THETA_0: sp.Rational(1, 100)}
    assert abs(sp.N((derived - expected).subs(at), 30)) < 1e-28


@pytest.mark.slow
def test_thread_limit_of_the_length_correction(built):
    assert built[rid(220, "thread")].derived == lam


def test_bounds_of_n70_are_positive_on_a_blade():
    from derivations.haag1935.ch6_short_blade import derivation
    from derivations.haag1935.symbols import G_2, M_lambda, mu, wl
    env = {v0: sp.Rational(2, 100), wl: sp.Rational(3, 100), w0: sp.Rational(4, 100), lam: sp.Rational(1, 10),
           mu: 2, M_lambda: sp.Rational(1, 100), G_2: sp.Rational(2, 100)}
    assert derivation.G2_bound_70(None).subs(env) > 0
    assert (derivation.G2_bound_70(None).subs(env | {G_2: 1})) < 0


def test_every_result_of_chapter_six_has_a_heading():
    from derivations.haag1935 import MEMOIR
    ids = {spec.id for spec in ch6_short_blade.specs()}
    headed = {i for heading in MEMOIR.report_headings() if heading.title.startswith("Chapter VI.") for i in heading.ids}
    assert headed == ids and len(ids) == len(ch6_short_blade.specs())


def test_every_claim_has_an_independent_check():
    for spec in ch6_short_blade.specs():
        assert spec.check is not None, spec.id
        assert spec.definition == isinstance(spec.check, checks.Definition), spec.id


@pytest.mark.slow
def test_fatigue_by_point_of_attack_meets_232_at_the_focus(built):
    """(230) and (231) both give √(3ET)U_2θ0 (232) when B is at F ≈ G (b = a); they differ elsewhere."""
    from derivations.haag1935.ch3_uniform.launch_symbols import stress_scale
    from derivations.haag1935.ch6_short_blade.derivation import THETA_0
    from derivations.haag1935.symbols import U2, b
    expected = (stress_scale * THETA_0 * U2).subs(dict(DEFS))
    between, below = (built[rid(eq, "T0")].derived.subs(dict(DEFS)) for eq in (230, 231))
    assert sp.simplify((between - expected).subs(b, a)) == 0
    assert sp.simplify((below - expected).subs(b, a)) == 0
    assert sp.simplify(between - below) != 0
