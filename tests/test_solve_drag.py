"""Quadratic air drag θ'' + εθ'|θ'| + k²θ = 0 over many swings: the slow flow and amplitude law
(averaging), the piecewise integration of the kinked equation, and the amplitude after N swings.

The independent truth here is the drag equation's own first integral on a half swing: while
θ' keeps the sign s, w = θ'² as a function of θ obeys the linear equation dw/dθ = −2k²θ − 2sεw,
so w(θ) = C e^{−2sεθ} − s k²θ/ε + k²/(2ε²), and the next turning point is the other zero of w.
Iterating that map (mpmath findroot at 30 digits) gives the amplitude at every turning point
without any ODE solver and without any perturbation formula.
"""
import mpmath as mp
import pytest
import sympy as sp

from pendsym.solve import averaging, from_dict, kinks, solve, variation
from pendsym.verify import fit_order, geometric

DRAG = {"small": "eps", "k": "k0", "phi": "eps*dtheta*abs(dtheta)", "initial": {"value": "A"},
        "parameters": {"A": 0.5, "k0": 2}}
eps, A, k0 = sp.Symbol("eps", positive=True), sp.Symbol("A", real=True), sp.Symbol("k0", real=True)
t = sp.Symbol("t", real=True)


def exact_turns(eps_val, k, amp, count, dps=30):
    """|θ| at the first ``count`` turning points from rest at amp > 0, by the half-swing first integral."""
    out = []
    with mp.workdps(dps):
        e, a, side = mp.mpf(eps_val), mp.mpf(amp), 1
        for _ in range(count):
            s, th0 = -side, side * a        # moving away from the turning point at side·a
            C = (s * k**2 * th0 / e - k**2 / (2 * e**2)) / mp.exp(-2 * s * e * th0)
            a = abs(mp.findroot(lambda th: C * mp.exp(-2 * s * e * th) - s * k**2 * th / e + k**2 / (2 * e**2),
                                -th0 * mp.mpf("0.9")))
            side = -side
            out.append(a)
    return out


def test_slow_flow_rate_is_four_over_three_pi():
    """dr/dt = −(4/(3π)) ε k r²: the mean of |sin ψ|³ over a period is (1/π)∫_0^π sin³ψ dψ = 4/(3π)
    (Nayfeh & Mook, Nonlinear Oscillations, 1979, §2.2 quadratic damping); no phase drift."""
    flow = averaging.slow_flow(from_dict(DRAG))
    r = flow.variables[0]
    assert flow.form == "polar"
    assert sp.simplify(flow.rates[0] + 4 * eps * k0 * r**2 / (3 * sp.pi)) == 0
    assert flow.rates[1] == 0


def test_amplitude_law_is_hyperbolic():
    """r' = −c r² from r(0) = |A| integrates to r = |A| / (1 + c|A| t), c = 4εk/(3π)."""
    pr = from_dict(DRAG)
    law = averaging.amplitude_law(pr, averaging.slow_flow(pr))
    c = 4 * eps * k0 / (3 * sp.pi)
    assert sp.simplify(law - sp.Abs(A) / (1 + c * sp.Abs(A) * t)) == 0


def test_per_swing_loss_from_the_slow_flow_is_the_first_swing_loss():
    """(π/k)·r' at r = A is the one-swing Δα of variation of constants, −(4/3)εA² (the issue)."""
    sol = solve(DRAG, verify=False)
    per = next(x.expr for x in sol.answers if x.name.startswith("Δα per swing at amplitude r"))
    r = sp.Symbol("r", positive=True)
    assert sp.simplify(per + sp.Rational(4, 3) * eps * r**2) == 0
    assert sp.simplify(variation.first_swing(from_dict(DRAG)).amplitude + sp.Rational(4, 3) * eps * A**2) == 0


def test_piecewise_integration_matches_the_first_integral_at_every_turn():
    """The equation integrated piece by piece (odefun between the kinks) against the exact turning map:
    six swings at ε = 0.1, 25 digits or better at every turning point."""
    pr = from_dict({**DRAG, "parameters": {"A": 1, "k0": 2}})
    pw = kinks.integrate(pr, "0.1", 30, 6 * mp.pi / 2 + 0.3)
    with mp.workdps(30):
        turns = pw.turning_points()[:6]
        got = [abs(pw(x)[0]) for x in turns]
        assert len(got) == 6 and all(abs(pw(x)[1]) < mp.mpf(10) ** -25 for x in turns)
    want = exact_turns("0.1", 2, 1, 6)
    assert max(abs(g - w) for g, w in zip(got, want)) < mp.mpf(10) ** -25


def test_sticking_is_refused():
    """Dry friction sign(θ') with a tiny amplitude sticks at once: the equation does not decide the motion."""
    pr = from_dict({"small": "eps", "phi": "eps*sign(dtheta)", "initial": {"value": "A"},
                    "parameters": {"A": 0.001}})
    with pytest.raises(kinks.NotIntegrable, match="sticking"):
        kinks.integrate(pr, "0.5", 30, 10)


def _law_vs_exact(law_expr, values):
    """|exact amplitude at the N-th turn − law(Nπ/k)|, N = round(k/(πε)), over the values of ε."""
    f = sp.lambdify((eps, t), law_expr.subs({A: sp.Rational(1, 2), k0: 2}), modules="mpmath")
    res = []
    with mp.workdps(30):
        for e in values:
            n = int(mp.nint(2 / (mp.pi * e)))
            res.append(exact_turns(e, 2, mp.mpf("0.5"), n)[-1] - f(e, n * mp.pi / 2))
    return res


def test_amplitude_law_over_many_swings_against_the_first_integral():
    """The amplitude law, repeated over N = 8 … 32 swings (ε = 0.08 … 0.02), against the exact turning map:
    the fitted order is at least the first order averaging claims; a law whose rate is 3π/8 times too large
    (a wrong mean of |sin ψ|³, 1/2 instead of 4/(3π)) fails the same check."""
    pr = from_dict(DRAG)
    law = averaging.amplitude_law(pr, averaging.slow_flow(pr))
    values = geometric("0.02", "0.08", 5)
    order = fit_order(values, _law_vs_exact(law, values))
    assert order > 0.65, order
    wrong = law.subs(eps, eps * 3 * sp.pi / 8)
    assert fit_order(values, _law_vs_exact(wrong, values)) < 0.35


@pytest.mark.slow
def test_drag_solve_verified_over_many_swings():
    """pendsym solve on the drag problem file: the amplitude law checked at the N-th turning point of the
    piecewise-integrated equation (N up to 32), and the one-swing answers, each by its fitted order."""
    from pathlib import Path
    sol = solve(Path(__file__).resolve().parents[1] / "problems" / "drag.toml")
    law = next(x for x in sol.answers if x.name.startswith("r(t)"))
    assert law.evidence is not None and law.holds and law.evidence.order > 0.65, law.evidence
    assert "piece by piece" in law.evidence.truth
    assert sol.verified
