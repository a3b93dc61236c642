"""Per-swing changes by variation of constants: closed forms from the issue (independent of this
code) and the fitted order against the problem's own equation."""
import pytest
import sympy as sp

from pendsym.solve import from_dict, solve
from pendsym.solve import variation

DRAG = {"small": "eps", "k": "k0", "phi": "eps*dtheta*abs(dtheta)", "initial": {"value": "A"},
        "parameters": {"A": 0.3, "k0": 2}}
LINEAR = {"small": "eps", "k": "2", "phi": "2*eps*dtheta", "initial": {"value": "A"}, "parameters": {"A": 0.3}}
LENGTH = {"small": "a", "length": "l0*(1 + a*t)", "gravity": "g", "initial": {"value": "alpha"},
          "parameters": {"l0": 1, "g": 4, "alpha": 0.1}}
eps, A, a, alpha = sp.Symbol("eps", positive=True), sp.Symbol("A", real=True), \
    sp.Symbol("a", positive=True), sp.Symbol("alpha", real=True)


def test_quadratic_drag_loses_four_thirds_eps_alpha_squared_per_swing():
    sw = variation.first_swing(from_dict(DRAG))
    assert sp.simplify(sw.amplitude + sp.Rational(4, 3) * eps * A**2) == 0
    assert sw.shift == 0


def test_linear_damping_loses_eps_alpha_T():
    """θ'' + 2εθ' + 4θ = 0 decays as e^{−εt}: over one swing T = π/2, Δα = −εαT."""
    sw = variation.first_swing(from_dict(LINEAR))
    assert sp.simplify(sw.amplitude + eps * A * sp.pi / 2) == 0


def test_lengthening_pendulum():
    """ΔT = aT²/4 and Δα = −(3/4)aαT, T = π/k the swing's duration, k = 2."""
    pr = from_dict(LENGTH)
    sw = variation.first_swing(pr)
    l0, g = sp.Symbol("l0", real=True), sp.Symbol("g", real=True)
    T = sp.pi * sp.sqrt(l0 / g)
    assert sp.simplify((sw.shift - a * T**2 / 4).subs({l0: 1, g: 4})) == 0
    assert sp.simplify((sw.amplitude + sp.Rational(3, 4) * a * alpha * T).subs({l0: 1, g: 4})) == 0
    assert sp.simplify((sw.amplitude + sp.Rational(3, 4) * a * alpha * T).subs({l0: 3, g: 5})) == 0


def test_linear_damping_to_order_2_from_the_exact_solution():
    """θ = A e^{−εt}(cos ωt + (ε/ω) sin ωt), ω = (4 − ε²)^½: the first turn at π/ω, where |θ| = A e^{−επ/ω}."""
    sw = variation.swing_to_order(from_dict({**LINEAR, "order": 2}), 2)
    assert sp.simplify(sw.shift - sp.pi * eps**2 / 16) == 0
    assert sp.simplify(sw.amplitude - (-sp.pi * A * eps / 2 + sp.pi**2 * A * eps**2 / 8)) == 0


@pytest.mark.slow
@pytest.mark.parametrize("data, order", [(DRAG, 2), (LINEAR, 2), (LENGTH, 2), ({**LINEAR, "order": 2}, 3)])
def test_per_swing_fitted_order(data, order):
    sol = solve(data)
    swing = [x for x in sol.answers if x.evidence is not None and x.name != "theta"]
    amp = [x for x in swing if x.name.startswith("Δα")]
    assert swing and all(x.holds for x in swing), [x.evidence for x in swing]
    assert amp[0].evidence.passed and abs(amp[0].evidence.order - order) < 0.35
