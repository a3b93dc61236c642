"""Haag 1935, chapter VII: the gravity pendulum's derivation steps and its truth (direct blade, eigenproblem)."""
import mpmath as mp
import sympy as sp

from derivations.haag1935.ch7_gravity import derivation, printed, truth
from derivations.haag1935.symbols import R


def test_foci_at_the_critical_distance_are_w0_and_minus_R2_over_w0():
    # (30) at a = a1: the roots of n°83; a wrong candidate is refused
    assert sp.simplify(derivation.zp_257(None) - printed.eq257().subs(printed.eps_p, printed.eq258())) == 0
    try:
        derivation.root_series(R)
    except ValueError:
        pass
    else:
        raise AssertionError("R is not a root of (30) at ε = 0")


def test_slow_mode_tends_to_265_and_fails_with_a_wrong_power():
    with mp.workdps(30):
        env = truth.state("u=2", 1, "1e-5")
        formula = env["varepsilon"] * env["g"] * env["lambda"] / (env["R"] ** 2 + env["w_0"] ** 2)
        assert abs(env["n^2"] / formula - 1) < mp.mpf("1e-3")
        wrong = env["varepsilon"] * env["g"] * env["lambda"] / (env["R"] ** 2 + env["w_0"])
        assert abs(env["n^2"] / wrong - 1) > mp.mpf("0.5")
        assert env["n'^2"] > 100 * env["n^2"] > 0


def test_critical_distance_of_the_direct_uniform_blade_is_minus_w_lambda():
    with mp.workdps(30):
        env = truth.numbers("u=2", 1)
        assert abs(env["a_1"] + env["w_lambda"]) < mp.mpf("1e-25")
        assert abs(env["w_lambda"] - mp.mpf("0.1") / (2 * mp.tanh(2))) < mp.mpf("1e-25")


def test_sensitivity_is_large_and_positive_near_the_critical_distance():
    with mp.workdps(30):
        G = truth.sensitivity("u=2", 1, "1e-4")
        u = mp.mpf(2)
        assert abs(G * mp.mpf("1e-4") - (1 / mp.sinh(u) ** 2 + mp.coth(u) / u) / 2) < mp.mpf("1e-3")
