"""The direct (no v, w) small-oscillation truth of pendsym.suspension, checked by physics of its own."""
import mpmath as mp
import pytest
import sympy as sp

from pendsym import blade as linear_blade
from pendsym import suspension

s = linear_blade.S


def test_stiffness_is_symmetric_for_an_unsymmetric_blade():
    """Reciprocity ∂Y/∂θ = ∂N/∂β (the loads derive from an energy) on a tapered blade."""
    sus = suspension.solve(linear_blade.Blade(sp.Rational(1, 10), sp.Rational(1, 800) * (1 + s * 10) ** 3), 30)
    S = sus.stiffness
    with mp.workdps(40):
        assert abs(S[0, 1] - S[1, 0]) < mp.mpf(10) ** -28 * abs(S[0, 1])


def test_stiff_blade_is_the_guided_cantilever():
    """M ≫ λ²: the tension is negligible, Y = 12Mβ/λ³ − 6Mθ/λ², N = −6Mβ/λ² + 4Mθ/λ (beam theory),
    with a relative correction O(λ²/M) that shrinks tenfold when M grows tenfold."""
    lam = sp.Integer(1)
    errs = []
    for M in (sp.Integer(100), sp.Integer(1000)):
        S = suspension.solve(linear_blade.Blade(lam, M), 20).stiffness
        Mf = mp.mpf(int(M))
        beam = mp.matrix([[12 * Mf, -6 * Mf], [-6 * Mf, 4 * Mf]])
        errs.append(max(abs(S[i, j] - beam[i, j]) / abs(beam[i, j]) for i in range(2) for j in range(2)))
    assert errs[0] < 0.02
    assert 8 < errs[0] / errs[1] < 12


def test_limp_blade_is_a_thread():
    """M → 0: the thread of length λ, Y = β/λ, N → 0; the corrections are O(√M) (tenfold smaller
    for M a hundredfold smaller)."""
    devs = []
    for M in (sp.Rational(1, 100), sp.Rational(1, 10**4)):
        S = suspension.solve(linear_blade.Blade(1, M), 20).stiffness
        devs.append(max(abs(S[0, 0] - 1), abs(S[1, 1]), abs(S[0, 1])))
    assert devs[1] < 0.03
    assert 7 < devs[0] / devs[1] < 15


def test_rigid_pendulum_limit_of_the_modes():
    """A very short, limp blade is a pivot at O: the principal mode is the compound pendulum about O,
    n² = g(a + λ)/((a + λ)² + R²), and its node (the upper focus) is O itself."""
    lam, a, R, g = sp.Rational(1, 1000), "0.5", "0.1", "9.81"
    sus = suspension.solve(linear_blade.Blade(lam, lam**2 / 10**4), 20)          # u = λ/√M = 100
    principal, parasitic = suspension.modes(sus, a, R, g)
    L = mp.mpf(a) + mp.mpf(1) / 1000
    expected = mp.mpf(g) * L / (L**2 + mp.mpf(R) ** 2)
    assert abs(principal.n2 / expected - 1) < 1e-3
    assert parasitic.n2 > 1e4 * principal.n2
    assert abs(principal.z + L) < 1e-3 * L
    assert principal.z < 0 < parasitic.z


def test_static_offset_balances_the_loads():
    sus = suspension.solve(linear_blade.Blade(sp.Rational(1, 10), sp.Rational(1, 400)), 20)
    b0, t0 = suspension.static_offset(sus, "0.9", "0.5", "0.01")
    with mp.workdps(30):
        c, Y, N = sus.loads(b0, t0)
        assert abs(Y - mp.mpf("0.01")) < 1e-20
        assert abs(N - (mp.mpf("0.01") * mp.mpf("0.5") - mp.mpf("0.9") * t0)) < 1e-20


def test_deflection_meets_the_end_position():
    sus = suspension.solve(linear_blade.Blade(sp.Rational(1, 10), sp.Rational(1, 400)), 20)
    y, phi, _ = sus.deflection(sp.Rational(1, 10), "0.003", "0.02")
    assert abs(y - mp.mpf("0.003")) < 1e-18 and abs(phi - mp.mpf("0.02")) < 1e-18


def test_singular_inverted_blade_is_reported():
    """M < 0 with λ/√(−M) = 2π: the clamped–clamped column buckles (y = 1 − cos(2πs/λ) carries no
    end displacement), so the end position does not determine the loads: SingularBlade."""
    with pytest.raises(linear_blade.SingularBlade):
        suspension.solve(linear_blade.Blade(1, -1 / (4 * sp.pi**2)), 20)
    suspension.solve(linear_blade.Blade(1, -1 / (3 * sp.pi**2)), 20)      # between the buckling values: regular
