"""The truth of a problem whose φ has abs or sign: the equation integrated piece by piece.

mpmath's Taylor solver needs an analytic right-hand side; θ'' = −k²θ − φ with |θ'| or
sign(θ') in φ (air drag, dry friction) is analytic only between the zeros of the arguments
of abs and sign (for air drag: between the turning points).  So the motion is integrated
as a chain of smooth pieces:

1. at the start of a piece every argument g_i(θ, θ', t) of an abs or a sign is given its
   sign σ_i: the sign of g_i, or, when g_i vanishes there (the piece starts on a kink), the
   sign of its rate dg_i/dt = ∂g_i/∂θ θ' + ∂g_i/∂θ' θ'' + ∂g_i/∂t along the motion;
2. φ with abs(g_i) → σ_i g_i and sign(g_i) → σ_i is integrated by
   :func:`pendsym.truth.integrate` (odefun) from the piece's start;
3. the piece ends at the first time some σ_i g_i turns negative: bracketed by a scan of the
   dense solution at a fixed fraction of the unperturbed period, refined by a bracketing root
   finder (Anderson–Björk), and the next piece starts from the state there.

Nothing in this uses a perturbation formula.  A piece that starts on a kink it cannot leave
on the side its rate points to (a sticking point of dry friction: with sign(θ') = σ the
acceleration points back) is refused: the motion there is not decided by the equation as
written.
"""
from __future__ import annotations

import itertools
from bisect import bisect_right
from dataclasses import dataclass

import mpmath as mp
import sympy as sp

from .. import truth as model
from .. import verify as engine
from .problem import Problem

SCAN = 24              # scan steps per unperturbed period
MAX_PIECES = 4000


class NotIntegrable(ValueError):
    """The piecewise integration cannot continue (the reason is the message)."""


def kink_arguments(phi: sp.Expr) -> list[sp.Expr]:
    """The arguments of abs and sign in φ, innermost first (sorted by size, then text)."""
    return sorted({a.args[0] for a in phi.atoms(sp.Abs, sp.sign)}, key=lambda g: (sp.count_ops(g), sp.sstr(g)))


def smooth_part(phi: sp.Expr, args: list, signs: tuple) -> sp.Expr:
    """φ with abs(g_i) → σ_i g_i and sign(g_i) → σ_i (σ_i = ±1)."""
    rep = {}
    for g, s in zip(args, signs):
        rep[sp.Abs(g)] = s * g
        rep[sp.sign(g)] = sp.Integer(s)
    return phi.xreplace(rep)


def _require_analytic(expr: sp.Expr, args: list) -> None:
    """Refuse a piece that is not analytic where it starts: a non-integer power of an expression that
    vanishes at the kink (|θ'|^{1/2}: the Taylor solver cannot start a piece at θ' = 0)."""
    for pw in expr.atoms(sp.Pow):
        base, ex = pw.as_base_exp()
        if not ex.is_integer and any(base.has(*g.free_symbols) for g in args if g.free_symbols):
            raise NotIntegrable(f"the equation is not analytic at its kinks ({sp.sstr(pw)}): the Taylor integrator "
                                f"cannot start a piece there, so it is not integrated")


@dataclass(frozen=True)
class Piecewise:
    """A dense solution made of smooth pieces: starts[i] is where pieces[i] begins."""

    starts: tuple
    pieces: tuple          # model.Trajectory of each piece
    dps: int

    def __call__(self, t) -> list:
        with mp.workdps(self.dps):
            i = max(bisect_right(self.starts, mp.mpf(t)) - 1, 0)
            return self.pieces[i](t)

    def turning_points(self) -> tuple:
        """The starts of the pieces after the first (for air drag: the turning points)."""
        return self.starts[1:]


