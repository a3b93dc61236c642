"""The answer of a solved problem as LaTeX and as Python and C kernels, with measured accuracy.

A kernel is emitted for each closed-form answer whose free symbols are the small parameter,
the parameters and (for a motion) τ or t, and measured under the project's accuracy contract
by the memoir kernels' machinery (:mod:`.kernels`). The accuracy is the kernel's agreement
with its formula; the formula's own error against the equation is the evidence of the solution.
"""
from __future__ import annotations

import re
from pathlib import Path

import sympy as sp

from ..emit.kernels import closed_form
from ..emit.mathtex import tex_expr
from . import kernels


def _ident(name: str) -> str:
    for greek, latin in (("Δ", "d"), ("α", "alpha"), ("θ", "theta"), ("'", "_speed")):
        name = name.replace(greek, latin)
    return "k_" + (re.sub(r"[^A-Za-z0-9]+", "_", name).strip("_") or "answer")


def kernels_of(sol) -> list[tuple[str, str, tuple, sp.Expr]]:
    """(function name, answer name, argument symbols, expression) of each closed-form answer with
    arguments (a constant answer is not a kernel) that the kernels' printers can write."""
    return [k for k in _closed(sol) if kernels.unprintable(*k) is None]


def not_kernels(sol) -> list[str]:
    """One line for each closed-form answer the printers cannot write (a function that neither
    Python's math nor C99's libm has, such as a Bessel function)."""
    return [f"no kernel for {k[1]}: {why}" for k in _closed(sol) if (why := kernels.unprintable(*k)) is not None]


def _closed(sol) -> list[tuple[str, str, tuple, sp.Expr]]:
    pr = sol.problem
    allowed = {pr.small, *pr.parameters, sp.Symbol(kernels.TAU, real=True), pr.t}
    out, seen = [], set()
    for ans in sol.answers:
        expr = ans.expr
        if (not isinstance(expr, sp.Expr) or expr.has(sp.Piecewise) or not closed_form(expr)
                or not expr.free_symbols <= allowed):
            continue
        name = _ident(ans.name.split(",")[0])
        if name in seen:
            continue
        seen.add(name)
        args = tuple(sorted(expr.free_symbols, key=lambda s: s.name))
        out.append((name, ans.name.rstrip(", "), args, expr))
    return out


def latex_text(sol) -> str:
    lines = [f"% {sol.problem.name}: {sol.method}"]
    for ans in sol.answers:
        lines.append(f"% {ans.name}")
        lines.append(r"\[" + tex_expr(ans.expr) + r"\]")
    return "\n".join(lines) + "\n"


def emit(sol, out: Path, points: int = kernels.audit.POINTS) -> list:
    """Write answer.tex, answer.py and answer.c under ``out``, the kernels measured from the files as
    written by the deep audit (:mod:`.kernels`); return the measured kernels (their ``figures``)."""
    out.mkdir(parents=True, exist_ok=True)
    (out / "answer.tex").write_text(latex_text(sol))
    ks = kernels.build(sol, kernels_of(sol))
    paths = kernels.write(ks, sol.problem, out)
    if not ks:
        return []
    ks = kernels.measure(ks, *paths, points=points)
    kernels.write(ks, sol.problem, out)        # the same code, its figures in its docstring and comment
    return ks
