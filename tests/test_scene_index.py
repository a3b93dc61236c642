"""pendsym.scenes.index: a scene reads its Results through an index of the tree, without importing a memoir.

The index must give the keys a full derive stores the forms under (else a warm scene derives again), each
Result's section and dependencies as the registry has them, and its definitions; importing a memoir's scene
effects must not build the memoir (else every scene pays for every section)."""
import subprocess
import sys

import pytest
import sympy as sp

from pendsym import registry, stages
from pendsym.scenes import index


def test_importing_the_scene_effects_builds_no_memoir():
    """The memoir packages build MEMOIR on first use: the scene effects and one section import alone."""
    code = ("import sys, importlib\n"
            "for m in ('derivations.haag1935.scene_effects', 'derivations.cellerier.scene_effects',"
            " 'derivations.charbonnier1908.scene_effects'):\n"
            "    importlib.import_module(m)\n"
            "print(' '.join(sorted(m for m in sys.modules if m.startswith('derivations'))))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    memoirs = ("haag1935", "cellerier", "charbonnier1908")
    assert set(out.stdout.split()) == {"derivations", *(f"derivations.{m}" for m in memoirs),
                                        *(f"derivations.{m}.scene_effects" for m in memoirs)}


def test_memoir_names_are_still_the_packages():
    """MEMOIR and a section are reached through the package as before (PEP 562), an unknown name is refused."""
    import derivations.haag1935 as haag
    assert haag.MEMOIR.key == "haag1935"
    assert haag.ch1_model.__name__ == "derivations.haag1935.ch1_model"
    with pytest.raises(AttributeError):
        haag.no_such_name


def test_closure_is_dependencies_first_and_refuses_an_unknown_id():
    fake = {"m.a": index.Entry("s", (), "k1", False), "m.b": index.Entry("s", ("m.a",), "k2", False),
            "m.c": index.Entry("s", ("m.b", "m.a"), "k3", False), "m.d": index.Entry("s", (), "k4", False)}
    assert index.closure(["m.c"], fake) == ["m.a", "m.b", "m.c"]
    with pytest.raises(registry.UnknownResult):
        index.closure(["m.x"], fake)


@pytest.mark.slow
def test_the_index_has_the_keys_sections_and_definitions_of_a_full_derive():
    """Against the derive's own plan (pendsym.stages.plan): every id, its dependencies, its section and the key
    its forms are stored under; and the definitions of a Result that has some."""
    pkgs = registry.packages()
    entries = index.compute(pkgs)
    plan = stages.plan("full")
    assert list(entries) == list(plan.order)
    for rid, entry in entries.items():
        spec = plan.specs[rid]
        assert entry.deps == spec.deps
        assert entry.key == plan.key("built", rid)
        assert registry.memoir(spec.memoir).section_of(rid).module == entry.section
        assert entry.has_defs == bool(spec.defs)
        assert entry.title == spec.title
        assert entry.ranges == (tuple((a.name, a.lo, a.hi) for a in spec.kernel.args) if spec.kernel else ())
    rid = "haag1935.eq043.dT"
    assert sp.srepr(sp.Tuple(*(sp.Tuple(*d) for d in index.defs(rid, entries)))) == \
        sp.srepr(sp.Tuple(*(sp.Tuple(*d) for d in plan.specs[rid].defs)))


def test_an_id_list_scene_imports_no_section_when_the_cache_holds_its_forms(root):
    """The memoir-minded scene (a list of ids) reads its forms, titles and ranges from the index and the cache: once
    its closure is stored, answering it again imports no section (it used to build every memoir)."""
    from pendsym import scene
    path = root / "derivations/cellerier/scenes/gravity_pendulum_on_support.toml"
    rows, built = scene.evaluate(scene.load(path))           # stores the closure's forms if they were missing
    assert built == 10 and [r[0] for r in rows] == ["cellerier.delta_static", "cellerier.delta_practical"]
    code = ("import sys\nfrom pendsym import scene\n"
            f"rows, built = scene.evaluate(scene.load({str(path)!r}))\n"
            "print(built, *(r[1] for r in rows), sep='|')\n"
            "print(' '.join(sorted(m for m in sys.modules if m.startswith('derivations'))))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, cwd=root)
    answer, modules = out.stdout.splitlines()
    assert answer.split("|") == ["10", *(r[1] for r in rows)]
    assert set(modules.split()) <= {"derivations", "derivations.cellerier"}
