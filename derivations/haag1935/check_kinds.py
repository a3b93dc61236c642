"""The check adapter this memoir needs beyond :mod:`pendsym.checks`, written once.

:class:`OnShotBlade` runs ``checks.Values`` on forms holding integrals over the blade (∫_0^λ, ∫_0^s)
and v, w, v', w' at a point, which :func:`pendsym.verify.value_at` cannot evaluate: each becomes a
symbol valued by quadrature on the shot blade.  It is a frozen declaration called as
``check(result, level)`` (the engine runs such a callable as a custom check).
"""
from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import Callable, Iterable, Mapping

import mpmath as mp
import sympy as sp

from pendsym import blade, checks, verify
from pendsym.checks import Point
from pendsym.result import Evidence, Result
from .symbols import M_of_s, epsilon_of_s, lam, s, v, w

Confirm = Callable[[int], Mapping[str, object]] | None


def blade_integral(integral: sp.Integral, env: Mapping, shot: blade.BladeSolution, eps=None, at=None) -> mp.mpf:
    """∫_0^λ f(v, w, M, ε, s) ds, or ∫_0^s with s = ``at``, by Gauss–Legendre quadrature on the shot blade
    (v'' = v/M (9)); the other symbols of f are read in env, ε(s) is ``eps`` (0 when None)."""
    (var, lo, hi), = integral.limits
    body = integral.function.subs({v(var).diff(var, 2): v(var) / M_of_s(var),
                                   w(var).diff(var, 2): w(var) / M_of_s(var)})
    v_, w_, M_, eps_ = sp.symbols("V_ W_ M_ E_")
    body = body.subs({v(var): v_, w(var): w_, M_of_s(var): M_, epsilon_of_s(var): eps_})
    others = sorted(body.free_symbols - {v_, w_, M_, eps_, var}, key=lambda x: x.name)
    integrand = verify.lambdify_mp(body, (v_, w_, M_, eps_, var, *others))
    values = [env[x.name] for x in others]
    eps = eps or (lambda x: 0)

    def f(x):
        state = shot.state(x)
        return integrand(state[0], state[2], shot.M_at(x), eps(x), x, *values)
    if lo == 0 and hi == lam:
        return shot.integrate(f)
    if lo == 0 and hi == s and at is not None:
        with mp.workdps(shot.wdps):
            return blade.integrate_pieces([(a, min(b, at), q, M) for a, b, q, M in shot.pieces if a < at], f)
    raise ValueError(f"no quadrature for an integral over {integral.limits}")


@dataclass(frozen=True)
class OnShotBlade:
    """checks.Values for forms holding integrals over the blade and v(s), w(s), v'(s), w'(s) at a point.

    ``points(level, dps)`` yields (Point, shot blade, ε(s) or None, s or None).  Each Integral of the
    derived and printed forms, and each derivative v'(s), w'(s) outside them, becomes a symbol, valued at
    each point from the point's shot blade (:func:`blade_integral`, its state at s); then the engine
    evaluates, compares, confirms and builds the Evidence.
    """

    truth: str
    points: Callable[[str, int], Iterable[tuple]]
    confirm: Confirm = None
    params: Callable[[str], tuple] | tuple = ()
    kind: str = "value"

    def __call__(self, result: Result, level: str) -> Evidence:
        integrals: dict[sp.Integral, sp.Symbol] = {}
        slopes: dict[sp.Derivative, sp.Symbol] = {}

        def rewrite(form):
            if form is None:
                return None
            for integral in sorted(form.atoms(sp.Integral), key=sp.srepr):
                integrals.setdefault(integral, sp.Symbol(f"_I{len(integrals)}"))
            form = form.xreplace(integrals)
            for slope in sorted(form.atoms(sp.Derivative), key=sp.srepr):
                if slope.args[0] not in (v(s), w(s)) or slope.derivative_count != 1:
                    raise ValueError(f"no value for {slope} at a point")
                slopes.setdefault(slope, sp.Symbol(f"_D{len(slopes)}"))
            return form.xreplace(slopes)
        derived, printed = rewrite(result.derived_value), rewrite(result.printed_value)
        proxy = dataclasses.replace(result, derived=derived, printed=printed,
                                    spec=dataclasses.replace(result.spec, defs=()))

        def points(level_: str, dps: int):
            for pt, shot, eps, at in self.points(level_, dps):
                env = dict(pt.env)
                env.update({symbol.name: blade_integral(integral, env, shot, eps, at)
                            for integral, symbol in integrals.items()})
                if at is not None:
                    state = shot.state(at)
                    env.update({v(s): state[0], w(s): state[2]})
                    env.update({symbol.name: state[1] if slope.args[0] == v(s) else state[3]
                                for slope, symbol in slopes.items()})
                yield Point(pt.label, env, pt.truth, pt.denom)
        return checks.run(checks.Values(truth=self.truth, points=points, confirm=self.confirm, params=self.params,
                                        kind=self.kind),
                          proxy, level)
