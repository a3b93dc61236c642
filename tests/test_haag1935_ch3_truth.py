"""Haag 1935, chapter III: the independent truth, the numerical uniform blade (ch3_uniform.truth, truth_modes)."""
import mpmath as mp
import pytest
import sympy as sp

from derivations.haag1935.ch3_uniform import derivation_functions, truth, truth_modes
from derivations.haag1935.common import CONFIRM_DPS, DPS
from derivations.haag1935.symbols import Fn, n
from pendsym import checks

U_EXACT = "43/10"


@pytest.fixture(scope="module")
def solution():
    return truth.blade_solution(U_EXACT)


def test_grid():
    assert len(truth.grid("quick")) == 2 and len(truth.grid("full")) == 6
    along = truth.grid("full", along=True, with_K=False, extra={"Y": "1"})
    assert len(along) == 6 and {env["K"] for env in along} == {"0"} and all(env["Y"] == "1" for env in along)
    assert {round(float(env["s"]), 12) for env in along} == {0.26, 0.845}
    assert truth.grid("quick")[0] == truth.grid("full")[0]


def test_shot_ends_are_those_of_a_uniform_blade(solution):
    """v_0 = λ th(u/2)/u and β1 = λ(1 − 2 th(u/2)/u) (159), from the shooting alone."""
    with mp.workdps(DPS):
        lam_value, u_value = truth.as_mpf(truth.LAMBDA_VALUE), truth.as_mpf(sp.Rational(U_EXACT))
        assert abs(solution.v0 - lam_value * mp.tanh(u_value / 2) / u_value) < mp.mpf(10) ** -(DPS - 2)
        assert abs(solution.beta1 - lam_value * (1 - 2 * mp.tanh(u_value / 2) / u_value)) < mp.mpf(10) ** -(DPS - 2)


def test_points_carry_the_truth_and_the_formula_inputs():
    on_blade = truth.OnBlade(truth.n_times_F, truth.with_index((2, 3, 4), keep=3), truth.F_recurrence_inputs)
    with mp.workdps(40):
        points = on_blade.points("quick", DPS)
        assert len(points) == 3 and [p.env["n"] for p in points] == [2, 3, 4]
        first = points[0]
        solution = truth.blade_solution(first.env["u_exact"])
        assert first.truth == 2 * solution.F(2, mp.mpf(first.env["K"]))
        assert abs(mp.mpf(first.env[Fn(n - 1)]) - solution.F(1, mp.mpf(first.env["K"]))) < mp.mpf(10) ** -38


def test_confirmation_agrees_at_two_precisions():
    on_blade = truth.OnBlade(truth.end_value("wl"), lambda level: truth.grid(level, with_K=False))
    digits = checks.confirmation_digits(on_blade.confirm)
    assert digits >= checks.MIN_DIGITS
    with mp.workdps(40):
        (low,) = on_blade.confirm(DPS).values()
        assert low == on_blade.points("full", DPS)[0].truth
    assert CONFIRM_DPS > DPS


def test_shape_point_measures_c_through_the_shape(solution):
    with mp.workdps(40):
        env = dict(truth.grid("full", along=True)[2], Y="1", theta="0.37")
        omega_s = mp.mpf(env["u"]) / mp.mpf(env["lambda"]) * mp.mpf(env["s"])
        omega_y = truth.omega_y(solution, env)
        c_exact = (omega_y - omega_s + mp.sinh(omega_s)) / (mp.cosh(omega_s) - 1)
        point = truth.shape_point("p", env, omega_y)
        right, wrong = sp.Float(c_exact, 45), sp.Float(c_exact + mp.mpf("1e-6"), 45)
        assert point.compare(right) < mp.mpf(10) ** -35
        assert point.compare(wrong) > mp.mpf(10) ** -9


def test_power_sums_satisfy_the_recurrence_and_not_another():
    with mp.workdps(40):
        points = truth.power_sum_points("full", DPS)
        assert len(points) == 9 and max(p.residual(0) for p in points) < mp.mpf(10) ** -30
        assert max(p.residual(1) for p in points) > mp.mpf("1e-3")


def test_leading_coefficients_from_roots():
    derived = derivation_functions.S_p_leading(None)
    assert truth.leading_coefficients_from_roots(derived)
    assert not truth.leading_coefficients_from_roots(sp.Tuple(*derived[:-1], derived[-1] + 1))


def test_Gamma_over_k_power_tends_to_its_leading_coefficient():
    truth_of = truth.Gamma_over_k_power(1, 3)
    with mp.workdps(DPS):
        u_value = truth.as_mpf(sp.Rational(U_EXACT))
        top = -mp.tanh(u_value / 2) ** 2 / u_value                     # U²(−k)/u of the footnote of (166)
        far, farther = (abs(truth_of(mp.mpf(eps), DPS) - top) for eps in ("1e-2", "1e-3"))
        assert farther < far / 50


# ---------------------------------------------------------------- truth_modes
def test_normal_modes_have_the_foci_of_chapter_one(solution):
    """The principal mode's K agrees with (36), and z z' = −R² (31), on the numerical model."""
    a, R, g = mp.mpf("0.9"), mp.mpf("0.35"), mp.mpf("9.81")
    with mp.workdps(40):
        z_value, z_prime, n2, K_value = truth_modes.normal_modes(solution, a, R, g)
        assert z_prime < 0 < z_value and n2 > 0
        assert abs(z_value * z_prime + R**2) < mp.mpf(10) ** -25
        assert abs(K_value - (a + solution.wl) / (a + z_value - solution.vl)) < mp.mpf(10) ** -25


def test_modal_state_starts_from_the_static_deviation(solution):
    env = dict(truth_modes.LAUNCH, t="0")
    with mp.workdps(40):
        beta, theta = truth_modes.modal_state(solution, env, shock=False)
        Q_over_mg = mp.mpf(env["Q"]) / mp.mpf(env["g"])
        a, b = mp.mpf(env["a"]), mp.mpf(env["b"])
        assert abs(theta - Q_over_mg * (b - solution.vl) / (a + solution.wl)) < mp.mpf(10) ** -25
        assert abs(truth_modes.modal_state(solution, env, shock=True)[1]) < mp.mpf(10) ** -25


def test_value_check_fails_for_a_wrong_formula():
    """The engine with this truth rejects w_λ + 10^−20."""
    from derivations.haag1935.ch3_uniform import table_functions
    from pendsym.result import Result
    spec = next(s for s in table_functions.specs() if s.id.endswith("eq159.wl"))
    right = sp.Symbol("lambda", positive=True) / sp.Symbol("u", positive=True) / sp.tanh(sp.Symbol("u", positive=True))
    with mp.workdps(40):
        assert checks.run(spec.check, Result(spec, right), "quick").passed
        assert not checks.run(spec.check, Result(spec, right + sp.Float("1e-20")), "quick").passed
