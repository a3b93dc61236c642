"""Haag 1935, chapter IX, n°107–110: the rhombus blade's v_0, w_0, w_λ and G_2 toward kernels (issue #14).

The forms and the measured diagnosis the kernels of :mod:`.kernels` (session 10, supplied forms) are built on;
nothing here is emitted (see the "Bessel functions" section of docs/kernel-accuracy.md).

* :func:`scaled`: the derived (343) and (346) divided by λ, as functions of two dimensionless arguments,
  u = ωλ (as in chapter III) and q = kλ (so M at the ends is M_0(1 + q/2)).  The memoir's forms depend on
  ω, k, x_0, x_1 only (λ through x_1, (334)), and each is λ times a function of (u, q): a kernel of (u, q) has two
  arguments instead of three, and its domain is stated in numbers a designer reads (ωλ < π, the hole's depth).
* :func:`end_gap`: x_1 − x_0 = u/(1 + √(1 + q/2)), from (334) without the difference of two large numbers.
* :func:`rectangle_concentric_scaled`: G_2/λ of the concentric rectangular hole (333) in u = ωλ, u_p = ω'p,
  ρ = p/λ.  Given a KernelSpec in session 9, the engine's own choice (the sin-basis rewrite of this form) held
  2.16 × max(1, κ) ulp on the derive sample but not the audit: 22.9 (u, u_p ∈ [0.01, 1.5], ρ ∈ [0.05, 0.95], at
  u = 0.01, ρ = 0.05), 5.04 (ρ ≥ 0.2), 5.62 in C (also u_p ≤ 1.25); the ~600 operations of the form round
  ~20 ulp where κ ≈ 2–3, so no kernel is declared until a shorter arrangement (over the determinant D², in
  sin and cos of u(1 − ρ)/2 and u_p) is derived.
* :func:`double_evaluator`: the derived form in double precision, with the Bessel values at x_0 and x_1 taken from a
  given library, either at the rounded arguments (``corrected=False``: the plain form) or corrected to first order
  for the rounding of the arguments (x_0 = 2u/q as a double-double by an exact residual, x_1 = x_0 + gap by a
  two-sum; J_0' = −J_1, J_1' = J_0 − J_1/x, the same for Y).

**The diagnosis** (measured by :func:`relative_errors`, tests/test_haag1935_ch9_kernels.py): as q → 0 the plain
form loses about log10(2u/q) digits, and this is the rounding of the *arguments*, not the cancellation of the
D's: x_0 = 2u/q rounded to a double is off by x_0·2⁻⁵³, an error of the Bessel functions' phase of that size
(1e-8 at q = 1e-8), which no accuracy of j_0 … y_1 can repair.  With the arguments corrected, v_0, w_0, w_λ come
within 6.4 × max(1, κ) ulp for u ≥ 0.3 (200 random points, q from 1e-8 to 200: v_0 6.37, w_0 5.91, w_λ 4.51, 3 %
of the points over 4) and 48 at u = 0.05 (where D_1, D' cancel like 2/u) (libm's j0, j1, y0, y1; the plain form:
up to 3e8): close to the contract, not within it.  G_2 does not: (346) itself subtracts terms of
order 1/k (corrected: 4e7–7e9 scaled ulp at q = 1e-8, 5–180 at q = 0.01, up to 8.7 at q = 1, within 3 from
q ≈ 10).  No series is needed: :mod:`.rhombus_g2_kernel` derives from (346) the same G_2 as a sum of positive
terms (quadratures of squared cross products over the gap x_1 − x_0), the form of its kernel (session 11: make
audit 6.55 scaled ulp at worst, over the contract; session 12, every operation after the cross products
compensated: 3.47, within it).
"""
from __future__ import annotations

import functools
import math
from fractions import Fraction
from typing import Callable, Mapping

import mpmath as mp
import sympy as sp

from ..symbols import lam, omega, u
from . import rhombus_derivation as derivation

q = sp.Symbol("q", positive=True)           # q = kλ: M at the ends is M_0(1 + q/2) (n°107)

NAMES = ("v0", "w0", "wl", "G2")


@functools.lru_cache(maxsize=None)
def derived(name: str) -> sp.Expr:
    """(343) v_0, w_0, w_λ or (346) G_2 as derived, in ω, k, x_0, x_1 (:mod:`.rhombus_derivation`)."""
    return {"v0": derivation.v_end, "w0": lambda: derivation.w_end("0"), "wl": lambda: derivation.w_end("l"),
            "G2": derivation.G2_final}[name]()


