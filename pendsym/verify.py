"""Verification: printed ≡ derived, and formula against an independent truth.

* :func:`compare_forms` decides `match` or `discrepancy` between the printed
  and the derived expression: 50-digit evaluation at random points seeded
  from the Result id, then an exact simplification to upgrade a numeric match.
* :func:`order_check` measures the residual of a formula against a truth
  computed from the governing model over a geometric sequence of the small
  parameter, fits the slope of log|residual| against log(parameter), and
  compares it with the order the theory predicts.
"""
from __future__ import annotations

import hashlib
import random
from typing import Callable, Iterable, Mapping, Sequence

import mpmath as mp
import sympy as sp
from sympy.core.function import AppliedUndef
from sympy.functions.elementary.hyperbolic import HyperbolicFunction

from .result import Evidence

LEVELS = {"quick": 4, "full": 6}
EXACT_OPS = 150   # past this size, exact simplification can run for minutes: the 50-digit verdict stands
EXACT_TERMS = 12  # past this many terms in the expanded numerator of a hyperbolic difference, too


def rounded(x) -> float:
    """A float with 6 significant digits: stable in JSON across runs."""
    return float(f"{float(x):.6g}")


def geometric(lo, hi, n: int) -> list:
    """n points from lo to hi in geometric progression (as mpf)."""
    lo, hi = mp.mpf(lo), mp.mpf(hi)
    if n == 1:
        return [lo]
    r = (hi / lo) ** (mp.mpf(1) / (n - 1))
    return [lo * r**i for i in range(n)]


def fit_order(xs: Sequence, ys: Sequence) -> float:
    """Least-squares slope of log|y| against log x."""
    lx = [mp.log(abs(mp.mpf(x))) for x in xs]
    ly = [mp.log(abs(mp.mpf(y))) for y in ys]
    n = len(lx)
    mx, my = sum(lx) / n, sum(ly) / n
    sxx = sum((a - mx) ** 2 for a in lx)
    sxy = sum((a - mx) * (b - my) for a, b in zip(lx, ly))
    return float(sxy / sxx)


def seeded_rng(result_id: str) -> random.Random:
    """A random generator seeded from the Result id: reruns draw the same points."""
    return random.Random(int.from_bytes(hashlib.sha256(result_id.encode()).digest()[:8], "big"))


def _sample_value(atom, rng: random.Random):
    """A random value respecting a symbol's assumptions."""
    if getattr(atom, "is_integer", False):
        return sp.Integer(rng.randint(1, 7))
    if getattr(atom, "is_positive", False) or getattr(atom, "is_nonnegative", False):
        return sp.Float(rng.uniform(0.15, 1.9), 60)
    return sp.Float(rng.uniform(-1.9, 1.9), 60)


def numeric_difference(a: sp.Expr, b: sp.Expr, seed: str, points: int = 6, dps: int = 50) -> float:
    """Largest relative |a − b| over random points (at ``dps`` digits), seeded from ``seed``.

    Free symbols and applied undefined functions (E_c(π) …) are drawn at
    random; both sides are evaluated by mpmath (integrals by mpmath quad).
    """
    rng = seeded_rng(seed)
    undef = sorted(a.atoms(AppliedUndef) | b.atoms(AppliedUndef), key=sp.srepr)
    stand = [sp.Dummy(f"f{i}") for i in range(len(undef))]
    a2, b2 = (x.xreplace(dict(zip(undef, stand))) for x in (a, b))
    syms = sorted((a2.free_symbols | b2.free_symbols) - set(stand), key=lambda s: s.name) + stand
    fa, fb = (sp.lambdify(syms, x, modules="mpmath") for x in (a2, b2))
    proxies = {d: f for d, f in zip(stand, undef)}
    worst = 0.0
    with mp.workdps(dps):
        for _ in range(points):
            vals = [mp.mpf(_sample_value(proxies.get(s, s), rng)) for s in syms]
            va, vb = mp.mpf(fa(*vals)), mp.mpf(fb(*vals))
            scale = max(abs(va), abs(vb), mp.mpf("1e-30"))
            worst = max(worst, float(abs(va - vb) / scale))
    return worst


def expansion_terms(d: sp.Expr) -> int:
    """The number of terms of the expanded numerator of d over a common denominator (functions kept as
    atoms): a structural, machine-independent measure of how much work is left once d is put together."""
    return len(sp.Add.make_args(sp.expand(sp.numer(sp.together(d)))))


