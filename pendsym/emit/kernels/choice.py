"""Choice of form: the candidate of least measured error among the named rules.

First the whole-expression rewrites (:data:`.rules.REWRITES`, with the near-zero series
variant), ranked on the kernel's full sample (hard points included); if the best does not hold
the bound there, the piecewise stable forms of :mod:`.leaves` compete on it.
Also here: the naive form a kernel is compared with.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Sequence

import math

import mpmath as mp
import sympy as sp

from ...result import KernelArg, Result
from .compile import emitted_py
from .leaves import hard_argument, stable_forms
from .measure import BOUND, Accuracy, _symbols, errors, measure, py_callable
from .rules import NEAR_ONE, NEAR_TAYLOR, NEAR_VERTEX, NEAR_ZERO, REWRITES, rounded_multiples
from .sampling import kernel_sample, sample_points, vertex_points

HEADROOM = 0.25         # a rewrite over a quarter of the bound on the sample lets the stable forms compete: the
                        # audit's 20,000 points found Γ3 and Γ5 at 5.1 and 4.2 where the sample saw 2.4 and 1.8
NOISE = 0.75            # scaled: rewrites whose maxima on the sample differ by less are ranked by their mean
MEAN_TIE = 0.015       # relative: mean errors closer than this are a tie (broken by the number of operations;
                        # n22_dtheta 1.15 %; at 2 % n30_Ec took its half-angle form, 1.9 % over, 4.25 in make audit)
SAME_POINTS = 8         # points a rewrite must agree with the derived form on (SAME_DPS digits, 1e-20)
SAME_DPS = 40


@dataclass(frozen=True)
class Choice:
    rule: str
    form: sp.Expr
    accuracy: Accuracy
    notes: tuple[str, ...] = ()     # the pieces of a stable form, with their measured errors


def _candidates(expr: sp.Expr, args: Sequence[KernelArg], seed: str):
    """(name, form) of every rewrite that applies and keeps the function, each also with the
    near-zero series below its phase where the form has one."""
    near = NEAR_ZERO.series(expr, args)
    trig = expr.has(sp.sin, sp.cos)
    for rule in REWRITES:
        if rule.trig and not trig:
            continue
        try:
            cand = rule(expr)
        except Exception:  # a rule that does not apply is skipped
            continue
        if (rule.name != "as-derived" and cand == expr) or not _same_numerically(cand, expr, args, seed):
            continue          # (a rule that changes nothing would only tie with the derived form)
        yield rule.name, cand
        if near is not None:
            yield f"{rule.name}+{NEAR_ZERO.name}", NEAR_ZERO(cand, near)


def choose_form(expr: sp.Expr, args: Sequence[KernelArg], seed: str) -> Choice:
    """The rewrite whose Python evaluation is the most accurate on the kernel's full sample (its
    hard points included: subnormal t, the zeros of sin and cos, where one rewrite holds and
    another cancels; maxima within NOISE: the least mean error, then rule order); when none holds BOUND and one argument alone feeds the
    transcendental functions, the piecewise stable forms of :func:`.leaves.stable_forms` compete
    (also when the best rewrite is over HEADROOM × BOUND: a sample of a few hundred points sees
    less than the audit's search)."""
    full = kernel_sample(expr, args, seed)
    ranked = []                                    # (max scaled, mean scaled, order, Choice)
    for name, form in _candidates(expr, args, seed):
        fn = py_callable(form, args)
        acc = measure(fn, expr, args, full)
        mean = sum(min(e[2], 1e3) for e in errors(fn, expr, args, full)) / len(full) if math.isfinite(acc.max_scaled) else math.inf
        ranked.append((acc.max_scaled, mean, len(ranked), Choice(name, form, acc)))
    # the sample's maximum is a noisy estimate of the domain's: among the rewrites within
    # NOISE of the least maximum, those that round no multiple angle m·φ (m ≥ 3, not a power of 2:
    # an error the inputs do not have), and among them the least mean error; means within MEAN_TIE
    # of the least are a tie, which the fewer operations win (the fewer roundings: n23_theta's
    # forms measured 0.1405 against 0.1405 on the sample, and 3.0 against 4.3 on 30,000 points
    # where the terms cancel; session 6 took the form with 4 operations more)
    least = min(r[0] for r in ranked)
    near = [r for r in ranked if r[0] <= least + NOISE]
    near = [r for r in near if not rounded_multiples(r[3].form)] or near
    low = min(r[1] for r in near)
    best = min((r for r in near if r[1] <= low * (1 + MEAN_TIE)), key=lambda r: (sp.count_ops(r[3].form), r[2]))[3]
    # the rewrites are ranked as one expression; the code emitted names its common subexpressions,
    # which rounds differently (Γ3 as derived: 1.38 as one expression, 2.4 as emitted, 5.08 in make audit): the
    # best is measured as emitted before it is taken
    best = Choice(best.rule, best.form, measure(emitted_py(seed, args, best.form), expr, args, full))
    if best.accuracy.max_scaled <= HEADROOM * BOUND:
        return best
    # the vertex form competes where the vertex lies inside the domain
    # the vertex form where it cancels less is taken when it holds the bound: the plain form
    # cancels along the vertex curve, which a sample of a few hundred points barely meets
    for label, form, notes in stable_forms(expr, args, vertex=True):
        # measured as emitted (statements: a leaf's pieces nest too deep for one Python expression)
        acc = measure(emitted_py(seed, args, form), expr, args, full)
        preferred = label in (NEAR_VERTEX.label, NEAR_TAYLOR.label, NEAR_ONE.label) and acc.max_scaled <= BOUND
        if acc.max_scaled < best.accuracy.max_scaled or preferred:
            hard = hard_argument(expr, args).name
            best = Choice(f"piecewise in {hard}: series below a switch, e^(-{hard}) or derived form above{label}",
                          form, acc, notes)
        if preferred:
            break
    return best


def _same_numerically(a, b, args, seed) -> bool:
    """A rewrite must not change the function: compare at 8 interior points at SAME_DPS digits (in
    double the derived form may itself lose more than 1e-9 to cancellation, and a good rewrite was
    rejected: G of an inverted blade, (cos 2u − 1) at u = 1e-5)."""
    points = sample_points(args, seed, SAME_POINTS, hard=False)[-SAME_POINTS:]
    try:
        fa, fb = (sp.lambdify(list(_symbols(x, args)), x, modules=["mpmath", {"Magnitude": abs}]) for x in (a, b))
        with mp.workdps(SAME_DPS):
            return all(abs(va - vb) <= mp.mpf(10) ** -20 * max(1, abs(vb))
                       for p in points for va, vb in [[f(*[mp.mpf(v) for v in p]) for f in (fa, fb)]])
    except Exception:  # a form mpmath cannot evaluate (a codegen function): compared in double, as before
        fa, fb = (py_callable(x, args) for x in (a, b))
        return all(abs(va - vb) <= 1e-9 * max(1.0, abs(vb)) for p in points for va, vb in [[fa(*p), fb(*p)]])


def naive_form(result: Result, args: Sequence[KernelArg]) -> tuple[str, sp.Expr]:
    """("printed", the printed formula with its symbols read the obvious way in double), when it is
    the same function as the derived one (checked at three points at 50 digits); otherwise
    ("as derived", the derived form evaluated as it stands)."""
    names = {a.name for a in args}
    if result.printed is not None:
        defs = result.spec.kernel.naive_defs or result.spec.defs
        pv = result.printed.subs(dict(defs), simultaneous=True)
        if {s.name for s in pv.free_symbols} <= names and _same_function(pv, result.derived, args):
            return "printed", pv
    return "as derived", result.derived


def _same_function(a: sp.Expr, b: sp.Expr, args: Sequence[KernelArg]) -> bool:
    fa, fb = (sp.lambdify([sp.Symbol(x.name, **_assumptions(e, x.name)) for x in args], e, modules="mpmath")
              for e in (a, b))
    with mp.workdps(50):
        for p in sample_points(args, "same", 3, hard=False)[-3:]:
            va, vb = fa(*[mp.mpf(v) for v in p]), fb(*[mp.mpf(v) for v in p])
            if abs(va - vb) > mp.mpf(10) ** -30 * max(1, abs(vb)):
                return False
    return True


def _assumptions(e: sp.Expr, name: str) -> dict:
    s = next((x for x in e.free_symbols if x.name == name), None)
    return s.assumptions0 if s is not None else {}
