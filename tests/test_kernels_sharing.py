"""pendsym.emit.kernels.sharing: a large part two kernels compute is emitted once, both call
it, and no value changes by a bit (Python and C)."""
import math
import shutil

import pytest
import sympy as sp

from pendsym.emit import files
from pendsym.emit import kernels as kn
from pendsym.result import KernelArg

u = sp.Symbol("u", positive=True)
ARGS = (KernelArg("u", 0.1, 3.0),)
POINTS = [0.1, 0.37, 0.999, 1.0, 1.7, 2.9, 3.0]


def _big_part() -> sp.Expr:
    """A Piecewise of well over SHARE_MIN nodes: a polynomial below 1, e^{−u}/u above."""
    poly = sp.Add(*[sp.Float(1.0 / (j + 1), 17) * u**j for j in range(300)])
    return sp.Piecewise((poly, u < 1), (sp.exp(-u) / u, True))


def _kernel(name: str, expr: sp.Expr) -> kn.Kernel:
    return kn.Kernel(name, f"test.{name}", ARGS, expr, "as-derived", "A test kernel.", "test")


@pytest.fixture(scope="module")
def pair():
    big = _big_part()
    return [_kernel("first", big + sp.sqrt(u)), _kernel("second", big / u - sp.sin(u))]


def test_a_part_of_two_kernels_is_emitted_once_and_called_by_both(pair):
    fns = kn.share(tuple(kn.kernel_function(k.name, k.args, k.expr) for k in pair))
    assert [f.name for f in fns] == ["first_part1", "first", "second"]
    part, first, second = fns
    assert part.callers == ("first", "second")
    for f in (first, second):
        assert not f.expr.has(sp.Piecewise), f.name
        assert any(getattr(c.func, "__name__", "") == "first_part1" for c in sp.preorder_traversal(f.expr))
    c = files.c_source("test", pair)
    assert c.count("static double first_part1(double u)") == 1
    for k in pair:                                  # each kernel evaluates the part once
        body = c.split(f"double {k.name}(double u)")[1].split("\n}\n")[0]
        assert body.count("first_part1(u)") == 1 and "if (u" not in body, k.name      # (the part's branches)
    assert "first_part1" not in files.c_header("test", pair)
    py = files.python_module("test", pair)
    assert py.count("def _first_part1(u):") == 1 and '"_first_part1"' not in py


def test_a_small_common_part_stays_in_each_kernel():
    small = sp.Piecewise((u**2, u < 1), (sp.exp(-u), True))
    ks = [_kernel("a", small + u), _kernel("b", small * u)]
    fns = kn.share(tuple(kn.kernel_function(k.name, k.args, k.expr) for k in ks))
    assert [f.name for f in fns] == ["a", "b"]
    assert kn.share(tuple(kn.kernel_function(k.name, k.args, k.expr) for k in ks), min_size=5)[0].name == "a_part1"


def test_the_shared_part_changes_no_python_value_by_a_bit(pair):
    module, alone = {"math": math}, {"math": math}
    exec(compile(files.python_module("test", pair), "<module>", "exec"), module)
    for k in pair:
        exec(compile(kn.py_function(k), "<alone>", "exec"), alone)
        for v in POINTS:
            assert module[k.name](v) == alone[k.name](v), (k.name, v)


def test_the_shared_part_changes_no_c_value_by_a_bit(pair, tmp_path):
    if not shutil.which("cc"):
        pytest.skip("no C compiler")
    (tmp_path / "m").mkdir()
    module = kn.compile_c(files.c_standalone("test", pair), tmp_path / "m")
    for k in pair:
        d = tmp_path / k.name
        d.mkdir()
        alone = kn.compile_c("#include <errno.h>\n#include <math.h>\n" + kn.c_function(k)[1], d)
        f, g = kn.c_callable(module, k.name, 1), kn.c_callable(alone, k.name, 1)
        for v in POINTS:
            assert f(v) == g(v), (k.name, v)


def test_generated_k_and_n2_share_one_root(generated):
    """Haag's K of (36) and n² of (34) both need the root z of (30): it is emitted once."""
    c = (generated / "c" / "haag1935.c").read_text()
    statics = [ln for ln in c.splitlines() if ln.startswith("static double ") and not ln.startswith("static double pendsym_")]
    # (pendsym_*: the helpers of supplied forms, printed once per file, not a shared part)
    assert len(statics) == 1
    name = statics[0].split()[2].split("(")[0]
    for kernel in ("eq036_K_uniform", "eq034_n2_z_uniform"):
        body = c.split(f"double {kernel}(")[1].split("\n}\n")[0]
        below = body.split("\n    } else {\n")[-1]     # u ≤ 700 (above it: the far form and the limit, issue #13)
        assert f"{name}(a, R, lambda_, u)" in below and "sqrt" not in below, kernel
    py = (generated / "python" / "haag1935.py").read_text()
    assert py.count(f"def _{name}(") == 1 and f'"_{name}"' not in py
