"""The memoirs' Results as a scene needs them, read without importing a memoir.

For every Result id: its section module, its dependencies, the key under which ``make derive`` stores its forms
(the ``built`` key of :class:`pendsym.stages.Plan`) and its definitions (``Spec.defs``, under which its derived
value is taken).  The index is a pure function of the sources: it is stored in the cache under the tree's key
(:func:`pendsym.keys.tree_key`), by ``pendsym derive`` after a full derive and otherwise by the first scene that
needs it.  A scene then reads its Results' forms from the cache under their keys and imports a memoir's sections
only to derive a form the cache does not hold (a cold cache), and then only the sections of that form's closure.
"""
from __future__ import annotations

import hashlib
import importlib
from dataclasses import dataclass
from pathlib import Path
from typing import Iterable, Mapping

import sympy as sp

from .. import cache, keys, registry
from ..result import Result, Spec
from . import program

FORMAT = "3"          # bump when the meaning of an entry changes


@dataclass(frozen=True)
class Entry:
    """What a scene needs to know of one Result without importing its memoir."""

    section: str                                   # the module whose ``specs()`` gives its Spec
    deps: tuple[str, ...]
    key: str                                       # the cache key of its (derived, printed) forms
    has_defs: bool                                 # whether its Spec has definitions (stored apart: :func:`defs`)
    title: str = ""                                # its Spec's title
    ranges: tuple[tuple[str, float, float], ...] = ()   # its kernel's declared ranges (name, lo, hi), if any


def index_key(pkgs: tuple[str, ...]) -> str:
    """The key of the index of the memoirs in ``pkgs``: every source file (no memoir imported)."""
    return keys.digest(("scene index", FORMAT, keys.tree_key(pkgs)))


def program_key(entry: Entry) -> str:
    """The key of a Result's numeric program (:mod:`pendsym.scenes.program`): its forms' key, and the source of the
    compiler (a change to it compiles again)."""
    return keys.digest(("scene program", FORMAT, _PROGRAM_SOURCE, entry.key))


_PROGRAM_SOURCE = hashlib.sha256(Path(program.__file__).read_bytes()).hexdigest()


def defs_key(entry: Entry) -> str:
    """The key of a Result's definitions: they are its Spec's, which its key covers (its section's source)."""
    return keys.digest(("scene defs", FORMAT, entry.key))


def compute(pkgs: tuple[str, ...]) -> dict[str, Entry]:
    """The index, from the memoirs themselves (imports and builds every section's Specs).  The definitions of the
    Results that have some are stored apart, each under :func:`defs_key` (a scene reads one or two), by
    :func:`remember` or by :func:`defs` when first needed."""
    found = registry.discover(pkgs)
    specs = registry.all_specs(found)
    order = registry.closure(list(specs), specs)
    section = {s.id: sec.module for m in found.values() for sec in m.sections for s in sec.specs}
    ks = keys.result_keys(section, {i: specs[i].deps for i in order}, order, ("pendsym", *pkgs))
    return {rid: Entry(section[rid], specs[rid].deps, keys.digest(("built", "", ks[rid])), bool(specs[rid].defs),
                       specs[rid].title, _ranges(specs[rid])) for rid in order}


def _ranges(spec: Spec) -> tuple[tuple[str, float, float], ...]:
    """The kernel's declared ranges of its arguments (the id-list scene refuses a value outside them)."""
    return tuple((a.name, float(a.lo), float(a.hi)) for a in spec.kernel.args) if spec.kernel else ()


def remember(pkgs: tuple[str, ...] | None = None) -> Mapping[str, Entry]:
    """The index, the definitions of every Result that has some, and the numeric programs of the Results the
    memoirs' scene effects name, stored (``pendsym derive`` calls it, with the memoirs already imported, so that the
    scenes that follow import none and print no form)."""
    pkgs = registry.packages() if pkgs is None else pkgs
    found = entries(pkgs)
    missing = [rid for rid, entry in found.items() if entry.has_defs and cache.load(defs_key(entry)) is cache.MISSING]
    if missing:
        specs = registry.all_specs(registry.discover(pkgs))
        for rid in missing:
            cache.store(defs_key(found[rid]), specs[rid].defs)
    from .effects import discover, discover_coefficients
    named = {rid for e in (*discover(pkgs), *discover_coefficients(pkgs)) for rid in (e.result, *e.uses)}
    programs(sorted(named & set(found)), found)
    return found


