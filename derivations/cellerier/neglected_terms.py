"""Cellérier, the terms the leading substitutions neglect (« On voit qu'en ne conservant dans le
calcul que les termes principaux … »): δ at finite amplitude and the change α1 of the amplitude,
both to first order in K, for the static support y1 = KQ.

The forcing of the support is exact in α here: y1'' = K d²Q/dt² along the free swing,
with Q = Q(θ, θ'), and δ, α1 are the exact first-order forms of pendsym.finite_amplitude.
"""
from __future__ import annotations

from functools import lru_cache

import mpmath as mp
import sympy as sp

from pendsym import checks, finite_amplitude, verify
from pendsym.result import Spec
from . import truth
from .common import DPS, H_TRUTH, printed, proof_of, rid, src
from .pressures import reduced
from .static_support import KS, mu_prime_with, static_truth_text, u_of_mu
from .symbols import K, alpha, g, h, l, m, phi, theta, thetad, thetadd, u
from .truth import cos_th, sin_th, w_th      # sin θ, cos θ, θ' of the truth's state



# ----------------------------------------------------------------- derivation
@lru_cache(maxsize=None)
def support_forcing() -> sp.Expr:
    """f = μ'/(mhl) = −cos θ y1''/l with y1'' = K d²Q/dt² along the free flow, Q = Q(θ, θ') (exact in α).

    In the symbols (sin θ, cos θ, θ') of the truth module: Q = mh(θ'² sin θ − θ'' cos θ) with
    θ'' = −(g/l) sin θ, differentiated twice along the free flow.
    """
    angle = sp.Symbol("TH")
    Q = reduced(1).subs({theta: angle})
    Q = Q.subs(thetadd, -g / l * sp.sin(angle)).subs(thetad, w_th).subs({sp.sin(angle): sin_th, sp.cos(angle): cos_th})
    acceleration = -g / l * sin_th
    y1_accel = K * truth.lie_derivative(truth.lie_derivative(Q, acceleration), acceleration)
    return sp.expand(-cos_th * y1_accel / l)


def forcing_numeric(hh: str):
    f = sp.lambdify((sin_th, cos_th, w_th), support_forcing().subs({K: 1, m: 1, g: 1, l: 1, h: sp.Rational(hh)}), "mpmath")
    return lambda s, c, w, t: f(s, c, w)


@lru_cache(maxsize=None)
def first_order_support(alpha_val: str, hh: str = H_TRUTH) -> dict:
    """Exact first-order δ, α1 per unit K for the static support (pendsym.finite_amplitude)."""
    return finite_amplitude.swing_first_order(forcing_numeric(hh), alpha_val, 1, hh, dps=DPS)


def u_of_support() -> sp.Expr:
    """u(φ) of the support forcing along the free swing (exact in α)."""
    w0 = sp.sqrt(g / l)
    angle = finite_amplitude.free_angle()
    along = support_forcing().subs({sin_th: sp.expand_trig(sp.sin(angle)), cos_th: sp.expand_trig(sp.cos(angle)),
                                    w_th: finite_amplitude.free_speed(alpha, phi, w0)})
    U = sp.Symbol("U")
    return sp.solve(sp.Eq(finite_amplitude.forcing_of_u(U).subs(finite_amplitude.w0, w0), along), U)[0]


def delta_static_finite_derived(deps) -> sp.Expr:
    """δ exact in α, first order in K: finite_amplitude.delta_exact with u of the static support."""
    return finite_amplitude.delta_exact().replace(u, sp.Lambda(phi, u_of_support())).subs(
        finite_amplitude.w0, sp.sqrt(g / l))


def alpha1_leading_derived(deps) -> sp.Expr:
    """α1 with the same leading substitutions as δ: ∝ ∫ cos φ sin φ dφ = 0."""
    mu = mu_prime_with(deps, 0, deps[rid("y1dd")].derived).subs(sp.cos(theta), 1)
    general = deps[rid("alpha1_general")].derived
    return sp.simplify(general.replace(u, sp.Lambda(phi, u_of_mu(mu))).doit())


