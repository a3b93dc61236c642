"""A safe parser of a user's formula text into SymPy.

The text is parsed by Python's ``ast`` (never evaluated) and only a whitelist of
node kinds is turned into SymPy: numbers, the problem's declared names, ``+ - * / **``,
unary ``+``/``-``, parentheses and calls of a few named functions with one argument.
Everything else (attribute access, subscripts, names not declared, dunder names,
lambdas, comprehensions, strings, keywords, comparisons…) is refused with a
:class:`FormulaError` whose message is one line.

Bounds, checked before any SymPy object is built: the text length, the nesting depth of
brackets and of the syntax tree, and the size of every numeric power (so ``9**9**9`` is
refused at once instead of computing a number with 10⁸ digits).  ``sympify`` is never
called on the text.
"""
from __future__ import annotations

import ast
import math
from typing import Mapping

import sympy as sp

MAX_CHARS = 2000        # a formula longer than this is refused
MAX_DEPTH = 40          # brackets and syntax-tree depth
MAX_EXPONENT = 64       # |n| of a power x**n (symbolic base)
MAX_BITS = 4096         # size of a numeric power a**n computed exactly
MAX_LITERAL_DIGITS = 60

FUNCTIONS = {
    "sin": sp.sin, "cos": sp.cos, "tan": sp.tan, "exp": sp.exp, "log": sp.log,
    "sqrt": sp.sqrt, "abs": sp.Abs, "sign": sp.sign,
    "sinh": sp.sinh, "cosh": sp.cosh, "tanh": sp.tanh, "atan": sp.atan,
}
CONSTANTS = {"pi": sp.pi}

_BINOPS = {ast.Add: "+", ast.Sub: "-", ast.Mult: "*", ast.Div: "/", ast.Pow: "**"}


class FormulaError(ValueError):
    """A formula that pendsym refuses to read; the message is one line."""


def _short(text: str, n: int = 40) -> str:
    text = text.replace("\n", " ").replace("\r", " ")
    shown = "".join(ch if ch.isprintable() else f"\\u{ord(ch):04x}" for ch in text[:n])
    return shown + ("…" if len(text) > n else "")


def _bracket_depth(text: str) -> int:
    depth = deepest = 0
    for ch in text:
        if ch in "([{":
            depth += 1
            deepest = max(deepest, depth)
        elif ch in ")]}":
            depth -= 1
    return deepest


def _tree_depth(node: ast.AST) -> int:
    """Depth of the syntax tree, iteratively (no recursion on a hostile tree)."""
    deepest, stack = 0, [(node, 1)]
    while stack:
        cur, d = stack.pop()
        deepest = max(deepest, d)
        if deepest > MAX_DEPTH:
            return deepest
        stack.extend((child, d + 1) for child in ast.iter_child_nodes(cur))
    return deepest


def _number(value) -> sp.Expr:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise FormulaError(f"only numbers are allowed as constants, not {type(value).__name__}")
    if isinstance(value, float):
        if not math.isfinite(value):
            raise FormulaError("a number must be finite")
        return sp.Rational(repr(value))         # the decimal the user wrote, exactly
    if len(str(abs(value))) > MAX_LITERAL_DIGITS:
        raise FormulaError(f"a number has more than {MAX_LITERAL_DIGITS} digits")
    return sp.Integer(value)


def _power(base: sp.Expr, exponent: sp.Expr) -> sp.Expr:
    if not exponent.is_number:
        raise FormulaError("an exponent must be a number")
    if not exponent.is_rational:
        raise FormulaError("an exponent must be a rational number")
    if abs(exponent) > MAX_EXPONENT:
        raise FormulaError(f"an exponent larger than {MAX_EXPONENT} in absolute value")
    if base.is_number and base.is_rational and base != 0:
        num, den = sp.fraction(sp.Abs(base))
        bits = max(int(num).bit_length(), int(den).bit_length()) * abs(exponent)
        if bits > MAX_BITS:
            raise FormulaError(f"a numeric power with more than {MAX_BITS} bits")
    if base == 0 and exponent.is_negative:
        raise FormulaError("division by zero (0 to a negative power)")
    return sp.Pow(base, exponent)


