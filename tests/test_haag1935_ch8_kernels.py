"""The kernels of chapter VIII (issue #13): n² and K of the inverted uniform blade stated in ε
(eq034_n2_inverted_eps, eq036_K_inverted_eps), G of (314) and C of (317) on the windows n = 0 (eq317_C) and
n = 1 (eq317_C_window1), emitted in Python and C.

References, never the forms under test:
- n² and K: the eigenproblem K q = n² 𝕄 q of the rigid pendulum on the directly solved inverted blade
  (pendsym.suspension, g < 0), the mode whose node is above G (the truth of eq034.n2_inverted's check), at
  a = a1 − ελ with a1 where det K = 0 (:func:`derivations.haag1935.ch8_inverted.table_kernels.node_mode`);
  K also from the memoir's definitions at 60 digits: (36) K = (a + wλ)/(a + z − vλ), z the positive root of the
  quadratic (30) of chapter I (mpmath polyroots), with vλ, wλ of (313), β1 of (307), a = a1 − ελ, a1 of (310);
- G and C: the inverted blade's w, the solution of w'' = w/M (9) with M = −λ²/u², w'(0) = 0, w'(λ) = 1 (checked
  below), G2 = wλ − F2 (81) and F4 = ∫w'^4 ds (282) by mpmath quadrature: G = −G2/(ελ) ((262) with ε → −ε, (312)),
  C = (wλ − F4)/G2 (284).
The kernels are the emitted ones: generated/python imported, generated/c compiled at -O2.
"""
import math
import re

import mpmath as mp
import pytest
import sympy as sp

from derivations.haag1935.ch7_gravity import truth as gravity_truth
from derivations.haag1935.ch8_inverted import kernels as ch8_kernels
from derivations.haag1935.ch8_inverted.table_kernels import node_mode
from pendsym.emit.kernels.measure import reference

BOUND = 4.0
DPS = 40
LAM = mp.mpf(1)     # G and C do not depend on λ
NAMES = {"eq034_n2_inverted_eps": 5, "eq314_G": 2, "eq317_C": 1, "eq036_K_inverted_eps": 4, "eq317_C_window1": 1}


@pytest.fixture(scope="module")
def emitted(emitted_kernels):
    """{name: {language: callable}} of the five kernels as generated (conftest: imported and compiled once a run)."""
    haag = emitted_kernels("haag1935")
    return {name: haag.functions(name, n) for name, n in NAMES.items()}


@pytest.fixture(scope="module")
def code(generated):
    return (generated / "python" / "haag1935.py").read_text()


def ulp_error(got, value) -> float:
    with mp.workdps(DPS):
        return float(abs(mp.mpf(got) - value) / mp.mpf(math.ulp(float(value))))


# ---------------------------------------------------------------- G and C: the memoir's definitions
def w_blade(u, s):
    """The inverted blade's w: w = −λ cos(us/λ)/(u sin u) solves w'' = −(u/λ)²w, w'(0) = 0, w'(λ) = 1."""
    return -LAM * mp.cos(u * s / LAM) / (u * mp.sin(u))


def G2(u):
    """(81): G2 = wλ − F2, F2 = ∫_0^λ w'² ds by quadrature."""
    return w_blade(u, LAM) - mp.quad(lambda s: (mp.sin(u * s / LAM) / mp.sin(u)) ** 2, [0, LAM])


def C_reference(u):
    """(284): C = (wλ − F4)/G2, F4 = ∫_0^λ w'^4 ds by quadrature."""
    return (w_blade(u, LAM) - mp.quad(lambda s: (mp.sin(u * s / LAM) / mp.sin(u)) ** 4, [0, LAM])) / G2(u)


def kappa_of(f, p, dps=DPS):
    """(f(p), κ = Σ|x_i ∂f/∂x_i|/|f|) by central differences (step 1e-15 relative) at dps digits."""
    with mp.workdps(dps):
        xs = [mp.mpf(v) for v in p]
        value, total = f(*xs), 0
        for i, x in enumerate(xs):
            h = abs(x) * mp.mpf(10) ** -15
            up, down = list(xs), list(xs)
            up[i], down[i] = x + h, x - h
            total += abs(x * (f(*up) - f(*down)) / (2 * h))
        return value, float(total / abs(value))


