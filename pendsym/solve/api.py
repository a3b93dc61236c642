"""``pendsym.solve``: a user's perturbation problem, solved and verified.

    from pendsym.solve import solve
    sol = solve({"small": "eps", "variable": "u", "phi": "eps*u**3", "order": 3,
                 "initial": {"value": "A"}, "parameters": {"A": 0.5}})
    print(sol.report())

The method follows the problem: Lindstedt–Poincaré for an autonomous polynomial φ (the
frequency, period and motion to the order wanted); for a resonant time dependence one line
says so and the slow flow by averaging is returned (no per-swing answer); otherwise the
first-order per-swing changes by variation of constants, with the slow flow for an
autonomous φ that changes the amplitude.  Every answer carries the evidence of its fitted
order against the problem's own equation integrated by mpmath, unless ``verify=False`` (the
report then says that nothing was verified).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import mpmath as mp
import sympy as sp

from ..result import Evidence
from . import averaging, frequency, lindstedt, secular, variation
from . import verify as truth
from .problem import Problem, ProblemError, from_dict, load

SLOW_RANGE = ("0.1", "0.4")   # ε of a slow-flow check, compared at t = 1/ε


@dataclass(frozen=True)
class Answer:
    name: str
    expr: sp.Expr
    evidence: Evidence | None = None

    @property
    def holds(self) -> bool | None:
        """The answer's error is O(ε^p) as claimed: the fitted order is in the band, or above it (the
        next term vanishes, or is small at these values) with the truth resolved at two precisions.
        None when not checked."""
        ev = self.evidence
        if ev is None:
            return None
        return bool(ev.passed or (ev.order is not None and ev.order > ev.band[1]
                                  and "not resolved" not in (ev.note or "")))


@dataclass
class Solution:
    problem: Problem
    method: str
    finding: str = ""
    notes: list = field(default_factory=list)
    answers: list = field(default_factory=list)
    verified: bool | None = None        # None: verification skipped

    def report(self) -> str:
        from .report import text
        return text(self)


def _numeric(problem: Problem, expr: sp.Expr):
    f = sp.lambdify(problem.small, expr.subs(problem.values()), modules="mpmath")
    return lambda eps: f(mp.mpf(eps))


def _frequency(problem: Problem, sol: Solution, check: bool) -> None:
    ans = frequency.solve(problem)
    sol.method = ans.steps
    ev = None
    if check:
        ev = truth.fitted(problem, truth=truth.frequency_truth(problem), answer=_numeric(problem, ans.omega),
                          expected=ans.expected, what="angular frequency 2π/T; T between the 1st and 3rd "
                          "turning points")
    sol.answers.append(Answer("omega", ans.omega, ev))
    sol.answers.append(Answer("period", ans.period))
    sol.answers.append(Answer(f"{problem.theta.name}(tau), tau = omega*{problem.t.name},", ans.motion))


def _slow(problem: Problem, sol: Solution, check: bool) -> None:
    flow = averaging.slow_flow(problem)
    for v, r in zip(flow.variables, flow.rates):
        sol.answers.append(Answer(f"d{v.name}/dt", r))
    sol.answers.append(Answer(f"{problem.theta.name}", flow.theta))
    if not check:
        return
    if problem.phi.has(sp.Abs, sp.sign):
        sol.notes.append("the slow flow is not checked over many swings: the Taylor integrator does not resolve "
                         "a right-hand side with abs or sign across its kinks (the one-swing checks stand)")
        return
    kval = truth.unperturbed_period(problem)

    def amplitude(th, dth):
        return mp.sqrt(th**2 + (dth * kval / (2 * mp.pi))**2)

    def times(eps):    # a window of one unperturbed period ending at t = 1/ε: the mean removes the
        return [1 / mp.mpf(eps) + kval * j / 8 for j in range(8)]   # oscillation within a period

    def state(eps, dps):
        traj = truth.trajectory(problem, eps, dps)
        with mp.workdps(dps):
            return sum(amplitude(*traj(s)) for s in times(eps)) / 8

    def approx(eps):
        return sum(amplitude(*y) for y in averaging.integrate(problem, flow, eps, times(eps), mp.mp.dps)) / 8
    ev = truth.fitted(problem, truth=state, answer=approx, expected=1, lo=SLOW_RANGE[0], hi=SLOW_RANGE[1],
                      what="the amplitude (θ² + θ'²/k²)^½, its mean over the period starting at t = 1/ε, against the slow flow integrated from "
                      "the same start (averaging: error O(ε) over times O(1/ε))")
    sol.answers[-1] = Answer(sol.answers[-1].name, sol.answers[-1].expr, ev)


def _swing(problem: Problem, sol: Solution, check: bool) -> None:
    n = 1
    if problem.order > 1 and problem.autonomous and not problem.phi.has(sp.Abs, sp.sign):
        n = problem.order
        sw = variation.swing_to_order(problem, n)
    else:
        if problem.order > 1:
            sol.notes.append(f"order {problem.order} asked; the per-swing expansion is first order for a "
                             "perturbation with abs, sign or an explicit time dependence")
        sw = variation.first_swing(problem)
    ev_t = ev_a = None
    if check:
        ev_t = truth.fitted(problem, truth=truth.swing_truth(problem, "duration"),
                            answer=_numeric(problem, sw.duration), expected=n + 1,
                            what="duration of the first swing: the first turning time after the start at rest")
        ev_a = truth.fitted(problem, truth=truth.swing_truth(problem, "amplitude"),
                            answer=_numeric(problem, sw.amplitude), expected=n + 1,
                            what="change of |θ| from the start to the first turning point")
    sol.answers += [Answer(f"swing duration (order {n})", sw.duration, ev_t), Answer("ΔT (one swing)", sw.shift),
                    Answer("Δα (one swing)", sw.amplitude, ev_a)]
    if sw.lowest_speed is not sp.nan:
        sol.answers.append(Answer("|θ'| at the lowest point (order 1)", sw.lowest_speed))


def solve(problem, *, verify: bool = True) -> Solution:
    """Solve a problem (a :class:`Problem`, a dict in the TOML schema, or a path to a TOML file)."""
    if isinstance(problem, (str, Path)):
        problem = load(problem)
    elif isinstance(problem, dict):
        problem = from_dict(problem)
    sol = Solution(problem, method="")
    find = secular.classify(problem)
    sol.finding = find.line
    want = problem.method
    if find.resonant:
        if want in ("lindstedt", "variation"):
            sol.notes.append(f"method {want} refused: a per-swing or periodic answer would repeat a wrong number")
        sol.method = "averaging (first order): the slow flow of the amplitude and phase"
        _slow(problem, sol, verify)
    elif problem.autonomous and want in ("auto", "lindstedt"):
        try:
            _frequency(problem, sol, verify)
        except (frequency.NotApplicable, lindstedt.NotAFrequency) as exc:
            if want == "lindstedt":
                raise ProblemError(f"Lindstedt–Poincaré does not apply: {exc}") from None
            sol.notes.append(f"Lindstedt–Poincaré does not apply: {exc}")
            sol.method = "averaging (first order) and variation of constants (one swing from rest)"
            if problem.order > 1:
                sol.notes.append(f"order {problem.order} asked; the slow flow is first order")
            _slow(problem, sol, verify)
            if problem.omega_i == 0:
                _swing(problem, sol, verify)
    elif want == "averaging":
        sol.method = "averaging (first order): the slow flow of the amplitude and phase"
        _slow(problem, sol, verify)
    else:
        sol.method = "variation of constants, one swing from rest"
        _swing(problem, sol, verify)
    checked = [a.holds for a in sol.answers if a.evidence is not None]
    sol.verified = None if not verify else all(checked) and bool(checked)
    return sol
