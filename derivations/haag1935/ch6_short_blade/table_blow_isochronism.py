"""Haag 1935, chapter VI, n°74 and n°78–79: the fatigue after a blow (233)–(234), the perturbing acceleration
(241) and the isochronism error of the short blade (242)–(245)."""
from __future__ import annotations

from pendsym import checks
from pendsym.result import Spec

from ..common import READ_VW, rid, src
from . import derivation_perturbations as derivation, printed_perturbations as printed, truth_perturbations as truth
from .printed import DEFINITIONS

BLOW_NOTE = ("K' = −l/β1 (224), z' = −a, z = R²/a at their leading order: the amplitude of the sin n't term of "
             "(181); (181)'s T'_λ gives the same with the opposite sign (\"simultanément aux deux encastrements\").")


def specs() -> tuple[Spec, ...]:
    uniform = ("uniform", "uniform_half")
    return (
        # ------------------------------------------------------------ n°74
        Spec(rid(233, "Tprime"), "the largest fatigue after a blow, at both clamps", src(74, "233"), "T'",
             derivation.fatigue_233, deps=(rid(181, "T0"), rid(181, "Tl"), rid(224, "Kp"), rid(214, "z"),
                                           rid(215, "zp")),
             printed=printed.fatigue_233, defs=DEFINITIONS + printed.THETA_DEFINITION, readings=(printed.READ_BF,),
             check=checks.All((truth.blow_order("uniform", "T0"), truth.blow_order("uniform", "Tl"),
                               truth.blow_order("uniform_half", "T0"))),
             note=BLOW_NOTE),
        Spec(rid(234, "Theta"), "Θ = Ua·BF/(β1n')", src(74, "234"), r"\Theta", derivation.theta_234,
             deps=(rid(233, "Tprime"),), printed=printed.theta_234, defs=DEFINITIONS, readings=(printed.READ_BF,),
             check=truth.blow_order("uniform", "T0", over=truth.shock_factor),
             note="(233) over its factor √(3ET)(1 + h)V/((a − b)² + R²(1 + m/m'))."),
        Spec(rid(234, "Theta_g"), "Θ = UR·BF/√(β1g)", src(74, "234"), r"\Theta", derivation.theta_234_g,
             deps=(rid(234, "Theta"), rid(225, "np2")), printed=printed.theta_234_g, defs=DEFINITIONS,
             readings=(printed.READ_BF,),
             check=truth.blow_order("uniform", "T0", family=truth.FIXED, over=truth.shock_factor),
             note="n'² of (225) with l = a: R² neglected before a² (the factor √(a/l) dropped), so that the check "
                  "keeps R fixed while a grows."),
        # ------------------------------------------------------------ n°78
        Spec(rid(241, "f"), "f = n²(aε2 − aε1θ + ε3), a perturbation proper", src(78, "241"), "f",
             derivation.f_241, deps=(rid(104, "f"), rid(216, "K"), rid(215, "zp")), printed=printed.f_241,
             check=checks.All((truth.perturbation_order("tapered"), truth.perturbation_order("uniform"))),
             note="(104) with no increment of the blade's moment (E_1 = E_2 = ε_λ = 0: forces on the pendulum only), "
                  "K → 1, z' → −a, the blade's moments J(i, j) = O(λ) dropped: the rigid axis. The truth is (104) "
                  "itself at the exact modes: it judges the step, not (104)."),
        # ------------------------------------------------------------ n°79
        Spec(rid(242, "ratio"), "Q'/Q = 1 + (−5λ + 5v_0 − w_0 + 8F_2 − F)/a", src(79, "242"), "Q'/Q",
             derivation.ratio_242, deps=(rid(112, "Qp"), rid(110, "F"), rid(216, "K"), rid(215, "zp"), rid(221, "Q"),
                                         rid(22, "beta1"), rid(16, "w0")),
             printed=printed.ratio_242, readings=(printed.READ_NU_OMEGA,),
             check=checks.All((truth.isochronism_order("tapered"), truth.isochronism_order("uniform"))),
             note="Haag's intermediate Q' = a − 4λ + 4v_0 + 8F_2 − F is the numerator; F = 4KF_3 − F_4 (110). The "
                  "truth is chapter II's (112)/(45) (checked there on the nonlinear blade) at the exact modes: it "
                  "judges the expansion in λ/a, not (112)."),
        Spec(rid(243, "F"), "F/λ of the uniform blade at K = 1", src(79, "243"), r"F/\lambda", derivation.F_243,
             deps=(rid(170, "F"),), printed=printed.F_243, defs=DEFINITIONS, check=truth.F_at_one()),
        Spec(rid(244, "dT"), "ΔT/T, the isochronism error of the short uniform blade", src(79, "244"),
             r"\frac{\Delta T}{T}", derivation.dT_244,
             deps=(rid(242, "ratio"), rid(111, "dT"), rid(112, "Qp"), rid(45, "Q"), rid(159, "v0"), rid(159, "w0"),
                   rid(239, "F2"), rid(243, "F")),
             printed=printed.dT_244, defs=DEFINITIONS,
             check=checks.All(tuple(truth.isochronism_order(name, with_theta=True) for name in uniform)),
             note="As u → ∞ the bracket → 0: the simple pendulum of length a + λ (Haag's check; Le Rolland's "
                  "−(λ/a)(1 − 2U/u), quoted in the footnote, fails it)."),
        Spec(rid(245, "dT"), "ΔT/T = (θ0²/16)(1 − 7λ/(4au)), u > 4", src("n°79, u > 4", "245"), r"\frac{\Delta T}{T}",
             derivation.dT_245, deps=(rid(244, "dT"),), printed=printed.dT_245, check=truth.thin_isochronism(),
             note="(244) with the terms in e^{−u} dropped (th(u/2) → 1)."),
    )
