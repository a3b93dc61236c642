"""Scenes: one concrete pendulum configuration, computed from the Results it names.

A scene file is TOML (read with the standard library's tomllib, never
evaluated):

    name = "…"
    results = ["<memoir>.<result>", …]
    [parameters]          # values of the Results' symbols, by name, SI units
    K = 1.0e-7

Only the dependency closure of the named Results is built.  Bad input (an
unreadable file, an unknown key or id, a missing or non-numeric parameter, a
value outside the symbol's domain) raises SceneError, reported in one line.
"""
from __future__ import annotations

import math
import tomllib
from dataclasses import dataclass
from pathlib import Path

import mpmath as mp
import sympy as sp

from . import registry


class SceneError(ValueError):
    """Bad scene input."""


@dataclass(frozen=True)
class Scene:
    name: str
    results: tuple[str, ...]
    parameters: tuple[tuple[str, float], ...]


def load(path: Path | str) -> Scene:
    try:
        data = tomllib.loads(Path(path).read_text(encoding="utf-8"))
    except OSError as exc:
        raise SceneError(f"cannot read scene {path}: {exc.strerror}") from None
    except tomllib.TOMLDecodeError as exc:
        raise SceneError(f"scene {path} is not valid TOML: {exc}") from None
    extra = set(data) - {"name", "results", "parameters"}
    if extra:
        raise SceneError(f"scene {path}: unknown keys {sorted(extra)}")
    ids = data.get("results")
    if not isinstance(ids, list) or not ids or not all(isinstance(i, str) for i in ids):
        raise SceneError(f"scene {path}: 'results' must be a non-empty list of result ids")
    params = data.get("parameters", {})
    if not isinstance(params, dict):
        raise SceneError(f"scene {path}: [parameters] must be a table")
    for key, val in params.items():
        if isinstance(val, bool) or not isinstance(val, (int, float)) or not math.isfinite(val):
            raise SceneError(f"scene {path}: parameter {key} must be a finite number")
    return Scene(str(data.get("name", Path(path).stem)), tuple(ids),
                 tuple(sorted((k, float(v)) for k, v in params.items())))


def _check_domain(sym: sp.Symbol, value: float) -> None:
    if sym.is_positive and not value > 0:
        raise SceneError(f"parameter {sym.name} = {value:g} is outside its domain (must be > 0)")
    if sym.is_nonnegative and value < 0:
        raise SceneError(f"parameter {sym.name} = {value:g} is outside its domain (must be >= 0)")
    if sym.is_integer and value != int(value):
        raise SceneError(f"parameter {sym.name} = {value:g} is outside its domain (must be an integer)")


def evaluate(scene: Scene, dps: int = 30) -> tuple[list[tuple[str, str, mp.mpf]], int]:
    """[(id, title, value)] and the number of Results built (the closure only)."""
    try:
        built = registry.build(scene.results)
    except registry.UnknownResult as exc:
        raise SceneError(str(exc)) from None
    values = dict(scene.parameters)
    out = []
    for rid in scene.results:
        expr = built[rid].derived
        subs = {}
        for sym in sorted(expr.free_symbols, key=lambda s: s.name):
            if sym.name not in values:
                raise SceneError(f"{rid} needs parameter {sym.name}, which the scene does not give")
            _check_domain(sym, values[sym.name])
            subs[sym] = sp.Float(repr(values[sym.name]), dps)
        with mp.workdps(dps):
            val = sp.N(expr.subs(subs), dps)
        if not val.is_number or val.has(sp.zoo, sp.nan):
            raise SceneError(f"{rid} has no numeric value for this scene")
        out.append((rid, built[rid].spec.title, mp.mpf(val)))
    return out, len(built)
