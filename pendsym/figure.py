"""Figures of a report: declared by a memoir, sampled by derive, drawn by the report (pgfplots).

A :class:`Figure` is data: a title, a caption that cites the equations, two axes, curves and
marks.  Each :class:`Curve` says where its points come from (its provenance): the printed or the
derived form of a Result, the emitted kernel of a Result, or a truth (an independent computation,
a function of the abscissa and the working digits).  :func:`sample` evaluates every curve at its
points, deterministically, at the digits the figure declares: a form by mpmath (``form_dps``), a
truth at ``dps``, a kernel as emitted (Python, double precision).  The sampled :class:`Plot` holds
floats only; derive caches it under a key covering the figure's module and the modules it imports,
the Results it cites and the versions (:func:`figure_key`), and counts the seconds it took.

A memoir registers its figures on its Memoir (``Memoir(figures=...)``); a figure is set in the
report after the Result named by ``after`` (by default the first Result a curve cites), so in the
chapter of that Result.  Nothing here names a memoir.
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass
from typing import Callable, Mapping, Sequence

import mpmath as mp
import sympy as sp
from sympy.core.function import AppliedUndef

from . import keys, verify

SOURCES = ("printed", "derived", "kernel", "truth")
STYLES = ("line", "marks", "dashed")


@dataclass(frozen=True)
class Axis:
    """One axis: its label (LaTeX math), log scale or not, and the shown range (None: automatic)."""

    label: str
    log: bool = False
    lo: float | None = None
    hi: float | None = None


@dataclass(frozen=True)
class Curve:
    """One curve and the provenance of its points.

    ``source``: "printed" or "derived" (that form of Result ``result``, evaluated by mpmath with the
    symbols' values ``env(x)``), "kernel" (the emitted Python kernel of ``result`` at ``env(x)``; no
    points when no kernel is emitted, which the caption then says), or "truth" (``truth(x, dps)``,
    an independent computation, described by ``describe``).  ``points``: the abscissae, as decimal
    strings (exact, so that the sampling is the same on every machine)."""

    label: str
    source: str
    points: tuple[str, ...]
    result: str | None = None
    env: Callable[[mp.mpf], Mapping[str, object]] | None = None
    truth: Callable[[mp.mpf, int], object] | None = None
    describe: str = ""
    style: str = "line"

    def __post_init__(self):
        if self.source not in SOURCES:
            raise ValueError(f"curve {self.label!r}: source must be one of {SOURCES}, not {self.source!r}")
        if self.style not in STYLES:
            raise ValueError(f"curve {self.label!r}: style must be one of {STYLES}, not {self.style!r}")
        if self.source == "truth" and (self.truth is None or not self.describe):
            raise ValueError(f"curve {self.label!r}: a truth needs its function and its description")
        if self.source != "truth" and (self.result is None or self.env is None):
            raise ValueError(f"curve {self.label!r}: a {self.source} curve needs the Result and env(x)")
        if not self.points:
            raise ValueError(f"curve {self.label!r}: no points")

    def provenance(self) -> str:
        """Where the points come from, in words (for the caption and results)."""
        if self.source == "truth":
            return self.describe
        if self.source == "kernel":
            return f"the emitted Python kernel of {self.result} (double precision)"
        return f"the {self.source} form of {self.result}"


@dataclass(frozen=True)
class Mark:
    """A vertical rule at x, labelled (e.g. an end printed in the memoir)."""

    x: float
    label: str


@dataclass(frozen=True)
class Figure:
    """A figure of a memoir's report.  ``id``: the memoir's key first (``mymemoir.fig.name``);
    ``module``: the declaring module (``__name__``), whose source and imports key the cache;
    ``dps``: the working digits of the truths, ``form_dps`` of the forms (the caption states both)."""

    id: str
    module: str
    title: str
    caption: str
    x: Axis
    y: Axis
    curves: tuple[Curve, ...]
    marks: tuple[Mark, ...] = ()
    after: str | None = None
    dps: int = 15
    form_dps: int = 30

    def __post_init__(self):
        if not self.curves:
            raise ValueError(f"figure {self.id}: no curves")

    @property
    def memoir(self) -> str:
        return self.id.split(".", 1)[0]

    @property
    def cites(self) -> tuple[str, ...]:
        """The Results whose forms or kernels the curves draw, in order, once each."""
        return tuple(dict.fromkeys(c.result for c in self.curves if c.result is not None))

    @property
    def place(self) -> str | None:
        """The Result after which the report sets the figure."""
        return self.after or (self.cites[0] if self.cites else None)


@dataclass(frozen=True)
class Plot:
    """A sampled figure: per curve its (x, y) points (y None where undefined), notes (a curve
    without points, say), and the CPU seconds the sampling took."""

    figure: str
    series: tuple[tuple[tuple[float, float | None], ...], ...]
    notes: tuple[str, ...]
    seconds: float


# ----------------------------------------------------------------- sampling
def _float(value) -> float | None:
    """A real value as a float; None when it is not finite or not real."""
    try:
        if isinstance(value, mp.mpc):
            if abs(value.imag) > abs(value.real) * mp.mpf(10) ** (-mp.mp.dps // 2):
                return None
            value = value.real
        out = float(value)
    except (TypeError, ValueError, OverflowError):
        return None
    return out if math.isfinite(out) else None


def _form_points(curve: Curve, expr: sp.Expr, dps: int) -> tuple:
    # a form holding applied undefined functions (F(2) …) takes their values from env(x), keyed by
    # the applied function itself (verify.value_at)
    apps = sorted(expr.atoms(AppliedUndef), key=sp.srepr)
    stand = [sp.Dummy() for _ in apps]
    expr = expr.xreplace(dict(zip(apps, stand)))
    syms = sorted(expr.free_symbols - set(stand), key=lambda s: s.name)
    fn = verify.lambdify_mp(expr, [*syms, *stand])
    out = []
    with mp.workdps(dps):
        for p in curve.points:
            x = mp.mpf(p)
            env = curve.env(x)
            try:
                y = fn(*(mp.mpf(env[s.name]) for s in syms), *(mp.mpf(env[ap]) for ap in apps))
            except (ZeroDivisionError, ValueError):
                y = None
            out.append((float(x), _float(y)))
    return tuple(out)


def _truth_points(curve: Curve, dps: int) -> tuple:
    with mp.workdps(dps):
        return tuple((float(mp.mpf(p)), _float(curve.truth(mp.mpf(p), dps))) for p in curve.points)


def _kernel_points(curve: Curve, kernel: Callable, names: Sequence[str]) -> tuple:
    out = []
    with mp.workdps(30):
        for p in curve.points:
            env = curve.env(mp.mpf(p))
            try:
                y = kernel(*(float(env[n]) for n in names))
            except (ValueError, ZeroDivisionError, OverflowError):
                y = None
            out.append((float(mp.mpf(p)), _float(y)))
    return tuple(out)


def sample(figure: Figure, results: Mapping[str, object],
           kernels: Mapping[str, tuple[Callable, Sequence[str]]] | None = None) -> Plot:
    """Every curve of the figure at its points.  ``results``: the built Results by id (at least
    those the figure cites); ``kernels``: per Result id, its emitted kernel as (callable, argument
    names), for "kernel" curves (a Result absent from it has no kernel: the curve is left empty and
    a note says so)."""
    start = time.process_time()
    series, notes = [], []
    for curve in figure.curves:
        if curve.source == "truth":
            series.append(_truth_points(curve, figure.dps))
        elif curve.source == "kernel":
            k = (kernels or {}).get(curve.result)
            if k is None:
                series.append(())
                notes.append(f"{curve.label}: no kernel of {curve.result} is emitted")
            else:
                series.append(_kernel_points(curve, *k))
        else:
            r = results[curve.result]
            expr = r.derived_value if curve.source == "derived" else r.printed_value
            if expr is None:
                series.append(())
                notes.append(f"{curve.label}: {curve.result} has no printed form")
            else:
                series.append(_form_points(curve, expr, figure.form_dps))
    return Plot(figure.id, tuple(series), tuple(notes), round(time.process_time() - start, 3))


def figure_key(figure: Figure, result_keys: Mapping[str, str], kernel_forms: Mapping[str, str],
               roots: tuple[str, ...]) -> str:
    """The cache key of a figure's sampling: its declaring module and every module of the engine or
    the memoir it imports (:func:`pendsym.keys.section_hash`), the keys of the Results it cites, the
    forms of the kernels it draws (``kernel_forms``: id → srepr, "" when none is emitted), the
    versions, and the figure's own fields (points, digits)."""
    drawn = [kernel_forms.get(c.result, "") for c in figure.curves if c.source == "kernel"]
    fields = repr((figure.id, figure.x, figure.y, figure.marks, figure.dps, figure.form_dps, figure.after,
                   [(c.label, c.source, c.points, c.result, c.describe, c.style) for c in figure.curves]))
    return keys.digest(("figure", keys.FORMAT, *keys.versions(), keys.section_hash(figure.module, roots), fields,
                        *(result_keys[i] for i in figure.cites), *drawn))
