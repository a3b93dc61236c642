"""One check engine: every independent check of every memoir is one of these kinds.

A check is a frozen declaration (what the truth is, where to compare, how
precisely); :func:`run` turns it into :class:`~pendsym.result.Evidence`, once,
for any memoir.  The engine evaluates the derived form *and* the printed form
(so the printed-form comparison is written once), confirms the truth at a
higher precision (also written once), and never patches an Evidence: each is
built in one place from what was measured.

Kinds
-----
* :class:`Values`     formula against a truth computed from the governing model, at points (a Tuple
                      form component by component; a vanishing form relative to Σ|terms|; or a
                      counterexample, ``fails_by``);
* :class:`Order`      fitted order of the residual over a geometric sequence of the small parameter
                      (rule of evidence 3); see :func:`pendsym.verify.order_check`;
* :class:`Inequality` a quantity the memoir claims positive, with its margins;
* :class:`Proof`      an exact symbolic statement about the derived form;
* :class:`Chain`      a step verified through the Results it feeds: the pipeline fills in their
                      evidence after they ran (no check rebuilds the registry);
* :class:`Definition` a pure definition: compared exactly with the text (componentwise for a Tuple),
                      never counted as verified;
* :class:`All`        several checks of one Result, passed only if all pass.

A plain callable ``check(result, level) -> Evidence`` is still accepted by
:func:`run` (kind "custom"): such a check must build its Evidence through
:mod:`pendsym.verify`.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Iterable, Mapping, Sequence

import mpmath as mp
import sympy as sp

from . import verify
from .result import Evidence

TOL = mp.mpf("1e-25")       # largest residual of a value check at 30 working digits
DPS, CONFIRM_DPS = 30, 45   # working and confirming precision of a truth
MIN_DIGITS = 28             # the two precisions must agree to this many digits


@dataclass(frozen=True)
class Point:
    """One comparison: the formula (its component ``component`` when it is a Tuple) at ``env``
    against ``truth``.

    The residual is |formula − truth| / denom; denom defaults to max(|truth|, 1) (relative for
    large values, absolute for small ones); ``denom="terms"`` scales by Σ|terms| of the expanded
    formula at env (for a quantity that must vanish: truth 0).  With ``through``, the formula's
    value is compared through that function (when the truth measures a quantity it determines).
    """

    label: str
    env: Mapping
    truth: object
    denom: object = None
    component: int | None = None
    through: Callable[[object], object] | None = None

    def residual(self, value, terms=None) -> mp.mpf:
        t = mp.mpf(self.truth)
        if isinstance(self.denom, str):
            den = mp.mpf(terms)
        else:
            den = max(abs(t), mp.mpf(1)) if self.denom is None else mp.mpf(self.denom)
        return abs(mp.mpf(value) - t) / den

    def compare(self, form: sp.Basic) -> mp.mpf:
        """The residual of a form (derived or printed) at this point."""
        if self.component is not None:
            form = form[self.component]
        terms = terms_scale(form, self.env) if self.denom == "terms" else None
        value = verify.value_at(form, self.env)
        return self.residual(value if self.through is None else self.through(value), terms)


def terms_scale(expr: sp.Expr, env: Mapping) -> mp.mpf:
    """Σ|terms| of the expanded expr at env: the scale of a quantity that should vanish."""
    return sum((abs(mp.mpf(verify.value_at(tm, env))) for tm in sp.Add.make_args(sp.expand(expr))), mp.mpf(0))


@dataclass(frozen=True)
class Geometric:
    """The small parameter's values of an order check: ``verify.LEVELS[level]`` points, in
    geometric progression from lo to hi."""

    lo: str
    hi: str

    def __call__(self, level: str) -> list:
        return verify.geometric(self.lo, self.hi, verify.LEVELS[level])


@dataclass(frozen=True)
class Values:
    """The formula against a truth from the governing model, at points.

    ``points(level, dps)`` yields :class:`Point`; ``confirm(dps)`` returns named
    truth values (the first point's truth, and whatever the truth rests on) at a
    precision: the engine calls it at ``DPS`` and ``CONFIRM_DPS`` and requires
    ``MIN_DIGITS`` of agreement on every nonzero value.

    With ``fails_by``, the check is a counterexample: it passes when the derived form is off the
    truth by more than ``fails_by`` at every point (its evidence reports the least residual).
    """

    truth: str
    points: Callable[[str, int], Iterable[Point]]
    confirm: Callable[[int], Mapping[str, object]] | None = None
    tol: object = TOL
    kind: str = "value"
    params: Callable[[str], tuple] | tuple = ()
    note: str = ""
    work_dps: int = 40
    fails_by: object = None


@dataclass(frozen=True)
class Order:
    """Fitted order of |truth(p) − formula(p)| in the small parameter ``param``.

    ``at(expr, p)`` evaluates a form (the derived or the printed one) at the parameter value p;
    ``truth(p, dps)`` computes the same quantity from the governing model.
    """

    param: str
    values: Callable[[str], Sequence]
    truth: Callable[[object, int], object]
    at: Callable[[sp.Expr, object], object]
    expected: float
    truth_desc: str
    band: float = 0.3
    params: tuple = ()
    dps: int = 30
    confirm_dps: int = 45
    note: str = ""


@dataclass(frozen=True)
class Inequality:
    """The memoir claims the quantity positive: at each point its value must exceed
    ``margin`` × Σ|terms| (so that a value lost in rounding does not count)."""

    truth: str
    points: Callable[[str, int], Iterable[tuple[str, Mapping]]]
    margin: object = mp.mpf("1e-20")
    confirm: Callable[[int], Mapping[str, object]] | None = None


@dataclass(frozen=True)
class Proof:
    """An exact statement about the derived form, decided by SymPy."""

    statement: str
    holds: Callable[[sp.Basic], bool] = lambda expr: sp.simplify(expr) == 0
    truth: str = "symbolic proof"


@dataclass(frozen=True)
class Chain:
    """A step verified through the Results it feeds (their checks use its derived form)."""

    downstream: tuple[str, ...]


@dataclass(frozen=True)
class Definition:
    """A pure definition: listed and compared with the text exactly, not a claim."""


@dataclass(frozen=True)
class All:
    """Several checks of one Result: passed only if every one passes."""

    checks: tuple
    truth: str | None = None


# ----------------------------------------------------------------- the engine
def run(check, result, level: str = "full") -> Evidence | None:
    """The Evidence of ``check`` on ``result`` (None for no check, or for a Chain before its
    downstream Results ran: see :func:`chained`)."""
    if check is None or isinstance(check, Chain):
        return None
    if isinstance(check, Values):
        return _values(check, result, level)
    if isinstance(check, Order):
        return _order(check, result, level)
    if isinstance(check, Inequality):
        return _inequality(check, result, level)
    if isinstance(check, Proof):
        return verify.proof(statement=check.statement, holds=bool(check.holds(result.derived)),
                            truth_desc=check.truth)
    if isinstance(check, Definition):
        return Evidence(kind="definition", passed=_same_exactly(result),
                        truth="a definition, compared exactly with the text")
    if isinstance(check, All):
        return _all([run(c, result, level) for c in check.checks], check.truth)
    return check(result, level)     # a custom check (built with pendsym.verify)


def chained(check: Chain, evidence: Mapping[str, Evidence | None]) -> Evidence:
    """A Chain's Evidence from the evidence of the Results it feeds (filled by the pipeline)."""
    evs = [evidence.get(d) for d in check.downstream]
    first = next((e for e in evs if e is not None), None)
    ok = bool(evs) and all(e is not None and e.passed for e in evs)
    truth = "through " + ", ".join(check.downstream) + ": " + "; ".join(e.truth for e in evs if e)
    if first is None:
        return Evidence(kind="chain", passed=False, truth=truth, note="the Results it feeds have no evidence")
    return Evidence(kind="chain", passed=ok, truth=truth, max_residual=first.max_residual, order=first.order,
                    expected_order=first.expected_order, band=first.band, param=first.param,
                    params=first.params, series=first.series, note="verified through the Results it feeds")


def confirmation_digits(confirm: Callable[[int], Mapping[str, object]] | None) -> float | None:
    """Agreement, in digits, of the named truth values at DPS and at CONFIRM_DPS."""
    if confirm is None:
        return None
    with mp.workdps(DPS + 10):
        lo = dict(confirm(DPS))
    with mp.workdps(CONFIRM_DPS + 10):
        hi = dict(confirm(CONFIRM_DPS))
        # compared at the higher precision: at the caller's precision two values could look equal
        ds = [verify.truth_digits(lo[k], hi[k]) for k in lo if k in hi and lo[k] != 0]
    return min(ds) if ds else float(CONFIRM_DPS)


def _same_exactly(result) -> bool:
    """The printed form equals the derived one exactly (componentwise for a Tuple)."""
    printed, derived = result.printed_value, result.derived_value
    if printed is None:
        return False
    if isinstance(derived, sp.Tuple) or isinstance(printed, sp.Tuple):
        return len(printed) == len(derived) and all(verify.exactly_equal(p, d) for p, d in zip(printed, derived))
    return bool(verify.exactly_equal(printed, derived))


def _forms(result) -> list[tuple[str, sp.Basic]]:
    out = [("derived", result.derived_value)]
    if result.printed is not None:
        out.append(("printed", result.printed_value))
    return out


def _values(check: Values, result, level: str) -> Evidence:
    if check.fails_by is not None:
        return _counterexample(check, result, level)
    worst = {name: mp.mpf(0) for name, _ in _forms(result)}
    labels = []
    with mp.workdps(check.work_dps):
        for pt in check.points(level, DPS):
            labels.append(pt.label)
            for name, form in _forms(result):
                worst[name] = max(worst[name], pt.compare(form))
    digits = confirmation_digits(check.confirm)
    tol = mp.mpf(check.tol)
    passed = worst["derived"] < tol and (digits is None or digits >= MIN_DIGITS)
    note = f"{len(labels)} points"
    if digits is not None:
        note += f"; truth confirmed to {digits:.1f} digits at {CONFIRM_DPS} digits"
    if "printed" in worst:
        note += f"; printed form: max residual {float(worst['printed']):.3g}"
    if check.note:
        note += f"; {check.note}"
    params = check.params(level) if callable(check.params) else check.params
    return Evidence(kind=check.kind, passed=bool(passed), truth=check.truth,
                    max_residual=verify.rounded(worst["derived"]), params=tuple(params),
                    printed_agrees=None if "printed" not in worst else bool(worst["printed"] < tol),
                    confirm_digits=None if digits is None else verify.rounded(digits), note=note)


def _counterexample(check: Values, result, level: str) -> Evidence:
    """A Values check with ``fails_by``: the derived form must miss the truth at every point."""
    with mp.workdps(check.work_dps):
        residuals = [(pt.label, pt.compare(result.derived_value)) for pt in check.points(level, DPS)]
    least = min(res for _, res in residuals)
    note = "must fail; relative residual " + "; ".join(f"{label}: {mp.nstr(res, 3)}" for label, res in residuals)
    return Evidence(kind=check.kind, passed=bool(least > mp.mpf(check.fails_by)), truth=check.truth,
                    max_residual=verify.rounded(least), note=note)


def _order(check: Order, result, level: str) -> Evidence:
    printed = result.printed_value
    return verify.order_check(
        param=check.param, values=check.values(level), truth=check.truth,
        derived=lambda p: check.at(result.derived_value, p),
        printed=(lambda p: check.at(printed, p)) if printed is not None else None,
        expected=check.expected, band=check.band, truth_desc=check.truth_desc, params=check.params,
        dps=check.dps, confirm_dps=check.confirm_dps, note=check.note)


def _inequality(check: Inequality, result, level: str) -> Evidence:
    margins, ok = [], True
    with mp.workdps(40):
        for label, env in check.points(level, DPS):
            value = mp.mpf(verify.value_at(result.derived_value, env))
            scale = terms_scale(result.derived_value, env)
            ok &= bool(value > scale * check.margin)
            if result.printed is not None:
                ok &= bool(mp.mpf(verify.value_at(result.printed_value, env)) > scale * check.margin)
            margins.append((label, value, value / scale if scale else value))
    digits = confirmation_digits(check.confirm)
    ok &= digits is None or digits >= MIN_DIGITS
    note = "margins (value; value/Σ|terms|): " + "; ".join(
        f"{lb}: {mp.nstr(mv, 6)} ({mp.nstr(rel, 3)})" for lb, mv, rel in margins)
    if digits is not None:
        note += f" | truth confirmed to {digits:.1f} digits at {CONFIRM_DPS}"
    return Evidence(kind="inequality", passed=bool(ok), truth=check.truth,
                    max_residual=verify.rounded(min(m[2] for m in margins)),
                    printed_agrees=None if result.printed is None else bool(ok),
                    confirm_digits=None if digits is None else verify.rounded(digits), note=note)


def _all(evs: list[Evidence | None], truth: str | None) -> Evidence:
    evs = [e for e in evs if e is not None]
    first = evs[0]
    fields = {k: getattr(first, k) for k in first.__dataclass_fields__}
    fields.update(passed=all(e.passed for e in evs), truth=truth or " + ".join(e.truth for e in evs),
                  note=" ; ".join(e.note for e in evs if e.note))
    return Evidence(**fields)
