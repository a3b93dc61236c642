"""Chapter III's kernels at u = inf give the thread (issue #13; docs/kernel-accuracy.md, "Above hi").

The reference is chapter IV's limits u → ∞ of the derived forms, taken by SymPy and checked against the shot thread
pendulum (ch4_thread: eq184.ends, eq184.F, eq185.I_J; K and n² of the direct blade: the thread's (193) with z' the
negative root of its (30), and (192)), not the kernels' far forms.  The kernels are the emitted ones: generated/python imported, generated/c compiled at -O2.
"""
import math
import sys

import mpmath as mp
import pytest
import sympy as sp

from pendsym import stages
from pendsym.emit.kernels.measure import reference

# kernel: (number of arguments, the thread's Result, component (None: the whole form), the other arguments' values)
AT = {"lambda": 0.37, "K": -0.71, "m'": 2.3, "a": 0.83, "R": 0.11, "g": 9.81}
THREAD = {
    "eq159_v0": (2, "haag1935.eq184.ends", 0),
    "eq159_w0": (2, "haag1935.eq184.ends", 2),
    "eq159_wl": (2, "haag1935.eq184.ends", 3),
    "eq159_beta1": (2, "haag1935.eq184.ends", 4),
    "eq168_F1": (2, "haag1935.eq184.F", 0),
    "eq169_F2": (2, "haag1935.eq184.F", 1),
    "eq170_F": (2, "haag1935.eq184.F", 2),
    "eq182_I": (4, "haag1935.eq185.I_J", 0),
    "eq183_J": (3, "haag1935.eq185.I_J", 1),
    "eq036_K_uniform": (4, "haag1935.eq193.K", None),
    "eq034_n2_z_uniform": (5, "haag1935.eq192.n2", None),
}
# K (36) and n² (34): above u = 700 their far forms, and above U_flat (where every 1/u correction is below 2⁻⁶⁰) the
# limit itself (their far forms overflow inside the root near u = 1e80 in Python): see test_K_and_n2_above_hi
FAR_ROOT = "haag1935.eq030.thread"
ARG_ORDER = {"eq159_v0": ("lambda", "u"), "eq159_w0": ("lambda", "u"), "eq159_wl": ("lambda", "u"),
             "eq159_beta1": ("lambda", "u"), "eq168_F1": ("u", "K"), "eq169_F2": ("u", "K"), "eq170_F": ("u", "K"),
             "eq182_I": ("lambda", "u", "K", "m'"), "eq183_J": ("lambda", "u", "K"),
             "eq036_K_uniform": ("a", "R", "lambda", "u"), "eq034_n2_z_uniform": ("a", "R", "lambda", "u", "g")}


@pytest.fixture(scope="module")
def emitted(emitted_kernels):
    """{name: {language: callable}} of the kernels of THREAD that are generated (conftest: imported and compiled
    once); a missing one fails its test."""
    haag = emitted_kernels("haag1935")
    return {name: haag.functions(name, THREAD[name][0]) for name in THREAD if hasattr(haag.python, name)}


@pytest.fixture(scope="module")
def limits():
    """{kernel: the thread's value as a SymPy expression of the other arguments}."""
    built = stages.results(sorted({rid for _, rid, _ in THREAD.values() if rid} | {FAR_ROOT}))
    out = {}
    for name, (_, rid, part) in THREAD.items():
        form = built[rid].derived
        out[name] = form[part] if part is not None else form
    # (193) is in z', the negative root of the thread's (30) (its roots' product is −R²)
    quadratic = built[FAR_ROOT].derived
    z = next(s for s in quadratic.free_symbols if s.name == "z")
    K = out["eq036_K_uniform"]
    zp = next(s for s in K.free_symbols if s.name == "z'")
    at = {s: AT[s.name] for s in quadratic.free_symbols if s.name in AT}
    roots = [r for r in sp.solve(quadratic, z) if sp.N(r.subs(at)) < 0]
    assert len(roots) == 1, roots
    out["eq036_K_uniform"] = K.subs(zp, roots[0])
    return out


def _value(expr, name):
    """(value, κ) of the thread's expression at AT, 50 digits (κ by the contract's own differences)."""
    syms = sorted(expr.free_symbols, key=lambda s: s.name)
    if not syms:
        return mp.mpf(sp.N(expr, 50)), 1.0
    f, cond = reference(expr, syms)
    with mp.workdps(50):
        xs = [mp.mpf(AT[s.name]) for s in syms]
        v = f(*xs)
        return v, (float(cond(*xs)) if v != 0 else 1.0)


@pytest.mark.parametrize("name", sorted(THREAD))
def test_the_kernel_at_infinity_is_the_thread(emitted, limits, name):
    """kernel(…, u = inf) is chapter IV's limit, within 4 ulp × max(1, κ) (exactly 0 where the limit is 0), in C
    and Python; and u = 1e300 gives the same."""
    assert name in emitted, f"{name} is not generated"
    value, kappa = _value(limits[name], name)
    for lang, fn in emitted[name].items():
        for far in (math.inf, 1e300):
            p = [far if a == "u" else AT[a] for a in ARG_ORDER[name]]
            got = fn(*p)
            assert math.isfinite(got), (name, lang, far, got)
            if value == 0:
                assert abs(got) < 1e-290, (name, lang, far, got)
            else:
                with mp.workdps(50):
                    err = abs(mp.mpf(got) - value) / mp.mpf(math.ulp(float(value)))
                assert err <= 4 * max(1.0, kappa) + (1e3 if far != math.inf and abs(value) < 1e-200 else 0), \
                    (name, lang, far, got, value)


