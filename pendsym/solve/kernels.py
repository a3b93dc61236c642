"""The kernels of a solve answer, held to the project's accuracy contract and measured as emitted.

Each closed-form answer of the small parameter, the parameters and τ (or t) becomes a Python
(math only) and a C99 (libm only) function, built and measured by the machinery of the memoir
kernels, not a second one (docs/kernel-accuracy.md):

- its **domain** is the box of :func:`domain_of`: the problem file's ``[domain]`` table, or the
  defaults written there (docs/solve.md);
- its **form** is chosen among the named rewrite rules by :func:`pendsym.emit.kernels.choose_form`
  on the kernel's seeded sample (:func:`pendsym.emit.kernels.kernel_sample`), against the answer
  in Horner form in the small parameter (:func:`small_last`) where it is a polynomial in it;
- it is **printed** by the kernels' printers (:func:`pendsym.emit.kernels.definition`), with the
  guard of its domain (a ValueError in Python, NaN and errno = EDOM in C outside it);
- it is **measured** from the files as written (answer.py imported, answer.c compiled with
  ``cc -std=c99 -O2``) by the deep audit's :func:`pendsym.audit.run.audit_one`: the hard points,
  20,000 points in all with an adversarial search, against the answer's SymPy form in mpmath at
  50 digits or more, the error in ulp divided by max(1, κ) (κ the condition number of the form).

The bound is :data:`pendsym.emit.kernels.BOUND` (4). A kernel over it is still written (the user
asked for it) but its docstring and header comment begin with ``OVER THE BOUND``, and the
command says so on stderr and exits 1.  The figures are of the code in the files: a docstring or
a comment changes no result, and the bodies measured are those written.
"""
from __future__ import annotations

import ctypes
import math
import tempfile
import types
from dataclasses import dataclass, replace
from pathlib import Path

import sympy as sp

from ..audit import run as audit
from ..emit import kernels as kn
from ..result import KernelArg

TAU = "tau"
CONTRACT = "docs/kernel-accuracy.md"


class DomainError(ValueError):
    """A kernel argument without a usable range; the message is one line."""


@dataclass(frozen=True)
class SolveKernel:
    name: str
    answer: str                 # the answer's name in the report
    args: tuple                 # KernelArg of each argument, in order
    expr: sp.Expr               # the answer's SymPy form: the reference
    form: sp.Expr               # the form emitted (chosen by the rewrite rules)
    rule: str
    figures: dict | None = None  # the audit's record (audit_one), once measured

    @property
    def over(self) -> bool:
        f = self.figures
        return f is not None and (f["python"]["worst_scaled"] > kn.BOUND or f["c"]["worst_scaled"] > kn.BOUND
                                  or bool(f.get("outside")))


def domain_of(problem, name: str) -> KernelArg:
    """The declared range of one kernel argument (docs/solve.md, "Kernels"): the problem's
    ``[domain]`` entry, else the default — the small parameter from 0 to the largest value the
    verification uses; a parameter of value v from v/4 to 4v (geometric; [−1, 1] when v = 0);
    τ over one period [0, 2π]; t from 0 to 1/ε at the smallest ε of the slow-flow checks."""
    given = dict(problem.domain)
    if name in given:
        lo, hi = given[name]
        return KernelArg(name, float(lo), float(hi), log=float(lo) > 0 and float(hi) / float(lo) > 10)
    if name == problem.small.name:
        return KernelArg(name, 0.0, max(float(problem.small_range[1]), float(problem.slow_range[1])), log=False)
    if name == TAU:
        return KernelArg(name, 0.0, 2 * math.pi, log=False)
    if name == problem.t.name:
        return KernelArg(name, 0.0, 1 / min(float(problem.small_range[0]), float(problem.slow_range[0])), log=False)
    value = next((float(sp.Rational(v)) for s, v in problem.parameters.items() if s.name == name), None)
    if value is None:
        raise DomainError(f"kernel argument {name} has no range: give it in [domain]")
    if value == 0:
        return KernelArg(name, -1.0, 1.0, log=False)
    lo, hi = sorted((value / 4, value * 4))
    return KernelArg(name, lo, hi, log=lo > 0)


