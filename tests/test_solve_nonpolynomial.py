"""A perturbation that is not a polynomial in θ, θ': averaged exactly when it is a sum of powers of θ,
θ', |θ|, |θ'| and signs (Coulomb friction, power-law damping, |θ|θ stiffness); refused in one line
otherwise.  Expected values come from classical results or from mpmath quadrature of the mean (an
independent computation of the same integral, not the Beta-function formula the code uses)."""
import subprocess
import sys

import mpmath as mp
import pytest
import sympy as sp

from pendsym.solve import averaging, from_dict, kinks, solve
from pendsym.solve.averaging import NotAveraged

eps, r = sp.Symbol("eps", positive=True), sp.Symbol("r", positive=True)
BASE = {"small": "eps", "k": "2", "initial": {"value": "A"}, "parameters": {"A": 0.5}}


def flow(phi):
    return averaging.slow_flow(from_dict({**BASE, "phi": phi}))


def test_coulomb_friction_loses_two_f_over_k_squared_per_swing():
    """θ'' + ε sign(θ') + k²θ = 0 loses exactly 2ε/k² of amplitude every half cycle (the classical Coulomb-damped
    oscillator, e.g. Lapidus, Am. J. Phys. 38 (1970) 1360): r' = −2ε/(πk), i.e. (π/k) r' = −2ε/k²."""
    f = flow("eps*sign(dtheta)")
    assert sp.simplify(f.rates[0] * sp.pi / 2 + 2 * eps / 4) == 0 and f.rates[1] == 0


def test_coulomb_piecewise_integration_is_exact_at_every_turn():
    """The equation integrated piece by piece (its right-hand side is linear on each piece) against the exact
    turning amplitudes A − 2nε/k², n = 1 … 5."""
    pr = from_dict({**BASE, "phi": "eps*sign(dtheta)"})
    pw = kinks.integrate(pr, "0.05", 30, 5 * mp.pi / 2 + 0.3)
    with mp.workdps(30):
        got = [abs(pw(x)[0]) for x in pw.turning_points()[:5]]
        want = [mp.mpf("0.5") - 2 * n * mp.mpf("0.05") / 4 for n in range(1, 6)]
        assert max(abs(g - w) for g, w in zip(got, want)) < mp.mpf(10) ** -25


@pytest.mark.parametrize("phi, weight", [
    ("eps*dtheta*sqrt(abs(dtheta))", "sin"),      # power-law drag: a loss of amplitude
    ("eps*abs(dtheta)**3", "sin"),                # even in θ': no loss
    ("eps*theta*abs(theta)", "cos"),              # |θ|θ stiffness: a frequency shift
])
def test_mean_against_quadrature(phi, weight):
    """The averaged rate against mpmath quadrature of the same mean over ψ (θ = r cos ψ, θ' = −2r sin ψ)."""
    f = flow(phi)
    rate = f.rates[0] if weight == "sin" else f.rates[1] * r
    th = lambda p: mp.cos(p)
    dth = lambda p: -2 * mp.sin(p)
    body = {"eps*dtheta*sqrt(abs(dtheta))": lambda p: dth(p) * mp.sqrt(abs(dth(p))),
            "eps*abs(dtheta)**3": lambda p: abs(dth(p)) ** 3,
            "eps*theta*abs(theta)": lambda p: th(p) * abs(th(p))}[phi]
    w = mp.sin if weight == "sin" else mp.cos
    with mp.workdps(30):
        mean = mp.quad(lambda p: body(p) * w(p), mp.linspace(0, 2 * mp.pi, 5)) / (2 * mp.pi) / 2   # r = 1, /k
        got = rate.subs({r: 1, eps: 1})
        assert abs(mp.mpf(sp.N(got, 40)) - mean) < mp.mpf(10) ** -25


def test_power_law_is_averaged_but_not_integrated_and_says_so():
    sol = solve({**BASE, "phi": "eps*dtheta*sqrt(abs(dtheta))", "verify": {"slow": [0.02, 0.08]}})
    assert sol.verified is None
    assert any("not analytic at its kinks" in u for u in sol.unverified)
    assert "NOT VERIFIED" in sol.report()


