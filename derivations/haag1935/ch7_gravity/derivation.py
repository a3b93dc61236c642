"""Haag 1935, chapter VII, n°82–91: the gravity pendulum with direct suspension, derived step by step.

Everything starts from chapter I's model (:mod:`..ch1_model`: the quadratic (30) of the foci, K of (35),
(36)), chapter I's derived (45), (62), (82) and chapter III's derived (159), (166), (158), taken as
dependencies; the limit ε → 0 (a − a1 = ελ, (256)) is a SymPy series.  Chapter VII's naming (n°83) is
kept: z' is the root near w0 (the node of the slow mode), z the one near −R²/w0.
"""
from __future__ import annotations

import functools

import sympy as sp

from .. import ch1_model
from ..common import rid
from ..symbols import (E, Fn, G_2, K, M_lambda, R, W_over_mg, a, a1, beta1, e, g, h, lam, m, s, theta, u, v0, vl, w0,
                      wl, z, zp)
from .symbols import a_r, eps, eps_p, l_syn

# (16): w0 = vλ + wλ; (17): β1 = λ + vλ − v0; (256): a = a1 + ελ with a1 = −wλ (41)
ENDS = {v0: lam + vl - beta1}
NEAR_CRITICAL = {a: -wl + eps * lam}


def derived_of(deps, eq: int, name: str) -> sp.Expr:
    return deps[rid(eq, name)].derived


# ---------------------------------------------------------------- n°82: (255)
def Q_255(deps) -> sp.Expr:
    """(255): Q = K(z − z') (45) with K of (36), z' = −R²/z (31) and wλ = −a1 (41)."""
    expr = derived_of(deps, 45, "Q").subs(K, ch1_model.K_of_z()).subs(zp, -R**2 / z).subs(wl, -a1)
    return sp.factor(sp.cancel(expr))


# ---------------------------------------------------------------- n°83: (257)–(261)
@functools.lru_cache(maxsize=1)
def foci_near_critical() -> sp.Expr:
    """The quadratic (30) of the foci at a = a1 + ελ (256), with v0 by (17) and wλ = w0 − vλ (16)."""
    quadratic = ch1_model.foci_quadratic().as_expr()
    return sp.together(quadratic.subs(NEAR_CRITICAL).subs(ENDS).subs(wl, w0 - vl))


@functools.lru_cache(maxsize=2)
def root_series(z_at_zero: sp.Expr) -> sp.Expr:
    """The root of (30) that tends to ``z_at_zero`` as ε → 0, to first order: z0 − ε ∂_εP/∂_zP (n°83).
    Raises when z_at_zero is not a root at ε = 0."""
    poly = sp.numer(foci_near_critical())
    if sp.simplify(poly.subs({eps: 0, z: z_at_zero})) != 0:
        raise ValueError(f"{z_at_zero} is not a root of (30) at ε = 0")
    slope = -(sp.diff(poly, eps) / sp.diff(poly, z)).subs({eps: 0, z: z_at_zero})
    return z_at_zero + sp.factor(sp.simplify(slope)) * eps


def zp_257(_deps) -> sp.Expr:
    """(257): z' = w0(1 + ε'), the root of (30) near w0 (one side of (33) vanishes at ε = 0)."""
    return root_series(w0)


def epsilon_prime_258(_deps) -> sp.Expr:
    """(258): ε' = (z' − w0)/w0 to first order in ε."""
    return sp.factor(sp.expand((root_series(w0) - w0) / w0))


def epsilon_prime_258_ends(deps) -> sp.Expr:
    """(258), second form: the first with β1 = λ + vλ − v0 (17) and vλ = w0 − wλ (16), over w0."""
    expr = derived_of(deps, 258, "epsilon_prime").subs(beta1, lam + vl - v0).subs(vl, w0 - wl)
    return sp.factor(expr)


def z_259(_deps) -> sp.Expr:
    """(259): z, the root of (30) near −R²/w0, to first order in ε, written with ε' of (258)."""
    lower = root_series(-R**2 / w0)
    ratio = sp.simplify((lower + R**2 / w0) / (-R**2 / w0) / ((root_series(w0) - w0) / w0))
    return -R**2 / w0 * (1 + ratio * eps_p)


def K_260(_deps) -> sp.Expr:
    """(260): K of (36) at a = a1 + ελ, z → −R²/w0: its leading term in ε."""
    K36 = ch1_model.K_of_z().subs(NEAR_CRITICAL).subs(wl, w0 - vl).subs(z, root_series(-R**2 / w0))
    return sp.factor(sp.series(K36, eps, 0, 2).removeO())


def K_260_foci(deps) -> sp.Expr:
    """(260), second form: the denominator −(w0² + R²)/w0 of the first is z − z' at ε = 0 (257), (259)."""
    first = derived_of(deps, 260, "K")
    gap = sp.simplify((root_series(-R**2 / w0) - root_series(w0)).subs(eps, 0))
    assert sp.simplify(first - eps * lam / gap) == 0
    return eps * lam / (z - zp)


