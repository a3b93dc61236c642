"""The truth of a user's problem: its own equation integrated by mpmath at 30 digits or more.

θ'' = −k²θ − φ(θ, θ', t) is integrated by :func:`pendsym.truth.integrate` (mpmath's Taylor
solver odefun) with the problem's parameter values and one value of the small parameter.
The events are found without any perturbation formula: the turning points (θ' = 0) are
bracketed by a scan of the dense solution at a fixed fraction of the unperturbed period, then
refined by a bracketing root finder.  The fitted order of |truth − answer| over a geometric
sequence of the small parameter is measured by :func:`pendsym.verify.order_check`.
"""
from __future__ import annotations

from dataclasses import replace
from typing import Callable

import mpmath as mp
import sympy as sp

from .. import truth as model
from .. import verify as engine
from ..result import Evidence
from .problem import Problem

SCAN = 24            # steps per unperturbed period in the turning-point scan
MAX_PERIODS = 12     # the scan gives up after this many unperturbed periods


def _substituted(problem: Problem, expr: sp.Expr, eps) -> sp.Expr:
    return expr.subs(problem.values()).subs(problem.small, eps)


def trajectory(problem: Problem, eps, dps: int) -> model.Trajectory:
    """The problem's own motion at small parameter ``eps`` (a number), to ``dps`` digits."""
    with mp.workdps(dps + 10):
        eps_exact = sp.Rational(str(mp.mpf(eps)))
    force = _substituted(problem, -problem.k**2 * problem.theta - problem.phi, eps_exact)
    accel = engine.lambdify_mp(force, (problem.t, problem.theta, problem.dtheta))
    y0 = [_substituted(problem, problem.theta_i, eps_exact), _substituted(problem, problem.omega_i, eps_exact)]
    with mp.workdps(dps):
        start = [engine.value_at(v, {}) for v in y0]
    return model.integrate(lambda t, y: [y[1], accel(t, y[0], y[1])], start, dps=dps)


def unperturbed_period(problem: Problem) -> mp.mpf:
    return 2 * mp.pi / engine.value_at(problem.k.subs(problem.values()), {})


def turning_times(problem: Problem, traj: model.Trajectory, count: int, periods: int = MAX_PERIODS) -> list:
    """The first ``count`` times t > 0 with θ'(t) = 0 (a start at rest at t = 0 is not counted),
    searched within ``periods`` unperturbed periods.  ``traj`` is a dense solution (a
    :class:`pendsym.truth.Trajectory` or a piecewise one from :mod:`pendsym.solve.kinks`)."""
    with mp.workdps(traj.dps):
        step = unperturbed_period(problem) / SCAN
        found, t_prev = [], step / 1000
        v_prev = traj(t_prev)[1]
        for i in range(1, SCAN * periods):
            t_next = step * i
            v_next = traj(t_next)[1]
            if v_next == 0 or v_prev * v_next < 0:
                root = mp.findroot(lambda s: traj(s)[1], (t_prev, t_next), solver="anderson")
                found.append(root)
                if len(found) == count:
                    return found
            t_prev, v_prev = t_next, v_next
    raise ValueError("the motion does not turn back within the scanned time (not oscillating)")


