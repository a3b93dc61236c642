"""A disk cache for pure computations (built forms, evidence, kernel forms).

An entry is stored under a content key that covers everything that determines
it (:mod:`pendsym.keys` makes the keys): any change of what it depends on
misses the cache; a hit returns exactly what the computation would return.

Entries are data, never code: ``<dir>/<key[:2]>/<key>.json`` holds
``{"format": 1, "key": key, "checksum": sha256 of the canonical JSON of the
payload, "payload": pendsym.codec data}``.  An entry that is missing,
unreadable, too big, of another format, filed under another key, with a wrong
checksum or that does not decode is recomputed and replaced; the cache never
fails because of what it finds on disk.  Old ``.pickle`` entries are never
opened.

The directory is ``$PENDSYM_CACHE`` (``off`` disables the cache), else
``.cache/pendsym`` in the project root (the checkout holding pyproject.toml
and pendsym/), else — for an installed package — ``$XDG_CACHE_HOME/pendsym``
or ``~/.cache/pendsym``.  It never depends on the working directory.
"""
from __future__ import annotations

import hashlib
import json
import os
import re
import secrets
import stat
from pathlib import Path
from typing import Any, Callable, TypeVar


from . import codec

T = TypeVar("T")

FORMAT = 1
MAX_BYTES = 64 * 2 ** 20      # a bigger entry is not read (and is replaced)
_KEY = re.compile(r"[0-9a-f]{16,128}")
_ENTRY = re.compile(r"[0-9a-f]{16,128}\.(?:json|pickle)|\.[0-9a-f]{16,128}\.[0-9a-f]+\.tmp")


class _Missing:
    """The type of :data:`MISSING`."""

    def __repr__(self) -> str:
        return "MISSING"


MISSING: Any = _Missing()   # what load() returns when there is no valid entry


# ----------------------------------------------------------------- where
def project_root() -> Path | None:
    """The checkout this pendsym was imported from (pyproject.toml beside pendsym/), or None."""
    root = Path(__file__).resolve().parent.parent
    if (root / "pyproject.toml").is_file() and (root / "pendsym" / "__init__.py").is_file():
        return root
    return None


def directory() -> Path | None:
    """The cache directory, or None when PENDSYM_CACHE=off."""
    env = os.environ.get("PENDSYM_CACHE", "")
    if env.lower() == "off":
        return None
    if env:
        return Path(env).expanduser()
    root = project_root()
    if root is not None:
        return root / ".cache" / "pendsym"
    xdg = os.environ.get("XDG_CACHE_HOME", "")
    base = Path(xdg) if os.path.isabs(xdg) else Path.home() / ".cache"
    return base / "pendsym"


def entry_path(d: Path, k: str) -> Path:
    """Where the entry of key k lives under d."""
    if not (isinstance(k, str) and _KEY.fullmatch(k)):
        raise ValueError(f"not a cache key: {k!r}")
    return d / k[:2] / f"{k}.json"


def canonical(data: Any) -> bytes:
    """The canonical JSON of codec data (sorted keys, no spaces, ASCII, no NaN)."""
    return json.dumps(data, sort_keys=True, separators=(",", ":"), ensure_ascii=True,
                      allow_nan=False).encode("ascii")


def checksum(payload: Any) -> str:
    """sha256 (hex) of the canonical JSON of a payload."""
    return hashlib.sha256(canonical(payload)).hexdigest()


def _no_constant(name: str):
    raise ValueError(f"{name} is not JSON")


def _read(path: Path) -> bytes | None:
    """The bytes of a regular file of at most MAX_BYTES (no symlink, no FIFO), else None."""
    flags = os.O_RDONLY | getattr(os, "O_NOFOLLOW", 0) | getattr(os, "O_NONBLOCK", 0)
    try:
        with os.fdopen(os.open(path, flags), "rb") as fh:
            st = os.fstat(fh.fileno())
            if not stat.S_ISREG(st.st_mode) or st.st_size > MAX_BYTES:
                return None
            data = fh.read(MAX_BYTES + 1)
    except OSError:
        return None
    return data if len(data) <= MAX_BYTES else None


def parse(raw: bytes, k: str) -> Any:
    """The value held by an entry's bytes for key k, or MISSING if they are not a valid entry."""
    try:
        doc = json.loads(raw.decode("utf-8"), parse_constant=_no_constant)
        if not (isinstance(doc, dict) and set(doc) == {"format", "key", "checksum", "payload"}
                and type(doc["format"]) is int and doc["format"] == FORMAT
                and doc["key"] == k and doc["checksum"] == checksum(doc["payload"])):
            return MISSING
        return codec.decode(doc["payload"])
    except Exception:        # bad UTF-8, bad JSON, CodecError, RecursionError, MemoryError …
        return MISSING


def load(k: str) -> Any:
    """The value stored under key k, or MISSING (no cache, no entry, or an invalid one)."""
    d = directory()
    if d is None:
        return MISSING
    raw = _read(entry_path(d, k))
    return MISSING if raw is None else parse(raw, k)


def dump(k: str, value: Any) -> bytes:
    """An entry's bytes for value under key k; CodecError if value cannot be encoded."""
    payload = codec.encode(value)
    return canonical({"format": FORMAT, "key": k, "checksum": checksum(payload), "payload": payload})


def store(k: str, value: Any) -> bool:
    """Store value under key k, atomically; False (and nothing written) when the cache is off,
    value cannot be encoded, its entry would exceed MAX_BYTES or the directory cannot be written."""
    d = directory()
    if d is None:
        return False
    path = entry_path(d, k)
    try:
        raw = dump(k, value)
    except (ValueError, RecursionError):      # CodecError is a ValueError
        return False
    if len(raw) > MAX_BYTES:                  # it would never be read back
        return False
    tmp = path.parent / f".{k}.{secrets.token_hex(8)}.tmp"
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        # 0o666 less the umask, as for any file the user creates (mkstemp would give 0o600)
        fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666)
        with os.fdopen(fd, "wb") as fh:
            fh.write(raw)
        os.replace(tmp, path)
        return True
    except OSError:
        try:
            tmp.unlink(missing_ok=True)
        except OSError:
            pass
        return False


def memo(k: str, compute: Callable[[], T]) -> T:
    """compute(), or its stored value under key k (an invalid entry is recomputed and replaced)."""
    return memo_fresh(k, compute)[0]


def memo_fresh(k: str, compute: Callable[[], T], keep: bool = True) -> tuple[T, bool]:
    """(value, computed): as :func:`memo`, and whether the value was computed now (and stored,
    unless ``keep`` is false)."""
    value = load(k)
    if value is not MISSING:
        return value, False
    value = compute()
    if keep:
        store(k, value)
    return value, True


def clear() -> int:
    """Remove the cache's entries (and its directories once empty); the number of files removed.
    Only files named as entries are removed, whatever PENDSYM_CACHE points to."""
    d = directory()
    if d is None or not d.is_dir():
        return 0
    n = 0
    for sub in d.iterdir():
        if not (re.fullmatch(r"[0-9a-f]{2}", sub.name) and sub.is_dir() and not sub.is_symlink()):
            continue
        for f in sub.iterdir():
            if _ENTRY.fullmatch(f.name) and not f.is_dir():
                f.unlink(missing_ok=True)
                n += 1
        try:
            sub.rmdir()
        except OSError:
            pass            # something else lives there
    try:
        d.rmdir()
    except OSError:
        pass
    return n


if __name__ == "__main__":      # python -m pendsym.cache [clear]
    import sys
    if sys.argv[1:] == ["clear"]:
        print(f"removed {clear()} entries from {directory()}")
    else:
        print(directory())
