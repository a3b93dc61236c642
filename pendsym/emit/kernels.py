"""Kernels: Python (math only) and C99 (libm only) functions for every closed form.

A Result whose Spec asks for a kernel is emitted from its derived form.  The
form is chosen among small named rewrite rules by measured accuracy in double
precision against 50-digit mpmath on a fixed, seeded sample of the declared
domain (its corners and hard points included); the printers subclass SymPy's
Python and C99 printers, and Jinja only lays out the files.
"""
from __future__ import annotations

import ctypes
import math
import random
import re
import subprocess
import tempfile
from dataclasses import dataclass
from pathlib import Path
from typing import Callable, Sequence

import mpmath as mp
import sympy as sp
from sympy.printing.c import C99CodePrinter
from sympy.printing.pycode import PythonCodePrinter

from ..result import KernelArg, Result

# ----------------------------------------------------------------- rewrite rules


def _sin_basis(e: sp.Expr) -> sp.Expr:
    """Even powers of cos → powers of (1 − sin²), then factor (good near kt = 0)."""
    w = sp.Wild("w")
    e = sp.expand(sp.expand_trig(e))
    e = e.replace(lambda x: x.is_Pow and x.base.func == sp.cos and x.exp.is_even and x.exp > 0,
                  lambda x: (1 - sp.sin(x.base.args[0]) ** 2) ** (x.exp // 2))
    return sp.factor(sp.expand(e))


def _cos_basis(e: sp.Expr) -> sp.Expr:
    """Even powers of sin → powers of (1 − cos²), then factor."""
    e = sp.expand(sp.expand_trig(e))
    e = e.replace(lambda x: x.is_Pow and x.base.func == sp.sin and x.exp.is_even and x.exp > 0,
                  lambda x: (1 - sp.cos(x.base.args[0]) ** 2) ** (x.exp // 2))
    return sp.factor(sp.expand(e))


SERIES_ORDER = 44          # orders kept near a removable zero of the time argument
SERIES_PHASE = sp.Rational(7, 20)  # the series is used for k·t below this phase


def near_zero_series(e: sp.Expr, args: Sequence[KernelArg]) -> tuple[sp.Expr, sp.Expr] | None:
    """(series, phase): the Taylor series in t, to be used where the phase k·t is small.

    Forms such as kt − sin kt cos kt cancel as t → 0; their series does not.
    With 44 orders kept, the truncation at k·t = 0.35 is below 2e-18 relative
    to a leading term of order ≤ 5.
    """
    by = {x.name: x for x in e.free_symbols}
    if "t" not in by or not any(a.name == "t" and a.lo == 0 for a in args):
        return None
    t = by["t"]
    ser = sp.series(e, t, 0, SERIES_ORDER).removeO()
    if ser == 0:
        return None
    phase = by["k"] * t if "k" in by else t
    # rational coefficients become 20-digit floats (exact to double), so no huge integer literals
    return sp.horner(sp.N(sp.collect(sp.expand(ser), t), 20), wrt=t), phase


REWRITES: tuple[tuple[str, Callable[[sp.Expr], sp.Expr]], ...] = (
    ("as-derived", lambda e: e),
    ("factor", sp.factor),
    ("expand-trig", lambda e: sp.factor(sp.expand(sp.expand_trig(e)))),
    ("sin-basis", _sin_basis),
    ("cos-basis", _cos_basis),
    ("horner", lambda e: sp.horner(sp.expand(e)) if e.is_polynomial() else e),
    # 1 − cos x cancels for small x: cos x = 1 − 2 sin²(x/2)
    ("half-angle", lambda e: sp.factor(sp.expand(e.replace(sp.cos, lambda x: 1 - 2 * sp.sin(x / 2) ** 2)))),
)

# ----------------------------------------------------------------- printers


class KernelC(C99CodePrinter):
    """C99 printer: small integer powers as products, no pow() for them; π as a literal
    (M_PI is POSIX, not C99)."""

    def _print_Pi(self, expr):
        return "3.14159265358979323846264338327950288"

    def _print_Integer(self, expr):
        # a C integer literal overflows past 64 bits: print large ones as doubles
        return super()._print_Integer(expr) if abs(int(expr)) < 2**53 else repr(float(expr))

    def _print_Pow(self, expr):
        b, e = expr.as_base_exp()
        if e.is_Integer and 1 < abs(int(e)) <= 8:
            prod = "*".join([f"({self._print(b)})"] * abs(int(e)))
            return f"(1.0/({prod}))" if e < 0 else f"({prod})"
        return super()._print_Pow(expr)


class KernelPy(PythonCodePrinter):
    """Python printer for math-only kernels (no SymPy at import)."""


def _body(expr: sp.Expr, printer, decl: str, end: str) -> tuple[list[str], str]:
    subs, (red,) = sp.cse([expr], symbols=sp.numbered_symbols("x_"), optimizations="basic")
    lines = [f"{decl}{printer.doprint(s)} = {printer.doprint(v)}{end}" for s, v in subs]
    return lines, printer.doprint(red)


def identifier(name: str) -> str:
    """A C and Python identifier for a symbol's name (p' → p_prime)."""
    out = re.sub(r"\W", "_", name.replace("'", "_prime"))
    return out if out[:1].isalpha() else "a_" + out


def _printable(k: "Kernel") -> sp.Expr:
    """The kernel's expression with every argument renamed to its identifier."""
    by = {x.name: x for x in k.expr.free_symbols}
    return k.expr.xreplace({by[a.name]: sp.Symbol(identifier(a.name), real=True) for a in k.args if a.name in by})


def c_function(k: "Kernel") -> tuple[str, str]:
    """(prototype, definition) of a kernel in C99."""
    pr = KernelC()
    args = ", ".join(f"double {identifier(a.name)}" for a in k.args)
    proto = f"double {k.name}({args})"
    lines, ret = _body(_printable(k), pr, "const double ", ";")
    return proto, proto + "\n{\n" + "".join(f"    {ln}\n" for ln in lines) + f"    return {ret};\n}}\n"


def py_function(k: "Kernel") -> str:
    pr = KernelPy(settings={"fully_qualified_modules": True})
    lines, ret = _body(_printable(k), pr, "", "")
    args = ", ".join(identifier(a.name) for a in k.args)
    doc = k.docstring().replace("\n", "\n    ")
    body = "".join(f"    {ln}\n" for ln in lines)
    return f'def {k.name}({args}):\n    """{doc}\n    """\n{body}    return {ret}\n'


# ----------------------------------------------------------------- kernels


@dataclass(frozen=True)
class Accuracy:
    points: int
    max_ulp: float           # largest error in units in the last place of the true value
    max_scaled: float        # largest error / max(1, condition number), in ulp
    worst_at: tuple          # the arguments of the largest scaled error


@dataclass(frozen=True)
class Kernel:
    name: str
    result_id: str
    args: tuple[KernelArg, ...]
    expr: sp.Expr
    rule: str
    doc: str
    ref: str
    py_accuracy: Accuracy | None = None
    c_accuracy: Accuracy | None = None

    def docstring(self) -> str:
        dom = "; ".join(f"{a.name} in [{a.lo:g}, {a.hi:g}] {a.unit}" for a in self.args)
        lines = [f"{self.doc} — {self.result_id} ({self.ref}).", f"Domain: {dom}.", f"Form: rewrite rule '{self.rule}'."]
        for lang, acc in (("Python", self.py_accuracy), ("C", self.c_accuracy)):
            if acc:
                lines.append(f"Measured {lang} error on {acc.points} points: {acc.max_ulp:.3g} ulp, "
                             f"{acc.max_scaled:.3g} ulp × max(1, condition number).")
        worst = max((a.max_ulp for a in (self.py_accuracy, self.c_accuracy) if a), default=0.0)
        if worst > 4:
            lines.append("Beyond 4 ulp only where the problem is ill-conditioned (near zeros of the function, "
                         "large k·t): the rounding of the inputs alone costs condition number × eps there.")
        return "\n".join(lines)


def kernel_name(result_id: str) -> str:
    return result_id.split(".", 1)[1].replace(".", "_")


def closed_form(expr: sp.Expr) -> bool:
    from sympy.core.function import AppliedUndef
    return not expr.has(sp.Integral) and not expr.atoms(AppliedUndef) and expr.free_symbols != set()


def sample_points(args: Sequence[KernelArg], seed: str, n: int = 160) -> list[tuple[float, ...]]:
    """Seeded points of the domain: its corners, hard points near 0, and random interior points."""
    rng = random.Random(seed)

    def draw(a: KernelArg) -> float:
        if a.log and a.lo > 0:
            return math.exp(rng.uniform(math.log(a.lo), math.log(a.hi)))
        return rng.uniform(a.lo, a.hi)

    def special(a: KernelArg) -> list[float]:
        vals = [a.lo, a.hi]
        if a.lo <= 0 <= a.hi and not a.log:
            vals += [v for v in (1e-9, 1e-4, 0.5 * math.pi, math.pi, 3.0) if a.lo <= v <= a.hi]
        return vals
    pts = []
    corner_sets = [special(a) for a in args]
    for i in range(min(64, math.prod(len(c) for c in corner_sets))):
        idx, p = i, []
        for c in corner_sets:
            p.append(c[idx % len(c)])
            idx //= len(c)
        pts.append(tuple(p))
    pts += [tuple(draw(a) for a in args) for _ in range(n)]
    return sorted(set(pts), key=pts.index)


def _reference(expr: sp.Expr, syms) -> tuple[Callable, Callable]:
    f = sp.lambdify(syms, expr, modules="mpmath")
    grads = [sp.lambdify(syms, sp.diff(expr, s), modules="mpmath") for s in syms]

    def cond(*xs):
        v = f(*xs)
        if v == 0:
            return mp.inf
        return sum(abs(x * g(*xs)) for x, g in zip(xs, grads)) / abs(v)
    return f, cond


def measure(fn: Callable[..., float], expr: sp.Expr, args: Sequence[KernelArg], points) -> Accuracy:
    """ulp error of a double kernel against 50-digit mpmath of expr at the points."""
    by = {s.name: s for s in expr.free_symbols}
    syms = [by.get(a.name, sp.Symbol(a.name)) for a in args]
    f, cond = _reference(expr, syms)
    worst_ulp = worst_scaled = 0.0
    worst_at: tuple = ()
    with mp.workdps(50):
        for p in points:
            xs = [mp.mpf(x) for x in p]
            true = f(*xs)
            got = fn(*p)
            if not math.isfinite(got):
                return Accuracy(len(points), math.inf, math.inf, p)
            if true == 0:
                err_ulp = 0.0 if got == 0 else abs(got) / math.ulp(0.0)
                scaled = 0.0 if abs(got) < 1e-300 else math.inf
            else:
                err_ulp = float(abs(mp.mpf(got) - true) / mp.mpf(math.ulp(float(true))))
                scaled = err_ulp / max(1.0, float(cond(*xs)))
            worst_ulp = max(worst_ulp, err_ulp)
            if scaled > worst_scaled:
                worst_scaled, worst_at = scaled, p
    return Accuracy(len(points), round(worst_ulp, 2), round(worst_scaled, 2), worst_at)


def py_callable(expr: sp.Expr, args: Sequence[KernelArg]) -> Callable[..., float]:
    by = {s.name: s for s in expr.free_symbols}
    syms = [by.get(a.name, sp.Symbol(a.name)) for a in args]
    return sp.lambdify(syms, expr, modules="math")


def choose_form(expr: sp.Expr, args: Sequence[KernelArg], seed: str) -> tuple[str, sp.Expr, Accuracy]:
    """The rewrite rule whose Python evaluation is the most accurate (ties: rule order)."""
    pts = sample_points(args, seed, 60)
    best = None
    ser = near_zero_series(expr, args)
    for name, rule in REWRITES:
        try:
            cand = rule(expr)
        except Exception:  # a rule that does not apply is skipped
            continue
        if not _same_numerically(cand, expr, args, seed):
            continue
        variants = [(name, cand)]
        if ser is not None:
            variants.append((name + "+series-near-t=0",
                             sp.Piecewise((ser[0], ser[1] < SERIES_PHASE), (cand, True))))
        for vname, v in variants:
            acc = measure(py_callable(v, args), expr, args, pts)
            if best is None or acc.max_scaled < best[2].max_scaled:
                best = (vname, v, acc)
    return best


def _same_numerically(a, b, args, seed) -> bool:
    """A rewrite must not change the function: compare at 8 interior points in double."""
    fa, fb = (py_callable(x, args) for x in (a, b))
    for p in sample_points(args, seed, 8)[-8:]:
        va, vb = fa(*p), fb(*p)
        if abs(va - vb) > 1e-9 * max(1.0, abs(vb)):
            return False
    return True


def kernel_of(result: Result) -> Kernel | None:
    spec = result.spec
    if spec.kernel is None or not closed_form(result.derived):
        return None
    names = {a.name for a in spec.kernel.args}
    if not {s.name for s in result.derived.free_symbols} <= names:
        missing = {s.name for s in result.derived.free_symbols} - names
        raise ValueError(f"{result.id}: kernel arguments miss {sorted(missing)}")
    args = tuple(a for a in spec.kernel.args if a.name in {s.name for s in result.derived.free_symbols})
    name = kernel_name(result.id)
    rule, expr, acc = choose_form(result.derived, args, name)
    k = Kernel(name, result.id, args, expr, rule, spec.kernel.doc or spec.title, spec.source.ref())
    full = measure(py_callable(expr, args), result.derived, args, sample_points(args, name))
    return Kernel(**{**k.__dict__, "py_accuracy": full})


# ----------------------------------------------------------------- C compilation (tests, derive)


def compile_c(c_text: str, workdir: Path) -> ctypes.CDLL:
    """Compile one C file into a shared library with the system compiler and load it."""
    src = workdir / "k.c"
    lib = workdir / "k.so"
    src.write_text(c_text)
    done = subprocess.run(["cc", "-std=c99", "-O2", "-fPIC", "-shared", "-o", str(lib), str(src), "-lm"],
                          capture_output=True, text=True)
    if done.returncode:
        raise RuntimeError(f"cc failed: {done.stderr.strip()[:2000]}")
    return ctypes.CDLL(str(lib))


def c_callable(lib: ctypes.CDLL, k: Kernel) -> Callable[..., float]:
    fn = getattr(lib, k.name)
    fn.restype = ctypes.c_double
    fn.argtypes = [ctypes.c_double] * len(k.args)
    return fn


def with_c_accuracy(kernels: Sequence[Kernel], results: dict[str, Result], c_text_of: Callable) -> list[Kernel]:
    """Measure the compiled C kernels and record their accuracy."""
    out = []
    with tempfile.TemporaryDirectory() as d:
        lib = compile_c(c_text_of(kernels), Path(d))
        for k in kernels:
            acc = measure(c_callable(lib, k), results[k.result_id].derived, k.args, sample_points(k.args, k.name))
            out.append(Kernel(**{**k.__dict__, "c_accuracy": acc}))
    return out