def turning_times_until(problem: Problem, traj, count: int) -> list:
    """The first ``count`` turning times, searched within count/2 + 4 unperturbed periods."""
    return turning_times(problem, traj, count, periods=count // 2 + 4)


def frequency_truth(problem: Problem) -> Callable:
    """truth(ε, dps) = 2π / (time between the first and third turning points)."""
    def truth(eps, dps):
        traj = trajectory(problem, eps, dps)
        times = turning_times(problem, traj, 3)
        with mp.workdps(dps):
            return 2 * mp.pi / (times[2] - times[0])
    return truth


def swing_truth(problem: Problem, which: str) -> Callable:
    """truth(ε, dps) of one swing from rest: 'duration' t₁ or 'amplitude' |θ(t₁)| − |θ(0)|."""
    def truth(eps, dps):
        traj = trajectory(problem, eps, dps)
        t1 = turning_times(problem, traj, 1)[0]
        with mp.workdps(dps):
            if which == "duration":
                return t1
            return abs(traj(t1)[0]) - abs(traj(0)[0])
    return truth


def state_truth(problem: Problem, at: Callable) -> Callable:
    """truth(ε, dps) = (θ, θ'/k) at the time at(ε) (for a slow flow: a fixed slow time)."""
    def truth(eps, dps):
        traj = trajectory(problem, eps, dps)
        with mp.workdps(dps):
            y = traj(at(eps))
            return y[0], y[1]
    return truth


def fitted(problem: Problem, *, truth: Callable, answer: Callable, expected: float, what: str,
           band: float = 0.35, lo=None, hi=None, truth_desc: str | None = None):
    """Evidence (pendsym.result.Evidence) of the fitted order of |truth − answer| in the small
    parameter over the problem's geometric sequence."""
    lo = lo or problem.small_range[0]
    hi = hi or problem.small_range[1]
    values = engine.geometric(lo, hi, problem.points)
    params = tuple((s.name, v) for s, v in sorted(problem.parameters.items(), key=lambda kv: kv[0].name))
    desc = truth_desc or (f"the problem's own equation integrated by mpmath odefun at {problem.dps} digits, "
                          f"confirmed at {problem.dps + 15}")
    ev = engine.order_check(param=problem.small.name, values=values, truth=truth, derived=answer,
                            expected=expected, band=band, truth_desc=desc, params=params,
                            dps=problem.dps, confirm_dps=problem.dps + 15, note=what)
    return exact_or(ev, problem.dps)


def exact_or(ev, dps: int):
    """The evidence, marked passed when the answer is exact: every residual under 1e-(dps − 5) of the
    truth (the rounding level of the integration), where no order can be fitted."""
    if ev.passed or not ev.values:
        return ev
    if all(res <= 10.0 ** (-(dps - 5)) * abs(t) for (_, res), (_, t, _) in zip(ev.series, ev.values)):
        return replace(ev, passed=True, note=ev.note + f" | exact: every residual is under 1e-{dps - 5} of the "
                                                       f"truth (rounding level); no order to fit")
    return ev


def fitted_distance(problem: Problem, *, truth: Callable, answer: Callable, expected: float, what: str,
                    band: float = 0.35, lo=None, hi=None):
    """Evidence of the fitted order of the distance |x_truth − x_answer| between two states (tuples),
    in the small parameter over a geometric sequence: a residual that is a Euclidean norm does not
    change sign, so the fit is not spoiled by a component crossing zero.  The truth at the smallest
    parameter is recomputed at dps + 15 digits and must resolve the smallest distance (as in
    :func:`pendsym.verify.order_check`)."""
    lo = lo or problem.slow_range[0]
    hi = hi or problem.slow_range[1]
    values = engine.geometric(lo, hi, problem.points)
    dps, confirm_dps = problem.dps, problem.dps + 15

    def dist(us, vs):      # the mean over the sampled states of the Euclidean distance
        return sum(mp.sqrt(sum((x - y) ** 2 for x, y in zip(u, v))) for u, v in zip(us, vs)) / len(us)
    with mp.workdps(dps):
        truths = [truth(p, dps) for p in values]
        res = [dist(tr, answer(p)) for p, tr in zip(values, truths)]
    with mp.workdps(confirm_dps):
        confirm = dist(truth(values[0], confirm_dps), truths[0])
    norm0 = mp.sqrt(sum(x**2 for x in truths[0][0]))
    digits = 45.0 if confirm == 0 else float(-mp.log10(confirm / norm0))
    exact = max(res) < norm0 * mp.mpf(10) ** (-(dps - 5))
    slope = engine.fit_order(values, res) if all(r != 0 for r in res) else float("inf")
    resolved = confirm < res[0] * mp.mpf("1e-3")
    if exact:      # the answer agrees with the truth to the working precision at every point
        what += f" | exact: the distance is under 1e-{dps - 5} of the state at every point (rounding level)"
    params = tuple((s.name, v) for s, v in sorted(problem.parameters.items(), key=lambda kv: kv[0].name))
    return Evidence(
        kind="order", passed=bool(exact or (abs(slope - expected) <= band and resolved)),
        truth=(f"the problem's own equation integrated by mpmath odefun at {dps} digits, confirmed at "
               f"{confirm_dps}"),
        max_residual=engine.rounded(max(res)), order=engine.rounded(slope), expected_order=float(expected),
        band=(expected - band, expected + band), param=problem.small.name, params=params,
        series=tuple((engine.rounded(p), engine.rounded(r)) for p, r in zip(values, res)),
        confirm_digits=engine.rounded(digits),
        note=what + ("" if resolved else " | truth not resolved at two precisions"))
