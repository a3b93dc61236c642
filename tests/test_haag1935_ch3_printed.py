"""Haag 1935, chapter III: the transcriptions as printed and their readings (ch3_uniform.printed)."""
import sympy as sp

from derivations.haag1935.ch3_uniform import printed
from derivations.haag1935.symbols import DEFS, K, U, U1, U2, a1, c, u, x0

TANH_FORMS = dict(DEFS)


def in_u(expr):
    return expr.subs(TANH_FORMS, simultaneous=True)


def test_both_printed_forms_of_C_lambda_agree_by_161():
    """(179) prints C_λ = U2 − KU = U1 + U(1 − K)."""
    assert sp.simplify((in_u(printed.C_lambda()) - in_u(U1 + U * (1 - K))).rewrite(sp.exp)) == 0


def test_definitions_follow_the_printed_ends():
    assert printed.A1_DEFINITION[0] == a1
    assert sp.simplify(printed.A1_DEFINITION[1] + in_u(printed.w_lambda())) == 0           # a1 = −w_λ (41)
    assert printed.X0_DEFINITION[0] == x0
    assert sp.simplify(printed.X0_DEFINITION[1] - in_u(K * printed.v0() + printed.w0())) == 0
    assert printed.C_DEFINITION[0] == c


def test_discrepancies_carry_uncertain_readings():
    for reading in (printed.READ_GAMMA5, printed.READ_F, printed.READ_K_PRIME_T0, printed.READ_K_PRIME_T_LAMBDA,
                    printed.READ_FOCI_COMBINATION):
        assert reading.certain is False and reading.shows and reading.read_as


def test_the_slips_are_in_the_constant_terms():
    """Γ_5 and F show U_1^3 in their k⁰, K⁰ terms; reading U_1^4 changes Γ_5 by (4/(5u))(U_1^4 − U_1^3)."""
    Gamma5_fixed = printed.Gamma5().subs(4 * U1**3, 4 * U1**4)
    assert sp.simplify(Gamma5_fixed - printed.Gamma5() - 4 * (U1**4 - U1**3) / (5 * u)) == 0
    assert sp.expand(printed.F().subs(K, 0)) == sp.expand((U2 / u * (3 * U1**2 - 2) - 3 * U1**3) / 8)


def test_transcriptions_are_sympy_expressions():
    names = [name for name in dir(printed) if callable(getattr(printed, name)) and getattr(printed, name).__module__
             == printed.__name__ and not name.startswith("_")]
    assert len(names) > 50
    for name in names:
        assert isinstance(getattr(printed, name)(), sp.Basic), name
