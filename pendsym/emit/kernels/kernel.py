"""The kernel of a Result: its form chosen, measured as emitted, and built once.

:func:`kernel_of` is the spine: the choice of form (:mod:`.choice`), the sample
(:mod:`.sampling`), the measurement of the emitted Python and of the naive form
(:mod:`.measure`, :mod:`.compile`); the :class:`Kernel` record holds plain data only.
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp
from sympy.core.function import AppliedUndef

from ...result import KernelArg, Result
from .choice import HEADROOM, choose_form, naive_form
from .compile import emitted_py
from .leaves import hard_argument
from .limits import accepted_domain, beyond
from .measure import BOUND, Accuracy, Naive, measure, measure_naive, references
from .rules import SMALL_LAST
from .sampling import kernel_sample

CONTRACT = "docs/kernel-accuracy.md"


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
    notes: tuple[str, ...] = ()      # the pieces of a stable form, with their measured errors
    naive: Naive | None = None
    reference: tuple = ()            # (50-digit value, κ) at each sample point, for the C measurement
    domain: tuple = ()               # the accepted [lo, hi] of each argument (default: the declared one)

    def docstring(self) -> str:
        """The kernel's own figures: source, domain, form, measured errors, the naive form's;
        the contract they are measured against is stated once, in docs/kernel-accuracy.md."""
        dom = "; ".join(f"{a.name} in [{a.lo:g}, {a.hi:g}] {a.unit}" for a in self.args)
        ext = [f"{a.name} down to {lo:g}" for a, (lo, _) in zip(self.args, self.domain) if lo < a.lo]
        ext += [f"{a.name} up to {hi:g}" for a, (_, hi) in zip(self.args, self.domain) if hi > a.hi]
        if ext:
            dom += f" (accepted, and measured by make audit, {', '.join(ext)}: the limit)"
        lines = [f"{self.doc} — {self.result_id} ({self.ref}).", f"Domain: {dom}.", f"Form: rewrite rule '{self.rule}'."]
        lines += [f"  {n}" for n in self.notes]
        measured = [f"{lang} {acc.max_ulp:.3g} ulp ({acc.max_scaled:.3g} scaled)"
                    for lang, acc in (("Python", self.py_accuracy), ("C", self.c_accuracy)) if acc]
        if measured:
            points = (self.py_accuracy or self.c_accuracy).points
            lines.append(f"Measured error on {points} points: {', '.join(measured)}.")
        if self.naive:
            nv = self.naive.accuracy
            lines.append(f"Naive {self.naive.form} form on the same points: {nv.max_ulp:.3g} ulp "
                         f"({nv.max_scaled:.3g} scaled); over the bound: {self.naive.fails}.")
        lines.append(f"Contract (bound, κ, sampling, domain): {CONTRACT}; scaled = ulp / max(1, κ).")
        return "\n".join(lines)


def kernel_name(result_id: str) -> str:
    return result_id.split(".", 1)[1].replace(".", "_")


def closed_form(expr: sp.Expr) -> bool:
    return not expr.has(sp.Integral) and not expr.atoms(AppliedUndef) and expr.free_symbols != set()


def _arguments(result: Result) -> tuple[KernelArg, ...]:
    """The declared arguments the derived form uses (an error if it uses an undeclared one)."""
    free = {s.name for s in result.derived.free_symbols}
    names = {a.name for a in result.spec.kernel.args}
    if not free <= names:
        raise ValueError(f"{result.id}: kernel arguments miss {sorted(free - names)}")
    return tuple(a for a in result.spec.kernel.args if a.name in free)


def kernel_of(result: Result) -> Kernel | None:
    """The kernel of a Result whose Spec asks for one and whose derived form is closed; its
    Python accuracy measured on the function as emitted, its naive form's on the same points
    (the C accuracy is measured where the memoir's C file is compiled)."""
    spec = result.spec
    if spec.kernel is None or not closed_form(result.derived):
        return None
    if getattr(spec.kernel, "form", None) is not None:      # a form the derivation supplies (.supplied)
        from .supplied import supplied_kernel
        return supplied_kernel(result)
    args = _arguments(result)
    name = kernel_name(result.id)
    choice = choose_form(result.derived, args, name)
    pts = kernel_sample(result.derived, args, name)
    truths = references(result.derived, args, pts)
    py = measure(emitted_py(name, args, choice.form), result.derived, args, pts, truths)
    form, naive_expr = naive_form(result, args)
    hard = hard_argument(result.derived, args)
    naive = measure_naive(naive_expr, form, result.derived, args, pts, args.index(hard) if hard is not None else 0)
    domain = accepted_domain(result.derived, args, name, choice.form)
    rule, expr = choice.rule, choice.form
    if hard is not None and domain == tuple((a.lo, a.hi) for a in args):
        # the limit at 0 is lost to a subnormal power: the small factors last, where that holds it
        x = next(s for s in result.derived.free_symbols if s.name == hard.name)
        last = SMALL_LAST(choice.form, x)
        if last != choice.form and (dom := accepted_domain(result.derived, args, name, last)) != domain:
            acc = measure(emitted_py(name, args, last), result.derived, args, pts, truths)
            if acc.max_scaled <= max(py.max_scaled, HEADROOM * BOUND):
                rule, expr, py, domain = f"{rule}+{SMALL_LAST.name}", last, acc, dom
    if hard is not None and (far := beyond(result.derived, args, name, expr, domain)) is not None:
        # up to +inf where the limit is finite: the far form above the declared hi (no change below it)
        expr, domain = far
        rule = f"{rule}+far form above {hard.name} = {hard.hi:g}"
        py = measure(emitted_py(name, args, expr, domain), result.derived, args, pts, truths)
    return Kernel(name, result.id, args, expr, rule, spec.kernel.doc or spec.title, spec.source.ref(),
                  py_accuracy=py, notes=choice.notes, naive=naive, reference=truths, domain=domain)
