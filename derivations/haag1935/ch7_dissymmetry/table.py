"""Haag 1935, chapter VII, n°98–99, eqs. (295)–(301): the dissymmetric blade of the gravity pendulum, the Results.

n°99 (friction with the unbalance) is announced and not published by Haag: no formula, no claim, no Result.
"""
from __future__ import annotations

import sympy as sp

from pendsym import checks
from pendsym.result import Spec
from ..common import rid, src
from . import derivation, printed
from .checks_dissymmetry import MODEL, dT_order, gamma_order, j301_order, jmax_order, minimum_check, side_order
from .printed import DEFS_AB, READ_2PI, READ_300_G, READ_ALPHA_BETA, READ_EPS

EXACT = "symbolic proof (SymPy)"
J_MAX, EPS_300 = rid(297, "j_max"), rid(300, "eps")
SUM_DEPS = (rid(117, "j"), rid(260, "K_foci"), rid(155, "AK_B"), rid(154, "dT"), rid(134, "dT"), rid(132, "hp"),
            rid(262, "G"))
FROM_154 = ("(154) (derived) with i of (117) (of order ε, (290)), B = g1 − AK, K = ελ/(z − z') (260) → 0, "
            "Q = ελ, G2 = Gελ (262); plus (286) rebuilt here from (134), (132), (117) (derived) and the definition "
            "(284) of C (not from chapter VII's clamping package): −GCj²/4.")
TRUTH_SCOPE = (" The truth is the reduced one-degree-of-freedom equation (one-sided stiffness ε_E G, cubic GC/6, "
               "the clamping couple): independent of Haag's averaging, not of the reduction.")
MISSING_PI = ("Printed (2π − 1) where the derivation has 1: the line before (295) drops the 1/π of (154) in its "
              "last term −4j cos φ1/(πθ0); with it, (2π − 1)/π becomes 1/π. The memoir's (the factor recurs six "
              "times), not the OCR's.")


def _zero(expr) -> bool:
    return sp.simplify(expr) == 0


def _small_and_large(expr) -> bool:
    """(leading term of j_max/θ0 in x = ε_E/(Cθ0²), limit at fixed ε_E/θ0 as θ0 → 0): the first → 0 with x,
    the second is −1 (not small)."""
    x = sp.Symbol("x", positive=True)
    lead, fixed = expr
    return sp.limit(lead, x, 0) == 0 and fixed == -1


