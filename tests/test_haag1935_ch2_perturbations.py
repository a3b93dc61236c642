"""Haag 1935, chapter II, n°36–39: the derivation of (135)–(143), its printed forms and its truth."""
import mpmath as mp
import pytest
import sympy as sp

from derivations.haag1935.ch2_perturbations import derivation, derivation_friction, printed, truth
from derivations.haag1935.symbols import G_2, K, Q, z, zp


def test_swap_changes_the_order_on_a_triangle():
    x, y = sp.symbols("x y", real=True)
    inner_upper = sp.Integral(x * sp.Integral(y**2 * sp.exp(x), (y, x, 1)), (x, 0, 1))
    inner_lower = sp.Integral(sp.cos(x) * sp.Integral(y * x, (y, 0, x)), (x, 0, 1))
    for original in (inner_upper, inner_lower):
        assert sp.simplify(derivation.swap(original).doit() - original.doit()) == 0


def test_replace_inner_refuses_an_integral_that_is_not_there():
    with pytest.raises(ValueError):
        derivation.replace_inner(derivation.I_lambda_def(), sp.Integral(derivation.slope_rate(derivation.s),
                                                                        (derivation.s, 0, derivation.s1)), 0)


def test_integrations_by_parts_of_36_and_37():
    assert all(x == 0 for x in derivation.parts_identity())
    assert all(x == 0 for x in derivation.slope_identity())


def test_135_and_136_as_printed():
    assert sp.simplify(derivation.eq135() - printed.eq135()) == 0
    assert sp.simplify(derivation.eq135() - printed.eq135_Q().subs(Q, K * (z - zp))) == 0
    assert sp.simplify(derivation.eq136() - printed.eq136()) == 0
    # the perturbing accelerations have the signs of the text: f opposes θ for the weight, not for the inertia
    assert sp.simplify(derivation.inertia_f() - printed.inertia_f()) == 0
    assert sp.simplify(derivation.weight_f() - printed.weight_f()) == 0


def test_141_keeps_theta0_to_the_power_q():
    """(141) ends with θ0^q (the OCR shows g'_0): at q = 2 the derived form is −i_4 g_3 θ0²/Q."""
    theta0 = sp.Symbol("theta_0", positive=True)
    derived = derivation.eq141().subs(derivation.q, 2)
    assert derived.has(theta0**2)
    assert sp.simplify(derived - printed.eq141().subs(derivation.q, 2)) == 0


def test_wallis_values_of_142_and_143():
    assert derivation.eq142().subs(derivation.q, 4) == sp.Rational(3, 8)
    assert sp.simplify(derivation.eq143().subs(derivation.q, 3) - 4 / (3 * sp.pi)) == 0
    with mp.workdps(30):
        for qv in (5, 6):
            exact = 2 / mp.pi * mp.quad(lambda x: mp.cos(x) ** qv, [0, mp.pi / 2])
            form = derivation.eq142() if qv % 2 == 0 else derivation.eq143()
            assert abs(sp.N(form.subs(derivation.q, qv), 35) - exact) < mp.mpf(10) ** -25


def test_young_case_is_half_G2_over_Q():
    assert sp.simplify(derivation.eq139_q0() + G_2 / (2 * Q) * derivation.dE_E) == 0


def test_135_against_the_blade_with_mass_and_a_wrong_sign_fails():
    """At m'/m = 10⁻³ on the uniform blade (135) is right to about 10⁻³ relative, its opposite is not."""
    ratio = mp.mpf("0.001")
    with mp.workdps(30):
        true = truth.period_change("uniform", True)(ratio, 20)
        env = truth.blade_env("uniform", 30)
        formula = -ratio * env["I_unit"] / (2 * env["z'"] * (env["z"] - env["z'"]))
        assert abs(true - formula) < mp.mpf("0.01") * abs(true)
        assert abs(true + formula) > abs(true)


def test_density_follows_the_width():
    rho = truth.density("hole")
    s = sp.Symbol("s", real=True)
    assert rho.subs(s, sp.Rational(1, 20)) == rho.subs(s, sp.Rational(1, 100)) / 2
    assert sp.integrate(rho, (s, 0, sp.Rational(1, 10))) == 1


def test_147_149_as_printed_with_g_linear():
    from derivations.haag1935.ch2_perturbations.printed import DEFS_147, DEFS_149
    assert sp.simplify(derivation_friction.eq147() - printed.eq147().subs(dict(DEFS_147))) == 0
    assert sp.simplify(derivation_friction.eq149() - printed.eq149().subs(dict(DEFS_149))) == 0
    assert sp.simplify(derivation_friction.eq146() - printed.eq146()) == 0


def test_friction_cycle_against_147_149_and_a_swapped_quadrant_fails():
    """At ε = 0.01 (p = q = 1) the integrated cycle agrees with (147), (149) to 1 %; exchanging the outgoing
    and incoming coefficients on the left (a' ↔ b') changes the sign of the first-order ΔT/T's part."""
    eps = mp.mpf("0.01")
    F = truth.FRICTION
    dT, dtheta = truth.friction_cycle("0.01", 20)
    n, Q, th0 = (mp.mpf(F[k]) for k in ("n", "Q", "theta_0"))
    a, b, ap, bp = (eps * mp.mpf(F[k]) for k in ("a_pq", "b_pq", "a'_pq", "b'_pq"))
    i21 = i12 = 2 / (3 * mp.pi)
    formula_T = n / (4 * Q) * (b + bp - a - ap) * i21 * th0
    formula_A = -mp.pi / 2 * n / Q * (a + b + ap + bp) * i12 * th0**2
    assert abs(dT - formula_T) < mp.mpf("0.01") * abs(formula_T)
    assert abs(dtheta - formula_A) < mp.mpf("0.01") * abs(formula_A)
    swapped = n / (4 * Q) * (b + ap - a - bp) * i21 * th0
    assert abs(dT - swapped) > mp.mpf("0.1") * abs(dT)


