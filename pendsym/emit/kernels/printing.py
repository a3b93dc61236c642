"""Printing: SymPy's C99 and Python printers, subclassed, print the codegen AST of
:mod:`.plan`; Jinja (templates/function.*.j2) lays a function out around what they print.

A function is a ``FunctionDefinition`` (:func:`function_ast`); its prototype and its body
are printed by :class:`KernelC` or :class:`KernelPy`.  Every expression in a statement is
printed as the printer's ``doprint`` prints it alone (C's conditional operator keeps
SymPy's own line breaks), and statements are indented four spaces a level.  A call of a
shared part (:mod:`.sharing`) is an applied undefined function: ``static`` in C, private
(``_name``) in Python.
"""
from __future__ import annotations

import functools
import keyword
import re
from dataclasses import dataclass
from typing import Sequence

import sympy as sp
from sympy.codegen.ast import (CodeBlock, FunctionDefinition, FunctionPrototype, NoneToken,
                               Variable, real, value_const)
from sympy.codegen.cnodes import static
from sympy.printing.c import C99CodePrinter
from sympy.printing.pycode import PythonCodePrinter

from ...result import KernelArg
from ..layout import lay_out
from .plan import If, body

INDENT = "    "


def identifier(name: str) -> str:
    """A C and Python identifier for a symbol's name (p' → p_prime)."""
    out = re.sub(r"\W", "_", name.replace("'", "_prime"))
    out = out if out[:1].isalpha() else "a_" + out
    return out + "_" if keyword.iskeyword(out) else out          # lambda → lambda_


def printable(expr: sp.Expr, args: Sequence[KernelArg]) -> sp.Expr:
    """expr with every argument renamed to its identifier (a real Symbol)."""
    by = {x.name: x for x in expr.free_symbols}
    return expr.xreplace({by[a.name]: parameter(a) for a in args if a.name in by})


def parameter(a: KernelArg) -> sp.Symbol:
    """The Symbol of a kernel argument in printed code."""
    return sp.Symbol(identifier(a.name), real=True)


class _Statements:
    """Statement printing shared by the two printers: codegen statements through the printer's
    own ``_print_*`` methods, expressions as ``doprint`` prints them alone."""

    def doprint(self, expr, assign_to=None):
        if isinstance(expr, (CodeBlock, FunctionPrototype, If)):
            return self._print(expr)
        return super().doprint(expr, assign_to)

    def _expr(self, e: sp.Basic) -> str:
        return super().doprint(e)

    def _print_Grouped(self, expr) -> str:
        return "(" + self._print(expr.args[0]) + ")"

    def _print_Magnitude(self, expr) -> str:
        return f"{self._abs}({self._print(expr.args[0])})"

    def _print_Select(self, expr) -> str:
        d, b, c = (self._print(a) for a in expr.args)
        return f"(({b}) if ({d}) > 0 else ({c}))" if self._abs == "abs" else f"(({d}) > 0 ? ({b}) : ({c}))"

    def _print_CodeBlock(self, block, depth: int = 1) -> str:
        lines = []
        for s in block.args:
            if isinstance(s, If):
                lines.append(self._print(s, depth=depth))
            else:
                text = self._print(s)
                if text:
                    lines.append(INDENT * depth + self._statement(text))
        return "\n".join(lines)

    def _print_Assignment(self, a) -> str:
        return f"{self._expr(a.lhs)} = {self._expr(a.rhs)}"

    def _print_Return(self, r) -> str:
        return f"return {self._expr(r.args[0])}"

    def _print_If(self, node, depth: int = 1) -> str:
        pad, out = INDENT * depth, []
        branches = node.branches
        for i, (cond, block) in enumerate(branches):
            last = i == len(branches) - 1
            out.append(pad + self._head(i, last and cond == sp.true, self._expr(cond)))
            out.append(self._print(block, depth=depth + 1))
        out += [pad + t for t in self._tail()]
        return "\n".join(out)


class KernelC(_Statements, C99CodePrinter):
    """C99 printer: small integer powers as products, no pow() for them; π as a literal
    (M_PI is POSIX, not C99); a Grouped leaf in parentheses; a shared part a static function."""

    _abs = "fabs"

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

    def _print_AppliedUndef(self, expr):
        return f"{expr.func.__name__}({', '.join(self._print(a) for a in expr.args)})"

    def _print_Declaration(self, decl) -> str:
        var = decl.variable
        head = f"{'const ' if value_const in var.attrs else ''}{self._print(var.type)} {self._print(var.symbol)}"
        return head if isinstance(var.value, NoneToken) else f"{head} = {self._expr(var.value)}"

    def _print_FunctionPrototype(self, proto) -> str:
        return ("static " if static in proto.attrs else "") + super()._print_FunctionPrototype(proto)

    def _statement(self, text: str) -> str:
        return text + ";"

    def _head(self, i: int, otherwise: bool, cond: str) -> str:
        return f"if ({cond}) {{" if i == 0 else "} else {" if otherwise else f"}} else if ({cond}) {{"

    def _tail(self) -> list[str]:
        return ["}"]


