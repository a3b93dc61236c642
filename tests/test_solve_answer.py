"""LaTeX and kernels of a solve answer: the kernels agree with their formula in double precision."""
import shutil

import pytest

from pendsym.solve import solve
from pendsym.solve import answer


@pytest.mark.skipif(shutil.which("cc") is None and shutil.which("gcc") is None, reason="no C compiler")
def test_duffing_kernels_are_accurate(tmp_path):
    sol = solve({"variable": "u", "small": "eps", "phi": "eps*u**3", "order": 3,
                 "initial": {"value": "A"}, "parameters": {"A": 0.5}}, verify=False)
    rows = answer.emit(sol, tmp_path)
    assert {r["kernel"] for r in rows} == {"k_omega", "k_period", "k_u_tau"}
    assert all(r["python"] < 1e-14 and r["c"] < 1e-14 for r in rows), rows
    tex = (tmp_path / "answer.tex").read_text()
    assert r"\frac{81 A^{6}" in tex
    assert "double k_omega(double A, double eps)" in (tmp_path / "answer.c").read_text()


@pytest.mark.skipif(shutil.which("cc") is None and shutil.which("gcc") is None, reason="no C compiler")
def test_drag_amplitude_law_kernel_compiles_and_is_accurate(tmp_path):
    """The drag's answers print M_PI_2 (π/2) and the amplitude law r(t): the C file defines the constants
    strict C leaves out, and the law's kernel agrees with its formula in double precision."""
    sol = solve({"small": "eps", "k": "2", "phi": "eps*dtheta*abs(dtheta)", "initial": {"value": "A"},
                 "parameters": {"A": 0.5}}, verify=False)
    rows = {r["kernel"]: r for r in answer.emit(sol, tmp_path)}
    assert "#define M_PI_2" in (tmp_path / "answer.c").read_text()
    assert rows["k_r_t"]["args"] == ["A", "eps", "t"]
    assert rows["k_r_t"]["python"] < 1e-14 and rows["k_r_t"]["c"] < 1e-14, rows
