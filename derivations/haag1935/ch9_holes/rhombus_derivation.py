"""Haag 1935, chapter IX, n°107–110, eqs. (334)–(346): the blade with a rhombus hole, derived with SymPy.

The blade is inverted (chapter VIII: g changed into −g) and Haag takes M in absolute value
(footnote (2) of n°107), so (9) reads M v'' + v = 0 with M = M0(1 + k|s|), the origin of s at the
middle of the blade, −λ/2 ≤ s ≤ λ/2.  The steps follow the memoir:

* (334)–(335): the change of variable x = (2ω/k)√(1 + k|s|) turns (9) into Bessel's equation;
* (336): its general solution by SymPy's ``dsolve``, rewritten in Haag's basis J_1, Y_1;
* (337)–(342): the constants of v and w from the conditions of n°4 (v' = −1 at both ends; w' = 0
  at the top, w' = 1 at the bottom; w, w' continuous at the middle), solved by ``sympy.solve``;
* (343)–(345): the end values and the identity (16);
* n°110, (346): G_2 = ∫ w²/M ds through the integral ∫ v²/x dx of the text.

**Convention.**  Haag's Y_n is the function of "Bessel and Neumann" of Jahnke–Emde, normalised by the
Wronskian he quotes, J_1 Y_0 − Y_1 J_0 = 1/x: Neumann's Y_n = (π/2)·Y_n(today) + (ln 2 − γ)·J_n
(:func:`neumann_Y`).  Today's Y_n has the Wronskian 2/(πx).  Every quantity of n°107–110 is a
combination Y(a)J(b) − J(a)Y(b), in which the J part of the admixture cancels; only the scale π/2
matters, and it is the one the Wronskian 1/x fixes.

The Bessel values at x_0 and x_1 enter the linear solves as plain symbols (:data:`AT_X0`,
:data:`AT_X1`) and are put back as functions at the end, so that the Wronskian is used exactly where
Haag uses it (footnote of n°108).
"""
from __future__ import annotations

import functools
import types

import sympy as sp

from ..symbols import lam, omega

# ---------------------------------------------------------------- symbols of n°107–110
k = sp.Symbol("k", positive=True)              # M = M0(1 + k|s|)  (n°107)
M0 = sp.Symbol("M_0", positive=True)           # M at the middle of the blade
sigma = sp.Symbol("s", real=True)              # abscissa from the middle, −λ/2 ≤ s ≤ λ/2
x = sp.Symbol("x", positive=True)              # (334)
x0 = sp.Symbol("x_0", positive=True)           # x at s = 0 (the middle)
x1 = sp.Symbol("x_1", positive=True)           # x at s = ±λ/2 (the ends)
A, B = sp.symbols("A B", real=True)            # constants of v (336)–(337)
A1, B1 = sp.symbols("A' B'", real=True)        # constants of w for s < 0 (n°108)
A2, B2 = sp.symbols("A'' B''", real=True)      # constants of w for s > 0
eps = sp.Symbol("epsilon", real=True)          # ε = ±1, the sign of s (n°107)
V = sp.Function("V")                           # v as a function of x

# Neumann's second-kind function in Jahnke–Emde's normalisation (the Wronskian 1/x)
NEUMANN_SHIFT = sp.log(2) - sp.EulerGamma


def neumann_Y(order: int, arg: sp.Expr) -> sp.Expr:
    """Haag's Y_n (n°107, footnote of n°110): Neumann's Y_n = (π/2) Y_n(today) + (ln 2 − γ) J_n."""
    return sp.pi / 2 * sp.bessely(order, arg) + NEUMANN_SHIFT * sp.besselj(order, arg)


def J(order: int, arg: sp.Expr) -> sp.Expr:
    return sp.besselj(order, arg)


def Y(order: int, arg: sp.Expr) -> sp.Expr:
    return neumann_Y(order, arg)


# the Bessel values at x_0 and x_1 as symbols, for the linear solves
J0a, J1a, Y0a, Y1a = sp.symbols("J0a J1a Y0a Y1a", real=True)
J0b, J1b, Y0b, Y1b = sp.symbols("J0b J1b Y0b Y1b", real=True)
AT_X0 = {J0a: J(0, x0), J1a: J(1, x0), Y0a: Y(0, x0), Y1a: Y(1, x0)}
AT_X1 = {J0b: J(0, x1), J1b: J(1, x1), Y0b: Y(0, x1), Y1b: Y(1, x1)}