@functools.lru_cache(maxsize=None)
def scaled(name: str) -> sp.Expr:
    """v_0/λ, w_0/λ, w_λ/λ (343) or G_2/λ (346) as functions of u = ωλ and q = kλ (x_0, x_1 by (334)); an error if
    the quotient still depends on λ."""
    return scaled_from(derived(name), name)


def scaled_from(form: sp.Expr, name: str = "form") -> sp.Expr:
    """A derived (343) or (346) in ω, k, x_0, x_1, divided by λ, in u = ωλ and q = kλ (x_0, x_1 by (334)); an
    error if the quotient still depends on λ."""
    ends = derivation.x_ends()
    expr = form.subs(ends).subs({omega: u / lam, derivation.k: q / lam}) / lam
    expr = expr.xreplace({a: sp.simplify(a) for a in expr.atoms(sp.besselj, sp.bessely)})
    at = {u: sp.Rational(17, 10), q: sp.Rational(1, 10)}
    values = [sp.N(expr.subs(at).subs(lam, length), 30) for length in (sp.Rational(1, 3), 7)]
    if abs(values[0] - values[1]) > 1e-25 * abs(values[1]):
        raise ValueError(f"{name}/λ depends on λ: {values}")
    return expr.subs(lam, 1)


def arguments() -> tuple[sp.Expr, sp.Expr]:
    """x_0 and x_1 of (334) in u, q (λ = 1 in :func:`scaled`)."""
    ends = derivation.x_ends()
    return tuple(sp.simplify(ends[x].subs({omega: u / lam, derivation.k: q / lam})) for x in (derivation.x0,
                                                                                              derivation.x1))


def end_gap() -> sp.Expr:
    """x_1 − x_0 from (334), times and over the conjugate √(1 + q/2) + 1: u/(1 + √(1 + q/2)), no cancellation."""
    x0, x1 = arguments()
    root = sp.sqrt(1 + q / 2)
    if sp.simplify(x1 - x0 * root) != 0:
        raise ValueError(f"x_1 is not x_0·√(1 + q/2): {x1}")
    gap = sp.factor(sp.expand(x0 * (root - 1) * (root + 1))) / (root + 1)
    if sp.simplify(gap - (x1 - x0)) != 0:
        raise ValueError(f"the gap {gap} is not x_1 − x_0")
    return gap


# ---------------------------------------------------------------- the form in double precision
VALUES = sp.symbols("J0a J1a Y0a Y1a J0b J1b Y0b Y1b", real=True)     # at x_0 (a), at x_1 (b)


def _with_value_symbols(expr: sp.Expr) -> sp.Expr:
    x0, x1 = derivation.x0, derivation.x1
    at = [sp.besselj(0, x0), sp.besselj(1, x0), sp.bessely(0, x0), sp.bessely(1, x0),
          sp.besselj(0, x1), sp.besselj(1, x1), sp.bessely(0, x1), sp.bessely(1, x1)]
    out = expr.xreplace(dict(zip(at, VALUES)))
    if out.atoms(sp.besselj, sp.bessely):
        raise ValueError(f"Bessel functions left: {out.atoms(sp.besselj, sp.bessely)}")
    return out


@functools.lru_cache(maxsize=None)
def _double_form(name: str) -> Callable[..., float]:
    """The derived form of :func:`derived` as a double function of (ω, k, x_0, x_1, the eight Bessel values)."""
    return sp.lambdify([omega, derivation.k, derivation.x0, derivation.x1, *VALUES],
                       _with_value_symbols(derived(name)), "math")


def _two_sum(a: float, b: float) -> tuple[float, float]:
    s = a + b
    bb = s - a
    return s, (a - (s - bb)) + (b - bb)


def _values(bessel: Mapping[str, Callable], x: float, low: float) -> tuple[float, ...]:
    """J_0, J_1, Y_0, Y_1 at x + low (|low| ≪ ulp(x)) to first order in low (J_0' = −J_1, J_1' = J_0 − J_1/x;
    today's Y obeys the same relations)."""
    j0, j1, y0, y1 = (bessel[n](x) for n in ("j0", "j1", "y0", "y1"))
    if low:
        j0, j1, y0, y1 = j0 - low * j1, j1 + low * (j0 - j1 / x), y0 - low * y1, y1 + low * (y0 - y1 / x)
    return j0, j1, y0, y1


