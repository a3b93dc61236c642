"""Sharing: a large part that several kernels of one file compute is emitted once.

When the forms of two or more functions of a file contain the same unit (a stable leaf or a
Piecewise, :func:`.plan.units`) of at least :data:`SHARE_MIN` nodes, the unit becomes a
function of its own, named after the first function that has it (``<name>_part<n>``):
``static`` in C, private in Python.  Every function that had a copy calls it instead.  The
part runs the statements the copy ran, in the same order, so no result changes by a bit.
The search repeats until no shared unit is left, so a part may call a smaller shared part.
"""
from __future__ import annotations

import functools
import re
from typing import Sequence

import sympy as sp
from sympy.core.function import AppliedUndef

from .plan import Grouped, units
from .printing import Function

SHARE_MIN = 1000    # nodes of a unit's expression tree: smaller parts are left in each kernel


def _size(e: sp.Basic, memo: dict) -> int:
    """The number of nodes of e's expression tree (each subtree counted once per occurrence)."""
    if e not in memo:
        memo[e] = 1 + sum(_size(a, memo) for a in e.args)
    return memo[e]


def _largest_shared(fns: Sequence[Function], min_size: int) -> sp.Basic | None:
    """The largest unit of at least min_size nodes found in two functions or more (ties: the
    one found first), or None."""
    memo: dict = {}
    where: dict = {}
    for i, f in enumerate(fns):
        for u in units(f.expr):
            if _size(u, memo) >= min_size:
                where.setdefault(u, []).append(i)
    common = [u for u, found in where.items() if len(found) > 1]
    if not common:
        return None
    return min(common, key=lambda u: (-memo[u], where[u][0], sp.srepr(u)))


def _part_name(owner: str, fns: Sequence[Function]) -> str:
    taken = sum(1 for f in fns if re.fullmatch(re.escape(owner) + r"_part\d+", f.name))
    return f"{owner}_part{taken + 1}"


def _split_off(fns: list[Function], unit: sp.Basic) -> list[Function]:
    """The functions with `unit` replaced by a call of a new part, and the part."""
    users = [f for f in fns if unit in units(f.expr)]
    mine = {f.name for f in users}
    value = unit.args[0] if isinstance(unit, Grouped) else unit
    params = tuple(p for p in users[0].params if p in value.free_symbols)
    name = _part_name(users[0].name, fns)
    call = sp.Function(name, real=True)(*params)
    out = [Function(f.name, f.params, f.expr.xreplace({unit: call}), f.callers, f.domain) if f.name in mine else f
           for f in fns]
    return out + [Function(name, params, value, tuple(f.name for f in users))]


def calls(expr: sp.Basic) -> list[str]:
    """The names of the parts expr calls, sorted."""
    return sorted({c.func.__name__ for c in expr.atoms(AppliedUndef)})


def _in_call_order(fns: Sequence[Function]) -> tuple[Function, ...]:
    """The kernels in their order, each preceded by the parts it calls not yet placed (a part
    after the parts it calls)."""
    by = {f.name: f for f in fns}
    out: list[Function] = []

    def place(f: Function) -> None:
        if any(g.name == f.name for g in out):
            return
        for name in calls(f.expr):
            place(by[name])
        out.append(f)
    for f in fns:
        if not f.callers:
            place(f)
    return tuple(out)


@functools.lru_cache(maxsize=16)
def share(functions: tuple[Function, ...], min_size: int = SHARE_MIN) -> tuple[Function, ...]:
    """The functions of one file, every unit of at least min_size nodes that two or more of
    them compute split off into a part they call; the parts placed before their first caller."""
    fns = list(functions)
    while (unit := _largest_shared(fns, min_size)) is not None:
        fns = _split_off(fns, unit)
    return _in_call_order(fns)


def part_doc(f: Function) -> str:
    """The comment or docstring of a shared part."""
    names = " and ".join([", ".join(f.callers[:-1]), f.callers[-1]] if len(f.callers) > 1 else f.callers)
    return f"A part of {names}, emitted once and called by each.\nIts errors are measured through them (see their figures)."
