"""Supplied forms: a kernel whose form the derivation supplies, instead of one chosen among the rewrites of
the derived expression (:mod:`.choice`), and the helper functions such a form may call.

Some forms cannot be reached by rewriting: a closed form in Bessel functions of two large, nearly equal
arguments loses every digit as they grow (their cross products cancel), and the stable form evaluates the
cross products by another route (an asymptotic expansion, a Taylor series of the ODE in the gap between the
arguments).  Such a form is still held to the same contract (docs/kernel-accuracy.md): it is measured, as
emitted, against the Result's *derived* expression at 50 digits, on the kernel's own sample, in Python and in
C; the engine only does not choose it.

* :class:`SuppliedKernelSpec`: a :class:`~pendsym.result.KernelSpec` with the form (a SymPy expression in the
  kernel's arguments, which may call the helpers below), the name of its rule and notes for the docstring.
* Helpers: SymPy functions that print as calls (``pendsym_<name>`` in C, ``_pendsym_<name>`` in Python) of
  functions printed once per file, before the kernels (:func:`helper_definitions`).  Each helper is written
  in both languages here, from the formulas its docstring cites, and is measured through the kernels that
  call it.  :class:`QuotientLow` is the double-double residual of a quotient (fma in C, Dekker's product in
  Python); :class:`BesselCross` the cross products Y_a(x_0)J_b(x_1) − J_a(x_0)Y_b(x_1) of orders 0 and 1.
* Bessel functions: no helper calls them since session 13 (``bessel_cross`` continues its Taylor series in steps
  where it called C's POSIX ``j0`` … ``y1`` and scipy's ``jv``, ``yv``); :data:`NEEDS_XOPEN` and
  :func:`c_preamble` remain for a helper that would (a C file must then define ``_XOPEN_SOURCE``; never scipy's
  Cephes ``j0`` … ``y1``: docs/kernel-accuracy.md, "Bessel functions").
"""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from typing import Callable, Sequence

import sympy as sp

from ...result import KernelArg, KernelSpec, Result
from .measure import BOUND, Accuracy, Naive, errors, measure, references
from .sampling import kernel_sample


@dataclass(frozen=True)
class SuppliedKernelSpec(KernelSpec):
    """A KernelSpec whose form is given: ``form`` in the kernel's arguments (helpers allowed), ``rule`` its
    name in the docstring, ``notes`` the lines that say how it is built and why."""

    form: sp.Expr | None = None
    rule: str = "supplied form"
    notes: tuple[str, ...] = ()


# ---------------------------------------------------------------- helpers
class Helper(sp.Function):
    """A call of a helper function printed once per file: ``name`` in C (with the prefix ``pendsym_``),
    ``_pendsym_name`` in Python; its definitions in :data:`DEFINITIONS`."""

    name = ""

    def _ccode(self, printer) -> str:
        return f"pendsym_{self.name}({', '.join(printer._print(a) for a in self.args)})"

    def _pythoncode(self, printer) -> str:
        return f"_pendsym_{self.name}({', '.join(printer._print(a) for a in self.args)})"

    def _numpycode(self, printer) -> str:
        return self._pythoncode(printer)


class QuotientLow(Helper):
    """QuotientLow(a, b, hi) = (a − b·hi)/b for hi = a/b rounded: the low part of the quotient as a
    double-double hi + lo (the residual a − b·hi is exact: fma in C, Dekker's exact product in Python)."""

    nargs = 3
    name = "quotient_low"


class RootQuotient(Helper):
    """RootQuotient(u, t, part) = u/(1 + √(1 + t)) as a double-double: part 0 the high, part 1 the low part (the sum
    1 + t by two-sum, the root corrected by its exact residual, the quotient by double-double division)."""

    nargs = 3
    name = "root_quotient"


class BesselCross(Helper):
    """BesselCross(a, b, x_0, l_0, h, l_h) = (π√(x_0x_1)/2)(Y_a(x_0)J_b(x_1) − J_a(x_0)Y_b(x_1)), a, b ∈ {0, 1},
    for x_0 given as the double-double x_0 + l_0 and x_1 = x_0 + h given by its gap, the double-double h + l_h > 0
    (not by x_1: the gap is what the cross product depends on, and x_0 + h rounded loses it); each route takes the
    low parts to first order.  Today's J, Y (the Wronskian
    J_1Y_0 − J_0Y_1 = 2/(πx)).  Two routes, by x_0:

    * x_0 ≥ 25: Hankel's asymptotic expansion, J_n = √(2/(πx))(P cos χ − Q sin χ), Y_n = √(2/(πx))(P sin χ +
      Q cos χ), χ = x − (2n + 1)π/4 (Abramowitz–Stegun 9.2.5–9.2.10; 19 terms hold 1e-22 at x = 25): the
      cross product is (PP' + QQ') sin Δ + (QP' − PQ') cos Δ with Δ = −h − (a − b)π/2, no cancellation, summed
      as sin Δ + [(PP' − 1 + QQ') sin Δ + (QP' − PQ') cos Δ] (P − 1 and Q are O(1/x)), so that its error is
      libm's sin or cos of h and little more;
    * otherwise the Taylor series of c(x) = Y_a(x_0)J_b(x) − J_a(x_0)Y_b(x), a solution of Bessel's equation of
      order b, from c(x_0), c'(x_0) (Wronskians, 2/(πx_0): exact) by the recurrence of its coefficients, in
      double-double, in steps of at most half the centre (the radius is the centre: terms fall as 2^−m at least):
      one step for h ≤ x_0/2, else c and c' carried from centre to centre, the last step landing on x_1 through
      the remaining gap (double-double), ⌈log(x_1/x_0)/log 1.5⌉ steps; each step until two terms fall below
      1e-20·(x_0/x_1)² (an error grows against the recessive solution as (x/x_0)²).  Until session 12 the route for
      h > x_0/2 was the library's Bessel functions (4–10.8 scaled ulp in the kernels); the steps hold ≤ 0.9 ulp up
      to q = 1e8 in the rhombus kernels' arguments (derivations/haag1935/ch9_holes/kernels.py, "Domain").
    """

    nargs = 6
    name = "bessel_cross"


