"""pendsym.cache: a hit returns the stored value; keys change with their inputs; it can be off;
whatever is found on disk, it never runs code, never returns another key's value, never crashes,
and replaces what it cannot use."""
import json
import os
import pickle
import random
import stat

import pytest
import sympy as sp

from pendsym import cache, codec, keys
from pendsym.result import Evidence


def key(*parts: str) -> str:
    """A cache key as the pipeline makes them (pendsym.keys.digest)."""
    return keys.digest(parts)


@pytest.fixture
def cdir(tmp_path, monkeypatch):
    d = tmp_path / "cache"
    monkeypatch.setenv("PENDSYM_CACHE", str(d))
    return d


class Counter:
    """compute functions that count their calls."""

    def __init__(self):
        self.calls = []

    def __call__(self, value):
        def compute():
            self.calls.append(value)
            return value
        return compute


def entry(d, k):
    return d / k[:2] / f"{k}.json"


x = sp.Symbol("x", positive=True)
VALUES = [
    {"v": 1, (1, 2): [3.5, None]},
    sp.Integral(sp.exp(-x) * sp.Function("f")(x), (x, 0, sp.oo)),
    Evidence(kind="order", passed=True, truth="t", max_residual=1e-12, series=((0.1, 1e-5),)),
    (float("inf"), -0.0, "θ"),
    None,
]


def test_memo_computes_once_per_key(cdir):
    calls = []

    def compute():
        calls.append(1)
        return {"v": len(calls)}
    k = key("test", "a")
    assert cache.memo(k, compute) == {"v": 1}
    assert cache.memo(k, compute) == {"v": 1}
    assert len(calls) == 1
    assert cache.memo(key("test", "b"), compute) == {"v": 2}


def test_entries_are_checked_json(cdir):
    count = Counter()
    for i, value in enumerate(VALUES):
        k = key("values", str(i))
        assert cache.memo(k, count(value)) == value
        back = cache.memo(k, count("recomputed"))
        assert back == value and type(back) is type(value)
        if isinstance(value, sp.Basic):
            assert sp.srepr(back) == sp.srepr(value)
        doc = json.loads(entry(cdir, k).read_text())
        assert doc["format"] == 1 and doc["key"] == k
        assert doc["checksum"] == cache.checksum(doc["payload"])
        assert codec.decode(doc["payload"]) == value
    assert count.calls == VALUES                      # each computed once; None is a value too


def test_cache_off(monkeypatch, tmp_path):
    monkeypatch.setenv("PENDSYM_CACHE", "off")
    monkeypatch.chdir(tmp_path)
    n = []
    cache.memo(key("x"), lambda: n.append(1))
    cache.memo(key("x"), lambda: n.append(1))
    assert len(n) == 2
    assert cache.directory() is None
    assert cache.store(key("x"), 1) is False and cache.load(key("x")) is cache.MISSING
    assert cache.clear() == 0
    assert not any(tmp_path.iterdir())


def test_bad_keys_are_refused(cdir):
    for bad in ("../../etc/passwd", "ab", "A" * 64, "", "g" * 64):
        with pytest.raises(ValueError):
            cache.memo(bad, lambda: 1)


# ----------------------------------------------------------------- planted code
class Plant:
    """Unpickling this creates the marker file (through open(marker, 'w'))."""

    def __init__(self, marker):
        self.marker = str(marker)

    def __reduce__(self):
        return (open, (self.marker, "w"))


