"""Statement planning: a kernel's form as a block of statements (SymPy's codegen AST).

The block is the same for C and Python (:mod:`.printing` prints it): constants are
declared once (``Declaration`` of a const ``Variable``), each stable leaf
(:class:`Grouped`) and each other ``Piecewise`` becomes an if-chain (:class:`If`) whose
branches have their own subexpressions, and the rest is SymPy's common-subexpression
elimination.  Nothing is evaluated outside its range: a series at u = 700 overflows, and
a far form may have a pole at small u.
"""
from __future__ import annotations

import functools
from typing import Iterator

import sympy as sp
from sympy.codegen.ast import (Assignment, CodeBlock, Declaration, Return, Token, Variable, real,
                               value_const)
from sympy.core.containers import Tuple
from sympy.core.function import AppliedUndef


class Grouped(sp.Function):
    """A leaf evaluated as one parenthesised unit: its terms are not merged into the sum around
    it, so the order of operations its accuracy was measured with is the order of the kernel."""

    nargs = 1


class Magnitude(sp.Function):
    """|x| of a real double (fabs in C, abs in Python), for the tests that choose a form; unlike
    ``Abs`` it is not rewritten with ``conjugate`` for symbols of unknown sign."""

    nargs = 1


class Select(sp.Function):
    """``b if d > 0 else c`` as one expression (C: ``d > 0 ? b : c``): a choice between two forms
    that, unlike a Piecewise condition, SymPy does not fold (a Piecewise whose condition holds
    the piecewise leaves is multiplied out over every combination of their pieces)."""

    nargs = 3


class If(Token):
    """``if … else if … else``: `branches`, a tuple of (condition, CodeBlock); a last condition
    ``true`` is the ``else``."""

    __slots__ = _fields = ("branches",)
    _construct_branches = staticmethod(lambda bs: Tuple(*[Tuple(c, b) for c, b in bs]))


def always_evaluated(expr: sp.Basic, kind) -> set:
    """The subexpressions of type `kind` that expr evaluates on every path: the search does not
    enter the branches of a Piecewise or of an ITE (SymPy folds a Piecewise out of a condition
    into an ITE), only their conditions."""
    found, stack = set(), [expr]
    while stack:
        e = stack.pop()
        if isinstance(e, kind):
            found.add(e)
            continue
        if isinstance(e, sp.Piecewise):
            stack += [c for _, c in e.args]
        elif isinstance(e, sp.ITE):
            stack.append(e.args[0])
        else:
            stack += list(e.args)
    return found


def units(expr: sp.Basic) -> set:
    """Every subexpression evaluated as one unit (a :class:`Grouped` leaf, a Piecewise or a
    :class:`Select`), wherever it is: the parts one kernel may share with another (:mod:`.sharing`;
    the root of (30) that K (36) and n² (34) both need is a Select since session 11)."""
    return expr.atoms(Grouped, sp.Piecewise, Select)


def _const(sym: sp.Symbol, value: sp.Expr) -> Declaration:
    return Declaration(Variable(sym, type=real, attrs=(value_const,), value=value))


def shared_exponentials(expr: sp.Basic) -> list:
    """The units Grouped(exp(…)) that expr evaluates in two or more places (the one exponential of
    several leaves' far forms, :func:`.rules.one_exponential`), sorted: each is computed once, before
    the leaves, on every path (one libm call where F of (170) made ten; exp of a real double does
    not fail, and it costs one call where no far form is taken)."""
    counts: dict = {}
    stack = [expr]
    while stack:
        e = stack.pop()
        if isinstance(e, Grouped) and isinstance(e.args[0], sp.exp):
            counts[e] = counts.get(e, 0) + 1
            continue
        stack += list(e.args)
    return sorted((e for e, n in counts.items() if n > 1), key=sp.default_sort_key)


def _steps(expr: sp.Expr, names: Iterator[sp.Symbol]) -> tuple[list, sp.Expr]:
    """(statements, value): the exponentials several far forms share first, then the leaves (a
    Piecewise may compare them), then every other always-evaluated Piecewise, then the calls of
    shared parts (each evaluated once), then common subexpressions (SymPy cse)."""
    steps: list = []
    hoisted = {e: next(names) for e in shared_exponentials(expr)}
    for e, sym in hoisted.items():
        steps.append(_const(sym, e.args[0]))
    expr = expr.xreplace(hoisted)
    for kind in (Grouped, sp.Piecewise, AppliedUndef):
        named = {}
        for e in sorted(always_evaluated(expr, kind), key=sp.default_sort_key):
            named[e] = next(names)
            if kind is AppliedUndef:           # a call: its arguments are the function's own
                steps.append(_const(named[e], e))
            else:
                steps += _assign(e.args[0] if kind is Grouped else e, named[e], names)
        expr = expr.xreplace(named)
    subs, (red,) = sp.cse([expr], symbols=names)
    steps += [_const(x, v) for x, v in subs]
    return steps, red


def _assign(value: sp.Expr, sym: sp.Symbol, names: Iterator[sp.Symbol]) -> list:
    """The statements that give sym its value: an if-chain for a Piecewise, else its own steps."""
    if isinstance(value, sp.Piecewise):
        branches = []
        for branch, cond in value.args:
            steps, red = _steps(branch, names)
            branches.append((cond, CodeBlock(*steps, Assignment(sym, red))))
        return [Declaration(Variable(sym, type=real)), If(branches)]
    steps, red = _steps(value, names)
    return [*steps, _const(sym, red)]


@functools.lru_cache(maxsize=512)
def body(expr: sp.Expr) -> CodeBlock:
    """The statements of a function returning expr, names x_0, x_1, … in order of appearance."""
    steps, red = _steps(expr, sp.numbered_symbols("x_"))
    return CodeBlock(*steps, Return(red))
