"""Arrays: the Python kernels on numpy arrays, printed from the same statements as the scalar path.

A kernel's Python function keeps its scalar path (math only, as measured, byte for byte) and
gains one dispatch: an argument that is a ``numpy.ndarray`` sends the call to ``_<name>_array``,
which runs the statements of :func:`.plan.body` elementwise, printed by SymPy's numpy printer
(:class:`KernelNumPy`), with no Python loop over the elements:

- the arguments are broadcast together as float arrays; the guard of each argument
  (:func:`.printing.guard`) becomes one test over the array, which raises the scalar path's
  ValueError (the same message) for the first element outside the domain;
- an if-chain (:class:`.plan.If`) becomes masks: each branch runs on its own elements only
  (the arrays it reads are indexed by its mask, its value written through it), so no piece
  is evaluated where it is invalid and none warns; so does every choice inside an expression
  (a Piecewise or ITE that SymPy folded into a condition, an ``and``/``or``, which Python
  stops evaluating at the first operand that decides, a :class:`.plan.Select`), in the order
  the scalar path evaluates it;
- a power is ``numpy.float_power`` (libm's pow, as Python's ``**`` on floats; numpy's ``**``
  squares and takes reciprocals in its own way), each distinct one computed once a statement
  (the scalar path's conditions repeat u**2 dozens of times); a shared part is called as
  ``_<part>_array``.

The operations are those of the scalar path in the same order.  numpy's own exp, expm1, log,
tan, sinh, cosh and tanh (its SIMD loops, on a CPU that has them) round differently from
libm's by up to 2 ulp, so there the two paths agree to a few ulp, not always bitwise (the audit
measures the array path against the reference); with ``NPY_DISABLE_CPU_FEATURES`` set to the
CPU's dispatched features numpy calls libm, and they agree bit for bit
(tests/test_kernels_numpy.py).
"""
from __future__ import annotations

import itertools
from typing import Iterator

import sympy as sp
from sympy.codegen.ast import Assignment, CodeBlock, Declaration, NoneToken, Return
from sympy.printing.numpy import NumPyPrinter
from sympy.printing.precedence import precedence

from .plan import If, Select, body
from .printing import INDENT, Function, _bound, definition
from .supplied import Helper

_TOP = "_shape"


class KernelNumPy(NumPyPrinter):
    """SymPy's numpy printer for the array path: an expression prints as the scalar path's
    (KernelPy) with ``numpy.`` for ``math.``, a power as ``numpy.float_power`` (libm's pow), a
    shared part as its array version.  The choices inside an expression (Piecewise, ITE, and, or,
    Select) never reach it: :func:`_hoist` computes them piece by piece first."""

    def __init__(self, settings=None):
        super().__init__({"fully_qualified_modules": True, **(settings or {})})
        self.memo: dict[str, str] = {}        # a power's text → the name it is computed into
        self.pending: list[tuple[str, str]] = []   # (name, text) of the powers of the statement being printed
        self.names = itertools.count()
        self.named: dict[sp.Basic, str] = {}  # a part of the statement being printed → the name it prints as

    def statement(self, e: sp.Basic, named: dict | None = None) -> tuple[str, list[tuple[str, str]]]:
        """e printed, and the powers it reads, each computed once before it: libm's pow costs ~40 ns
        an element, and the scalar path's conditions repeat u**2 dozens of times (the same value:
        the result is the same to the bit).  ``named`` {part of e: name}: a choice computed before
        the statement, an array indexed by a branch's mask.  The names are put in as e is printed,
        never into e itself: SymPy orders a sum's terms and a product's factors by their names, and
        e with other names in it would be summed or multiplied in another order than the scalar
        path's (a different rounding)."""
        self.memo, self.pending, self.named = {}, [], dict(named or {})
        try:
            text = self.doprint(e)
        finally:
            self.named = {}
        return text, self.pending

    def _print(self, expr, **kwargs) -> str:
        if self.named and isinstance(expr, sp.Basic) and expr in self.named:
            return self.named[expr]
        return super()._print(expr, **kwargs)

    def parenthesize(self, item, level, strict=False) -> str:
        if self.named and isinstance(item, sp.Basic) and item in self.named:   # a name: no parentheses
            return self.named[item]
        return super().parenthesize(item, level, strict)

    def _print_Grouped(self, expr) -> str:
        return "(" + self._print(expr.args[0]) + ")"

    def _print_Magnitude(self, expr) -> str:
        return f"numpy.abs({self._print(expr.args[0])})"

    def _print_AppliedUndef(self, expr) -> str:
        return f"_{expr.func.__name__}_array({', '.join(self._print(a) for a in expr.args)})"

    def _print_Pow(self, expr, rational=False):
        # the forms of PythonCodePrinter._hprint_Pow (sqrt, 1/sqrt, 1/x), else libm's pow
        if expr.exp == sp.S.Half:
            return f"numpy.sqrt({self._print(expr.base)})"
        if expr.exp == -sp.S.Half:
            return f"1/numpy.sqrt({self._print(expr.base)})"
        if expr.exp is sp.S.NegativeOne:
            return f"1/{self.parenthesize(expr.base, precedence(expr), strict=False)}"
        text = f"numpy.float_power({self._print(expr.base)}, {self._print(expr.exp)})"
        if text not in self.memo:
            self.memo[text] = f"_w{next(self.names)}"
            self.pending.append((self.memo[text], text))
        return self.memo[text]


