"""The kernels of chapter VII (issue #13): G of (263) and C of (285), emitted in Python and C.

The references are written here from the memoir's definitions, not from the kernels' forms:
the uniform blade's w of (157) (the solution of w'' = w/M (9), M = λ²/u², w'(0) = 0, w'(λ) = 1,
verified below), G2 = ∫_0^λ w²/M ds (79) by mpmath quadrature, G = G2/(ελ) (262) and
C = (wλ − F4)/G2 (284) with F4 = ∫_0^λ w'^4 ds (282).  κ = Σ|x_i ∂f/∂x_i|/|f| by central differences of
the same quadratures.  The kernels are the emitted ones: generated/python imported, generated/c compiled at -O2.
"""
import math

import mpmath as mp
import pytest


BOUND = 4.0
DPS = 40
LAM = mp.mpf(1)     # G and C do not depend on λ (both are ratios of lengths); λ = 1


def w_blade(u, s):
    """(157): w(s) = λ ch(us/λ)/(u sh u), the uniform blade's w."""
    return LAM * mp.cosh(u * s / LAM) / (u * mp.sinh(u))


def _pieces(u):
    """Quadrature intervals on [0, λ]: the integrands are ~e^{2u(s/λ − 1)}, peaked at s = λ over λ/u."""
    cuts = sorted({LAM * (1 - mp.mpf(j) / u) for j in (256, 64, 16, 4, 1) if j < u})
    return [mp.mpf(0)] + cuts + [LAM]


def G2(u):
    """(79): G2 = ∫_0^λ w²/M ds at K = 0, M = λ²/u² (156), by quadrature."""
    return mp.quad(lambda s: w_blade(u, s) ** 2 * u**2 / LAM**2, _pieces(u))


def F4(u):
    """(282): F4 = ∫_0^λ w'^4 ds, w' = sh(us/λ)/sh u the derivative of (157)'s w (checked below)."""
    return mp.quad(lambda s: (mp.sinh(u * s / LAM) / mp.sinh(u)) ** 4, _pieces(u))


def C_reference(u):
    """(284): C = (wλ − F4)/G2, wλ = w(λ)."""
    return (w_blade(u, LAM) - F4(u)) / G2(u)


def reference(f, p):
    """(value, κ) of f at the double point p, at DPS digits (κ by central differences, step 1e-15 relative)."""
    with mp.workdps(DPS):
        xs = [mp.mpf(v) for v in p]
        value = f(*xs)
        kappa = 0
        for i, x in enumerate(xs):
            h = abs(x) * mp.mpf(10) ** -15
            up, down = list(xs), list(xs)
            up[i], down[i] = x + h, x - h
            kappa += abs(x * (f(*up) - f(*down)) / (2 * h))
        return value, float(kappa / abs(value))


def ulp_error(got, value) -> float:
    with mp.workdps(DPS):
        return float(abs(mp.mpf(got) - value) / mp.mpf(math.ulp(float(value))))


@pytest.fixture(scope="module")
def emitted(emitted_kernels):
    """{name: {language: callable}} of the two kernels as generated (conftest: imported and compiled once)."""
    haag = emitted_kernels("haag1935")
    return {"eq263_G": haag.functions("eq263_G", 2), "eq285_C": haag.functions("eq285_C", 1)}


def test_the_reference_blade_solves_the_blade_equation():
    """w of (157) solves w'' = w/M (9), M = λ²/u², with w'(0) = 0 and w'(λ) = 1 (n°3), and G2 = wλ − F2 (81)
    at K = 0: the reference stands on the memoir's equations, not on a typed-in result."""
    with mp.workdps(DPS):
        for u in (mp.mpf("0.3"), mp.mpf(2), mp.mpf(40)):
            for s in (mp.mpf(0), mp.mpf("0.37"), LAM):
                w2 = mp.diff(lambda x: w_blade(u, x), s, 2)
                assert abs(w2 - w_blade(u, s) * u**2 / LAM**2) < mp.mpf(10) ** -25 * abs(w2 + 1)
                w1 = mp.diff(lambda x: w_blade(u, x), s)
                assert abs(w1 - mp.sinh(u * s / LAM) / mp.sinh(u)) < mp.mpf(10) ** -25   # F4's w'
            assert abs(mp.diff(lambda x: w_blade(u, x), mp.mpf(0))) < mp.mpf(10) ** -25
            assert abs(mp.diff(lambda x: w_blade(u, x), LAM) - 1) < mp.mpf(10) ** -25
            F2 = mp.quad(lambda s: (mp.sinh(u * s / LAM) / mp.sinh(u)) ** 2, _pieces(u))
            assert abs(G2(u) - (w_blade(u, LAM) - F2)) < mp.mpf(10) ** -30 * G2(u)


G_US = (1e-6, 3.7e-5, 1e-3, 0.0999, 0.12499999999999999, 0.125, 0.12500000000000003, 0.29091020926049677, 0.61,
        1.0, 2.0, 7.3, 31.0, 250.0, 700.0)     # 0.2909…: the audit's worst point (1.35 scaled)
