"""``pendsym.solve``: a user's perturbation problem, solved and verified.

    from pendsym.solve import solve
    sol = solve({"small": "eps", "variable": "u", "phi": "eps*u**3", "order": 3,
                 "initial": {"value": "A"}, "parameters": {"A": 0.5}})
    print(sol.report())

The method follows the problem: Lindstedt–Poincaré for an autonomous polynomial φ (the
frequency, period and motion to the order wanted); for a resonant time dependence one line
says so and the slow flow by averaging is returned (no per-swing answer); an autonomous φ that
changes the amplitude (damping, drag, friction, power laws) gets the polar slow flow, its
amplitude law r(t) and loss per swing, checked at the N-th turning point after about 1/ε of
time; a smooth φ asked at order ≥ 2 also gets the second-order slow flow (:mod:`averaging2`);
otherwise the per-swing changes by variation of constants to the order asked.  Every answer
carries the evidence of its fitted order against the problem's own equation integrated by mpmath
(piece by piece between the kinks of abs and sign, :mod:`kinks`), unless ``verify=False`` (the
report then says that nothing was verified) or it cannot be integrated (said, with the reason).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import mpmath as mp
import sympy as sp

from .. import verify as engine
from ..result import Evidence
from . import averaging, averaging2, frequency, kinks, lindstedt, secular, variation
from . import verify as truth
from .problem import Problem, ProblemError, from_dict, load



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
    verified: bool | None = None        # None: verification skipped, or nothing could be checked
    unverified: list = field(default_factory=list)   # why an answer could not be checked (said in the report)

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
    """The first-order slow flow, and the second-order one when the order asked is 2 or more."""
    _slow1(problem, sol, check)
    if problem.order < 2:
        return
    try:
        _slow2(problem, sol, check)
    except averaging.NotAveraged as exc:
        sol.notes.append(f"order {problem.order} asked; the slow flow is first order only: {exc}")
        return
    sol.method = sol.method.replace("averaging (first order)", "averaging (first and second order)")
    if problem.order > 2:
        sol.notes.append(f"order {problem.order} asked; averaging is done to second order")


def _slow2(problem: Problem, sol: Solution, check: bool) -> None:
    flow = averaging2.slow_flow2(problem)
    names = [f"d{v.name}/dt (second order)" for v in flow.variables]
    tn = problem.t.name
    sol.answers += [Answer(n, r) for n, r in zip(names, flow.rates)]
    sol.answers += [Answer(f"u1_{v.name}(a, b, {tn}), x = z + {problem.small.name}*u1", g)
                    for v, g in zip(flow.variables, flow.generator)]
    sol.answers += [Answer(f"{v.name}(0) of the slow flow", s) for v, s in zip(flow.variables, flow.start)]
    if not check:
        return
    lo, hi = problem.slow_range
    with mp.workdps(problem.dps + 25):        # held at more digits than any truth uses
        kval = engine.value_at(problem.k.subs(problem.values()), {})
        period = truth.unperturbed_period(problem)

    def times(eps):    # one unperturbed period from t = 1/ε: the mean distance over it does not
        return [1 / mp.mpf(eps) + period * j / 8 for j in range(8)]   # hang on one phase of ε²u2

    def state(eps, dps):
        traj = truth.trajectory(problem, eps, dps)
        out = []
        with mp.workdps(dps):
            for s in times(eps):
                th, dth = traj(s)
                c, n = mp.cos(kval * s), mp.sin(kval * s)
                out.append((th * c - dth / kval * n, th * n + dth / kval * c))
        return out

    ev = truth.fitted_distance(
        problem, truth=state, answer=lambda eps: averaging2.integrate(problem, flow, eps, times(eps), mp.mp.dps),
        expected=2, lo=lo, hi=hi,
        what="the distance |(a, b) − (a, b)_averaged|, its mean over the unperturbed period from t = 1/ε, "
             "(a, b) = (θ cos kt − (θ'/k) sin kt, θ sin kt + (θ'/k) cos kt) the variation-of-constants "
             "coordinates of the motion, against z + εu1(z, t) with z the second-order slow flow integrated "
             "from z(0) (error O(ε²) over times O(1/ε))")
    _attach(sol, names[0], ev)


def _attach(sol: Solution, name: str, ev: Evidence) -> None:
    """The evidence of a check put beside the answer of that name."""
    i = next(j for j, a in enumerate(sol.answers) if a.name == name)
    sol.answers[i] = Answer(sol.answers[i].name, sol.answers[i].expr, ev)


def _slow1(problem: Problem, sol: Solution, check: bool) -> None:
    flow = averaging.slow_flow(problem)
    for v, r in zip(flow.variables, flow.rates):
        sol.answers.append(Answer(f"d{v.name}/dt", r))
    sol.answers.append(Answer(f"{problem.theta.name}", flow.theta))
    law = averaging.amplitude_law(problem, flow)
    if law is not None:
        sol.answers.append(Answer(f"r({problem.t.name}), the amplitude law", law))
        per_swing = sp.simplify(sp.pi / problem.k * flow.rates[0])
        sol.answers.append(Answer("Δα per swing at amplitude r (first order, any swing)", per_swing))
    if flow.form == "polar" and flow.rates[0] == 0 and flow.rates[1] != 0:
        _averaged_frequency(problem, sol, flow, check)
    if check:
        try:
            found = slow_checks(problem, flow, law)
        except kinks.NotIntegrable as exc:
            sol.unverified.append(f"the slow flow is not checked: {exc}")
            found = []
        for name, ev in found:
            _attach(sol, name, ev)


def _averaged_frequency(problem: Problem, sol: Solution, flow, check: bool) -> None:
    """A conservative φ keeps the amplitude (r' = 0) and shifts the frequency: ω = k + β'(r) at the
    starting amplitude, to first order; checked like Lindstedt's ω (order 2)."""
    omega = sp.simplify(problem.k + flow.rates[1].subs(flow.variables[0], flow.start[0]))
    ev = None
    if check:
        ev = truth.fitted(problem, truth=truth.frequency_truth(problem), answer=_numeric(problem, omega), expected=2,
                          what="angular frequency 2π/T; T between the 1st and 3rd turning points, against "
                               "k + β'(r) at the starting amplitude (first-order averaging)")
    sol.answers.append(Answer("omega (first order, averaging)", omega, ev))
    sol.answers.append(Answer("period (first order, averaging)",
                              sp.expand(sp.series(2 * sp.pi / omega, problem.small, 0, 2).removeO())))


def slow_checks(problem: Problem, flow, law, amplitude_of=None) -> list:
    """[(answer name, evidence)] of the slow flow against the problem's own equation over many swings.

    ``amplitude_of(eps, times)``, when given, replaces the slow flow's amplitude at those times (the
    bench judges another package's amplitude by this same check; ``flow`` and ``law`` are then unused).

    The observable is at times O(1/ε), where the averaging error is O(ε): for an autonomous
    problem, |θ| at the N-th turning point, N = round(k/(πε)) swings (about 1/ε in time), against
    the amplitude law at t = Nπ/k (or the slow flow integrated, when there is no closed law); for
    a time-dependent one (no turning points to count on), the amplitude (θ² + θ'²/k²)^½
    averaged over the unperturbed period starting at t = 1/ε.  A
    problem with abs or sign is integrated piece by piece between its kinks (:mod:`kinks`)."""
    with mp.workdps(problem.dps + 25):        # the unperturbed period, at more digits than any truth uses
        period = truth.unperturbed_period(problem)
    lo, hi = problem.slow_range
    kinked = problem.phi.has(sp.Abs, sp.sign)
    memo = {}

    def motion(eps, dps):
        key = (str(eps), dps)
        if key not in memo:
            if kinked:
                memo[key] = kinks.integrate(problem, eps, dps, 1 / mp.mpf(eps) + 2 * period)
            else:
                memo[key] = truth.trajectory(problem, eps, dps)
        return memo[key]

    def amplitude(th, dth):
        return mp.sqrt(th**2 + (dth * period / (2 * mp.pi))**2)

    def times(eps):    # a window of one unperturbed period from t = 1/ε: the mean removes the
        return [1 / mp.mpf(eps) + period * j / 8 for j in range(8)]   # oscillation within a period

    def window(eps, dps):
        traj = motion(eps, dps)
        with mp.workdps(dps):
            return sum(amplitude(*traj(s)) for s in times(eps)) / 8

    law_at = (sp.lambdify((problem.small, problem.t), law.subs(problem.values()), modules="mpmath")
              if law is not None and amplitude_of is None else None)

    def slow_amplitude(eps, at):
        """The slow flow's amplitude at the increasing times ``at``."""
        if amplitude_of is not None:
            return amplitude_of(eps, at)
        if law_at is not None:
            return [law_at(mp.mpf(eps), s) for s in at]
        return [amplitude(*y) for y in averaging.integrate(problem, flow, eps, at, mp.mp.dps)]

    name = f"r({problem.t.name}), the amplitude law" if law is not None else problem.theta.name
    how = ("the amplitude given" if amplitude_of is not None else "the amplitude law" if law is not None
           else "the slow flow integrated")
    if not problem.autonomous:
        return [(name, truth.fitted(
            problem, truth=window, answer=lambda eps: sum(slow_amplitude(eps, times(eps))) / 8, expected=1,
            lo=lo, hi=hi, truth_desc=_desc(problem, kinked),
            what=f"the amplitude (θ² + θ'²/k²)^½, its mean over the period starting at t = 1/ε, against {how} "
                 f"at the same times (averaging: error O(ε) over times O(1/ε))"))]

    def swings(eps):
        return max(1, int(mp.nint(2 / (period * mp.mpf(eps)))))

    def nth_turn(eps, dps):
        traj = motion(eps, dps)
        t_n = truth.turning_times_until(problem, traj, swings(eps))[-1]
        with mp.workdps(dps):
            return abs(traj(t_n)[0])

    return [(name, truth.fitted(
        problem, truth=nth_turn, answer=lambda eps: slow_amplitude(eps, [swings(eps) * period / 2])[0], expected=1,
        lo=lo, hi=hi, truth_desc=_desc(problem, kinked),
        what=f"|θ| at the N-th turning point, N = round(k/(πε)) swings (N = {swings(hi)} … {swings(lo)}), "
             f"against {how} at t = Nπ/k: the per-swing loss repeated over many swings (averaging: error "
             f"O(ε) over times O(1/ε))"))]


def _desc(problem: Problem, kinked: bool) -> str:
    if not kinked:
        return None
    return (f"the problem's own equation integrated by mpmath odefun at {problem.dps} digits piece by piece "
            f"between the zeros of the abs/sign arguments (each zero bracketed and refined by findroot), "
            f"confirmed at {problem.dps + 15}")


def _swing(problem: Problem, sol: Solution, check: bool) -> None:
    n = 1
    smooth = not problem.phi.has(sp.Abs, sp.sign)
    if problem.order > 1 and smooth and variation.closed_form_in_time(problem, problem.order):
        n = problem.order
        sw = variation.swing_to_order(problem, n)
    else:
        if problem.order > 1:
            sol.notes.append(f"order {problem.order} asked; the per-swing expansion is first order for a "
                             "perturbation with abs or sign, or a time dependence other than powers of t times "
                             "sines and cosines")
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
            _slow(problem, sol, verify)
            if problem.omega_i == 0 and _polynomial_once_resolved(problem):
                _swing(problem, sol, verify)
            elif problem.omega_i == 0:
                sol.method = sol.method.replace(" and variation of constants (one swing from rest)", "")
                sol.notes.append("no one-swing expansion by variation of constants: φ is not polynomial in θ, θ' "
                                 "once abs and sign are resolved (the slow flow's loss per swing stands)")
    elif want == "averaging":
        sol.method = "averaging (first order): the slow flow of the amplitude and phase"
        _slow(problem, sol, verify)
    else:
        sol.method = "variation of constants, one swing from rest"
        _swing(problem, sol, verify)
    checked = [a.holds for a in sol.answers if a.evidence is not None]
    if verify and not checked and not sol.unverified:
        sol.unverified.append("no answer of this problem carries a check")
    sol.verified = None if not verify or not checked else all(checked)
    return sol


def _polynomial_once_resolved(problem: Problem) -> bool:
    """φ with every abs and sign replaced by a symbol is a polynomial in θ and θ'."""
    plain = problem.phi.xreplace({atom: sp.Dummy() for atom in problem.phi.atoms(sp.Abs, sp.sign)})
    try:
        poly = sp.Poly(plain, problem.theta, problem.dtheta)
    except sp.PolynomialError:
        return False
    if any(c.has(problem.theta, problem.dtheta) for c in poly.coeffs()):
        return False
    kinked = problem.phi.atoms(sp.Abs, sp.sign)
    return all(pw.exp.is_integer for pw in problem.phi.atoms(sp.Pow) if pw.base in kinked)