def alpha1_static_derived(_deps) -> sp.Expr:
    """α1 at first order in K, exact in α: the integrand is odd about φ = π/2, so α1 = 0.

    u(π − φ) = −u(φ) because Q is odd in θ, even in θ', and θ(π − φ) = −θ(φ),
    θ'(π − φ) = θ'(φ); the weight sin φ/√(1 − κ² cos²φ) is even.  Checked by SymPy.
    """
    density = finite_amplitude.first_order_densities()["dalpha"].subs(finite_amplitude.kappa, sp.sin(alpha / 2))
    integrand = density.replace(u, sp.Lambda(phi, u_of_support()))
    if sp.simplify(sp.expand_trig(integrand.subs(phi, sp.pi - phi) + integrand)) != 0:
        raise ValueError("the α1 integrand is not odd about π/2")
    return sp.S.Zero


# ----------------------------------------------------------------- checks
def delta_finite_check(result, level):
    """α = 1 rad: the exact first-order δ (finite_amplitude) per unit K against the integrated model."""
    coefficient = first_order_support("1.0")["delta"]
    return verify.order_check(
        param="K", values=KS(level),
        truth=lambda k, dps: truth.delta_measured("1.0", mp.nstr(k, 40), "0", dps, h_val=H_TRUTH),
        derived=lambda k: k * coefficient, expected=2, band=0.3, truth_desc=static_truth_text("1.0"),
        params=(("alpha", "1.0"), ("h/l", H_TRUTH)),
        note="α = 1 rad: exact first-order δ (finite_amplitude) has residual O(K²); "
             "Kmgh/(2l²) alone is off by a relative O(α²)")


ALPHA1_STATIC_CHECK = checks.Order(
    param="K", values=KS, truth=lambda k, dps: truth.amplitude_change("1.0", mp.nstr(k, 40), "0", dps, h_val=H_TRUTH),
    at=lambda expr, k: verify.value_at(expr, {"K": k}), expected=3, band=0.4,
    truth_desc="the same pendulum on a spring, α = 1 rad: |θ(T)| − α over one swing (mpmath odefun)",
    params=(("alpha", "1.0"),),
    note=("No O(K) (nor O(K²)) change of amplitude: the quasi-static motion is reversible; the O(K³) "
          "left is the support vibration excited by the truncated (O(K²)) slow-manifold start."))


# ----------------------------------------------------------------- the Result table
def specs() -> tuple[Spec, ...]:
    return (
        Spec(rid("delta_static_finite"), "δ at finite amplitude, first order in K (not in the memoir)",
             src("principal_terms", "l'influence des termes négligés, qui par rapport à ceux-là sont de l'ordre de θ², "
                 "est tout à fait insignifiante"), r"\delta", delta_static_finite_derived, check=delta_finite_check,
             note="pendsym.finite_amplitude.delta_exact with u of the static support; equals Kmgh/(2l²)(1 + O(α²))."),
        Spec(rid("alpha1_leading"), "The leading term of α1 vanishes",
             src("principal_terms", "l'intégrale serait remplacée par ∫_0^π cos φ sin φ dφ ou 0"), r"\alpha_1",
             alpha1_leading_derived, deps=(rid("alpha1_general"), rid("mu_prime"), rid("y1dd")),
             printed=printed(sp.S.Zero), check=proof_of(0)),
        Spec(rid("alpha1_static"), "α1 at first order in K, exact in α (the surviving terms)",
             src("principal_terms", "les termes négligés subsisteraient seuls, et l'expression contient de plus "
                 "tang ½α comme facteur"), r"\alpha_1", alpha1_static_derived, check=ALPHA1_STATIC_CHECK,
             note=("The text expects surviving terms of relative order θ² (α1 = O(Kα³)); in fact the whole "
                   "first-order integrand is odd about φ = π/2, so α1 = 0 at O(K) for every α; the "
                   "integrated model shows no change below O(K³).")),
    )