def test_planted_pickle_and_crafted_json_never_run(cdir, tmp_path):
    marker = tmp_path / "ran"
    k = key("planted")
    f = entry(cdir, k)
    f.parent.mkdir(parents=True)
    f.with_suffix(".pickle").write_bytes(pickle.dumps(Plant(marker)))
    # a well-formed entry (right key and checksum) naming code to run
    payload = {"$": "dataclass", "module": "builtins", "qualname": "open",
               "fields": {"file": str(marker), "mode": "w"}}
    f.write_text(json.dumps({"format": 1, "key": k, "checksum": cache.checksum(payload), "payload": payload}))
    k2 = key("planted", "2")
    entry(cdir, k2).parent.mkdir(exist_ok=True)
    entry(cdir, k2).write_bytes(pickle.dumps(Plant(marker)))   # a pickle under the .json name
    count = Counter()
    assert cache.memo(k, count("safe")) == "safe"
    assert cache.memo(k2, count("safe2")) == "safe2"
    assert not marker.exists()
    assert count.calls == ["safe", "safe2"]
    assert cache.load(k) == "safe" and cache.load(k2) == "safe2"     # replaced by valid entries
    assert not marker.exists()
    pickle.loads(f.with_suffix(".pickle").read_bytes())             # the plant does work
    assert marker.exists()


# ----------------------------------------------------------------- damaged entries
def garbage(rng, valid: bytes) -> bytes:
    kind = rng.randrange(8)
    if kind == 0:
        return b""
    if kind == 1:
        return valid[: rng.randrange(len(valid))]                   # truncated
    if kind == 2:                                                   # one byte changed
        i = rng.randrange(len(valid))
        return valid[:i] + bytes([valid[i] ^ (1 << rng.randrange(8))]) + valid[i + 1:]
    if kind == 3:
        return json.dumps({"format": 2, "key": "x", "checksum": "", "payload": None}).encode()
    if kind == 4:
        return b"\xff\xfe" + os.urandom(rng.randrange(1, 300))      # not UTF-8
    if kind == 5:
        return b"[" * 100_000                                        # deep JSON
    if kind == 6:
        return b'{"format": 1, "key": NaN}'
    return os.urandom(rng.randrange(1, 2000))


def test_garbage_in_every_entry_is_recomputed_and_replaced(cdir):
    rng = random.Random(9)
    keys = [key("garbage", str(i)) for i in range(60)]
    values = [VALUES[i % len(VALUES)] for i in range(len(keys))]
    for k, value in zip(keys, values):
        cache.memo(k, lambda: value)
    for k in keys:
        f = entry(cdir, k)
        f.write_bytes(garbage(rng, f.read_bytes()))
    count = Counter()
    for k, value in zip(keys, values):
        assert cache.memo(k, count(value)) == value
    assert len(count.calls) == len(keys)              # no garbage read as a value
    for k, value in zip(keys, values):                # the next reads hit
        assert cache.memo(k, count("recomputed")) == value
    assert len(count.calls) == len(keys)


def test_swapped_entries_are_both_recomputed(cdir):
    ka, kb = key("swap", "a"), key("swap", "b")
    cache.memo(ka, lambda: "evidence of a")
    cache.memo(kb, lambda: "evidence of b")
    fa, fb = entry(cdir, ka), entry(cdir, kb)
    da, db = fa.read_bytes(), fb.read_bytes()
    fa.write_bytes(db)
    fb.write_bytes(da)
    count = Counter()
    assert cache.memo(ka, count("evidence of a")) == "evidence of a"
    assert cache.memo(kb, count("evidence of b")) == "evidence of b"
    assert count.calls == ["evidence of a", "evidence of b"]
    assert cache.load(ka) == "evidence of a" and cache.load(kb) == "evidence of b"


def test_entry_that_does_not_decode_is_replaced(cdir, monkeypatch):
    k = key("undecodable")
    payload = {"$": "basic", "class": {"sympy": "Add"}, "args": [1, 2]}   # valid JSON, bad codec data
    f = entry(cdir, k)
    f.parent.mkdir(parents=True)
    f.write_text(json.dumps({"format": 1, "key": k, "checksum": cache.checksum(payload), "payload": payload}))
    assert cache.load(k) is cache.MISSING
    assert cache.memo(k, lambda: 3) == 3
    assert cache.load(k) == 3

    def explode(data):
        raise RecursionError("deep")
    count = Counter()
    with monkeypatch.context() as m:
        m.setattr(codec, "decode", explode)
        assert cache.memo(k, count(4)) == 4           # a decoder raising anything: recomputed …
    assert cache.load(k) == 4 and count.calls == [4]  # … and replaced


