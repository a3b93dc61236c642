"""Haag 1935, chapter IX (issue #14): compensated arithmetic as SymPy forms (:mod:`derivations.haag1935.ch9_holes.compensated`),
measured as the engine emits it (Python and C), against exact rational arithmetic (``fractions``) and mpmath."""
from __future__ import annotations

import math
import random
from fractions import Fraction

import mpmath as mp
import pytest
import sympy as sp

from derivations.haag1935.ch9_holes import compensated as cm
from pendsym.emit import files
from pendsym.emit import kernels as kn
from pendsym.result import KernelArg

from test_haag1935_ch9_kernels import LIBM          # tests/ is on sys.path (pytest, rootdir-less)

a_, b_, c_ = sp.symbols("a b c", positive=True)
ARGS = tuple(KernelArg(n, 1e-300, 1e300, log=True) for n in ("a", "b", "c"))


def _emitted(tmp_path, name: str, form: sp.Expr) -> dict:
    """{language: callable(a, b, c)} of form as the engine prints a kernel (helpers included)."""
    out = {"Python": kn.emitted_py(name, ARGS, form)}
    if LIBM is not None:
        k = kn.Kernel(name, f"test.{name}", ARGS, form, "supplied", "", "", domain=tuple((a.lo, a.hi) for a in ARGS))
        out["C"] = kn.c_callable(kn.compile_c(files.c_standalone("test", [k]), tmp_path / name), name, 3)
    return out


def _points(n: int = 300):
    rnd = random.Random(14)
    return [tuple(math.exp(rnd.uniform(math.log(1e-3), math.log(1e3))) for _ in range(3)) for _ in range(n)]


def _rel(value: float, exact) -> float:
    return float(abs((Fraction(value) - exact) / exact))


@pytest.mark.parametrize("name, build, exact", [
    ("sum3", lambda: cm.total([cm.exact(a_), cm.exact(b_), cm.exact(c_)]), lambda a, b, c: a + b + c),
    ("mulsum", lambda: cm.mul(cm.add(cm.exact(a_), cm.exact(b_)), cm.exact(c_)), lambda a, b, c: (a + b) * c),
    ("divsq", lambda: cm.div(cm.square(cm.exact(a_)), cm.mul(cm.exact(b_), cm.exact(c_))), lambda a, b, c: a * a / (b * c)),
])
def test_compensated_forms_are_correctly_rounded_to_an_ulp(tmp_path, name, build, exact):
    """(a + b) + c, (a + b)c, a²/(bc) by the compensated forms: within 0.5 ulp + 2⁻⁹⁰ relative of the exact rational
    value at 300 points (a plain evaluation would err by up to ~1.5 ulp)."""
    (tmp_path / name).mkdir()
    for lang, fn in _emitted(tmp_path, name, build().value()).items():
        for p in _points():
            true = exact(*(Fraction(x) for x in p))
            value = fn(*p)
            assert _rel(value, true) <= 2.0**-53 + 2.0**-90, (lang, p)


def test_root_and_constant_hold_twice_the_digits():
    """√(a + b) as hi + lo, each emitted apart (not rounded together): within 1e-30 relative of mpmath; the constant π
    as a Pair is π to 1e-31 (its low part is π − fl(π))."""
    pi = cm.constant(mp.pi)
    with mp.workdps(50):
        assert abs(mp.mpf(float(pi.hi)) + mp.mpf(float(pi.lo)) - mp.pi) < 1e-31
    root = cm.root(cm.add(cm.exact(a_), cm.exact(b_)))
    hi, lo = kn.emitted_py("hi", ARGS, root.hi), kn.emitted_py("lo", ARGS, root.lo)
    for p in _points(100):
        with mp.workdps(50):
            true = mp.sqrt(mp.mpf(p[0]) + mp.mpf(p[1]))
            assert abs((mp.mpf(hi(*p)) + mp.mpf(lo(*p))) / true - 1) < 1e-30, p


def test_plain_sum_fails_where_the_compensated_one_holds(tmp_path):
    """The test can fail: the plain (a + b) + c at a = 1, b = c = 2⁻⁵³ is 1, 2⁻⁵² short (a full ulp); the
    compensated total is 1 + 2⁻⁵², exact, in Python and C."""
    p = (1.0, 2.0**-53, 2.0**-53)
    assert (p[0] + p[1]) + p[2] == 1.0
    (tmp_path / "sum").mkdir()
    for lang, fn in _emitted(tmp_path, "sum", cm.total([cm.exact(a_), cm.exact(b_), cm.exact(c_)]).value()).items():
        assert fn(*p) == 1.0 + 2.0**-52, lang


def test_convert_compensates_a_whole_expression(tmp_path):
    """:func:`convert` of an expression with a third, a square root, sin and cos, a negative power and a Piecewise:
    within 1.5 ulp of mpmath at 300 points, Python and C (sin and cos by libm, within about half an ulp each, so that
    their product alone may be off by an ulp; the rest adds ~2⁻¹⁰⁰); the plain double form of the same expression,
    measured beside it, is worse (a test that can fail)."""
    expr = sp.Piecewise(((a_ + b_ / 3) ** 2 / (c_ + 1) + sp.sin(a_ / c_) * sp.cos(b_), a_ < b_),
                        (sp.sqrt(a_ * b_ + c_) / 7, True))
    (tmp_path / "conv").mkdir()
    (tmp_path / "plain").mkdir()
    held = _emitted(tmp_path, "conv", cm.convert(expr, {}).value())
    plain = _emitted(tmp_path, "plain", expr)
    f = sp.lambdify((a_, b_, c_), expr, "mpmath")
    worst = {"held": 0.0, "plain": 0.0}
    for p in _points():
        with mp.workdps(40):
            true = f(*(mp.mpf(x) for x in p))
        for kind, fns in (("held", held), ("plain", plain)):
            for fn in fns.values():
                worst[kind] = max(worst[kind], float(abs(mp.mpf(fn(*p)) - true)) / math.ulp(float(true)))
    assert worst["held"] <= 1.5 and worst["plain"] > worst["held"] + 0.5, worst
