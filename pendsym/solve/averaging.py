"""First-order averaging: the slow flow of amplitude and phase.

With θ = a cos kt + b sin kt and θ' = k(−a sin kt + b cos kt) (variation of constants),
θ'' + k²θ + φ = 0 is exactly

    a' = (φ/k) sin kt,      b' = −(φ/k) cos kt.

The slow flow keeps the part of the right-hand sides that does not oscillate: written with
exponentials, the terms e^{iwt} whose frequency w vanishes with the small parameter (w = 0 at
exact resonance, w = O(ε) near it, which then stays in the slow flow as a slow phase).  An
autonomous perturbation (damping, quadratic drag, dry friction, a nonlinear stiffness) is
averaged in the polar form θ = r cos(kt + β):  r' = ⟨φ sin ψ⟩/k,  β' = ⟨φ cos ψ⟩/(kr),
ψ = kt + β, the mean over ψ taken on quarter periods where every abs and sign argument keeps
its sign.  Its amplitude equation r' = f(r) is then solved by SymPy's dsolve for the amplitude
law r(t) (:func:`amplitude_law`), and one swing (a time π/k) changes the amplitude by
(π/k) f(r) to first order.
"""
from __future__ import annotations

from dataclasses import dataclass

import mpmath as mp
import sympy as sp

from .. import truth as model
from .. import verify as engine
from .problem import Problem
from .secular import NEAR

a_, b_ = sp.symbols("a b", real=True)
r_, beta_ = sp.Symbol("r", positive=True), sp.Symbol("beta", real=True)
psi_ = sp.Symbol("psi", real=True)


class NotAveraged(ValueError):
    """The perturbation could not be averaged (the reason is the message)."""


@dataclass(frozen=True)
class SlowFlow:
    form: str                # "cartesian" (a, b) or "polar" (r, beta)
    variables: tuple         # the two slow variables
    rates: tuple             # their derivatives (may hold t near resonance)
    theta: sp.Expr           # θ in terms of the slow variables and t
    start: tuple             # their values at t = 0

    def equations(self) -> list[str]:
        return [f"{sp.sstr(v)}' = {sp.sstr(r)}" for v, r in zip(self.variables, self.rates)]


def _slow_part(expr: sp.Expr, problem: Problem) -> sp.Expr:
    """The terms of expr whose frequency vanishes, vanishes with ε, or is under NEAR·k (slow)."""
    t, small = problem.t, problem.small
    kval = abs(sp.N(problem.k.subs(problem.values())))
    ex = sp.expand(sp.powsimp(sp.expand(expr.rewrite(sp.exp)), combine="exp"))
    keep = sp.S.Zero
    for term in sp.Add.make_args(ex):
        w = sp.S.Zero
        for fac in sp.Mul.make_args(term):
            if fac.func == sp.exp and fac.has(t):
                w += sp.expand(fac.args[0] / (sp.I * t))
        if w.has(t):
            raise NotAveraged("the time dependence is not a sum of oscillations e^{iwt}")
        w0 = w.subs(problem.values()).subs(small, 0)
        if w == 0 or sp.simplify(w0) == 0 or (w0.is_number and abs(sp.N(w0)) < NEAR * kval):
            keep += term
    return sp.simplify(sp.expand(keep.rewrite(sp.cos)))


def _mean_piecewise(f: sp.Expr, psi: sp.Symbol, num: dict) -> sp.Expr:
    """(1/2π)∫_0^{2π} f dψ, with abs and sign resolved on each quarter period (their signs probed
    at the parameters' values ``num`` and r = 1; the integral stays symbolic)."""
    total = sp.S.Zero
    kinks = [a for a in f.atoms(sp.Abs, sp.sign)]
    for j in range(4):
        lo, hi = j * sp.pi / 2, (j + 1) * sp.pi / 2
        piece = f
        for atom in kinks:
            arg = atom.args[0]
            probe = [arg.subs(num).subs({psi: lo + (hi - lo) * s / 8}).subs(r_, 1) for s in range(1, 8)]
            signs = {sp.sign(sp.N(p)) for p in probe}
            signs.discard(0)
            if len(signs) != 1 or not all(p.is_number for p in probe):
                raise NotAveraged(f"the sign of {sp.sstr(arg)} is not constant on a quarter period")
            s = signs.pop()
            piece = piece.xreplace({atom: s * arg if atom.func == sp.Abs else s})
        total += sp.integrate(sp.expand(piece), (psi, lo, hi))
    return sp.simplify(total / (2 * sp.pi))


