"""Haag 1935, chapter III: the kernel declarations (ch3_uniform.kernels)."""
from derivations.haag1935 import ch3_uniform
from derivations.haag1935.ch3_uniform import kernels

P = "haag1935"
WANTED = {
    "eq159.v0": ("lambda", "u"), "eq159.w0": ("lambda", "u"), "eq159.wl": ("lambda", "u"),
    "eq159.beta1": ("lambda", "u"), "eq166.Gamma2": ("u", "k"), "eq166.Gamma3": ("u", "k"),
    "eq166.Gamma4": ("u", "k"), "eq166.Gamma5": ("u", "k"), "eq168.F1": ("u", "K"), "eq169.F2": ("u", "K"),
    "eq170.F": ("u", "K"), "eq036.K_uniform": ("a", "R", "lambda", "u"),
    "eq034.n2_z_uniform": ("a", "R", "lambda", "u", "g"), "eq182.I": ("lambda", "u", "K", "m'"),
    "eq183.J": ("lambda", "u", "K"),
}


def declared():
    return {spec.id: spec.kernel for spec in ch3_uniform.specs() if spec.kernel is not None}


def test_the_fifteen_kernels_and_their_arguments():
    assert kernels.KERNELS_READY is True
    found = declared()
    assert set(found) == {f"{P}.{name}" for name in WANTED}
    for name, args in WANTED.items():
        assert tuple(a.name for a in found[f"{P}.{name}"].args) == args, name


def test_domains_units_and_naive_readings():
    found = declared()
    for kernel in found.values():
        by_name = {a.name: a for a in kernel.args}
        assert (by_name["u"].lo, by_name["u"].hi, by_name["u"].log) == (1e-6, 700.0, True)
        if "K" in by_name:
            assert (by_name["K"].lo, by_name["K"].hi, by_name["K"].log) == (-3.0, 3.0, False)
        if "k" in by_name:
            assert (by_name["k"].lo, by_name["k"].hi) == (-12.0, 0.25)
        assert kernel.doc.endswith(kernels.CANCEL) and kernel.naive_defs == kernels.NAIVE
    units = {name.split(".", 1)[1]: kernel.unit for name, kernel in found.items()}
    assert units["eq159.v0"] == "m" and units["eq034.n2_z_uniform"] == "1/s^2" and units["eq182.I"] == "kg m^2"
    assert units["eq166.Gamma2"] == "1" and units["eq183.J"] == "m"
    assert {(a.lo, a.hi, a.unit) for a in found[f"{P}.eq036.K_uniform"].args if a.name in ("a", "R")} == \
        {(1e-2, 5.0, "m"), (1e-3, 2.0, "m")}
