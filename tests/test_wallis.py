"""pendsym.wallis: J_m(y) = ∫_0^y cos^{m+1}, its recurrence and J_m(π)."""
import mpmath as mp
import sympy as sp

from pendsym import wallis

y = sp.Symbol("y", real=True)
m = sp.Symbol("m", integer=True, positive=True)
n = sp.Symbol("n", integer=True, nonnegative=True)


def test_recurrence_defect_vanishes_for_symbolic_m():
    assert wallis.recurrence_defect(m, y) == 0


def test_J_by_recurrence_matches_quadrature():
    with mp.workdps(30):
        for j in range(-1, 8):
            f = sp.lambdify(y, wallis.J(j, y), modules="mpmath")
            for yv in (mp.mpf("0.3"), mp.mpf("2.9"), mp.mpf("7.1")):
                ref = mp.quad(lambda s: mp.cos(s) ** (j + 1), [0, yv])
                assert abs(f(yv) - ref) < mp.mpf("1e-25")


def test_J_pi_closed_form_for_odd_m():
    with mp.workdps(30):
        for j in (1, 3, 5, 7, 9, 11):
            ref = mp.quad(lambda s: mp.cos(s) ** (j + 1), [0, mp.pi])
            assert abs(sp.N(wallis.J_pi_odd(j), 30) - ref) < mp.mpf("1e-25")
    # the Gamma form agrees symbolically
    assert sp.simplify(sp.gammasimp(wallis.J_pi_odd(2 * n + 1).rewrite(sp.gamma) - wallis.J_pi_odd_gamma(n))) == 0


def test_reflection_kills_even_m():
    assert sp.simplify(wallis.parity_reflection(2 * n, y)) == -1
    assert sp.simplify(wallis.parity_reflection(2 * n + 1, y)) == 1


def test_J_rejects_m_below_minus_one():
    import pytest
    with pytest.raises(ValueError):
        wallis.J(-2, y)
