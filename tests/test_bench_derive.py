"""make bench-derive: the list of the original 314 Results and the closure derived with them (issue #9 point 9)."""
from types import SimpleNamespace

from pendsym import bench_derive
from pendsym.checks import Chain


def test_original_ids_are_the_314_of_the_three_first_memoirs():
    ids = bench_derive.original_ids()
    assert len(ids) == 314 and len(set(ids)) == 314
    assert {i.split(".")[0] for i in ids} == {"charbonnier1908", "cellerier", "haag1935"}


def test_subset_order_takes_dependencies_and_what_a_chain_feeds_in_the_derive_order():
    spec = lambda deps=(), check=None: SimpleNamespace(deps=deps, check=check)
    specs = {"a": spec(), "b": spec(("a",), Chain(("d",))), "c": spec(("b",)), "d": spec(("b",)),
             "e": spec(("a",)), "f": spec()}
    order = ("f", "a", "e", "b", "d", "c")
    assert bench_derive.subset_order(["b"], specs, order) == ("a", "b", "d")
    assert bench_derive.subset_order(["c", "f"], specs, order) == ("f", "a", "b", "d", "c")
