"""Scenes: one concrete pendulum configuration, computed from the Results it names.

This is the memoir-minded form (a list of Result ids); a scene that describes hardware
(bob, suspension, support…) is read by :mod:`pendsym.scenes` (see docs/scenes.md).  A file
with a ``results`` key is of this form, any other is a hardware scene.

A scene file is TOML (read with the standard library's tomllib, never
evaluated), at most 1 MiB of UTF-8:

    name = "…"
    results = ["<memoir>.<result>", …]
    [parameters]            # values of the Results' symbols, by name, SI units
    K = 1.0e-7

A scene whose Results come from several memoirs gives each memoir's parameters in
its own table, ``[parameters.<memoir key>]``: a symbol belongs to its memoir (the
same letter means different things in different memoirs).

Only the dependency closure of the named Results is built.  Bad input (an
unreadable or oversized file, bytes that are not UTF-8, nesting too deep, an unknown
key, id or parameter, a missing or non-numeric parameter, a value outside the
symbol's domain or the Result's declared range, a result that is not a finite
number) raises SceneError, reported in one line.
"""
from __future__ import annotations

import math
import tomllib
import unicodedata
from dataclasses import dataclass
from pathlib import Path

import mpmath as mp
import sympy as sp

from . import registry

MAX_BYTES = 1 << 20


class SceneError(ValueError):
    """Bad scene input."""


@dataclass(frozen=True)
class Scene:
    name: str
    results: tuple[str, ...]
    parameters: tuple[tuple[str, tuple[tuple[str, float], ...]], ...]   # (memoir key or "", ((name, value), …))


def printable(text: str) -> str:
    """Text safe for a terminal: control and bidirectional-format characters shown as escapes."""
    return "".join(ch if unicodedata.category(ch) not in ("Cc", "Cf") else f"\\u{ord(ch):04x}" for ch in text)


def _read(path: Path | str) -> str:
    try:
        with open(path, "rb") as fh:
            raw = fh.read(MAX_BYTES + 1)
    except OSError as exc:
        raise SceneError(f"cannot read scene {printable(str(path))}: {exc.strerror}") from None
    if len(raw) > MAX_BYTES:
        raise SceneError(f"scene {printable(str(path))} is larger than {MAX_BYTES // 1024} KiB")
    try:
        return raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise SceneError(f"scene {printable(str(path))} is not UTF-8 text (byte {exc.start})") from None


def _numbers(where: str, table) -> tuple[tuple[str, float], ...]:
    if not isinstance(table, dict):
        raise SceneError(f"{where} must be a table of numbers")
    for key, val in table.items():
        if isinstance(val, bool) or not isinstance(val, (int, float)) or not math.isfinite(val):
            raise SceneError(f"{where}: parameter {printable(key)} must be a finite number")
    return tuple(sorted((k, float(v)) for k, v in table.items()))


def parse(path: Path | str) -> dict:
    """The file's TOML as a dict (size, encoding, syntax and nesting checked; nothing evaluated)."""
    text = _read(path)
    where = f"scene {printable(str(path))}"
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise SceneError(f"{where} is not valid TOML: {printable(str(exc))}") from None
    except RecursionError:
        raise SceneError(f"{where} is nested too deeply") from None


def is_hardware(data: dict) -> bool:
    """A hardware scene (pendsym.scenes: bob, suspension, …) rather than a list of Result ids."""
    return "results" not in data