def test_sin_theta_frequency_shift_is_j1_over_r():
    """θ'' + θ + ε sin θ: r' = 0 and β' = εJ₁(r)/r (Jacobi–Anger: the mean of sin(r cos ψ) cos ψ is J₁(r));
    checked against mpmath quadrature at r = 0.7, and for small r against the Duffing shift of its Taylor
    polynomial θ − θ³/6: by hand, ω₁ = 1/2 + (3/8)(−1/6)r² = 1/2 − r²/16."""
    f = averaging.slow_flow(from_dict({"small": "eps", "phi": "eps*sin(theta)", "initial": {"value": "A"},
                                       "parameters": {"A": 0.5}}))
    assert f.rates[0] == 0
    with mp.workdps(30):
        mean = mp.quad(lambda p: mp.sin(mp.mpf("0.7") * mp.cos(p)) * mp.cos(p), [0, mp.pi, 2 * mp.pi]) / (2 * mp.pi)
        assert abs(mp.mpf(sp.N(f.rates[1].subs({r: sp.Rational(7, 10), eps: 1}), 40)) - mean / mp.mpf("0.7")) < 1e-25
    small = sp.series(f.rates[1] / eps, r, 0, 3).removeO()
    assert sp.expand(small - (sp.Rational(1, 2) - r**2 / 16)) == 0


def test_sin_squared_is_reduced_then_averaged():
    """ε sin²θ = ε(1 − cos 2θ)/2 (TR8): β' = ε⟨sin²(r cos ψ) cos ψ⟩/r = 0 by parity, r' = 0."""
    f = averaging.slow_flow(from_dict({"small": "eps", "phi": "eps*sin(theta)**2", "initial": {"value": "A"},
                                       "parameters": {"A": 0.5}}))
    assert f.rates == (0, 0)


def test_cos_theta_damping_is_bessel():
    """θ'' + θ + ε cos(θ) θ' = 0: r' = −ε⟨cos(r cos ψ) sin² ψ⟩ r = −εJ₁(r), against mpmath quadrature at r = 0.9."""
    f = averaging.slow_flow(from_dict({"small": "eps", "phi": "eps*cos(theta)*dtheta", "initial": {"value": "A"},
                                       "parameters": {"A": 0.5}}))
    with mp.workdps(30):
        mean = mp.quad(lambda p: mp.cos(mp.mpf("0.9") * mp.cos(p)) * mp.sin(p) ** 2, [0, mp.pi, 2 * mp.pi]) / (2 * mp.pi)
        assert abs(mp.mpf(sp.N(f.rates[0].subs({r: sp.Rational(9, 10), eps: 1}), 40)) + mp.mpf("0.9") * mean) < 1e-25


@pytest.mark.slow
def test_sin_theta_frequency_fitted_order_two():
    sol = solve({"small": "eps", "phi": "eps*sin(theta)", "initial": {"value": "A"}, "parameters": {"A": 1}})
    om = next(x for x in sol.answers if x.name.startswith("omega"))
    assert om.evidence.passed and abs(om.evidence.order - 2) < 0.35, om.evidence
    assert sol.verified


@pytest.mark.parametrize("phi", ["eps*sin(dtheta)", "eps*exp(dtheta)", "eps*theta/(1 + theta**2)"])
def test_other_non_polynomial_phi_is_refused_in_one_line(phi):
    with pytest.raises(NotAveraged) as exc:
        solve({**BASE, "phi": phi}, verify=False)
    assert "\n" not in str(exc.value)


def test_cli_refusal_exit_2(tmp_path):
    f = tmp_path / "p.toml"
    f.write_text('small = "eps"\nphi = "eps*exp(theta)"\n[initial]\nvalue = "0.5"\n')
    p = subprocess.run([sys.executable, "-m", "pendsym.cli", "solve", str(f), "--no-verify"],
                       capture_output=True, text=True)
    assert p.returncode == 2 and len(p.stderr.strip().splitlines()) == 1, p.stderr


@pytest.mark.slow
def test_coulomb_solve_exact_over_many_swings():
    """The amplitude law A − 2εt/(πk) at t = Nπ/k is the exact turning amplitude (N = 8 … 32 swings): the check
    passes as exact, not by a fitted order."""
    sol = solve({**BASE, "phi": "eps*sign(dtheta)", "verify": {"slow": [0.02, 0.08]}})
    law = next(x for x in sol.answers if x.name.startswith("r(t)"))
    assert law.holds and "exact" in law.evidence.note
    assert sol.verified
