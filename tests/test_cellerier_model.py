"""Cellérier: the support model and the built Results (fast checks)."""
import mpmath as mp
import pytest
import sympy as sp

from derivations.cellerier import truth as tr
from derivations.cellerier.symbols import C, K, M, g, h, m, theta, thetadd, x1dd, y1dd
from pendsym import registry, verify


@pytest.fixture(scope="module")
def results():
    return registry.build(memoirs=["cellerier"])


def test_lagrangian_theta_equation_is_the_memoirs_equation(results):
    # Euler–Lagrange θ-equation, y1'' free: C θ'' + mh cos θ y1'' + mgh sin θ = 0
    E_th, _ = tr.equations()
    eq = results["cellerier.equation"]
    rhs = eq.derived_value.subs({x1dd: 0})                     # −mgh sin θ + μ'(x1'' = 0)
    mine = sp.solve(E_th, tr.A_th)[0]
    theirs = (rhs / C).subs({sp.sin(theta): tr.S, sp.cos(theta): tr.Cc, y1dd: tr.A_y})
    assert sp.simplify(sp.expand(sp.cancel(mine - theirs)).subs(tr.S**2, 1 - tr.Cc**2)) == 0 or \
        sp.simplify(sp.factor(mine - theirs).subs(tr.S**2, 1 - tr.Cc**2)) == 0


def test_slow_manifold_leading_term_is_K_times_Q():
    Y0, _ = tr.slow_manifold()
    # Q = mh(θ'² sin θ + (g/l) sin θ cos θ), g/l = mgh/C; compare with S² + C² = 1
    Q = m * h * (tr.W**2 * tr.S + m * g * h / C * tr.S * tr.Cc)
    val = sp.lambdify((tr.S, tr.Cc, tr.W, m, h, C, g), Y0 - Q)
    for th_, w_ in ((0.3, 0.1), (1.2, -0.7)):
        assert abs(val(mp.sin(th_), mp.cos(th_), w_, 1.3, 0.4, 0.9, 9.8)) < 1e-12


def test_statuses(results):
    disc = sorted(r.id for r in results.values()
                  if r.printed is not None and verify.compare_forms(r.printed_value, r.derived_value, r.id,
                                                                    r.spec.instances)[0] == "discrepancy")
    assert disc == ["cellerier.F"]


def test_worked_example_numbers(results):
    assert results["cellerier.eps_bound"].derived == sp.Rational(3, 200)
    assert sp.simplify(results["cellerier.example_delta"].derived - sp.Symbol("epsilon", positive=True) / 3) == 0


def test_massless_support_swing_is_longer():
    d = tr.delta_measured("0.05", "0.02", "0", 20)
    assert 0 < d < 0.01
