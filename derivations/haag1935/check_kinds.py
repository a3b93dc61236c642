"""Check kinds that :mod:`pendsym.checks` lacks, written once for the memoir.

Each is a frozen declaration called as ``check(result, level)`` (the engine runs
such a callable as a custom check) and builds its Evidence once, with the
engine's confirmation (:func:`pendsym.checks.confirmation_digits`).  They are
candidates for the engine:

* :class:`TupleDefinition` a definition with several components (``checks.Definition`` takes one);
* :class:`Components`      ``checks.Values`` for a form with several components (a Tuple);
* :class:`Vanishes`        a form that must vanish, its residual relative to Σ|terms| of that form;
* :class:`Fails`           a counterexample: the formula must be off the truth by a margin;
* :class:`OnShotBlade`     ``checks.Values`` for forms holding integrals over the blade (∫_0^λ, ∫_0^s) and
                           v, w, v', w' at a point, which :func:`pendsym.verify.value_at` cannot evaluate.
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


def terms_scale(expr: sp.Expr, env: Mapping) -> mp.mpf:
    """Σ|terms| of the expanded expr at env: the scale of a quantity that should vanish."""
    terms = sp.Add.make_args(sp.expand(expr))
    return sum((abs(mp.mpf(verify.value_at(term, env))) for term in terms), mp.mpf(0))


def _confirmed(digits: float | None) -> bool:
    return digits is None or digits >= checks.MIN_DIGITS


def _confirm_note(digits: float | None) -> str:
    return "" if digits is None else f"; truth confirmed to {digits:.1f} digits at {checks.CONFIRM_DPS} digits"


@dataclass(frozen=True)
class TupleDefinition:
    """A definition with several components: each equal to the text, exactly."""

    def __call__(self, result: Result, level: str) -> Evidence:
        same = result.printed is not None and len(result.printed) == len(result.derived) and all(
            sp.simplify(p - d) == 0 for p, d in zip(result.printed_value, result.derived_value))
        return Evidence(kind="definition", passed=bool(same), truth="a definition, compared exactly with the text")


@dataclass(frozen=True)
class Components:
    """Each component of a Tuple form against a truth: ``points(level, dps)`` yields
    (component index, Point); as checks.Values otherwise."""

    truth: str
    points: Callable[[str, int], Iterable[tuple[int, Point]]]
    confirm: Confirm = None
    tol: object = checks.TOL

    def __call__(self, result: Result, level: str) -> Evidence:
        forms = {"derived": result.derived_value}
        if result.printed is not None:
            forms["printed"] = result.printed_value
        worst = dict.fromkeys(forms, mp.mpf(0))
        n = 0
        with mp.workdps(40):
            for index, pt in self.points(level, checks.DPS):
                n += 1
                for name, form in forms.items():
                    worst[name] = max(worst[name], pt.residual(verify.value_at(form[index], pt.env)))
        digits = checks.confirmation_digits(self.confirm)
        tol = mp.mpf(self.tol)
        note = f"{n} (point, component) pairs" + _confirm_note(digits)
        if "printed" in worst:
            note += f"; printed form: max residual {float(worst['printed']):.3g}"
        return Evidence(kind="value", passed=bool(worst["derived"] < tol and _confirmed(digits)), truth=self.truth,
                        max_residual=verify.rounded(worst["derived"]),
                        printed_agrees=None if "printed" not in worst else bool(worst["printed"] < tol),
                        confirm_digits=None if digits is None else verify.rounded(digits), note=note)


@dataclass(frozen=True)
class Vanishes:
    """The form vanishes at each point of ``points(level, dps)`` ((label, env)): its value relative
    to Σ|terms| of the same form must stay below ``tol``, for the derived and the printed form."""

    truth: str
    points: Callable[[str, int], Iterable[tuple[str, Mapping]]]
    confirm: Confirm = None
    tol: object = checks.TOL

    def __call__(self, result: Result, level: str) -> Evidence:
        forms = {"derived": result.derived_value}
        if result.printed is not None:
            forms["printed"] = result.printed_value
        worst = dict.fromkeys(forms, mp.mpf(0))
        n = 0
        with mp.workdps(40):
            for _, env in self.points(level, checks.DPS):
                n += 1
                for name, form in forms.items():
                    value = abs(mp.mpf(verify.value_at(form, env))) / terms_scale(form, env)
                    worst[name] = max(worst[name], value)
        digits = checks.confirmation_digits(self.confirm)
        tol = mp.mpf(self.tol)
        note = f"{n} cases, residual relative to Σ|terms|" + _confirm_note(digits)
        if "printed" in worst:
            note += f"; printed: {float(worst['printed']):.3g}"
        return Evidence(kind="value", passed=bool(worst["derived"] < tol and _confirmed(digits)), truth=self.truth,
                        max_residual=verify.rounded(worst["derived"]),
                        printed_agrees=None if "printed" not in worst else bool(worst["printed"] < tol),
                        confirm_digits=None if digits is None else verify.rounded(digits), note=note)


@dataclass(frozen=True)
class Fails:
    """A counterexample: at every point the derived form must be off its truth by more than
    ``margin`` (relative residual, as Point.residual)."""

    truth: str
    points: Callable[[str, int], Iterable[Point]]
    margin: object = mp.mpf("1e-4")

    def __call__(self, result: Result, level: str) -> Evidence:
        residuals = []
        with mp.workdps(40):
            for pt in self.points(level, checks.DPS):
                residuals.append((pt.label, pt.residual(verify.value_at(result.derived_value, pt.env))))
        least = min(res for _, res in residuals)
        note = "must fail; relative residual " + "; ".join(f"{label}: {mp.nstr(res, 3)}" for label, res in residuals)
        return Evidence(kind="value", passed=bool(least > mp.mpf(self.margin)), truth=self.truth,
                        max_residual=verify.rounded(least), note=note)


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
