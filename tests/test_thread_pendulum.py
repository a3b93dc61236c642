"""pendsym.thread_pendulum: the exact double pendulum (a body on a thread)."""
import mpmath as mp
import pytest

from pendsym import thread_pendulum as tp


def pendulum(**extra):
    return tp.Pendulum(mp.mpf(1), mp.mpf(1), mp.mpf("0.6"), mp.mpf("9.81"), **extra)


def test_point_body_on_a_thread_is_a_simple_pendulum_of_length_lambda_plus_a():
    """R = 0: the massless joint A lines up with O and G; one finite mode, n² = g/(λ + a)."""
    with mp.workdps(30):
        p = tp.Pendulum(mp.mpf("0.4"), mp.mpf("0.7"), 0, mp.mpf("9.81"))
        (mode,) = tp.linear_modes(p)
        assert abs(mode.n2 - mp.mpf("9.81") / mp.mpf("1.1")) < mp.mpf("1e-25")
        assert abs(mode.ratio - 1) < mp.mpf("1e-25")      # ψ = θ: a straight line


def test_very_short_thread_gives_the_compound_pendulum():
    with mp.workdps(30):
        p = tp.Pendulum(mp.mpf("1e-12"), mp.mpf("0.5"), mp.mpf("0.2"), mp.mpf("9.81"))
        low = tp.linear_modes(p)[0].n2
        assert abs(low / (mp.mpf("9.81") * mp.mpf("0.5") / (mp.mpf("0.04") + mp.mpf("0.25"))) - 1) < mp.mpf("1e-10")


def test_energy_is_conserved_by_the_exact_equations():
    """The accelerations (hand-written Lagrange equations) against the energies from the positions."""
    with mp.workdps(25):
        p = pendulum(thread_mass=mp.mpf("0.3"))
        start = (mp.mpf("0.9"), mp.mpf("-0.4"), mp.mpf("0.3"), mp.mpf("1.2"))
        sol = tp.motion(p, start)
        energy = lambda y: tp.kinetic_energy(p, *y) + tp.potential_energy(p, y[0], y[1])
        drift = abs(energy(sol(mp.mpf("0.7"))) - energy(start))
        assert drift < mp.mpf("1e-18")


def test_energy_drift_detects_a_wrong_weight():
    """The same test fails when the weight of the thread is switched off in the equations only."""
    with mp.workdps(20):
        p = pendulum(thread_mass=mp.mpf("0.3"), thread_weight=0)
        start = (mp.mpf("0.9"), mp.mpf("-0.4"), mp.mpf("0.3"), mp.mpf("1.2"))
        sol = tp.motion(p, start)
        heavy = pendulum(thread_mass=mp.mpf("0.3"))
        energy = lambda y: tp.kinetic_energy(heavy, *y) + tp.potential_energy(heavy, y[0], y[1])
        assert abs(energy(sol(mp.mpf("0.7"))) - energy(start)) > mp.mpf("1e-4")


def test_principal_mode_has_its_node_above_G():
    with mp.workdps(30):
        principal = tp.principal_mode(pendulum())
        other = max(tp.linear_modes(pendulum()), key=lambda md: md.z)
        assert principal.z < 0 < other.z
        assert principal.n2 < other.n2


@pytest.mark.slow
def test_small_amplitude_period_is_the_linear_one():
    with mp.workdps(20):
        p = pendulum()
        T0 = 2 * mp.pi / mp.sqrt(tp.principal_mode(p).n2)
        assert abs(tp.principal_period(p, mp.mpf("1e-4")) / T0 - 1) < mp.mpf("1e-8")