def test_oversized_entry_is_replaced_and_not_written(cdir, monkeypatch):
    k = key("big")
    cache.memo(k, lambda: "small")
    f = entry(cdir, k)
    f.write_bytes(f.read_bytes() + b" " * 4096)       # still a valid entry, but too big
    monkeypatch.setattr(cache, "MAX_BYTES", 1024)
    assert cache.load(k) is cache.MISSING
    assert cache.memo(k, lambda: "small") == "small" and f.stat().st_size < 1024
    k2 = key("big", "2")
    assert cache.store(k2, "x" * 5000) is False and not entry(cdir, k2).exists()


def test_fifo_or_directory_in_place_of_an_entry(cdir):
    k, k2 = key("fifo"), key("dir")
    entry(cdir, k).parent.mkdir(parents=True, exist_ok=True)
    os.mkfifo(entry(cdir, k))                         # opening it to read would block
    entry(cdir, k2).parent.mkdir(parents=True, exist_ok=True)
    entry(cdir, k2).mkdir()
    assert cache.memo(k, lambda: 1) == 1 and cache.load(k) == 1
    assert cache.memo(k2, lambda: 2) == 2             # cannot be replaced: returned, not stored


def test_old_pickle_entries_are_ignored(cdir):
    k = key("old")
    f = entry(cdir, k).with_suffix(".pickle")
    f.parent.mkdir(parents=True)
    f.write_bytes(pickle.dumps("stale"))
    assert cache.memo(k, lambda: "fresh") == "fresh"


# ----------------------------------------------------------------- writing
def test_unencodable_value_is_returned_not_stored(cdir):
    k = key("unencodable")
    fn = lambda: 1                                     # noqa: E731
    count = Counter()
    assert cache.memo(k, count(fn)) is fn
    assert cache.memo(k, count(fn)) is fn
    assert len(count.calls) == 2
    assert not cdir.exists() or not any(p.is_file() for p in cdir.rglob("*"))   # no partial file


@pytest.mark.parametrize("umask, mode", [(0o022, 0o644), (0o077, 0o600), (0o002, 0o664)])
def test_entry_mode_respects_the_umask(cdir, umask, mode):
    old = os.umask(umask)
    try:
        k = key("mode", oct(umask))
        assert cache.store(k, [1, 2]) is True
    finally:
        os.umask(old)
    assert stat.S_IMODE(entry(cdir, k).stat().st_mode) == mode
    assert [p.name for p in entry(cdir, k).parent.iterdir()] == [f"{k}.json"]   # no temp file left


def test_clear_removes_only_entries(cdir):
    for i in range(5):
        cache.store(key("clear", str(i)), i)
    (cdir / "notes.txt").write_text("mine")
    assert cache.clear() == 5
    assert [p.name for p in cdir.iterdir()] == ["notes.txt"]
    (cdir / "notes.txt").unlink()
    cache.store(key("clear"), 1)
    assert cache.clear() == 1 and not cdir.exists()


# ----------------------------------------------------------------- location
def test_location_does_not_depend_on_the_working_directory(monkeypatch, tmp_path, root):
    monkeypatch.delenv("PENDSYM_CACHE", raising=False)
    d = cache.directory()
    assert cache.project_root() == root
    assert d == root / ".cache" / "pendsym"
    monkeypatch.chdir(tmp_path)
    assert cache.directory() == d


def test_location_without_a_checkout(monkeypatch, tmp_path):
    monkeypatch.delenv("PENDSYM_CACHE", raising=False)
    monkeypatch.setattr(cache, "project_root", lambda: None)   # an installed package
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    assert cache.directory() == tmp_path / "xdg" / "pendsym"
    monkeypatch.setenv("XDG_CACHE_HOME", "relative")            # ignored, as the XDG spec says
    monkeypatch.setenv("HOME", str(tmp_path / "home"))
    assert cache.directory() == tmp_path / "home" / ".cache" / "pendsym"
    monkeypatch.setenv("PENDSYM_CACHE", str(tmp_path / "mine"))
    assert cache.directory() == tmp_path / "mine"