def beyond_exact_reach(d: sp.Expr) -> bool:
    """True when exact simplification of d could stall: d holds hyperbolic functions and its expanded
    numerator has more than EXACT_TERMS terms.  SymPy's trigsimp turns sh, ch, th into circular functions
    of i·u and factors polynomials over Q(i) in several function atoms: that can run for minutes on a form
    far below EXACT_OPS (a hyperbolic identity of 108 operations whose numerator has 20 terms ran over
    90 s), where circular identities of 15 terms are proven in seconds (chapter IX's no-hole limits).
    A structural measure, not a clock, so that a derive's output never depends on the machine's load."""
    return d.has(HyperbolicFunction) and expansion_terms(d) > EXACT_TERMS


def exactly_equal(a: sp.Expr, b: sp.Expr) -> bool:
    """True when SymPy proves a − b = 0 (simplification, then trig expansion); False, without trying,
    for a difference :func:`beyond_exact_reach` (the caller's 50-digit comparison then stands)."""
    if beyond_exact_reach(a - b):
        return False
    d = sp.simplify(a - b)
    if d == 0:
        return True
    return sp.simplify(sp.expand(sp.expand_trig(d))) == 0


def compare_decimal(printed: sp.Expr, derived: sp.Expr, decimals) -> tuple[str, str]:
    """('match' | 'discrepancy', how) for a number printed to ``decimals`` decimals (for a Tuple, a
    number of decimals per component): a match when each is the derived value correctly rounded;
    a truncation or any other value is a discrepancy."""
    if isinstance(printed, sp.Tuple):
        places = decimals if isinstance(decimals, tuple) else (decimals,) * len(printed)
        if not isinstance(derived, sp.Tuple) or not len(printed) == len(derived) == len(places):
            return "discrepancy", "components differ in number"
        verdicts = [compare_decimal(p, d, n) for p, d, n in zip(printed, derived, places)]
        status = "match" if all(s == "match" for s, _ in verdicts) else "discrepancy"
        return status, "; ".join(f"component {i + 1}: {how}" for i, (_, how) in enumerate(verdicts))
    with mp.workdps(50):
        exact = mp.mpf(sp.N(derived, 60))
        shown = mp.mpf(sp.N(printed, 60))
        unit = mp.mpf(10) ** -decimals
        rounded = mp.nint(exact / unit) * unit
        truncated = (mp.floor(abs(exact) / unit) * unit) * mp.sign(exact)
        digits = f"{decimals} decimal{'s' if decimals != 1 else ''}"
        said = f"derived {mp.nstr(exact, 12)}"
        if abs(shown - rounded) < unit / 1000:
            return "match", f"the printed value is the derived one correctly rounded to {digits} ({said})"
        if abs(shown - truncated) < unit / 1000:
            return ("discrepancy", f"the printed value is the derived one truncated to {digits}, not rounded "
                    f"(rounding gives {mp.nstr(rounded, decimals + 2)}; {said})")
        return "discrepancy", f"the printed value is not the derived one to {digits} ({said})"


def compare_forms(printed: sp.Expr, derived: sp.Expr, seed: str, instances=()) -> tuple[str, str]:
    """('match' | 'discrepancy', how it was decided).

    With ``instances`` (substitutions of arbitrary functions by test
    functions), the numeric comparison is made under each of them.
    """
    if isinstance(printed, sp.Tuple) or isinstance(derived, sp.Tuple):
        same = len(printed) == len(derived) and all(sp.simplify(p - d) == 0 for p, d in zip(printed, derived))
        return ("match", "identical by exact simplification") if same else ("discrepancy", "components differ")
    if printed == derived and printed.has(sp.Integral):
        # the same tree: evaluating its integrals at 50 digits could only agree with itself
        return "match", "identical expression trees (structural equality)"
    if instances:
        worst = 0.0
        for inst in instances:
            a = _instantiate(printed, inst)
            b = _instantiate(derived, inst)
            worst = max(worst, numeric_difference(a, b, seed, points=3, dps=30))
        if worst > 1e-25:
            return "discrepancy", f"relative difference up to {worst:.3g} for test functions (30 digits)"
        return "match", f"identical to 30 digits for {len(instances)} test functions at random points"
    worst = numeric_difference(printed, derived, seed)
    if worst > 1e-40:
        return "discrepancy", f"relative difference up to {worst:.3g} at random points (50 digits)"
    if printed.has(sp.Integral) or derived.has(sp.Integral) or \
            sp.count_ops(printed) + sp.count_ops(derived) > EXACT_OPS:
        return "match", "identical at random points to 50 digits"
    if exactly_equal(printed, derived):
        return "match", "identical by exact simplification"
    return "match", "identical at random points to 50 digits"


def lambdify_mp(expr: sp.Expr, symbols: Iterable[sp.Symbol]) -> Callable:
    """An mpmath evaluator of expr (works at the precision in force)."""
    return sp.lambdify(tuple(symbols), expr, modules="mpmath")