class _Builder:
    def __init__(self, names: Mapping[str, sp.Expr]):
        self.names = names

    def build(self, node: ast.AST) -> sp.Expr:
        if isinstance(node, ast.Expression):
            return self.build(node.body)
        if isinstance(node, ast.Constant):
            return _number(node.value)
        if isinstance(node, ast.Name):
            return self._name(node.id)
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
            val = self.build(node.operand)
            return -val if isinstance(node.op, ast.USub) else val
        if isinstance(node, ast.BinOp) and type(node.op) in _BINOPS:
            left, right = self.build(node.left), self.build(node.right)
            op = _BINOPS[type(node.op)]
            if op == "+":
                return left + right
            if op == "-":
                return left - right
            if op == "*":
                return left * right
            if op == "/":
                if right == 0:
                    raise FormulaError("division by zero")
                return left / right
            return _power(left, right)
        if isinstance(node, ast.Call):
            return self._call(node)
        raise FormulaError(f"{_what(node)} is not allowed in a formula")

    def _name(self, name: str) -> sp.Expr:
        if name.startswith("_"):
            raise FormulaError(f"name {_short(name)!r} is not allowed")
        if name in self.names:
            return self.names[name]
        if name in CONSTANTS:
            return CONSTANTS[name]
        if name in FUNCTIONS:
            raise FormulaError(f"function {name} must be called with one argument")
        known = ", ".join(sorted(self.names)) or "none"
        raise FormulaError(f"unknown name {_short(name)!r} (known names: {known}; functions: "
                           f"{', '.join(sorted(FUNCTIONS))})")

    def _call(self, node: ast.Call) -> sp.Expr:
        if not isinstance(node.func, ast.Name) or node.func.id not in FUNCTIONS:
            what = node.func.id if isinstance(node.func, ast.Name) else _what(node.func)
            raise FormulaError(f"call of {_short(str(what))!r} is not allowed (functions: "
                               f"{', '.join(sorted(FUNCTIONS))})")
        if node.keywords or len(node.args) != 1 or isinstance(node.args[0], ast.Starred):
            raise FormulaError(f"{node.func.id} takes exactly one plain argument")
        return FUNCTIONS[node.func.id](self.build(node.args[0]))


def _what(node: ast.AST) -> str:
    return {ast.Attribute: "attribute access", ast.Subscript: "subscript", ast.Lambda: "lambda",
            ast.Compare: "comparison", ast.BoolOp: "a boolean operator", ast.IfExp: "if-else",
            ast.Starred: "a starred argument"}.get(type(node), f"syntax {type(node).__name__}")


def parse(text: str, names: Mapping[str, sp.Expr], what: str = "formula") -> sp.Expr:
    """SymPy expression of ``text`` whose free names must be in ``names`` (name → SymPy object).

    Raises :class:`FormulaError` (one line, naming ``what``) for anything outside the whitelist.
    """
    if not isinstance(text, str):
        if isinstance(text, (int, float)) and not isinstance(text, bool):
            return _number(text)
        raise FormulaError(f"{what}: must be a formula in a string or a number")
    try:
        if len(text) > MAX_CHARS:
            raise FormulaError(f"longer than {MAX_CHARS} characters")
        if not text.strip():
            raise FormulaError("empty")
        if _bracket_depth(text) > MAX_DEPTH:
            raise FormulaError(f"brackets nested deeper than {MAX_DEPTH}")
        try:
            tree = ast.parse(text.strip(), mode="eval")
        except (SyntaxError, ValueError, MemoryError, RecursionError) as exc:
            msg = exc.msg if isinstance(exc, SyntaxError) else type(exc).__name__
            raise FormulaError(f"not a formula ({_short(str(msg), 60)})") from None
        if _tree_depth(tree) > MAX_DEPTH:
            raise FormulaError(f"nested deeper than {MAX_DEPTH}")
        expr = _Builder(names).build(tree)
    except FormulaError as exc:
        raise FormulaError(f"{what} {_short(text)!r}: {exc}") from None
    except RecursionError:
        raise FormulaError(f"{what} {_short(text)!r}: nested too deeply") from None
    if expr.has(sp.zoo, sp.nan, sp.oo, -sp.oo):
        raise FormulaError(f"{what} {_short(text)!r}: not finite")
    return expr