def as_functions(expr: sp.Expr) -> sp.Expr:
    """The Bessel symbols put back as Haag's functions of x_0 and x_1."""
    return expr.xreplace({**AT_X0, **AT_X1})


def x_of(s_value: sp.Expr) -> sp.Expr:
    """(334): x = (2ω/k)√(1 + k|s|)."""
    return 2 * omega / k * sp.sqrt(1 + k * sp.Abs(s_value))


def x_ends() -> dict:
    """x_0 (s = 0) and x_1 (s = ±λ/2) from (334)."""
    return {x0: x_of(0), x1: sp.simplify(x_of(lam / 2))}


# ================================================================ n°107: (334)–(336)
def stiffness() -> sp.Expr:
    """n°107: M = M0(1 + k|s|)."""
    return M0 * (1 + k * sp.Abs(sigma))


def omega_squared() -> sp.Expr:
    """(334): ω² = 1/M0."""
    return 1 / M0


@functools.lru_cache(maxsize=None)
def transformed_equation(sign: int) -> sp.Expr:
    """(9) for the inverted blade, M v'' + v = 0 (footnote (2) of n°107), on the half sign·s > 0, after the
    change of variable (334); divided by the coefficient of V'' and written in x."""
    s_pos = sp.Symbol("s_pos", positive=True)        # |s|
    s_half = sign * s_pos
    x_s = 2 * omega / k * sp.sqrt(1 + k * s_pos)     # (334) on this half
    v_s = V(x_s)
    M_s = stiffness().subs(sigma, s_half).subs(M0, 1 / omega**2)
    # d/ds = sign · d/d|s|
    dv = sign * sp.diff(v_s, s_pos)
    d2v = sign * sp.diff(dv, s_pos)
    ode = M_s * d2v + v_s
    # back to x: 1 + k|s| = (kx/(2ω))²
    s_of_x = ((k * x / (2 * omega)) ** 2 - 1) / k
    ode = sp.simplify(ode.subs(s_pos, s_of_x))
    lead = ode.coeff(sp.Derivative(V(x), (x, 2)))
    return sp.expand(sp.simplify(ode / lead))


@functools.lru_cache(maxsize=None)
def bessel_equation() -> sp.Expr:
    """(335): d²v/dx² − (1/x) dv/dx + v = 0, from (9) by (334) (the half s > 0; s < 0 gives the same)."""
    return transformed_equation(+1)


@functools.lru_cache(maxsize=None)
def general_solution() -> sp.Expr:
    """(336): v = x[A J_1(x) + B Y_1(x)] from ``dsolve`` of (335), rewritten in Haag's basis J_1, Y_1
    (today's Y_1 = (2/π)(Y_1^Neumann − (ln 2 − γ)J_1), so the constants are renamed linearly)."""
    solution = sp.dsolve(bessel_equation(), V(x)).rhs
    C1, C2 = sorted(solution.free_symbols - {x}, key=lambda c: c.name)
    # C1 J1 + C2 Y1(today) = C1 J1 + C2 (2/π)(Y1 − shift·J1) = A J1 + B Y1
    rewritten = solution.subs(sp.bessely(1, x), 2 / sp.pi * (Y(1, x) - NEUMANN_SHIFT * J(1, x)))
    rewritten = rewritten.subs({C2: sp.pi / 2 * B}).subs({C1: A + sp.pi / 2 * B * 2 / sp.pi * NEUMANN_SHIFT})
    return sp.expand(rewritten).collect([A, B])


def slope_in_x() -> sp.Expr:
    """n°107: dv/dx of (336), reduced to x[A J_0(x) + B Y_0(x)] by SymPy's Bessel derivatives."""
    return sp.simplify(sp.diff(general_solution(), x))


def wronskian(second=neumann_Y) -> sp.Expr:
    """The identity of the footnote of n°110: J_1(x)Y_0(x) − Y_1(x)J_0(x) (= 1/x for Neumann's Y)."""
    return J(1, x) * second(0, x) - second(1, x) * J(0, x)


def ds_factor() -> sp.Expr:
    """n°107: dx/ds = ε 2ω²/(kx), from (334) with 1 + k|s| = (kx/2ω)²."""
    s_pos = sp.Symbol("s_pos", positive=True)
    dxds = sp.diff(2 * omega / k * sp.sqrt(1 + k * s_pos), s_pos)
    return sp.simplify(eps * dxds.subs(s_pos, ((k * x / (2 * omega)) ** 2 - 1) / k))


