"""Formulas for the LaTeX reports: SymPy's LaTeX with the project's names, broken into lines.

:class:`ReportLatex` prints the symbols and functions of the code by the names the memoirs use
(``dbeta_1`` → dβ₁, ``theta''`` → θ'', ``x1dd`` → ẍ₁, ``epsilon`` → ε as printed).
:func:`display` sets ``lhs = expr`` as lines that fit the page: a sum is broken between its
terms, a product or quotient with a long sum is opened around that sum (``c·[…]``, ``(1/D)[…]``);
only what cannot be broken is left on one line (and scaled down by the template).  Widths are
estimated from the LaTeX by :func:`width` (in em of the 10 pt font, within ~10 % of TeX's).
"""
from __future__ import annotations

import re

import sympy as sp
from sympy.core.function import _coeff_isneg
from sympy.printing.latex import LatexPrinter

from .textex import GREEK_NAMES, tex_name

_NAME = re.compile(r"(?P<head>[A-Za-z]+?)(?P<digits>\d*)(?P<primes>'*)(?:_(?P<sub>[A-Za-z0-9']+))?")
_DOTTED = re.compile(r"([A-Za-z]+?)(\d*)(ddot|dd|dot)")


ABBREVIATION = "_abbr"   # the prefix of the names of abbreviations (set in sans-serif: A, B, …)


def symbol_tex(name: str) -> str | None:
    """The LaTeX of a symbol's or function's name where SymPy's would leak the code's spelling
    (primes, differentials dβ, dotted names, ε and φ as the memoirs print them); None otherwise."""
    if name.startswith(ABBREVIATION):
        return r"\mathsf{" + name[len(ABBREVIATION):] + "}"
    if "/" in name:                                    # a ratio named as one symbol: dR/R
        num, _, den = name.partition("/")
        return r"\left(" + (symbol_tex(num) or num) + "/" + (symbol_tex(den) or den) + r"\right)"
    if _DOTTED.fullmatch(name):
        return tex_name(name)
    m = _NAME.fullmatch(name)
    if not m:
        return None
    head = m.group("head")
    greek_d = len(head) > 1 and head[0] == "d" and head[1:] in GREEK_NAMES and head not in GREEK_NAMES
    if not (m.group("primes") or greek_d or head in ("epsilon", "phi", "lam")
            or (m.group("sub") and "'" in m.group("sub"))):
        return None
    out = tex_name(head) + (f"_{{{m.group('digits')}}}" if m.group("digits") else "") + m.group("primes")
    if m.group("sub"):
        sub = m.group("sub")
        out += "_{" + (tex_name(sub.rstrip("'")) + sub[len(sub.rstrip("'")):]) + "}"
    return out


class ReportLatex(LatexPrinter):
    """SymPy's LaTeX printer with the memoirs' names for the code's symbols and functions."""

    def _deal_with_super_sub(self, string: str, style="plain") -> str:
        mapped = symbol_tex(string)
        if mapped is None:
            return super()._deal_with_super_sub(string, style)
        return r"\mathbf{" + mapped + "}" if style == "bold" else mapped

    def parenthesize_super(self, s: str) -> str:
        """A base with a prime and a subscript (y'_{0}) is braced before a power: TeX's prime is a
        superscript, and y'_{0}^{2} would be a double one."""
        if "'" in s and "_" in s and "^" not in s:
            return "{" + s + "}"
        return super().parenthesize_super(s)

    def add_terms(self, expr: sp.Add) -> list[tuple[str, sp.Basic, str]]:
        """The terms of a sum as _print_Add prints them: (sign, term without it, LaTeX)."""
        out = []
        for i, term in enumerate(self._as_ordered_terms(expr)):
            sign = "- " if _coeff_isneg(term) else ("+ " if i else "")
            if _coeff_isneg(term):
                term = -term
            tex = self._print(term)
            if self._needs_add_brackets(term):
                tex = r"\left(%s\right)" % tex
            out.append((sign, term, tex))
        return out


PRINTER = ReportLatex({"ln_notation": False})


def tex_expr(e: sp.Basic | None) -> str:
    return "" if e is None else PRINTER.doprint(e)


# ------------------------------------------------------------------------ width estimate
_CMD = re.compile(r"\\([A-Za-z]+|.)")
_UPRIGHT = {"sin", "cos", "tan", "cot", "sec", "csc", "sinh", "cosh", "tanh", "coth", "log", "ln", "exp",
            "max", "min", "arcsin", "arccos", "arctan", "sign", "det", "lim"}