def specs() -> tuple[Spec, ...]:
    S = lambda eq: src(98, eq)    # noqa: E731
    return (
        Spec(rid(295, "sum"), "(4/G)ΔT/T = −Cj² + (g1/G2)(−1 + (2φ1 − sin 2φ1)/π − 4j cos φ1/(πθ0))", S(None),
             r"\frac{4}{G}\frac{\Delta T}{T}", derivation.eq295_sum, deps=SUM_DEPS, printed=printed.eq295_sum,
             readings=(READ_EPS, printed.READ_LINE_295), check=dT_order("-0.4", in_j=True),
             note=FROM_154 + " Printed −4j cos φ1/θ0: the 1/π of (154) is lost (the source of (2π − 1) below)."
                  + TRUTH_SCOPE),
        Spec(rid(295, "dT"), "ΔT/T of the dissymmetric blade with the unbalance j, in φ1", S("295"),
             r"\frac{\Delta T}{T}", derivation.eq295, deps=(rid(295, "sum"), rid(140, "g")), printed=printed.eq295,
             readings=(READ_EPS, READ_2PI),
             check=checks.All((dT_order("-0.4"), dT_order("0.5")),
                              truth=MODEL + ": ΔT/T(j, ε_E) − ΔT/T(0, 0), at j = −0.4θ0 and 0.5θ0"),
             note="j = −θ0 sin φ1 (153), g1 = ε_E G2 ((140), ε_E constant). " + MISSING_PI
                  + " Checked with the pendulum crossing to the soft side (j = −0.4θ0) and on the stiff side "
                    "(j = 0.5θ0)." + TRUTH_SCOPE),
        Spec(rid(296, "D"), "D = d[bracket of (295)]/dφ1", S(None), "D", derivation.eq296_D, deps=(rid(295, "dT"),),
             printed=printed.eq296_D, readings=(READ_EPS, READ_2PI), check=checks.Chain((J_MAX, EPS_300)),
             note="Derived D = 2 cos φ1[(2ε_E/π)cos φ1 − Cθ0² sin φ1]: it vanishes at φ1 = ±π/2 and at tan φ1 = "
                  "2ε_E/(πCθ0²)."),
        Spec(rid(296, "tan_alpha"), "tang α = 2ε(2π − 1)/(Cθ0²π)", S("296"), r"\tan\alpha", derivation.eq296,
             deps=(rid(296, "D"),), printed=printed.eq296, readings=(READ_EPS, READ_2PI),
             check=checks.Chain((J_MAX, EPS_300)),
             note="tan α = (coefficient of cos 2φ1)/(−coefficient of sin 2φ1) of D; derived 2ε_E/(πCθ0²)."),
        Spec(rid(296, "D_alpha"), "D = (Cθ0²/cos α)[sin α/(2π − 1) − sin(2φ1 − α)]", S(None), "D",
             derivation.eq296_D_alpha, deps=(rid(296, "D"),), printed=printed.eq296_D_alpha,
             readings=(READ_2PI,), check=checks.Chain((J_MAX, EPS_300)),
             note="Rewriting checked by SymPy at α = atan(tan α); derived bracket sin α − sin(2φ1 − α)."),
        Spec(rid(296, "sin_beta"), "sin β = sin α/(2π − 1)", S(None), r"\sin\beta", derivation.sin_beta,
             deps=(rid(296, "D_alpha"),), printed=printed.sin_beta, readings=(READ_2PI,),
             check=checks.Chain((J_MAX, EPS_300)),
             note="Derived sin β = sin α, β = α: Haag's roots (α + β)/2 and (α − β)/2 − π/2 of D become α and −π/2."),
        Spec(J_MAX, "ΔT/T is maximum at j = −θ0 sin((α + β)/2)", S("297"), "j", derivation.eq297,
             deps=(rid(295, "dT"), rid(296, "D")), printed=printed.eq297, defs=DEFS_AB,
             readings=(READ_EPS, READ_ALPHA_BETA, READ_2PI), check=jmax_order(),
             note="Roots of D by SymPy (factored in sin φ1, cos φ1, solved for tan φ1), mapped by (153); the only "
                  "stationary point in j, a maximum (d²/dj² < 0): j = −θ0 sin α, tan α = 2ε_E/(πCθ0²). The printed "
                  "form (α, β of the printed (296)) sits at about 1.4 times the truth's j for ε_E = θ0², C = 1.25."
                  + TRUTH_SCOPE),
        Spec(rid(298, "j_min"), "ΔT/T is minimum at j = θ0 cos((α − β)/2)", S("298"), "j", derivation.eq298,
             deps=(rid(295, "dT"), rid(296, "D")), printed=printed.eq298, defs=DEFS_AB,
             readings=(READ_EPS, READ_ALPHA_BETA, READ_2PI), check=minimum_check(),
             note="Derived: no stationary minimum; (295) falls from the maximum to the end of its range j = θ0 "
                  "(slope −GCθ0/2 there), where the whole swing is on the stiff side; beyond, T keeps falling "
                  "(−ε_E G/2 − GCj²/4). Haag's interior minimum is made by the (2π − 1): with it, D ≠ 0 at "
                  "φ1 = −π/2 and the printed (295) rises again near j = θ0. His remark that the minimum needs the "
                  "swing almost entirely on one side holds in the derived form as 'entirely'." + TRUTH_SCOPE),
        Spec(rid(298, "small_dissymmetry"), "ε small against θ0: (297) small against θ0, the maximum easy to reach",
             S(None), r"\left(\frac{j_{\max}}{\theta_0}\Big|_{\varepsilon = xC\theta_0^2},\ "
                      r"\lim_{\theta_0\to0}\frac{j_{\max}}{\theta_0}\Big|_{\varepsilon = x\theta_0}\right)",
             derivation.jmax_small_dissymmetry, deps=(J_MAX,), printed=None,
             check=checks.Proof("j_max/θ0 = −sin α → 0 as x = ε_E/(Cθ0²) → 0 (leading term −2x/π), but at a fixed "
                                "ratio ε_E/θ0 it tends to −1 as θ0 → 0", holds=_small_and_large, truth=EXACT),
             note="The claim holds when ε_E ≪ Cθ0² (tan α = 2ε_E/(πCθ0²)); 'ε small against θ0' is not enough. "
                  "The minimum's half of the claim: see (298)."),
        Spec(rid(298, "large_dissymmetry"), "a strong dissymmetry puts the maximum out of reach too", S(None),
             r"\lim \frac{j_{\max}}{\theta_0}", derivation.jmax_large_dissymmetry, deps=(J_MAX,), printed=None,
             check=checks.Proof("j_max/θ0 → −1 as ε_E/(Cθ0²) → ∞ (the swing then almost entirely on the soft side)",
                                holds=lambda e: sp.simplify(e + 1) == 0, truth=EXACT)),
        Spec(rid(298, "side"),
             "the larger modulus is on the side opposite to the shift of the equilibrium that makes T grow", S(None),
             r"\frac{d}{dj}\frac{\Delta T}{T}\Big|_{j=0}", derivation.slope_at_vertical,
             deps=(rid(295, "dT"),), printed=None, check=side_order(),
             note="Derived slope −ε_E G/(πθ0) at j = 0: opposite in sign to ε_E. (The printed (295) gives −ε_E G/θ0: "
                  "the same sign, so the claim stands either way.)" + TRUTH_SCOPE),
        Spec(rid(299, "gamma"), "sin γ = −j/θ0, γ in (−π/2, π/2)", S("299"), r"\theta_0\sin\gamma + j",
             lambda deps: derivation.eq299(), printed=printed.eq299, check=checks.Definition(), definition=True),
        Spec(rid(300, "relation"), "sin(2γ − α) = sin α/(2π − 1)", S(None), r"\sin(2\gamma - \alpha) - \sin\beta",
             derivation.eq300_relation, deps=(rid(296, "sin_beta"),), printed=printed.eq300_relation,
             readings=(READ_2PI,), check=checks.Chain((EPS_300,)),
             note="D = 0 at φ1 = γ in the second form of D; derived sin(2γ − α) = sin α, i.e. γ = α."),
        Spec(EPS_300, "ε = (Cπ/2)θ0² sin 2γ/(1 + (2π − 1)cos 2γ)", S("300"), r"\varepsilon", derivation.eq300,
             deps=(rid(296, "D"),), printed=printed.eq300, readings=(READ_EPS, READ_300_G, READ_2PI),
             check=gamma_order(),
             note="D(γ) = 0 solved for ε_E by SymPy: (π/2)Cθ0² tan γ (= the printed form with 1 for 2π − 1). "
                  + TRUTH_SCOPE),
        Spec(rid(301, "eps"), "ε = −(C/2)jθ0 for γ small", S("301"), r"\varepsilon", derivation.eq301,
             deps=(EPS_300,), printed=printed.eq301, readings=(READ_EPS,), check=j301_order(),
             note="(300) with γ = asin(−j/θ0), first term in j: −(π/2)Cjθ0; the printed form is off by the factor "
                  "π (1 + (2π − 1) = 2π in the printed (300)), consistent with the printed (300)." + TRUTH_SCOPE),
        Spec(rid(301, "free_of_G"), "the sense of variation of T with j does not depend on the sensitivity", S(None),
             r"\frac{\partial}{\partial G}\left(\frac{1}{G}\frac{\Delta T}{T}\right)", derivation.sense_free_of_G,
             deps=(rid(295, "dT"),), printed=None,
             check=checks.Proof("(295)/G is free of G (G > 0 a constant factor)", holds=_zero, truth=EXACT),
             note="Holds for the derived (295) as for the printed one; G also multiplies the perturbation's size "
                  "(Haag's 'amplifie énormément')."),
    )
