"""Cellérier, the general formulas for δ and α1 quoted from his earlier memoir (not in the file),
under « Cette équation coïncide avec celle qui se trouve au § 4 d'un mémoire sur le pendule … ».

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

from pendsym import checks, finite_amplitude, verify
from pendsym.result import Reading, Spec
from . import truth
from .common import DPS, Geometric, rid, src
from .symbols import alpha, h, phi, u

U_TESTS = (sp.Lambda(phi, sp.cos(phi) + phi**2 / 5), sp.Lambda(phi, sp.sin(2 * phi) + sp.Rational(1, 3)))
U_INSTANCES = tuple(((u, lam),) for lam in U_TESTS)
QUOTE = ("si l'on nomme δ l'accroissement relatif de la durée d'oscillation … et α1 la diminution de "
         "l'amplitude pendant une oscillation, on trouve: δ = 1/(πh) ∫_0^π u cos φ dφ, "
         "α1 = 2/h ∫_0^π u tang(a/4) sin φ dφ, en négligeant les termes de")


# ----------------------------------------------------------------- printed
def delta_printed() -> sp.Expr:
    return sp.Integral(u(phi) * sp.cos(phi), (phi, 0, sp.pi)) / (sp.pi * h)


def alpha1_printed() -> sp.Expr:
    return 2 / h * sp.Integral(u(phi) * sp.tan(alpha / 2) * sp.sin(phi), (phi, 0, sp.pi))


# ----------------------------------------------------------------- checks: θ'' = −sin θ + εF integrated
@lru_cache(maxsize=None)
def first_order(key: str, alpha_val: str, dps: int = DPS):
    """The exact first-order δ, α1 of the test forcing ``key`` at amplitude α (finite_amplitude)."""
    with mp.workdps(dps):
        return finite_amplitude.swing_first_order(truth.time_form(key, alpha_val), alpha_val, dps=dps)


def exact_order_check(quantity: str, alpha_val: str = "2.0"):
    """The exact first-order form (finite amplitude) against θ'' = −sin θ + εF: residual O(ε²)."""
    def check(result, level):
        coefficient = first_order("generic", alpha_val)["delta" if quantity == "delta" else "alpha1"]
        which = 0 if quantity == "delta" else 1
        return verify.order_check(
            param="epsilon", values=Geometric("1e-4", "1e-2")(level),
            truth=lambda e, dps: truth.forced_swing("generic", alpha_val, mp.nstr(e, 40), dps)[which],
            derived=lambda e: e * coefficient, expected=2, band=0.3,
            truth_desc=f"θ'' = −sin θ + ε F, {truth.FORCING_TEXT}, α = {alpha_val} (mpmath odefun)",
            params=(("alpha", alpha_val),),
            note="exact first-order form of pendsym.finite_amplitude (weights at finite α)")
    return check


def u_of_phi_timefree(amplitude=alpha) -> sp.Expr:
    """u(φ) for F = sin θ + 0.4 θ' + 0.3 sin θ cos θ along the free motion (ω0 = 1, h = 1)."""
    th = finite_amplitude.free_angle(amplitude, phi)
    s, c = sp.expand_trig(sp.sin(th)), sp.expand_trig(sp.cos(th))
    F = s + sp.Rational(2, 5) * finite_amplitude.free_speed(amplitude, phi, 1) + sp.Rational(3, 10) * s * c
    U = sp.Symbol("U")
    return sp.solve(sp.Eq(finite_amplitude.forcing_of_u(U).subs({finite_amplitude.w0: 1, h: 1}), F), U)[0]


def leading_order_check(quantity: str):
    """The leading form (printed = derived) against the truth's first-order coefficient, vs α."""
    def check(result, level):
        A = sp.Symbol("A")
        form = result.derived.subs(h, 1).replace(u, sp.Lambda(phi, u_of_phi_timefree().subs(alpha, A)))
        f = sp.lambdify(alpha, form.subs(A, alpha), "mpmath")
        which = 0 if quantity == "delta" else 1
        e = mp.mpf("1e-9")

        def coefficient(a, dps):
            sa = mp.nstr(a, 40)
            up = truth.forced_swing("timefree", sa, mp.nstr(e, 40), dps)[which]
            down = truth.forced_swing("timefree", sa, mp.nstr(-e, 40), dps)[which]
            return (up - down) / (2 * e)
        expected = 2 if quantity == "delta" else 3
        return verify.order_check(
            param="alpha", values=Geometric("0.03", "0.3")(level), truth=coefficient, derived=lambda a: f(a),
            expected=expected, band=0.35,
            truth_desc="first-order coefficient of θ'' = −sin θ + εF, F = sin θ + 0.4θ' + 0.3 sin θ cos θ, "
                       "by a central difference ε = ±1e-9 of two mpmath odefun swings",
            note=f"leading form: relative error O(sin²½α), absolute O(α^{expected}) for u = O(1)")
    return check


# ----------------------------------------------------------------- the Result table
def specs() -> tuple[Spec, ...]:
    return (
        Spec(rid("delta_general"), "Relative lengthening δ of the swing for a perturbing moment μ'",
             src("earlier_memoir", QUOTE), r"\delta", lambda d: finite_amplitude.delta_leading(),
             printed=delta_printed, readings=(Reading("∂ = 1/(πħ) ∫ u cos φ dφ", "δ = 1/(πh) ∫_0^π u cos φ dφ"),),
             instances=U_INSTANCES,
             check=checks.All((leading_order_check("delta"), exact_order_check("delta"))),
             note=("Derived: exact first-order δ (pendsym.finite_amplitude.delta_exact: weight cos φ/(2K(κ²) D²) "
                   "plus an isochronism term) with the free-motion modulus κ → 0; exact to O(μ') and to relative "
                   "O(sin²½α). The check fits both: the exact form against ε (order 2, α = 2 rad) and "
                   "the printed form against α (order 2).")),
        Spec(rid("alpha1_general"), "Decrease α1 of the amplitude over one swing",
             src("earlier_memoir", QUOTE), r"\alpha_1", lambda d: finite_amplitude.alpha1_leading(),
             printed=alpha1_printed,
             readings=(Reading("tang(a/4)", "tang ½α: the text later says 'l'expression contient de plus "
                               "tang ½α comme facteur', and variation of constants gives tan(α/2)", certain=False),
                       Reading("2/ħ", "2/h")),
             instances=U_INSTANCES,
             check=checks.All((leading_order_check("alpha1"), exact_order_check("alpha1"))),
             note=("Exact first-order form: α1 = (2/h) tan(α/2) ∫_0^π u sin φ/√(1 − sin²½α cos²φ) dφ "
                   "(pendsym.finite_amplitude.alpha1_exact); the printed form drops the radical (κ → 0): "
                   "relative error O(sin²½α).")),
    )