def test_the_reference_blade_solves_the_inverted_blade_equation():
    with mp.workdps(DPS):
        for u in (mp.mpf("0.3"), mp.mpf(2), mp.mpf(3)):
            for s in (mp.mpf(0), mp.mpf("0.37"), LAM):
                w2 = mp.diff(lambda x: w_blade(u, x), s, 2)
                assert abs(w2 + w_blade(u, s) * u**2 / LAM**2) < mp.mpf(10) ** -25 * (abs(w2) + 1)
                assert abs(mp.diff(lambda x: w_blade(u, x), s) - mp.sin(u * s / LAM) / mp.sin(u)) < mp.mpf(10) ** -25
            assert abs(mp.diff(lambda x: w_blade(u, x), LAM) - 1) < mp.mpf(10) ** -25
            # G2 = ∫ w²/M ds (79) with M = −λ²/u²
            direct = -mp.quad(lambda s: w_blade(u, s) ** 2 * u**2 / LAM**2, [0, LAM])
            assert abs(G2(u) - direct) < mp.mpf(10) ** -30 * abs(direct)


# the switches 0.125, 1 (the series of C below 1) with the doubles beside them; π/2 (cos u = 0 in the form as
# derived), 3.14159… (the window's end, the double below π), and points near it
C_US = (1e-6, 1e-3, 0.12499999999999999, 0.125, 0.9999999999999999, 1.0, 1.0000000000000002, 1.5,
        1.5707963267948966, 2.0, 2.9, 3.1, 3.14159, 3.141592653589793)
G_EPS = (1e-9, 3.3e-4, 0.1)


def test_C_kernel_holds_the_contract_against_the_quadrature(emitted):
    for u in C_US:
        value, kappa = kappa_of(C_reference, (u,))
        for lang, fn in emitted["eq317_C"].items():
            assert ulp_error(fn(u), value) <= BOUND * max(1.0, kappa), (lang, u, kappa)


def test_C_kernel_gives_its_limit_at_zero(emitted):
    """C → 1 as u → 0 (accepted down to 0)."""
    for lang, fn in emitted["eq317_C"].items():
        for u in (0.0, 5e-324, 1e-300, 1e-160):
            assert abs(fn(u) - 1.0) <= 2 * math.ulp(1.0), (lang, u)


def test_G_kernel_holds_the_contract_against_the_quadrature(emitted):
    """G = −G2/(ελ): one quadrature per u; ε adds exactly 1 to κ."""
    for u in C_US[:1] + C_US[2:]:
        g2, kappa_u = kappa_of(G2, (u,))
        for eps in G_EPS:
            with mp.workdps(DPS):
                value = -g2 / (mp.mpf(eps) * LAM)
            for lang, fn in emitted["eq314_G"].items():
                assert ulp_error(fn(u, eps), value) <= BOUND * (kappa_u + 1), (lang, u, eps, kappa_u)


def test_the_G_reference_sees_the_cancellation_of_the_form_as_derived():
    """The test can fail: (−u − sin 2u/2)/(uε(cos 2u − 1)), G as derived, divides by cos 2u − 1 = 0 at the double
    below π and loses half its digits at u = 1e-5 (cos 2u − 1 cancels)."""
    def as_derived(u, eps):
        return (-u - math.sin(2 * u) / 2) / (u * eps * (math.cos(2 * u) - 1))
    with pytest.raises(ZeroDivisionError):
        as_derived(math.pi, 1e-3)
    u = 1e-5
    g2, kappa_u = kappa_of(G2, (u,))
    with mp.workdps(DPS):
        value = -g2 / (mp.mpf(1e-3) * LAM)
    assert ulp_error(as_derived(u, 1e-3), value) > 100 * BOUND * (kappa_u + 1)


# ---------------------------------------------------------------- n² and K: the eigenproblem
# (u, ε): inside the window below and above π/2 (a1 < 0 there), near the critical distance and at ε = 0.4
TRUTH_POINTS = (("u=1/2", "1/1000"), ("u=1", "1/10"), ("u=3/2", "1/5"), ("u=5/2", "1/10"))


def _truth_args(key, eps):
    u = float(mp.mpf(key[2:].split("/")[0]) / mp.mpf(key[2:].split("/")[1])) if "/" in key else float(key[2:])
    R = float(gravity_truth.R_VALUE)
    lam = float(gravity_truth.LAMBDA)
    g = float(gravity_truth.G_VALUE)
    return u, float(mp.mpf(eps.split("/")[0]) / mp.mpf(eps.split("/")[1])), R, lam, g