def test_a_wrong_thread_value_would_fail(limits):
    """The test can fail: β1 at inf is λ, and λ(1 − 2/u) at u = 1e15 (a far form read at a finite u) is 13 ulp off."""
    value, _ = _value(limits["eq159_beta1"], "eq159_beta1")
    wrong = AT["lambda"] * (1 - 2 / 1e15)
    with mp.workdps(50):
        assert abs(mp.mpf(wrong) - value) / mp.mpf(math.ulp(float(value))) > 4


KU = ("eq036_K_uniform", "eq034_n2_z_uniform")
KU_IDS = {"eq036_K_uniform": "haag1935.eq036.K_uniform", "eq034_n2_z_uniform": "haag1935.eq034.n2_z_uniform"}


def _far_points() -> list[float]:
    """u above hi = 700: the double after it, 1.01hi … 2hi, decades 10³ … 10³⁰⁸ (and 2.8×), both sides of 1e25 (K's
    and n²'s U_flat, computed by limits.flat_form), and the largest double."""
    hi = 700.0
    pts = [math.nextafter(hi, math.inf), hi * 1.01, hi * 1.07, hi * 1.5, hi * 2]
    pts += [m * 10.0 ** k for k in range(3, 309, 5) for m in (1.0, 2.8) if m * 10.0 ** k < math.inf]
    pts += [math.nextafter(1e25, 0), 1e25, math.nextafter(1e25, math.inf), 1e308, sys.float_info.max]
    return pts


@pytest.mark.slow
@pytest.mark.parametrize("name", KU)
def test_K_and_n2_above_hi(emitted, name):
    """K (36) and n² (34) above u = 700, in C and Python, within 4 ulp × max(1, κ) of the derived form at 50 digits
    (plus 3 per decade of u: the form as derived cancels like u²), at seeded values of the other arguments."""
    import random
    derived = stages.results([KU_IDS[name]])[KU_IDS[name]].derived
    by = {s.name: s for s in derived.free_symbols}
    syms = [by[a] for a in ARG_ORDER[name]]
    f, cond = reference(derived, syms)
    rng = random.Random(name)
    boxes = {"a": (1e-2, 5.0), "R": (1e-3, 2.0), "lambda": (1e-3, 10.0), "g": (9.7, 9.9)}
    for u in _far_points():
        for _ in range(2):
            p = [u if a == "u" else math.exp(rng.uniform(math.log(boxes[a][0]), math.log(boxes[a][1])))
                 for a in ARG_ORDER[name]]
            with mp.workdps(50 + 3 * math.ceil(math.log10(u))):
                xs = [mp.mpf(v) for v in p]
                true = f(*xs)
                kappa = float(cond(*xs))
                for lang, fn in emitted[name].items():
                    got = fn(*p)
                    err = float(abs(mp.mpf(got) - true) / mp.mpf(math.ulp(float(true))))
                    assert err <= 4 * max(1.0, kappa), (name, lang, p, got, float(true), err, kappa)


def test_a_scaled_K_at_infinity_would_fail(limits):
    """The test can fail: K's thread value times 1 + 3e-15 is over 4 ulp × max(1, κ) from it."""
    value, kappa = _value(limits["eq036_K_uniform"], "eq036_K_uniform")
    wrong = float(value) * (1 + 3e-15)
    with mp.workdps(50):
        assert abs(mp.mpf(wrong) - value) / mp.mpf(math.ulp(float(value))) > 4 * max(1.0, kappa)


@pytest.mark.parametrize("name", KU)
def test_K_and_n2_nan_and_minus_inf_stay_domain_errors(emitted, name):
    """u = NaN and −inf are outside the accepted domain [1e-6, +inf]: ValueError in Python, NaN in C."""
    n = THREAD[name][0]
    for bad in (math.nan, -math.inf):
        p = [0.5, 0.1, 0.2, bad, 9.81][:n]
        for lang, fn in emitted[name].items():
            if lang == "Python":
                with pytest.raises(ValueError, match=name):
                    fn(*p)
            else:
                assert math.isnan(fn(*p))


@pytest.mark.parametrize("n", [2, 3, 4, 5])
def test_Gamma_n_at_infinity_follows_184(emitted_kernels, n):
    """(184): n·u·Γ_n tends to the bracket B_n(K) of eq184.Gn (G_n = λ(u/λ)^{n−2}Γ_n (163)), with k = K(1 − K): the
    kernel at u = 1e300 times n·u is B_n to 1e-14, and at u = inf it is 0 (Γ_n → 0), in Python."""
    fn = getattr(emitted_kernels("haag1935").python, f"eq166_Gamma{n}")
    Gn = stages.results(["haag1935.eq184.Gn"])["haag1935.eq184.Gn"].derived
    by = {s.name: s for s in Gn.free_symbols}
    u, lam = by["u"], by["lambda"]
    n_sym = next(s for s in Gn.free_symbols if s.name == "n")
    B = sp.simplify((Gn.subs(n_sym, n) * n * u / (lam * (u / lam) ** (n - 2))))
    assert not B.has(u) and not B.has(lam), B
    for k in (-11.5, -0.7, 0.03, 0.2499):
        K_value = (1 - math.sqrt(1 - 4 * k)) / 2
        expected = float(B.subs(by["K"], K_value))
        got = fn(1e300, k) * n * 1e300
        assert abs(got - expected) <= 1e-14 * abs(expected), (n, k, got, expected)
        assert fn(math.inf, k) == 0.0, (n, k)
