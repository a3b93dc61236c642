"""The DAG of Results: find Specs, take a dependency closure, build lazily.

The memoirs are named in one static table; importing a memoir's package gives
its ``SPECS`` tuple.  Nothing is registered as a side effect of an import, so
the order of imports cannot change what is found.
"""
from __future__ import annotations

import importlib
from graphlib import CycleError, TopologicalSorter
from typing import Iterable, Mapping

from .result import Result, Spec

MEMOIRS: Mapping[str, str] = {
    "charbonnier1908": "derivations.charbonnier1908",
    "haag1935": "derivations.haag1935",
    "cellerier": "derivations.cellerier",
}


class UnknownResult(KeyError):
    """An id that no memoir defines."""

    def __str__(self) -> str:  # one line, for the CLI
        return f"unknown result id: {self.args[0]}"


def memoir_specs(memoir: str) -> tuple[Spec, ...]:
    """The Specs of one memoir, in the memoir's order."""
    if memoir not in MEMOIRS:
        raise UnknownResult(memoir)
    return tuple(importlib.import_module(MEMOIRS[memoir]).SPECS)


def all_specs(memoirs: Iterable[str] | None = None) -> dict[str, Spec]:
    """Specs by id, memoir by memoir in table order; duplicate ids are an error."""
    out: dict[str, Spec] = {}
    for key in (MEMOIRS if memoirs is None else memoirs):
        for spec in memoir_specs(key):
            if spec.id in out:
                raise ValueError(f"duplicate result id {spec.id}")
            if spec.memoir != key:
                raise ValueError(f"{spec.id} claims memoir {spec.memoir}, found in {key}")
            out[spec.id] = spec
    return out


def memoir_of(result_id: str) -> str:
    key = result_id.split(".", 1)[0]
    if key not in MEMOIRS:
        raise UnknownResult(result_id)
    return key


def closure(ids: Iterable[str], specs: Mapping[str, Spec]) -> list[str]:
    """The ids and all they depend on, dependencies first (deterministic order)."""
    need: dict[str, tuple[str, ...]] = {}
    stack = list(ids)
    while stack:
        rid = stack.pop()
        if rid in need:
            continue
        if rid not in specs:
            raise UnknownResult(rid)
        need[rid] = specs[rid].deps
        stack.extend(specs[rid].deps)
    order = list(specs)  # memoir order breaks ties
    sorter = TopologicalSorter({r: sorted(d, key=order.index) for r, d in need.items()})
    try:
        sorter.prepare()
    except CycleError as exc:
        raise ValueError(f"dependency cycle: {exc.args[1]}") from None
    out: list[str] = []
    while sorter.is_active():
        ready = sorted(sorter.get_ready(), key=order.index)
        out.extend(ready)
        sorter.done(*ready)
    return out


def build_one(spec: Spec, built: Mapping[str, Result]) -> Result:
    """Build one Result from its already built dependencies."""
    deps = {d: built[d] for d in spec.deps}
    derived = spec.derive(deps)
    printed = spec.printed() if spec.printed is not None else None
    return Result(spec=spec, derived=derived, printed=printed, deps=deps)


def build(ids: Iterable[str] | None = None, memoirs: Iterable[str] | None = None) -> dict[str, Result]:
    """Build the requested Results (all, when ids is None) and only their closure."""
    if ids is not None:
        ids = list(ids)
        memoirs = sorted({memoir_of(i) for i in ids}, key=list(MEMOIRS).index)
    specs = all_specs(memoirs)
    wanted = list(specs) if ids is None else ids
    built: dict[str, Result] = {}
    for rid in closure(wanted, specs):
        built[rid] = build_one(specs[rid], built)
    return built