def integrate(problem: Problem, eps, dps: int, t_end) -> Piecewise:
    """The motion of the problem at small parameter ``eps`` from t = 0 to ``t_end``, piece by piece."""
    th, dth, t = problem.theta, problem.dtheta, problem.t
    with mp.workdps(dps + 10):
        eps_exact = sp.Rational(str(mp.mpf(eps)))
    vals = {**problem.values(), problem.small: eps_exact}
    k2 = (problem.k**2).subs(vals)
    phi = problem.phi.subs(vals)
    args = kink_arguments(phi)
    for s in itertools.product((1, -1), repeat=len(args)):
        _require_analytic(smooth_part(phi, args, s), args)
    g_f = [engine.lambdify_mp(g, (t, th, dth)) for g in args]
    dg_f = [engine.lambdify_mp(sp.diff(g, th), (t, th, dth)) for g in args]
    dgv_f = [engine.lambdify_mp(sp.diff(g, dth), (t, th, dth)) for g in args]
    dgt_f = [engine.lambdify_mp(sp.diff(g, t), (t, th, dth)) for g in args]
    kinked_accel = engine.lambdify_mp(-k2 * th - phi, (t, th, dth))
    accel_of = {}

    def rate(i, t0, y, acc):
        """dg_i/dt along the motion at (t0, y), θ'' given by acc."""
        return dg_f[i](t0, *y) * y[1] + dgv_f[i](t0, *y) * acc(t0, *y) + dgt_f[i](t0, *y)

    def accel(signs):
        if signs not in accel_of:
            accel_of[signs] = engine.lambdify_mp(-k2 * th - smooth_part(phi, args, signs), (t, th, dth))
        return accel_of[signs]

    with mp.workdps(dps):
        period = 2 * mp.pi / mp.sqrt(engine.value_at(k2, {}))
        step = period / SCAN
        t_end = mp.mpf(t_end)
        y = [engine.value_at(problem.theta_i.subs(vals), {}), engine.value_at(problem.omega_i.subs(vals), {})]
        tiny = mp.mpf(10) ** (-(dps // 2))
        t0 = mp.mpf(0)
        starts, pieces = [], []
        while True:
            signs = []
            for i in range(len(args)):
                g = g_f[i](t0, *y)
                if abs(g) > tiny:
                    signs.append(1 if g > 0 else -1)
                    continue
                r = rate(i, t0, y, kinked_accel)
                if abs(r) <= tiny:
                    raise NotIntegrable(f"the motion reaches {sp.sstr(args[i])} = 0 with zero rate at "
                                        f"t = {mp.nstr(t0, 8)} (sticking): the equation does not decide it")
                signs.append(1 if r > 0 else -1)
            signs = tuple(signs)
            f = accel(signs)
            for i, s in enumerate(signs):      # leaving the kink on the chosen side must be consistent
                if abs(g_f[i](t0, *y)) <= tiny:
                    if s * rate(i, t0, y, f) <= 0:
                        raise NotIntegrable(f"the motion cannot leave {sp.sstr(args[i])} = 0 on either side at "
                                            f"t = {mp.nstr(t0, 8)} (sticking): the equation does not decide it")
            traj = model.integrate(lambda s, u, f=f: [u[1], f(s, u[0], u[1])], y, dps=dps, t0=t0)
            starts.append(t0)
            pieces.append(traj)
            if len(pieces) > MAX_PIECES:
                raise NotIntegrable("more than 4000 smooth pieces before the end time")
            # the first time some σ_i g_i turns negative
            t_prev, end = t0, None
            while end is None and t_prev < t_end:
                t_next = min(t_prev + step, t_end)
                u = traj(t_next)
                for i, s in enumerate(signs):
                    if s * g_f[i](t_next, *u) < 0:
                        lo = t_prev if t_prev > t0 else t0 + step / 1000
                        root = mp.findroot(lambda x, i=i: g_f[i](x, *traj.solve(x)), (lo, t_next), solver="anderson")
                        end = root if end is None else min(end, root)
                t_prev = t_next
            if end is None:
                break
            t0, y = end, traj(end)
    return Piecewise(tuple(starts), tuple(pieces), dps)
