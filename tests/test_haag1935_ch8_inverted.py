"""Haag 1935, chapter VIII: the inverted blade's truth (M < 0, g < 0, solved directly) and its windows."""
import mpmath as mp
import sympy as sp

from derivations.haag1935.ch8_inverted import derivation, truth


def test_inverted_critical_distance_and_beta1_from_the_direct_stiffness():
    with mp.workdps(30):
        u = mp.mpf(1)
        assert abs(truth.critical("u=1") - mp.mpf("0.1") / (u * mp.tan(u))) < mp.mpf("1e-25")
        assert abs(truth.beta1("u=1") - mp.mpf("0.1") * (1 - 2 * mp.tan(u / 2) / u)) < mp.mpf("1e-25")
        # (308): β1 < 0 for 0 < u < π, β1 > 0 between π and 2x1
        assert truth.beta1("u=5/2") < 0 and truth.beta1("u=1") < 0 < truth.beta1("u=6")


def test_stable_inside_a_window_and_unstable_outside():
    with mp.workdps(30):
        inside = truth.eigenvalues(mp.mpf("9.2"), mp.mpf(-1), 30)      # 2x1 < 9.2 < 3π
        outside = truth.eigenvalues(mp.mpf("6"), mp.mpf(-1), 30)       # π < 6 < 2x1
        assert min(inside) > 0
        assert min(outside) < 0


def test_lower_end_of_the_first_window_is_twice_the_root_of_tan_x_equal_x():
    with mp.workdps(30):
        end = truth.lower_end("8.99", 30)
        assert abs(end - 2 * mp.findroot(lambda x: mp.tan(x) - x, 4.49)) < mp.mpf("1e-20")
        assert abs((end / (mp.pi / 2)) ** 2 - mp.mpf("32.7")) > mp.mpf("0.01")   # the printed 32.7 is rounded
    assert abs(derivation.x1_of_308() - sp.Float("4.4934094579090641753", 20)) < 1e-18


def test_existence_iff_accepts_the_potential_coefficients_and_refuses_a_wrong_sign():
    from types import SimpleNamespace

    from derivations.haag1935.symbols import a, beta1, wl
    right = SimpleNamespace(derived_value=sp.Tuple(beta1, a + wl))
    wrong = SimpleNamespace(derived_value=sp.Tuple(-beta1, a + wl))
    assert truth.ExistenceIff()(right, "quick").passed
    assert not truth.ExistenceIff()(wrong, "quick").passed


def test_potential_coefficients_are_beta1_and_a_plus_w_lambda():
    from derivations.haag1935.symbols import a, beta1, wl
    assert derivation.potential_coefficients(None) == sp.Tuple(beta1, a + wl)


def test_upper_ends_of_the_windows_are_the_zeros_of_the_transverse_stiffness():
    """(309) as a → −∞: S00 = 1/β1 of the direct inverted blade vanishes at π and 3π."""
    with mp.workdps(30):
        assert abs(truth.far_upper_end("9.42", 30) - 3 * mp.pi) < mp.mpf("1e-25")
        assert abs(truth.far_upper_end("3.14", 30) - mp.pi) < mp.mpf("1e-25")


def test_window_signs_accept_the_derived_windows_and_refuse_shifted_ones():
    from types import SimpleNamespace
    right = SimpleNamespace(derived_value=derivation.windows_309(None))
    shifted = SimpleNamespace(derived_value=sp.Tuple(2 * derivation.x1_of_308(), 3 * sp.pi, 2 * sp.pi))
    assert truth.WindowSigns()(right, "quick").passed
    assert not truth.WindowSigns()(shifted, "quick").passed    # u = 3 … 5 would be claimed stable


def test_mode_signs_accept_302_and_refuse_the_swapped_signs():
    from types import SimpleNamespace

    from derivations.haag1935.symbols import K, K_prime
    assert truth.NegativeIffExists("K, −K'")(SimpleNamespace(derived_value=sp.Tuple(K, -K_prime)), "quick").passed
    assert not truth.NegativeIffExists("−K, K'")(SimpleNamespace(derived_value=sp.Tuple(-K, K_prime)), "quick").passed


def test_303_is_necessary_but_not_sufficient():
    """With β1 > 0 and a + wλ > 0 (u = 6, a > a1) both n² are negative while (303) holds: only the implication."""
    from types import SimpleNamespace

    from derivations.haag1935.symbols import a, vl, z, zp
    claim = SimpleNamespace(derived_value=sp.Tuple(a + zp - vl, -(a + z - vl)))
    assert truth.NegativeIffExists("(303)", iff=False)(claim, "quick").passed
    assert not truth.NegativeIffExists("(303)", iff=True)(claim, "quick").passed


def test_306_and_308_refuse_the_opposite_sign():
    from types import SimpleNamespace

    from derivations.haag1935.symbols import u, wl
    assert truth.PositiveDistanceIff()(SimpleNamespace(derived_value=wl), "quick").passed
    assert not truth.PositiveDistanceIff()(SimpleNamespace(derived_value=-wl), "quick").passed
    assert truth.PositiveIffStable()(SimpleNamespace(derived_value=sp.tan(u / 2) - u / 2), "quick").passed
    assert not truth.PositiveIffStable()(SimpleNamespace(derived_value=u / 2 - sp.tan(u / 2)), "quick").passed


def test_n2_of_the_inverted_blade_is_the_mode_with_the_upper_node_and_vanishes_at_a1():
    """The scenes' n² (n°101 with n°50): the truth's mode with node z' < 0, which near a1 is the slow one; the
    derived form agrees with it, changes sign at a1 (n² ∝ a1 − a) and is not the fast mode's n²."""
    from pendsym import verify
    from pendsym.scenes.evaluate import build
    from derivations.haag1935.ch7_gravity import truth as gravity
    a, n2 = truth.node_mode_n2("u=1", "-0.01")
    with mp.workdps(40):
        sus = gravity.direct("u=1", -1)
        fast = max(x for x, _ in gravity.eigenmodes(sus, a, gravity.R_VALUE, -mp.mpf(gravity.G_VALUE)))
    assert 0 < n2 < fast / 100                     # the slow mode, far below the fast one
    form = build(["haag1935.eq034.n2_inverted"])["haag1935.eq034.n2_inverted"].derived
    a1 = truth.critical("u=1")
    with mp.workdps(40):
        env = {"u": mp.mpf(1), "lambda": mp.mpf("0.1"), "R": mp.mpf(gravity.R_VALUE), "g": mp.mpf(gravity.G_VALUE)}
        assert abs(verify.value_at(form, dict(env, a=a)) / n2 - 1) < mp.mpf("1e-25")
        assert abs(verify.value_at(form, dict(env, a=a)) / fast - 1) > mp.mpf("0.5")
        assert verify.value_at(form, dict(env, a=a1 + mp.mpf("0.01"))) < 0 < verify.value_at(form, dict(env, a=a1 - mp.mpf("0.001")))
