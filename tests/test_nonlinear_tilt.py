"""Clamping errors on the exact blade: the tilted equilibrium and the small oscillation about it."""
import mpmath as mp
import pytest
import sympy as sp

from pendsym import blade as linear_blade
from pendsym import nonlinear_blade, nonlinear_tilt, suspension

UNIFORM = linear_blade.Blade(sp.Rational(1, 10), sp.Rational(1, 400))
COMPACT = ("0.12", "0.05", "9.81")


def test_no_tilt_is_the_straight_blade_and_its_linear_period():
    """i = i' = 0: the blade stays straight, and the period of the small oscillation (elastica Jacobian,
    3×3 eigenproblem in the loads) is the linear blade's 2π/n (pendsym.suspension's 2×2 eigenproblem)."""
    a, R, g = COMPACT
    st = nonlinear_tilt.tilted(UNIFORM, a, R, g, "0", "0", 30)
    assert st.theta == 0 and st.beta == 0 and st.c0 == 0
    T_lin = nonlinear_blade.linear_period(UNIFORM, a, R, g, 30)
    assert abs(st.period - T_lin) < mp.mpf("1e-28") * T_lin


def linear_equilibrium(i, i_prime):
    """The small-tilt equilibrium of the linearised blade (pendsym.suspension's end loads, no v, w): the
    end position (β, θ) with Y = −i and N = a(Y − θ − i') (X = 1)."""
    a = mp.mpf(COMPACT[0])
    sus = suspension.solve(UNIFORM, 30)
    with mp.workdps(40):
        _, Yb, Nb = sus.loads(1, 0)
        _, Yt, Nt = sus.loads(0, 1)
        # Yb β + Yt θ = −i ;  Nb β + Nt θ = a(−i − θ − i')
        sol = mp.lu_solve(mp.matrix([[Yb, Yt], [Nb, Nt + a]]), mp.matrix([-i, -a * (i + i_prime)]))
        return sol[0], sol[1]


def test_tilted_equilibrium_against_the_linear_blade():
    """The exact equilibrium (θ, β) against the linearised blade's, at i' = −0.7i: the difference falls like
    i³ (the equilibrium is odd in (i, i') by the mirror symmetry), and is small against i."""
    a, R, g = COMPACT
    errs = []
    for i in (mp.mpf("0.004"), mp.mpf("0.002")):
        st = nonlinear_tilt.tilted(UNIFORM, a, R, g, mp.nstr(i, 30), mp.nstr(-7 * i / 10, 30), 30)
        beta_lin, theta_lin = linear_equilibrium(i, -7 * i / 10)
        assert abs(theta_lin) > i / 10                      # the tilt does move the pendulum
        errs.append(abs(st.theta - theta_lin) + abs(st.beta - beta_lin) / mp.mpf("0.1"))
    assert errs[0] < mp.mpf("1e-5") * mp.mpf("0.004")
    assert 6 < errs[0] / errs[1] < 10                      # ≈ 8: third order


@pytest.mark.slow
def test_mirror_symmetry_and_second_order_period():
    """(i, i') → (−i, −i') mirrors the system: θ changes sign, the period does not; the period's change
    is of the second order in the tilt (ratio ≈ 4 when i halves)."""
    a, R, g = COMPACT
    T0 = nonlinear_blade.linear_period(UNIFORM, a, R, g, 30)
    up = nonlinear_tilt.tilted(UNIFORM, a, R, g, "0.004", "0.001", 30)
    down = nonlinear_tilt.tilted(UNIFORM, a, R, g, "-0.004", "-0.001", 30)
    half = nonlinear_tilt.tilted(UNIFORM, a, R, g, "0.002", "0.0005", 30)
    assert abs(up.theta + down.theta) < mp.mpf("1e-30")
    assert abs(up.period - down.period) < mp.mpf("1e-30") * T0
    ratio = (up.period / T0 - 1) / (half.period / T0 - 1)
    assert abs(ratio - 4) < mp.mpf("1e-4")
