"""The blade with mass (pendsym.massive_blade) against truths it does not compute itself.

* no mass: the principal n² of pendsym.suspension.modes (the massless blade, solved another way);
* uniform blade with its inertia only: the state equations have constant coefficients, so the blade's
  transfer matrix is mpmath's expm(Aλ), and the root of the same 2×2 determinant follows without odefun;
* the signs of the two effects and their proportionality to the mass at small mass.
"""
import mpmath as mp
import pytest
import sympy as sp

from pendsym import blade, massive_blade, suspension

LAM, M0 = sp.Rational(1, 10), sp.Rational(1, 400)
PEND = ("0.12", "0.05", "9.81")


def uniform(mass: str, inertia=True, weight=True):
    return massive_blade.MassiveBlade(blade.Blade(LAM, M0), sp.Rational(mass) / LAM, inertia, weight)


def test_massless_blade_gives_the_modes_of_suspension():
    n2 = massive_blade.principal_n2(uniform("0"), *PEND, dps=30)
    with mp.workdps(40):
        ref = suspension.modes(suspension.solve(blade.Blade(LAM, M0), 30), *(mp.mpf(x) for x in PEND))[0].n2
        assert abs(n2 - ref) < mp.mpf(10) ** -27 * ref


def test_inertia_of_a_uniform_blade_against_the_transfer_matrix():
    mass = "0.05"
    n2 = massive_blade.principal_n2(uniform(mass, weight=False), *PEND, dps=30)
    with mp.workdps(45):
        a, R, g = (mp.mpf(x) for x in PEND)
        lam, M, rho = mp.mpf(1) / 10, mp.mpf(1) / 400, mp.mpf(mass) * 10

        def det(om2):
            # u = (y, φ, Mφ', Y): y' = φ, φ' = c/M, c' = φ − Y, Y' = −(ω²/g)ρ y
            A = mp.matrix([[0, 1, 0, 0], [0, 0, 1 / M, 0], [0, 1, 0, -1], [-om2 / g * rho, 0, 0, 0]])
            T = mp.expm(A * lam)
            rows = []
            for col in (2, 3):
                be, th, N, Y = (T[i, col] for i in range(4))
                rows.append((om2 * (be + a * th) - g * Y, -om2 * R * R * th + g * (N - a * Y + a * th)))
            return rows[0][0] * rows[1][1] - rows[0][1] * rows[1][0]
        ref = mp.findroot(det, n2 * (1 + mp.mpf(10) ** -8))
        assert abs(n2 - ref) < mp.mpf(10) ** -26 * ref


def test_inertia_delays_weight_advances_in_proportion_to_the_mass():
    d1 = massive_blade.relative_period_change(uniform("0.001", True, False), *PEND, dps=20)
    d2 = massive_blade.relative_period_change(uniform("0.002", True, False), *PEND, dps=20)
    w1 = massive_blade.relative_period_change(uniform("0.001", False, True), *PEND, dps=20)
    assert d1 > 0 > w1
    assert abs(d2 / d1 - 2) < mp.mpf("0.01")


def test_density_must_depend_on_s_only():
    with pytest.raises(ValueError):
        massive_blade.MassiveBlade(blade.Blade(LAM, M0), sp.Symbol("k"))