@pytest.mark.slow
def test_n2_kernel_holds_the_contract_against_the_eigenproblem(emitted):
    """n² and K of the slow mode at a = a1 − ελ from the eigenproblem of the directly solved blade (30 digits), at
    points where u, λ, R are the truth's (exact doubles or within 1e-17 of them): within 4 ulp × max(1, κ), κ ≤ 3
    here (n² ∝ ε; the other arguments enter through ratios of O(1))."""
    for key, eps in TRUTH_POINTS:
        n2, K = node_mode(key, eps, 30)
        u, e, R, lam, g = _truth_args(key, eps)
        for lang, fn in emitted["eq034_n2_inverted_eps"].items():
            assert ulp_error(fn(e, R, lam, u, g), n2) <= BOUND * 3, (lang, key, eps)


def test_n2_kernel_against_one_eigenproblem_point(emitted):
    """Quick sibling of the slow test: one point (u = 1, ε = 1/10) of the eigenproblem, and a kernel scaled by
    1 + 3e-15 (13 ulp) would fail it."""
    n2, K = node_mode("u=1", "1/10", 30)
    u, e, R, lam, g = _truth_args("u=1", "1/10")
    for lang, fn in emitted["eq034_n2_inverted_eps"].items():
        got = fn(e, R, lam, u, g)
        assert ulp_error(got, n2) <= BOUND, (lang, got)
        assert ulp_error(got * (1 + 3e-15), n2) > BOUND, lang


def test_n2_is_proportional_to_eps_near_the_critical_distance(emitted):
    """n² ∝ ε near the critical distance (the sensitivity of the inverted gravity meter): n²/ε from the eigenproblem
    at ε = 1/1000 is the kernel's to 1e-12 there, and its value at ε = 1e-9 to 1e-2 (the O(ε) term)."""
    n2, _ = node_mode("u=1/2", "1/1000", 30)
    slope = n2 / mp.mpf("0.001")
    u, _, R, lam, g = _truth_args("u=1/2", "1/1000")
    for lang, fn in emitted["eq034_n2_inverted_eps"].items():
        assert abs(fn(1e-9, R, lam, u, g) / 1e-9 / slope - 1) < 1e-2, lang
        assert abs(fn(1e-3, R, lam, u, g) / 1e-3 / slope - 1) < 1e-12, lang


# ---------------------------------------------------------------- switches and the audit's worst points
def _switch_points(code: str, name: str) -> list[float]:
    m = re.search(rf"^def {name}\(.*?(?=^def |\Z)", code, re.S | re.M)
    return sorted({float(c) for c in re.findall(r"\bu *[<>]=? *([0-9.]+(?:e[-+]?[0-9]+)?)\b", m.group(0))})


@pytest.mark.slow
def test_kernels_hold_the_contract_at_their_switches(emitted, code):
    """At each switch of u read from the emitted Python, the double below, the switch and the double above:
    within 4 ulp × max(1, κ) of the Result's derived form at 50 digits (κ: measure.reference), in C and Python."""
    from pendsym import stages
    ids = {"eq034_n2_inverted_eps": "haag1935.eq034.n2_inverted_eps", "eq314_G": "haag1935.eq314.G",
           "eq317_C": "haag1935.eq317.C"}
    built = stages.results(list(ids.values()))
    others = {"varepsilon": 0.0371, "R": 0.05, "lambda": 0.1, "g": 9.81}
    for name, rid in ids.items():
        result = built[rid]
        args = [a for a in result.spec.kernel.args if a.name in {s.name for s in result.derived.free_symbols}]
        syms = [next(s for s in result.derived.free_symbols if s.name == a.name) for a in args]
        f, cond = reference(result.derived, syms)
        for c in _switch_points(code, name):
            for u in (math.nextafter(c, 0.0), c, math.nextafter(c, math.inf)):
                if not 1e-6 <= u <= math.pi:
                    continue
                p = [u if a.name == "u" else others[a.name] for a in args]
                with mp.workdps(50):
                    value = f(*[mp.mpf(v) for v in p])
                    kappa = float(cond(*[mp.mpf(v) for v in p]))
                for lang, fn in emitted[name].items():
                    assert ulp_error(fn(*p), value) <= BOUND * max(1.0, kappa), (name, lang, u)