_BINARY = {"cdot", "times", "pm", "mp", "le", "ge", "leq", "geq", "equiv", "approx", "to", "neq", "ne", "in",
           "propto", "sim", "ll", "gg"}


def _group(s: str, i: int) -> tuple[str, int]:
    depth = 0
    for j in range(i, len(s)):
        if s[j] == "{":
            depth += 1
        elif s[j] == "}":
            depth -= 1
            if depth == 0:
                return s[i + 1:j], j + 1
    return s[i + 1:], len(s)


def _arg(s: str, i: int) -> tuple[str, int]:
    while i < len(s) and s[i] == " ":
        i += 1
    if i < len(s) and s[i] == "{":
        return _group(s, i)
    if i < len(s) and s[i] == "\\":
        m = _CMD.match(s, i)
        return m.group(0), m.end()
    return s[i:i + 1], i + 1


def width(s: str, scale: float = 1.0) -> float:
    """The estimated width, in em, of math LaTeX set in display style (as SymPy writes it)."""
    w, i = 0.0, 0
    while i < len(s):
        c = s[i]
        if c == "\\":
            m = _CMD.match(s, i)
            name, i = m.group(1), m.end()
            if name in ("frac", "dfrac", "tfrac"):
                a, i = _arg(s, i)
                b, i = _arg(s, i)
                inner = scale if scale >= 1 and name != "tfrac" else scale * 0.75
                w += max(width(a, inner), width(b, inner)) + 0.3 * scale
            elif name == "sqrt":
                a, i = _arg(s, i)
                w += width(a, scale) + 0.9 * scale
            elif name in ("left", "right", "bigl", "bigr", "Bigl", "Bigr", "biggl", "biggr", "big", "Big"):
                d, i = _arg(s, i)
                w += 0.45 * scale if d != "." else 0
            elif name in _UPRIGHT:
                w += (0.5 * len(name) + 0.3) * scale
            elif name in ("mathrm", "text", "mathbf", "operatorname", "mathit"):
                a, i = _arg(s, i)
                w += 0.5 * len(a) * scale
            elif name in ("dot", "ddot", "bar", "hat", "tilde", "overline", "mathbb"):
                a, i = _arg(s, i)
                w += width(a, scale)
            elif name == "int":
                w += 1.0 * scale
            elif name in ("limits", "displaystyle", "nolimits"):
                pass
            elif name in ("quad", "qquad"):
                w += (1.0 if name == "quad" else 2.0) * scale
            elif name in (",", ":", ";", " ", "!"):
                w += 0.2 * scale
            elif name in _BINARY:
                w += 1.3 * scale
            elif name in ("begin", "end"):
                _, i = _arg(s, i)
                w += 0.5 * scale
            else:
                w += 0.6 * scale
        elif c in "^_":
            a, i = _arg(s, i + 1)
            sw = width(a, scale * 0.7)
            if i < len(s) and s[i] in "^_":
                b, i = _arg(s, i + 1)
                sw = max(sw, width(b, scale * 0.7))
            w += sw
        elif c in "+-=<>":
            w += 1.25 * scale if scale >= 1 else 0.8 * scale
            i += 1
        elif c in "{} ":
            i += 1
        elif c in "()[]|":
            w += 0.4 * scale
            i += 1
        elif c in ",;":
            w += 0.45 * scale
            i += 1
        elif c == "&":
            w += 1.0 * scale
            i += 1
        elif c == "'":
            w += 0.3 * scale
            i += 1
        else:
            w += 0.52 * scale
            i += 1
    return w


# ------------------------------------------------------------------------ lines
INDENT = r"\qquad "


def display(lhs: str, expr: sp.Basic, budget: float, names=None) -> tuple[list[str], list[str]]:
    """``lhs = expr`` as lines of math of at most ``budget`` em where it can be broken: the first
    line holds ``lhs =``, the others start with their operator, indented.  A formula longer than
    a few lines names its large repeated parts (and a case distinction inside it) by letters
    A, B, … drawn from ``names``; the second list holds their definitions, as lines."""
    one = f"{lhs} = {tex_expr(expr)}" if lhs else tex_expr(expr)
    if width(one) <= budget:
        return [one], []
    head = f"{lhs} = " if lhs else ""
    lines = _split(expr, head, budget) or [one]
    if names is None or _reads_well(lines, budget):
        return lines, []
    short, defs = abbreviate(expr, names)
    if not defs:
        return lines, []
    where: list[str] = []
    for sym, sub in defs:
        where += display(tex_expr(sym), sub, budget - 4)[0]
    one = f"{lhs} = {tex_expr(short)}" if lhs else tex_expr(short)
    return ([one] if width(one) <= budget else (_split(short, head, budget) or [one])), where


