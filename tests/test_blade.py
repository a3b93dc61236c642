"""The blade engine (pendsym.blade) against truths it does not compute itself.

* constant M: closed forms by SymPy dsolve, integrals by mpmath quad of them;
* piecewise-constant M (a hole): transfer matrices of ch/sh on each piece;
* M = c(1+s)²: the Euler equation, solved by the powers (1+s)^r;
* identities of the theory that hold for every M (Haag 1935, (15), (16), (81), n°3);
* the inverted blade: trigonometric closed forms and the singular buckling values.
"""
import mpmath as mp
import pytest
import sympy as sp

from pendsym import blade as B

s = B.S


def close(a, b, digits=30):
    a, b = mp.mpf(a), mp.mpf(b)
    return abs(a - b) <= mp.mpf(10) ** (-digits) * max(abs(a), abs(b), 1)


@pytest.mark.parametrize("M, lam", [("1/4", "2"), ("1/3", "7"), ("1/100", "1")])
def test_constant_blade_matches_dsolve(M, lam):
    M, lam = sp.Rational(M), sp.Rational(lam)
    cf = B.closed_forms(M, lam)
    sol = B.solve(B.Blade(lam, M), 30)
    with mp.workdps(40):
        for key in ("v0", "vl", "w0", "wl", "beta1", "beta2"):
            assert close(getattr(sol, key), sp.N(cf[key], 45)), key
        for x in ("0.3", "0.77"):
            xs = sp.Rational(x) * lam
            assert close(sol.v(xs), sp.N(cf["v"].subs(s, xs), 45))
            assert close(sol.phi1(xs), sp.N(cf["phi1"].subs(s, xs), 45))
            assert close(sol.phi2(xs), sp.N(cf["phi2"].subs(s, xs), 45))


@pytest.mark.slow
def test_constant_blade_integrals_by_quad_of_closed_forms():
    M, lam = sp.Rational(1, 5), sp.Integer(3)
    cf = B.closed_forms(M, lam)
    sol = B.solve(B.Blade(lam, M), 30)
    f1, f2, v, w = (sp.lambdify(s, cf[k], "mpmath") for k in ("phi1", "phi2", "v", "w"))
    with mp.workdps(40):
        K = mp.mpf("0.63")
        Mv = mp.mpf(1) / 5
        for n in (1, 2, 3, 4):
            F = mp.quad(lambda x: (K * f1(x) + f2(x)) ** n, mp.linspace(0, 3, 5))
            G = mp.quad(lambda x: (K * v(x) + w(x)) ** n / Mv ** (n - 1), mp.linspace(0, 3, 5))
            assert close(sol.F(n, K), F), n
            assert close(sol.G(n, K), G), n
        H = mp.quad(lambda x: (mp.mpf("0.4") * f1(x) - mp.mpf("1.3") * f2(x)) ** 3, mp.linspace(0, 3, 5))
        assert close(sol.H(3, "0.4", "-1.3"), H)


def _transfer(pieces, x):
    """[y1, y1', y2, y2'] at x for piecewise-constant M by products of ch/sh matrices."""
    Y = mp.matrix([[1, 0], [0, 1]])
    for a, b, Mv in pieces:
        if x <= a:
            break
        h = min(x, b) - a
        om = 1 / mp.sqrt(Mv)
        T = mp.matrix([[mp.cosh(om * h), mp.sinh(om * h) / om], [om * mp.sinh(om * h), mp.cosh(om * h)]])
        Y = T * Y
    return Y


def test_hole_blade_matches_transfer_matrices():
    M = sp.Piecewise((sp.Rational(1, 4), s < sp.Rational(3, 5)), (sp.Rational(1, 9), s < sp.Rational(6, 5)),
                     (sp.Rational(1, 4), True))
    bl = B.Blade(2, M)
    assert B.breakpoints(bl) == (0, sp.Rational(3, 5), sp.Rational(6, 5), 2)
    sol = B.solve(bl, 30)
    with mp.workdps(50):
        pieces = [(mp.mpf(0), mp.mpf("0.6"), mp.mpf(1) / 4), (mp.mpf("0.6"), mp.mpf("1.2"), mp.mpf(1) / 9),
                  (mp.mpf("1.2"), mp.mpf(2), mp.mpf(1) / 4)]
        Yl = _transfer(pieces, mp.mpf(2))
        Av = (Yl[1, 1] - 1) / Yl[1, 0]      # v = Av y1 − y2, v'(λ) = −1
        Aw = 1 / Yl[1, 0]
        for x in ("0", "0.45", "0.6", "0.9", "1.5", "2"):
            Yx = _transfer(pieces, mp.mpf(x))
            assert close(sol.v(x), Av * Yx[0, 0] - Yx[0, 1]), x
            assert close(sol.w(x), Aw * Yx[0, 0]), x
            assert close(sol.phi2(x), Aw * Yx[1, 0]), x