def _uses(node) -> set:
    """The symbols a statement or block reads (its conditions and values, nested blocks included)."""
    if isinstance(node, CodeBlock):
        return set().union(*[_uses(s) for s in node.args]) if node.args else set()
    if isinstance(node, If):
        out = set()
        for cond, block in node.branches:
            out |= sp.sympify(cond).free_symbols | _uses(block)
        return out
    if isinstance(node, Declaration):
        v = node.variable.value
        return set() if isinstance(v, NoneToken) else v.free_symbols
    if isinstance(node, Assignment):
        return node.rhs.free_symbols
    if isinstance(node, Return):
        return node.args[0].free_symbols
    return set()


class _Level:
    """The arrays of one level of the array function: the whole broadcast shape at the top, a
    branch's elements inside it (`rename`: each array read there, as indexed by the mask)."""

    def __init__(self, shape: str, rename: dict, arrays: set, params: frozenset = frozenset()):
        self.shape, self.rename, self.arrays, self.params = shape, rename, arrays, params

    def value(self, e: sp.Expr) -> sp.Expr:
        return e.xreplace(self.rename) if self.rename else e

    def is_array(self, e: sp.Expr) -> bool:
        """e (as renamed at this level) reads an array."""
        return bool(e.free_symbols & (self.arrays | set(self.rename.values())))


def _pieces(x: sp.Basic) -> list[tuple]:
    """(condition, value) of each piece of a choice, in the order the scalar path tries them:
    Python's ``and``/``or`` evaluate their operands in the printer's (sorted) order and stop at
    the first that decides; a Select tests d > 0 and evaluates one of its two forms."""
    if isinstance(x, sp.Piecewise):
        return [(c, v) for v, c in x.args]
    if isinstance(x, sp.ITE):
        return [(x.args[0], x.args[1]), (sp.true, x.args[2])]
    if isinstance(x, Select):
        return [(x.args[0] > 0, x.args[1]), (sp.true, x.args[2])]
    first, *rest = sorted(x.args, key=sp.default_sort_key)
    rest = x.func(*rest) if len(rest) > 1 else rest[0]
    return [(first, rest), (sp.true, sp.false)] if isinstance(x, sp.And) else [(first, sp.true), (sp.true, rest)]