def _reads_well(lines: list[str], budget: float) -> bool:
    """Lines that need no scaling, and not too many of them."""
    return len(lines) <= ABBREVIATE_OVER and all(width(ln) <= 1.1 * budget for ln in lines)


ABBREVIATE_OVER = 4       # lines of a formula over which its large repeated parts are named
ABBREVIATE_MIN = 10.0     # em: the least width of a part worth a name
ABBREVIATE_MAX = 4        # names per formula


def abbreviation_names():
    """The names A, B, … of the abbreviations of one Result's formulas."""
    return iter(sp.Symbol(ABBREVIATION + chr(c)) for c in range(ord("A"), ord("Z") + 1))


def abbreviate(expr: sp.Basic, names) -> tuple[sp.Basic, list[tuple[sp.Symbol, sp.Basic]]]:
    """expr with its widest repeated subexpressions (and any case distinction not at its top)
    replaced by new symbols: (expr, [(symbol, what it stands for)]), widest first."""
    defs: list[tuple[sp.Symbol, sp.Basic]] = []
    for _ in range(ABBREVIATE_MAX):
        counts: dict[sp.Basic, int] = {}
        roots = [expr, *(d for _, d in defs)]
        for root in roots:
            for node in sp.preorder_traversal(root):
                if not node.is_Atom:
                    counts[node] = counts.get(node, 0) + 1
        cands = [(width(tex_expr(node)), sp.default_sort_key(node), node) for node, n in counts.items()
                 if node not in roots and (n >= 2 or isinstance(node, sp.Piecewise))]
        cands = [c for c in cands if c[0] >= ABBREVIATE_MIN]
        if not cands:
            break
        _, _, best = max(cands, key=lambda c: (c[0], c[1]))
        sym = next(names)
        expr = expr.xreplace({best: sym})
        defs = [(s, d.xreplace({best: sym})) for s, d in defs] + [(sym, best)]
    return expr, defs


def _split(expr: sp.Basic, head: str, budget: float) -> list[str] | None:
    """Lines for expr after head (None if expr cannot be broken)."""
    if isinstance(expr, sp.Tuple):
        parts = [tex_expr(x) for x in expr]
        lines = []
        for k, (x, p) in enumerate(zip(expr, parts)):
            pre = (head + r"\Bigl(") if k == 0 else INDENT
            post = r"\Bigr)" if k == len(parts) - 1 else ","
            if width(pre + p + post) <= budget:
                lines.append(pre + p + post)
            else:
                sub = _split(x, pre, budget) or [pre + p]
                sub[-1] += post
                lines += sub
        return lines
    if isinstance(expr, sp.Add):
        return _pack(PRINTER.add_terms(expr), head, budget)
    if isinstance(expr, sp.Pow) and expr.exp.is_positive and isinstance(expr.base, sp.Add):
        return _open_power(expr, head, budget)
    if isinstance(expr, (sp.Mul, sp.Pow)):
        return _open_product(expr, head, budget)
    if isinstance(expr, sp.Piecewise):
        return _cases(expr, head, budget)
    if isinstance(expr, sp.Integral):
        return _integral(expr, head, budget)
    return None


def _cases(expr: sp.Piecewise, head: str, budget: float) -> list[str]:
    """A case distinction as one formula per case, each followed by its condition."""
    lines: list[str] = []
    for k, (e, cond) in enumerate(expr.args):
        when = r"\quad\text{otherwise}" if cond == sp.true else r"\quad\text{if } " + tex_expr(cond)
        pre = head if k == 0 else INDENT + (head.strip() + " " if head.strip() else "")
        body = tex_expr(e)
        if width(pre + body + when) <= budget:
            lines.append(pre + body + when)
            continue
        sub = _split(e, pre, budget) or [pre + body]
        if width(sub[-1] + when) <= budget:
            sub[-1] += when
        else:
            sub.append(INDENT + when.replace(r"\quad", ""))
        lines += sub
    return lines


