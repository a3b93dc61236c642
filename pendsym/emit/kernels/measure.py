"""Measurement: the error of a double-precision function in ulp against 50-digit mpmath.

The contract (docs/kernel-accuracy.md): at each sample point the error in ulp of the true
value, divided by max(1, κ) with κ the condition number of the problem there, is at most
:data:`BOUND`.  κ = Σ|x_i ∂f/∂x_i|/|f| is computed from the derived expression by forward
differences at 80 digits (:func:`reference`).
"""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from typing import Callable, Iterator, Sequence

import mpmath as mp
import sympy as sp

from ...result import KernelArg
from .printing import KernelPy

BOUND = 4.0    # ulp × max(1, condition number): the accuracy a kernel must hold
REF_DPS = 50   # digits of the reference values
DIGITS_PER_DECADE = 8   # a form may cancel like 1/x^8 as x → 0: so many more digits per decade below 1
COND_DPS = 80  # digits of the forward differences of κ (at least; 30 more than the value's), step 10^-COND_STEP
COND_STEP = 35


def ref_dps(p: Sequence[float]) -> int:
    """Digits for the derived form at p: REF_DPS, plus DIGITS_PER_DECADE for each decade the
    smallest nonzero coordinate lies below 1 (t = 1e-300 in kt − sin kt cos kt cancels 600 digits)."""
    small = min((abs(v) for v in p if v != 0 and math.isfinite(v)), default=1.0)
    return REF_DPS + DIGITS_PER_DECADE * max(0, math.ceil(-math.log10(small)))


@dataclass(frozen=True)
class Accuracy:
    points: int
    max_ulp: float           # largest error in units in the last place of the true value
    max_scaled: float        # largest error / max(1, condition number), in ulp
    worst_at: tuple          # the arguments of the largest scaled error


@dataclass(frozen=True)
class Naive:
    """The obvious double-precision evaluation of the printed formula, measured on the same points."""

    form: str                # "printed" or "as derived" (when the memoir prints none, or another function)
    accuracy: Accuracy
    fails: str               # where its scaled error exceeds BOUND, e.g. "u ≤ 0.03; u ≥ 700"


def reference(expr: sp.Expr, syms) -> tuple[Callable, Callable]:
    """(f, κ): the expression in mpmath, and its condition number Σ|x_i ∂f/∂x_i|/|f|.

    The partial derivatives are forward differences at 80 digits with a relative step of
    1e-35 (truncation and rounding both ~1e-35 relative): as good as the symbolic derivative
    for a condition number, and far cheaper for large kernels."""
    f = sp.lambdify(syms, expr, modules="mpmath", cse=True)    # (tanh(u/2) once, not thirty times)

    def cond(*xs):
        v = f(*xs)
        if v == 0:
            return mp.inf
        with mp.workdps(max(COND_DPS, mp.mp.dps + 30)):    # the differences keep 30 digits more than f needs
            xs = [mp.mpf(x) for x in xs]
            here, total = f(*xs), mp.mpf(0)
            for i, x in enumerate(xs):
                if x == 0:
                    continue
                h = abs(x) * mp.mpf(10) ** -COND_STEP
                up = list(xs)
                up[i] = x + h
                total += abs(x * (f(*up) - here) / h)
        return total / abs(v)
    return f, cond


@functools.lru_cache(maxsize=64)
def _reference_of(expr: sp.Expr, syms: tuple) -> tuple[Callable, Callable]:
    return reference(expr, list(syms))


@functools.lru_cache(maxsize=100_000)
def _truth_at(expr: sp.Expr, syms: tuple, p: tuple) -> tuple:
    """(50-digit value, condition number) of expr at the point p; every candidate form of a
    kernel is measured on the same points, so each is computed once."""
    f, cond = _reference_of(expr, syms)
    with mp.workdps(ref_dps(p)):
        xs = [mp.mpf(x) for x in p]
        true = f(*xs)
        try:
            kappa = float(cond(*xs)) if true != 0 else math.inf
        except (ZeroDivisionError, OverflowError, ValueError):
            kappa = math.inf
        return true, kappa


def _symbols(expr: sp.Expr, args: Sequence[KernelArg]) -> tuple[sp.Symbol, ...]:
    by = {s.name: s for s in expr.free_symbols}
    return tuple(by.get(a.name, sp.Symbol(a.name)) for a in args)


def references(expr: sp.Expr, args: Sequence[KernelArg], points) -> tuple:
    """(50-digit value, κ) of expr at each point."""
    syms = _symbols(expr, args)
    return tuple(_truth_at(expr, syms, tuple(p)) for p in points)


