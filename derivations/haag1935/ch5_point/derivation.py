"""Haag 1935, chapter V, n°64–67: the point pendulum, the point mass on the blade, beats (198)–(211).

Everything starts from chapter I's foci quadratic (30), (34)–(35) and motion (25)–(26)
(:mod:`..ch1_model`), with (16) and (22), and, for the uniform blade, from chapter III's
derived end values (the dependencies, by id).  Pure SymPy.
"""
from __future__ import annotations

import sympy as sp

from .. import ch1_model
from ..common import rid
from ..symbols import R, a, beta, beta1, g, lam, theta, u, v0, vl, w0, wl, z, zp
from .symbols import R0, a0, eps, rho

KAPPA = sp.Symbol("kappa", real=True)      # R = R0(1 + κε) near the condition (205)

BETA1 = lam + vl - v0                              # (22)
WRONSKIAN = {wl: w0 - vl}                          # (16): w0 = vλ + wλ


def derived_of(deps, eq: int, name: str) -> sp.Expr:
    return deps[rid(eq, name)].derived


def quadratic_coefficients() -> tuple[sp.Expr, sp.Expr]:
    """(b, c) of the monic (30): z² + bz + c."""
    _one, b, c = ch1_model.foci_quadratic().all_coeffs()
    return b, c


def roots_at_R_zero(_deps) -> sp.Tuple:
    """(198): the roots of (30) for R = 0: z = 0 (the one that tends to zero with R) and z' = −b."""
    b, c = quadratic_coefficients()
    if sp.simplify(c.subs(R, 0)) != 0:
        raise ValueError("the constant term of (30) does not vanish with R")
    return sp.Tuple(sp.Integer(0), sp.factor(-b.subs(R, 0)))


def parasitic_n2(deps) -> sp.Expr:
    """(199): n'² = −K'g/z (34) with z ↔ z', K' = −(a + z − vλ)/β1 (35), z = −R²/z' (31), to the
    leading order in R: lim R²n'² as R → 0, over R²."""
    z_prime_0 = derived_of(deps, 198, "roots")[1]
    K_prime = ch1_model.K_of_zp().subs(zp, z)
    n2p = -K_prime * g / z
    leading = sp.limit(sp.simplify((R**2 * n2p).subs(z, -R**2 / z_prime_0)), R, 0)
    return sp.factor(leading) / R**2


def uniform_ends(deps) -> dict:
    return {v0: derived_of(deps, 159, "v0"), vl: derived_of(deps, 159, "vl"), wl: derived_of(deps, 159, "wl"),
            beta1: derived_of(deps, 159, "beta1")}


def point_mass_n2(deps) -> sp.Expr:
    """(200): n² = −Kg/z' (34), K of (35), z' of (198), for a = 0 on the uniform blade (159)."""
    z_prime = derived_of(deps, 198, "roots")[1]
    K_value = ch1_model.K_of_zp()
    n2 = (-K_value * g / zp).subs(zp, z_prime)
    expr = sp.simplify(n2.subs(a, 0).subs(uniform_ends(deps)))
    return sp.simplify(sp.simplify(expr.rewrite(sp.exp)).rewrite(sp.cosh))


def point_mass_thread(deps) -> sp.Expr:
    """n°65: (200) at u = ∞."""
    return sp.limit(derived_of(deps, 200, "n2").rewrite(sp.exp), u, sp.oo)


def point_mass_stiff(deps) -> sp.Expr:
    """(201): the leading term of (200) as u → 0."""
    expr = derived_of(deps, 200, "n2").rewrite(sp.exp)
    return sp.simplify(sp.series(expr, u, 0, 0).removeO())


def point_mass_stiff_elastic(deps) -> sp.Expr:
    """(201): 3g/(λu²) with u² = λ²ω² (156), ω² = 12mg/(Ee³h), mg = m·g."""
    from ..symbols import m, mg
    omega2 = derived_of(deps, 156, "omega2")
    return sp.simplify(derived_of(deps, 201, "n2").subs(u**2, lam**2 * omega2).subs(u, lam * sp.sqrt(omega2))
                       .subs(mg, m * g))


def critical_a(_deps) -> sp.Expr:
    """(202): the a where the linear coefficient of (30) has a pole (roots 0 and ∞): a − vλ = 0."""
    b, _c = quadratic_coefficients()
    roots = sp.solve(sp.denom(sp.together(b)), a)
    if len(roots) != 1:
        raise ValueError("(30) has not one critical a")
    return roots[0]


def decoupled_motion(deps) -> sp.Tuple:
    """(203), (204): (25), (26) at a = vλ (202), with β2 = −vλ (22) and wλ = w0 − vλ (16)."""
    a_critical = derived_of(deps, 202, "a0")
    first, second = ch1_model.motion()
    return sp.Tuple(sp.factor(first.subs(a, a_critical)),
                    sp.factor(sp.expand(second.subs(a, a_critical).subs(WRONSKIAN).subs(beta1, BETA1))))