def build(sol, closed: list) -> list[SolveKernel]:
    """A kernel for each (name, answer name, symbols, expr) of ``closed``: its domain and its form."""
    out = []
    for name, label, syms, expr in closed:
        args = tuple(domain_of(sol.problem, s.name) for s in syms)
        plain = _signs_known(expr, syms, args)
        try:
            choice = kn.choose_form(plain, args, name)
            form, rule = choice.form, choice.rule
        except (sp.PolynomialError, ValueError, TypeError, ZeroDivisionError) as exc:   # a rule that cannot
            form, rule = plain, f"as-derived (the rewrite rules did not apply: {type(exc).__name__})"  # take it
        small = next((s for s in syms if s == sol.problem.small), None)
        series = small_last(plain, small) if small is not None else None
        if series is not None and series != form:
            pts = kn.kernel_sample(expr, args, name)
            truths = kn.references(expr, args, pts)
            mine, theirs = (kn.measure(kn.emitted_py(name, args, f), expr, args, pts, truths).max_scaled
                            for f in (series, form))
            if mine < theirs:
                form, rule = series, SMALL_LAST
        out.append(SolveKernel(name, label, args, expr, form, rule))
    return out


SMALL_LAST = "small-parameter Horner (higher orders first, each coefficient's multiple angles in its phase)"


def small_last(expr: sp.Expr, small: sp.Symbol) -> sp.Expr | None:
    """An answer Σ εʲ c_j written (… (c_n ε + c_{n−1}) ε + …) ε + c_0: the corrections, small, are summed
    first and the leading term last, so that the roundings of the many small terms do not add up at
    the ulp of the whole (the pendulum's θ(τ) to α¹¹: 5.6 ulp as one sum, 1.3 so); each c_j with its
    sin mφ, cos mφ (m ≥ 3) written in sin φ, cos φ (the rule 'multiple-angles'). None when the answer
    is not a polynomial in ε of degree ≥ 2."""
    try:
        poly = sp.Poly(sp.expand(expr), small)
    except sp.PolynomialError:
        return None
    if poly.degree() < 2 or any(c.has(small) for c in poly.all_coeffs()):
        return None
    angles = next(r for r in kn.REWRITES if r.name == "multiple-angles")
    out = sp.S.Zero
    for c in poly.all_coeffs():
        try:
            c = angles(c)
        except ValueError:          # no multiple angle in this coefficient
            pass
        out = out * small + c
    return out


def unprintable(name: str, label: str, syms: tuple, expr: sp.Expr) -> str | None:
    """Why the kernels' printers cannot write expr in Python or C (None when both can)."""
    args = tuple(KernelArg(s.name, 0.0, 1.0) for s in syms)
    for lang in ("py", "c"):
        try:
            kn.printed(kn.kernel_function(name, args, expr), lang)
        except Exception as exc:  # SymPy's printers raise their own kinds for an unsupported function
            return f"{'Python math' if lang == 'py' else 'C99 libm'} has no {str(exc).split(': ')[-1].splitlines()[0]}"
    return None


def _signs_known(expr: sp.Expr, syms: tuple, args: tuple) -> sp.Expr:
    """expr with |x| → ±x and sign(x) → ±1 for each argument whose domain has one sign (the same
    function there; the reference stays the answer's own form)."""
    rep = {}
    for s, a in zip(syms, args):
        if a.lo >= 0 or a.hi <= 0:
            sgn = 1 if a.lo >= 0 else -1
            rep.update({sp.Abs(s): sgn * s, sp.sign(s): sp.Integer(sgn)})
    return expr.xreplace(rep) if rep else expr


def _header(k: SolveKernel, problem) -> str:
    dom = "; ".join(f"{a.name} in [{a.lo:g}, {a.hi:g}]" for a in k.args)
    lines = [f"{k.answer} — pendsym solve, {problem.name}.", f"Domain: {dom}.", f"Form: rewrite rule '{k.rule}'."]
    f = k.figures
    if f is not None:
        where = audit._fmt_point(f["args"], f["worst_at"])
        lines.insert(0, "OVER THE BOUND: do not rely on this kernel's last digits." if k.over else
                     "Within the bound.")
        lines.append(f"Measured on {f['points']} points (hard points, random points, adversarial search) against "
                     f"the answer's form in mpmath at 50 digits or more: Python {f['python']['worst_ulp']:.3g} ulp "
                     f"({f['python']['worst_scaled']:.3g} scaled), C {f['c']['worst_ulp']:.3g} ulp "
                     f"({f['c']['worst_scaled']:.3g} scaled); worst at {where}.")
        if f.get("outside"):
            lines.append(f"Outside the domain: {'; '.join(f['outside'][:3])}.")
    else:
        lines.insert(0, "NOT MEASURED.")
    lines.append(f"Contract: scaled = ulp / max(1, κ) ≤ {kn.BOUND:g} ({CONTRACT}).")
    return "\n".join(lines)


