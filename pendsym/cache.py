"""A disk cache for pure computations (independent checks, kernel forms).

An entry is keyed by the content hash of everything that determines it: the
Result's id and expressions, the level, the versions of SymPy and mpmath, and
the source text of the engine and of the memoir's derivations.  Any change
of code therefore misses the cache; a hit returns exactly what the
computation would return.  The cache lives in ``.cache/pendsym`` under the
working directory (PENDSYM_CACHE overrides it; PENDSYM_CACHE=off disables it).
"""
from __future__ import annotations

import hashlib
import importlib
import os
import pickle
import tempfile
from functools import lru_cache
from pathlib import Path
from typing import Callable, TypeVar

import mpmath
import sympy

T = TypeVar("T")


def directory() -> Path | None:
    env = os.environ.get("PENDSYM_CACHE", "")
    if env.lower() == "off":
        return None
    return Path(env) if env else Path.cwd() / ".cache" / "pendsym"


# Parts of the engine that cannot change a check's evidence (they only emit files).
EMITTERS = ("emit", "templates", "cli.py", "bench.py", "derive.py")


@lru_cache(maxsize=None)
def code_hash(package: str, exclude: tuple[str, ...] = ()) -> str:
    """sha256 of the source files of a package (sorted by path), less the excluded parts."""
    mod = importlib.import_module(package)
    root = Path(next(iter(mod.__path__)))
    h = hashlib.sha256()
    for f in sorted(root.rglob("*")):
        rel = f.relative_to(root).parts
        if rel and rel[0] in exclude:
            continue
        if f.suffix in (".py", ".j2") and "__pycache__" not in f.parts:
            h.update(str(f.relative_to(root)).encode())
            h.update(f.read_bytes())
    return h.hexdigest()


def key(*parts: str, packages: tuple[str, ...] = ("pendsym",), exclude: tuple[str, ...] = ()) -> str:
    h = hashlib.sha256()
    for p in (sympy.__version__, mpmath.__version__, *(code_hash(pk, exclude) for pk in packages), *parts):
        h.update(p.encode())
        h.update(b"\0")
    return h.hexdigest()


MISSING = object()


def _path(k: str) -> Path | None:
    d = directory()
    return None if d is None else d / k[:2] / f"{k}.pickle"


def load(k: str):
    """The stored value under k, or MISSING."""
    path = _path(k)
    if path is None or not path.exists():
        return MISSING
    try:
        with path.open("rb") as fh:
            return pickle.load(fh)
    except (OSError, pickle.UnpicklingError, EOFError, AttributeError, ImportError):
        return MISSING


def store(k: str, value) -> None:
    path = _path(k)
    if path is None:
        return
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=path.parent, suffix=".tmp")
    with os.fdopen(fd, "wb") as fh:
        pickle.dump(value, fh)
    os.replace(tmp, path)


def memo(k: str, compute: Callable[[], T]) -> T:
    """compute(), or its stored value under key k."""
    d = directory()
    if d is None:
        return compute()
    path = d / k[:2] / f"{k}.pickle"
    if path.exists():
        try:
            with path.open("rb") as fh:
                return pickle.load(fh)
        except (OSError, pickle.UnpicklingError, EOFError, AttributeError, ImportError):
            pass  # an unreadable entry is recomputed and replaced
    value = compute()
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=path.parent, suffix=".tmp")
    with os.fdopen(fd, "wb") as fh:
        pickle.dump(value, fh)
    os.replace(tmp, path)
    return value
