"""The exact (large-deflection) blade carrying a rigid pendulum: its elastica, its two limits, convergence."""
import mpmath as mp
import pytest
import sympy as sp

from pendsym import blade as linear_blade
from pendsym import nonlinear_blade

UNIFORM = linear_blade.Blade(sp.Rational(1, 10), sp.Rational(1, 400))
CLOCK = ("0.9", "0.08", "9.81")


def test_elastica_straight_under_tension():
    """No transverse load, no clamping couple: the blade stays straight, α = λ, β = θ = N = 0."""
    end = nonlinear_blade.end_state(UNIFORM, 1, 0, 0, 30)
    with mp.workdps(30):
        assert abs(end.alpha - mp.mpf(1) / 10) < mp.mpf("1e-28")
    assert abs(end.beta) < 1e-40 and abs(end.theta) < 1e-40 and abs(end.N) < 1e-40


def test_elastica_small_load_matches_the_linear_blade():
    """A small clamping couple and force: (β, θ) against the linearised blade's stiffness
    (pendsym.suspension), to the first order (residual ∝ the load squared)."""
    from pendsym import suspension
    sus = suspension.solve(UNIFORM, 30)
    errs = []
    for eps in (mp.mpf("1e-3"), mp.mpf("1e-4")):
        Y, c0 = eps, 2 * eps
        end = nonlinear_blade.end_state(UNIFORM, 1, Y, c0, 40, variations=False)
        c_lin, Y_lin, N_lin = sus.loads(end.beta, end.theta)
        errs.append(abs(Y_lin - Y) / eps + abs(N_lin - end.N) / eps)
    assert errs[1] < errs[0] / 50         # first-order agreement: the error falls like ε


def test_elastica_jacobian_against_finite_differences():
    """The variational equations against central differences of the end state."""
    X, Y, c0 = mp.mpf("1.01"), mp.mpf("0.02"), mp.mpf("0.003")
    with mp.workdps(40):
        end = nonlinear_blade.end_state(UNIFORM, X, Y, c0, 40)
        h = mp.mpf("1e-12")
        for p in range(3):
            up = [X, Y, c0]
            dn = [X, Y, c0]
            up[p] += h
            dn[p] -= h
            e_up = nonlinear_blade.end_state(UNIFORM, *up, 40, variations=False)
            e_dn = nonlinear_blade.end_state(UNIFORM, *dn, 40, variations=False)
            for r, name in enumerate(("alpha", "beta", "theta", "N")):
                fd = (getattr(e_up, name) - getattr(e_dn, name)) / (2 * h)
                assert abs(fd - end.jacobian[r][p]) < mp.mpf("1e-18") * (1 + abs(fd))


def _trigonometric_end(blade, X, Y, c0, wdps):
    """The elastica in its textbook form, φ' = μ/M, μ' = X sin φ − Y cos φ, x' = cos φ, y' = sin φ (odefun),
    with the variations in (X, Y, c0): ∂φ' = ∂μ/M, ∂μ' = (X cos φ + Y sin φ)∂φ + [X] sin φ − [Y] cos φ,
    ∂x' = −sin φ ∂φ, ∂y' = cos φ ∂φ."""
    with mp.workdps(wdps):
        X, Y, c0 = mp.mpf(X), mp.mpf(Y), mp.mpf(c0)
        state = [mp.mpf(0), c0, mp.mpf(0), mp.mpf(0)] + [mp.mpf(0)] * 9 + [mp.mpf(1), mp.mpf(0), mp.mpf(0)]
        for a, b, expr in linear_blade.segments(blade):
            M = sp.lambdify(blade.var, expr, modules="mpmath")

            def rhs(s, u, M=M):
                sn, cs = mp.sin(u[0]), mp.cos(u[0])
                out = [u[1] / M(s), X * sn - Y * cs, cs, sn]
                for d, force in enumerate((sn, -cs, 0)):
                    dphi, dmu = u[4 + 4 * d], u[5 + 4 * d]
                    out += [dmu / M(s), force + (X * cs + Y * sn) * dphi, -sn * dphi, cs * dphi]
                return out
            state = mp.odefun(rhs, mp.mpf(sp.Rational(a)), state, tol=mp.mpf(10) ** -wdps)(mp.mpf(sp.Rational(b)))
        return state


