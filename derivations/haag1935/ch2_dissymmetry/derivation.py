"""Haag 1935, chapter II, n°44–45, eqs. (151)–(155): a blade whose Young's modulus is not the same on the two
sides, with clamping errors, derived.

n°44: on the side θ > 0 the modulus exceeds by ΔE = εE, so the moment Mφ' gains εMφ' there: the moment
increment of the blade's equation is ε_4 = −εM dφ/ds (θ > 0), 0 (θ < 0).  M dφ/ds = Yv + θw ((9), (13)),
taken along the oscillation about the tilted equilibrium (θ = j + θ1 (119), Y = Kθ1 − i (122)); f follows by
(104)–(105) (:func:`..ch2_perturbations.derivation.f_of_moment`), its three integrals recognised as g_1(ε)
(139), A and B (152).  ΔT/T (154) is the first harmonic (114) along θ1 = θ0 sin φ over the half-period where
θ = j + θ1 > 0, φ1 < φ < π − φ1 with θ0 sin φ1 = −j (153).  n°45: i' = 0, i of (117), B = g_1 − AK, (134)
written Cj²/Q, the sum times 4Q is P (155); the relation (36) for K turns the coefficient of A into Kz.
"""
from __future__ import annotations

import sympy as sp

from .. import ch1_model
from ..ch2_clamping import derivation as clamping
from ..ch2_common import i_clamp, i_prime, j_eq, theta0, theta1
from ..ch2_general import derivation as general
from ..ch2_perturbations.derivation import _single_integral, eq139, f_of_moment, g_fn, q
from ..symbols import K, M_of_s, Q, Y, a1, lam, s, theta, v, w, wl, z, zp

eps_E = sp.Function("varepsilon")              # ε(s) = ΔE/E, the excess of the modulus on the right (n°44)
A_d, B_d = sp.symbols("A B", real=True)        # (152)
phi = sp.Symbol("phi", real=True)              # the phase, θ1 = θ0 sin φ (n°44)
phi1 = sp.Symbol("varphi_1", real=True)        # (153), in (−π/2, π/2)
C_j = sp.Symbol("C", real=True)                # (134) = Cj²/Q when i' = 0 (n°45)
x_hom = sp.Symbol("x_h", positive=True)        # the variable of homogeneity: g_1 = ∫(Kv + x_h w)²ε/M at x_h = 1


def curvature_moment() -> sp.Expr:
    """M dφ/ds = Yv + θw: φ = Yφ1 + θφ2 (13) with Mφ1' = v, Mφ2' = w ((9), (11)) — Haag's (14)."""
    return Y * v(s) + theta * w(s)


def eps4() -> sp.Expr:
    """n°44: ε_4 = −εM dφ/ds for θ > 0 (the modulus E(1 + ε): the moment EI(1 + ε)φ' exceeds Mφ' by εMφ')."""
    return -eps_E(s) * curvature_moment()


def eps_along() -> sp.Expr:
    """n°44: ε_4 along the oscillation about the tilted equilibrium, θ = j + θ1 (119), Y = Kθ1 − i (122):
    −ε[θ1(Kv + w) + wj − vi]."""
    return sp.expand(eps4().subs({Y: K * theta1 - i_clamp, theta: j_eq + theta1}, simultaneous=True))


def g1_def() -> sp.Integral:
    """g_1(ε) of (139): ∫(Kv + w)²ε/M ds."""
    return eq139().subs(q, 1).subs(sp.Symbol("x"), eps_E(s))


def eq152() -> sp.Tuple:
    """(152): A = ∫v(Kv + w)ε/M ds, B = ∫w(Kv + w)ε/M ds (∫_0^λ; definitions)."""
    common = (K * v(s) + w(s)) * eps_E(s) / M_of_s(s)
    return sp.Tuple(sp.Integral(v(s) * common, (s, 0, lam)), sp.Integral(w(s) * common, (s, 0, lam)))


def eq151() -> sp.Expr:
    """(151): f by (104)–(105) for ε_4 of :func:`eps_along`; the integrand split by θ1, i, j and each part
    recognised as g_1(ε) (139), A or B (152) (a part must be a constant multiple of the definition)."""
    f = f_of_moment(lambda x: eps_along().subs(s, x))
    k, integral = _single_integral(f)
    body = sp.expand(integral.function)
    defs = ((theta1, g1_def(), g_fn(1, eps_E(s))), (i_clamp, eq152()[0], A_d), (j_eq, eq152()[1], B_d))
    out = sp.S.Zero
    for var, definition, symbol in defs:
        part = body.coeff(var)
        ratio = sp.simplify(part / definition.function)
        if ratio.has(s):
            raise ValueError(f"the {var} part is not a multiple of {definition}")
        out += ratio * var * symbol
    if sp.simplify(body - sum(body.coeff(var) * var for var, _, _ in defs)) != 0:
        raise ValueError("ε_4 has a part free of θ1, i, j")
    return k * out


