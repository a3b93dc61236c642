"""Scenes of real instruments: a pendulum described as hardware (TOML), its period with an
error budget, built from only the Results it needs.  See docs/scenes.md.

    load(path)   → the validated :class:`pendsym.scenes.schema.Scene` (one-line SceneError otherwise)
    solve(scene) → :class:`pendsym.scenes.budget.Budget`
    report(path, as_json) → the text (or JSON) the CLI prints

Memoirs contribute effects through ``derivations/<memoir>/scene_effects.py``
(:mod:`pendsym.scenes.effects`).  A scene reads its Results' forms from the cache through the tree's index
(:mod:`pendsym.scenes.index`, stored by ``pendsym derive``) and imports no memoir section when the cache holds
them; from a cold cache it imports every memoir once (to index them) and derives only the closure it needs.
"""
from __future__ import annotations

import json
from pathlib import Path

from pydantic import ValidationError

from .. import cache, keys, registry
from ..scene import SceneError, parse, printable
from . import schema
from .budget import Budget, solve, text, as_json

__all__ = ["load", "from_data", "solve", "report", "Budget", "SceneError"]


def _short(value, limit: int = 60) -> str:
    try:
        s = repr(value)
    except RecursionError:
        s = "(nested too deeply)"
    s = printable(s)
    return s if len(s) <= limit else s[:limit - 1] + "…"


def from_data(data: dict, where: str = "scene") -> schema.Scene:
    """Validate a parsed TOML table; the first error as one line naming the key, the value and the range."""
    try:
        return schema.Scene.model_validate(data)
    except ValidationError as exc:
        errs = exc.errors(include_url=False)
        first = errs[0]
        path = [p for i, p in enumerate(first["loc"])          # suspension.E, not suspension.blade.E
                if not (i and first["loc"][i - 1] == "suspension" and p in ("knife", "thread", "blade"))]
        loc = ".".join(printable(str(p)) for p in path) or "(top level)"
        msg = printable(first["msg"]).replace("\n", " ")
        if first["type"] == "value_error":          # the consistency checks write their own line
            line = f"{where}: {msg.removeprefix('Value error, ')}"
        elif first["type"] == "missing":
            line = f"{where}: {loc}: missing (required)"
        elif first["type"] == "extra_forbidden":
            line = f"{where}: {loc}: unknown key"
        else:
            desc = _description(first["loc"])
            line = f"{where}: {loc} = {_short(first.get('input'))}: {msg}" + (f" — expected {desc}" if desc else "")
        more = f" (and {len(errs) - 1} more)" if len(errs) > 1 else ""
        raise SceneError(line.replace("\n", " ") + more) from None
    except RecursionError:
        raise SceneError(f"{where} is nested too deeply") from None


def _description(loc: tuple) -> str:
    """The schema's description of the field at loc (its unit and range), if any."""
    model, desc = schema.Scene, ""
    for part in loc:
        fields = getattr(model, "model_fields", None)
        if not fields or part not in fields:
            if isinstance(part, str) and part in ("knife", "thread", "blade"):
                model = {"knife": schema.Knife, "thread": schema.Thread, "blade": schema.Blade}[part]
            continue
        info = fields[part]
        desc = info.description or ""
        ann = info.annotation
        for cand in (getattr(ann, "__args__", None) or (ann,)):
            if isinstance(cand, type) and issubclass(cand, schema.BaseModel):
                model = cand
                break
    return printable(desc)


def remember(key: str, compute):
    """The answer from the shared cache, or computed and stored."""
    return cache.memo(key, compute)


def load(path: Path | str) -> schema.Scene:
    data = parse(path)
    return from_data(data, f"scene {printable(str(path))}")


def solved(sc: schema.Scene, where: str) -> Budget:
    """:func:`solve`, an error while solving named by the scene's file as the loading errors are."""
    try:
        return solve(sc)
    except SceneError as exc:
        raise SceneError(f"{where}: {exc}") from None


def pdf(path: Path | str, out: Path | str, data: dict | None = None) -> Path:
    """The one-page PDF of the scene's budget (see :mod:`pendsym.scenes.page`)."""
    from . import page
    data = parse(path) if data is None else data
    where = f"scene {printable(str(path))}"
    sc = from_data(data, where)
    return page.write(solved(sc, where), printable(sc.name or Path(path).stem), out)


def report(path: Path | str, as_json_out: bool = False, data: dict | None = None) -> str:
    """The answer and its budget, as text or JSON; everything is computed before anything is returned."""
    data = parse(path) if data is None else data
    where = f"scene {printable(str(path))}"
    sc = from_data(data, where)
    name = printable(sc.name or Path(path).stem)

    def answer() -> str:
        b = solved(sc, where)
        return json.dumps(as_json(b, name), indent=1, allow_nan=False) if as_json_out else text(b, name)
    # the answer is a pure function of the scene and of every source file (tree_key, computed
    # without importing a memoir): a repeated scene is read back without importing the memoirs
    key = keys.digest(("scene answer", keys.tree_key(registry.packages()), sc.model_dump_json(), name,
                       "json" if as_json_out else "text"))
    return remember(key, answer)