def test_end_state_is_the_trigonometric_elastica():
    """end_state carries cos φ and sin φ in its state (no sine at odefun's raised precision): its end and its
    Jacobian are those of the elastica written with sin φ and cos φ, to the working precision, on a blade
    whose M tapers and then jumps (the state passes the jump)."""
    s = sp.Symbol("s", real=True)
    M = sp.Piecewise((sp.Rational(1, 400) * (1 + 5 * s), s < sp.Rational(1, 20)), (sp.Rational(1, 800), True))
    stepped = linear_blade.Blade(sp.Rational(1, 10), M, s)
    wdps = 20
    end = nonlinear_blade.end_state(stepped, "0.97", "0.04", "-0.006", wdps)
    ref = _trigonometric_end(stepped, "0.97", "0.04", "-0.006", wdps)
    with mp.workdps(wdps):
        got = [end.theta, end.N, end.alpha, end.beta] + [end.jacobian[r][d] for d in range(3) for r in (2, 3, 0, 1)]
        for g, w in zip(got, ref):
            assert abs(g - w) <= mp.mpf(10) ** (2 - wdps) * (1 + abs(w))
    # the loads bend the blade well beyond the linear range
    assert abs(end.theta) > 0.05


SMALL = mp.mpf("0.002")


@pytest.fixture(scope="module")
def small_orbit():
    """The orbit at θ0 = SMALL (4 nodes, 30 digits, the default first stage at LADDER_DPS digits), computed once
    for the two tests that read it (it was computed twice, ~6 s of CPU each)."""
    nonlinear_blade._first_stage.cache_clear()
    return nonlinear_blade.orbit(UNIFORM, *CLOCK, SMALL, 4, 30)


@pytest.mark.slow
def test_amplitude_to_zero_gives_the_linear_period(small_orbit):
    """T(θ0) → 2π/n of the linear eigenproblem, with T/T_lin − 1 of order θ0² (fitted slope 2)."""
    T_lin = nonlinear_blade.linear_period(UNIFORM, *CLOCK)
    amps = (mp.mpf("0.004"), SMALL)
    rel = [nonlinear_blade.orbit(UNIFORM, *CLOCK, amps[0], 4, 30).period / T_lin - 1, small_orbit.period / T_lin - 1]
    slope = mp.log(rel[0] / rel[1]) / mp.log(2)
    assert abs(slope - 2) < 0.01
    assert 0 < rel[1] < 1e-5


@pytest.mark.slow
def test_collocation_converges_in_nodes_and_precision():
    """The period at θ0 = 0.01 with 5 nodes at 30 digits, 7 nodes at 40 digits: 30 digits agree."""
    T5 = nonlinear_blade.orbit(UNIFORM, *CLOCK, "0.01", 5, 30)
    T7 = nonlinear_blade.orbit(UNIFORM, *CLOCK, "0.01", 7, 40)
    assert T5.residual < 1e-33
    assert abs(T5.period - T7.period) < mp.mpf("1e-30") * T7.period


@pytest.mark.slow
def test_short_flexible_blade_is_a_rigid_compound_pendulum():
    """λ → 0 with u = λ/√M fixed: the period tends to the exact period 4K(sin²(θ0/2))·√(L/g) of the rigid
    pendulum pivoting at the clamp, L = (d² + R²)/d with d = λ + a (mpmath's ellipk, an AGM); the
    discrepancy falls with λ (the blade's own length and bending length √M are what separate them)."""
    a, R, g, th = mp.mpf("0.2"), mp.mpf("0.05"), mp.mpf("9.81"), mp.mpf("0.1")
    errs = []
    for lam in (sp.Rational(1, 500), sp.Rational(1, 5000)):
        blade = linear_blade.Blade(lam, (lam / 3) ** 2)
        with mp.workdps(30):
            d = a + mp.mpf(lam.p) / lam.q
            L = (d * d + R * R) / d
            rigid = 4 * mp.ellipk(mp.sin(th / 2) ** 2) * mp.sqrt(L / g)
            T = nonlinear_blade.orbit(blade, a, R, g, th, 5, 20).period
            errs.append((abs(T / rigid - 1), mp.mpf(lam.p) / lam.q / a))
    # the discrepancy is bounded by the blade's relative length λ/a (where along it the pivot acts) and
    # falls with it; at λ/a = 1e-3 it is below the amplitude effect θ0²/16 ≈ 6e-4 itself
    assert all(err < rel_length for err, rel_length in errs)
    assert errs[1][0] < errs[0][0] / 5


@pytest.mark.slow
def test_precision_ladder_returns_the_full_precision_root(monkeypatch, small_orbit):
    """The orbit is the root of the full-precision collocation, not of its first rung: with the first stage at
    12 or at 20 digits (a different start and a different chord Jacobian) the 30-digit periods agree to 30
    digits."""
    assert nonlinear_blade.LADDER_DPS == 12
    T12 = small_orbit.period
    nonlinear_blade._first_stage.cache_clear()
    monkeypatch.setattr(nonlinear_blade, "LADDER_DPS", 20)
    T20 = nonlinear_blade.orbit(UNIFORM, *CLOCK, SMALL, 4, 30).period
    nonlinear_blade._first_stage.cache_clear()
    with mp.workdps(40):
        assert abs(T12 - T20) < mp.mpf("1e-30") * T12