def _euler_blade(c, lam):
    """M = c(1+s)²: y = (1+s)^r with c r(r−1) = 1; v, w by solving (10) exactly."""
    r = sp.symbols("r")
    r1, r2 = sp.solve(c * r * (r - 1) - 1, r)
    A, Bc = sp.symbols("A B")
    y = A * (1 + s) ** r1 + Bc * (1 + s) ** r2
    dy = sp.diff(y, s)
    v = y.subs(sp.solve([dy.subs(s, 0) + 1, dy.subs(s, lam) + 1], [A, Bc]))
    w = y.subs(sp.solve([dy.subs(s, 0), dy.subs(s, lam) - 1], [A, Bc]))
    return v, w


def test_variable_blade_matches_euler_equation():
    c, lam = sp.Rational(1, 3), sp.Rational(3, 2)
    v, w = _euler_blade(c, lam)
    sol = B.solve(B.Blade(lam, c * (1 + s) ** 2), 30)
    with mp.workdps(40):
        for x in ("0", "0.4", "1.1", "1.5"):
            xs = sp.Rational(x)
            assert close(sol.v(x), sp.N(v.subs(s, xs), 45)), x
            assert close(sol.w(x), sp.N(w.subs(s, xs), 45)), x
            assert close(sol.phi1(x), sp.N(1 + sp.diff(v, s).subs(s, xs), 45)), x


@pytest.mark.parametrize("M", [sp.Rational(1, 3) * (1 + s) ** 2,
                               sp.Piecewise((sp.Rational(1, 5), s < 1), (sp.Rational(1, 20) + s / 7, True))])
def test_general_identities(M):
    """(15) vw' − wv' = w0, (16) vλ + wλ = w0, n°3 ∫ w/M = 1, (81) F2 + G2 = K²β1 + wλ."""
    sol = B.solve(B.Blade(2, M), 30)
    with mp.workdps(40):
        for x in ("0.2", "0.99", "1.01", "1.7"):
            v, dv, w, dw = sol.state(x)
            assert close(v * dw - w * dv, sol.w0), x
        assert close(sol.vl + sol.wl, sol.w0)
        assert close(sol.integrate(lambda x: sol.w(x) / sol.M_at(x)), 1)
        K = mp.mpf("0.81")
        assert close(sol.F(2, K) + sol.G(2, K), K**2 * sol.beta1 + sol.wl)
        assert close(sol.H(2, K, 1), sol.F(2, K))


@pytest.mark.slow
def test_precision_is_resolved():
    """The 30-digit solution agrees with a 45-digit one to 30 digits."""
    M = sp.Rational(1, 4) + s / 3
    a, b = B.solve(B.Blade(3, M), 30), B.solve(B.Blade(3, M), 45)
    with mp.workdps(50):
        assert close(a.v0, b.v0) and close(a.wl, b.wl) and close(a.F(3, "0.6"), b.F(3, "0.6"))
        assert not close(a.v0, b.v0, 60)   # the comparison can fail


@pytest.mark.slow
def test_large_u_keeps_digits():
    """u = λ/√M = 40: v decays like e^{−u} against growing fundamental solutions."""
    M, lam = sp.Rational(1, 400), sp.Integer(2)
    cf = B.closed_forms(M, lam)
    sol = B.solve(B.Blade(lam, M), 30)
    with mp.workdps(40):
        for key in ("v0", "w0", "wl", "beta1"):
            assert close(getattr(sol, key), sp.N(cf[key], 45)), key
        assert close(sol.v(1), sp.N(cf["v"].subs(s, 1), 60))


def test_inverted_blade_trigonometric():
    Mn = sp.Symbol("M", negative=True)
    lam = sp.Integer(1)
    cf = B.closed_forms(Mn, lam)
    assert cf["w"].has(sp.cos)
    Mv = -sp.Rational(1, 5)   # u = √5 < π: no buckling
    sol = B.solve(B.Blade(lam, Mv), 30)
    with mp.workdps(40):
        for key in ("v0", "vl", "w0", "wl"):
            assert close(getattr(sol, key), sp.N(cf[key].subs(Mn, Mv), 45)), key


@pytest.mark.parametrize("j", [1, 2])
def test_inverted_blade_singular_at_buckling(j):
    with pytest.raises(B.SingularBlade):
        B.solve(B.Blade(1, -1 / (j * sp.pi) ** 2), 30)
    # just off the buckling value the problem is regular (and large)
    sol = B.solve(B.Blade(1, -1 / (j * sp.pi * (1 + sp.Rational(1, 1000))) ** 2), 30)
    with mp.workdps(30):
        assert abs(sol.w0) > 10


def test_piecewise_with_branch_on_boundary_rejects_zero_M():
    with pytest.raises(ValueError):
        B.solve(B.Blade(1, sp.Piecewise((0, s < sp.Rational(1, 2)), (1, True))), 30)


def test_blade_closed_forms_only_for_constant_M():
    assert B.blade_closed_forms(B.Blade(1, s + 1)) is None
    cf = B.blade_closed_forms(B.Blade(2, sp.Rational(1, 4)))
    sol = B.solve(B.Blade(2, sp.Rational(1, 4)), 30)
    with mp.workdps(40):
        assert close(sol.wl, sp.N(cf["wl"], 45))