G_EPS = (1e-9, 0.00018719440689896928, 2.3e-4, 0.1)
# the switches 1 and 3 of the emitted pieces with the doubles beside them; 1.2555…: the audit's worst point (0.63)
C_POINTS = [1e-6, 1e-4, 0.01, 0.37, 0.9999999999999999, 1.0, 1.0000000000000002, 1.2555048700599256, 2.0,
            2.9999999999999996, 3.0, 3.0000000000000004, 5.5, 12.0, 40.0, 88.0, 90.0, 300.0, 700.0]


def test_G_kernel_holds_the_contract_against_the_quadrature(emitted):
    """(263)'s kernel within 4 ulp × max(1, κ) of G2/(ελ) (262) across u ∈ [1e-6, 700], ε ∈ [1e-9, 0.1].
    G2/(ελ) is 1/ε times a function of u: one quadrature (and its κ in u) per u, and ε adds exactly 1 to κ."""
    for u in G_US:
        G2_value, kappa_u = reference(G2, (u,))
        for eps in G_EPS:
            with mp.workdps(DPS):
                value = G2_value / (mp.mpf(eps) * LAM)
            for lang, fn in emitted["eq263_G"].items():
                assert ulp_error(fn(u, eps), value) <= BOUND * (kappa_u + 1), (lang, u, eps, kappa_u)


def test_C_kernel_holds_the_contract_against_the_quadrature(emitted):
    """(285)'s kernel within 4 ulp × max(1, κ) of (wλ − F4)/G2 (284) across u ∈ [1e-6, 700]."""
    for u in C_POINTS:
        value, kappa = reference(C_reference, (u,))
        for lang, fn in emitted["eq285_C"].items():
            assert ulp_error(fn(u), value) <= BOUND * max(1.0, kappa), (lang, u, kappa)


def test_C_kernel_gives_its_limits(emitted):
    """C → 1 as u → 0 (accepted down to 0: 0 and the smallest subnormal give 1 to the ulp) and C → 3/2 as
    u → ∞ (at u = 700 the e^{-u} terms are far below an ulp)."""
    for lang, fn in emitted["eq285_C"].items():
        for u in (0.0, 5e-324, 1e-300, 1e-160):
            assert abs(fn(u) - 1.0) <= 2 * math.ulp(1.0), (lang, u)
        assert abs(fn(700.0) - 1.5) <= 4 * math.ulp(1.5) * max(1.0, reference(C_reference, (700.0,))[1]), lang


def test_outside_the_domain_is_a_domain_error(emitted):
    """docs/kernel-accuracy.md: ValueError in Python, NaN (errno EDOM) in C, for NaN, −inf and the doubles just
    outside each end; G keeps u ≥ 1e-6 (it grows as 1/(εu²), (264): no limit at 0)."""
    nxt = lambda x, d: math.nextafter(x, d)    # noqa: E731
    bad = {"eq263_G": [(0.0, 1e-3), (nxt(1e-6, 0), 1e-3), (-math.inf, 1e-3),
                       (math.nan, 1e-3), (1.0, nxt(1e-9, 0)), (1.0, nxt(0.1, 1)), (1.0, 0.0), (-1.0, 1e-3)],
           "eq285_C": [(-5e-324,), (-math.inf,), (math.nan,)]}     # (u above 700 and u = inf: the thread, below)
    for name, points in bad.items():
        for lang, fn in emitted[name].items():
            for p in points:
                if lang == "Python":
                    with pytest.raises(ValueError, match=name):
                        fn(*p)
                else:
                    assert math.isnan(fn(*p)), (name, p)


def test_the_reference_sees_the_cancellation_of_the_printed_C():
    """The test can fail: the printed (3/8)(sh 4u − 4u)/(sh²u(sh 2u + 2u)) in double is far over the bound at
    u = 1e-4 (sh 4u − 4u cancels 8 digits) against the same reference."""
    u = 1e-4
    naive = 0.375 * (math.sinh(4 * u) - 4 * u) / (math.sinh(u) ** 2 * (math.sinh(2 * u) + 2 * u))
    value, kappa = reference(C_reference, (u,))
    assert ulp_error(naive, value) > 100 * BOUND * max(1.0, kappa)


def test_G_and_C_give_the_thread_above_700_and_at_inf(emitted):
    """Both have a finite limit as u → ∞ (docs/kernel-accuracy.md, "Above hi"): C → 3/2 (the thread, (285)), and
    G ~ 1/(2εu) → 0; above 700 the e^{-u} terms are below 1e-304, so the references are 3/2 and (coth u/u)/(2ε)
    with coth u = 1, from (263)'s own terms (U_1² = 1/sh²u underflows)."""
    for u in (math.nextafter(700.0, math.inf), 1e4, 1e300, math.inf):
        for lang, fn in emitted["eq285_C"].items():
            assert fn(u) == 1.5, (lang, u)
        for eps in (1e-9, 0.1):
            with mp.workdps(DPS):
                value = 1 / (2 * mp.mpf(eps) * mp.mpf(u)) if u < math.inf else mp.mpf(0)
            for lang, fn in emitted["eq263_G"].items():
                got = fn(u, eps)
                assert (got == 0.0) if value == 0 else ulp_error(got, value) <= BOUND, (lang, u, eps, got)