def Kp_261(deps) -> sp.Expr:
    """(261): K' from KK' = −(a + wλ)/β1 (37) with a + wλ = ελ (256) and K = ελ/(z − z') (260)."""
    return sp.simplify(-eps * lam / (beta1 * derived_of(deps, 260, "K_foci")))


# ---------------------------------------------------------------- n°84–85: (262)–(264)
def G_262(deps) -> sp.Expr:
    """(262): G = −1 + G2/Q (62), Q = a + wλ + K²β1 with a + wλ = ελ and K of (260): the principal part in ε."""
    G62 = derived_of(deps, 62, "G").subs(a, -wl + eps * lam).subs(K, derived_of(deps, 260, "K"))
    return sp.factor(sp.limit(sp.simplify(G62 * eps), eps, 0) / eps)


def G_262_energy(deps) -> sp.Expr:
    """(262), second form: G2 = 2W/(mg) for θ = 1 (63)."""
    return derived_of(deps, 262, "G").subs(G_2, 2 * W_over_mg)


def G_263(deps) -> sp.Expr:
    """(263): G2 = λΓ2 ((163), n = 2) for the uniform blade, k = K(1 − K) → 0 with K (260)."""
    Gamma2 = derived_of(deps, 166, "Gamma2")
    k_symbol, = [x for x in Gamma2.free_symbols if x.name == "k"]
    return sp.simplify(derived_of(deps, 262, "G").subs(G_2, lam * Gamma2.subs(k_symbol, 0)))


def G_264(deps) -> sp.Expr:
    """(264): the leading term of (263) as u → 0."""
    return sp.series(derived_of(deps, 263, "G"), u, 0, 0).removeO()


def G_264_distance(deps) -> sp.Expr:
    """(264), second form: λ/u² is −a1 to leading order (a1 = −wλ, (159)), a ≈ a1, ελ = a − a1."""
    lead = sp.series(derived_of(deps, 159, "wl"), u, 0, 0).removeO()           # λ/u² = −a1 to leading order
    assert sp.simplify(derived_of(deps, 264, "G") - lead / (eps * lam)) == 0     # (264) = (λ/u²)/(ελ)
    # λ/u² → −a1 → −a (a = a1 + ελ, ελ ≪ |a1|), ελ = a − a1
    return -a_r / (a_r - a1)


# ---------------------------------------------------------------- n°86: (265)–(268)
def n2_265(deps) -> sp.Expr:
    """(265): n² = −Kg/z' (34) with K of (260) and z' of (257), leading term in ε."""
    n2 = -derived_of(deps, 260, "K") * g / root_series(w0)
    return sp.factor(sp.series(n2, eps, 0, 2).removeO())


def n2p_266(deps) -> sp.Expr:
    """(266): n'² = −K'g/z (34) for the other focus, K' of (261), z, z' at ε = 0 ((257), (259))."""
    zero = {z: -R**2 / w0, zp: w0}
    return sp.factor(sp.simplify(-derived_of(deps, 261, "Kp").subs(zero) * g / zero[z]))


def n2_267_distance(deps) -> sp.Expr:
    """(267), first form: u → 0 in (265): w0 = λ/(u sh u) (159) and a = a1 + ελ → −λ/u² share their
    leading term, so w0² → a²."""
    w0_lead = sp.series(derived_of(deps, 159, "w0"), u, 0, 0).removeO()
    a_lead = -sp.series(derived_of(deps, 159, "wl"), u, 0, 0).removeO()
    assert sp.simplify(w0_lead + a_lead) == 0
    return derived_of(deps, 265, "n2").subs(w0, -a_r)


def n2_267_synchronous(deps) -> sp.Expr:
    """(267), second form: R² + a² = al, l the synchronous length (n°68)."""
    return derived_of(deps, 267, "n2").subs(R**2, a_r * l_syn - a_r**2)


def n2_267_expanded(deps) -> sp.Expr:
    """(267), third form: ελ = a − a1 with a1 = −wλ (159) expanded to O(1) as u → 0: −λ/u² − λ/3."""
    a1_series = -sp.series(derived_of(deps, 159, "wl"), u, 0, 1).removeO()
    second = derived_of(deps, 267, "n2_l").subs(eps, (a_r - a1_series) / lam)
    return sp.expand(second)


def period_268(deps) -> sp.Expr:
    """(268): π²/T² = n² (T = π/n) with (267) and gλ/u² = gM/λ = EI/(mλ), I = e³h/12 (156), mg = m·g."""
    expr = derived_of(deps, 267, "n2_expanded")
    return sp.expand(expr.subs(u, lam * sp.sqrt(m * g / (E * e**3 * h / 12))))


