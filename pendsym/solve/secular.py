"""Secular terms and resonance of a problem's explicit time dependence, said in one line.

The perturbation φ(θ, θ', t) is split into its autonomous part and the part that depends on
t.  The latter is evaluated along the unperturbed motion θ0 = a cos kt + b sin kt, written
with exponentials and taken term by term: a term e^{iwt} with w = ±k resonates with the
oscillator (the expansion grows like t·sin kt), a term with w ∓ k vanishing with the small
parameter or under 5 % of k is near resonance, and a factor t outside the trigonometric
functions is a slow drift of the parameters.  The autonomous part's own resonance is a
frequency shift (removed by Lindstedt–Poincaré) or a change of amplitude (averaging).
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from .problem import Problem

NEAR = sp.Rational(1, 20)


@dataclass(frozen=True)
class Finding:
    kind: str       # none | forcing | parametric | resonance | near | slow
    line: str       # one line for the user
    resonant: bool  # a per-swing answer repeated over swings would be wrong


def frequencies(expr: sp.Expr, t: sp.Symbol) -> list[tuple[sp.Expr, sp.Expr]]:
    """[(w, c)] with expr = Σ c e^{iwt}; c may still hold powers of t."""
    ex = sp.expand(sp.powsimp(sp.expand(expr.rewrite(sp.exp)), combine="exp"))
    out = []
    for term in sp.Add.make_args(ex):
        w, rest = sp.S.Zero, sp.S.One
        for fac in sp.Mul.make_args(sp.powsimp(term, combine="exp")):
            base, ex_pow = fac.as_base_exp()
            if (fac.func == sp.exp or base == sp.E) and fac.has(t):
                arg = fac.args[0] if fac.func == sp.exp else ex_pow
                w += sp.expand(arg / (sp.I * t))
            else:
                rest *= fac
        out.append((sp.expand(w), rest))
    return out


def _relation(w: sp.Expr, k: sp.Expr, problem: Problem) -> str:
    """'exact', 'near' or 'far' for the frequency w against k (parameters at their values)."""
    diff = sp.simplify(w - k)
    if diff == 0:
        return "exact"
    if diff.has(problem.small) and sp.simplify(diff.subs(problem.small, 0)) == 0:
        return "near"
    num = diff.subs(problem.values()).subs(problem.small, 0)
    kval = k.subs(problem.values())
    if num.is_number and kval.is_number and kval != 0 and abs(sp.N(num / kval)) < NEAR:
        return "near"
    return "far"


def classify(problem: Problem) -> Finding:
    """The one-line finding about the explicit time dependence of φ."""
    t, k = problem.t, problem.k
    timed = sp.Add(*[term for term in sp.Add.make_args(sp.expand(problem.phi)) if term.has(t)])
    if timed == 0:
        return Finding("none", "", False)
    a, b = sp.Symbol("a_", real=True), sp.Symbol("b_", real=True)
    theta0 = a * sp.cos(k * t) + b * sp.sin(k * t)
    along = timed.subs({problem.theta: theta0, problem.dtheta: sp.diff(theta0, t)}, simultaneous=True)
    exact, near, slow = [], [], False
    for w, c in frequencies(along, t):
        if c.has(t):
            slow = True
            continue
        for sign in (1, -1):
            rel = _relation(sign * w, k, problem)
            if rel == "exact":
                exact.append(c)
            elif rel == "near":
                near.append(c)
    if exact or near:
        state = any(c.has(a) or c.has(b) for c in exact + near)
        closeness = "at" if exact else "near"
        if not state:
            return Finding("forcing", f"secular: forcing {closeness} the natural frequency k = "
                           f"{sp.sstr(k)}; the amplitude grows without bound in the expansion, so no "
                           f"per-swing answer is given: the slow flow (averaging) follows", True)
        shown = [f for f in sp.preorder_traversal(timed) if isinstance(f, (sp.sin, sp.cos)) and f.has(t)]
        freq = sp.sstr(sp.simplify(sp.diff(shown[0].args[0], t))) if shown else "?"
        return Finding("parametric", f"secular: parametric resonance (a coefficient of θ varies at "
                       f"frequency {freq}, {closeness} 2k = {sp.sstr(2 * k)}); the amplitude grows "
                       f"exponentially, so no per-swing answer is given: the slow flow (averaging) follows",
                       True)
    if slow:
        return Finding("slow", "slow drift: the coefficients change with t, so the expansion holds t·sin kt "
                       "terms from the drift itself; per-swing values are those of the first swing from t = 0 "
                       "and change from swing to swing", False)
    return Finding("far", "time dependence away from resonance: bounded forced terms only; per-swing values are "
                   "those of the first swing from t = 0 (the forcing's phase differs on later swings)", False)
