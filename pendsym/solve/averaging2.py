"""Second-order averaging: the slow flow of (a, b) to ε², with its near-identity transformation.

With θ = a cos kt + b sin kt and θ' = k(−a sin kt + b cos kt) (variation of constants), the
equation θ'' + k²θ + φ = 0 is exactly x' = F(x, t) for x = (a, b),

    F = (φ sin kt / k, −φ cos kt / k),      F = ε F₁ + ε² F₂ + O(ε³),

φ taken along θ and θ' and expanded in ε.  When every F_j is a finite sum of oscillations
e^{iwt} with constant frequencies (φ autonomous, or periodic in t with no slow frequency), the
averaging theorem to second order (Sanders, Verhulst & Murdock, *Averaging Methods in Nonlinear
Dynamical Systems*, 2nd ed. 2007, §2.9, with the zero-mean generator) gives

    x = z + ε u₁(z, t),     u₁ = ∫ (F₁ − ⟨F₁⟩) dt   (the antiderivative with zero mean),
    z' = ε ⟨F₁⟩(z) + ε² (⟨F₂⟩(z) + ⟨DF₁ · u₁⟩(z)),

⟨·⟩ the part of frequency zero, and x(t) − z(t) − εu₁(z(t), t) = O(ε²) over times O(1/ε).  The
initial value of the slow flow is z(0) = x(0) − εu₁(x(0), 0).  Each F_j is held as a dict
w → coefficient (a polynomial in a and b), so products are convolutions of those dicts.
"""
from __future__ import annotations

from dataclasses import dataclass

import mpmath as mp
import sympy as sp

from .. import verify as engine
from .averaging import NotAveraged, a_, b_, flow_trajectory
from .problem import Problem
from .secular import NEAR, frequencies

Modes = dict   # w -> SymPy coefficient of e^{iwt}


@dataclass(frozen=True)
class SlowFlow2:
    rates: tuple          # (a', b') to ε²
    generator: tuple      # (u₁a, u₁b) as real functions of a, b, t
    start: tuple          # z(0) to first order

    @property
    def variables(self) -> tuple:
        return (a_, b_)


def modes(expr: sp.Expr, t: sp.Symbol) -> Modes:
    """expr = Σ c_w e^{iwt}: {w: c_w} (:func:`.secular.frequencies`, terms of one w added);
    raises NotAveraged if some c_w still holds t."""
    out: dict = {}
    for w, rest in frequencies(expr, t):
        if rest.has(t) or w.has(t):
            raise NotAveraged("the time dependence is not a sum of oscillations e^{iwt} with constant frequencies")
        out[w] = out.get(w, 0) + rest
    return {w: c for w, c in ((w, sp.expand(c)) for w, c in out.items()) if c != 0}


def _mul(p: Modes, q: Modes) -> Modes:
    out: dict = {}
    for w1, c1 in p.items():
        for w2, c2 in q.items():
            w = sp.expand(w1 + w2)
            out[w] = out.get(w, 0) + c1 * c2
    return {w: c for w, c in ((w, sp.expand(c)) for w, c in out.items()) if c != 0}


def _diff(p: Modes, s: sp.Symbol) -> Modes:
    return {w: c for w, c in ((w, sp.diff(c, s)) for w, c in p.items()) if c != 0}


def _real(p: Modes, t: sp.Symbol, vals: dict) -> sp.Expr:
    """Σ c_w e^{iwt} as Σ (c_w + c_−w) cos wt + i(c_w − c_−w) sin wt over w > 0 (w's sign taken at the
    parameters' values ``vals``): real when p holds the modes of a real function."""
    out = sp.expand(p.get(0, 0))
    for w, c in p.items():
        if w == 0 or sp.N(w.subs(vals)) < 0:
            continue
        cm = p.get(sp.expand(-w), 0)
        out += sp.expand(c + cm) * sp.cos(w * t) + sp.expand(sp.I * (c - cm)) * sp.sin(w * t)
    return out


def _check_frequencies(p: Modes, problem: Problem) -> None:
    kval = abs(sp.N(problem.k.subs(problem.values())))
    for w in p:
        if w == 0:
            continue
        if w.has(problem.small):
            raise NotAveraged("a frequency depends on the small parameter (near resonance): second-order "
                              "averaging is done for exact resonance or none")
        w0 = w.subs(problem.values())
        if not w0.is_number or abs(sp.N(w0)) < NEAR * kval:
            raise NotAveraged(f"the frequency {sp.sstr(w)} is slow but not zero: second-order averaging is "
                              f"done for exact resonance or none")


def slow_flow2(problem: Problem) -> SlowFlow2:
    """The second-order averaged equations and the generator u₁ (see the module docstring)."""
    t, k, eps = problem.t, problem.k, problem.small
    if problem.phi.has(sp.Abs, sp.sign):
        raise NotAveraged("second-order averaging needs a smooth perturbation (no abs or sign)")
    theta = a_ * sp.cos(k * t) + b_ * sp.sin(k * t)
    on = problem.phi.subs({problem.theta: theta, problem.dtheta: sp.diff(theta, t)}, simultaneous=True)
    try:
        ser = sp.expand(sp.series(on, eps, 0, 3).removeO())
    except (ValueError, NotImplementedError, TypeError):
        raise NotAveraged("the perturbation has no power series in the small parameter") from None
    if sp.simplify(ser.coeff(eps, 0)) != 0:
        raise NotAveraged("the perturbation does not vanish with the small parameter")
    F = []
    for j in (1, 2):
        phij = ser.coeff(eps, j)
        F.append([modes(phij * sp.sin(k * t) / k, t), modes(-phij * sp.cos(k * t) / k, t)])
    for comp in F[0] + F[1]:
        _check_frequencies(comp, problem)
    u1 = [{w: sp.expand(c / (sp.I * w)) for w, c in comp.items() if w != 0} for comp in F[0]]
    rates = []
    for i in range(2):
        corr = _mul(_diff(F[0][i], a_), u1[0])
        for w, c in _mul(_diff(F[0][i], b_), u1[1]).items():
            corr[w] = sp.expand(corr.get(w, 0) + c)
        second = sp.expand(F[1][i].get(0, 0) + corr.get(0, 0))
        rates.append(sp.simplify(sp.expand_complex(eps * F[0][i].get(0, 0) + eps**2 * second)))
    gen = tuple(_real(u, t, problem.values()) for u in u1)
    a0, b0 = problem.theta_i, problem.omega_i / k
    start = tuple(sp.expand(x0 - eps * g.subs({a_: a0, b_: b0, t: 0}, simultaneous=True)) for x0, g in zip((a0, b0), gen))
    return SlowFlow2(tuple(rates), gen, start)


def integrate(problem: Problem, flow: SlowFlow2, eps, times, dps: int) -> list:
    """[(a, b)] of the motion at the increasing ``times``: z integrated by mpmath from z(0)
    (:func:`.averaging.flow_trajectory`), then x = z + εu₁(z, t)."""
    traj, sub = flow_trajectory(problem, flow.rates, (a_, b_), flow.start, eps, dps)
    g = [engine.lambdify_mp(sub(problem.small * u), (problem.t, a_, b_)) for u in flow.generator]
    out = []
    with mp.workdps(dps):
        for at in times:
            z, s = traj(at), mp.mpf(at)
            out.append((z[0] + g[0](s, *z), z[1] + g[1](s, *z)))
    return out