def value_at(expr: sp.Expr, env: Mapping) -> object:
    """expr at env by mpmath at the precision in force: env maps a symbol's name, or an applied
    undefined function such as v(s) or F(2), to its value."""
    expr = sp.sympify(expr)
    apps = sorted(expr.atoms(AppliedUndef), key=sp.srepr)
    stand = [sp.Dummy() for _ in apps]
    ex = expr.xreplace(dict(zip(apps, stand)))
    syms = sorted(ex.free_symbols - set(stand), key=lambda x: x.name)
    f = lambdify_mp(ex, [*syms, *stand])
    return f(*([mp.mpf(env[x.name]) for x in syms] + [mp.mpf(env[ap]) for ap in apps]))


def order_check(*, param: str, values: Sequence, truth: Callable, derived: Callable,
                expected: float, band: float = 0.3, truth_desc: str,
                printed: Callable | None = None, params: Sequence[tuple[str, str]] = (),
                dps: int = 30, confirm_dps: int = 45, note: str = "") -> Evidence:
    """Fit the order of |truth(p) − formula(p)| over the parameter values.

    truth(p, dps) must compute the quantity from the governing model; derived(p)
    and printed(p) evaluate the formulas for the same quantity.  The truth at
    the smallest parameter is recomputed at ``confirm_dps`` digits, and the
    check fails unless that confirmation resolves the smallest residual.
    """
    with mp.workdps(dps):
        truths = [truth(p, dps) for p in values]
        res = [t - derived(p) for p, t in zip(values, truths)]
        pres = [t - printed(p) for p, t in zip(values, truths)] if printed else []
    with mp.workdps(confirm_dps):
        t_hi = truth(values[0], confirm_dps)
    confirm = abs(t_hi - truths[0])
    slope = fit_order(values, res) if all(r != 0 for r in res) else float("inf")
    ok_slope = abs(slope - expected) <= band
    resolved = confirm < abs(res[0]) * mp.mpf("1e-3")
    pslope = fit_order(values, pres) if pres and all(r != 0 for r in pres) else None
    printed_agrees = None if pslope is None else abs(pslope - expected) <= band or pslope > expected
    return Evidence(
        kind="order", passed=bool(ok_slope and resolved), truth=truth_desc,
        max_residual=rounded(max(abs(r) for r in res)), order=rounded(slope),
        expected_order=float(expected), band=(expected - band, expected + band), param=param,
        params=tuple(params),
        series=tuple((rounded(p), rounded(abs(r))) for p, r in zip(values, res)),
        printed_series=tuple((rounded(p), rounded(abs(r))) for p, r in zip(values, pres)),
        printed_order=None if pslope is None else rounded(pslope),
        printed_agrees=printed_agrees,
        confirm_digits=rounded(truth_digits(truths[0], t_hi)),
        values=tuple((rounded(p), rounded(t), rounded(t - r)) for p, t, r in zip(values, truths, res)),
        note=note + ("" if resolved else " | truth not resolved at two precisions"),
    )


def truth_digits(a, b) -> float:
    a, b = mp.mpf(a), mp.mpf(b)
    if a == b:
        return 45.0
    return float(-mp.log10(abs(a - b) / max(abs(a), abs(b))))


def value_check(*, truth_desc: str, pairs: Sequence[tuple[str, object, object]], tol,
                params: Sequence[tuple[str, str]] = (), kind: str = "quadrature",
                note: str = "") -> Evidence:
    """Compare formula values with independently computed values at given points.

    ``pairs`` holds (label, formula value, truth value); the check passes when
    every relative (or, near zero, absolute) difference is below ``tol``.
    """
    worst = mp.mpf(0)
    for _, f, t in pairs:
        scale = max(abs(mp.mpf(t)), mp.mpf(1))
        worst = max(worst, abs(mp.mpf(f) - mp.mpf(t)) / scale)
    return Evidence(kind=kind, passed=bool(worst < tol), truth=truth_desc,
                    max_residual=rounded(worst), params=tuple(params), note=note)


def proof(*, statement: str, holds: bool, truth_desc: str, note: str = "") -> Evidence:
    """Evidence of a symbolic proof (for general m, not sampled)."""
    return Evidence(kind="proof", passed=bool(holds), truth=truth_desc, note=statement + (" " + note if note else ""))


def _instantiate(expr: sp.Expr, inst) -> sp.Expr:
    """Replace each arbitrary function by its test function and evaluate derivatives."""
    for fn, lam in inst:
        expr = expr.replace(fn, lam)
    # evaluate derivatives only: integrals stay for mpmath quad
    return expr.replace(lambda e: isinstance(e, (sp.Derivative, sp.Subs)), lambda e: e.doit())


def trig_name(fn) -> str:
    """'sin' or 'cos' for mpmath's functions (whose __name__ is not their name)."""
    return {mp.sin: "sin", mp.cos: "cos"}.get(fn, getattr(fn, "__name__", "?"))
