"""Haag 1935, chapter II, n°26–30: the derivation of (88)–(114) and its printed forms."""
import mpmath as mp
import sympy as sp

from derivations.haag1935.ch2_common import F_110, H_moments, J, eps1, in_F
from derivations.haag1935.ch2_general import derivation, printed, table, truth
from derivations.haag1935.symbols import Fn, K, R, Y, a, theta, theta_ddot, theta_dot, z, zp


def test_first_order_terms_of_f_vanish_on_the_foci():
    assert derivation.first_order_vanishes() == 0


def test_f_91_as_printed():
    assert sp.simplify(derivation.eq91() - printed.eq91()) == 0


def test_green_identities_give_101_and_102():
    assert derivation.green_identities() == (-1, 0)
    assert sp.simplify(derivation.Delta_Y() - printed.eq101()) == 0
    assert sp.simplify(derivation.Delta_N() - printed.eq102()) == 0


def test_104_with_the_ocr_readings():
    assert sp.expand(derivation.eq104() - printed.eq104()) == 0


def test_109_needs_the_H2_reading():
    """The OCR's ½ε4(K∂H4/∂Y + ∂H4/∂θ) read literally (ε1 and H4) does not give the derived bracket;
    with H2 it does."""
    defs = dict(printed.DEF_EPS1)
    derived = derivation.eq109_bracket().subs(defs)
    as_read = printed.eq109().subs(defs)
    assert sp.expand(derived - as_read) == 0
    literal = as_read + (eps1 / 2 * (K * sp.diff(H_moments(4) - H_moments(2), Y)
                                     + sp.diff(H_moments(4) - H_moments(2), theta))).subs(defs)
    assert sp.expand(derived - literal) != 0


def test_identity_before_108_and_euler_identities():
    assert derivation.identity_108() == 0
    assert sp.expand(derivation.euler_H2() - 2 * theta * Fn(2)) == 0
    assert sp.expand(derivation.euler_H() - 4 * theta**3 * printed.eq110()) == 0


def test_in_F_rejects_a_moment_that_is_not_an_F():
    try:
        in_F(J(1, 0))
    except ValueError:
        return
    raise AssertionError("∫φ1 ds is not a combination of the F_n")


def test_112_is_printed_and_111_reduces_to_the_rigid_pendulum():
    """Q' derived equals the printed (112) with F = 4KF3 − F4; for a blade reduced to a hinge (F_n = 0,
    z' = −a, z = R²/a, K = a²/(a² + R²)) ΔT/T is θ0²/16, the rigid pendulum's."""
    assert sp.expand(derivation.eq112() - printed.eq112().subs(F_110, printed.eq110())) == 0
    hinge = {Fn(2): 0, Fn(3): 0, Fn(4): 0, zp: -a, z: R**2 / a, K: a**2 / (a**2 + R**2)}
    theta0 = sp.Symbol("theta_0", positive=True)
    assert sp.simplify(derivation.eq111().subs(hinge) - theta0**2 / 16) == 0


def test_f_of_the_principal_oscillation_is_A_theta3_plus_B_theta_thetadot2():
    A, B = derivation.A_and_B()
    f = derivation.f_principal()
    n2 = sp.Symbol("n^2", positive=True)
    assert sp.expand(f - A * n2 * theta**3 - B * theta * theta_dot**2) == 0
    assert not f.has(theta_ddot) and not f.has(sp.Symbol("alpha''", real=True))


def test_classical_formula_on_the_rigid_pendulum():
    """(114) with Φ = n²θ³/6 gives θ0²/16; the exact period's relative change at θ0 = 1e-3 agrees to θ0⁴."""
    ph, theta0 = sp.symbols("phi theta_0", positive=True)
    n2 = sp.Symbol("n^2", positive=True)
    C = sp.integrate(n2 * (theta0 * sp.cos(ph)) ** 3 / 6 * sp.cos(ph), (ph, 0, 2 * sp.pi))
    rel = derivation.eq114_relative().subs(sp.Symbol("C"), C)
    assert sp.simplify(rel - theta0**2 / 16) == 0
    with mp.workdps(40):
        exact = truth.rigid_relative(mp.mpf("1e-3"), 40)
        assert abs(exact - mp.mpf("1e-6") / 16) < mp.mpf("1e-12")


def test_every_equation_from_88_to_112_has_a_result():
    ids = {spec.id.split(".")[1] for spec in table.specs()}
    expected = {f"eq{k:03d}" for k in (*range(88, 95), *range(101, 113), 114)}
    assert expected <= ids


# ---------------------------------------------------------------- n°27 by the variation of constants, n°30
def test_variation_of_constants_solves_96_and_gives_101():
    from derivations.haag1935.ch2_general import variation
    assert variation.eq97_solves_96() == 0
    assert sp.simplify(variation.eq101_by_constants() - derivation.Delta_Y()) == 0
    assert sp.expand(variation.eq99() - printed.eq99()) == 0


def test_98_with_the_ocr_primes_is_not_the_derivation():
    """The OCR's A = −(1/w0)∫ε'w' ds (primes on w) is not the variation of constants' −(1/w0)∫ε'w ds."""
    from derivations.haag1935.ch2_general import variation
    sg, ef = variation.sigma, variation.eps_f
    literal = -1 / variation.w0 * sp.Integral(ef(sg).diff(sg) * variation.w(sg).diff(sg), (sg, 0, variation.s))
    assert sp.simplify(variation.eq98_integrals()[0] - printed.eq98_integrals()[0]) == 0
    assert sp.simplify(variation.eq98_integrals()[0] - literal) != 0


def test_direct_boundary_value_problem_gives_I1_over_beta1():
    """ΔY of (93) solved directly, against ∫εφ1 ds/β1 on the shot uniform blade; and against a wrong
    candidate (∫εφ2 ds/β1), which it must miss."""
    from derivations.haag1935 import profiles
    shot = profiles.shot_blade("uniform", 30)
    with mp.workdps(shot.wdps):
        eps = truth._test_eps(profiles.as_mpf(shot.blade.length))
        I1 = shot.integrate(lambda x: eps(x) * shot.phi1(x))
        I2 = shot.integrate(lambda x: eps(x) * shot.phi2(x))
        dY = truth.direct_delta_Y("uniform", 30)
        assert abs(dY - I1 / shot.beta1) < mp.mpf("1e-28") * abs(dY)
        assert abs(dY - I2 / shot.beta1) > mp.mpf("1e-3") * abs(dY)


def test_calculable_terms_and_the_pendulum_footnote():
    from derivations.haag1935.ch2_general import variation
    assert set(variation.nonzero_calculable()) == {0}
    assert variation.calculable_terms(2, 1) == (0, 0, 0)          # p even, q odd: nothing calculable
    assert variation.pendulum_next_term() == sp.Rational(-1, 384)
    with mp.workdps(40):
        t0 = mp.mpf("1e-4")
        c4 = (truth.rigid_relative(t0, 40) - t0**2 / 16) / t0**4
        assert abs(c4 - mp.mpf(11) / 3072) < mp.mpf("1e-6")       # the true coefficient is not −1/384


def test_table_covers_88_to_115():
    ids = {s.id.rsplit(".", 1)[0] for s in table.specs()}
    assert {f"haag1935.eq{n:03d}" for n in range(88, 116)} <= ids
    numbers = [int(s.id.split(".")[1][2:]) for s in table.specs()]
    assert numbers == sorted(numbers)
