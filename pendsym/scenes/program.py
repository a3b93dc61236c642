"""A Result's derived form as a numeric program: its distinct subexpressions, evaluated once each by mpmath.

A derived form is a SymPy DAG whose unfolded tree can be a thousand times larger than the DAG (a holed blade's
(343) n² has ~100 distinct nodes and prints to 33,000 characters).  Printing it for ``lambdify`` and evaluating the
printed tree were most of a warm scene's time; decoding the unfolded tree from the cache most of the rest.
:func:`compile` walks the DAG once and lists each distinct node once, its arguments by index; :func:`run` evaluates
the list lazily (a Piecewise evaluates only the branch its conditions choose), each node once, by mpmath at the
precision in force.  An Integral's body is evaluated at each node of ``mpmath.quad``, the nodes that do not depend
on its variable once.

A :class:`Program` is plain data (names, operations, numbers): the cache stores it through :mod:`pendsym.codec` and
nothing is evaluated on loading; :func:`run` looks operations up in a fixed table.  A form with a node outside the
table gives :class:`Unsupported` (the scene then evaluates the SymPy form as before).
"""
from __future__ import annotations

from dataclasses import dataclass

import mpmath as mp
import sympy as sp
from sympy.core.relational import Relational
from sympy.logic.boolalg import BooleanFalse, BooleanTrue

__all__ = ["Program", "Unsupported", "compile", "run"]


class Unsupported(ValueError):
    """A node :func:`run` has no operation for."""


@dataclass(frozen=True)
class Program:
    """``names``: the free symbols' names (sorted); ``code``: one tuple per distinct node, ``(op, *operands)``,
    operands being node indices except for the constants' payloads; the last node is the value.
    ``bound[i]``: node i depends on an Integral's variable (it is evaluated again at each quadrature node)."""

    names: tuple[str, ...]
    code: tuple[tuple, ...]
    bound: tuple[bool, ...]


# SymPy function → mpmath function (by name: a Program holds only the name)
FUNCTIONS = {
    "sin": mp.sin, "cos": mp.cos, "tan": mp.tan, "cot": mp.cot, "sec": mp.sec, "csc": mp.csc,
    "sinh": mp.sinh, "cosh": mp.cosh, "tanh": mp.tanh, "coth": mp.coth, "sech": mp.sech, "csch": mp.csch,
    "asin": mp.asin, "acos": mp.acos, "atan": mp.atan, "asinh": mp.asinh, "acosh": mp.acosh, "atanh": mp.atanh,
    "exp": mp.exp, "log": mp.log, "Abs": mp.fabs, "besselj": mp.besselj, "bessely": mp.bessely,
    "besseli": mp.besseli, "besselk": mp.besselk, "elliptic_k": lambda m: mp.ellipk(m),
    "elliptic_e": lambda m: mp.ellipe(m),
}
CONSTANTS = {sp.pi: "pi", sp.E: "e", sp.EulerGamma: "euler", sp.Catalan: "catalan", sp.GoldenRatio: "phi"}
_CONSTANT_NAMES = frozenset(CONSTANTS.values())
RELATIONS = {"StrictGreaterThan": "gt", "GreaterThan": "ge", "StrictLessThan": "lt", "LessThan": "le",
             "Equality": "eq", "Unequality": "ne"}


def compile(expr: sp.Basic) -> Program:
    """The program of ``expr`` (:class:`Unsupported` if a node has no operation)."""
    names: set[str] = set()          # the free symbols, found by the walk (free_symbols unfolds the tree)
    code: list[tuple] = []
    bound: list[bool] = []
    index: dict[tuple, int] = {}

    def emit(op: tuple, is_bound: bool) -> int:
        if op not in index:
            index[op] = len(code)
            code.append(op)
            bound.append(is_bound)
        return index[op]

    memo: dict[tuple[sp.Basic, frozenset], int] = {}

    def walk(e: sp.Basic, variables: frozenset) -> int:
        key = (e, variables)
        if key not in memo:
            memo[key] = node(e, variables)
        return memo[key]

    def node(e: sp.Basic, variables: frozenset) -> int:
        if e.is_Symbol:
            if e in variables:
                return emit(("var", e.name), True)
            names.add(e.name)
            return emit(("in", e.name), False)
        if e.is_Integer:
            return emit(("int", int(e)), False)
        if e.is_Rational:
            return emit(("rat", int(e.p), int(e.q)), False)
        if e.is_Float:
            sign, man, exp, _ = e._mpf_                # exact: (−1)^sign man 2^exp
            return emit(("float", -int(man) if sign else int(man), int(exp)), False)
        if e in CONSTANTS:
            return emit(("const", CONSTANTS[e]), False)
        if isinstance(e, BooleanTrue):
            return emit(("true",), False)
        if isinstance(e, BooleanFalse):
            return emit(("false",), False)
        if isinstance(e, sp.Integral):
            if len(e.limits) != 1 or len(e.limits[0]) != 3:
                raise Unsupported(f"an Integral with limits {e.limits}")
            x, lo, hi = e.limits[0]
            inner = variables | {x}
            lo_i, hi_i = walk(lo, variables), walk(hi, variables)
            body = walk(e.function, inner)
            return emit(("integral", x.name, body, lo_i, hi_i), bound[lo_i] or bound[hi_i] or bool(variables))
        if isinstance(e, sp.Piecewise):
            parts = []
            for value, cond in e.args:
                parts += [walk(cond, variables), walk(value, variables)]
            return emit(("piecewise", *parts), any(bound[p] for p in parts))
        if isinstance(e, Relational) and type(e).__name__ in RELATIONS:
            args = [walk(a, variables) for a in e.args]
            return emit((RELATIONS[type(e).__name__], *args), any(bound[a] for a in args))
        if isinstance(e, (sp.And, sp.Or, sp.Not)):
            args = [walk(a, variables) for a in e.args]
            return emit((type(e).__name__.lower(), *args), any(bound[a] for a in args))
        if isinstance(e, (sp.Add, sp.Mul, sp.Pow)):
            args = [walk(a, variables) for a in e.args]
            return emit((type(e).__name__.lower(), *args), any(bound[a] for a in args))
        if isinstance(e, sp.Function) and type(e).__name__ in FUNCTIONS:
            args = [walk(a, variables) for a in e.args]
            return emit(("fn", type(e).__name__, *args), any(bound[a] for a in args))
        raise Unsupported(f"no numeric operation for {type(e).__name__}")

    root = walk(expr, frozenset())
    if root != len(code) - 1:                 # the value is the node emitted last (after its arguments)
        raise Unsupported("the form's value is not its last node")
    return Program(tuple(sorted(names)), tuple(code), tuple(bound))


