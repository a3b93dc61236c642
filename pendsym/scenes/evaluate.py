"""The numbers of a scene's Results: each kept Result's derived form at the scene's values.

A form is evaluated as a numeric program (:mod:`pendsym.scenes.program`: its distinct nodes once each, by mpmath at
GUARD digits, rounded to 30, then to a double), stored in the cache by ``pendsym derive`` (:func:`programs`); a form
the compiler does not support by SymPy at 30 digits, or by its lambdified mpmath form when it holds Bessel functions or
an Integral (:data:`SLOW_FOR_EVALF`).  The scene's numbers are read as the decimals they print as (their shortest
repr) at 30 digits.
"""
from __future__ import annotations

import functools
import math

import mpmath as mp
import sympy as sp
from sympy.printing.pycode import MpmathPrinter

from ..result import Result
from ..scene import SceneError
from . import index, program

def build(ids: list[str]) -> dict[str, Result]:
    """The Results of the closure of ids (:func:`pendsym.scenes.index.results`)."""
    return index.results(ids, index.entries())


def derived_forms(ids: list[str]) -> tuple[dict[str, sp.Basic], int, int]:
    """({id: its derived form under its definitions}, the size of the ids' closure, how many Results the memoirs
    hold), from the index of the Results (:mod:`pendsym.scenes.index`): the forms are read from the shared cache
    under the keys a full derive uses, or derived here (only the sections of their closure imported) and stored."""
    entries = index.entries()
    values, closure_size = index.derived_values(ids, entries)
    return values, closure_size, len(entries)


def programs(ids: list[str]) -> tuple[dict[str, program.Program | sp.Basic], int, int]:
    """({id: the numeric program of its derived form (:mod:`pendsym.scenes.program`), or the SymPy form when the
    compiler does not support it}, the size of the ids' closure, how many Results the memoirs hold): from the cache
    (``pendsym derive`` stores the programs of every Result a scene effect names), or compiled here from the forms
    (:func:`derived_forms`) and stored."""
    entries = index.entries()
    return index.programs(ids, entries), len(index.closure(ids, entries)), len(entries)


def _value(expr: program.Program | sp.Expr, values: dict[str, float], rid: str) -> float:
    """The derived form at this scene: its program at GUARD digits, rounded to 30 (a form the compiler does not
    support: SymPy's evaluation at 30 digits)."""
    if isinstance(expr, program.Program):
        return _run(expr, values, rid)
    subs = {}
    for sym in expr.free_symbols:
        if sym.name not in values:
            raise SceneError(f"{rid} needs the symbol {sym.name}, which the memoir's scene mapping does not give")
        subs[sym] = sp.Float(repr(float(values[sym.name])), 30)
    with mp.workdps(30):
        val = _by_mpmath(expr, subs) if expr.has(*SLOW_FOR_EVALF) else sp.N(expr.subs(subs), 30)
    if not val.is_number or not val.is_real or val.has(sp.nan, sp.zoo, sp.oo, -sp.oo):
        raise SceneError(f"{rid} has no finite real value for this scene")
    out = float(val)
    if not math.isfinite(out):
        raise SceneError(f"{rid} = {val} for this scene: not a finite double")
    return out


# Forms that sp.N evaluates slowly (its adaptive evalf of Bessel functions takes minutes on the large forms of a
# holed blade) or inexactly (an integral without closed form): evaluated by mpmath at GUARD digits instead, the
# Bessel values at fixed arguments computed once, the integral by mpmath's quadrature.
SLOW_FOR_EVALF = (sp.Integral, sp.besselj, sp.bessely)
GUARD = 45


@functools.lru_cache(maxsize=32)
def _compiled(expr: sp.Expr):
    """(names of the free symbols, f): f(*values) evaluates expr by mpmath at the precision in force; the Bessel
    values that do not depend on an integration variable are computed once per call (not at each quadrature node).
    Compiled once per form (a form is evaluated again for the sensitivity)."""
    bound = {v for i in expr.atoms(sp.Integral) for v in i.variables}
    fixed = sorted((f for f in expr.atoms(sp.besselj, sp.bessely) if not f.free_symbols & bound), key=sp.srepr)
    stand = [sp.Symbol(f"bessel_value_{n}") for n in range(len(fixed))]
    syms = sorted(expr.free_symbols, key=lambda x: x.name)
    values_of = _lambdify_mp(sp.Tuple(*fixed), syms)
    main = _lambdify_mp(expr.xreplace(dict(zip(fixed, stand))), [*syms, *stand])

    def f(*args):
        return main(*args, *values_of(*args))
    return tuple(x.name for x in syms), f


