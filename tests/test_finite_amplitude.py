"""pendsym.finite_amplitude: the osculating (α, φ) machinery, checked independently."""
import mpmath as mp
import pytest
import sympy as sp

from pendsym import finite_amplitude
from pendsym import truth, verify


def test_free_angle_satisfies_the_definition():
    th = finite_amplitude.free_angle()
    rel = sp.cos(th) - (sp.cos(finite_amplitude.alpha) * sp.cos(finite_amplitude.phi) ** 2 + sp.sin(finite_amplitude.phi) ** 2)
    f = sp.lambdify((finite_amplitude.alpha, finite_amplitude.phi), rel, "mpmath")
    for a, p in ((0.3, 0.2), (1.9, 2.8), (1.0, 1.5)):
        assert abs(f(a, p)) < 1e-14
    g = sp.lambdify((finite_amplitude.alpha, finite_amplitude.phi), th, "mpmath")
    for a in (0.3, 2.0):
        assert abs(g(a, 0) - a) < 1e-14 and abs(g(a, mp.pi) + a) < 1e-14


def test_amplitude_rate_agrees_with_the_energy_method():
    # E = θ'²/2 − ω0² cos θ = −ω0² cos α, dE/dt = θ' f  ⇒  α' = θ' f/(ω0² sin α)
    thd = -2 * finite_amplitude.w0 * sp.sin(finite_amplitude.alpha / 2) * sp.sin(finite_amplitude.phi)
    energy_rate = thd * finite_amplitude.f / (finite_amplitude.w0**2 * sp.sin(finite_amplitude.alpha))
    assert sp.simplify(sp.expand_trig(finite_amplitude.rates()[0] - energy_rate)) == 0


def test_free_swing_time_is_the_complete_elliptic_integral():
    expr = finite_amplitude.T0()
    for a in (0.2, 1.0, 2.0):
        val = sp.lambdify((finite_amplitude.kappa, finite_amplitude.w0), expr, "mpmath")
        got = mp.quad(lambda p: 1 / mp.sqrt(1 - mp.sin(a / 2) ** 2 * mp.cos(p) ** 2), [0, mp.pi])
        assert abs(got - 2 * mp.ellipk(mp.sin(a / 2) ** 2)) < 1e-12
        del val


def test_leading_forms_for_u_equal_cos_phi():
    # hand computation: ∫_0^π cos²φ dφ = π/2, ∫_0^π cos φ sin φ dφ = 0
    lam = sp.Lambda(finite_amplitude.phi, sp.cos(finite_amplitude.phi))
    assert sp.simplify(finite_amplitude.delta_leading().replace(finite_amplitude.u, lam).doit() - 1 / (2 * finite_amplitude.h)) == 0
    assert sp.simplify(finite_amplitude.alpha1_leading().replace(finite_amplitude.u, lam).doit()) == 0


def test_isochronism_term_has_no_weight_at_zero_modulus():
    w = sp.diff(finite_amplitude.first_order_densities()["dt_free"], finite_amplitude.kappa)
    assert sp.simplify(w.subs(finite_amplitude.kappa, 0)) == 0


def _forced(a, e, dps):
    with mp.workdps(dps):
        a, e = mp.mpf(a), mp.mpf(e)
        # state [sin θ, cos θ, θ']: no trigonometric calls at odefun's working precision
        rhs = lambda t, y: [y[1] * y[2], -y[0] * y[2], -y[0] + e * (y[0] + y[2] / 3)]
        traj = truth.integrate(rhs, [mp.sin(a), mp.cos(a), 0], dps)
        T0 = 2 * mp.ellipk(mp.sin(a / 2) ** 2)
        T = truth.event(traj, lambda y, t: y[2], T0, width=T0 / 8)
        s, c, _ = traj(T)
        return T / T0 - 1, a + mp.atan2(s, c)


@pytest.mark.slow
@pytest.mark.parametrize("alpha", ["0.5", "2.0"])
def test_exact_first_order_against_integration(alpha):
    F = lambda s, c, w, t: s + w / 3
    fo = finite_amplitude.swing_first_order(F, alpha)
    for key, idx in (("delta", 0), ("alpha1", 1)):
        ev = verify.order_check(param="epsilon", values=verify.geometric("1e-4", "1e-2", 3),
                                truth=lambda e, dps: _forced(alpha, e, dps)[idx],
                                derived=lambda e: e * fo[key], expected=2, band=0.3,
                                truth_desc="θ'' = −sin θ + ε(sin θ + θ'/3)", confirm_dps=40)
        assert ev.passed, ev