def _join(cur: str, piece: str) -> str:
    return cur + ("" if not cur or cur.endswith((" ", "(", "[")) else " ") + piece


_SPLITTABLE = (sp.Add, sp.Mul, sp.Pow, sp.Integral, sp.Piecewise)


def _pack(terms: list[tuple[str, sp.Basic, str]], head: str, budget: float, close: str = "") -> list[str]:
    """Terms (each with its sign) packed greedily into lines; a term too wide for the rest of the
    line is itself broken (from that line if it is short, else from a new one)."""
    lines: list[str] = []
    cur = head
    for sign, term, tex in terms:
        cand = _join(cur, sign + tex)
        if width(cand) <= budget:
            cur = cand
            continue
        splittable = isinstance(term, _SPLITTABLE)
        if cur.strip():
            if splittable and width(cur) < 0.6 * budget:
                sub = _split(term, _join(cur, sign), budget)
                if sub:
                    lines += sub[:-1]
                    cur = sub[-1]
                    continue
            lines.append(cur)
            cur = INDENT
        cand = cur + sign + tex
        if width(cand) > budget and splittable:
            sub = _split(term, cur + sign, budget)
            if sub:
                lines += sub[:-1]
                cur = sub[-1]
                continue
        cur = cand
    lines.append(cur + close)
    return [ln for ln in lines if ln.strip()]


def _open_product(expr: sp.Basic, head: str, budget: float) -> list[str] | None:
    """A product (or quotient) whose widest part is a sum or an integral: the rest, then that
    part broken (a sum opened in brackets between its terms, an integral around its integrand)."""
    num, den = sp.fraction(expr)
    sign = ""
    if _coeff_isneg(num):
        sign, num = "- ", -num
    factors = sp.Mul.make_args(num)
    opened = [f for f in factors if isinstance(f, (sp.Add, sp.Integral))]
    if den != 1 and width(tex_expr(den)) > budget / 2 and (not opened or width(tex_expr(num)) < budget / 2):
        return _over(num, den, head + sign, budget)
    if not opened:
        return None
    widest = max(opened, key=lambda f: (width(tex_expr(f)), sp.default_sort_key(f)))
    rest = sp.Mul(*[f for f in factors if f is not widest])
    if den != 1:
        coeff = r"\frac{%s}{%s}" % (tex_expr(rest), tex_expr(den))
    else:
        coeff = "" if rest == 1 else tex_expr(rest)
        if coeff and PRINTER._needs_mul_brackets(rest, first=True):
            coeff = r"\left(%s\right)" % coeff
    pre = head + sign + coeff
    if isinstance(widest, sp.Integral):
        return _integral(widest, pre + (" " if coeff else ""), budget)
    terms = PRINTER.add_terms(widest)
    if not coeff:
        return _pack(terms, pre, budget)
    return _pack(terms, pre + r" \Bigl[", budget, close=r" \Bigr]")


def _integral(expr: sp.Integral, head: str, budget: float) -> list[str] | None:
    """A one-variable integral with a long integrand: ∫ ( integrand, broken ) dx."""
    if len(expr.limits) != 1:
        return None
    lim = expr.limits[0]
    var = tex_expr(lim[0])
    bounds = r"\limits_{%s}^{%s}" % (tex_expr(lim[1]), tex_expr(lim[2])) if len(lim) == 3 else ""
    pre = head + r"\int" + bounds + r" \Bigl("
    inner = _split(expr.function, pre, budget)
    if not inner:
        return None
    inner[-1] += r" \Bigr)\, d" + var
    return inner


def _over(num: sp.Basic, den: sp.Basic, head: str, budget: float) -> list[str] | None:
    """A quotient with a long denominator: num / ( denominator, broken )."""
    pre = head + tex_expr(num) + r" \Big/ "
    if isinstance(den, sp.Add):
        return _pack(PRINTER.add_terms(den), pre + r"\Bigl(", budget, close=r" \Bigr)")
    return _split(den, pre, budget)


def _open_power(expr: sp.Pow, head: str, budget: float) -> list[str]:
    """A power of a long sum (a square root included): ( sum, broken )^exponent."""
    exp = r"^{1/2}" if expr.exp == sp.Rational(1, 2) else "^{%s}" % tex_expr(expr.exp)
    return _pack(PRINTER.add_terms(expr.base), head + r"\Bigl(", budget, close=r" \Bigr)" + exp)
