"""The generated Python kernels on numpy arrays (pendsym/emit/kernels/arrays.py): the array path
against the scalar path, kernel by kernel, on random points of the accepted domain and its hard
points (ends, the doubles inside them, 0, the smallest subnormal, +inf where accepted, each branch
switch and the doubles on either side); the same ValueError for an element outside the domain;
broadcasting; no warning.

The scalar path is the reference here (it is the code the audit holds to the contract).  With
numpy's SIMD loops disabled (NPY_DISABLE_CPU_FEATURES), numpy calls libm as math does, and the
array path must then equal the scalar path bit for bit: the same operations in the same order.
With them (numpy's default on a CPU that has them), numpy's exp, expm1, log, tan, sinh, cosh,
tanh round differently from libm's by up to 2 ulp (the array path calls libm's pow through
numpy.float_power); the results then agree to TOLERANCE (relative) here, and `make audit` measures
the array path against the 50-digit reference where the two differ.

The kernels are those of PENDSYM_GENERATED (default: generated/), the tree make derive writes.
"""
import importlib.util
import json
import math
import os
import re
import subprocess
import sys
import warnings
from pathlib import Path

import numpy
import pytest

from pendsym.audit import arrays as ar

ROOT = Path(__file__).resolve().parents[1]
GENERATED = Path(os.environ.get("PENDSYM_GENERATED", ROOT / "generated"))
MEMOIRS = ("haag1935", "charbonnier1908", "cellerier")
QUICK_POINTS = 24          # random points per kernel in the quick tier (plus the hard points)
SLOW_POINTS = 20000
# the rhombus kernels cost 2.6-5.4 ms a call on each path since session 13 (cross products by Taylor steps in
# double-double, up to q = 1000; G2 takes 26 of them): 20,000 points would cost many minutes here for an equality of
# two paths that the hard points (every route switch) and a thousand random points already exercise (make audit
# holds them to the contract on 20,000)
FEWER_POINTS = {"eq346_G2_u_q": 1000, "eq343_v0_u_q": 1000, "eq343_w0_u_q": 1000, "eq343_wl_u_q": 1000}


def slow_points(name: str) -> int:
    """The slow tier's random points for the kernel `name`."""
    return FEWER_POINTS.get(name, SLOW_POINTS)


def _names(memoir: str) -> list[str]:
    text = (GENERATED / "python" / f"{memoir}.py").read_text()
    return json.loads(re.search(r"^__all__ = (\[.*\])$", text, re.M).group(1))


KERNELS = [(m, n) for m in MEMOIRS for n in _names(m)]


