"""Haag 1935, chapter VII, n°92–93 and n°97: the derivation of (281)–(284), its printed forms and its truths."""
import dataclasses

import mpmath as mp
import pytest
import sympy as sp

from derivations.haag1935 import ch7_isochronism
from derivations.haag1935.ch7_gravity import truth as gravity
from derivations.haag1935.ch7_isochronism import checks_isochronism, derivation, printed, truth
from derivations.haag1935.common import rid
from derivations.haag1935.symbols import G, lam, s, w, w0
from pendsym import checks, stages
from pendsym.result import Result

_x = sp.Symbol("x", real=True)


@pytest.fixture(scope="module")
def built():
    return stages.results([spec.id for spec in ch7_isochronism.table.specs()])


# ---------------------------------------------------------------- printed forms and derivation steps
def test_third_form_of_284_is_the_second_with_a_cube():
    """w0 + ∫w'(1 − w'³) over w0 + ∫w'(1 − w') is (wλ − F4)/(wλ − F2) for wλ = w0 + ∫w'; the printed square is
    not (test function w = x²/2, λ = 1, w0 = 1/3: w' = x)."""
    at = {lam: 1, w0: sp.Rational(1, 3)}
    test = {w: sp.Lambda(_x, _x**2 / 2)}

    def value(expr):
        return expr.subs(at).replace(w, test[w]).doit()
    wl, F2, F4 = sp.Rational(1, 3) + sp.Rational(1, 2), sp.Rational(1, 3), sp.Rational(1, 5)
    second = (wl - F4) / (wl - F2)
    assert sp.simplify(value(printed.C_284_integrals()) - second) != 0
    slope = w(s).diff(s)
    cube = (w0 + sp.Integral(slope * (1 - slope**3), (s, 0, lam))) / (w0 + sp.Integral(slope * (1 - slope), (s, 0, lam)))
    assert sp.simplify(value(cube) - second) == 0


def test_positivity_of_C_minus_one_is_decided_on_the_integrand():
    slope = w(s).diff(s)
    assert derivation.integrand_nonnegative(printed.C_minus_one())
    assert not derivation.integrand_nonnegative(sp.Integral(slope**2 * (slope**2 - 1), (s, 0, lam)))


def test_over_G_refuses_a_form_that_keeps_epsilon():
    from derivations.haag1935.ch7_gravity.symbols import eps
    assert derivation.over_G_free(-G / 2)
    assert not derivation.over_G_free(-G / (2 * eps))


@pytest.mark.slow
def test_derived_forms_equal_the_printed_ones_but_the_third_C(built):
    for eq, name in ((282, "Qp"), (283, "dT"), (284, "C"), (284, "C_F2")):
        result = built[rid(eq, name)]
        assert sp.simplify(result.derived - result.printed) == 0, (eq, name)
    f = built[rid(281, "f")]
    assert f.derived.atoms(sp.Integral) == f.printed.atoms(sp.Integral)
    assert sp.simplify(f.derived - f.printed) == 0
    third = built[rid(284, "C_integrals")]
    assert third.derived.atoms(sp.Integral) != third.printed.atoms(sp.Integral)


@pytest.mark.slow
def test_n97_forms_have_no_epsilon_and_keep_theta0_to_the_q(built):
    from derivations.haag1935.ch7_gravity.symbols import eps
    law = built[rid(284, "law_G")].derived
    assert law.has(G) and not law.has(eps) and law.has(sp.Symbol("theta_0", positive=True))
    assert derivation.over_G_free(built[rid(284, "friction_G")].derived)


# ---------------------------------------------------------------- truths
def test_linear_perturbations_of_the_slow_mode():
    """ε3 = κθ moves log n² by −1/(ελ) at leading order; E(1 + κ) and g(1 + κ) with M/(1 + κ) differ by exactly 1
    (n² = g·h(M): d log n²/d log E = 1 − d log n²/d log g)."""
    eps = mp.mpf("1e-4")
    with mp.workdps(30):
        couple = truth.log_n2_slope("u=2", "eps3", eps)
        assert abs(couple * eps * mp.mpf("0.1") + 1) < mp.mpf("1e-3")
        stiffer, vertical = truth.log_n2_slope("u=2", "stiffer", eps), truth.log_n2_slope("u=2", "eps1", eps)
        assert abs(stiffer + vertical - 1) < mp.mpf("1e-15")
        assert vertical < -100


@pytest.mark.slow
def test_slow_orbit_converges_in_the_nodes_and_is_the_slow_one():
    """4 and 5 collocation nodes agree to 28 digits of T/T_lin at ε = 1e-2 (θ0 = 1e-3); ΔT/T is near −θ0²GC/16
    (the fast mode would give about θ0²/16 > 0)."""
    eps = mp.mpf("1e-2")
    with mp.workdps(30):
        four = truth.relative_change("u=2", eps, 30, 4)
        five = truth.relative_change("u=2", eps, 30, 5)
        assert abs(four - five) < mp.mpf("1e-28")
        env = checks_isochronism.blade_env("u=2", 30)
        G = gravity.sensitivity("u=2", 1, eps)
        assert abs(four / (-truth.amplitude(eps) ** 2 * G * env["C"] / 16) - 1) < mp.mpf("0.02")


def run_as_derive(check, result):
    """A check at the working precision of pendsym.pipeline.check (the orbits it needs are then those a derive
    cached)."""
    with mp.workdps(40):
        return checks.run(check, result, "full")


@pytest.mark.slow
def test_isochronism_check_fails_for_a_wrong_coefficient(built):
    """−θ0²GC/12 instead of /16: the relative error 1/3 does not vanish, the residual is of order 0."""
    result = built[rid(283, "dT")]
    wrong = Result(result.spec, result.derived * sp.Rational(4, 3), None)
    evidence = run_as_derive(result.spec.check, wrong)
    assert not evidence.passed and abs(evidence.order) < 0.3


@pytest.mark.slow
def test_third_form_of_284_fails_its_check_where_the_first_passes(built):
    (status, _), evidence = stages.assessed(built[rid(284, "C_integrals")])
    assert status == "discrepancy" and evidence.passed and evidence.printed_agrees is False
    (status, _), evidence = stages.assessed(built[rid(284, "C")])
    assert status == "match" and evidence.passed and evidence.printed_agrees is True


@pytest.mark.slow
def test_281_check_fails_with_a_wrong_sign_of_the_horizontal_force(built):
    from derivations.haag1935.ch2_common import eps2
    result = built[rid(281, "f")]
    wrong = dataclasses.replace(Result(result.spec, result.derived.subs(eps2, -eps2), None))
    assert not run_as_derive(checks_isochronism.perturbation_order("eps2"), wrong).passed
