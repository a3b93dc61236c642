"""The answer of a solved problem as LaTeX and as Python and C kernels, with measured accuracy.

A kernel is emitted for each closed-form answer whose free symbols are the small parameter,
the parameters and (for a motion) τ or t; SymPy's printers write the code, the C file is
compiled by :func:`pendsym.emit.kernels.compile.compile_c`, and each kernel's accuracy is
measured in double precision against the same closed form evaluated by mpmath at 30 digits,
over the verification's sequence of the small parameter (and τ on one period for a motion).
The accuracy is the kernel's agreement with its formula; the formula's own error against the
equation is the evidence of the solution.
"""
from __future__ import annotations

import importlib.util
import re
import tempfile
from pathlib import Path

import mpmath as mp
import sympy as sp

from ..emit.kernels.compile import c_callable, compile_c
from ..emit.mathtex import tex_expr
from .. import verify as engine


def _ident(name: str) -> str:
    for greek, latin in (("Δ", "d"), ("α", "alpha"), ("θ", "theta"), ("'", "_speed")):
        name = name.replace(greek, latin)
    return "k_" + (re.sub(r"[^A-Za-z0-9]+", "_", name).strip("_") or "answer")


def kernels_of(sol) -> list[tuple[str, tuple, sp.Expr]]:
    """(function name, argument symbols, expression) of each closed-form answer."""
    pr = sol.problem
    allowed = {pr.small, *pr.parameters, sp.Symbol("tau", real=True), pr.t}
    out, seen = [], set()
    for ans in sol.answers:
        expr = ans.expr
        if not isinstance(expr, sp.Expr) or expr.has(sp.Piecewise) or not expr.free_symbols <= allowed:
            continue
        name = _ident(ans.name.split(",")[0])
        if name in seen:
            continue
        seen.add(name)
        args = tuple(sorted(expr.free_symbols, key=lambda s: s.name))
        out.append((name, args, expr))
    return out


def python_text(ks) -> str:
    lines = ['"""Kernels of a pendsym solve answer (generated)."""', "import math", ""]
    for name, args, expr in ks:
        code = sp.pycode(expr, fully_qualified_modules=True)
        lines += [f"def {name}({', '.join(a.name for a in args)}):", f"    return {code}", ""]
    return "\n".join(lines)


_C_CONSTANTS = (
    ("M_PI", "3.14159265358979323846264338327950288"), ("M_PI_2", "1.57079632679489661923132169163975144"),
    ("M_PI_4", "0.785398163397448309615660845819875721"), ("M_1_PI", "0.318309886183790671537767526745028724"),
    ("M_2_PI", "0.636619772367581343075535053490057448"), ("M_2_SQRTPI", "1.12837916709551257389615890312154517"),
    ("M_SQRT2", "1.41421356237309504880168872420969808"), ("M_SQRT1_2", "0.707106781186547524400844362104849039"),
    ("M_E", "2.71828182845904523536028747135266250"), ("M_LN2", "0.693147180559945309417232121458176568"),
    ("M_LN10", "2.30258509299404568401799145468436421"), ("M_LOG2E", "1.44269504088896340735992468100189214"),
    ("M_LOG10E", "0.434294481903251827651128918916605082"))


def c_text(ks) -> str:
    lines = ["/* Kernels of a pendsym solve answer (generated). */", "#include <math.h>"]
    for name, value in _C_CONSTANTS:   # SymPy's C printer writes these; strict C does not define them
        lines += [f"#ifndef {name}", f"#define {name} {value}", "#endif"]
    lines.append("")
    for name, args, expr in ks:
        lines += [f"double {name}({', '.join('double ' + a.name for a in args)}) {{",
                  f"    return {sp.ccode(expr)};", "}", ""]
    return "\n".join(lines)


def latex_text(sol) -> str:
    lines = [f"% {sol.problem.name}: {sol.method}"]
    for ans in sol.answers:
        lines.append(f"% {ans.name}")
        lines.append(r"\[" + tex_expr(ans.expr) + r"\]")
    return "\n".join(lines) + "\n"


def _sample(sol, args) -> list[dict]:
    pr = sol.problem
    base = {s.name: mp.mpf(v) for s, v in pr.parameters.items()}
    eps = engine.geometric(pr.small_range[0], pr.small_range[1], pr.points)
    pts = []
    for e in eps:
        for j in range(4 if any(a.name in ("tau", pr.t.name) for a in args) else 1):
            env = dict(base, **{pr.small.name: e, "tau": 2 * mp.pi * j / 4 + mp.mpf(1) / 7,
                                pr.t.name: 2 * mp.pi * j / 4 + mp.mpf(1) / 7})
            pts.append(env)
    return pts


def measure(sol, ks, py_module, c_lib) -> list[dict]:
    """Largest relative error (absolute below 1) of each Python and C kernel on its sample."""
    rows = []
    for name, args, expr in ks:
        f_py = getattr(py_module, name)
        f_c = c_callable(c_lib, name, len(args))
        worst_py = worst_c = 0.0
        for env in _sample(sol, args):
            with mp.workdps(30):
                ref = engine.value_at(expr, env)
            xs = [float(env[a.name]) for a in args]
            scale = max(abs(ref), 1)
            worst_py = max(worst_py, float(abs(mp.mpf(f_py(*xs)) - ref) / scale))
            worst_c = max(worst_c, float(abs(mp.mpf(f_c(*xs)) - ref) / scale))
        rows.append({"kernel": name, "args": [a.name for a in args], "python": worst_py, "c": worst_c})
    return rows


def emit(sol, out: Path) -> list[dict]:
    """Write answer.tex, answer.py and answer.c under ``out``; return the measured accuracies."""
    out.mkdir(parents=True, exist_ok=True)
    ks = kernels_of(sol)
    (out / "answer.tex").write_text(latex_text(sol))
    (out / "answer.py").write_text(python_text(ks))
    (out / "answer.c").write_text(c_text(ks))
    if not ks:
        return []
    spec = importlib.util.spec_from_file_location("pendsym_solve_answer", out / "answer.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)          # the code SymPy printed from the parsed answer
    with tempfile.TemporaryDirectory() as tmp:
        lib = compile_c(c_text(ks), Path(tmp))
        return measure(sol, ks, module, lib)
