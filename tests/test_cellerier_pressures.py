"""derivations.cellerier.pressures: P, Q, F, F' and their maxima."""
import mpmath as mp
import sympy as sp

from derivations.cellerier import pressures
from derivations.cellerier.symbols import alpha, g, l, m, h, theta, thetad
from pendsym import checks, stages


def test_F_is_the_centrifugal_force():
    F, Fp = pressures.components()
    assert sp.simplify(F - m * h * thetad**2) == 0                 # + m h θ'², against the printed −
    assert sp.simplify(Fp - pressures.PRINTED["Fp"]) == 0


def test_the_free_motion_energy_integral():
    assert sp.simplify(pressures.free_motion()[thetad**2] - 2 * g / l * (sp.cos(theta) - sp.cos(alpha))) == 0


def test_maxima_on_the_swing():
    built = stages.results(["cellerier.F_max", "cellerier.Fp_max"])
    assert sp.simplify(built["cellerier.F_max"].derived - pressures.PRINTED["F_max"]) == 0
    assert sp.simplify(built["cellerier.Fp_max"].derived - pressures.PRINTED["Fp_max"]) == 0


def test_max_on_the_integrated_swing():
    # θ'² is largest at the lowest point: 2(1 − cos α) for g = l = 1
    value = pressures.max_on_trajectory("0.3", pressures.F_on_swing, 20)
    with mp.workdps(20):
        assert abs(value - 2 * (1 - mp.cos(mp.mpf("0.3")))) < mp.mpf("1e-12")


def test_projection_check_sides_with_the_derived_F():
    built = stages.results(["cellerier.F"])
    assert isinstance(built["cellerier.F"].spec.check, checks.Values)
    ev = stages.assessed(built["cellerier.F"])[1]
    assert ev.passed and ev.printed_agrees is False


def test_the_horizontal_pressure_dominates():
    assert pressures.ratio_derived({}) == alpha
