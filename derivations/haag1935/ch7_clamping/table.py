"""Haag 1935, chapter VII, n°94–95, eqs. (286)–(290): the clamping errors of the gravity pendulum, the Results."""
from __future__ import annotations

from pendsym import checks
from pendsym.result import Spec

from ..common import READ_VW, rid, src
from ..symbols import DEFS
from . import derivation, printed, truth
from .truth import DIRECT, LOOSE, REGULATED

NEAR = (rid(260, "K"), rid(257, "zp"))
TO_A1 = (rid(256, "epsilon"), rid(41, "a1"))
Q_DEPS = (rid(45, "Q"), rid(260, "K_foci"))
PERIOD_286, PERIOD_288 = rid(286, "dT"), rid(288, "dT")
EXACT = "symbolic proof (SymPy)"
LEADING = ("The limit ε → 0 is a SymPy series after K (260) and z' (257) are put in chapter II's derived form; a kept, "
           "as Haag keeps it (a = a1 + ελ → −wλ in the next step).")


def specs() -> tuple[Spec, ...]:
    return (
        # ------------------------------------------------------------ n°94
        Spec(rid(286, "tilt_G"), "n°94: the tilt of the equilibrium is about proportional to G", src(94, None), "j'",
             derivation.tilt_G, deps=(rid(118, "j_prime"), rid(262, "G"), rid(256, "epsilon")),
             check=truth.tilt_order(),
             note="Haag's claim in words ('l'écart du pendule avec la verticale … est approximativement proportionnel au "
                  "coefficient de sensibilité', from (118)): (118) with a − a1 = ελ = G2/G (262), j' = G(w0 i − ai')/G2. "
                  "Listed under (286), whose premise it is (j holds the factor 1/ε). Against the exact tilted "
                  "equilibrium with G of the truth (stencil in g)."),
        # ------------------------------------------------------------ n°95, not regulated
        Spec(rid(286, "Q1"), "Q1 = j²(a + F_4)/4, the pendulum not regulated", src(95, None), "Q_1",
             derivation.Q1_286, deps=(rid(133, "Q1"), rid(127, "h"), rid(132, "hp")) + NEAR,
             printed=printed.Q1_286, readings=(printed.READ_F1,), check=checks.Chain((PERIOD_286,)),
             note="(133) with j = ĵ/ε ((117): j holds 1/ε), its leading term ε^{-2}; h (127), h' (132) in moments, "
                  "F_4 at K = 0. " + LEADING),
        Spec(rid(286, "Q1_C"), "Q1 = −(j²/4)CG2", src(95, None), "Q_1", derivation.Q1_286_C,
             deps=(rid(286, "Q1"),) + TO_A1, printed=printed.Q1_286_C, check=checks.Chain((PERIOD_286,)),
             note="a = a1 + ελ, a1 = −wλ (41), the leading term kept, and C = (wλ − F_4)/G2 (284)."),
        Spec(PERIOD_286, "ΔT/T = −(j²/4)GC, the pendulum not regulated", src(95, "286"), r"\frac{\Delta T}{T}",
             derivation.dT_286, deps=(rid(286, "Q1_C"), rid(262, "G")) + Q_DEPS, printed=printed.dT_286,
             check=truth.period_order(DIRECT, 1, LOOSE, "G of the truth (stencil in g), C = (wλ − F_4)/G2 (284) by "
                                      "quadrature, j = the exact θ", sensitivity=True),
             note="Q1/Q (134), Q = K(z − z') = ελ (260), G2 = ελG (262). An advance ∝ G³ (j ∝ G)."),
        # ------------------------------------------------------------ n°95, regulated
        Spec(rid(287, "hp"), "h' = 12A_0j² − 6A_1ij + 2A_2i², F = ΣA_pK^p", src(95, "287"), "h'",
             derivation.hp_287, deps=(rid(132, "hp"),), printed=printed.hp_287, readings=(printed.READ_PI,),
             check=checks.Chain((PERIOD_288,)),
             note="(132) at K = 0 (K → 0 with ε), its moments rewritten in the coefficients A_p of F = 4KF_3 − F_4 "
                  "(110) (the derivation raises if a moment is left over)."),
        Spec(rid(288, "Q1"), "4Q1 = a(i + i' + j)² + i²F_2 − h'/12, the pendulum regulated", src(95, None), "4Q_1",
             derivation.Q1_288, deps=(rid(133, "Q1"), rid(127, "h")) + NEAR, printed=printed.Q1_288,
             check=checks.Chain((PERIOD_288,)),
             note="(133) with i, i', j of one order: its leading term ε^0; h (127) in moments, h' and F_2 at K = 0. "
                  + LEADING),
        Spec(PERIOD_288, "ΔT/T of the clamping errors, the pendulum regulated", src(95, "288"), r"\frac{\Delta T}{T}",
             derivation.dT_288, deps=(rid(288, "Q1"), rid(287, "hp")) + TO_A1 + Q_DEPS, printed=printed.dT_288,
             readings=(printed.READ_ALPHA_LAMBDA, READ_VW),
             check=truth.period_order(DIRECT, 1, REGULATED, "F_2, A_0, A_1, A_2 (287) by quadrature at K = 0, j = the "
                                      "exact θ"),
             note="Q1/Q (134), Q = K(z − z') = ελ (260), h' of (287), a = a1 + ελ, a1 = −wλ (41): the leading term; of "
                  "the order of G only."),
        Spec(rid(289, "dT"), "ΔT/T of the clamping errors, regulated, the uniform blade", src(95, "289"),
             r"\frac{\Delta T}{T}", derivation.dT_289, deps=(PERIOD_288, rid(159, "wl"), rid(169, "F2"), rid(170, "F")),
             printed=printed.dT_289, defs=DEFS,
             check=truth.period_order(DIRECT, 1, REGULATED, "j = the exact θ"),
             note="(288) with wλ (159), F_2 (169) and the A_p (170) at K = 0, in th(u/2) and u."),
        # ------------------------------------------------------------ n°95, (290)
        Spec(rid(290, "i"), "i = ελj/w0 when i' = 0", src(95, "290"), "i", derivation.i_290,
             deps=(rid(117, "j"), rid(256, "epsilon"), rid(41, "a1")), printed=printed.i_290,
             check=truth.symmetric_order(),
             note="(117) with i' = 0 at a = a1 + ελ, solved for i, leading term in ε; vλ = w0 − wλ (16). Against ∂θ/∂i "
                  "of the exact equilibrium."),
        Spec(rid(290, "reduces"), "the j² terms of (288) are (286)", src(95, None),
             r"\frac{\Delta T}{T}\Big|_{j^2,\,(288)} - \frac{\Delta T}{T}\Big|_{(286)}", derivation.reduction_290,
             deps=(PERIOD_288, PERIOD_286, rid(262, "G")),
             check=checks.Proof("the j² terms of the derived (288), with A_0 = −F_4 ((287) at K = 0), wλ − F_4 = CG2 "
                                "(284) and G2 = ελG (262), minus the derived (286): 0", truth=EXACT),
             note="Haag: « (286), à laquelle se réduit d'ailleurs la formule (288) si l'on ne garde que les termes en "
                  "j² ». With i' = 0, i/j = ελ/w0 (290) is O(ε): (286) applies."),
    )