class KernelPy(_Statements, PythonCodePrinter):
    """Python printer for math-only kernels (no SymPy at import); a Grouped leaf in
    parentheses; a shared part a private function."""

    _abs = "abs"

    def __init__(self, settings=None):
        super().__init__({"fully_qualified_modules": True, **(settings or {})})

    def _print_AppliedUndef(self, expr):
        return f"_{expr.func.__name__}({', '.join(self._print(a) for a in expr.args)})"

    def _print_Declaration(self, decl) -> str:
        var = decl.variable
        return "" if isinstance(var.value, NoneToken) else f"{self._print(var.symbol)} = {self._expr(var.value)}"

    def _print_FunctionPrototype(self, proto) -> str:
        name = ("_" if static in proto.attrs else "") + str(proto.name)
        return f"def {name}({', '.join(self._print(p.symbol) for p in proto.parameters)}):"

    def _statement(self, text: str) -> str:
        return text

    def _head(self, i: int, otherwise: bool, cond: str) -> str:
        return f"if {cond}:" if i == 0 else "else:" if otherwise else f"elif {cond}:"

    def _tail(self) -> list[str]:
        return []


PRINTERS = {"c": KernelC, "py": KernelPy}


@dataclass(frozen=True)
class Function:
    """A function to emit: a kernel, or a part that several kernels share (`callers`: their
    names; such a part is ``static`` in C, private in Python)."""

    name: str
    params: tuple[sp.Symbol, ...]
    expr: sp.Expr
    callers: tuple[str, ...] = ()
    domain: tuple[tuple[float, float], ...] = ()   # the accepted [lo, hi] of each parameter (a kernel's)


def prototype_ast(f: Function) -> FunctionPrototype:
    """The codegen AST of f's prototype: a double of doubles, ``static`` for a shared part."""
    return FunctionPrototype(real, f.name, [Variable(p, type=real) for p in f.params],
                             attrs=(static,) if f.callers else ())


def function_ast(f: Function) -> FunctionDefinition:
    """The codegen AST of a function returning f.expr (its statements: :func:`.plan.body`)."""
    return FunctionDefinition.from_FunctionPrototype(prototype_ast(f), body(f.expr))


@dataclass(frozen=True)
class Printed:
    """A function as printed: the prototype line, the test of its arguments and the body's statements."""

    prototype: str
    body: str
    guard: str = ""


def _bound(v: float, lang: str = "py") -> str:
    if v in (float("inf"), float("-inf")):         # an argument accepted up to +inf (its limit there)
        return ("-" if v < 0 else "") + ("math.inf" if lang == "py" else "INFINITY")
    return repr(float(v))


def guard(f: Function, lang: str) -> str:
    """The test of each argument against its accepted domain, the same in both languages (the
    behaviour outside the domain, docs/kernel-accuracy.md): a NaN or a value outside [lo, hi]
    is a domain error, ValueError in Python (naming the argument and the domain), NaN with
    errno = EDOM in C."""
    out = []
    for p, (lo, hi) in zip(f.params, f.domain):
        name = PRINTERS[lang]()._print(p)
        where = f"[{lo:g}, {hi:g}]"
        if lang == "py":
            out += [f"{INDENT}if not {_bound(lo)} <= {name} <= {_bound(hi)}:",
                    f'{INDENT * 2}raise ValueError(f"{f.name}: {name} = {{{name}!r}} is outside its domain {where}")']
        else:
            out += [f"{INDENT}if (!({_bound(lo, lang)} <= {name} && {name} <= {_bound(hi, lang)})) {{",
                    f"{INDENT * 2}errno = EDOM;  /* {name} outside its domain {where} */",
                    f"{INDENT * 2}return NAN;", f"{INDENT}}}"]
    return "\n".join(out)


def prototype(f: Function, lang: str) -> str:
    """f's prototype printed in C ("c") or Python ("py")."""
    return PRINTERS[lang]().doprint(prototype_ast(f))


@functools.lru_cache(maxsize=512)
def printed(f: Function, lang: str) -> Printed:
    """f printed in C ("c") or Python ("py")."""
    return Printed(prototype(f, lang), PRINTERS[lang]().doprint(function_ast(f).body), guard(f, lang))


def kernel_function(name: str, args: Sequence[KernelArg], expr: sp.Expr,
                    domain: Sequence[tuple[float, float]] | None = None) -> Function:
    """The Function of a kernel named `name` of its arguments, returning expr; its arguments are
    tested against `domain` (default: the declared [lo, hi] of each)."""
    dom = tuple(domain) if domain else tuple((a.lo, a.hi) for a in args)
    return Function(name, tuple(parameter(a) for a in args), printable(expr, args), domain=dom)


def definition(f: Function, lang: str, doc: str = "", dispatch: str = "") -> str:
    """The whole definition of f, laid out by templates/function.<lang>.j2 (doc: the Python
    docstring or the C comment above the function; dispatch: Python lines before the guard that
    send numpy arrays to the array path, :func:`.arrays.dispatch`)."""
    return lay_out(f"function.{lang}.j2", f=printed(f, lang), doc=doc, dispatch=dispatch)


def c_function(k) -> tuple[str, str]:
    """(prototype, definition) of a kernel in C99, standalone (no shared parts)."""
    f = kernel_function(k.name, k.args, k.expr, k.domain)
    return printed(f, "c").prototype, definition(f, "c")


def py_function(k) -> str:
    """The Python definition of a kernel, standalone (no shared parts), with its docstring."""
    return definition(kernel_function(k.name, k.args, k.expr, k.domain), "py", k.docstring())
