"""pendsym.emit.kernels.kernel: kernel_of builds a Kernel of plain data, its Python accuracy
measured on the function as emitted; sampling and measurement as the contract states."""
import dataclasses
import math

import mpmath as mp
import pytest
import sympy as sp

from pendsym.emit import kernels as kn
from pendsym.result import KernelArg, KernelSpec, Result, Source, Spec

u = sp.Symbol("u", positive=True)
lam = sp.Symbol("lambda", positive=True)
ARGS = (KernelArg("lambda", 1e-3, 10.0, unit="m"), KernelArg("u", 1e-6, 700.0))
DERIVED = lam * (1 - 2 * sp.tanh(u / 2) / u)


@pytest.fixture(scope="module")
def result():
    spec = Spec("test.eq1.beta", "β", Source("test", "n°1", eq="1"), r"\beta", lambda deps: DERIVED,
                kernel=KernelSpec(args=ARGS, doc="β = λ(1 − 2 th(u/2)/u)."))
    return Result(spec=spec, derived=DERIVED, printed=None)


@pytest.fixture(scope="module")
def kernel(result):
    return kn.kernel_of(result)


def _plain(v) -> bool:
    """Plain data: what a data-only codec can store (no callables, no ctypes objects)."""
    if v is None or isinstance(v, (bool, int, float, str, mp.mpf, sp.Basic)):
        return not isinstance(v, sp.Basic) or all(_plain(a) for a in v.args)
    if isinstance(v, tuple):
        return all(_plain(x) for x in v)
    if dataclasses.is_dataclass(v) and not isinstance(v, type):
        return v.__dataclass_params__.frozen and all(_plain(getattr(v, f.name)) for f in dataclasses.fields(v))
    return False


def test_the_kernel_is_a_frozen_record_of_plain_data(kernel):
    assert _plain(kernel)
    with pytest.raises(dataclasses.FrozenInstanceError):
        kernel.rule = "x"
    assert kernel.name == "eq1_beta" and kernel.args == ARGS and kernel.c_accuracy is None


def test_the_python_accuracy_is_that_of_the_emitted_function(kernel, result):
    ns = {"math": math}
    exec(compile(kn.py_function(kernel), "<k>", "exec"), ns)
    pts = kn.kernel_sample(result.derived, kernel.args, kernel.name)
    assert kn.measure(ns[kernel.name], result.derived, kernel.args, pts) == kernel.py_accuracy
    assert kernel.py_accuracy.points == len(pts) == len(kernel.reference)
    assert kernel.py_accuracy.max_scaled <= kn.BOUND
    assert kernel.naive.form == "as derived" and kernel.naive.accuracy.max_scaled > 1e6
    assert kernel.notes and kernel.rule.startswith("piecewise in u")


def test_the_sample_holds_the_hard_points(kernel, result):
    pts = kn.kernel_sample(result.derived, kernel.args, kernel.name)
    us = {p[1] for p in pts}
    assert {1e-6, 2e-6, 350.0, 700.0} <= us and {10.0**e for e in range(-6, 3)} <= us
    for s in kn.SWITCHES + kn.KNOTS:
        assert {math.nextafter(s, 0.0), s, math.nextafter(s, math.inf)} <= us, s
    assert pts == kn.kernel_sample(result.derived, kernel.args, kernel.name)     # seeded


def test_measure_scales_by_the_condition_number():
    """x − 1 near x = 1 is ill-conditioned (κ = |x/(x − 1)|): an error of many ulp there is
    within the bound once scaled; the same error where κ ≈ 1 is not."""
    x = sp.Symbol("x", positive=True)
    arg = (KernelArg("x", 0.5, 4.0),)
    near_one = 1.0 + 2.0**-30
    off = lambda v: (v - 1.0) * (1 + 64 * 2.0**-52)           # 64 ulp off everywhere
    near = kn.measure(off, x - 1, arg, [(near_one,)])
    assert near.max_ulp > 32 and near.max_scaled < 1e-3
    far = kn.measure(off, x - 1, arg, [(3.0,)])
    assert far.max_scaled > kn.BOUND
    assert kn.measure(lambda v: 1 / 0, x - 1, arg, [(3.0,)]).max_ulp == math.inf
