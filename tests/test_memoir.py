"""pendsym.memoir: what a plug-in exports."""
from types import SimpleNamespace

from pendsym.memoir import Memoir, Section
from pendsym.result import Source, Spec


def _module(name, ids):
    specs = tuple(Spec(i, i, Source("m", "n°1"), i, lambda d: 0) for i in ids)
    return SimpleNamespace(__name__=name, specs=lambda: specs)


def test_check_groups_are_the_affinity_groups_and_the_shared_sections():
    plain = Section.of(_module("m.plain", ["m.a", "m.b"]), "plain")
    shared = Section.of(_module("m.shared", ["m.c", "m.d", "m.e"]), "shared", shared=True)
    memoir = Memoir("m", "M", (plain, shared), affinity=(("m.a", "m.c"),))
    assert memoir.check_groups() == (("m.a", "m.c"), ("m.c", "m.d", "m.e"))
    assert not plain.shared and shared.shared
