"""pendsym.perturbation: variation of constants, for any k, φ(θ, θ', t) and initial state."""
import mpmath as mp
import pytest
import sympy as sp

from pendsym import perturbation as pt
from pendsym import truth, verify

t = sp.Symbol("t", nonnegative=True)
k = sp.Symbol("k", positive=True)
eps = sp.Symbol("epsilon", real=True)
th, dth = sp.symbols("theta thetadot", real=True)


@pytest.mark.slow
def test_theta1_solves_the_forced_equation_exactly():
    # θ1'' + k²θ1 = −εφ(t) for the Duhamel form, with φ explicit in t
    phi_t = t * sp.cos(3 * t) + sp.sin(k * t) ** 2
    Es, Ec = pt.E_s(phi_t, t, k), pt.E_c(phi_t, t, k)
    th1 = pt.theta1(Es, Ec, eps, k, t)
    assert sp.simplify(sp.diff(th1, t, 2) + k**2 * th1 + eps * phi_t) == 0
    assert sp.simplify(th1.subs(t, 0)) == 0
    assert sp.simplify(sp.diff(th1, t).subs(t, 0)) == 0


def test_dtheta1_is_the_derivative_of_theta1():
    phi_t = sp.cos(k * t) ** 3 + t
    Es, Ec = pt.E_s(phi_t, t, k), pt.E_c(phi_t, t, k)
    d = sp.diff(pt.theta1(Es, Ec, eps, k, t), t) - pt.dtheta1(Es, Ec, eps, k, t)
    assert sp.simplify(d) == 0


def test_E_s_matches_quadrature_for_k_not_one():
    phi_t = sp.exp(-t) * sp.cos(2 * t)
    Es = sp.lambdify((t, k), pt.E_s(phi_t, t, k), modules="mpmath")
    with mp.workdps(30):
        for kv, tv in ((mp.mpf("2.5"), mp.mpf("1.7")), (mp.mpf("0.4"), mp.mpf("3.1"))):
            ref = mp.quad(lambda s: mp.exp(-s) * mp.cos(2 * s) * mp.sin(kv * s), [0, tv])
            assert abs(Es(tv, kv) - ref) < mp.mpf("1e-25")


@pytest.mark.slow
def test_first_order_solution_against_integration_general_case():
    """k = 2, φ = tθ + θ'², start at θ = 0.2, θ' = −0.3: the error of θ0 + θ1 is O(ε²)."""
    kv, thi, omi = 2, sp.Rational(1, 5), -sp.Rational(3, 10)
    phi = t * th + dth**2
    th0 = pt.unperturbed(t, k, thi, omi)
    phi_t = pt.along(phi, th, dth, th0, t)
    Es, Ec = pt.E_s(phi_t, t, k), pt.E_c(phi_t, t, k)
    sol, _ = pt.first_order(th0, Es, Ec, eps, k, t)
    f = sp.lambdify((t, eps), sol.subs(k, kv), modules="mpmath")

    def err(e, dps):
        traj = truth.integrate(lambda s, y: [y[1], -kv**2 * y[0] - e * (s * y[0] + y[1] ** 2)],
                               [mp.mpf(1) / 5, -mp.mpf(3) / 10], dps)
        return max(abs(traj(s)[0] - f(s, e)) for s in (mp.mpf("0.7"), mp.mpf("2.2")))
    ev = verify.order_check(param="epsilon", values=verify.geometric("1e-4", "1e-2", 4), truth=err,
                            derived=lambda e: 0, expected=2, band=0.25, truth_desc="test")
    assert ev.passed, ev


def test_turning_shift_of_the_linear_spring():
    # θ'' + k²θ + εθ = 0 is exact: T = π/√(k²+ε), so ΔT = −επ/(2k³) to first order
    th0 = pt.unperturbed(t, k, -sp.Symbol("alpha", positive=True))
    phi_t = pt.along(th, th, dth, th0, t)
    d1 = pt.dtheta1(pt.E_s(phi_t, t, k), pt.E_c(phi_t, t, k), eps, k, t)
    dT = pt.turning_shift(th0, d1, t, sp.pi / k)
    exact = sp.series(sp.pi / sp.sqrt(k**2 + eps) - sp.pi / k, eps, 0, 2).removeO()
    assert sp.simplify(dT - exact) == 0