def _load(memoir: str):
    spec = importlib.util.spec_from_file_location(f"numpy_test_{memoir}", GENERATED / "python" / f"{memoir}.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


@pytest.fixture(scope="module")
def modules():
    return {m: (_load(m), (GENERATED / "python" / f"{m}.py").read_text()) for m in MEMOIRS}


def _agree(fn, pts) -> dict:
    """ar.compare with every numpy warning an error (an underflow to a subnormal is the scalar path's
    own result, not a warning)."""
    with warnings.catch_warnings(), numpy.errstate(over="raise", invalid="raise", divide="raise", under="ignore"):
        warnings.simplefilter("error")
        return ar.compare(fn, pts)


def test_every_memoir_kernel_has_an_array_path(modules):
    for memoir, (mod, code) in modules.items():
        for name in mod.__all__:
            assert f"return _{name}_array(" in ar.function_text(code, name), name
            assert callable(getattr(mod, f"_{name}_array")), name


@pytest.mark.parametrize(("memoir", "name"), KERNELS, ids=[n for _, n in KERNELS])
def test_array_path_equals_scalar_path(modules, memoir, name):
    mod, code = modules[memoir]
    pts = ar.points(code, name, QUICK_POINTS)
    got = _agree(getattr(mod, name), pts)
    assert got["max_rel"] <= TOLERANCE, got


# relative: numpy's SIMD exp, expm1, tanh … differ from libm's by up to 2 ulp, and where a kernel's
# terms cancel (κ ≫ 1) that is many ulp of its value (measured on 20,000 points a kernel: 116 ulp for
# eq220_dl, 32 for eq170_F, 12 for eq168_F1, each at a point of large κ, where the array path's
# error divided by max(1, κ) is below 2, as the scalar path's); a wrong branch or operation is off by
# far more.  The exactness of the operations is the bitwise test below; the contract is make audit's.
TOLERANCE = 1e-12


@pytest.mark.parametrize(("memoir", "name"), KERNELS, ids=[n for _, n in KERNELS])
def test_an_element_outside_the_domain_raises_the_scalar_paths_error(modules, memoir, name):
    mod, code = modules[memoir]
    fn = getattr(mod, name)
    dom = ar.domain(code, name)
    inside = ar.random_points(dom, 3, name + ":outside")
    for i, (_, lo, hi) in enumerate(dom):
        for bad in (math.nan, math.nextafter(lo, -math.inf), -math.inf if lo > -math.inf else None,
                    math.nextafter(hi, math.inf) if hi < math.inf else None):
            if bad is None or lo <= bad <= hi:
                continue
            cols = [c.copy() for c in inside.T]
            cols[i][1] = bad
            with pytest.raises(ValueError) as scalar:
                fn(*[float(c[1]) for c in cols])
            with pytest.raises(ValueError) as array:
                fn(*cols)
            assert str(array.value) == str(scalar.value)


def test_arguments_broadcast_and_keep_their_shape(modules):
    mod, code = modules["haag1935"]
    for name in ("eq182_I", "eq170_F"):
        fn = getattr(mod, name)
        dom = ar.domain(code, name)
        i_u = [x for x, _, _ in dom].index("u")
        mid = [math.sqrt(lo * hi) if lo > 0 and hi < math.inf else (lo + min(hi, 10.0)) / 2 for _, lo, hi in dom]
        u = numpy.geomspace(1e-3, 20.0, 6).reshape(2, 3)          # across the switches of the u pieces
        got = fn(*[u if i == i_u else m for i, m in enumerate(mid)])
        assert got.shape == (2, 3)
        want = [[fn(*[float(u[r, c]) if i == i_u else m for i, m in enumerate(mid)]) for c in range(3)] for r in range(2)]
        assert numpy.allclose(got, want, rtol=1e-14, atol=0)
        assert fn(*[numpy.float64(v) for v in mid]) == fn(*mid)        # a numpy scalar takes the scalar path
        assert fn(*[numpy.array(v) for v in mid]).shape == ()           # a 0-d array: a 0-d result
        column = numpy.array(mid)[:, None] * numpy.ones((1, 4))       # every argument an array, broadcast (4,) × scalar
        assert fn(*[c if i == i_u else float(m) for i, (c, m) in enumerate(zip(column, mid))]).shape == (4,)


def _cpu_dispatch() -> str:
    """The dispatched CPU features numpy found on this machine (those NPY_DISABLE_CPU_FEATURES may name)."""
    try:
        from numpy._core._multiarray_umath import __cpu_dispatch__, __cpu_features__
    except ImportError:           # numpy's layout changed: the bitwise comparison needs this switch
        pytest.skip("numpy does not tell its dispatched CPU features")
    return " ".join(f for f in __cpu_dispatch__ if __cpu_features__.get(f))


BITWISE = """
import json, sys
sys.path.insert(0, {root!r})
import numpy
from pendsym.audit import arrays as ar
from tests.test_kernels_numpy import KERNELS, _load, GENERATED, QUICK_POINTS, slow_points
out = {{}}
mods = {{}}
for memoir, name in KERNELS:
    if memoir not in mods:
        mods[memoir] = (_load(memoir), (GENERATED / "python" / f"{{memoir}}.py").read_text())
    mod, code = mods[memoir]
    r = ar.compare(getattr(mod, name), ar.points(code, name, slow_points(name) if {slow} else QUICK_POINTS))
    out[name] = [r["differ"], r["max_ulp"], r["at"]]
print(json.dumps(out))
"""


def _bitwise(slow: bool) -> dict:
    env = {**os.environ, "NPY_DISABLE_CPU_FEATURES": _cpu_dispatch(), "PENDSYM_GENERATED": str(GENERATED)}
    done = subprocess.run([sys.executable, "-c", BITWISE.format(root=str(ROOT), slow=slow)], env=env,
                          capture_output=True, text=True, check=True)
    return json.loads(done.stdout)


def test_with_numpy_calling_libm_the_two_paths_agree_bit_for_bit():
    got = _bitwise(slow=False)
    assert set(got) == {n for _, n in KERNELS}
    assert {n: r for n, r in got.items() if r[0]} == {}


@pytest.mark.slow
def test_with_numpy_calling_libm_the_two_paths_agree_bit_for_bit_on_many_points():
    """On the slow tier's points too (session 12: F (170) and J (183) differed at 6 points by up to 3 ulp and at
    one by 1 ulp, while the array path named a branch's arrays inside an expression, which SymPy then multiplied
    in another order than the scalar path: arrays.KernelNumPy.statement)."""
    got = _bitwise(slow=True)
    assert set(got) == {n for _, n in KERNELS}
    assert {n: r for n, r in got.items() if r[0]} == {}


@pytest.mark.slow
@pytest.mark.parametrize(("memoir", "name"), KERNELS, ids=[n for _, n in KERNELS])
def test_array_path_equals_scalar_path_on_many_points(modules, memoir, name):
    mod, code = modules[memoir]
    got = _agree(getattr(mod, name), ar.points(code, name, slow_points(name), seed=name + ":slow"))
    assert got["max_rel"] <= TOLERANCE, got