# ================================================================ n°107: v, (337)–(338)
@functools.lru_cache(maxsize=None)
def v_constants() -> types.MappingProxyType:
    """(337): A, B of v from v(0) = 0 (v odd, n°4: A J_1(x_0) + B Y_1(x_0) = 0) and v' = −1 at the end of
    the half, i.e. x_1(AJ_0(x_1) + BY_0(x_1))·ε2ω²/(kx_1) = −1."""
    slope_end = x1 * (A * J0b + B * Y0b) * ds_factor().subs(x, x1)
    sol = sp.solve([A * J1a + B * Y1a, slope_end + 1], [A, B], dict=True)[0]
    return types.MappingProxyType({name: sp.factor(sol[name]) for name in (A, B)})


def D_definition() -> sp.Expr:
    """(338): D = Y_1(x_0)J_0(x_1) − Y_0(x_1)J_1(x_0)."""
    return Y(1, x0) * J(0, x1) - Y(0, x1) * J(1, x0)


def D_prime_definition() -> sp.Expr:
    """(341): D' = Y_0(x_0)J_0(x_1) − Y_0(x_1)J_0(x_0)."""
    return Y(0, x0) * J(0, x1) - Y(0, x1) * J(0, x0)


def D1_definition() -> sp.Expr:
    """(344): D_1 = Y_1(x_0)J_1(x_1) − J_1(x_0)Y_1(x_1)."""
    return Y(1, x0) * J(1, x1) - J(1, x0) * Y(1, x1)


def D1_prime_definition() -> sp.Expr:
    """(344): D'_1 = Y_0(x_0)J_1(x_1) − Y_1(x_1)J_0(x_0)."""
    return Y(0, x0) * J(1, x1) - Y(1, x1) * J(0, x0)


def v_constant(name: str) -> sp.Expr:
    """(337): A or B, with the Bessel values put back as functions."""
    return as_functions(v_constants()[{"A": A, "B": B}[name]])


def v_constant_haag(name: str) -> sp.Expr:
    """(337) with Haag's ε: the ε of (337) is − for s > 0 (minus the sign of s used above); ε² = 1."""
    expr = sp.factor(v_constant(name).subs(eps, -eps))
    return expr.xreplace({eps**-1: eps})


# ================================================================ n°108: w, (339)–(342)
WRONSKIAN_X0 = J1a * Y0a - Y1a * J0a      # = 1/x_0 (footnote of n°110)


def middle_conditions() -> list:
    """n°108: w and dw/ds continuous at s = 0 (dx/ds changes sign with ε there)."""
    return [A2 * J1a + B2 * Y1a - (A1 * J1a + B1 * Y1a),
            A2 * J0a + B2 * Y0a + (A1 * J0a + B1 * Y0a)]


def middle_slope() -> sp.Expr:
    """n°108: A''J_0(x_0) + B''Y_0(x_0) from the continuity of dw/ds = ε(dw/dx)·2ω²/(kx) at s = 0, where
    dw/dx = x(AJ_0 + BY_0) and ε = −1 on the left (A', B'), +1 on the right (A'', B'')."""
    right = sp.Symbol("R")
    left_slope = ds_factor().subs({eps: -1, x: x0}) * x0 * (A1 * J0a + B1 * Y0a)
    right_slope = ds_factor().subs({eps: 1, x: x0}) * x0 * right
    return as_functions(sp.solve(left_slope - right_slope, right)[0])


@functools.lru_cache(maxsize=None)
def continuation() -> types.MappingProxyType:
    """(339): A'', B'' from A', B' by the conditions at the middle; the determinant J_1 Y_0 − Y_1 J_0 at x_0
    is replaced by 1/x_0 (the Wronskian, footnote of n°110), as Haag does."""
    sol = sp.solve(middle_conditions(), [A2, B2], dict=True)[0]
    out = {}
    for name in (A2, B2):
        expr = sp.together(sol[name])
        num, den = sp.fraction(expr)
        ratio = sp.simplify(den / WRONSKIAN_X0)
        if ratio not in (1, -1):
            raise ValueError(f"the denominator of {name} is not ± the Wronskian at x_0: {den}")
        out[name] = sp.expand(num * ratio * x0)
    return types.MappingProxyType(out)