def _value(fn: Callable[..., float], p) -> float:
    """fn at p; NaN where it raises (an overflow, a division by zero, a domain error)."""
    try:
        return fn(*p)
    except (OverflowError, ZeroDivisionError, ValueError):
        return math.nan


def errors(fn: Callable[..., float], expr: sp.Expr, args: Sequence[KernelArg], points,
           truths=None) -> Iterator[tuple[tuple, float, float]]:
    """(point, ulp error, ulp error / max(1, κ)) at each point, against 50-digit mpmath of expr
    (or the given (value, κ) of each point); a non-finite value or an exception (overflow)
    counts as an infinite error."""
    truths = truths or references(expr, args, points)
    with mp.workdps(REF_DPS):
        for p, (true, kappa) in zip(points, truths):
            got = _value(fn, p)
            if not math.isfinite(got):
                yield p, math.inf, math.inf
            elif true == 0:
                err_ulp = 0.0 if got == 0 else abs(got) / math.ulp(0.0)
                yield p, err_ulp, 0.0 if abs(got) < 1e-300 else math.inf
            else:
                err_ulp = float(abs(mp.mpf(got) - true) / mp.mpf(math.ulp(float(true))))
                yield p, err_ulp, err_ulp / max(1.0, kappa)


def measure(fn: Callable[..., float], expr: sp.Expr, args: Sequence[KernelArg], points, truths=None) -> Accuracy:
    """ulp error of a double kernel against 50-digit mpmath of expr at the points."""
    worst_ulp = worst_scaled = 0.0
    worst_at: tuple = ()
    for p, err_ulp, scaled in errors(fn, expr, args, points, truths):
        if not math.isfinite(err_ulp):
            return Accuracy(len(points), math.inf, math.inf, p)
        worst_ulp = max(worst_ulp, err_ulp)
        if scaled > worst_scaled:
            worst_scaled, worst_at = scaled, p
    return Accuracy(len(points), round(worst_ulp, 2), round(worst_scaled, 2), worst_at)


def _failing_runs(errs: list, along: int) -> list[list[float]]:
    """[lo, hi] of each run of consecutive points (sorted along argument `along`) over BOUND."""
    runs, cur = [], None
    for p, _, scaled in sorted(errs, key=lambda e: e[0][along]):
        if scaled > BOUND:
            cur = [p[along], p[along]] if cur is None else [cur[0], p[along]]
        elif cur is not None:
            runs.append(cur)
            cur = None
    return runs + ([cur] if cur is not None else [])


def measure_naive(expr_naive: sp.Expr, form: str, truth: sp.Expr, args: Sequence[KernelArg], points,
                  along: int = 0) -> Naive:
    """The naive form's accuracy on the points, and the ranges of argument number `along`
    where its scaled error exceeds BOUND (runs of consecutive failing points)."""
    errs = list(errors(py_callable(expr_naive, args), truth, args, points))
    fin = [e for e in errs if math.isfinite(e[1])]
    worst = max(fin, key=lambda e: e[2], default=None)
    inf_any = len(fin) < len(errs)
    acc = Accuracy(len(points), math.inf if inf_any else round(max(e[1] for e in errs), 2),
                   math.inf if inf_any else round(worst[2], 2),
                   next((e[0] for e in errs if not math.isfinite(e[1])), worst[0] if worst else ()))
    name = args[along].name
    fails = "; ".join(f"{name} = {lo:.3g}" if lo == hi else f"{name} in [{lo:.3g}, {hi:.3g}]"
                      for lo, hi in _failing_runs(errs, along))
    return Naive(form, acc, fails or "nowhere on the sample")


def ulp_errors(fn: Callable, xs: Sequence[float], truth: Sequence) -> list[float]:
    """The error of a function of one argument at each point in ulp of the true value (inf
    where it fails or overflows; 0 where the true value is below 1e-290)."""
    out = []
    for xv, tv in zip(xs, truth):
        got = _value(fn, (xv,))
        if not math.isfinite(got):
            out.append(math.inf)
        elif abs(tv) < 1e-290:
            out.append(0.0)
        else:
            out.append(float(abs(mp.mpf(got) - tv) / mp.mpf(math.ulp(float(tv)))))
    return out


def py_callable(expr: sp.Expr, args: Sequence[KernelArg]) -> Callable[..., float]:
    """expr as a Python function of the arguments in double (math module, the kernels' printer)."""
    return _py_callable(expr, tuple(args))


@functools.lru_cache(maxsize=256)
def _py_callable(expr: sp.Expr, args: tuple[KernelArg, ...]) -> Callable[..., float]:
    return sp.lambdify(list(_symbols(expr, args)), expr, modules=["math", {"math": math}], printer=KernelPy)
