"""Per-swing changes by variation of constants, to first order in the small parameter.

For a start at rest, θ0 = θ_i cos kt turns back at t* = π/k.  With the integrals
E_s = ∫_0^{t*} φ sin kτ dτ and E_c = ∫_0^{t*} φ cos kτ dτ along θ0 (φ taken to first order in
the small parameter), :mod:`pendsym.perturbation` gives θ1 and θ1' at t*, the shift of the
turning time (the change of the swing's duration, ΔT) and θ(t*) = −θ_i + θ1(t*), so the change
of amplitude over the swing is Δα = −sign(θ_i)·θ1(t*).  The integrals are definite: abs and
sign are resolved on the two quarter periods of the swing, where their arguments keep a sign.
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from .. import perturbation
from .problem import Problem


class NotPerSwing(ValueError):
    """No per-swing answer (the reason is the message)."""


@dataclass(frozen=True)
class SwingAnswer:
    duration: sp.Expr      # the swing's duration π/k + ΔT
    shift: sp.Expr         # ΔT
    amplitude: sp.Expr     # Δα, change of |θ| at the turning point
    lowest_speed: sp.Expr  # |θ'| at the lowest point of θ0 (t = π/2k), to first order


def _definite(expr: sp.Expr, t: sp.Symbol, k: sp.Expr, lo, hi, num: dict) -> sp.Expr:
    """∫ expr dt over the phase kt ∈ [lo, hi] (within one quarter period when abs or sign occur:
    their signs are probed at the parameters' values ``num`` and the integral kept symbolic)."""
    x = sp.Dummy("x", real=True)
    f = expr.subs(t, x / k) / k
    for atom in f.atoms(sp.Abs, sp.sign):
        arg = atom.args[0]
        probes = [sp.N(arg.subs(num).subs(x, lo + (hi - lo) * s / 8)) for s in range(1, 8)]
        signs = {sp.sign(p) for p in probes if p.is_number} - {0}
        if len(signs) != 1 or not all(p.is_number for p in probes):
            raise NotPerSwing(f"cannot resolve the sign of {sp.sstr(arg)} over the swing")
        s = signs.pop()
        f = f.xreplace({atom: s * arg if atom.func == sp.Abs else s})
    return sp.integrate(sp.expand(f), (x, lo, hi))


def _integral(expr, t, k, lo, hi, num) -> sp.Expr:
    """∫ over the phase [lo, hi], split at quarter periods when abs or sign occur."""
    if not expr.has(sp.Abs, sp.sign):
        return _definite(expr, t, k, lo, hi, num)
    cuts = [lo + j * sp.pi / 2 for j in range(int((hi - lo) / (sp.pi / 2)) + 1)]
    return sum((_definite(expr, t, k, c0, c1, num) for c0, c1 in zip(cuts, cuts[1:])), sp.S.Zero)


def first_swing(problem: Problem) -> SwingAnswer:
    """ΔT and Δα of the first swing from rest, to first order in the small parameter."""
    if problem.omega_i != 0:
        raise NotPerSwing("per-swing values need a start at rest (initial velocity 0)")
    t, k, eps = problem.t, problem.k, problem.small
    phi1 = sp.diff(problem.phi, eps).subs(eps, 0)
    if sp.expand(problem.phi.subs(eps, 0)) != 0:
        raise NotPerSwing("the perturbation does not vanish with the small parameter")
    theta0 = perturbation.unperturbed(t, k, problem.theta_i)
    num = {s: sp.Rational(v) for s, v in problem.parameters.items()}
    along = perturbation.along(phi1, problem.theta, problem.dtheta, theta0, t)
    Es = _integral(along * sp.sin(k * t), t, k, 0, sp.pi, num)
    Ec = _integral(along * sp.cos(k * t), t, k, 0, sp.pi, num)
    t_star = sp.pi / k
    # θ1, θ1' at t* from the integrals at t* (they are constants there)
    th1 = perturbation.theta1(Es, Ec, eps, k, t).subs(t, t_star)
    dth1 = perturbation.dtheta1(Es, Ec, eps, k, t)
    shift = perturbation.turning_shift(theta0, dth1, t, t_star)
    sgn = sp.sign(problem.theta_i.subs(num))
    amplitude = sp.simplify(-sgn * th1)
    # |θ'| at the lowest point of θ0, to first order: θ0' + θ1' at π/2k (integrals over one quarter)
    quarter = sp.pi / (2 * k)
    Es_q = _integral(along * sp.sin(k * t), t, k, 0, sp.pi / 2, num)
    Ec_q = _integral(along * sp.cos(k * t), t, k, 0, sp.pi / 2, num)
    speed = sp.diff(theta0, t).subs(t, quarter) + perturbation.dtheta1(Es_q, Ec_q, eps, k, t).subs(t, quarter)
    return SwingAnswer(duration=sp.simplify(t_star + shift), shift=sp.simplify(shift),
                       amplitude=amplitude, lowest_speed=sp.simplify(sp.Abs(speed)))


def _sums(expr: sp.Expr) -> sp.Expr:
    """Products of sines and cosines written as sums (SymPy's product-to-sum rule TR8)."""
    from sympy.simplify.fu import TR8
    return sp.expand(TR8(sp.expand(expr)))


def _duhamel(force: sp.Expr, t: sp.Symbol, k: sp.Expr) -> sp.Expr:
    """θ_n with θ_n'' + k²θ_n = force, θ_n(0) = θ_n'(0) = 0 (variation of constants):
    θ_n = (1/k)[sin kt ∫_0^t force cos ks ds − cos kt ∫_0^t force sin ks ds]."""
    s = sp.Dummy("s", positive=True)
    f = force.subs(t, s)

    def integral(weight):
        body = _sums(f * weight(k * s))
        return sp.Add(*[sp.integrate(term, (s, 0, t), conds="none") for term in sp.Add.make_args(body)])
    return _sums((sp.sin(k * t) * integral(sp.cos) - sp.cos(k * t) * integral(sp.sin)) / k)


def closed_form_in_time(problem: Problem, n: int) -> bool:
    """Every εʲ coefficient (j ≤ n) of φ is a sum of terms t^m sin(wt + c), t^m cos(wt + c) times powers of
    θ and θ': the repeated Duhamel integrals then have closed forms (SymPy can hang on others, 1/(1 + t))."""
    t, eps = problem.t, problem.small
    try:
        ser = sp.expand(sp.series(problem.phi, eps, 0, n + 1).removeO()) if problem.phi.has(eps) else problem.phi
    except (ValueError, NotImplementedError, TypeError):
        return False
    for term in sp.Add.make_args(sp.expand(ser)):
        for fac in sp.Mul.make_args(term):
            if not fac.has(t):
                continue
            base, pw = fac.as_base_exp()
            if base == t and pw.is_integer and pw >= 0:
                continue
            if fac.func in (sp.sin, sp.cos) and sp.diff(fac.args[0], t, 2) == 0 \
                    and not fac.args[0].has(problem.theta, problem.dtheta):
                continue
            if base.func in (sp.sin, sp.cos) and pw.is_integer and pw > 0 and sp.diff(base.args[0], t, 2) == 0 \
                    and not base.args[0].has(problem.theta, problem.dtheta):
                continue
            return False
    return True


def swing_to_order(problem: Problem, n: int) -> SwingAnswer:
    """ΔT and Δα of the first swing from rest to order n: θ = Σ εʲ θ_j by repeated variation of
    constants (each θ_j from the εʲ part of −φ along the lower orders), then the turning time
    t* = π/k + Σ εʲ δ_j solved order by order from θ'(t*) = 0 and θ(t*) expanded."""
    if problem.omega_i != 0:
        raise NotPerSwing("per-swing values need a start at rest (initial velocity 0)")
    if problem.phi.has(sp.Abs, sp.sign):
        raise NotPerSwing("abs or sign: the per-swing expansion is first order only")
    t, k, eps = problem.t, problem.k, problem.small
    theta0 = perturbation.unperturbed(t, k, problem.theta_i)
    thetas = [theta0]
    phi_ser = sp.series(problem.phi, eps, 0, n + 1).removeO() if problem.phi.has(eps) else problem.phi
    for j in range(1, n + 1):
        partial = sum((eps**i * th for i, th in enumerate(thetas)), sp.S.Zero)
        along = phi_ser.subs({problem.theta: partial, problem.dtheta: sp.diff(partial, t)}, simultaneous=True)
        force = -sp.expand(sp.series(along, eps, 0, j + 1).removeO()).coeff(eps, j)
        thetas.append(_duhamel(force, t, k))
    theta = sum((eps**i * th for i, th in enumerate(thetas)), sp.S.Zero)
    deltas = sp.symbols(f"delta1:{n + 1}")
    t_star = sp.pi / k + sum((eps**j * d for j, d in enumerate(deltas, start=1)), sp.S.Zero)
    vel = sp.expand(sp.series(sp.diff(theta, t).subs(t, t_star), eps, 0, n + 1).removeO())
    found = {}
    for j, d in enumerate(deltas, start=1):
        eq = sp.expand(vel.coeff(eps, j).subs(found))
        found[d] = sp.simplify(sp.solve(eq, d)[0])
    shift = sp.expand(sum((eps**j * found[d] for j, d in enumerate(deltas, start=1)), sp.S.Zero))
    pos = sp.series(theta.subs(t, t_star).subs(found), eps, 0, n + 1).removeO()
    sgn = sp.sign(problem.theta_i.subs(problem.values()))
    amplitude = sp.simplify(sp.expand(-sgn * pos - sgn * problem.theta_i))
    shift = sp.simplify(shift)
    return SwingAnswer(duration=sp.pi / k + shift, shift=shift, amplitude=amplitude,
                       lowest_speed=sp.nan)
