"""pendsym.audit: `make audit` fails loudly (exit 1, a one-line verdict naming the kernel) when a
kernel is over the bound, and passes otherwise; its cheaper parts (the Arb reference of the Bessel
forms, the real roots of the polynomial hard points) give what the slower ones gave."""
import json
import math

import mpmath as mp
import pytest
import sympy as sp

from pendsym.audit import points as pt
from pendsym.audit import run
from pendsym.emit.kernels.measure import reference
from pendsym.result import KernelArg

u, q = sp.symbols("u q", positive=True)
ARGS = (KernelArg("u", 1e-6, 700.0, log=True),)


def _job(name, expr, fn):
    return run.Job(name, "test", "test." + name, ARGS, expr, (u,), fn, fn, "")


@pytest.fixture
def two_kernels(monkeypatch):
    """make audit's main on two plain kernels instead of generated/: e^-u evaluated as such (within the
    bound) and 1 − cos u evaluated plainly (true value u²/2: it loses every digit as u → 0)."""
    todo = {"good_exp": _job("good_exp", sp.exp(-u), lambda x: math.exp(-x)),
            "bad_cos": _job("bad_cos", 1 - sp.cos(u), lambda x: 1 - math.cos(x))}
    monkeypatch.setattr(run, "jobs", lambda generated, work, only=(): (
        {k: v for k, v in todo.items() if not only or k in only}, {}))
    monkeypatch.setattr(run, "outside", lambda job, errno_of: [])     # (plain functions have no guard)
    monkeypatch.setattr(run, "POINTS", 600)
    monkeypatch.setattr(run, "CLIMB_BUDGET", 80)
    monkeypatch.setenv("PENDSYM_WORKERS", "1")


def test_the_audit_exits_1_with_a_one_line_verdict_when_a_kernel_is_over_the_bound(two_kernels, tmp_path, capsys):
    code = run.main(["--out", str(tmp_path), "--no-timing"])
    lines = capsys.readouterr().out.strip().splitlines()
    assert code == 1
    assert lines[-1].startswith("audit: FAILED: 1 of 2 kernels") and lines[-1].endswith(": bad_cos"), lines
    assert any(line.startswith("OVER THE BOUND bad_cos") for line in lines)
    rows = {r["kernel"]: r for r in json.loads((tmp_path / "audit.json").read_text())["kernels"]}
    assert rows["bad_cos"]["c"]["over_bound"] > 0 and rows["bad_cos"]["worst_at"][0] < 1e-3
    assert rows["good_exp"]["worst_scaled"] <= 1.0
    table = (tmp_path / "audit.md").read_text()
    assert "| `bad_cos` |" in table and "| `good_exp` |" in table


def test_the_audit_exits_0_when_every_kernel_is_within_the_bound(two_kernels, tmp_path, capsys):
    code = run.main(["--out", str(tmp_path), "--no-timing", "--only", "good_exp"])
    last = capsys.readouterr().out.strip().splitlines()[-1]
    assert code == 0 and last.startswith("audit: passed: 1 kernels within 4 ulp"), last


def test_a_kernel_off_by_3e_15_relative_fails():
    """Scaled by 1 + 3e-15 (13.5 ulp at most), a correct kernel is over the bound: the verdict sees it."""
    rep = run.audit_one(_job("x", sp.exp(-u), lambda x: math.exp(-x) * (1 + 3e-15)), points=600)
    assert run.over([rep]) and rep["python"]["worst_scaled"] > 4


def test_the_arb_reference_is_mpmaths_at_every_digit_and_is_used_for_bessel_forms():
    """A cross product of Bessel functions as in the rhombus blade (x0 = 2u/q up to 6e8): the Arb form at
    60 digits equals mpmath's at 120 to its last digit (mpmath's own at 60 digits is off by 1.3e-56 at
    x0 = 1.8e5), and the audit's reference value to its 45 proven digits; κ from the Arb form too; a
    form with a Piecewise is left to MPFR or mpmath."""
    from pendsym.audit.reference import ARB_TRUTH_DIGITS, arb_form
    expr = (sp.besselj(1, 2 * u / q) * sp.bessely(0, u * sp.sqrt(2 * q + 4) / q)
            - sp.EulerGamma * sp.bessely(1, 2 * u / q) * sp.besselj(0, u * sp.sqrt(2 * q + 4) / q)) / u
    f, cond, engine = run.fast_reference(expr, (u, q), (1.0, 1e-3))
    assert engine == "arb" and ARB_TRUTH_DIGITS >= 30
    f_mp, cond_mp = reference(expr, [u, q])
    every = arb_form(expr, (u, q), f_mp)
    for p in ((1.9, 2.1e-5), (3.14, 1e-8), (0.05, 2.5)):
        with mp.workdps(120):
            b = f_mp(*map(mp.mpf, p))
        with mp.workdps(60):
            a, c = every(*map(mp.mpf, p)), f(*map(mp.mpf, p))
            assert abs(a - b) <= mp.mpf(10) ** -59 * abs(b), (p, a, b)
            assert abs(c - b) <= mp.mpf(10) ** -ARB_TRUTH_DIGITS * abs(b), (p, c, b)
    with mp.workdps(60):
        assert abs(cond(mp.mpf(1.9), mp.mpf(2.1e-5)) / cond_mp(mp.mpf(1.9), mp.mpf(2.1e-5)) - 1) < 1e-20
    assert run.fast_reference(sp.Piecewise((sp.besselj(0, u), u < 1), (u, True)), (u,), (0.5,))[2] == "mpmath"


def test_the_real_roots_are_polyroots_real_roots():
    """(X − 1)(X + 2)(X − 1e-3)(X² + 1)(X² − 2X + 1 + 1e-20): the three real roots, to 40 digits; the
    complex pairs (one 1e-10 from the line) are not roots."""
    X = sp.Symbol("X")
    poly = sp.Poly(sp.expand((X - 1) * (X + 2) * (X - sp.Rational(1, 1000)) * (X**2 + 1)
                             * (X**2 - 2 * X + 1 + sp.Rational(1, 10**20))), X)
    with mp.workdps(60):
        got = sorted(pt.real_roots([mp.mpf(sp.Float(c, 70)) for c in poly.all_coeffs()]))
        assert len(got) == 3
        for r, want in zip(got, (-2, mp.mpf(1) / 1000, 1)):
            assert abs(r - want) < mp.mpf(10) ** -40


def test_a_double_root_is_found_by_newton_for_a_double_root():
    """(X − 3)²(X + 1): −1 and the double root 3 (once per estimate numpy gives), to 30 digits (a double
    root at 60 digits is known to about 30, by polyroots too), so the hard point is the double 3.0."""
    with mp.workdps(60):
        got = sorted(pt.real_roots([mp.mpf(c) for c in (1, -5, 3, 9)]))
        assert len(got) == 3 and all(abs(r - w) < mp.mpf(10) ** -30 and float(r) == w
                                     for r, w in zip(got, (-1, 3, 3))), got
