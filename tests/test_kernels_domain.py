"""One behaviour outside the domain, the same in C and Python (docs/kernel-accuracy.md):
a NaN or a value outside the accepted domain is a domain error — ValueError naming the argument
and the domain in Python, NaN with errno = EDOM in C; u → 0 and u → +∞ (u = inf included) give the
limit where it is finite (pendsym/emit/kernels/limits.py)."""
import ctypes
import math
import shutil
import sys

import mpmath as mp
import pytest
import sympy as sp

from pendsym.emit import kernels as kn
from pendsym.result import KernelArg, KernelSpec, Result, Source, Spec

u = sp.Symbol("u", positive=True)
lam = sp.Symbol("lambda", positive=True)
ARGS = (KernelArg("lambda", 1e-3, 10.0, unit="m"), KernelArg("u", 1e-6, 700.0, log=True))
BETA = lam * (1 - 2 * sp.tanh(u / 2) / u)          # → λu²/12 as u → 0: finite limit 0
W0 = lam / (u * sp.sinh(u))                         # → ∞ as u → 0: no limit; → 0 as u → ∞
GROW = lam * u / sp.tanh(u)                         # → λ as u → 0; grows as λu: no limit at +∞
SUBNORMAL = 5e-324


def _result(rid, derived):
    spec = Spec(rid, "k", Source("test", "n°1", eq="1"), "k", lambda deps: derived,
                kernel=KernelSpec(args=ARGS, doc="k."))
    return Result(spec=spec, derived=derived, printed=None)


@pytest.fixture(scope="module")
def kernels():
    return {k.name: k for k in (kn.kernel_of(_result("test.eq1.beta", BETA)), kn.kernel_of(_result("test.eq2.w0", W0)),
                                 kn.kernel_of(_result("test.eq3.grow", GROW)))}


@pytest.fixture(scope="module")
def py(kernels):
    ns = {"math": math}
    for k in kernels.values():
        exec(compile(kn.py_function(k), "<k>", "exec"), ns)
    return ns


@pytest.fixture(scope="module")
def clib(kernels, tmp_path_factory):
    if not shutil.which("cc"):
        pytest.skip("no C compiler")
    text = "#include <errno.h>\n#include <math.h>\n" + "\n".join(kn.c_function(k)[1] for k in kernels.values())
    text += "\nint last_errno(void) { return errno; }\nvoid clear_errno(void) { errno = 0; }\n"
    return kn.compile_c(text, tmp_path_factory.mktemp("domain"))


def _c(lib, name):
    f = getattr(lib, name)
    f.restype, f.argtypes = ctypes.c_double, [ctypes.c_double, ctypes.c_double]
    return f


def _errno(lib, fn, *p):
    lib.clear_errno.restype = None
    lib.last_errno.restype = ctypes.c_int
    lib.clear_errno()
    v = fn(*p)
    return v, lib.last_errno()


def test_the_limits_at_zero_and_infinity_are_accepted_only_where_they_are_finite(kernels):
    assert kernels["eq1_beta"].domain == ((1e-3, 10.0), (0.0, math.inf))
    assert kernels["eq2_w0"].domain == ((1e-3, 10.0), (1e-6, math.inf))
    assert kernels["eq3_grow"].domain == ((1e-3, 10.0), (0.0, 700.0))


OUTSIDE_U = (-1.0, -SUBNORMAL, math.nan, -math.inf)
OUTSIDE_GROW = OUTSIDE_U + (math.inf, math.nextafter(700.0, math.inf), 1e300)
CASES = [(n, b) for n in ("eq1_beta", "eq2_w0") for b in OUTSIDE_U] + [("eq3_grow", b) for b in OUTSIDE_GROW]


@pytest.mark.parametrize(("name", "bad"), CASES)
def test_outside_the_domain_python_raises_a_value_error_naming_the_argument(py, name, bad):
    with pytest.raises(ValueError, match=rf"^{name}: u = .* is outside its domain \[") as err:
        py[name](1.0, bad)
    assert "\n" not in str(err.value)


@pytest.mark.parametrize(("name", "bad"), CASES)
def test_outside_the_domain_c_returns_nan_with_edom(clib, name, bad):
    import errno
    v, e = _errno(clib, _c(clib, name), 1.0, bad)
    assert math.isnan(v) and e == errno.EDOM


