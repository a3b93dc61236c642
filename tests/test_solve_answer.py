"""LaTeX and kernels of a solve answer: the emitted kernels measured under the accuracy contract
(4 ulp × max(1, κ), docs/kernel-accuracy.md) by the deep audit, from the files as written."""
import importlib.util
import math
import shutil
import subprocess
import sys
from fractions import Fraction

import pytest

from pendsym.solve import answer, from_dict, kernels, solve
from pendsym.solve import ProblemError

needs_cc = pytest.mark.skipif(shutil.which("cc") is None, reason="no C compiler")
DUFFING = {"variable": "u", "small": "eps", "phi": "eps*u**3", "order": 3,
           "initial": {"value": "A"}, "parameters": {"A": 0.5}}
DRAG = {"small": "eps", "k": "2", "phi": "eps*dtheta*abs(dtheta)", "initial": {"value": "A"},
        "parameters": {"A": 0.5}, "verify": {"slow": [0.02, 0.08]}}


def _load(path):
    spec = importlib.util.spec_from_file_location(f"t_{path.parent.name}", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def _omega_exact(A, eps):
    """The issue's ω = 1 + 3εA²/8 − 21ε²A⁴/256 + 81ε³A⁶/2048, in exact rationals (not the form under test)."""
    a, e = Fraction(A), Fraction(eps)
    return 1 + Fraction(3, 8) * e * a**2 - Fraction(21, 256) * e**2 * a**4 + Fraction(81, 2048) * e**3 * a**6


def test_domain_defaults_and_declared():
    pr = from_dict({**DUFFING, "domain": {"eps": [0, 0.2], "tau": [0, 3.5]}})
    assert kernels.domain_of(pr, "eps").hi == 0.2 and kernels.domain_of(pr, "tau").hi == 3.5
    a = kernels.domain_of(pr, "A")
    assert (a.lo, a.hi, a.log) == (0.125, 2.0, True)                # v/4 … 4v by default
    bare = from_dict(DUFFING)
    assert kernels.domain_of(bare, "eps").lo == 0 and kernels.domain_of(bare, "tau").hi == 2 * math.pi
    for bad in ({"B": [0, 1]}, {"eps": [1, 0]}, {"eps": [0, float("inf")]}, {"eps": "0..1"}, {"eps": [0, True]}):
        with pytest.raises(ProblemError):
            from_dict({**DUFFING, "domain": bad})


@needs_cc
def test_perturbed_kernel_fails_the_bound(tmp_path):
    """k_omega (first order: ω = 1 + 3εA²/8) measured from its files holds the bound; scaled by
    1 + 3e-15 in both languages it is said to be over it (a quick measure: 600 points)."""
    sol = solve({**DUFFING, "order": 1}, verify=False)
    ks = kernels.build(sol, [k for k in answer.kernels_of(sol) if k[0] == "k_omega"])
    py, c = kernels.write(ks, sol.problem, tmp_path)
    good = kernels.measure(ks, py, c, points=600)
    assert not good[0].over and good[0].figures["python"]["worst_scaled"] <= 4, good[0].figures
    for path, ret in ((py, "\n    return "), (c, "\n    return ")):
        text = path.read_text()
        assert text.count(ret) == 1
        end = ";" if path.suffix == ".c" else ""
        body = text.split(ret, 1)[1].split("\n", 1)
        text = text.split(ret, 1)[0] + ret + "(1 + 3e-15)*(" + body[0].rstrip(";") + ")" + end + "\n" + body[1]
        path.write_text(text)
    bad = kernels.measure(ks, py, c, points=600)
    f = bad[0].figures
    assert bad[0].over and f["python"]["worst_scaled"] > 4 and f["c"]["worst_scaled"] > 4, f
    assert "OVER THE BOUND" in kernels.summary(bad)[0]
    kernels.write(bad, sol.problem, tmp_path)
    assert '"""OVER THE BOUND' in py.read_text() and "/* OVER THE BOUND" in c.read_text()


@needs_cc
@pytest.mark.slow
def test_duffing_kernels_measured(tmp_path):
    """Every Duffing kernel within 4 ulp × max(1, κ) on 20,000 points (hard points and the
    adversarial search), its figure in its docstring and comment; ω also against the issue's
    coefficients in exact arithmetic, and outside its domain a ValueError."""
    sol = solve(DUFFING, verify=False)
    ks = answer.emit(sol, tmp_path)
    assert {k.name for k in ks} == {"k_omega", "k_period", "k_u_tau"}
    for k in ks:
        assert not k.over and k.figures["points"] >= 20_000, k.figures
    mod = _load(tmp_path / "answer.py")
    for A, eps in ((0.5, 0.01), (1.9, 0.39), (0.125, 0.4), (2.0, 0.0)):
        exact = _omega_exact(A, eps)
        assert abs(Fraction(mod.k_omega(A, eps)) - exact) <= 4 * math.ulp(float(exact))
    with pytest.raises(ValueError, match="outside its domain"):
        mod.k_omega(0.5, 0.5)
    py, c = (tmp_path / "answer.py").read_text(), (tmp_path / "answer.c").read_text()
    assert py.count("Within the bound.") == 3 and c.count("Within the bound.") == 3
    assert "Measured on 2" in py and "Domain: A in [0.125, 2]; eps in [0, 0.4]; tau in [0, 6.28319]" in c
    assert r"\frac{81 A^{6}" in (tmp_path / "answer.tex").read_text()


@needs_cc
@pytest.mark.slow
def test_drag_kernels_measured_through_the_command(tmp_path):
    """`pendsym solve --emit` on the drag problem: the amplitude law r(t) (|A| written A on the
    declared A > 0) and the one-swing answers within the bound, each figure reported."""
    done = subprocess.run([sys.executable, "-m", "pendsym.cli", "solve", "problems/drag.toml", "--no-verify",
                           "--emit", str(tmp_path)], capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    lines = [ln for ln in done.stdout.splitlines() if ln.strip().startswith("kernel k_")]
    assert {ln.split()[1].split("(")[0] for ln in lines} >= {"k_r_t", "k_dalpha_one_swing"}
    for ln in lines:
        assert "worst ulp/max(1, κ)" in ln and "on 20" in ln
    mod = _load(tmp_path / "answer.py")
    A, eps, t = 0.5, 0.05, 40.0          # r(t) = 3π|A|/(3π + 4εk|A|t), k = 2, from the drag's averaged flow
    want = 3 * math.pi * A / (3 * math.pi + 8 * eps * A * t)
    assert abs(mod.k_r_t(A, eps, t) - want) <= 4 * math.ulp(want)
    assert "OVER THE BOUND" not in (tmp_path / "answer.c").read_text()


def test_answer_without_a_math_function_is_said_not_emitted():
    """θ'' + θ + ε sin θ: ω = 1 + εJ₁(A)/A has no kernel (neither math nor C99 libm has J₁): said, not a crash."""
    sol = solve({"small": "eps", "phi": "eps*sin(theta)", "initial": {"value": "A"}, "parameters": {"A": 1}},
                verify=False)
    names = [k[1] for k in answer.kernels_of(sol)]
    lines = answer.not_kernels(sol)
    assert any(line.startswith("no kernel for omega (first order, averaging): ") and "besselj" in line
               for line in lines), lines
    assert not any(n.startswith("omega") for n in names)
