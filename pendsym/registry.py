"""The DAG of Results: discover the memoirs, take a dependency closure, build lazily.

Memoirs are plug-ins: every sub-package of a memoir package (``derivations``
by default; ``PENDSYM_MEMOIR_PACKAGES``, a comma-separated list, names others)
that defines ``MEMOIR = pendsym.memoir.Memoir(...)`` is a memoir.  Nothing
here names one, and nothing is registered as a side effect of an import: the
scan is a pure function of the package names.
"""
from __future__ import annotations

import difflib
import re
import importlib
import os
import pkgutil
from functools import lru_cache
from graphlib import CycleError, TopologicalSorter
from types import MappingProxyType
from typing import Iterable, Mapping

from .memoir import Memoir
from .result import Result, Spec

DEFAULT_PACKAGES = ("derivations",)


class UnknownResult(KeyError):
    """An id (or memoir key) that no memoir defines; suggests the nearest ones."""

    def __init__(self, name: str, known: Iterable[str] = ()):
        super().__init__(name)
        known = sorted(known)
        # the ids that extend the name (with numbers read without their leading zeros: eq43 → eq043.*)
        extending = [k for k in known if _unpadded(k).startswith(_unpadded(name) + ".")]
        self.near = tuple(extending[:3]) or tuple(difflib.get_close_matches(name, known, n=3, cutoff=0.6))
        if not self.near and known:
            self.near = tuple(k for k in known if k.startswith(name.rsplit(".", 1)[0] + "."))[:3]

    def __str__(self) -> str:  # one line, for the CLI
        hint = f" (nearest: {', '.join(self.near)})" if self.near else ""
        return f"unknown result id: {self.args[0]}{hint}"


def _unpadded(name: str) -> str:
    """The name with the leading zeros of its numbers dropped (eq043 → eq43)."""
    return re.sub(r"(?<!\d)0+(?=\d)", "", name)


def packages() -> tuple[str, ...]:
    """The packages whose sub-packages are memoirs."""
    env = os.environ.get("PENDSYM_MEMOIR_PACKAGES", "")
    names = tuple(p.strip() for p in env.split(",") if p.strip())
    return names or DEFAULT_PACKAGES


@lru_cache(maxsize=8)
def discover(pkgs: tuple[str, ...]) -> Mapping[str, Memoir]:
    """Every memoir found in the packages, by key, sorted by key."""
    found: dict[str, Memoir] = {}
    for pkg_name in pkgs:
        pkg = importlib.import_module(pkg_name)
        for info in sorted(pkgutil.iter_modules(pkg.__path__), key=lambda i: i.name):
            if not info.ispkg:
                continue
            memoir = getattr(importlib.import_module(f"{pkg_name}.{info.name}"), "MEMOIR", None)
            if not isinstance(memoir, Memoir):
                continue
            if memoir.key in found:
                raise ValueError(f"two memoirs with the key {memoir.key}")
            found[memoir.key] = memoir
    return MappingProxyType(dict(sorted(found.items())))


def memoirs() -> Mapping[str, Memoir]:
    """The memoirs of this installation, by key."""
    return discover(packages())


def memoir(key: str) -> Memoir:
    known = memoirs()
    if key not in known:
        raise UnknownResult(key, known)
    return known[key]


def memoir_specs(key: str) -> tuple[Spec, ...]:
    """The Specs of one memoir, in the memoir's order."""
    return memoir(key).specs


def all_specs(keys: Iterable[str] | None = None) -> dict[str, Spec]:
    """Specs by id, memoir by memoir; duplicate ids are an error."""
    out: dict[str, Spec] = {}
    for key in (memoirs() if keys is None else keys):
        for spec in memoir_specs(key):
            if spec.id in out:
                raise ValueError(f"duplicate result id {spec.id}")
            if spec.memoir != key:
                raise ValueError(f"{spec.id} claims memoir {spec.memoir}, found in {key}")
            out[spec.id] = spec
    return out


def memoir_of(result_id: str) -> str:
    key = result_id.split(".", 1)[0]
    if key not in memoirs():
        raise UnknownResult(result_id, [s for m in memoirs().values() for s in (x.id for x in m.specs)])
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
            raise UnknownResult(rid, specs)
        need[rid] = specs[rid].deps
        stack.extend(specs[rid].deps)
    order = {sid: i for i, sid in enumerate(specs)}  # memoir order breaks ties
    sorter = TopologicalSorter({r: sorted(d, key=order.__getitem__) for r, d in need.items()})
    try:
        sorter.prepare()
    except CycleError as exc:
        raise ValueError(f"dependency cycle: {exc.args[1]}") from None
    out: list[str] = []
    while sorter.is_active():
        ready = sorted(sorter.get_ready(), key=order.__getitem__)
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
        memoirs = sorted({memoir_of(i) for i in ids})
    specs = all_specs(memoirs)
    wanted = list(specs) if ids is None else ids
    built: dict[str, Result] = {}
    for rid in closure(wanted, specs):
        built[rid] = build_one(specs[rid], built)
    return built