def half_derivatives() -> sp.Tuple:
    """n°44: (½∂g_1/∂K − A, ½∂g_1/∂x_h − B at x_h = 1), g_1 = ∫(Kv + x_h w)²ε/M (homogeneous of degree 2 in
    (K, x_h)): both 0, the derivatives taken under the integral."""
    g1h = g1_def().function.subs(w(s), x_hom * w(s))
    A, B = (e.function for e in eq152())
    return sp.Tuple(sp.simplify(g1h.diff(K) / 2 - A).subs(x_hom, 1),
                    sp.simplify((g1h.diff(x_hom) / 2).subs(x_hom, 1) - B))


def identity_AK_B() -> sp.Expr:
    """n°45: AK + B − g_1, the integrands of (152) and (139): 0 (Euler's relation for the degree 2)."""
    A, B = (e.function for e in eq152())
    return sp.simplify(A * K + B - g1_def().function)


def eq153() -> sp.Expr:
    """(153): φ1 defined by θ0 sin φ1 = −j, the phase at which θ = j + θ1 = 0 on θ1 = θ0 sin φ (a definition),
    returned as θ0 sin φ1 + j (= 0)."""
    return theta0 * sp.sin(phi1) + j_eq


def harmonic_integral() -> sp.Expr:
    """The line before (154): ΔT/T = (1/(2πn²θ0))∫Φ sin φ dφ by (114) (θ1 = θ0 sin φ = θ0 cos(φ − π/2)),
    Φ = f/(z − z') where θ = j + θ1 > 0, i.e. sin φ > sin φ1, φ1 < φ < π − φ1; over Q = K(z − z')."""
    Cs = sp.Symbol("C")
    f = eq151().subs(theta1, theta0 * sp.sin(phi))
    integral = sp.Integral(sp.expand(f / (z - zp) * sp.sin(phi)), (phi, phi1, sp.pi - phi1))
    rel = general.eq114_relative().subs(Cs, integral)
    return rel


def eq154() -> sp.Expr:
    """(154): the integral of :func:`harmonic_integral` done, z − z' = Q/K."""
    rel = harmonic_integral().doit()
    rel = sp.expand(sp.simplify(rel.subs(z, Q / K + zp)))
    return _double_angle(sp.expand(sp.expand_trig(rel)))


def _double_angle(expr: sp.Expr) -> sp.Expr:
    """sin φ1 cos φ1 → ½ sin 2φ1, sin²φ1 → ½(1 − cos 2φ1) (Haag's form)."""
    return sp.expand(expr.subs(sp.sin(phi1) ** 2, (1 - sp.cos(2 * phi1)) / 2)
                     .subs(sp.sin(phi1) * sp.cos(phi1), sp.sin(2 * phi1) / 2))


def i_of_j() -> sp.Expr:
    """n°45: i from (117) (derived) with i' = 0, wλ = −a1 (41): −j(a + wλ)/(a − vλ)."""
    j117 = clamping.eq117_j().subs(i_prime, 0)
    return sp.factor(sp.solve(sp.Eq(j_eq, j117), i_clamp)[0].subs(a1, -wl))


def eq155() -> sp.Expr:
    """(155): P = 4Q·[(154) + Cj²/Q] with i of (117), B = g_1 − AK (:func:`identity_AK_B`), j = −θ0 sin φ1
    (153); a + wλ − K(a − vλ) = Kz by K of (36) (derived, :func:`..ch1_model.K_of_z`), solved for wλ."""
    if identity_AK_B() != 0:
        raise ValueError("AK + B ≠ g_1")
    g1 = g_fn(1, eps_E(s))
    total = eq154() + C_j * j_eq**2 / Q
    total = total.subs(i_clamp, i_of_j()).subs(B_d, g1 - A_d * K)
    total = total.subs(j_eq, -theta0 * sp.sin(phi1))
    wl_of_z = sp.solve(sp.Eq(K, ch1_model.K_of_z()), wl)[0]
    P = _double_angle(sp.expand(sp.expand_trig(sp.expand(sp.simplify(4 * Q * total.subs(wl, wl_of_z))))))
    return sp.collect(P, [g1, C_j, A_d], func=sp.cancel)


def odd_part_155() -> sp.Expr:
    """n°45: the part of P odd in j (φ1 = asin(−j/θ0) odd in j): P(j) − P(−j) over 2, in φ1."""
    P = eq155()
    return sp.simplify((P - P.subs(phi1, -phi1)) / 2)