def run(prog: Program, inputs: dict[str, mp.mpf]):
    """The value of the program at ``inputs`` (by name), by mpmath at the precision in force (mpf or mpc)."""
    code, bound = prog.code, prog.bound
    given = {n: inputs[n] for n in prog.names}
    outer: dict[int, object] = {}

    def ev(k: int, env: dict, local: dict):
        memo = local if bound[k] else outer
        if k in memo:
            return memo[k]
        op = code[k]
        kind = op[0]
        if kind == "in":
            if op[1] not in given:
                raise Unsupported(f"input {op[1]!r} is not among the program's names")
            v = given[op[1]]
        elif kind == "var":
            v = env[op[1]]
        elif kind == "int":
            v = mp.mpf(op[1])
        elif kind == "rat":
            v = mp.mpf(op[1]) / op[2]
        elif kind == "float":
            v = mp.ldexp(mp.mpf(op[1]), op[2])
        elif kind == "const":
            if op[1] not in _CONSTANT_NAMES:            # the name comes from the cache: only the table's
                raise Unsupported(f"constant {op[1]!r}")
            v = +getattr(mp, op[1])
        elif kind == "true":
            v = True
        elif kind == "false":
            v = False
        elif kind == "add":
            v = mp.fsum(ev(a, env, local) for a in op[1:])
        elif kind == "mul":
            v = mp.fprod(ev(a, env, local) for a in op[1:])
        elif kind == "pow":
            base, expo = op[1], op[2]
            if code[expo][0] == "int":
                v = ev(base, env, local) ** code[expo][1]
            elif code[expo] == ("rat", 1, 2):
                v = mp.sqrt(ev(base, env, local))
            elif code[expo] == ("rat", -1, 2):
                v = 1 / mp.sqrt(ev(base, env, local))
            else:
                v = mp.power(ev(base, env, local), ev(expo, env, local))
        elif kind == "fn":
            if op[1] not in FUNCTIONS:
                raise Unsupported(f"function {op[1]!r}")
            v = FUNCTIONS[op[1]](*(ev(a, env, local) for a in op[2:]))
        elif kind in ("gt", "ge", "lt", "le", "eq", "ne"):
            x, y = ev(op[1], env, local), ev(op[2], env, local)
            if isinstance(x, mp.mpc) or isinstance(y, mp.mpc):
                if kind not in ("eq", "ne"):
                    raise ValueError("a comparison of complex numbers")
            v = {"gt": x > y, "ge": x >= y, "lt": x < y, "le": x <= y, "eq": x == y, "ne": x != y}[kind]
        elif kind == "and":
            v = all(ev(a, env, local) for a in op[1:])
        elif kind == "or":
            v = any(ev(a, env, local) for a in op[1:])
        elif kind == "not":
            v = not ev(op[1], env, local)
        elif kind == "piecewise":
            v = None
            for c, val in zip(op[1::2], op[2::2]):
                if ev(c, env, local):
                    v = ev(val, env, local)
                    break
            if v is None:
                raise ValueError("no branch of a Piecewise holds")
        elif kind == "integral":
            name, body = op[1], op[2]
            lo, hi = ev(op[3], env, local), ev(op[4], env, local)
            v = _quad(lambda t: ev(body, {**env, name: t}, {}), lo, hi)
        else:
            raise Unsupported(f"operation {kind!r}")
        memo[k] = v
        return v

    return ev(len(code) - 1, {}, {})


def _quad(f, lo, hi):
    """∫ f over [lo, hi] at the precision in force: Gauss–Legendre (about half the nodes of tanh–sinh for the smooth
    integrands of the forms, e.g. the Bessel products of (346)), kept when its own error estimate is within
    2¹⁰ ε max(|value|, 1) at the working precision; else mpmath's default tanh–sinh (e.g. an endpoint singularity)."""
    value, err = mp.quad(f, [lo, hi], method="gauss-legendre", error=True)
    if err <= mp.eps * 2**10 * max(abs(value), 1) and mp.isfinite(value):
        return value
    return mp.quad(f, [lo, hi])
