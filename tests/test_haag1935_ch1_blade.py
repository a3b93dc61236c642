"""Haag 1935, chapter I n°1–4 (eqs. (1)–(20)): derivation steps, printed ≡ derived, checks that can fail."""
import dataclasses

import mpmath as mp
import pytest
import sympy as sp

from derivations.haag1935 import ch1_blade
from derivations.haag1935.ch1_blade import derivation, printed
from derivations.haag1935.common import rid
from derivations.haag1935.symbols import M_of_s, Y, a, lam, m, s, theta, theta_ddot, v, v0, varphi, w, w0
from pendsym import checks, pipeline, stages, verify

IDS = [spec.id for spec in ch1_blade.specs()]


def test_ids_are_unique_and_cover_1_to_20():
    assert len(IDS) == len(set(IDS)) == 40
    assert {int(i.split(".")[1][2:]) for i in IDS} == set(range(1, 21))


def test_centre_of_gravity_gives_printed_4_and_5():
    assert sp.expand(derivation.centre_of_gravity(0) - printed.eq4()) == 0
    assert sp.expand(derivation.centre_of_gravity(1) - printed.eq5()) == 0
    # a sign error in the kinematics would show: the term m a θ'' cos θ of (5)
    assert derivation.centre_of_gravity(1).coeff(theta_ddot) == m * a * sp.cos(theta)


def test_bending_equation_linearises_to_8():
    assert sp.expand(derivation.linearised_bending() - (varphi(s) - Y)) == 0
    assert derivation.eq8_residual() == 0


def test_phi_prime_is_14():
    assert sp.simplify(derivation.phi_prime() - (Y * v(s) + theta * w(s)) / M_of_s(s)) == 0


def test_symmetric_forms_of_20():
    assert derivation.symmetric_vl() == -v0
    assert sp.expand(derivation.symmetric_beta1() - (lam - 2 * v0)) == 0
    assert sp.expand(derivation.symmetric_wl() - (w0 + v0)) == 0


def test_end_slopes_are_a_definition_compared_exactly():
    r = stages.results([rid(10, "bc")])[rid(10, "bc")]
    assert checks.run(r.spec.check, r).passed
    assert not checks.run(r.spec.check, dataclasses.replace(r, printed=sp.Tuple(-1, 1, 0, 1))).passed


# ---------------------------------------------------------------- slow: the built Results and their checks
@pytest.fixture(scope="module")
def built():
    return stages.results(IDS)


@pytest.mark.slow
def test_printed_matches_derived_everywhere(built):
    """By hand: every printed form of (1)–(20) agrees with its derivation."""
    assert [i for i in IDS if pipeline.compare(built[i])[0] != "match"] == []


@pytest.mark.slow
@pytest.mark.parametrize("name", ["eq005.gy", "eq008.linear", "eq012.ends", "eq013.satisfies8", "eq013.phi_ends",
                                  "eq014.phip", "eq015.wronskian", "eq018.first", "eq019.lower", "eq020.vl"])
def test_checks_pass(built, name):
    ev = stages.assessed(built[f"haag1935.{name}"])[1]
    assert ev.passed, ev.note


@pytest.mark.slow
@pytest.mark.parametrize("name, wrong", [
    ("eq005.gy", lambda d: d.subs(theta_ddot, -theta_ddot)),      # the sign of the inertia of G
    ("eq008.linear", lambda d: d + Y),
    ("eq012.ends", lambda d: sp.Tuple(0, 0, 0, 2)),
    ("eq013.satisfies8", lambda d: Y),
    ("eq013.phi_ends", lambda d: sp.Tuple(0, 2 * theta)),
    ("eq014.phip", lambda d: d * (1 + sp.Rational(1, 10**20))),
    ("eq017.beta1_pos", lambda d: -d),
    ("eq020.vl", lambda d: v0),
])
def test_a_wrong_formula_fails(built, name, wrong):
    r = built[f"haag1935.{name}"]
    assert not pipeline.check(dataclasses.replace(r, derived=wrong(r.derived)), "quick").passed


@pytest.mark.slow
def test_symmetric_identity_fails_for_tapered(built):
    """(20) holds on the symmetric blades; on the tapered blade vλ + v0 is far from 0 (the second part of the check)."""
    r = built[rid(20, "vl")]
    holds, fails = r.spec.check.checks
    with mp.workdps(40):
        assert checks.run(holds, r).passed
        ev = checks.run(fails, r)
    assert ev.passed and ev.max_residual > 0.1


@pytest.mark.slow
def test_wronskian_of_the_shot_blade_is_w0():
    """(15) at s = λ/2 of the shot tapered blade, by the derivation's end value."""
    from derivations.haag1935 import profiles
    shot = profiles.shot_blade("tapered")
    with mp.workdps(40):
        v_s, dv, w_s, dw = shot.state(profiles.as_mpf(shot.blade.length) / 2)
        w0_value = verify.value_at(derivation.wronskian(), profiles.shot_env("tapered"))
        assert abs(v_s * dw - w_s * dv - w0_value) < mp.mpf("1e-28")
