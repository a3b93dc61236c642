"""pendsym.audit: the points of the deep audit (hard points, the adversarial search) and its
verdict, on small kernels whose worst points are known."""
import math

import pytest
import sympy as sp

from pendsym.audit import points as pt
from pendsym.audit import run
from pendsym.result import KernelArg

u, K = sp.symbols("u K", real=True)
ARGS = (KernelArg("u", 1e-6, 700.0, log=True), KernelArg("K", -3.0, 3.0))


def test_switches_are_read_from_the_emitted_comparisons():
    code = "def f(u, K):\n    if (u < 0.125):\n        x = 1\n    elif (u < 3.0):\n        x = 2\n    if K <= -1.5e-3:\n"
    assert pt.switches(code, ["u", "K"]) == {"u": [0.125, 3.0], "K": [-1.5e-3]}


def test_the_stationary_points_and_zeros_of_a_polynomial_argument_are_hard_points():
    """(K − c(u))² − 1 with c = 1/(1 + u): its vertex K = c and zeros K = c ± 1 are found."""
    expr = (K - 1 / (1 + u)) ** 2 - 1
    import random
    got = pt.polynomial_points(ARGS, expr, (u, K), random.Random(1))
    assert got
    for p in got[:60]:
        c = 1 / (1 + p[0])
        assert min(abs(p[1] - c), abs(p[1] - c - 1), abs(p[1] - c + 1)) < 1e-12


@pytest.mark.slow
def test_hard_points_hold_the_ends_and_the_doubles_inside_them():
    pts = pt.hard_points(ARGS, ["u", "K"], "if (u < 0.5):", (K - u) ** 2, (u, K), "s")
    us, ks = {p[0] for p in pts}, {p[1] for p in pts}
    assert {1e-6, math.nextafter(1e-6, 1), 700.0, math.nextafter(700.0, 0)} <= us
    assert {-3.0, 3.0, 0.0, 5e-324} <= ks
    assert {0.5, math.nextafter(0.5, 0), math.nextafter(0.5, 1)} <= us
    assert all(1e-6 <= a <= 700 and -3 <= b <= 3 for a, b in pts)
    assert pts == pt.hard_points(ARGS, ["u", "K"], "if (u < 0.5):", (K - u) ** 2, (u, K), "s")   # seeded


def test_the_search_climbs_to_a_narrow_peak():
    peak = (2.0, 0.25)

    def score(p, floor):
        return 1.0 / (1e-9 + abs(math.log(p[0] / peak[0])) + abs(p[1] - peak[1]))
    start = (1.5, 0.0)
    best, value, tried = pt.climb(start, score(start, 0), score, ARGS, "s", 400)
    assert value > 20 * score(start, 0) and len(tried) == pt.climb_length(400)


def _job(name, expr, fn, args=ARGS[:1]):
    syms = tuple(sorted(expr.free_symbols, key=lambda s: s.name))
    return run.Job(name, "test", "test." + name, args, expr, syms, fn, fn, "")


@pytest.fixture
def few_points(monkeypatch):
    monkeypatch.setattr(run, "POINTS", 1500)
    monkeypatch.setattr(run, "CLIMB_BUDGET", 160)


def test_a_correct_kernel_passes(few_points):
    rep = run.audit_one(_job("e", sp.exp(-u), lambda x: math.exp(-x)))
    assert rep["points"] >= 1500 and rep["worst_scaled"] <= 1.0 and rep["python"]["over_bound"] == 0
    assert not run.over([rep])


def test_a_kernel_that_cancels_fails_and_its_worst_point_is_found(few_points):
    """1 − cos u evaluated plainly loses everything as u → 0 (true value u²/2)."""
    rep = run.audit_one(_job("c", 1 - sp.cos(u), lambda x: 1 - math.cos(x)))
    assert run.over([rep]) and rep["c"]["over_bound"] > 0
    assert rep["worst_at"][0] < 1e-3


