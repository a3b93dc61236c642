"""pendsym.registry: ids, dependency closure, lazy building."""
import pytest
import sympy as sp

from pendsym import registry
from pendsym.result import Source, Spec


def _spec(i, deps=()):
    return Spec(i, i, Source("m", "n°1"), "x", lambda d: sp.Integer(len(d)), deps=deps)


def test_closure_puts_dependencies_first_and_only_what_is_needed():
    specs = {s.id: s for s in (_spec("m.a"), _spec("m.b", ("m.a",)), _spec("m.c", ("m.b",)), _spec("m.d"))}
    assert registry.closure(["m.c"], specs) == ["m.a", "m.b", "m.c"]
    assert "m.d" not in registry.closure(["m.c"], specs)


def test_closure_detects_cycles_and_unknown_ids():
    specs = {s.id: s for s in (_spec("m.a", ("m.b",)), _spec("m.b", ("m.a",)))}
    with pytest.raises(ValueError):
        registry.closure(["m.a"], specs)
    with pytest.raises(registry.UnknownResult):
        registry.closure(["m.zz"], specs)


def test_build_of_one_id_builds_its_closure_only():
    built = registry.build(["charbonnier1908.n21.dT"])
    assert "charbonnier1908.n21.dT" in built
    assert "charbonnier1908.n09.dT" in built            # a dependency
    assert "charbonnier1908.n33.dalpha" not in built    # not needed
    assert len(built) < 15


def test_unknown_memoir_and_id():
    with pytest.raises(registry.UnknownResult):
        registry.build(["nosuch.n1.x"])
    with pytest.raises(registry.UnknownResult):
        registry.build(["charbonnier1908.n99.x"])


def test_ids_are_unique_and_name_their_memoir():
    specs = registry.all_specs()
    for sid, spec in specs.items():
        assert sid.startswith(spec.memoir + ".")


def test_unknown_id_suggests_the_ids_it_abbreviates_before_lookalikes():
    known = ["m.eq043.dT", "m.eq043.x", "m.eq343.a", "m.eq430.b"]
    assert registry.UnknownResult("m.eq43", known).near == ("m.eq043.dT", "m.eq043.x")
    assert registry.UnknownResult("m.eq343", known).near == ("m.eq343.a",)


def test_every_result_is_under_one_heading_of_its_memoirs_report():
    for key, memoir in registry.memoirs().items():
        placed = [i for heading in memoir.report_headings() for i in heading.ids]
        assert sorted(placed) == sorted(s.id for s in memoir.specs), key