def load(path: Path | str, data: dict | None = None) -> Scene:
    data = parse(path) if data is None else data
    where = f"scene {printable(str(path))}"
    extra = set(data) - {"name", "results", "parameters"}
    if extra:
        raise SceneError(f"{where}: unknown keys {[printable(k) for k in sorted(extra)]}")
    ids = data.get("results")
    if not isinstance(ids, list) or not ids or not all(isinstance(i, str) for i in ids):
        raise SceneError(f"{where}: 'results' must be a non-empty list of result ids")
    name = data.get("name", Path(path).stem)
    if not isinstance(name, str) or any(unicodedata.category(ch) in ("Cc", "Cf") for ch in name):
        raise SceneError(f"{where}: 'name' must be text without control characters")
    params = data.get("parameters", {})
    if not isinstance(params, dict):
        raise SceneError(f"{where}: [parameters] must be a table")
    memoirs = sorted({i.split(".", 1)[0] for i in ids})
    if len(memoirs) > 1 or any(isinstance(v, dict) for v in params.values()):
        unknown = set(params) - set(memoirs)
        if unknown:
            raise SceneError(f"{where}: the Results come from {', '.join(memoirs)}: give each memoir's parameters "
                             f"as [parameters.<memoir>] (not {', '.join(printable(k) for k in sorted(unknown))})")
        tables = tuple((m, _numbers(f"{where}: [parameters.{m}]", params.get(m, {}))) for m in memoirs)
    else:
        tables = (("", _numbers(f"{where}: [parameters]", params)),)
    return Scene(name, tuple(ids), tables)


def _check_domain(rid: str, sym: sp.Symbol, value: float, declared: dict) -> None:
    if sym.is_positive and not value > 0:
        raise SceneError(f"parameter {sym.name} = {value:g} is outside its domain (must be > 0)")
    if sym.is_nonnegative and value < 0:
        raise SceneError(f"parameter {sym.name} = {value:g} is outside its domain (must be >= 0)")
    if sym.is_integer and value != int(value):
        raise SceneError(f"parameter {sym.name} = {value:g} is outside its domain (must be an integer)")
    if sym.name in declared:
        lo, hi = declared[sym.name]
        if not lo <= value <= hi:
            raise SceneError(f"parameter {sym.name} = {value:g} is outside the range {rid} declares "
                             f"([{lo:g}, {hi:g}])")


def _parameters_of(scene: Scene, memoir: str) -> dict[str, float]:
    for key, table in scene.parameters:
        if key in ("", memoir):
            return dict(table)
    return {}


def evaluate(scene: Scene, dps: int = 30) -> tuple[list[tuple[str, str, mp.mpf]], int]:
    """[(id, title, value)] and the number of Results in the closure of the scene's Results.  The forms, titles and
    declared ranges come from the index of the Results and the cache (:mod:`pendsym.scenes.index`): no memoir is
    imported when a derive stored them; otherwise only the sections of the closure are, and the closure is built."""
    from .scenes import index          # the index of the Results, read without importing a memoir
    try:
        entries = index.entries()
        for rid in scene.results:
            if rid not in entries:
                raise registry.UnknownResult(rid, entries)
        forms, n_built = index.derived_values(scene.results, entries)
    except registry.UnknownResult as exc:
        raise SceneError(str(exc)) from None
    used: dict[str, set[str]] = {}
    out = []
    for rid in scene.results:
        memoir = rid.split(".", 1)[0]
        values = _parameters_of(scene, memoir)
        declared = {name: (lo, hi) for name, lo, hi in entries[rid].ranges}
        expr = forms[rid]
        subs = {}
        for sym in sorted(expr.free_symbols, key=lambda s: s.name):
            if sym.name not in values:
                raise SceneError(f"{rid} needs parameter {sym.name}, which the scene does not give")
            _check_domain(rid, sym, values[sym.name], declared)
            subs[sym] = sp.Float(repr(values[sym.name]), dps)
            used.setdefault(memoir, set()).add(sym.name)
        with mp.workdps(dps):
            val = sp.N(expr.subs(subs), dps)
        if not val.is_number or val.has(sp.zoo, sp.nan, sp.oo, -sp.oo) or not val.is_real:
            raise SceneError(f"{rid} has no finite real value for this scene")
        value = mp.mpf(val)
        if not mp.isfinite(value) or not math.isfinite(float(value)):
            raise SceneError(f"{rid} = {mp.nstr(value, 5)} for this scene: not a finite double")
        out.append((rid, entries[rid].title, value))
    for key, table in scene.parameters:
        memoirs = [key] if key else sorted({i.split(".", 1)[0] for i in scene.results})
        unused = {name for name, _ in table} - set().union(*(used.get(m, set()) for m in memoirs))
        if unused:
            raise SceneError(f"parameters not used by the scene's Results: {', '.join(printable(u) for u in sorted(unused))}")
    return out, n_built
