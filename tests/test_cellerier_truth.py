"""derivations.cellerier.truth: the pendulum on a spring, the free pendulum, Newton's pressures."""
import mpmath as mp
import sympy as sp

from derivations.cellerier import truth
from derivations.cellerier.symbols import C, g, h, m, theta, x1dd, y1dd
from pendsym import stages


def test_lagrangian_theta_equation_is_the_memoirs_equation():
    # Euler–Lagrange θ-equation, y1'' free: C θ'' + mh cos θ y1'' + mgh sin θ = 0
    E_th, _ = truth.equations()
    eq = stages.results(["cellerier.equation"])["cellerier.equation"]
    rhs = eq.derived_value.subs({x1dd: 0})                     # −mgh sin θ + μ'(x1'' = 0)
    mine = sp.solve(E_th, truth.theta_acc)[0]
    theirs = (rhs / C).subs({sp.sin(theta): truth.sin_th, sp.cos(theta): truth.cos_th, y1dd: truth.y1_acc})
    assert sp.simplify(sp.factor(mine - theirs).subs(truth.sin_th**2, 1 - truth.cos_th**2)) == 0


def test_slow_manifold_leading_term_is_K_times_Q():
    Y0, _ = truth.slow_manifold()
    # Q = mh(θ'² sin θ + (g/l) sin θ cos θ), g/l = mgh/C; compare with S² + C² = 1
    Q = m * h * (truth.w_th**2 * truth.sin_th + m * g * h / C * truth.sin_th * truth.cos_th)
    val = sp.lambdify((truth.sin_th, truth.cos_th, truth.w_th, m, h, C, g), Y0 - Q)
    for th_, w_ in ((0.3, 0.1), (1.2, -0.7)):
        assert abs(val(mp.sin(th_), mp.cos(th_), w_, 1.3, 0.4, 0.9, 9.8)) < 1e-12


def test_massless_support_swing_is_longer():
    d = truth.delta_measured("0.05", "0.02", "0", 20)
    assert 0 < d < 0.01


def test_the_free_swing_keeps_its_energy_and_newton_pressures():
    traj = truth.free_swing_trajectory("0.8", 20)
    with mp.workdps(20):
        th, w = traj(mp.mpf("1.1"))
        assert abs(w**2 / 2 - (mp.cos(th) - mp.cos(mp.mpf("0.8")))) < mp.mpf("1e-15")
        P, Q = truth.newton_pressures(traj, mp.mpf("1.1"))
        # Q = −(sin θ)'' = sin θ θ'² + cos θ sin θ with θ'' = −sin θ
        assert abs(Q - (mp.sin(th) * w**2 + mp.cos(th) * mp.sin(th))) < mp.mpf("1e-8")


def test_lie_derivative_of_cos_theta():
    assert truth.lie_derivative(truth.cos_th, -truth.sin_th) == -truth.sin_th * truth.w_th
