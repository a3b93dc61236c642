"""pendsym.plugin: a memoir package's lazy registration (PEP 562)."""
import sys

import pytest

from pendsym.plugin import lazy_package


@pytest.fixture
def lazy_pkg(tmp_path, monkeypatch):
    pkg = tmp_path / "lazy_toy_pkg"
    pkg.mkdir()
    (pkg / "__init__.py").write_text("from pendsym.plugin import lazy_package\n__getattr__ = lazy_package(__name__)\n")
    (pkg / "registration.py").write_text("MEMOIR = 'the memoir'\n")
    (pkg / "section.py").write_text("VALUE = 3\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    yield "lazy_toy_pkg"
    for name in [m for m in sys.modules if m.split(".")[0] == "lazy_toy_pkg"]:
        del sys.modules[name]


def test_a_section_imports_without_the_registration(lazy_pkg):
    import lazy_toy_pkg
    assert lazy_toy_pkg.section.VALUE == 3
    assert "lazy_toy_pkg.registration" not in sys.modules


def test_other_names_come_from_the_registration_on_first_use(lazy_pkg):
    import lazy_toy_pkg
    assert lazy_toy_pkg.MEMOIR == "the memoir"
    assert "lazy_toy_pkg.registration" in sys.modules


def test_an_unknown_name_is_an_attribute_error(lazy_pkg):
    import lazy_toy_pkg
    with pytest.raises(AttributeError, match="no attribute 'nothing_here'"):
        lazy_toy_pkg.nothing_here
    with pytest.raises(AttributeError):
        lazy_toy_pkg.__wrapped__


def test_the_three_memoirs_delegate_to_it():
    import derivations.cellerier
    import derivations.charbonnier1908
    import derivations.haag1935
    for pkg in (derivations.cellerier, derivations.charbonnier1908, derivations.haag1935):
        assert pkg.__getattr__.__qualname__ == lazy_package(pkg.__name__).__qualname__