@pytest.mark.parametrize("bad", [0.0, math.nan, math.nextafter(1e-3, 0.0), math.nextafter(10.0, math.inf), -1.0])
def test_every_argument_is_tested(py, clib, bad):
    import errno
    with pytest.raises(ValueError, match=r"lambda_ = "):
        py["eq1_beta"](bad, 1.0)
    v, e = _errno(clib, _c(clib, "eq1_beta"), bad, 1.0)
    assert math.isnan(v) and e == errno.EDOM


@pytest.mark.parametrize("name", ["eq2_w0"])
@pytest.mark.parametrize("tiny", [0.0, SUBNORMAL, 1e-300, math.nextafter(1e-6, 0.0)])
def test_below_lo_without_a_finite_limit_is_a_domain_error(py, clib, name, tiny):
    import errno
    with pytest.raises(ValueError):
        py[name](1.0, tiny)
    v, e = _errno(clib, _c(clib, name), 1.0, tiny)
    assert math.isnan(v) and e == errno.EDOM


@pytest.mark.parametrize("tiny", [0.0, SUBNORMAL, 1e-300, 1e-160, 1e-20, math.nextafter(1e-6, 0.0)])
def test_below_lo_with_a_finite_limit_gives_the_value(py, clib, tiny):
    """β = λ(1 − 2 th(u/2)/u) = λu²/12 (1 − u²/10 + …): the reference is that series at 60 digits."""
    with mp.workdps(60):
        true = mp.mpf(2.5) * mp.mpf(tiny) ** 2 / 12 * (1 - mp.mpf(tiny) ** 2 / 10)
    for got in (py["eq1_beta"](2.5, tiny), _c(clib, "eq1_beta")(2.5, tiny)):
        assert math.isfinite(got)
        if true < 1e-300:
            assert abs(got) < 1e-300
        else:
            assert abs(mp.mpf(got) - true) <= 4 * math.ulp(float(true))


def test_the_ends_themselves_are_inside(py, clib):
    for p in ((1e-3, 1e-6), (10.0, 700.0), (1e-3, 700.0)):
        for got in (py["eq2_w0"](*p), _c(clib, "eq2_w0")(*p)):
            assert math.isfinite(got) and got > 0


FAR_U = (math.nextafter(700.0, math.inf), 701.0, 745.0, 1e4, 1e16, 1e300, sys.float_info.max, math.inf)


@pytest.mark.parametrize("far", FAR_U)
def test_above_hi_with_a_finite_limit_gives_the_value(py, clib, far):
    """β = λ(1 − 2 th(u/2)/u) → λ and w0 = λ/(u sh u) → 0 as u → ∞: above 700 the kernels give the form at
    60 digits, and at u = inf its limit (λ; 0), in C and Python."""
    with mp.workdps(60):
        if far == math.inf:
            beta, w0 = mp.mpf(2.5), mp.mpf(0)
        else:
            x = mp.mpf(far)
            beta, w0 = 2.5 * (1 - 2 * mp.tanh(x / 2) / x), 2.5 / (x * mp.sinh(x))
    for lang, (b, w) in {"Python": (py["eq1_beta"](2.5, far), py["eq2_w0"](2.5, far)),
                         "C": (_c(clib, "eq1_beta")(2.5, far), _c(clib, "eq2_w0")(2.5, far))}.items():
        assert abs(mp.mpf(b) - beta) <= 4 * math.ulp(float(beta)), (lang, far, b)
        assert math.isfinite(w) and w >= 0, (lang, far, w)
        assert abs(mp.mpf(w) - w0) <= 4 * math.ulp(float(w0)), (lang, far, w)


def test_the_far_form_drops_only_what_is_below_an_ulp():
    """far_form: the leading terms in e^{−u}, written in 1/u (β: λ − 2λ/u; w0: 2λe^{−u}/u); none for a form
    that grows (λu coth u) or has no limit (a sine)."""
    from pendsym.emit.kernels.limits import far_form
    assert sp.simplify(far_form(BETA, u) - (lam - 2 * lam / u)) == 0
    assert sp.simplify(far_form(W0, u) - 2 * lam * sp.exp(-u) / u) == 0
    assert far_form(GROW, u) is None or sp.limit(far_form(GROW, u), u, sp.oo) == sp.oo
    assert far_form(lam * sp.sin(u) / u, u) is None
