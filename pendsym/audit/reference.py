"""The audit's fast references.  Used by :mod:`.run`.

- In MPFR (gmpy2), where it applies: the Result's derived form, lambdified with common subexpressions
  shared, each operation correctly rounded at mpmath's working precision, with mpmath's own form as the
  fallback wherever MPFR would leave mpmath's behaviour.
- In Arb (python-flint), for a form with a function MPFR lacks (the Bessel functions of the rhombus
  blade): the same lambdified form in ball arithmetic, its precision raised until the ball's relative
  radius is below 2^-prec of mpmath's working precision (a rigorous bound: every digit returned is
  correct), with mpmath's form as the fallback where it cannot (a value that is 0, a ball that will not
  shrink, a non-finite value).  mpmath's Bessel functions at 114 digits cost 1–3 ms a call at x = 6e8;
  Arb's, 0.03–0.1 ms.
"""
from __future__ import annotations

from typing import Callable, Sequence

import gmpy2
import mpmath as mp
import sympy as sp
from sympy.printing.pycode import MpmathPrinter

from ..emit.kernels.measure import COND_DPS, COND_STEP, reference

try:                                     # optional: without it, such a form falls back to mpmath's
    import flint
except ImportError:                      # pragma: no cover
    flint = None


MPFR_FUNCTIONS = {"sin": gmpy2.sin, "cos": gmpy2.cos, "tan": gmpy2.tan, "sinh": gmpy2.sinh, "cosh": gmpy2.cosh,
                  "tanh": gmpy2.tanh, "exp": gmpy2.exp, "log": gmpy2.log, "sqrt": gmpy2.sqrt, "atan": gmpy2.atan,
                  "asin": gmpy2.asin, "acos": gmpy2.acos, "asinh": gmpy2.asinh, "acosh": gmpy2.acosh,
                  "atanh": gmpy2.atanh}
MPFR_TRAPS = (gmpy2.DivisionByZeroError, gmpy2.InvalidOperationError, gmpy2.OverflowResultError,
              gmpy2.UnderflowResultError, gmpy2.RangeError)
MPFR_AGREE = 40          # digits the MPFR and mpmath forms must share at a test point (else mpmath is used)


class _MpfrPrinter(MpmathPrinter):
    """The mpmath printer, with π and e as MPFR constants at the working precision."""

    def _print_Pi(self, expr):
        return "const_pi()"

    def _print_Exp1(self, expr):
        return "exp(mpf(1))"


def _to_mpfr(x):
    """A double or an mpmath mpf as an MPFR number, exactly (the context has at least its bits)."""
    if isinstance(x, float):
        return gmpy2.mpfr(x)
    sign, man, exp, _ = x._mpf_ if isinstance(x, mp.mpf) else mp.mpf(x)._mpf_      # (never re-rounded)
    if not man:
        return gmpy2.mpfr(float(x))     # 0, ±inf, NaN
    v = gmpy2.mul_2exp(gmpy2.mpfr(man), exp)
    return -v if sign else v


def mpfr_form(expr: sp.Expr, syms, fallback: Callable) -> Callable | None:
    """expr as a function of mpmath numbers evaluated in MPFR (gmpy2) at mpmath's working precision,
    each operation correctly rounded, its value returned as an mpmath mpf; None where expr holds a
    function MPFR lacks or a Float.  Where MPFR would leave mpmath's behaviour (an overflow or underflow
    of its exponent range, ±2^(2^62), a division by zero, an invalid operation) the point is evaluated by
    `fallback`, mpmath's form, instead.  The same lambdified code as mpmath's (common subexpressions
    shared), several times faster per operation."""
    names = {type(f).__name__.lower() for f in expr.atoms(sp.Function)}
    if expr.atoms(sp.Float) or not names - {"piecewise"} <= set(MPFR_FUNCTIONS) or expr.has(sp.I):
        return None
    namespace = {"mpf": gmpy2.mpfr, "const_pi": gmpy2.const_pi, **MPFR_FUNCTIONS}
    g = sp.lambdify(list(syms), expr, modules=[namespace], cse=True,
                    printer=_MpfrPrinter({"fully_qualified_modules": False, "inline": True, "allow_unknown_functions": True}))

    def f(*xs):
        prec = mp.mp.prec
        try:
            with gmpy2.context(precision=prec, emax=gmpy2.get_emax_max(), emin=gmpy2.get_emin_min(),
                               trap_divzero=True, trap_invalid=True, trap_overflow=True, trap_underflow=True):
                v = g(*[_to_mpfr(x) for x in xs])
                if not gmpy2.is_finite(v):
                    return fallback(*xs)
                man, exp = v.as_mantissa_exp()
        except MPFR_TRAPS:
            return fallback(*xs)
        return mp.mpf((int(man), int(exp)))             # exact: man has at most prec bits
    return f


ARB_FUNCTIONS = {"besselj": "bessel_j", "bessely": "bessel_y", "besseli": "bessel_i", "besselk": "bessel_k"}
ARB_UNARY = ("sin", "cos", "tan", "sinh", "cosh", "tanh", "exp", "log", "sqrt", "atan", "asin", "acos",
             "asinh", "acosh", "atanh")
ARB_GUARD = 64           # bits beyond the target at which a ball is first evaluated
ARB_TRUTH_DIGITS = 45    # digits proven of a reference value (κ's differences: every digit of the working precision)
ARB_TRIES = 4            # each try doubles the extra bits; then mpmath's form