def defs(rid: str, index: Mapping[str, Entry]) -> tuple:
    """The definitions of Result rid (Spec.defs), from the cache, or from its section (imported) and stored."""
    entry = index[rid]
    if not entry.has_defs:
        return ()
    return cache.memo(defs_key(entry), lambda: _specs([entry.section])[rid].defs)


def entries(pkgs: tuple[str, ...] | None = None) -> Mapping[str, Entry]:
    """The index from the cache, or computed and stored."""
    pkgs = registry.packages() if pkgs is None else pkgs
    return cache.memo(index_key(pkgs), lambda: compute(pkgs))


def closure(ids: Iterable[str], index: Mapping[str, Entry]) -> list[str]:
    """The ids and all they depend on, dependencies first, in the order a derive takes them: the registry's
    :func:`pendsym.registry.closure` over the index's entries (each has its ``deps``; the index is in plan order)."""
    return registry.closure(ids, index)


def _specs(sections: Iterable[str]) -> dict[str, Spec]:
    """The Specs of the given section modules only (each imported, its ``specs()`` called)."""
    return {s.id: s for mod in sorted(set(sections)) for s in importlib.import_module(mod).specs()}


def results(ids: Iterable[str], index: Mapping[str, Entry]) -> dict[str, Result]:
    """The Results of the closure of ids, their forms from the cache under the keys a full derive uses, or derived
    here and stored; only the sections of that closure are imported."""
    order = closure(ids, index)
    specs = _specs(index[rid].section for rid in order)
    built: dict[str, Result] = {}
    for rid in order:
        spec = specs[rid]

        def derive(spec=spec):
            r = registry.build_one(spec, built)
            return r.derived, r.printed
        derived, printed = cache.memo(index[rid].key, derive)
        built[rid] = Result(spec=spec, derived=derived, printed=printed, deps={d: built[d] for d in spec.deps})
    return built


def derived_values(ids: Iterable[str], index: Mapping[str, Entry]) -> tuple[dict[str, sp.Basic], int]:
    """({id: its derived form under its definitions}, the size of the closure of ids).

    A form the cache holds is read alone (no section imported, no dependency read); the others come from
    :func:`results` of their closure (derived and stored when missing)."""
    ids = list(dict.fromkeys(ids))
    size = len(closure(ids, index))
    forms: dict[str, sp.Basic] = {}
    for rid in ids:
        got = cache.load(index[rid].key)
        if got is not cache.MISSING:
            forms[rid] = got[0]
    missing = [rid for rid in ids if rid not in forms]
    if missing:
        built = results(missing, index)
        forms.update({rid: built[rid].derived for rid in missing})
    out = {}
    for rid in ids:
        given = defs(rid, index)
        out[rid] = forms[rid].subs(dict(given), simultaneous=True) if given else forms[rid]
    return out, size


def programs(ids: Iterable[str], index: Mapping[str, Entry]) -> dict[str, "program.Program | sp.Basic"]:
    """{id: the numeric program of its derived form under its definitions}, from the cache, or compiled from the form
    (:func:`derived_values`) and stored; a form the compiler does not support is given as the SymPy form itself (and
    ``None`` is stored for it, so that it is not compiled again)."""
    ids = list(dict.fromkeys(ids))
    out: dict[str, program.Program | sp.Basic] = {}
    unsupported = []
    for rid in ids:
        got = cache.load(program_key(index[rid]))
        if got is None:
            unsupported.append(rid)
        elif got is not cache.MISSING:
            out[rid] = got
    missing = [rid for rid in ids if rid not in out]
    if missing:
        forms, _ = derived_values(missing, index)
        for rid in missing:
            if rid in unsupported:
                out[rid] = forms[rid]
                continue
            try:
                compiled = program.compile(forms[rid])
            except program.Unsupported:
                compiled = None
            cache.store(program_key(index[rid]), compiled)
            out[rid] = forms[rid] if compiled is None else compiled
    return out
