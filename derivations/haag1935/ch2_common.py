"""What the sections of Haag 1935, chapter II share: its symbols and the algebra of the blade's integrals.

Chapter II (n°26–46, eqs. (88)–(155)) keeps chapter I's equations to the next order.  The integrals over
the blade that it writes (∫εφ1 ds, H_n (103), F_n (79) …) all have integrands that are polynomials in
φ1(s), φ2(s) (11) once φ = Yφ1 + θφ2 (13); :func:`blade_integral` maps such a polynomial to the linear
combination of the moments J(i, j) = ∫_0^λ φ1^i φ2^j ds, so that identities between those integrals are
decided exactly.  F_n and H_n are then sums of moments; :func:`in_F` rewrites a combination of moments
in the F_n(K) when it is one (at Y = Kθ, the principal oscillation).
"""
from __future__ import annotations

import sympy as sp

from .symbols import K, Y, theta, varphi1_s, varphi2_s

eps1, eps2, eps3 = sp.symbols("epsilon_1 epsilon_2 epsilon_3", real=True)   # mgε1, mgε2, mgε3 (n°26)
eps_blade = sp.Symbol("epsilon'", real=True)      # increment of d(Mφ')/ds (ε' = dε/ds, (94), (106))
eps_bar = sp.Symbol("bar_epsilon", real=True)     # ε_bar = φε1 + ε' (94) (printed ε)
eps_lambda = sp.Symbol("epsilon_lambda", real=True)   # ε at s = λ: increment of the couple (102)
dX, dY, dN = sp.symbols("Delta_X Delta_Y Delta_N", real=True)                # corrections of X, Y, N (n°26)
f_acc = sp.Symbol("f", real=True)                 # perturbing acceleration of the canonical variable (91)
theta0 = sp.Symbol("theta_0", positive=True)      # amplitude (n°29)
Y_dot, Y_ddot = sp.symbols("Y' Y''", real=True)   # time derivatives of Y (107)
alpha_ddot = sp.Symbol("alpha''", real=True)      # α'' (106)
Qp = sp.Symbol("Q'", real=True)                   # (112)
Q = sp.Symbol("Q", real=True)                     # (45)
F_110 = sp.Symbol("F", real=True)                 # F = H(K, 1) = 4KF3 − F4 (110)
A_coef, B_coef = sp.symbols("A B", real=True)     # f = An²θ³ + Bθθ'² (n°29)
Hn = sp.Function("H")                             # H_n(Y, θ) (103): H(n, Y, θ)
J = sp.Function("J")                              # J(i, j) = ∫ φ1^i φ2^j ds (a moment of the blade)
phi_s = Y * varphi1_s + theta * varphi2_s         # φ = Yφ1 + θφ2 at a point (13)
psi_s = sp.Symbol("psi", real=True)               # Kφ1 + φ2 at a point


def blade_integral(poly: sp.Expr) -> sp.Expr:
    """∫_0^λ poly ds for a polynomial in φ1, φ2 (coefficients free of s): Σ c_ij J(i, j)."""
    p = sp.Poly(sp.expand(poly), varphi1_s, varphi2_s)
    return sp.expand(sum(coeff * J(i, j) for (i, j), coeff in p.terms()))


def H_moments(n: int, Yv=Y, thetav=theta) -> sp.Expr:
    """H_n(Y, θ) = ∫(Yφ1 + θφ2)^n ds (103) in moments."""
    return blade_integral((Yv * varphi1_s + thetav * varphi2_s) ** n)


def F_moments(n: int) -> sp.Expr:
    """F_n = ∫(Kφ1 + φ2)^n ds (79) in moments."""
    return blade_integral((K * varphi1_s + varphi2_s) ** n)


def in_F(expr: sp.Expr, max_n: int = 6) -> sp.Expr:
    """A combination of moments rewritten in F_2 … F_max_n (the F_n of (79), as F(n)): the moments are
    changed to the basis ∫ φ1^i (Kφ1 + φ2)^j ds; raises if a moment with i > 0 remains (then the
    combination is not a function of the F_n)."""
    from .symbols import Fn
    expr = sp.expand(expr)
    moments = sorted(expr.atoms(J), key=sp.srepr)
    if not moments:
        return expr
    # J(i, j) = ∫ φ1^i (ψ − Kφ1)^j: expand in the basis L(i, j) = ∫ φ1^i ψ^j
    L = sp.Function("L")
    in_L = {}
    for mom in moments:
        i, j = (int(x) for x in mom.args)
        poly = sp.Poly(sp.expand(varphi1_s**i * (psi_s - K * varphi1_s) ** j), varphi1_s, psi_s)
        in_L[mom] = sum(c * L(p, q) for (p, q), c in poly.terms())
    out = sp.expand(expr.xreplace(in_L))
    rest = [x for x in out.atoms(L) if int(x.args[0]) != 0]
    if rest:
        raise ValueError(f"not a combination of the F_n: {rest}")
    return sp.expand(out.xreplace({x: Fn(int(x.args[1])) for x in out.atoms(L)}))


# ---------------------------------------------------------------- clamping errors (n°31–35)
i_clamp = sp.Symbol("i", real=True)               # angle (OV, Ox) of the clamp's tangent with the vertical (n°31)
i_prime = sp.Symbol("i'", real=True)              # angle (AT, AG): G off the tangent at A (n°31)
j_eq = sp.Symbol("j", real=True)                  # θ at the equilibrium (117)
h_beta = sp.Symbol("h_beta", real=True)           # β at the equilibrium: Haag's h of (117) (renamed: (127) has another h)
j_prime = sp.Symbol("j'", real=True)              # angle of the tangent AT with the vertical at equilibrium (118)
theta1 = sp.Symbol("theta_1", real=True)          # θ − j (119)
beta1_var = sp.Symbol("tilde_beta_1", real=True)  # β − h (119): Haag's β1, not the β1 of (22)
h_127 = sp.Symbol("h", real=True)                 # ½(K∂H2/∂Y + ∂H2/∂θ) at Y = −i, θ = j (127)
h_132 = sp.Symbol("h'", real=True)                # (K²∂²/∂Y² + 2K∂²/∂Y∂θ + ∂²/∂θ²)H at Y = −i, θ = j (132)
Q1 = sp.Symbol("Q_1", real=True)                  # (133)