def test_inertia_and_weight_together_add_135_and_136():
    """The blade with both its inertia and its weight: T/T0 − 1 is (135) + (136) to first order in m'/m."""
    from pendsym import massive_blade
    from derivations.haag1935 import profiles
    ratio = "0.001"
    both = massive_blade.MassiveBlade(profiles.profile("uniform"), sp.Rational(ratio) * truth.density("uniform"))
    with mp.workdps(30):
        true = massive_blade.relative_period_change(both, *profiles.PENDULUMS["compact"], dps=20)
        env = truth.blade_env("uniform", 30)
        p = mp.mpf(ratio)
        formula = (-p * env["I_unit"] / (2 * env["z'"] * (env["z"] - env["z'"])) - p * env["J_unit"] / env["Q"])
        assert abs(true - formula) < mp.mpf("0.01") * abs(formula)


# ---------------------------------------------------------------- (145), n°43 (150)
def test_145_is_the_outgoing_term_with_the_opposite_sign_when_b_equals_a():
    """(145) as printed; with b = a the incoming ε is minus the outgoing one at the same |c'| (friction opposes
    the motion both ways), which a sign error in the replacement would break."""
    from derivations.haag1935.ch2_perturbations import derivation_experiment as exp
    f = derivation_friction
    assert sp.simplify(exp.eq145() - printed.eq145()) == 0
    rate = sp.Symbol("r", positive=True)
    incoming = exp.eq145().subs({f.b_f: f.a_f, f.c_rate: rate})
    outgoing = f.friction_moment().subs(f.c_rate, rate)
    assert sp.simplify(incoming + outgoing) == 0
    assert sp.simplify(incoming - outgoing) != 0


def test_150_powers_and_alpha00():
    from derivations.haag1935.ch2_perturbations import derivation_experiment as exp
    assert sp.simplify(exp.eq150_period() - printed.eq150_period()) == 0
    assert sp.simplify(exp.eq150_amplitude() - printed.eq150_amplitude()) == 0
    at2 = exp.eq150_period().subs(exp.p_first, 2)
    assert at2.has(exp.theta0**-1) and at2.has(exp.theta0) and at2.has(exp.theta0**2)
    assert exp.alpha00() - printed.alpha00() == 0
    # exchanging the outgoing and incoming coefficients changes the sign of the condition
    swapped = exp.alpha00().subs({exp.a00: exp.b00, exp.b00: exp.a00, exp.ap00: exp.bp00, exp.bp00: exp.ap00},
                                 simultaneous=True)
    assert sp.simplify(swapped + exp.alpha00()) == 0


def test_no_dissymmetry_but_a_change_of_total_friction_is_seen():
    from derivations.haag1935.ch2_perturbations import derivation_experiment as exp
    f = derivation_friction
    assert all(x == 0 for x in exp.no_dissymmetry())
    d = sp.Symbol("d", real=True)
    moved = f.eq147().xreplace({f.a_f: f.a_f + d, f.bp_f: f.bp_f - d})    # outgoing right → incoming left
    assert sp.simplify(moved - f.eq147()) != 0
    alpha, beta = exp.alpha_beta()
    assert sp.simplify(alpha - printed.alpha_beta()[0]) == 0 and sp.simplify(beta - printed.alpha_beta()[1]) == 0
    half_a, half_b = exp.means()
    vals = {exp.alpha_f: alpha, exp.beta_f: beta}
    assert sp.simplify(half_a.subs(vals) - (f.a_f + f.ap_f) / 2) == 0
    assert sp.simplify(half_b.subs(vals) - (f.b_f + f.bp_f) / 2) == 0


@pytest.mark.slow
def test_141_at_q2_against_the_exact_blade_with_the_law_and_a_wrong_wallis_factor_fails():
    """At θ0 = 0.0004 the exact blade with the law M(c + a2c³) changes the period as (141) says to about 10⁻⁸
    relative (the next order, θ0²); i_3 in place of i_4 (one rank off in the Wallis factor) is 13 % off."""
    theta0 = mp.mpf("0.0004")
    env = truth.law_env("uniform", "compact", 30)
    with mp.workdps(40):
        true = truth.law_change("uniform", "compact")(theta0, 30)
        a2 = mp.mpf(truth.LAW_A2.p) / truth.LAW_A2.q
        formula = sp.N(truth.law_order().at(derivation.eq141(), theta0), 30)
        assert abs(formula + env["i_4"] * a2 * env["G_4"] * theta0 ** 2 / env["Q"]) < mp.mpf("1e-40")
        assert abs(true - formula) < mp.mpf("1e-7") * abs(true)
        i3 = 2 / mp.pi * mp.quad(lambda x: mp.cos(x) ** 3, [0, mp.pi / 2])
        assert abs(true - formula * i3 / env["i_4"]) > mp.mpf("0.1") * abs(true)