def _function(k: SolveKernel) -> kn.Function:
    return kn.kernel_function(k.name, k.args, k.form)


def python_text(ks: list, problem) -> str:
    parts = [f'"""Kernels of a pendsym solve answer: {problem.name} (generated; do not edit).\n\n'
             f'Each docstring gives the kernel\'s domain and its measured error; the contract is {CONTRACT}.\n"""',
             "import math", ""]
    for k in ks:
        parts += ["", kn.definition(_function(k), "py", _header(k, problem)), ""]
    return "\n".join(parts)


# SymPy's C printer writes these macros for π/2, √2 …; strict C99 does not define them
_C_CONSTANTS = (
    ("M_PI", "3.14159265358979323846264338327950288"), ("M_PI_2", "1.57079632679489661923132169163975144"),
    ("M_PI_4", "0.785398163397448309615660845819875721"), ("M_1_PI", "0.318309886183790671537767526745028724"),
    ("M_2_PI", "0.636619772367581343075535053490057448"), ("M_2_SQRTPI", "1.12837916709551257389615890312154517"),
    ("M_SQRT2", "1.41421356237309504880168872420969808"), ("M_SQRT1_2", "0.707106781186547524400844362104849039"),
    ("M_E", "2.71828182845904523536028747135266250"), ("M_LN2", "0.693147180559945309417232121458176568"),
    ("M_LN10", "2.30258509299404568401799145468436421"), ("M_LOG2E", "1.44269504088896340735992468100189214"),
    ("M_LOG10E", "0.434294481903251827651128918916605082"))


def c_text(ks: list, problem) -> str:
    parts = [f"/* Kernels of a pendsym solve answer: {problem.name} (generated; do not edit).\n"
             f" * C99, libm only.  Each comment gives the kernel's domain and its measured error;\n"
             f" * the contract is {CONTRACT}. */", "#include <errno.h>", "#include <math.h>"]
    for name, value in _C_CONSTANTS:
        parts += [f"#ifndef {name}", f"#define {name} {value}", "#endif"]
    parts.append("")
    for k in ks:
        parts += [kn.definition(_function(k), "c", _header(k, problem)), ""]
    return "\n".join(parts)


def _load_py(path: Path):
    """answer.py run as a module (no bytecode cache is written beside it)."""
    module = types.ModuleType("pendsym_solve_answer")
    module.__file__ = str(path)
    exec(compile(path.read_text(), str(path), "exec"), module.__dict__)   # the code pendsym printed from the answer
    return module


def measure(ks: list, py_path: Path, c_path: Path, points: int = audit.POINTS) -> list[SolveKernel]:
    """Each kernel measured by the deep audit (:func:`pendsym.audit.run.audit_one`, at least `points`
    points) from the files as written: answer.py imported, answer.c compiled on its own."""
    module = _load_py(py_path)
    code = py_path.read_text()
    out = []
    with tempfile.TemporaryDirectory() as tmp:
        lib = kn.compile_c(c_path.read_text(), Path(tmp))
        lib = ctypes.CDLL(lib._name, use_errno=True)        # errno read by the test outside the domain
        for k in ks:
            syms = tuple(next(s for s in k.expr.free_symbols if s.name == a.name) for a in k.args)
            job = audit.Job(k.name, "solve", k.answer, k.args, k.expr, syms, getattr(module, k.name),
                            audit.c_function(lib, k.name, len(k.args)), code, audit.accepted(code, k.name, k.args))
            out.append(replace(k, figures=audit.audit_one(job, points)))
    return out


def write(ks: list, problem, out: Path) -> tuple[Path, Path]:
    py_path, c_path = out / "answer.py", out / "answer.c"
    py_path.write_text(python_text(ks, problem))
    c_path.write_text(c_text(ks, problem))
    return py_path, c_path


def summary(ks: list) -> list[str]:
    """One line per kernel: its worst scaled error in each language and where; a kernel over the
    bound is said in capitals."""
    lines = []
    for k in ks:
        f = k.figures
        where = audit._fmt_point(f["args"], f["worst_at"])
        head = "KERNEL OVER THE BOUND" if k.over else "kernel"
        lines.append(f"  {head} {k.name}({', '.join(a.name for a in k.args)}): worst ulp/max(1, κ) "
                     f"Python {f['python']['worst_scaled']:.3g}, C {f['c']['worst_scaled']:.3g} (bound {kn.BOUND:g}) "
                     f"on {f['points']} points, at {where}"
                     + (f"; outside its domain: {'; '.join(f['outside'][:2])}" if f.get("outside") else ""))
    return lines