from .helper_text import _c_definitions, _py_definitions  # noqa: E402  (the helpers' text)

HELPERS: tuple[type[Helper], ...] = (QuotientLow, RootQuotient, BesselCross)


NEEDS = {"quotient_low": ("dd",), "root_quotient": ("dd",), "bessel_cross": ("dd",)}    # blocks printed before
NEEDS_XOPEN: frozenset[str] = frozenset()        # helpers that call POSIX j0 … y1 (none since session 13)


@functools.lru_cache(maxsize=None)
def _definitions(lang: str) -> dict[str, str]:
    return _c_definitions() if lang == "c" else _py_definitions()


def helpers_called(exprs: Sequence[sp.Basic]) -> tuple[str, ...]:
    """The names of the helpers the expressions call, in the order of :data:`HELPERS`."""
    found = {h.name for e in exprs for h in HELPERS if e.atoms(h)}
    return tuple(h.name for h in HELPERS if h.name in found)


def _blocks(exprs: Sequence[sp.Basic]) -> tuple[str, ...]:
    """The blocks to print: the helpers called, each after the blocks it needs, each once."""
    out: list[str] = []
    for name in helpers_called(exprs):
        out += [b for b in (*NEEDS.get(name, ()), name) if b not in out]
    return tuple(out)


def helper_definitions(exprs: Sequence[sp.Basic], lang: str) -> list[str]:
    """The definitions (C or Python) of the helpers the expressions call, each once: nothing for forms that call
    none, so other files are unchanged."""
    return [_definitions(lang)[name] for name in _blocks(exprs)]


def c_preamble(exprs: Sequence[sp.Basic]) -> str:
    """What a C file must define before its includes: ``_XOPEN_SOURCE`` where a helper calls POSIX j0 … y1
    (not C99: ``cc -std=c99`` declares them only so)."""
    return "#define _XOPEN_SOURCE 700" if set(helpers_called(exprs)) & NEEDS_XOPEN else ""


def _naive(result: Result, args: Sequence[KernelArg], points, truths) -> Naive:
    """The derived form in double, scipy's jv, yv at the rounded arguments: the form a user would type."""
    syms = [next(s for s in result.derived.free_symbols if s.name == a.name) for a in args]
    fn = sp.lambdify(syms, result.derived, modules=[{"besselj": _scipy("jv"), "bessely": _scipy("yv")}, "math"])
    errs = list(errors(fn, result.derived, args, points, truths))
    fin = [e for e in errs if math.isfinite(e[1])]
    worst = max(fin, key=lambda e: e[2], default=None)
    acc = Accuracy(len(points), math.inf if len(fin) < len(errs) else round(max(e[1] for e in errs), 2),
                   math.inf if len(fin) < len(errs) else round(worst[2], 2), worst[0] if worst else ())
    over = [e for e in errs if e[2] > BOUND]
    where = "nowhere on the sample" if not over else (
        f"{len(over)} of {len(errs)} points, " + ", ".join(
            f"{a.name} in [{min(e[0][i] for e in over):.3g}, {max(e[0][i] for e in over):.3g}]"
            for i, a in enumerate(args)))
    return Naive("as derived (scipy jv, yv)", acc, where)


def _scipy(name: str) -> Callable:
    from scipy import special
    return getattr(special, name)


def supplied_kernel(result: Result):
    """The Kernel of a Result whose KernelSpec supplies its form: measured as emitted (Python, helpers included)
    on the kernel's sample against the derived expression; the accepted domain is the declared box."""
    from .kernel import Kernel, _arguments, kernel_name
    spec = result.spec.kernel
    args = _arguments(result)
    name = kernel_name(result.id)
    form = spec.form
    free = {s.name for s in form.free_symbols}
    if not free <= {a.name for a in args}:
        raise ValueError(f"{result.id}: the supplied form uses {sorted(free - {a.name for a in args})}")
    pts = kernel_sample(result.derived, args, name)
    truths = references(result.derived, args, pts)
    from .compile import emitted_py          # (compile imports this module's helper_definitions)
    py = measure(emitted_py(name, args, form), result.derived, args, pts, truths)
    return Kernel(name, result.id, args, form, spec.rule, spec.doc or result.spec.title, result.spec.source.ref(),
                  py_accuracy=py, notes=spec.notes, naive=_naive(result, args, pts, truths), reference=truths,
                  domain=tuple((a.lo, a.hi) for a in args))