def test_outside_the_domain_is_a_domain_error(emitted):
    """ValueError in Python, NaN in C: u beyond the window (π and above: the circular forms have no limit at ∞,
    so u = inf is a domain error; for C on the window n = 1, outside 2x1 ≤ u < 3π), ε ≤ 0 or above 1/4, NaN."""
    nxt = math.nextafter
    bad = {"eq034_n2_inverted_eps": [(0.1, 0.05, 0.1, 3.1415926535897936, 9.81), (0.1, 0.05, 0.1, math.inf, 9.81),
                                     (0.0, 0.05, 0.1, 1.0, 9.81), (nxt(0.25, 1), 0.05, 0.1, 1.0, 9.81),
                                     (math.nan, 0.05, 0.1, 1.0, 9.81), (0.1, 0.05, 0.1, 0.0, 9.81)],
           "eq314_G": [(0.0, 1e-3), (3.1415926535897936, 1e-3), (math.inf, 1e-3), (1.0, 0.0), (1.0, nxt(0.1, 1))],
           "eq317_C": [(-5e-324,), (3.1415926535897936,), (9.0,), (math.inf,), (math.nan,)],
           "eq036_K_inverted_eps": [(0.0, 0.05, 0.1, 1.0), (nxt(0.25, 1), 0.05, 0.1, 1.0), (0.1, 0.05, 0.1, 0.0),
                                    (0.1, 0.05, 0.1, 3.1415926535897936), (0.1, 0.05, 0.1, math.inf),
                                    (math.nan, 0.05, 0.1, 1.0)],
           "eq317_C_window1": [(nxt(8.986818915818128, 0),), (nxt(9.42477796076938, 10),), (1.0,), (math.inf,),
                               (math.nan,)]}
    for name, points in bad.items():
        for lang, fn in emitted[name].items():
            for p in points:
                if lang == "Python":
                    with pytest.raises(ValueError, match=name):
                        fn(*p)
                else:
                    assert math.isnan(fn(*p)), (name, p)


def test_the_eps_domain_keeps_the_root_positive():
    """ε ≤ 1/4 < min over the window of 1/(u sin u) (0.5495 at tan u = −u): D = a − vλ > 0 on the whole box."""
    assert ch8_kernels.EPS_INVERTED.hi == 0.25
    with mp.workdps(30):
        u_star = mp.findroot(lambda x: mp.tan(x) + x, 2.03)
        assert 1 / (u_star * mp.sin(u_star)) > ch8_kernels.EPS_INVERTED.hi
        assert all(1 / (x * mp.sin(x)) > 2 * ch8_kernels.EPS_INVERTED.hi for x in mp.linspace(mp.mpf("1e-6"), mp.pi - mp.mpf("1e-9"), 400))


# the worst points make audit found (scaled 3.44 for C, 2.43 for G, 2.44 for n²): C and G against the quadratures,
# n² against the Result's derived form at 50 digits (the contract's reference; the eigenproblem truth is at λ = 1/10)
def test_C_and_G_at_the_audit_worst_points(emitted):
    value, kappa = kappa_of(C_reference, (1.017566226270265,))
    for lang, fn in emitted["eq317_C"].items():
        assert ulp_error(fn(1.017566226270265), value) <= BOUND * max(1.0, kappa), lang
    g2, kappa_u = kappa_of(G2, (1.8191182427059926,))
    with mp.workdps(DPS):
        value = -g2 / (mp.mpf(4.492336668341541e-09) * LAM)
    for lang, fn in emitted["eq314_G"].items():
        assert ulp_error(fn(1.8191182427059926, 4.492336668341541e-09), value) <= BOUND * (kappa_u + 1), lang


@pytest.mark.slow
def test_n2_at_the_audit_worst_point(emitted):
    from pendsym import stages
    result = stages.results(["haag1935.eq034.n2_inverted_eps"])["haag1935.eq034.n2_inverted_eps"]
    p = (0.24313618986389524, 0.2657024516246783, 1.6564097084043943, 1.827704536987043, 9.827929170558107)
    syms = [next(s for s in result.derived.free_symbols if s.name == a.name) for a in result.spec.kernel.args]
    f, cond = reference(result.derived, syms)
    with mp.workdps(50):
        value, kappa = f(*[mp.mpf(v) for v in p]), float(cond(*[mp.mpf(v) for v in p]))
    for lang, fn in emitted["eq034_n2_inverted_eps"].items():
        assert ulp_error(fn(*p), value) <= BOUND * max(1.0, kappa), lang


