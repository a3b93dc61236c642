"""pendsym.keys: a Result's key covers its section's imports and its dependencies, nothing else."""
import sys

import pytest

from pendsym import keys


@pytest.fixture()
def pkg(tmp_path, monkeypatch):
    """A throw-away package: sec_a imports helper, sec_b imports nothing of the package."""
    root = tmp_path / "keypkg"
    root.mkdir()
    (root / "__init__.py").write_text("from . import sec_a, sec_b\n")
    (root / "helper.py").write_text("X = 1\n")
    (root / "sec_a.py").write_text("from . import helper\nfrom pendsym import verify\n")
    (root / "sec_b.py").write_text("import math\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    for cache in (keys.module_file, keys.imports_of, keys.closure, keys.file_hash):
        cache.cache_clear()
    yield root
    for name in [m for m in sys.modules if m.startswith("keypkg")]:
        del sys.modules[name]
    for cache in (keys.module_file, keys.imports_of, keys.closure, keys.file_hash):
        cache.cache_clear()


ROOTS = ("pendsym", "keypkg")


def test_closure_follows_imports_not_the_package(pkg):
    a = keys.closure("keypkg.sec_a", ROOTS)
    assert "keypkg.helper" in a and "pendsym.verify" in a
    assert "keypkg.sec_b" not in a and "keypkg" not in a      # the package __init__ imports every section
    assert keys.closure("keypkg.sec_b", ROOTS) == ("keypkg.sec_b",)


def _keys():
    sections = {"r1": "keypkg.sec_a", "r2": "keypkg.sec_b", "r3": "keypkg.sec_b"}
    deps = {"r1": (), "r2": (), "r3": ("r1",)}
    return keys.result_keys(sections, deps, ["r1", "r2", "r3"], ROOTS)


def test_a_change_reaches_its_section_and_its_dependents_only(pkg):
    before = _keys()
    (pkg / "helper.py").write_text("X = 2\n")
    keys.file_hash.cache_clear()
    after = _keys()
    assert before["r1"] != after["r1"]          # sec_a imports helper
    assert before["r2"] == after["r2"]          # sec_b does not
    assert before["r3"] != after["r3"]          # r3 depends on r1


def test_the_tree_key_sees_every_source_file(pkg):
    before = keys.tree_key(("keypkg",), "full")
    assert keys.tree_key(("keypkg",), "quick") != before
    (pkg / "sec_b.py").write_text("import math  # edited\n")
    keys.file_hash.cache_clear()
    assert keys.tree_key(("keypkg",), "full") != before


def test_file_hash_is_the_sha256_of_the_bytes(tmp_path):
    f = tmp_path / "f"
    f.write_bytes(b"abc")
    assert keys.file_hash(f) == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad"


def test_digest_separates_its_parts():
    assert keys.digest(("a", "bc")) == keys.digest(("a", "bc")) != keys.digest(("ab", "c"))