def _hoist(e: sp.Basic, level: _Level, depth: int, ids: Iterator[int], p: KernelNumPy) -> tuple[dict, list[str]]:
    """{each outermost choice inside e (a Piecewise or ITE, which SymPy folds into a condition; an
    ``and``/``or``; a Select): the Symbol it is computed into}, and the lines that compute it piece
    by piece, each piece on the elements where the scalar path evaluates it (so none is evaluated
    where it is invalid)."""
    found = e.atoms(sp.Piecewise, sp.ITE, sp.And, sp.Or, Select)
    outer = [x for x in found if not any(y != x and y.has(x) for y in found)]
    pad, lines, named = INDENT * depth, [], {}
    for x in sorted(outer, key=sp.default_sort_key):
        pieces = _pieces(x)
        boolean = all(isinstance(v, sp.logic.boolalg.Boolean) for _, v in pieces)
        t = sp.Symbol(f"_p{next(ids)}")
        lines.append(f"{pad}{t} = numpy.empty({level.shape}{', dtype=bool' if boolean else ''})")
        lines += _branches(pieces, str(t), level, depth, ids, p)
        level.arrays.add(t)
        named[x] = t
    return named, lines


def _value(e: sp.Basic, level: _Level, depth: int, ids: Iterator[int], p: KernelNumPy) -> tuple[sp.Basic, str, list[str]]:
    """(e at this level, e printed, the lines that must run first).  e is printed as it is (the scalar
    path's order of its terms and factors), its choices and this level's arrays named as it prints."""
    named, lines = _hoist(e, level, depth, ids, p)
    here = level.value(e.xreplace(named) if named else e)
    names = {x: p._print(t) for x, t in named.items()}
    names.update({s: p._print(t) for s, t in level.rename.items()})
    text, powers = p.statement(e, names)
    return here, text, lines + [f"{INDENT * depth}{name} = {power}" for name, power in powers]


def _statements(block: CodeBlock, level: _Level, depth: int, ids: Iterator[int], p: KernelNumPy,
                target: tuple[str, str] | None = None) -> list[str]:
    """The lines of block at `level` (target: the array and mask a branch's Assignment writes)."""
    pad, lines = INDENT * depth, []
    for s in block.args:
        if isinstance(s, Declaration):
            var = s.variable
            name = p._print(var.symbol)
            if isinstance(var.value, NoneToken):          # the value of an if-chain: one slot per element
                lines.append(f"{pad}{name} = numpy.empty({level.shape})")
                level.arrays.add(var.symbol)
            else:
                value, text, pre = _value(var.value, level, depth, ids, p)
                lines += pre + [f"{pad}{name} = {text}"]
                if level.is_array(value):
                    level.arrays.add(var.symbol)
        elif isinstance(s, If):
            target_of = p._print(next(a.lhs for a in s.branches[0][1].args if isinstance(a, Assignment)))
            lines += _branches(s.branches, target_of, level, depth, ids, p)
        elif isinstance(s, Assignment):
            array, mask = target
            _, text, pre = _value(s.rhs, level, depth, ids, p)
            lines += pre + [f"{pad}{array}[{mask}] = {text}"]
        elif isinstance(s, Return):
            value, text, pre = _value(s.args[0], level, depth, ids, p)
            if not level.is_array(value) or value in level.params:   # a constant, or an argument itself: a new array
                text = f"numpy.array(numpy.broadcast_to({text}, {level.shape}), dtype=float)"
            lines += pre + [f"{pad}return {text}"]
    return lines


def _branches(branches, target: str, level: _Level, depth: int, ids: Iterator[int], p: KernelNumPy) -> list[str]:
    """An if-chain (condition, block or expression) as masks: branch i runs on the elements where its
    condition is the first to hold, and writes target there."""
    pad, lines, k = INDENT * depth, [], next(ids)
    left = None                                           # the elements no earlier branch took
    for i, (cond, block) in enumerate(branches):
        mask = f"_m{k}_{i}"
        last = i == len(branches) - 1
        if cond == sp.true:
            lines.append(f"{pad}{mask} = {left}" if left else f"{pad}{mask} = numpy.ones({level.shape}, dtype=bool)")
        else:
            c, test, pre = _value(cond, level, depth, ids, p)
            lines += pre
            if not level.is_array(c):
                test = f"numpy.broadcast_to({test}, {level.shape})"
            lines.append(f"{pad}{mask} = {test}" if left is None else f"{pad}{mask} = {left} & {test}")
            if not last:
                lines.append(f"{pad}_n{k} = ~{mask}" if left is None else f"{pad}_n{k} = {left} & ~{mask}")
                left = f"_n{k}"
        lines.append(f"{pad}if {mask}.any():")
        inner = {}
        uses = _uses(block) if isinstance(block, CodeBlock) else block.free_symbols
        for s in sorted(uses & level.arrays, key=sp.default_sort_key):
            sub = sp.Symbol(f"{p._print(s)}__{k}_{i}", real=True)
            lines.append(f"{pad}{INDENT}{p._print(sub)} = {p._print(level.value(s))}[{mask}]")
            inner[s] = sub
        branch = _Level(f"numpy.count_nonzero({mask})", inner, set(inner))
        if isinstance(block, CodeBlock):
            lines += _statements(block, branch, depth + 1, ids, p, (target, mask))
        else:
            _, text, pre = _value(block, branch, depth + 1, ids, p)
            lines += pre + [f"{pad}{INDENT}{target}[{mask}] = {text}"]
    return lines