# ---------------------------------------------------------------- n°91: suppleness
def S_91(deps) -> sp.Expr:
    """n°91: S of (82), G2 (the symbol G(2)) finite, a + wλ = ελ and K of (260), as ε → 0."""
    S82 = derived_of(deps, 82, "S").subs(a, -wl + eps * lam).subs(K, derived_of(deps, 260, "K"))
    return sp.limit(sp.simplify(S82), eps, 0)


# ---------------------------------------------------------------- n°93: (285)
def C_of_phi2(C_form: sp.Expr, phi2: sp.Expr, wl_value: sp.Expr) -> sp.Expr:
    """(285): the derived C of (284) in wλ, F2, F4, with F_n = ∫_0^λ φ2^n ds (79) at K = 0 and wλ (159).

    φ2 and wλ in exponentials of u (158), (159): with p = e^{us/λ} (ds = λ dp/(up)) and q = e^u the integrals
    are of rational functions of p; the result is rational in e^u and u."""
    p, q = sp.symbols("p q", positive=True)
    f = sp.expand(sp.expand_power_exp(sp.powsimp(phi2.subs(s, lam * sp.log(p) / u), force=True))).subs(sp.exp(u), q)
    F = {n: (lam / u * sp.integrate(sp.cancel(f**n / p), (p, 1, q))).subs(sp.log(q), u) for n in (2, 4)}
    w_q = sp.cancel(sp.expand(wl_value.rewrite(sp.exp)).subs(sp.exp(u), q))
    return sp.factor(sp.cancel(C_form.subs({Fn(2): F[2], Fn(4): F[4], wl: w_q}))).subs(q, sp.exp(u))


def C_285(deps) -> sp.Expr:
    """(285): C of (284) (its second form, (wλ − F4)/(wλ − F2)) for the uniform blade, φ2 of (158), wλ of (159)."""
    return C_of_phi2(derived_of(deps, 284, "C_F2"), derived_of(deps, 158, "phi2"), derived_of(deps, 159, "wl"))


def C_285_same(deps) -> sp.Expr:
    """(285), second form: the same C (the printed forms differ only by their writing)."""
    return derived_of(deps, 285, "C")



# ---------------------------------------------------------------- n°87: (270)–(273)
def dT_270(deps) -> sp.Expr:
    """(270): (60) at a = a1 + ελ, K of (260): the principal part in ε."""
    expr = derived_of(deps, 60, "dT").subs(a, -wl + eps * lam).subs(K, derived_of(deps, 260, "K"))
    return sp.factor(sp.limit(sp.simplify(expr * eps), eps, 0)) / eps


def dg_271(deps) -> sp.Expr:
    """(271): dg/g = −(2/G) dT/T (61) with (270) and G of (262)."""
    return sp.expand(sp.simplify(-2 * derived_of(deps, 270, "dT") / derived_of(deps, 262, "G")))


def dg_272(deps) -> sp.Expr:
    """(272): (271) for the uniform blade: G2 = λΓ2(k = 0) ((163), (166)), wλ of (159), M_λ = λ²/u² (156);
    th u = 2t/(1 + t²) with t = th(u/2), so that the form is rational in t and u (as chapter III writes)."""
    Gamma2 = derived_of(deps, 166, "Gamma2")
    k_symbol, = [x for x in Gamma2.free_symbols if x.name == "k"]
    expr = derived_of(deps, 271, "dg").subs({G_2: lam * Gamma2.subs(k_symbol, 0), wl: derived_of(deps, 159, "wl"),
                                             M_lambda: lam**2 / u**2})
    half = sp.Symbol("t", positive=True)
    expr = expr.subs(sp.tanh(u), 2 * sp.tanh(u / 2) / (1 + sp.tanh(u / 2) ** 2)).subs(sp.tanh(u / 2), half)
    return sp.cancel(sp.together(expr)).subs(half, sp.tanh(u / 2))


def dg_273(deps) -> sp.Expr:
    """(273): (272) as u → 0."""
    return sp.limit(derived_of(deps, 272, "dg"), u, 0)


# ---------------------------------------------------------------- n°89–90: (277)–(280)
def shape_278(deps) -> sp.Expr:
    """(278): ωy with y = θ(w − w0) ((77) with Y = Kθ → 0, n°89), w of (157), ω = u/λ (156)."""
    w_uniform = derived_of(deps, 157, "w")
    return sp.simplify((u / lam * theta * (w_uniform - w_uniform.subs(s, 0))).rewrite(sp.cosh))


def fatigue_280(deps) -> sp.Expr:
    """(280): the bending stress E(e/2)φ' (78) with φ' = θw/M ((14), Y → 0), w of (157), M = λ²/u² (156)."""
    return sp.simplify((E * e / 2 * theta * derived_of(deps, 157, "w") * u**2 / lam**2).rewrite(sp.cosh))