# ---------------------------------------------------------------- K of (36): the memoir's definitions and the eigenproblem
def K_memoir(eps, R, lam, u):
    """(36) K = (a + wλ)/(a + z − vλ) at 60 digits: vλ = −(λ/u) tan(u/2), wλ = −λ/(u tan u) (313), β1 = λ(1 − 2 tan(u/2)/u)
    (307), a = a1 − ελ with a1 = λ/(u tan u) (310), z the positive root of (30): z² + z(a² + aβ1 − 2avλ + β1wλ + vλ² −
    R²)/(a − vλ) − R² = 0 (chapter I, as ch1_model.foci_quadratic prints it), by mpmath polyroots."""
    with mp.workdps(60):
        eps, R, lam, u = (mp.mpf(x) for x in (eps, R, lam, u))
        vl = -lam * mp.tan(u / 2) / u
        wl = -lam / (u * mp.tan(u))
        b1 = lam * (1 - 2 * mp.tan(u / 2) / u)
        a = lam / (u * mp.tan(u)) - eps * lam
        coef = (a**2 + a * b1 - 2 * a * vl + b1 * wl + vl**2 - R**2) / (a - vl)
        z = max(mp.re(r) for r in mp.polyroots([1, coef, -R**2], maxsteps=200, extraprec=200))
        return (a + wl) / (a - vl + z)


def test_the_K_reference_is_the_eigenproblem():
    """The memoir's-definitions reference agrees with the eigenproblem of the directly solved blade (30 digits) at
    u = 1, ε = 1/10 (R = 0.05, λ = 1/10), so it is the slow mode's K and not the fast one's."""
    _, K = node_mode("u=1", "1/10", 30)
    with mp.workdps(30):
        assert abs(K_memoir(mp.mpf(1) / 10, mp.mpf("0.05"), mp.mpf(1) / 10, 1) / K - 1) < mp.mpf(10) ** -25


def test_K_kernel_against_one_eigenproblem_point(emitted):
    """Quick: K at u = 1, ε = 1/10, r = R/λ = 1/2 from the eigenproblem (K = −n²z'/g of the mode whose node is
    above G); the doubles 0.05 and 0.1 have the ratio 1/2 exactly, and a kernel scaled by 1 + 3e-15 would fail."""
    _, K = node_mode("u=1", "1/10", 30)
    value, kappa = kappa_of(K_memoir, (0.1, 0.05, 0.1, 1.0))
    for lang, fn in emitted["eq036_K_inverted_eps"].items():
        got = fn(0.1, 0.05, 0.1, 1.0)
        assert ulp_error(got, K) <= BOUND * max(1.0, kappa), (lang, got, kappa)


# the worst points of make audit (2.46 scaled, κ = 1.03) and of a 3,000-point search with local climbs (κ ≈ 1 near u = 2.03, where
# 1/(u sin u) is stationary and its rounding is not covered by κ); the branch p = 0 of the root (r² = d² − εb at
# u = 1, ε = 1/10, λ = 1); corners of the box (u = 3 for π: at the double below π, κ ~ u/(π − u) ~ 1e16 and the
# central differences of kappa_of straddle π)
K_POINTS = ((0.00012433127694323583, 0.0016348740104686792, 0.37363152135961775, 2.018743962723669),
            (1.0284992483864916e-06, 0.019126446379176733, 2.627992054067572, 2.0429557609057576),
            (1e-09, 0.001, 10.0, 3.0), (0.25, 2.0, 0.001, 1e-06), (0.25, 0.001, 10.0, 2.0287578381104345),
            (1e-09, 2.0, 0.001, 3.0), (1e-09, 0.001, 10.0, 1e-06), (0.1, 1.0926410225918324, 1.0, 1.0),
            (0.1, 1.0926410225918326, 1.0, 1.0), (0.1, 1.0926410225918328, 1.0, 1.0))


def test_K_kernel_holds_the_contract_against_the_memoir_definitions(emitted):
    for p in K_POINTS:
        value, kappa = kappa_of(K_memoir, p)
        for lang, fn in emitted["eq036_K_inverted_eps"].items():
            assert ulp_error(fn(*p), value) <= BOUND * max(1.0, kappa), (lang, p, kappa)


def test_K_kernel_scaled_by_3e_15_fails_at_the_worst_point(emitted):
    """κ ≈ 1.04 at the search's worst point: 1 + 3e-15 is 13 ulp, over 4 × κ; the kernel itself holds 4 × κ."""
    p = K_POINTS[0]
    value, kappa = kappa_of(K_memoir, p)
    assert kappa < 1.5
    for lang, fn in emitted["eq036_K_inverted_eps"].items():
        got = fn(*p)
        assert ulp_error(got, value) <= BOUND * max(1.0, kappa), lang
        assert ulp_error(got * (1 + 3e-15), value) > BOUND * max(1.0, kappa), lang