@functools.lru_cache(maxsize=None)
def w_constants() -> types.MappingProxyType:
    """(340), (342): A', B' from w'(−λ/2) = 0 (A'J_0(x_1) + B'Y_0(x_1) = 0) and w'(λ/2) = 1, i.e.
    x_1(A''J_0(x_1) + B''Y_0(x_1))·2ω²/(kx_1) = 1 with A'', B'' of (339); then A'', B'' by (339)."""
    cont = continuation()
    top = A1 * J0b + B1 * Y0b
    bottom = x1 * (cont[A2] * J0b + cont[B2] * Y0b) * ds_factor().subs({x: x1, eps: 1}) - 1
    sol = sp.solve([top, bottom], [A1, B1], dict=True)[0]
    out = {A1: sp.factor(sol[A1]), B1: sp.factor(sol[B1])}
    out.update({name: sp.factor(cont[name].subs(sol)) for name in (A2, B2)})
    return types.MappingProxyType(out)


def w_constant(name: str) -> sp.Expr:
    """(340), (342): A', B', A'' or B'', with the Bessel values put back as functions."""
    return as_functions(w_constants()[{"A'": A1, "B'": B1, "A''": A2, "B''": B2}[name]])


# ================================================================ n°109: (343)–(345)
BESSEL_AT = {0: {0: J0a, 1: J1a}, 1: {0: J0b, 1: J1b}}
NEUMANN_AT = {0: {0: Y0a, 1: Y1a}, 1: {0: Y0b, 1: Y1b}}


def solution_at(constants: tuple, end: int) -> sp.Expr:
    """x[AJ_1(x) + BY_1(x)] (336) at x_0 (end = 0) or x_1 (end = 1), the Bessel values as symbols."""
    first, second = constants
    at = (x0, x1)[end]
    return at * (first * BESSEL_AT[end][1] + second * NEUMANN_AT[end][1])


def slope_at(constants: tuple, end: int) -> sp.Expr:
    """dv/dx = x[AJ_0(x) + BY_0(x)] (n°107) at x_0 or x_1, the Bessel values as symbols."""
    first, second = constants
    at = (x0, x1)[end]
    return at * (first * BESSEL_AT[end][0] + second * NEUMANN_AT[end][0])


def v_end() -> sp.Expr:
    """(343): v_0 = v(−λ/2) = x_1[AJ_1(x_1) + BY_1(x_1)] with (337) on the half s < 0 (the sign of s, −1, in
    dx/ds; Haag's ε of (337) is the opposite one)."""
    c = v_constants()
    return as_functions(sp.factor(solution_at((c[A], c[B]), 1).subs(eps, -1)))


def v_end_bottom() -> sp.Expr:
    """(343): v_λ = v(λ/2), with (337) on the half s > 0 (sign of s: +1)."""
    c = v_constants()
    return as_functions(sp.factor(solution_at((c[A], c[B]), 1).subs(eps, 1)))


def w_end_symbols(which: str) -> sp.Expr:
    """(343): w_0 = y(x_1) with A', B' (s < 0), w_λ = z(x_1) with A'', B'' (s > 0); Bessel values as symbols."""
    c = w_constants()
    pair = (c[A1], c[B1]) if which == "0" else (c[A2], c[B2])
    return sp.factor(solution_at(pair, 1))


def w_end(which: str) -> sp.Expr:
    """(343): w_0 or w_λ as functions of x_0, x_1."""
    return as_functions(w_end_symbols(which))


def identity_345() -> sp.Expr:
    """(345): D_1 D' − D D'_1, expanded from the definitions (338), (341), (344) and factored: it is the product of
    the Wronskians J_1 Y_0 − Y_1 J_0 at x_0 and at x_1, each 1/x (footnote of n°110), hence 1/(x_0 x_1)."""
    D_ = Y1a * J0b - Y0b * J1a
    Dp_ = Y0a * J0b - Y0b * J0a
    D1_ = Y1a * J1b - J1a * Y1b
    D1p_ = Y0a * J1b - Y1b * J0a
    product = sp.factor(sp.expand(D1_ * Dp_ - D_ * D1p_))
    wa, wb = J1a * Y0a - Y1a * J0a, J1b * Y0b - Y1b * J0b
    if sp.expand(product - wa * wb) != 0:
        raise ValueError(f"D_1 D' − D D'_1 is not the product of the Wronskians: {product}")
    return (wa * wb).subs({J1a: (1 / x0 + Y1a * J0a) / Y0a, J1b: (1 / x1 + Y1b * J0b) / Y0b}).simplify()


def D_symbols() -> tuple:
    """The symbols D, D', D_1, D'_1 of (338), (341), (344)."""
    return sp.symbols("D D' D_1 D'_1", real=True)


