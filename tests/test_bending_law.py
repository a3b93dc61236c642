"""The exact blade with a bending moment not linear in the curvature, M(c + a2c³): its elastica (a closed form,
a first integral, the linear law as a2 = 0, the variations), and the pendulum's period on it (the limit a2 → 0,
the order of the change in a2 and in the amplitude, convergence in precision)."""
import functools

import mpmath as mp
import pytest
import sympy as sp

from pendsym import bending_law
from pendsym import blade as linear_blade
from pendsym import nonlinear_blade

S = linear_blade.S
UNIFORM = linear_blade.Blade(sp.Rational(1, 10), sp.Rational(1, 400))
# a jump and a taper: the curvature jumps where M does (μ is continuous), and M' enters the equations
STEPPED = linear_blade.Blade(sp.Rational(1, 10), sp.Piecewise(
    (sp.Rational(1, 400) * (1 + 5 * S), S < sp.Rational(1, 20)), (sp.Rational(1, 800), True)))
COMPACT = ("0.12", "0.05", "9.81")


def test_pure_couple_bends_the_blade_into_the_circle_of_the_law():
    """X = Y = 0: μ = c0 all along, so c is the root of M(c + a2c³) = c0 and the blade an arc of circle:
    θ = cλ, α = sin(cλ)/c, β = (1 − cos cλ)/c, N = c0 (closed forms, mpmath's polyroots for c)."""
    a2, c0 = sp.Rational(1, 2), mp.mpf("0.01")
    end = bending_law.CubicLaw(a2).end_state(UNIFORM, 0, 0, c0, 40, variations=False)
    with mp.workdps(40):
        M, lam = mp.mpf(1) / 400, mp.mpf(1) / 10
        # 0.5c³ + c − c0/M = 0: the one real root
        c = [r for r in mp.polyroots([mp.mpf(1) / 2, 0, 1, -c0 / M], extraprec=60) if abs(mp.im(r)) < 1e-30][0].real
        assert abs(c - c0 / M) > mp.mpf("0.1")              # the law matters here: c differs from the linear c0/M
        for got, want in ((end.theta, c * lam), (end.alpha, mp.sin(c * lam) / c),
                          (end.beta, (1 - mp.cos(c * lam)) / c), (end.N, c0)):
            assert abs(got - want) < mp.mpf("1e-32")


def test_elastica_keeps_its_first_integral():
    """M constant: μ'c = (X sin φ − Y cos φ)φ' integrates to H = M(c²/2 + 3a2c⁴/4) + X cos φ + Y sin φ,
    the same at both ends (c at each end from its moment)."""
    a2 = mp.mpf("0.5")
    X, Y, c0 = mp.mpf("1.01"), mp.mpf("0.02"), mp.mpf("0.3")
    end = bending_law.CubicLaw(sp.Rational(1, 2)).end_state(UNIFORM, X, Y, c0, 32, variations=False)
    with mp.workdps(32):
        M = mp.mpf(1) / 400

        def H(mu, phi):
            c = bending_law.curvature(mu, M, a2)
            return M * (c * c / 2 + 3 * a2 * c ** 4 / 4) + X * mp.cos(phi) + Y * mp.sin(phi)
        assert abs(end.theta) > mp.mpf("0.5")                   # a large deflection
        assert abs(H(c0, 0) - H(end.N, end.theta)) < mp.mpf("1e-29")


def test_law_zero_is_the_linear_elastica():
    """a2 = 0 on the stepped blade: the linear law's end state (pendsym.nonlinear_blade.end_state, the moment as
    its state) to 30 digits."""
    args = (STEPPED, "1.01", "0.02", "0.003", 32)
    lin = nonlinear_blade.end_state(*args, variations=False)
    law = bending_law.CubicLaw(0).end_state(*args, variations=False)
    for name in ("alpha", "beta", "theta", "N"):
        assert abs(getattr(lin, name) - getattr(law, name)) < mp.mpf("1e-29") * (1 + abs(getattr(lin, name)))


@pytest.mark.slow
def test_variations_against_finite_differences():
    """∂(α, β, θ, N)/∂(X, Y, c0) of the stepped blade with a2 = 1/2 (large curvature: the law's terms count)
    against central differences."""
    law = bending_law.CubicLaw(sp.Rational(1, 2))
    X, Y, c0 = mp.mpf("1.01"), mp.mpf("0.05"), mp.mpf("0.2")
    with mp.workdps(30):
        end = law.end_state(STEPPED, X, Y, c0, 30)
        h = mp.mpf("1e-9")
        for p in range(3):
            up, dn = [X, Y, c0], [X, Y, c0]
            up[p] += h
            dn[p] -= h
            e_up = law.end_state(STEPPED, *up, 30, variations=False)
            e_dn = law.end_state(STEPPED, *dn, 30, variations=False)
            for r, name in enumerate(("alpha", "beta", "theta", "N")):
                fd = (getattr(e_up, name) - getattr(e_dn, name)) / (2 * h)
                assert abs(fd - end.jacobian[r][p]) < mp.mpf("1e-14") * (1 + abs(fd))


@functools.lru_cache(maxsize=None)
def _period(theta0: str, a2: str, nodes: int = 4, dps: int = 30):
    law = None if a2 == "0" else bending_law.CubicLaw(sp.Rational(a2))
    return nonlinear_blade.orbit(UNIFORM, *COMPACT, theta0, nodes, dps, law=law).period


def _law_part(theta0: str, a2: str):
    with mp.workdps(40):
        return _period(theta0, a2) / _period(theta0, "0") - 1


@pytest.mark.slow
def test_period_change_vanishes_linearly_with_a2():
    """a2 → 0 gives back the linear law's period: T(θ0; a2)/T(θ0; 0) − 1 halves with a2 (fitted order 1 in a2),
    and a stiffening law (a2 > 0) shortens the period."""
    small, double = _law_part("0.002", "1/10000"), _law_part("0.002", "2/10000")
    assert small < 0 and double < 0
    assert abs(mp.log(double / small) / mp.log(2) - 1) < 1e-3


@pytest.mark.slow
def test_period_change_is_of_the_second_order_in_the_amplitude():
    """The law's moment a2Mc³ is of the third order in the amplitude, so the period changes at the order θ0²:
    doubling θ0 multiplies T(θ0; a2)/T(θ0; 0) − 1 by 4 (fitted order 2, up to the next order θ0⁴)."""
    ratio = _law_part("0.004", "1/10000") / _law_part("0.002", "1/10000")
    assert abs(mp.log(ratio) / mp.log(2) - 2) < 1e-3


@pytest.mark.slow
def test_law_orbit_converges_in_nodes_and_precision():
    """The period with the law at 4 nodes and 30 digits against 5 nodes and 36 digits: 30 digits agree."""
    coarse, fine = _period("0.002", "1/10000"), _period("0.002", "1/10000", 5, 36)
    with mp.workdps(45):
        assert abs(coarse - fine) < mp.mpf("1e-30") * fine