def _lambdify_mp(expr: sp.Basic, symbols: list[sp.Symbol]):
    """:func:`pendsym.verify.lambdify_mp` with the terms printed in the tree's order, not sorted (sorting the terms
    of a holed blade's large forms was most of a warm scene's time; the same terms are summed)."""
    printer = MpmathPrinter({"fully_qualified_modules": False, "inline": True, "allow_unknown_functions": True,
                             "user_functions": {}, "order": "none"})
    return sp.lambdify(tuple(symbols), expr, modules="mpmath", printer=printer)


def _by_mpmath(expr: sp.Expr, subs: dict) -> sp.Float:
    """expr at the numbers ``subs`` by mpmath at GUARD digits (:func:`_compiled`)."""
    names, f = _compiled(expr)
    by_name = {sym.name: value for sym, value in subs.items()}
    with mp.workdps(GUARD):
        return sp.Float(f(*[mp.mpf(by_name[n]) for n in names]), 30)


def _inputs(prog: program.Program, values: dict[str, float], rid: str) -> list[mp.mpf]:
    """The program's inputs (call it at GUARD digits: mpf rounds to the precision in force)."""
    missing = [n for n in prog.names if n not in values]
    if missing:
        raise SceneError(f"{rid} needs the symbol {missing[0]}, which the memoir's scene mapping does not give")
    # the decimal the scene's number reads as (its shortest repr), at 30 digits, as the SymPy path substitutes it
    return [mp.mpf(sp.Float(repr(float(values[n])), 30)) for n in prog.names]


def _at(prog: program.Program, args: list[mp.mpf], rid: str):
    """The program at ``args`` (in the order of its names), at the precision in force."""
    try:
        return program.run(prog, dict(zip(prog.names, args)))
    except (ZeroDivisionError, ValueError, OverflowError) as exc:
        raise SceneError(f"{rid} has no finite real value for this scene ({exc})") from None


def _run(prog: program.Program, values: dict[str, float], rid: str) -> float:
    """The program at this scene at GUARD digits, rounded to 30 digits, then to a double."""
    with mp.workdps(GUARD):
        val = _at(prog, _inputs(prog, values, rid), rid)
        if isinstance(val, mp.mpc):
            if val.imag != 0:
                raise SceneError(f"{rid} has no finite real value for this scene")
            val = val.real
    val = sp.Float(val, 30)
    if not val.is_finite:
        raise SceneError(f"{rid} has no finite real value for this scene")
    out = float(val)
    if not math.isfinite(out):
        raise SceneError(f"{rid} = {val} for this scene: not a finite double")
    return out


def _log_slope(expr: program.Program | sp.Expr, values: dict[str, float], exponents, rid: str) -> float:
    """d log(expr)/d log g = Σ p_s s ∂log(expr)/∂s over the symbols s ∝ g^p: a program's by mpmath's ``diff`` at
    GUARD digits (:func:`_log_slope_of_program`); a SymPy form's by symbolic derivatives at 30 digits."""
    if isinstance(expr, program.Program):
        return _log_slope_of_program(expr, values, exponents, rid)
    if expr.has(*SLOW_FOR_EVALF):
        return _log_slope_by_mpmath(expr, values, exponents)
    out, base = 0.0, None
    for sym in expr.free_symbols:
        p = exponents.get(sym.name, 0)
        if p:
            base = _value(expr, values, rid) if base is None else base      # the form's value, evaluated once
            out += p * values[sym.name] * _value(sp.diff(expr, sym), values, rid) / base
    return out


def _log_slope_by_mpmath(expr: sp.Expr, values: dict[str, float], exponents) -> float:
    """d log(expr)/d log g for a form :data:`SLOW_FOR_EVALF`: the derivative in t of log expr(s e^{p_s t}) at t = 0,
    the compiled form (:func:`_compiled`) differentiated by mpmath (``mp.diff``, GUARD digits)."""
    names, f = _compiled(expr)
    with mp.workdps(GUARD):
        base = [mp.mpf(values[n]) for n in names]
        powers = [mp.mpf(exponents.get(n, 0)) for n in names]

        def log_at(t):
            return mp.log(f(*[b * mp.exp(p * t) for b, p in zip(base, powers)]))
        return float(mp.diff(log_at, 0))


def _log_slope_of_program(prog: program.Program, values: dict[str, float], exponents, rid: str) -> float:
    """d log(expr)/d log g: the derivative in t of log expr(s e^{p_s t}) at t = 0 (``mp.diff``, GUARD digits)."""
    with mp.workdps(GUARD):
        base = _inputs(prog, values, rid)
        powers = [mp.mpf(exponents.get(n, 0)) for n in prog.names]

        def log_at(t):
            return mp.log(_at(prog, [b * mp.exp(p * t) for b, p in zip(base, powers)], rid))
        return float(mp.diff(log_at, 0))
