"""Haag 1935, chapter III: the derivation (ch3_uniform.derivation_functions, derivation_pendulum)."""
import pytest
import sympy as sp

from derivations.haag1935.ch3_uniform import derivation_functions as functions
from derivations.haag1935.ch3_uniform import derivation_pendulum as pendulum
from derivations.haag1935.ch3_uniform import launch_symbols, printed
from derivations.haag1935.common import rid
from derivations.haag1935.symbols import K, U, U1, U2, a, b, k, lam, s, u, vl, wl, z, zp
from pendsym import stages

P = "haag1935"


# ---------------------------------------------------------------- n°47
def test_closed_forms_solve_the_two_point_problem():
    """v, w of (157) satisfy (9)–(10) with M = λ²/u²: M y'' = y, v'(0) = v'(λ) = −1, w'(0) = 0, w'(λ) = 1."""
    forms = functions.uniform_closed_forms()
    for name, ends in (("v", (-1, -1)), ("w", (0, 1))):
        y = forms[name]
        assert sp.simplify((lam**2 / u**2 * sp.diff(y, s, 2) - y).rewrite(sp.exp)) == 0
        for at, slope in zip((0, lam), ends):
            assert sp.simplify(sp.diff(y, s).subs(s, at) - slope) == 0


def test_identity_difference_vanishes_only_for_identities():
    assert functions.identity_difference(U2 - U - U1)(None) == 0
    assert functions.identity_difference(U2 - U)(None) != 0


# ---------------------------------------------------------------- n°48
def test_S_p_recurrence_is_zero_for_symbolic_p():
    assert functions.S_p_recurrence(None) == 0


def test_S_p_leading_coefficients():
    assert functions.S_p_leading(None) == printed.S_p_leading()


def test_G_recurrence_matches_the_memoir_text():
    difference = functions.G_recurrence(None) - printed.G_recurrence()
    assert sp.simplify(sp.powsimp(sp.expand(difference), force=True)) == 0


@pytest.mark.slow
def test_Gamma_n_are_polynomials_in_k():
    ids = [rid(166, f"Gamma{m}") for m in (2, 3, 4, 5)]
    built = stages.results(ids)
    for m, i in zip((2, 3, 4, 5), ids):
        Gamma = built[i].derived
        assert K not in Gamma.free_symbols
        assert sp.Poly(sp.expand(Gamma), k).degree() == m // 2


# ---------------------------------------------------------------- n°50
def test_k_of_foci_is_K_one_minus_K():
    K_36 = (a + wl) / (a + z - vl)
    assert sp.simplify(pendulum.k_of_foci(None) - K_36 * (1 - K_36)) == 0


def test_end_brackets_are_those_of_179():
    zero_end, lambda_end = pendulum.end_brackets(K)
    assert (zero_end, lambda_end) == (printed.C0(), printed.C_lambda())


# ---------------------------------------------------------------- n°54: (180)–(181)
def test_static_launch_reduces_K_A_to_the_focus_distance():
    """K·A = (Q/mg)(b − a − z') follows from (67), (27), (36) and (33) (n°18, (68)); the second term has K'."""
    T0 = pendulum.static_launch(0)(None)
    assert not T0.has(vl) and not T0.has(wl)
    L = launch_symbols
    principal = sp.expand(T0).coeff(sp.cos(L.n_principal * L.t))
    expected = L.stress_scale * L.Q / L.weight * (U + U1 / K) * (b - a - zp) / (z - zp)
    assert sp.simplify(principal - expected) == 0
    parasitic = sp.expand(T0).coeff(sp.cos(L.n_parasitic * L.t))
    assert parasitic.has(L.K_prime) and not parasitic.has(K)


def test_shock_launch_matches_181():
    for at, transcription in ((0, printed.shock_launch_T0), (1, printed.shock_launch_T_lambda)):
        assert sp.simplify(pendulum.shock_launch(at)(None) - transcription()) == 0