def equal_period_radius(deps) -> sp.Expr:
    """(205): the R for which (204), R²θ'' = −g·c θ, has the pulsation g/β1 of (203): R² = β1·c."""
    first, second = derived_of(deps, 203, "motion")
    n0_squared = -sp.simplify(first.subs(theta, 0) / beta)           # (203): β'' = −(g/β1)β at θ = 0
    stiffness = -sp.simplify(second / theta)                        # (204): R²θ'' = −(…)θ
    solutions = [r for r in sp.solve(sp.Eq(stiffness / R**2, n0_squared), R) if r.is_positive is not False]
    return sp.factor(solutions[-1])


def synchronous_n2(deps) -> sp.Expr:
    """(206): n0² = g/β1, the pulsation of (203)."""
    first, _second = derived_of(deps, 203, "motion")
    return sp.simplify(-first.subs(theta, 0) / beta)


def rho_of(deps) -> sp.Expr:
    """(207): ρ such that (30) reads (208): with a − vλ = εR, the numerator of its linear coefficient
    equals 2ρεR²."""
    b, _c = quadratic_coefficients()
    numerator = sp.expand(sp.numer(sp.together(b)))
    if sp.simplify(sp.denom(sp.together(b)) - (a - vl)) != 0:
        raise ValueError("(30)'s denominator is not a − vλ")
    return sp.expand(numerator.subs(beta1, BETA1)) / (2 * (a - vl) * R)


def beat_quadratic(deps) -> sp.Expr:
    """(208): (30) with a − vλ = εR and its numerator 2ρεR² (207)."""
    _b, c = quadratic_coefficients()
    b_new = (2 * rho * eps * R**2) / (eps * R)          # numerator / (a − vλ)
    return sp.expand(z**2 + b_new * z + c)


def beat_n2(deps) -> sp.Expr:
    """n°67: n² = −Kg/z' (34), K of (35), at a = vλ + εR, z' = −R²/z (31): n0²(1 − εz/R)."""
    n2 = (-ch1_model.K_of_zp() * g / zp).subs(zp, -R**2 / z).subs(a, vl + eps * R)
    return sp.factor(sp.simplify(n2))


def beat_frequencies(deps) -> sp.Tuple:
    """(209): F = √n²/2π to the first order in ε, and F' with z ↔ z'."""
    n2 = derived_of(deps, 209, "n2")
    F = sp.series(sp.sqrt(n2) / (2 * sp.pi), eps, 0, 2).removeO()
    return sp.Tuple(sp.simplify(F), sp.simplify(F.subs(z, zp)))


def beat_frequency(deps) -> sp.Expr:
    """(210): f = F' − F (209), z − z' = 2R√(1 + ρ²) from the roots of (208)."""
    F, F_prime = derived_of(deps, 209, "F")
    roots = sp.solve(derived_of(deps, 208, "quadratic"), z)
    z_plus, z_minus = sorted(roots, key=lambda r: sp.N(r.subs({rho: sp.Rational(1, 3), R: 1})), reverse=True)
    return sp.simplify(sp.expand(F_prime - F).subs({z: z_plus, zp: z_minus}))


def rho_near_equal_periods(deps) -> sp.Expr:
    """(211): ρ of (207) with a = vλ + εR (207), wλ = w0 − vλ (16), λ = β1 − vλ + v0 (22), w0 = R0²/β1 (205),
    and R = R0(1 + κε): its term of order ε⁰ is −κ + β1/(2R0); to that order κ = (R − R0)/(a − a0)."""
    expr = derived_of(deps, 207, "rho")
    expr = expr.subs(a, vl + eps * R).subs(wl, w0 - vl).subs(lam, beta1 - vl + v0)
    expr = sp.simplify(expr.subs(w0, R0**2 / beta1).subs(R, R0 * (1 + KAPPA * eps)))
    leading = sp.simplify(sp.series(expr, eps, 0, 1).removeO())
    if KAPPA not in leading.free_symbols:
        raise ValueError("the leading term does not depend on R − R0")
    return sp.expand(leading.subs(KAPPA, (R - R0) / (a - a0)))


def first_term_of_58(deps) -> sp.Expr:
    """n°64: the coefficient of dR/R in (58) of chapter I with K of (36) at z = 0 (198): it vanishes."""
    from ..symbols import dlog_R
    expr = sp.expand(derived_of(deps, 58, "dT"))
    coefficient = expr.coeff(dlog_R)
    return sp.simplify(coefficient.subs(sp.Symbol("K", real=True), ch1_model.K_of_z().subs(z, derived_of(deps, 198, "roots")[0])))