class _ArbPrinter(MpmathPrinter):
    """The mpmath printer, with π, e and Euler's γ as Arb constants at the working precision."""

    def _print_Pi(self, expr):
        return "const_pi()"

    def _print_Exp1(self, expr):
        return "const_e()"

    def _print_EulerGamma(self, expr):
        return "const_euler()"


def _to_arb(x):
    """A double or an mpmath mpf as an exact Arb ball (the context has at least its bits)."""
    if isinstance(x, float):
        return flint.arb(x)
    sign, man, exp, _ = x._mpf_ if isinstance(x, mp.mpf) else mp.mpf(x)._mpf_
    if not man:
        return flint.arb(float(x))
    return flint.arb(flint.fmpz(int(-man if sign else man))) * flint.arb(2) ** exp     # (exact: a power of 2)


def _arb_namespace() -> dict:
    ar = flint.arb

    def unary(name):
        return lambda x: getattr(x if isinstance(x, ar) else ar(x), name)()

    def bessel(name):
        return lambda n, x: getattr(x if isinstance(x, ar) else ar(x), name)(ar(n))
    return {"mpf": ar, "const_pi": ar.pi, "const_e": ar.const_e, "const_euler": ar.const_euler,
            **{k: unary(k) for k in ARB_UNARY}, **{k: bessel(v) for k, v in ARB_FUNCTIONS.items()}}


def arb_form(expr: sp.Expr, syms, fallback: Callable, digits: int | None = None) -> Callable | None:
    """expr as a function of mpmath numbers evaluated in Arb ball arithmetic, its value returned as an
    mpmath mpf whose every bit at mpmath's working precision is proven (the ball's radius is below
    2^-prec of its midpoint), or only its first `digits` digits where fewer (the ball's radius is then
    below 10^-digits of its midpoint: the digits of a reference value need no guard against cancellation
    when they are proven); None where python-flint is missing, or expr holds a Float, a Piecewise, a
    relation, or a function this form does not map.  Where the ball will not shrink (a value that is 0
    or nearly) or is not finite, the point is evaluated by `fallback`, mpmath's form."""
    if flint is None:
        return None
    names = {type(f).__name__.lower() for f in expr.atoms(sp.Function)}
    if (expr.atoms(sp.Float) or expr.has(sp.Piecewise) or expr.atoms(sp.Rel) or expr.has(sp.I)
            or not names <= set(ARB_UNARY) | set(ARB_FUNCTIONS)):
        return None
    g = sp.lambdify(list(syms), expr, modules=[_arb_namespace()], cse=True,
                    printer=_ArbPrinter({"fully_qualified_modules": False, "inline": True,
                                         "allow_unknown_functions": True}))

    def f(*xs):
        target = mp.mp.prec if digits is None else min(mp.mp.prec, int(digits * 3.33) + 1)
        old = flint.ctx.prec
        try:
            for k in range(ARB_TRIES):
                flint.ctx.prec = max(target, *(_bits(x) for x in xs)) + ARB_GUARD * 2 ** k
                try:
                    v = g(*[_to_arb(x) for x in xs])
                except (ZeroDivisionError, ValueError):
                    return fallback(*xs)
                if not v.is_finite():
                    break
                if v.is_zero():
                    return mp.mpf(0)
                if v.rel_accuracy_bits() >= target + 2:
                    man, exp = v.mid().man_exp()
                    return mp.mpf((int(man), int(exp)))       # rounded once, to the working precision
        finally:
            flint.ctx.prec = old
        return fallback(*xs)
    return f


def _bits(x) -> int:
    """The bits of the mantissa of a double or an mpf (the Arb context must hold them exactly)."""
    if isinstance(x, float):
        return 53
    return int((x._mpf_ if isinstance(x, mp.mpf) else mp.mpf(x)._mpf_)[3])


def condition(f: Callable) -> Callable:
    """κ = Σ|x_i ∂f/∂x_i|/|f| by forward differences, as :func:`pendsym.emit.kernels.measure.reference`
    computes it (the same digits and step), of another evaluation of the same form."""
    def cond(*xs):
        v = f(*xs)
        if v == 0:
            return mp.inf
        with mp.workdps(max(COND_DPS, mp.mp.dps + 30)):
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
    return cond


def fast_reference(expr: sp.Expr, syms, probe: Sequence[float]) -> tuple[Callable, Callable, str]:
    """(f, κ, engine): the reference in MPFR where :func:`mpfr_form` applies, else in Arb where
    :func:`arb_form` does, if it agrees with mpmath's to MPFR_AGREE digits at the point `probe` (at 60
    digits); else mpmath's (:func:`reference`)."""
    f_mp, cond_mp = reference(expr, list(syms))
    f, engine = mpfr_form(expr, syms, f_mp), "mpfr"
    cond = None
    if f is None:
        f, engine = arb_form(expr, syms, f_mp, ARB_TRUTH_DIGITS), "arb"
        cond = f and condition(arb_form(expr, syms, f_mp))
    if f is None:
        return f_mp, cond_mp, "mpmath"
    with mp.workdps(60):
        try:
            a, b = f(*[mp.mpf(x) for x in probe]), f_mp(*[mp.mpf(x) for x in probe])
            same = mp.isfinite(b) and abs(a - b) <= mp.mpf(10) ** -MPFR_AGREE * max(abs(b), mp.mpf(10) ** -300)
        except (ZeroDivisionError, ValueError, OverflowError, TypeError):
            same = False
    return (f, cond or condition(f), engine) if same else (f_mp, cond_mp, "mpmath")
