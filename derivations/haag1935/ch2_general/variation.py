"""Haag 1935, chapter II, n°27 and n°30: the variation of constants (95)–(100), (101) by that route, and the
remark of n°30 ((113), (115)), derived.

n°27 integrates (93) as Haag does: y = Mx' turns it into (95), (96); (96) is solved by varying the
constants of v, w (9) with the Wronskian vw' − wv' = w0 (15), (97)–(98); the ends x = 0 give (99), (100);
∫x ds = 0 (β given) then gives (101) — the same ΔY as the Green identity of :mod:`.derivation`.
Here ε(s) is the right side ε_bar of (93)–(94), a function of s, and ε' its derivative.

n°30: along θ = θ1(1 + ε) (113) a perturbing acceleration Aθ^pθ'^q(1 + α) becomes the integrand of (115);
β = (1 + ε)^p(1 + ε')^q − 1 is of the second order, so (114) gives only the first term and the terms of
the next degree, of which one at most has a nonzero average.
"""
from __future__ import annotations

import sympy as sp

from .. import ch1_model
from ..ch2_common import dY, theta0
from ..symbols import M_of_s, beta1, lam, n_squared, s, v, v0, varphi1, varphi2, vl, w, w0, wl

eps_f = sp.Function("bar_epsilon")               # ε(s) of (93)–(94)
x_f, y_f = sp.Function("x"), sp.Function("y")   # the increment of φ (93) and y = Mx' (n°27)
sigma = sp.Symbol("sigma", real=True)            # the variable of integration of A, B (98)
C, Cp = sp.symbols("C C'", real=True)            # the constants of (97)
A_l, B_l = sp.symbols("A_lambda B_lambda", real=True)
eps0, epsl = sp.symbols("epsilon_0 epsilon_lambda", real=True)     # ε(0), ε(λ)
I0, I1, I2 = sp.symbols("I_0 I_1 I_2")     # ∫ε ds, ∫εφ1 ds, ∫εφ2 ds (I_1, I_2 as in .derivation)
SECOND = {v(s).diff(s, 2): v(s) / M_of_s(s), w(s).diff(s, 2): w(s) / M_of_s(s)}    # (9)
AT_0 = {v(s).diff(s): -1, w(s).diff(s): 0}       # (10) at s = 0
AT_L = {v(s).diff(s): -1, w(s).diff(s): 1}       # (10) at s = λ


def eq95() -> sp.Expr:
    """(95): x from (93), d(Mx')/ds − x = ε − ΔY, with Mx' = y."""
    return sp.solve(sp.Eq(y_f(s).diff(s) - x_f(s), eps_f(s) - dY), x_f(s))[0]


def eq96() -> sp.Expr:
    """(96): the right side of My'' − y, from x' = y/M and the derivative of (95) (ΔY constant)."""
    residual = M_of_s(s) * eq95().diff(s) - y_f(s)            # = 0 since x' = y/M
    return sp.expand(M_of_s(s) * y_f(s).diff(s, 2) - y_f(s) - residual)


def derivatives_of_constants() -> tuple[sp.Expr, sp.Expr]:
    """(A', B') of y = Av + Bw with A'v + B'w = 0, A'v' + B'w' = ε' ((96) divided by M, v'' = v/M, w'' = w/M),
    the Wronskian vw' − wv' = w0 (15)."""
    Ap, Bp = sp.symbols("A' B'")
    sol = sp.solve([Ap * v(s) + Bp * w(s), Ap * v(s).diff(s) + Bp * w(s).diff(s) - eps_f(s).diff(s)], [Ap, Bp])
    wr = v(s) * w(s).diff(s) - w(s) * v(s).diff(s)
    out = []
    for value in (sol[Ap], sol[Bp]):
        num, den = sp.fraction(sp.together(value))
        assert sp.expand(den - wr) == 0 or sp.expand(den + wr) == 0
        out.append(sp.expand(num / (ch1_model.wronskian_constant() * (1 if sp.expand(den - wr) == 0 else -1))))
    return out[0], out[1]


def eq98_integrals() -> sp.Tuple:
    """(98), first forms: A = ∫_0^s A' ds, B = ∫_0^s B' ds."""
    return sp.Tuple(*(integral(d.subs(s, sigma), s) for d in derivatives_of_constants()))


def _by_parts(first: sp.Expr) -> sp.Expr:
    """c∫_0^s ε'(σ)u(σ) dσ = c[εu]_0^s − c∫_0^s ε u' dσ, u' by φ1 = 1 + v', φ2 = w' (11)."""
    (inner,) = first.atoms(sp.Integral)
    factor = sp.simplify(first / inner)
    assert not factor.has(sigma, s)
    return sp.expand(factor * _by_parts_one(inner))