@pytest.mark.slow
def test_K_kernel_against_the_eigenproblem_at_the_worst_point(emitted):
    """The eigenproblem of the directly solved blade at 50 digits at the worst point's u and ε, the blade λ = 1/10 and
    R = λ·(R/λ of the point) (K depends on R and λ through R/λ alone): within 4 ulp × max(1, κ)."""
    from derivations.haag1935.ch8_inverted import truth
    eps, R, lam, u = K_POINTS[0]
    key = f"u={sp.Rational(u)}"
    sus = truth.truth.direct(key, truth.SIGN, 0, 50)
    with mp.workdps(sus.wdps):
        env = truth.truth.numbers(key, truth.SIGN, 50)
        a = env["a_1"] - mp.mpf(eps) * env["lambda"]
        R_t = mp.mpf(R) / mp.mpf(lam) * env["lambda"]
        n2, zp = min(truth.truth.eigenmodes(sus, a, R_t, env["g"]), key=lambda pair: pair[1])
        K = -n2 * zp / env["g"]
    _, kappa = kappa_of(K_memoir, K_POINTS[0])
    for lang, fn in emitted["eq036_K_inverted_eps"].items():
        assert ulp_error(fn(*K_POINTS[0]), K) <= BOUND * max(1.0, kappa), lang


# ---------------------------------------------------------------- C on the window n = 1 (2x1 < u < 3π)
C1_US = (8.986818915818128, 9.0, 9.029286992629844, 9.2, 9.4, 9.42477, 9.42477796076938)   # 9.0293: make audit's worst


def test_C_window1_kernel_holds_the_contract_against_the_quadrature(emitted):
    """The quadrature at 50 digits (the audit's worst point among them)."""
    for u in C1_US:
        value, kappa = kappa_of(C_reference, (u,), 50)
        for lang, fn in emitted["eq317_C_window1"].items():
            got = fn(u)
            assert ulp_error(got, value) <= BOUND * max(1.0, kappa), (lang, u, kappa)


def test_C_window1_domain_is_the_window():
    """The declared ends are 2x1 (x1: tan x = x, (308)) rounded up and 3π rounded down: the window n = 1 of (309)."""
    arg = ch8_kernels.U_WINDOW1
    with mp.workdps(40):
        end = 2 * mp.findroot(lambda x: mp.tan(x) - x, 4.49)
        assert mp.mpf(arg.lo) >= end and mp.mpf(math.nextafter(arg.lo, 0)) < end
        assert mp.mpf(arg.hi) < 3 * mp.pi and mp.mpf(math.nextafter(arg.hi, math.inf)) >= 3 * mp.pi


def test_C_window1_kernel_scaled_by_4e_14_fails_at_the_window_end(emitted):
    """κ ≥ 37 on the whole window n = 1 (1/sin²u): a scaling by 1 + 4e-14 (≥ 180 ulp) is over 4κ at its lower end."""
    u = C1_US[0]
    value, kappa = kappa_of(C_reference, (u,), 50)
    for lang, fn in emitted["eq317_C_window1"].items():
        assert ulp_error(fn(u) * (1 + 4e-14), value) > BOUND * max(1.0, kappa), lang


def test_C_grows_as_three_quarters_over_sin_squared_at_the_windows_ends():
    """The kernels' docstrings: C ~ 3/(4 sin²u) as u → π (window n = 0) and u → 3π (window n = 1), not 3π/(16 sin²u)
    as session 9's docstring of eq317_C said.  From the quadrature, C sin²u − 3/4 falls like (mπ − u)¹: its fitted
    order over h = mπ − u = 1e-2 … 1e-5 is 1 (rule 3), so the limit is 3/4 and nothing else."""
    with mp.workdps(DPS):
        for m in (1, 3):
            hs = [mp.mpf(10) ** -k for k in range(2, 6)]
            res = [abs(C_reference(m * mp.pi - h) * mp.sin(m * mp.pi - h) ** 2 - mp.mpf(3) / 4) for h in hs]
            slopes = [mp.log(res[i] / res[i + 1]) / mp.log(hs[i] / hs[i + 1]) for i in range(len(hs) - 1)]
            assert all(abs(s - 1) < 0.02 for s in slopes), (m, slopes)
            assert abs(C_reference(m * mp.pi - hs[-1]) * mp.sin(m * mp.pi - hs[-1]) ** 2 - 3 * mp.pi / 16) > mp.mpf("0.1")
