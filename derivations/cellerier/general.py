"""Cellérier p. 3–4: the general formulas for δ and α1 quoted from his earlier memoir (not in the file).

Rebuilt in :mod:`pendsym.finite_amplitude` by variation of constants on the
osculating α, φ.  The printed forms are the exact first-order forms with the
weights of the free motion (√(1 − sin²½α cos²φ) and the swing time 2K/ω0) at
their α → 0 values: exact to first order in μ' and to relative O(sin²½α).
The text breaks off at "en négligeant les termes de …".
"""
from __future__ import annotations

from functools import lru_cache

import mpmath as mp
import sympy as sp

from pendsym import finite_amplitude as fa
from pendsym import verify
from pendsym.result import Reading, Spec
from . import truth as tr
from .equation import MEMOIR, src
from .symbols import alpha, h, phi, u

U_TESTS = (sp.Lambda(phi, sp.cos(phi) + phi**2 / 5), sp.Lambda(phi, sp.sin(2 * phi) + sp.Rational(1, 3)))
U_INSTANCES = tuple(((u, lam),) for lam in U_TESTS)


def delta_printed() -> sp.Expr:
    return sp.Integral(u(phi) * sp.cos(phi), (phi, 0, sp.pi)) / (sp.pi * h)


def alpha1_printed() -> sp.Expr:
    return 2 / h * sp.Integral(u(phi) * sp.tan(alpha / 2) * sp.sin(phi), (phi, 0, sp.pi))


@lru_cache(maxsize=None)
def _first_order(key: str, alpha_val: str, dps: int = 30):
    with mp.workdps(dps):
        return fa.swing_first_order(tr.time_form(key, alpha_val), alpha_val, dps=dps)


def _exact_order_check(quantity: str, alphas=("2.0",)):
    """The exact first-order form (finite amplitude) against θ'' = −sin θ + εF: residual O(ε²)."""
    def run(level):
        evs = []
        for a in alphas:
            fo = _first_order("generic", a)
            key = 0 if quantity == "delta" else 1
            coef = fo["delta"] if quantity == "delta" else fo["alpha1"]
            evs.append(verify.order_check(
                param="epsilon", values=verify.geometric("1e-4", "1e-2", verify.LEVELS[level]),
                truth=lambda e, dps, a=a, key=key: tr.forced_swing("generic", a, mp.nstr(e, 40), dps)[key],
                derived=lambda e, coef=coef: e * coef, expected=2, band=0.3,
                truth_desc=f"θ'' = −sin θ + ε F, {tr.FORCING_TEXT}, α = {a} (mpmath odefun)",
                params=(("alpha", a),),
                note="exact first-order form of pendsym.finite_amplitude (weights at finite α)"))
        return evs
    return run


def _u_of_phi_timefree(a_sym=alpha) -> sp.Expr:
    """u(φ) for F = sin θ + 0.4 θ' + 0.3 sin θ cos θ along the free motion (ω0 = 1, h = 1)."""
    th = fa.free_angle(a_sym, phi)
    s, c, w = sp.expand_trig(sp.sin(th)), sp.expand_trig(sp.cos(th)), fa.free_speed(a_sym, phi, 1)
    F = s + sp.Rational(2, 5) * w + sp.Rational(3, 10) * s * c
    U = sp.Symbol("U")
    return sp.solve(sp.Eq(fa.forcing_of_u(U).subs({fa.w0: 1, h: 1}), F), U)[0]


def _leading_order_check(quantity: str):
    """The leading form (printed = derived) against the truth's first-order coefficient, vs α."""
    def run(result, level):
        uexpr = _u_of_phi_timefree()
        form = result.derived.subs(h, 1).replace(u, sp.Lambda(phi, uexpr.subs(alpha, sp.Symbol("A"))))
        form = form.subs(sp.Symbol("A"), alpha)
        f = sp.lambdify(alpha, form, "mpmath")
        key = 0 if quantity == "delta" else 1
        e = mp.mpf("1e-9")

        def coef(a, dps):
            sa = mp.nstr(a, 40)
            up = tr.forced_swing("timefree", sa, mp.nstr(e, 40), dps)[key]
            dn = tr.forced_swing("timefree", sa, mp.nstr(-e, 40), dps)[key]
            return (up - dn) / (2 * e)
        expected = 2 if quantity == "delta" else 3
        return verify.order_check(
            param="alpha", values=verify.geometric("0.03", "0.3", verify.LEVELS[level]),
            truth=coef, derived=lambda a: f(a), expected=expected, band=0.35,
            truth_desc="first-order coefficient of θ'' = −sin θ + εF, F = sin θ + 0.4θ' + 0.3 sin θ cos θ, "
                       "by a central difference ε = ±1e-9 of two mpmath odefun swings",
            note=f"leading form: relative error O(sin²½α), absolute O(α^{expected}) for u = O(1)")
    return run


def _delta_check(result, level):
    return verify.combine(_leading_order_check("delta")(result, level), *_exact_order_check("delta")(level))


def _alpha1_check(result, level):
    return verify.combine(_leading_order_check("alpha1")(result, level), *_exact_order_check("alpha1")(level))


def specs() -> tuple[Spec, ...]:
    P = MEMOIR
    quote = ("si l'on nomme δ l'accroissement relatif de la durée d'oscillation … et α1 la diminution de "
             "l'amplitude pendant une oscillation, on trouve: δ = 1/(πh) ∫_0^π u cos φ dφ, "
             "α1 = 2/h ∫_0^π u tang(a/4) sin φ dφ, en négligeant les termes de  (p. 3)")
    return (
        Spec(f"{P}.delta_general", "Relative lengthening δ of the swing for a perturbing moment μ'",
             src(quote), r"\delta", lambda d: fa.delta_leading(), printed=delta_printed,
             readings=(Reading("∂ = 1/(πħ) ∫ u cos φ dφ", "δ = 1/(πh) ∫_0^π u cos φ dφ"),),
             instances=U_INSTANCES, check=_delta_check,
             note=("Derived: exact first-order δ (pendsym.finite_amplitude.delta_exact: weight cos φ/(2K(κ²) D²) "
                   "plus an isochronism term) with the free-motion modulus κ → 0; exact to O(μ') and to relative "
                   "O(sin²½α). The check fits both: the exact form against ε (order 2, α = 0.1 and 2 rad) and "
                   "the printed form against α (order 2).")),
        Spec(f"{P}.alpha1_general", "Decrease α1 of the amplitude over one swing",
             src(quote), r"\alpha_1", lambda d: fa.alpha1_leading(), printed=alpha1_printed,
             readings=(Reading("tang(a/4)", "tang ½α: the text later says 'l'expression contient de plus "
                               "tang ½α comme facteur', and variation of constants gives tan(α/2)", certain=False),
                       Reading("2/ħ", "2/h")),
             instances=U_INSTANCES, check=_alpha1_check,
             note=("Exact first-order form: α1 = (2/h) tan(α/2) ∫_0^π u sin φ/√(1 − sin²½α cos²φ) dφ "
                   "(pendsym.finite_amplitude.alpha1_exact); the printed form drops the radical (κ → 0): "
                   "relative error O(sin²½α).")),
    )