def array_function(f: Function) -> str:
    """The array version of f: ``_<name>_array`` (a kernel: its arguments broadcast and tested
    against its domain; a shared part: called with its caller's arrays)."""
    p = KernelNumPy()
    params = [p._print(s) for s in f.params]
    doc = f"{f.name} on numpy arrays: the scalar path's statements elementwise, each branch on its own elements."
    lines = [f"def _{f.name}_array({', '.join(params)}):", f'{INDENT}"""{doc}"""']
    if not f.callers:
        arrays = ", ".join(f"numpy.asarray({x}, dtype=float)" for x in params)
        if len(params) == 1:
            lines.append(f"{INDENT}{params[0]} = {arrays}")
        else:
            lines.append(f"{INDENT}{', '.join(params)} = numpy.broadcast_arrays({arrays})")
        lines += array_guard(f)
    if f.expr.atoms(Helper):
        # a supplied form's helpers (double-double, Bessel cross products) are scalar code: the
        # elements go through the scalar path one by one (a Python loop, said in the docstring)
        lines[1] = (f'{INDENT}"""{f.name} on numpy arrays: the scalar path on each element (its helpers are scalar; '
                    f'a Python loop over the elements)."""')
        lines.append(f"{INDENT}return numpy.vectorize({f.name}, otypes=[float])({', '.join(params)})")
        return "\n".join(lines) + "\n"
    lines.append(f"{INDENT}{_TOP} = {params[0]}.shape")
    level = _Level(_TOP, {}, set(f.params), frozenset(f.params))
    lines += _statements(body(f.expr), level, 1, itertools.count(), p)
    return "\n".join(lines) + "\n"


def array_guard(f: Function) -> list[str]:
    """:func:`.printing.guard` over arrays: the first element of the first argument outside its
    domain (NaN included) raises the ValueError the scalar path raises for it."""
    out = []
    for s, (lo, hi) in zip(f.params, f.domain):
        name = KernelNumPy()._print(s)
        where = f"[{lo:g}, {hi:g}]"
        out += [f"{INDENT}_bad = ~(({_bound(lo)} <= {name}) & ({name} <= {_bound(hi)}))",
                f"{INDENT}if _bad.any():",
                f'{INDENT * 2}raise ValueError(f"{f.name}: {name} = {{float({name}[_bad].flat[0])!r}} '
                f'is outside its domain {where}")']
    return out


def dispatch(f: Function) -> str:
    """The line of the scalar path that sends numpy arrays to the array path."""
    params = [KernelNumPy()._print(s) for s in f.params]
    test = " or ".join(f"isinstance({x}, _ndarray)" for x in params)    # _ndarray: numpy.ndarray, bound once
    return f"{INDENT}if {test}:\n{INDENT * 2}return _{f.name}_array({', '.join(params)})"


def numpy_definition(f: Function, doc: str = "") -> str:
    """The Python definition of f as a module of kernels emits it: the scalar function (with the
    dispatch, for a kernel), then its array version."""
    scalar = definition(f, "py", doc, dispatch="" if f.callers else dispatch(f))
    return scalar + "\n\n" + array_function(f)