def _by_parts_one(first: sp.Integral) -> sp.Expr:
    integrand = first.function
    u = sp.simplify(integrand / eps_f(sigma).diff(sigma))
    assert not u.has(eps_f)
    boundary = (eps_f(s) * u.subs(sigma, s) - (eps_f(sigma) * u).subs(sigma, 0)).subs(
        {eps_f(0): eps0, v(0): v0, w(0): w0})
    du = u.diff(sigma).subs({v(sigma).diff(sigma): varphi1(sigma) - 1, w(sigma).diff(sigma): varphi2(sigma)})
    return sp.expand(boundary) - integral(eps_f(sigma) * du, s)


def integral(integrand: sp.Expr, upper) -> sp.Expr:
    """∫_0^upper integrand dσ, term by term, the factors free of σ taken out."""
    out = sp.S.Zero
    for term in sp.Add.make_args(sp.expand(integrand)):
        c, f = term.as_independent(sigma, as_Add=False)
        out += c * sp.Integral(f, (sigma, 0, upper))
    return out


def in_I(expr: sp.Expr) -> sp.Expr:
    """∫_0^λ ε dσ, ∫_0^λ εφ1 dσ, ∫_0^λ εφ2 dσ written I0, I1, I2."""
    names = {eps_f(sigma): I0, eps_f(sigma) * varphi1(sigma): I1, eps_f(sigma) * varphi2(sigma): I2}
    return expr.replace(lambda e: isinstance(e, sp.Integral) and e.function in names and e.limits[0][2] == lam,
                        lambda e: names[e.function])


def eq98() -> sp.Tuple:
    """(98), second forms: A and B integrated by parts."""
    return sp.Tuple(*(_by_parts(i) for i in eq98_integrals()))


def eq97() -> sp.Expr:
    """(97): y = Av + Bw + Cv + C'w, A and B of (98)."""
    A, B = eq98_integrals()
    return (A + C) * v(s) + (B + Cp) * w(s)


def eq97_solves_96() -> sp.Expr:
    """M y'' − y − Mε' for y of (97), with (9) and the Wronskian (15): 0."""
    y = eq97()
    expr = sp.expand(M_of_s(s) * y.diff(s, 2) - y - M_of_s(s) * eps_f(s).diff(s))
    expr = expr.subs(SECOND).doit()
    # the Wronskian vw' − wv' = w0 (15): w' = (w0 + wv')/v
    expr = expr.subs(w(s).diff(s), (w0 + w(s) * v(s).diff(s)) / v(s))
    return sp.simplify(expr)


def y_prime_at(point) -> sp.Expr:
    """y' at s = 0 or s = λ: (A + C)v' + (B + C')w' (A'v + B'w = 0 by (98)), A = B = 0 at s = 0, (10)."""
    A_f, B_f = sp.Function("A"), sp.Function("B")
    Ap, Bp = derivatives_of_constants()
    y = (A_f(s) + C) * v(s) + (B_f(s) + Cp) * w(s)
    yp = sp.expand(y.diff(s).subs({A_f(s).diff(s): Ap, B_f(s).diff(s): Bp}))
    if point == 0:
        return sp.expand(yp.subs(AT_0).subs({A_f(s): 0, B_f(s): 0}))
    return sp.expand(yp.subs(AT_L).subs({A_f(s): A_l, B_f(s): B_l}))


def eq99() -> sp.Expr:
    """(99): C from x(0) = 0, i.e. y'(0) = ε0 − ΔY by (95)."""
    return sp.solve(sp.Eq(y_prime_at(0), eps0 - dY), C)[0]


def eq100() -> sp.Expr:
    """(100): y'(λ) (the left side of y'(λ) = ε_λ − ΔY, from x(λ) = 0)."""
    return y_prime_at(lam)


def eq101_by_constants() -> sp.Expr:
    """(101) by Haag's route: ∫x ds = λΔY − ∫ε ds + y_λ − y_0 = 0 (β given), y of (97) at the ends, wλ = w0 − vλ
    (16), C (99), C' (100), B_λ of (98) at s = λ (∫ε(1 − φ1) = I0 − I1): solved for ΔY."""
    y_l = (A_l + C) * vl + (B_l + Cp) * wl
    y_0 = C * v0 + Cp * w0
    eq = lam * dY - I0 + y_l - y_0
    Cp_val = sp.solve(sp.Eq(eq100(), epsl - dY), Cp)[0]
    B_at_l = in_I(eq98()[1].subs(s, lam).subs({eps_f(lam): epsl, v(lam): vl}))
    eq = eq.subs(wl, w0 - vl).subs(Cp, Cp_val).subs(C, eq99()).subs(B_l, B_at_l)
    sol = sp.solve(eq, dY)[0]
    return sp.simplify(sol.subs(lam, beta1 - vl + v0))          # λ = β1 − vλ + v0 (22)