def D_definitions() -> tuple:
    """The memoir's definitions (338), (341), (344), to apply to forms written with D, D', D_1, D'_1."""
    D, Dp, D1, D1p = D_symbols()
    return ((D, D_definition()), (Dp, D_prime_definition()), (D1, D1_definition()), (D1p, D1_prime_definition()))


# ================================================================ n°110: G_2 and (346)
def jacobian_in_x() -> sp.Expr:
    """n°110: (1/M)·ds/dx as a function of x, M = M0(1 + k|s|) = k²x²/(4ω⁴) by (334): so that
    ∫ w²/M ds = (2ω²/k) ∫ w²/x dx on each half."""
    s_of_x = ((k * x / (2 * omega)) ** 2 - 1) / k              # |s| from (334)
    M_of_x = (M0 * (1 + k * s_of_x)).subs(M0, 1 / omega**2)
    return sp.simplify(1 / (M_of_x * ds_factor().subs(eps, 1)))


def integral_identity() -> sp.Expr:
    """n°110: a primitive of v²/x for every solution of (335), found by the ansatz a v² + b v'² + c vv'/x
    whose derivative, with v'' = v'/x − v, must equal v²/x."""
    a, b, c = sp.symbols("a b c")
    val, der = sp.symbols("v v'", real=True)
    second = der / x - val                                     # (335)
    F = a * val**2 + b * der**2 + c * val * der / x
    dF = sp.diff(F, val) * der + sp.diff(F, der) * second + sp.diff(F, x)
    eqs = sp.Poly(sp.expand((dF - val**2 / x) * x**2), val, der).coeffs()
    sol = sp.solve(eqs, [a, b, c], dict=True)[0]
    return F.subs(sol)


def half_integral(which: str) -> sp.Expr:
    """n°110: ∫_{x_0}^{x_1} y²/x dx (which = "y") or z²/x (which = "z") by the primitive, with the values at
    x_1: y = w_0, dy/dx = 0 (w'(−λ/2) = 0); z = w_λ, dz/dx = (kx_1/2ω²)·w'(λ/2) = kx_1/(2ω²) (n°107)."""
    F = integral_identity()
    val, der = sp.symbols("v v'", real=True)
    w0, wl, y0, y0p, z0, z0p = half_symbols()
    if which == "y":
        top = F.subs({val: w0, der: 0, x: x1})
        bottom = F.subs({val: y0, der: y0p, x: x0})
    else:
        top = F.subs({val: wl, der: 1 / ds_factor().subs({eps: 1, x: x1}), x: x1})
        bottom = F.subs({val: z0, der: z0p, x: x0})
    return sp.expand(top - bottom)


def half_symbols() -> tuple:
    """w_0, w_λ, y_0, y'_0, z_0, z'_0 (n°110)."""
    return sp.symbols("w_0 w_lambda y_0 y'_0 z_0 z'_0", real=True)


def middle_values() -> dict:
    """n°110: y_0 = z_0 = x_0[A'J_1(x_0) + B'Y_1(x_0)], y'_0 = x_0[A'J_0(x_0) + B'Y_0(x_0)] = −z'_0, by (340);
    the Bessel values as symbols."""
    w0, wl, y0, y0p, z0, z0p = half_symbols()
    c = w_constants()
    value, slope = sp.factor(solution_at((c[A1], c[B1]), 0)), sp.factor(slope_at((c[A1], c[B1]), 0))
    return {y0: value, z0: value, y0p: slope, z0p: -slope}


def middle_value(name: str) -> sp.Expr:
    """y_0 or y'_0 of n°110 as functions of x_0, x_1."""
    w0, wl, y0, y0p, z0, z0p = half_symbols()
    return as_functions(middle_values()[{"y0": y0, "y0p": y0p}[name]])


def G2_intermediate_symbols() -> sp.Expr:
    """n°110: G_2 = (2ω²/k)(∫y²/x + ∫z²/x) with the middle values (Bessel values as symbols)."""
    total = 2 * omega**2 / k * (half_integral("y") + half_integral("z"))
    return total.subs(middle_values())


def G2_intermediate() -> sp.Expr:
    """n°110: G_2 in terms of w_0, w_λ and the Bessel functions at x_0, x_1."""
    return as_functions(G2_intermediate_symbols())


def G2_final() -> sp.Expr:
    """(346): G_2 with w_0, w_λ of (343): a function of ω, k, x_0, x_1 (λ through x_1)."""
    w0, wl = half_symbols()[:2]
    return as_functions(G2_intermediate_symbols().subs({w0: w_end_symbols("0"), wl: w_end_symbols("l")}))
