"""Haag 1935, chapter III: the rational forms in th(u/2) (ch3_uniform.rational)."""
import mpmath as mp
import pytest
import sympy as sp

from derivations.haag1935.ch3_uniform import rational
from derivations.haag1935.symbols import K, lam, s, u


def close(expr, value, at: dict, digits=25):
    with mp.workdps(digits + 5):
        return abs(sp.N(expr.subs(at), digits + 5) - value) < mp.mpf(10) ** -digits * max(1, abs(value))


def test_integrate_exp_poly_against_quad():
    t = rational.reduced_abscissa
    f = (3 * t**2 - 1) * sp.exp(2 * t) + sp.exp(-t) * (t + sp.exp(u)) + 5
    exact = rational.integrate_exp_poly(f, u)
    g = sp.lambdify((t, u), f, "mpmath")
    with mp.workdps(40):
        for u_value in (mp.mpf("0.3"), mp.mpf("2.7")):
            assert close(exact, mp.quad(lambda x: g(x, u_value), [0, u_value]), {u: u_value}, digits=35)


def test_integrate_exp_poly_rejects_non_exponential():
    with pytest.raises(ValueError):
        rational.integrate_exp_poly(1 / (1 + sp.exp(rational.reduced_abscissa)), u)


def test_integrate_along_blade_against_quad():
    expr = s * sp.cosh(u * s / lam) + sp.exp(-2 * u * s / lam)
    exact = rational.integrate_along_blade(expr)
    with mp.workdps(35):
        lam_value, u_value = mp.mpf("1.3"), mp.mpf("0.9")
        numeric = mp.quad(lambda x: x * mp.cosh(u_value * x / lam_value) + mp.exp(-2 * u_value * x / lam_value),
                          [0, lam_value])
        assert close(exact, numeric, {lam: lam_value, u: u_value}, digits=30)


def test_in_tanh_half_is_rational_in_tanh_half():
    expr = 1 / sp.sinh(u) + sp.cosh(u) / sp.tanh(u) - sp.exp(-u)
    r = rational.in_tanh_half(expr)
    assert r.free_symbols <= {rational.tanh_half}
    with mp.workdps(30):
        u_value = mp.mpf("1.37")
        assert close(r, sp.N(expr.subs(u, u_value), 30), {rational.tanh_half: mp.tanh(u_value / 2)})


def test_in_tanh_half_rejects_exponentials_not_in_u():
    with pytest.raises(ValueError):
        rational.in_tanh_half(sp.exp(u**2))


def test_tanh_half_form_reduces_an_identity_to_zero():
    assert rational.tanh_half_form(1 / sp.tanh(u) - sp.tanh(u / 2) - 1 / sp.sinh(u)) == 0


def test_in_hyperbolic_basis_keeps_the_function():
    expr = sp.exp(2 * u * s / lam) * (1 + s) - sp.exp(-u * s / lam) / sp.cosh(u)
    basis = rational.in_hyperbolic_basis(expr)
    assert not any(isinstance(x, sp.exp) for x in sp.preorder_traversal(basis) if x.has(s))
    at = {u: sp.Rational(7, 10), lam: sp.Rational(13, 10), s: sp.Rational(1, 3)}
    assert abs(sp.N((basis - expr).subs(at), 40)) < 1e-35


def test_polynomial_in_K():
    poly = rational.polynomial_in_K(sp.expand((K * sp.sinh(u) + 1 / sp.cosh(u)) ** 2))
    assert sp.Poly(poly, K).degree() == 2
    at = {K: sp.Rational(3, 10), u: sp.Rational(11, 10)}
    assert abs(sp.N((poly - (K * sp.sinh(u) + 1 / sp.cosh(u)) ** 2).subs(at), 30)) < 1e-25


def test_with_tanh_half_symbol_is_the_same_rational_function_as_in_tanh_half():
    n = sp.Symbol("n")
    only_tanh_half = ((K * sp.tanh(u / 2) ** 2 + 1) / (2 * sp.tanh(u / 2))) ** (n - 1) * K / u + lam * sp.tanh(u / 2)
    symbolic = rational.with_tanh_half_symbol(only_tanh_half)
    assert not symbolic.has(sp.tanh) and symbolic.has(rational.tanh_half)
    at_3 = sp.cancel(symbolic.subs(n, 3))
    assert sp.srepr(at_3) == sp.srepr(rational.in_tanh_half(only_tanh_half.subs(n, 3)))
    other = sp.tanh(u) + sp.exp(u) * K          # other functions of u: the full rewrite
    assert sp.srepr(rational.with_tanh_half_symbol(other)) == sp.srepr(rational.in_tanh_half(other))