# ================================================================ n°30: (113), (115)
phi = sp.Symbol("phi", real=True)
eps_30, eps_30p = sp.symbols("epsilon epsilon'", real=True)          # θ = θ1(1 + ε), θ' = θ1'(1 + ε')
alpha_30, beta_30, A_30 = sp.symbols("alpha beta_30 A", real=True)
p_30, q_30 = sp.symbols("p q", integer=True, nonnegative=True)
theta1_30, theta1p_30 = sp.symbols("theta_1 theta_1'", real=True)


def eq113() -> sp.Expr:
    """(113): θ = θ1(1 + ε), θ1 = θ0 cos φ, φ = nt."""
    return theta0 * sp.cos(phi) * (1 + eps_30)


def eq115_integrand() -> sp.Expr:
    """(115): Aθ^pθ'^q(1 + α) at θ = θ1(1 + ε), θ' = θ1'(1 + ε'): Aθ1^pθ1'^q(1 + β)(1 + α) with
    β = (1 + ε)^p(1 + ε')^q − 1; αβ (α of the first order, β of the second) dropped by the order counter."""
    mark = sp.Symbol("m", positive=True)
    F = A_30 * (theta1_30 * (1 + eps_30)) ** p_30 * (theta1p_30 * (1 + eps_30p)) ** q_30 * (1 + alpha_30)
    F = F / (A_30 * theta1_30**p_30 * theta1p_30**q_30)
    F = sp.powsimp(sp.expand_power_base(F, force=True))
    in_beta = sp.expand(F.subs((1 + eps_30) ** p_30 * (1 + eps_30p) ** q_30, 1 + beta_30))
    kept = sp.series(in_beta.subs({alpha_30: mark * alpha_30, beta_30: mark**2 * beta_30}), mark, 0, 3).removeO()
    return A_30 * theta1_30**p_30 * theta1p_30**q_30 * sp.expand(kept.subs(mark, 1))


def eq115() -> sp.Expr:
    """(115): ΔT = (1/(n³θ0))∫_0^{2π} (the integrand) cos φ dφ ((114) with θ replaced by (113))."""
    n = sp.sqrt(n_squared)
    return sp.Integral(eq115_integrand() * sp.cos(phi), (phi, 0, 2 * sp.pi)) / (n**3 * theta0)


def beta_30_series() -> sp.Expr:
    """β = (1 + ε)^p(1 + ε')^q − 1 to the first order: pε + qε'."""
    mark = sp.Symbol("m", positive=True)
    expr = (1 + mark * eps_30) ** p_30 * (1 + mark * eps_30p) ** q_30 - 1
    return sp.expand(sp.series(expr, mark, 0, 2).removeO().subs(mark, 1))


def calculable_terms(p: int, q: int) -> tuple:
    """n°30: the averages ∫θ1^aθ1'^b cos φ dφ of the first term (a, b) = (p, q) and of the terms of the next
    degree (p + 1, q), (p, q + 1), along θ1 = θ0 cos φ, θ1' = −nθ0 sin φ (θ0 = n = 1)."""
    return tuple(sp.integrate(sp.cos(phi) ** a * (-sp.sin(phi)) ** b * sp.cos(phi), (phi, 0, 2 * sp.pi))
                 for a, b in ((p, q), (p + 1, q), (p, q + 1)))


def nonzero_calculable(upto: int = 5) -> sp.Tuple:
    """For 0 ≤ p, q ≤ upto, (p, q) ≠ (0, 0): the number of nonzero calculable averages minus the text's count
    (0 when p is even and q odd, 1 otherwise): all 0."""
    out = []
    for p in range(upto + 1):
        for q in range(upto + 1):
            if (p, q) == (0, 0):
                continue
            count = sum(1 for x in calculable_terms(p, q) if x != 0)
            out.append(count - (0 if p % 2 == 0 and q % 2 == 1 else 1))
    return sp.Tuple(*out)


def pendulum_next_term() -> sp.Expr:
    """The footnote of n°31: (114) with the whole F = n²(θ − sin θ) along θ = θ0 cos φ gives ΔT/T to θ0⁴;
    its θ0⁴ coefficient (the term the remark calls false)."""
    from .derivation import eq114_relative
    th = theta0 * sp.cos(phi)
    F = n_squared * sp.series(th - sp.sin(th), theta0, 0, 6).removeO()
    Cv = sp.integrate(sp.expand(F * sp.cos(phi)), (phi, 0, 2 * sp.pi))
    rel = sp.expand(eq114_relative().subs(sp.Symbol("C"), Cv))
    return rel.coeff(theta0, 4)
