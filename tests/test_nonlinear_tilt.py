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


# The regulator's spring steel (scenes/regulator_spring_blade.toml: E = 200 GPa, 20 mm × 0.1 mm, 6.35 kg, g of
# London) at a span of 30 mm: u = λ√(mg/EI) ≈ 13, sh u ≈ 2e5 (the clamp's couple reaches the end through e^u).
# Before the multiple shooting of nonlinear_tilt.equilibrium, Newton from c0 = 0 ran to a looped elastica there
# (θ ≈ −2π − 0.03) and the period's change came out −4.4e-3 instead of about −8.5e-8.
STEEL = ("2.0e11", "0.02", "1.0e-4", "6.35", "9.8119")
REGULATOR = ("0.982", "0.08", "9.8119")                 # a, R, g of the scene


def steel_blade(length: str) -> linear_blade.Blade:
    E, width, thickness, mass, g = (mp.mpf(x) for x in STEEL)
    with mp.workdps(40):
        M = E * width * thickness**3 / 12 / (mass * g)
    return linear_blade.Blade(sp.Rational(length), sp.Float(M, 40))


def haag_250(i, i_prime, lam, a, u):
    """Haag (250), ΔT/T = −(λ/(16au))(3i² + 4ij + 2j²), with j of (247), j + i + i' = (λ/(au))(i/sh u + i'/th u),
    as printed (n°80, n°32): the short blade's first order in λ/a, R²/a² neglected (the test's reference, not
    the engine's)."""
    j = lam / (a * u) * (i / mp.sinh(u) + i_prime / mp.tanh(u)) - i - i_prime
    return -lam / (16 * a * u) * (3 * i * i + 4 * i * j + 2 * j * j)


def regulator_change(blade, i, i_prime, dps=15):
    """(T(i, i')/T(0, 0) − 1, θ) on the steel blade under the regulator's pendulum."""
    st = nonlinear_tilt.tilted(blade, *REGULATOR, mp.nstr(i, 20), mp.nstr(i_prime, 20), dps)
    with mp.workdps(dps):
        return st.period / nonlinear_blade.linear_period(blade, *REGULATOR, dps) - 1, st.theta


@pytest.mark.slow
def test_stiff_blade_at_u13_is_quadratic_in_the_angles_and_agrees_with_250():
    """u ≈ 13: the equilibrium is the straight blade's branch (θ near −(i + i'), not shifted by 2π), the period's
    change falls like the square of the angles (fitted order 2 over i = 0.02, 0.01, 0.005 at i' = i/2), and
    agrees with (250) within (250)'s first-order error, |(250)|(λ/a + 2R²/a²)."""
    blade = steel_blade("0.03")
    a, R = mp.mpf(REGULATOR[0]), mp.mpf(REGULATOR[1])
    lam = mp.mpf("0.03")
    u = lam / mp.sqrt(suspension.number(blade.M))
    assert 12.9 < u < 13.1
    changes = []
    for i in (mp.mpf("0.02"), mp.mpf("0.01"), mp.mpf("0.005")):
        change, theta = regulator_change(blade, i, i / 2)
        assert abs(theta + 3 * i / 2) < 0.01 * i, theta           # j ≈ θ + i' ≈ −i − i' + O(√M/a)
        changes.append(change)
    orders = [mp.log(changes[k] / changes[k + 1], 2) for k in range(2)]
    assert all(abs(p - 2) < 1e-3 for p in orders), orders
    reference = haag_250(mp.mpf("0.02"), mp.mpf("0.01"), lam, a, u)
    assert abs(changes[0] - reference) <= abs(reference) * (lam / a + 2 * R * R / (a * a)), (changes[0], reference)


@pytest.mark.slow
@pytest.mark.parametrize("length, u_range", [("0.00116", (0.45, 0.55)), ("0.0463", (19.9, 20.1))])
def test_the_branch_and_the_second_order_hold_from_u_half_to_u_20(length, u_range):
    """The ends of the range the solver is meant for: the equilibrium is on the straight blade's branch (θ within
    the linear blade's by 1e-3 of itself) and the change is of the second order (ratio 4 when the angles halve)."""
    blade = steel_blade(length)
    u = mp.mpf(length) / mp.sqrt(suspension.number(blade.M))
    assert u_range[0] < u < u_range[1]
    full, theta = regulator_change(blade, mp.mpf("0.02"), mp.mpf("0.01"))
    half, _ = regulator_change(blade, mp.mpf("0.01"), mp.mpf("0.005"))
    sus = suspension.solve(blade, 20)
    with mp.workdps(40):
        S, a = sus.stiffness, mp.mpf(REGULATOR[0])
        # linear statics (X = 1, Y = −i): S·(β, θ) = (Y, N), N = a(Y − θ − i')
        theta_lin = mp.lu_solve(mp.matrix([[S[0, 0], S[0, 1]], [S[1, 0], S[1, 1] + a]]),
                                mp.matrix([-mp.mpf("0.02"), -a * mp.mpf("0.03")]))[1]
    assert abs(theta - theta_lin) < mp.mpf("1e-3") * abs(theta_lin), (theta, theta_lin)
    assert abs(full / half - 4) < 1e-3, full / half


def test_a_looped_elastica_is_refused():
    """The branch guard: an end angle off by 2π (a looped elastica) is refused with a clear error."""
    with pytest.raises(nonlinear_blade.NoConvergence, match="looped elastica"):
        nonlinear_tilt.check_branch(-2 * mp.pi - mp.mpf("0.03"), mp.mpf("0.02"), mp.mpf("0.01"))
    nonlinear_tilt.check_branch(mp.mpf("-0.03"), mp.mpf("0.02"), mp.mpf("0.01"))
