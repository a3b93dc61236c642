"""The bench's judging of another package's answer: what cannot be evaluated is said, never guessed.
(asymptotics itself is not a dependency: these tests hand the judge SymPy expressions.)"""
import types

import pytest
import sympy as sp

from pendsym.solve import bench


def test_unsolved_function_and_unevaluated_integral_cannot_be_judged():
    pr = bench._problem("drag.toml")
    T0, T1, y, A = sp.symbols("T_0 T_1 _y A")
    with pytest.raises(bench.PeerError, match="unsolved function A"):
        bench._ours(pr, sp.Function("A")(T1) * sp.cos(2 * T0), {})
    peer = types.SimpleNamespace(amplitude_A=-T1 * sp.Abs(sp.sin(2 * T0)) + sp.Integral(1 / (y * sp.Abs(y)), (y, A)),
                                 amplitude_B=sp.S.Zero)
    with pytest.raises(bench.PeerError, match="fast time T_0.*unevaluated Integral"):
        bench._judge_slow(pr, peer)
    with pytest.raises(bench.PeerError, match="not a SymPy expression"):
        bench._ours(pr, "A*exp(-T_1)", {})


def test_every_case_names_a_problem_file_or_a_problem():
    for label, data, method, (eq, conds), order, square in bench.CASES:
        pr = bench._problem(data)
        assert method in ("lindstedt", "multiple_scales", "regular") and order >= 1, label
        assert len(conds) == 2 and "''" in eq, label
        assert square in (None, "square")
