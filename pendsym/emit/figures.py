"""The figures of a report, as pgfplots (templates/report_figure.tex.j2), from sampled Plots.

A figure is drawn from its Plot (floats only); its caption is the memoir's caption followed by
the provenance of every curve (which Result's form, which kernel, which truth), the digits at
which forms and truths were computed, and any note of the sampling (a curve left empty).  On a
linear axis with a given range, values far outside it are held just outside (the line leaves the
frame where it should) and a line is broken where it jumps from one side to the other (a pole is
not a zero); on a log axis, values that are not positive are not drawn and the caption says so.
"""
from __future__ import annotations

from .layout import lay_out
from .textex import tex_text

COLORS = ("blue", "red!80!black", "black", "green!50!black", "orange!90!black", "violet")


def _num(x: float) -> str:
    return f"{x:.7g}"


def _held(points, axis) -> tuple[list[tuple[float, float | None]], int]:
    """The points as drawn on ``axis`` (y), and how many were dropped as not positive on a log axis."""
    out: list[tuple[float, float | None]] = []
    dropped = 0
    if axis.log:
        for x, y in points:
            if y is not None and y <= 0:
                dropped += 1
                y = None
            out.append((x, y))
        return out, dropped
    if axis.lo is None or axis.hi is None:
        return list(points), 0
    span = axis.hi - axis.lo
    lo, hi = axis.lo - span / 4, axis.hi + span / 4
    side_before = 0
    for x, y in points:
        side = 0 if y is None else (-1 if y < lo else 1 if y > hi else 0)
        if side and side_before == -side:
            out.append((x, None))                  # from one side out of the frame to the other
        out.append((x, None if y is None else min(max(y, lo), hi)))
        side_before = side
    return out, 0


def _coordinates(points) -> str:
    return " ".join(f"({_num(x)},{'nan' if y is None else _num(y)})" for x, y in points)


def _style(curve, color: str) -> str:
    if curve.style == "marks":
        return f"{color},only marks,mark=*,mark size=1.6pt"
    if curve.style == "dashed":
        return f"{color},dashed,thick"
    return f"{color},thick"


def _digits(fig, plot) -> str:
    parts = []
    if any(c.source in ("printed", "derived") for c in fig.curves):
        parts.append(f"forms evaluated by mpmath at {fig.form_dps} digits")
    if any(c.source == "truth" for c in fig.curves):
        parts.append(f"truths computed at {fig.dps} working digits")
    if any(c.source == "kernel" and points for c, points in zip(fig.curves, plot.series)):
        parts.append("kernels in double precision")
    return "; ".join(parts)


def figure_tex(fig, plot, number: int) -> str:
    """The LaTeX of one figure (a tikzpicture and its numbered caption)."""
    curves, notes = [], list(plot.notes)
    for i, (curve, points) in enumerate(zip(fig.curves, plot.series)):
        drawn, dropped = _held(points, fig.y)
        if dropped:
            notes.append(f"{curve.label}: {dropped} of its {len(points)} values are not positive and are not drawn "
                         "on the log axis")
        if not any(y is not None for _, y in drawn):
            continue
        curves.append({"style": _style(curve, COLORS[i % len(COLORS)]), "coords": _coordinates(drawn),
                       "legend": tex_text(curve.label)})
    provenance = "; ".join(f"{c.label}: {c.provenance()}" for c in fig.curves)
    caption = (f"{fig.caption} Points: {provenance}. {_upper(_digits(fig, plot))}."
               + "".join(f" {n[0].upper()}{n[1:]}." for n in notes))
    return lay_out("report_figure.tex.j2", number=number, title=tex_text(fig.title), caption=tex_text(caption),
                   xlabel=fig.x.label, ylabel=fig.y.label, xlog=fig.x.log, ylog=fig.y.log,
                   limits=_limits(fig), curves=curves,
                   marks=[{"x": _num(m.x), "label": tex_text(m.label)} for m in fig.marks])


def _limits(fig) -> str:
    out = []
    for name, axis in (("x", fig.x), ("y", fig.y)):
        if axis.lo is not None:
            out.append(f"{name}min={_num(axis.lo)}")
        if axis.hi is not None:
            out.append(f"{name}max={_num(axis.hi)}")
    return ",".join(out)


def _upper(text: str) -> str:
    return text[:1].upper() + text[1:]