def _bessel_mean(facs: list, al, be, mu, nu):
    """⟨g(z cos ψ) cos^α ψ sin^β ψ⟩, z = cr, for one factor g = sin or cos of cθ (θ = r cos ψ) given as
    (g, z), and integer powers,
    by the Jacobi–Anger expansions cos(z cos ψ) = J₀(z) + 2Σ_{m≥1}(−1)^m J_{2m}(z) cos 2mψ and
    sin(z cos ψ) = 2Σ_{m≥0}(−1)^m J_{2m+1}(z) cos(2m+1)ψ: only the harmonics up to α + β meet the
    trigonometric polynomial cos^α sin^β, so the sum is finite.  None for several such factors or for
    abs/sign powers beside them."""
    if len(facs) != 1 or not (al.is_integer and be.is_integer) or al != mu or be != nu:
        return None
    func, z = facs[0]
    poly = sp.cos(psi_)**al * sp.sin(psi_)**be
    top = int(al + be)

    def mean_with(n):
        return sp.integrate(sp.expand(poly * sp.cos(n * psi_)), (psi_, 0, 2 * sp.pi)) / (2 * sp.pi)
    if func == sp.cos:
        out = sp.besselj(0, z) * mean_with(0)
        out += sum((2 * (-1)**m * sp.besselj(2 * m, z) * mean_with(2 * m) for m in range(1, top // 2 + 1)), sp.S.Zero)
    else:
        out = sum((2 * (-1)**m * sp.besselj(2 * m + 1, z) * mean_with(2 * m + 1) for m in range((top + 1) // 2)),
                  sp.S.Zero)
    return sp.simplify(out)


def _monomial_mean(expr: sp.Expr, problem: Problem, weight: str):
    """⟨φ w⟩ over ψ ∈ [0, 2π] along θ = r cos ψ, θ' = −rk sin ψ (w = sin ψ or cos ψ), in closed form, when
    φ is a sum of generalized monomials c θ^i θ'^j |θ|^p |θ'|^q sign(θ)^m sign(θ')^n (p, q any real
    powers: power-law damping, Coulomb friction, |θ|θ).  Each is ±r^… |cos ψ|^α |sin ψ|^β sgn(cos ψ)^μ
    sgn(sin ψ)^ν, whose mean is 0 when μ or ν is odd (the four quarters cancel) and otherwise
    B((α+1)/2, (β+1)/2)/π (the Wallis–Beta integral ∫_0^{π/2} cos^α sin^β = B((α+1)/2, (β+1)/2)/2 on
    each quarter).  None when φ is not of that form."""
    th, dth, k = problem.theta, problem.dtheta, problem.k
    total = sp.S.Zero
    for term in sp.Add.make_args(sp.expand(expr)):
        coeff = sp.S.One
        al, be, mu, nu = sp.S.Zero, sp.S.Zero, 0, 0      # |cos|^al |sin|^be sgn(cos)^mu sgn(sin)^nu
        scale = sp.S.One                                   # powers of r and k, and signs
        bessel = []                                        # sin(cθ), cos(cθ) factors
        for fac in sp.Mul.make_args(term):
            base, pw = fac.as_base_exp()
            if not fac.has(th, dth):
                coeff *= fac
                continue
            if fac.func in (sp.sin, sp.cos) and not fac.args[0].has(dth) and \
                    sp.expand(fac.args[0] - th * sp.diff(fac.args[0], th)) == 0 and \
                    not sp.diff(fac.args[0], th).has(th):
                bessel.append((fac.func, sp.diff(fac.args[0], th) * r_))
                continue
            if base == th and pw.is_integer:
                al, mu, scale = al + pw, mu + pw, scale * r_**pw
            elif base == dth and pw.is_integer:
                be, nu, scale = be + pw, nu + pw, scale * (-r_ * k)**pw
            elif base == sp.Abs(th) and pw.is_real:
                al, scale = al + pw, scale * r_**pw
            elif base == sp.Abs(dth) and pw.is_real:
                be, scale = be + pw, scale * (r_ * k)**pw
            elif base == sp.sign(th) and pw.is_integer:
                mu += pw
            elif base == sp.sign(dth) and pw.is_integer:
                nu, scale = nu + pw, scale * (-1)**pw
            else:
                return None
        if weight == "sin":
            be, nu = be + 1, nu + 1
        else:
            al, mu = al + 1, mu + 1
        if not (al.is_number and be.is_number) or al <= -1 or be <= -1:
            return None
        if bessel:
            part = _bessel_mean(bessel, al, be, mu, nu)
            if part is None:
                return None
            total += coeff * scale * part
            continue
        if int(mu) % 2 or int(nu) % 2:
            continue
        total += coeff * scale * sp.gamma((al + 1) / 2) * sp.gamma((be + 1) / 2) / (sp.pi * sp.gamma((al + be + 2) / 2))
    return sp.simplify(total)


def slow_flow(problem: Problem) -> SlowFlow:
    """The averaged equations of the problem (first order in the small parameter)."""
    t, k, phi = problem.t, problem.k, problem.phi
    a0, b0 = problem.theta_i, problem.omega_i / k
    if problem.autonomous:
        from sympy.simplify.fu import TR8     # products and powers of sin, cos of θ as sums (sin²θ → ½ − ½cos 2θ)
        flat = sp.expand(TR8(phi)) if phi.has(sp.sin, sp.cos) else phi
        dr = _monomial_mean(flat / k, problem, "sin")
        dbeta = _monomial_mean(flat / (k * r_), problem, "cos")
        if dr is not None and dbeta is not None:
            return SlowFlow("polar", (r_, beta_), (dr, dbeta), r_ * sp.cos(k * t + beta_),
                            (sp.sqrt(a0**2 + b0**2), sp.atan2(-b0, a0)))
    kinks = {atom: sp.Dummy() for atom in phi.atoms(sp.Abs, sp.sign)}
    try:
        poly = sp.Poly(phi.xreplace(kinks), problem.theta, problem.dtheta)
    except sp.PolynomialError:
        poly = None
    if poly is None or any(c.has(problem.theta, problem.dtheta) for c in poly.coeffs()):
        raise NotAveraged("averaging is done for φ polynomial in the variable and its velocity (abs and sign of "
                          "any expression allowed when autonomous), or a sum of terms θ^i θ'^j |θ|^p |θ'|^q "
                          "sign(θ)^m sign(θ')^n with any real p, q, or θ^i θ'^j times one sin or cos of cθ; "
                          "for another φ make the small parameter the "
                          "amplitude (Lindstedt–Poincaré expands it)")
    if phi.has(sp.Abs, sp.sign) and not problem.autonomous:
        raise NotAveraged("abs or sign with an explicit time dependence is not averaged")
    if problem.autonomous:
        on = phi.subs({problem.theta: r_ * sp.cos(psi_), problem.dtheta: -r_ * k * sp.sin(psi_)},
                      simultaneous=True)
        num = problem.values()
        dr = _mean_piecewise(on * sp.sin(psi_) / k, psi_, num)
        dbeta = _mean_piecewise(on * sp.cos(psi_) / (k * r_), psi_, num)
        return SlowFlow("polar", (r_, beta_), (dr, dbeta), r_ * sp.cos(k * t + beta_),
                        (sp.sqrt(a0**2 + b0**2), sp.atan2(-b0, a0)))
    theta = a_ * sp.cos(k * t) + b_ * sp.sin(k * t)
    on = phi.subs({problem.theta: theta, problem.dtheta: sp.diff(theta, t)}, simultaneous=True)
    da = _slow_part(on * sp.sin(k * t) / k, problem)
    db = _slow_part(-on * sp.cos(k * t) / k, problem)
    return SlowFlow("cartesian", (a_, b_), (da, db), theta, (a0, b0))


def amplitude_law(problem: Problem, flow: SlowFlow) -> sp.Expr | None:
    """r(t) solving the averaged amplitude equation r' = f(r) from r(0) (SymPy's dsolve), or None
    when the flow is not polar, f depends on more than r, or dsolve gives no single explicit law."""
    if flow.form != "polar" or flow.rates[0].has(beta_, problem.t):
        return None
    t = problem.t
    rf, r0 = sp.Function("r"), sp.Symbol("r0", positive=True)
    try:
        sol = sp.dsolve(sp.Eq(rf(t).diff(t), flow.rates[0].subs(r_, rf(t))), rf(t), ics={rf(t).subs(t, 0): r0})
    except (NotImplementedError, ValueError, TypeError):
        return None
    for cand in (sol if isinstance(sol, list) else [sol]):       # the one solution that is r(t) from r(0)
        if cand.rhs.has(rf) or cand.rhs.has(sp.Integral):
            continue
        law = sp.simplify(cand.rhs.subs(r0, flow.start[0]))
        ok = sp.simplify(sp.diff(law, t) - flow.rates[0].subs(r_, law))       # r' = f(r) holds
        if ok == 0 and sp.simplify(law.subs(t, 0) - flow.start[0]) == 0:
            return law
    return None


def flow_trajectory(problem: Problem, rates, variables, start, eps, dps: int):
    """(trajectory, sub): the slow flow y' = rates(t, y) from y(0) = start at ε = eps, integrated
    by mpmath at dps digits (trajectory(t) → y), and the substitution of the problem's values and
    of ε it was built with."""
    vals = problem.values()
    sub = lambda e: e.subs(vals).subs(problem.small, sp.Rational(str(eps)))
    f = [engine.lambdify_mp(sub(r), (problem.t, *variables)) for r in rates]
    with mp.workdps(dps):
        y0 = [engine.value_at(sub(s), {}) for s in start]
    return model.integrate(lambda t, y: [fi(t, *y) for fi in f], y0, dps=dps), sub


def integrate(problem: Problem, flow: SlowFlow, eps, times, dps: int) -> list:
    """[(θ, θ')] of the averaged motion at the increasing ``times`` (the slow flow integrated by mpmath)."""
    traj, sub = flow_trajectory(problem, flow.rates, flow.variables, flow.start, eps, dps)
    th = engine.lambdify_mp(sub(flow.theta), (problem.t, *flow.variables))
    dth = engine.lambdify_mp(sub(sp.diff(flow.theta, problem.t)), (problem.t, *flow.variables))
    out = []
    with mp.workdps(dps):
        for s in times:
            y = traj(s)
            out.append((th(mp.mpf(s), *y), dth(mp.mpf(s), *y)))
    return out