def double_evaluator(name: str, bessel: Mapping[str, Callable], corrected: bool = True) -> Callable[[float, float], float]:
    """name/λ at (u, q) in double precision from the derived form, with today's J_n, Y_n from ``bessel`` (callables
    j0, j1, y0, y1: the derived form holds SymPy's besselj, bessely, Haag's Y_n written through
    :func:`.rhombus_derivation.neumann_Y`).  ``corrected``: the arguments as double-doubles, x_0 = 2u/q with its
    exact residual (C: fma(−q, x_0, 2u)/q), x_1 = x_0 + :func:`end_gap` by a two-sum, and the Bessel values taken
    to first order in the low parts; otherwise x_0 = 2u/q and x_1 = x_0·√(1 + q/2) as rounded."""
    form = _double_form(name)

    def evaluate(u_: float, q_: float) -> float:
        x0 = 2 * u_ / q_
        if corrected:
            x0_low = float((Fraction(2 * u_) - Fraction(q_) * Fraction(x0)) / Fraction(q_))   # exact residual
            x1, x1_low = _two_sum(x0, u_ / (1 + math.sqrt(1 + q_ / 2)))
            x1_low += x0_low
        else:
            x0_low, x1, x1_low = 0.0, x0 * math.sqrt(1 + q_ / 2), 0.0
        return form(u_, q_, x0, x1, *_values(bessel, x0, x0_low), *_values(bessel, x1, x1_low))
    return evaluate


# ---------------------------------------------------------------- references and measurement
@functools.lru_cache(maxsize=None)
def _mp_form(name: str) -> Callable:
    return sp.lambdify([u, q], scaled(name), "mpmath")


def reference(name: str, u_: float, q_: float, dps: int = 60) -> mp.mpf:
    """name/λ at the doubles (u, q), the derived form by mpmath at ``dps`` digits (the Bessel form loses
    log10(x_0) digits: 60 leave over 40 at q = 1e-8)."""
    with mp.workdps(dps):
        return +_mp_form(name)(mp.mpf(u_), mp.mpf(q_))


def condition(name: str, u_: float, q_: float, dps: int = 80) -> float:
    """κ = (|u ∂f/∂u| + |q ∂f/∂q|)/|f| by forward differences of relative step 1e-35 at ``dps`` digits."""
    with mp.workdps(dps):
        f = _mp_form(name)
        U, Q = mp.mpf(u_), mp.mpf(q_)
        h = mp.mpf(10) ** -35
        f0 = f(U, Q)
        du = (f(U * (1 + h), Q) - f0) / h
        dq = (f(U, Q * (1 + h)) - f0) / h
        return float((abs(du) + abs(dq)) / abs(f0))


def ulp_error(value: float, ref: mp.mpf) -> float:
    """|value − ref| in ulp of the double nearest ref."""
    with mp.workdps(60):
        return float(abs(mp.mpf(value) - ref) / math.ulp(float(ref)))


def relative_errors(name: str, bessel: Mapping[str, Callable], points) -> list[tuple[float, float, float, float]]:
    """(u, q, plain form's error in ulp, corrected form's error in ulp) at each point."""
    plain, fixed = double_evaluator(name, bessel, False), double_evaluator(name, bessel, True)
    out = []
    for u_, q_ in points:
        ref = reference(name, u_, q_)
        out.append((u_, q_, ulp_error(plain(u_, q_), ref), ulp_error(fixed(u_, q_), ref)))
    return out


# ---------------------------------------------------------------- the rectangular hole, concentric
u_p = sp.Symbol("u_p", positive=True)        # u_p = ω'p, the hole's phase
rho = sp.Symbol("rho", positive=True)        # ρ = p/λ


def rectangle_concentric_scaled() -> sp.Expr:
    """(333) with s_0 = (λ − p)/2 (the concentric hole of n°106's footnote), divided by λ, in u = ωλ, u_p = ω'p,
    ρ = p/λ: three arguments in a box (an off-centre hole needs s_0 + p ≤ λ, which a box cannot state); an error if
    λ remains.  Each trigonometric argument is written as one product (sin(ρu + u(1/2 − ρ/2) − u) as
    −sin(u(1 − ρ)/2))."""
    from . import rectangle_derivation as rd
    g2 = rd.G2().subs(rd.s0, (lam - rd.p) / 2)
    g2 = g2.subs({omega: u / lam, rd.omega_p: u_p / (rho * lam)}).subs(rd.p, rho * lam) / lam
    at = {u: sp.Rational(7, 5), u_p: sp.Rational(1, 2), rho: sp.Rational(3, 10)}
    values = [sp.N(g2.subs(at).subs(lam, length), 30) for length in (sp.Rational(1, 3), 7)]
    if abs(values[0] - values[1]) > 1e-25 * abs(values[1]):
        raise ValueError(f"G_2/λ depends on λ: {values}")
    return g2.subs(lam, 1).replace(lambda e: isinstance(e, (sp.sin, sp.cos)), lambda e: e.func(sp.factor(e.args[0])))
