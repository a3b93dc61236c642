"""pendsym.cache: a hit returns the stored value; keys change with their inputs; it can be off."""
from pendsym import cache


def test_memo_computes_once_per_key(tmp_path, monkeypatch):
    monkeypatch.setenv("PENDSYM_CACHE", str(tmp_path))
    calls = []

    def compute():
        calls.append(1)
        return {"v": len(calls)}
    k = cache.key("test", "a")
    assert cache.memo(k, compute) == {"v": 1}
    assert cache.memo(k, compute) == {"v": 1}
    assert len(calls) == 1
    assert cache.memo(cache.key("test", "b"), compute) == {"v": 2}


def test_cache_off(monkeypatch):
    monkeypatch.setenv("PENDSYM_CACHE", "off")
    n = []
    cache.memo(cache.key("x"), lambda: n.append(1))
    cache.memo(cache.key("x"), lambda: n.append(1))
    assert len(n) == 2


def test_key_depends_on_the_code():
    assert cache.key("a", packages=("pendsym",)) != cache.key("a", packages=("pendsym", "derivations.charbonnier1908"))