def test_the_reference_has_digits_for_the_cancellation_near_zero(few_points):
    """(1 − cos u)/u² at u = 1e-6 cancels 12 digits: a correct kernel (its series) must pass."""
    def good(x):
        return 2 * math.sin(x / 2) ** 2 / (x * x)
    rep = run.audit_one(_job("s", (1 - sp.cos(u)) / u**2, good, (KernelArg("u", 1e-6, 3.0, log=True),)))
    assert rep["worst_scaled"] <= 4.0, rep


def test_an_argument_accepted_up_to_inf_is_read_and_sampled_there(few_points, monkeypatch):
    """A guard `<= math.inf` is read as +inf, the audit then samples above hi and +inf itself, where the
    reference is the limit: th u/u → 0 given as 0 passes; a kernel that gives NaN at inf fails."""
    code = "def k(u):\n    if not 1e-06 <= u <= math.inf:\n        raise ValueError('k: u = 1 is outside its domain')\n"
    assert run.accepted(code, "k", ARGS[:1]) == ((1e-6, math.inf),)
    expr = sp.tanh(u) / u

    def good(x):
        return 1.0 / x if x > 700.0 else math.tanh(x) / x

    def bad(x):
        return math.tanh(x) / x if x < math.inf else math.nan
    monkeypatch.setattr(run, "outside", lambda job, errno_of: [])     # (these plain functions have no guard)
    for fn, passes in ((good, True), (bad, False)):
        job = run.Job("t", "test", "test.t", ARGS[:1], expr, (u,), fn, fn, "", ((1e-6, math.inf),))
        far = run.far_points(job, "t")
        assert math.inf in [p[0] for p in far] and min(p[0] for p in far) > 700.0
        rep = run.audit_one(job)
        assert (not run.over([rep])) == passes, rep


def test_the_mpfr_reference_is_mpmaths_to_its_last_digits_and_falls_back_where_it_cannot():
    """The MPFR form of a derived expression (π, a Piecewise, a rational) equals mpmath's at 60 digits;
    a function MPFR lacks (besselj) gives Arb's form (tests/test_audit_verdict.py)."""
    import mpmath as mp
    expr = sp.Piecewise((sp.tanh(u / 2) * K**2 / 3 + sp.pi, u < 1), (sp.sin(u) / u - K, True))
    f_mp, _ = run.reference(expr, [u, K])
    f, cond, engine = run.fast_reference(expr, (u, K), (0.5, 1.5))
    assert engine == "mpfr"
    with mp.workdps(60):
        for p in ((0.25, -2.0), (3.0, 0.125), (1e-300, 3.0)):
            a, b = f(*map(mp.mpf, p)), f_mp(*map(mp.mpf, p))
            assert abs(a - b) <= mp.mpf(10) ** -58 * abs(b), (p, a, b)
    assert run.fast_reference(sp.besselj(0, u), (u,), (0.5,))[2] == "arb"      # (MPFR lacks it: Arb)
    big, _, _ = run.fast_reference((sp.exp(8 * u) - 1) / sp.exp(8 * u), (u,), (0.5,))     # beyond MPFR's exponents
    with mp.workdps(50):
        assert big(mp.mpf(1e8)) == 1 and big(mp.mpf(1e300)) == 1


def test_the_error_in_ulp_from_the_split_truth_is_the_direct_one():
    """|got − true|/ulp(true) from true = hi + lo in doubles equals the 64-bit mpmath difference, for an
    error of a fraction of an ulp, several ulp, and a value far off; 0 and NaN keep their meaning."""
    import mpmath as mp
    with mp.workdps(50):
        true = mp.mpf(1) / 3
        for got in (1 / 3, math.nextafter(1 / 3, 1), 1 / 3 + 7 * math.ulp(1 / 3), 0.5, -1.0):
            with mp.workprec(64):
                direct = float(abs(mp.mpf(got) - true)) / math.ulp(float(true))
            assert run.Judge.ulp(got, true) == pytest.approx(direct, rel=1e-15, abs=1e-300)
        assert run.Judge.ulp(0.0, mp.mpf(0)) == 0.0 and run.Judge.ulp(1e-10, mp.mpf(0)) == math.inf
        assert run.Judge.ulp(1.0, mp.nan) == math.inf and run.Judge.ulp(math.nan, true) == math.inf
