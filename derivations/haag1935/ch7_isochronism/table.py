"""Haag 1935, chapter VII, n°92–93 and n°97, eqs. (281)–(284): the Results, joining derivation, print and truth."""
from __future__ import annotations

import sympy as sp

from pendsym import checks
from pendsym.result import Spec

from ..common import rid, src
from ..symbols import M_of_s, epsilon_of_s, w
from . import checks_isochronism as check, derivation, printed

EXACT = "symbolic proof (SymPy)"
_x = sp.Symbol("x", real=True)
# test functions under which forms holding w(s), ε(s), M(s) are compared (w' rises from 0 at s = 0)
INSTANCES = (((w, sp.Lambda(_x, _x**2 / 2 + _x**3 / 7 + sp.Rational(1, 3))), (epsilon_of_s, sp.Lambda(_x, 1 + _x)),
              (M_of_s, sp.Lambda(_x, 2 + _x))),)
LIMIT = (rid(257, "zp"), rid(260, "K"))
PROPORTIONAL = (rid(139, "g"), rid(45, "Q"), rid(260, "K_foci"), rid(262, "G"))
N97 = ("n°97 prints no formula: the id is on (284), the last number of n°93, whose Results this claim extends. ")


def specs() -> tuple[Spec, ...]:
    over_G = checks.Proof("the form is G times a factor of the blade alone (no ε, a, R, z, z', K, Q)",
                          holds=derivation.over_G_free, truth=EXACT)
    return (
        # ---------------------------------------------------------------- n°92
        Spec(rid(281, "f"), "f/(z − z') = −(n²/(ελ))(ε2w0 − ε3 − ε1θ∫ww'' ds − ∫εw'' ds)", src(92, "281"),
             r"\frac{f}{z - z'}", derivation.f_281,
             deps=(rid(104, "f"), rid(105, "parts"), rid(81, "F2G2"), rid(79, "G"), rid(9, "v"), rid(260, "K_foci"))
             + LIMIT, printed=printed.f_281, readings=(printed.READ_EPS_I,), instances=INSTANCES,
             check=checks.All(tuple(check.perturbation_order(kind) for kind in ("eps1", "eps2", "eps3", "stiffer"))),
             note="(104) with (105), Y = Kθ, a = a1 + ελ, K, z' of (257), (260) at ε → 0, F2 = wλ − G2 (81) and "
                  "w/M = w'' (9); −n²/(K(z − z')) = −n²/(ελ) by (260). Checked term by term on linear perturbations "
                  "(each moves only n² of the slow mode), ε·d log n²/dκ against ε·(−(f/(z − z'))/(n²θ))."),
        # ---------------------------------------------------------------- n°93
        Spec(rid(282, "Qp"), "Q' = a − F = F4 − wλ", src(93, None), "Q'", derivation.Qp_limit,
             deps=(rid(112, "Qp"),) + LIMIT, printed=printed.Qp_93, readings=(printed.READ_F1,),
             check=check.Qp_order(),
             note="(112) at a = a1 + ελ, K of (260), z' of (257), ε → 0; the intermediate a − F is (112) at K = 0 "
                  "(F = 4KF3 − F4 → −F4)."),
        Spec(rid(282, "F4"), "F4 = ∫w'^4 ds", src(93, "282"), "F_4", derivation.F4_282,
             deps=(rid(79, "F"), rid(11, "phi12")), printed=printed.F4_282, readings=(printed.READ_F1,),
             instances=INSTANCES, definition=True, check=checks.Definition(),
             note="(79) at K = 0, n = 4, φ2 = w' (11)."),
        Spec(rid(283, "dT"), "ΔT/T = −(θ0²/16)GC", src(93, "283"), r"\frac{\Delta T}{T}", derivation.dT_283,
             deps=(rid(111, "dT"), rid(260, "K_foci"), rid(262, "G"), rid(284, "C")) + LIMIT,
             printed=printed.dT_283, check=check.isochronism_order(), show_values=True,
             note="(111) at a = a1 + ελ, K = ελ/(z − z') (260) (Q = ελ), z' of (257), leading term in ε; then "
                  "G2 = ελG (262) and wλ − F4 = CG2 (284). Truth: the slow oscillation on the exact blade, θ0 = ε/10."),
        Spec(rid(284, "C"), "C = (wλ − F4)/G2", src(93, "284"), "C", derivation.C_284,
             deps=(rid(111, "dT"), rid(260, "K_foci"), rid(262, "G")) + LIMIT, printed=printed.C_284,
             readings=(printed.READ_OMEGA,), check=check.coefficient_order(),
             note="C = −16(ΔT/T)/(θ0²G) with the leading ΔT/T of (111) and G of (262)."),
        Spec(rid(284, "C_F2"), "C = (wλ − F4)/(wλ − F2)", src(93, "284"), "C", derivation.C_284_F2,
             deps=(rid(284, "C"), rid(81, "F2G2")), printed=printed.C_284_F2, readings=(printed.READ_OMEGA,),
             check=check.coefficient_order(), note="G2 = wλ − F2: (81) at K = 0."),
        Spec(rid(284, "C_integrals"), "C = (w0 + ∫w'(1 − w'²) ds)/(w0 + ∫w'(1 − w') ds) (printed)", src(93, "284"),
             "C", derivation.C_284_integrals, deps=(rid(284, "C_F2"), rid(79, "F"), rid(11, "phi12")),
             printed=printed.C_284_integrals, readings=(printed.READ_OMEGA, printed.READ_SQUARE),
             instances=INSTANCES, check=check.coefficient_order(),
             note="wλ = w0 + ∫w' ds and F_n = ∫w'^n ds in the second form: the numerator's integrand is "
                  "w' − w'^4 = w'(1 − w')(1 + w' + w'²), not the printed w'(1 − w'²). The printed form misses the "
                  "truth's C by ∫w'³(1 − w') ds/G2 (order 0 in ε); Haag's next line, C − 1 = ∫w'²(1 − w'²) ds/G2, "
                  "follows from the first forms, not from the printed third: a misprint or an OCR 2 for 3."),
        Spec(rid(284, "C_minus_one"), "C − 1 = ∫w'²(1 − w'²) ds/G2 > 0", src(93, None), "C - 1",
             derivation.C_minus_one, deps=(rid(284, "C"), rid(81, "F2G2"), rid(79, "F"), rid(11, "phi12")),
             printed=printed.C_minus_one, readings=(printed.READ_OMEGA,), instances=INSTANCES,
             check=checks.All((check.coefficient_order(minus_one=True),
                               checks.Proof("the integrand is ≥ 0 for 0 ≤ w' ≤ 1 (n°3): C > 1",
                                            holds=derivation.integrand_nonnegative, truth=EXACT))),
             note="(284) with wλ = F2 + G2 (81) at K = 0."),
        # ---------------------------------------------------------------- n°97
        Spec(rid(284, "law_G"), "n°97: (141) with K = 0 and Q = ελ is proportional to G", src(97, None),
             r"\frac{\Delta_q T}{T}", derivation.law_97, deps=(rid(141, "dT"),) + PROPORTIONAL,
             check=checks.All((check.law_order(), over_G)),
             note=N97 + "(139) at K = 0, Q = K(z − z') = ελ (45), (260), ελ = G2/G (262). Checked at q = 0 (a stiffer "
                        "blade) against the eigenproblem; q ≥ 1 would need the exact blade with the modified law."),
        Spec(rid(284, "friction_G"), "n°97: (147) with K = 0 and Q = ελ is proportional to G", src(97, None),
             r"\frac{\Delta T}{T}", derivation.friction_97, deps=(rid(147, "dT"),) + PROPORTIONAL, check=over_G,
             note=N97 + "\"Les mêmes observations s'appliquent aux formules (147) et (149)\": the symbolic "
                        "specialisation only (no truth of internal friction on the exact blade)."),
        Spec(rid(284, "damping_G"), "n°97: (149) with K = 0 and Q = ελ is proportional to G", src(97, None),
             r"\Delta\theta_0", derivation.damping_97, deps=(rid(149, "amplitude"),) + PROPORTIONAL, check=over_G,
             note=N97 + "The symbolic specialisation only, as for (147)."),
    )
