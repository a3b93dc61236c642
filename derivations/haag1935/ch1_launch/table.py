"""Haag 1935, chapter I, n°16–20, eqs. (64)–(76): the Results, joining derivation, print and truth."""
from __future__ import annotations

from pendsym.result import Spec
from ..common import READ_VW, rid, src
from ..symbols import a, a1, a_minus_a1, beta1, beta1_positive
from . import derivation, printed, truth
from .printed import READ_69, READ_73, READ_75, READ_FOCUS_VELOCITY

POSITIVE = ((beta1, beta1_positive), (a1, a - a_minus_a1))   # β1 > 0 (17), a − a1 > 0 (40) under square roots


def specs() -> tuple[Spec, ...]:
    return (
        # ---------------------------------------------------------------- n°16
        Spec(rid(64, "beta"), "principal oscillation: F' fixed, β + (a + z')θ = 0", src(16, "64"), r"\beta",
             derivation.beta_principal_64, printed=printed.eq64, check=truth.beta_principal(),
             note="printed as β + (a + z')θ = 0 (solved for β). F' is the node above G (z' < 0)."),
        Spec(rid(65, "Y"), "Y = Kθ in the principal oscillation", src(16, "65"), "Y", derivation.Y_principal_65,
             deps=(rid(64, "beta"),), printed=printed.eq65, check=truth.end_load("principal")),
        Spec(rid(66, "phi"), "φ = θ(Kφ1 + φ2) in the principal oscillation", src(16, "66"), r"\varphi",
             derivation.phi_principal_66, deps=(rid(65, "Y"),), printed=printed.eq66_phi,
             check=truth.deflection(1, "φ(s)")),
        Spec(rid(66, "dphi"), "dφ/ds = θ(Kv + w)/M in the principal oscillation", src(16, "66"),
             r"\frac{d\varphi}{ds}", derivation.dphi_principal_66, deps=(rid(65, "Y"),), printed=printed.eq66_dphi,
             check=truth.deflection(2, "φ'(s)")),
        Spec(rid(66, "Y_parasitic"), "parasitic vibration (F fixed): Y = K'θ, z and z' exchanged", src(16, "66"),
             "Y", derivation.Y_parasitic_66, printed=printed.eq66_parasitic, check=truth.end_load("parasitic"),
             note="The text: the parasitic vibration is given by (64)–(66) with z and z' exchanged; "
                  "K' is (35) with z for z'."),
        # ---------------------------------------------------------------- n°18
        Spec(rid(67, "theta0"), "initial θ under a force Q at AB = b", src(18, "67"), r"\theta_0", derivation.theta0_67,
             printed=printed.eq67_theta0, readings=(READ_VW,), check=truth.static(1, "θ0")),
        Spec(rid(67, "beta0"), "initial β under a force Q at AB = b", src(18, "67"), r"\beta_0", derivation.beta0_67,
             printed=printed.eq67_beta0, check=truth.static(0, "β0")),
        Spec(rid(68, "A"), "amplitude of F after release from rest: A = Q F'B/(K mg)", src(18, "68"), "A",
             derivation.A_static_68, deps=(rid(67, "theta0"), rid(67, "beta0")), printed=printed.eq68_A,
             check=truth.static(2, "A = β0 + (a + z)θ0, the initial ordinate of the node F of the parasitic mode")),
        Spec(rid(68, "Ap"), "amplitude of F': A' = Q FB/(K' mg)", src(18, "68"), "A'", derivation.Ap_static_68,
             deps=(rid(67, "theta0"), rid(67, "beta0")), printed=printed.eq68_Ap,
             check=truth.static(3, "A' = β0 + (a + z')θ0, the initial ordinate of the node F' of the principal mode"),
             note="Printed in words: replace F by F' and K by K' in (68)."),
        Spec(rid(69, "ratio"), "A/A' after release from rest", src(18, "69"), "A/A'", derivation.ratio_static_69,
             deps=(rid(68, "A"), rid(68, "Ap")), printed=printed.eq69, readings=(READ_69,),
             check=truth.static(4, "A/A' from the static offset")),
        # ---------------------------------------------------------------- n°19–20
        Spec(rid(70, "momentum"), "angular momentum about B after a blow at B: (β'0 + aθ'0)(a − b) + R²θ'0 = 0",
             src(19, "70"), r"(\beta'_0 + a\theta'_0)(a - b) + R^2\theta'_0", derivation.momentum_70,
             printed=printed.eq70, check=truth.momentum(),
             note="printed as an equation = 0; the pendulum is free during the blow (footnote of n°19)."),
        Spec(rid(71, "vF"), "velocity of F after the blow: θ'0 z BF'/BG", src(19, "71"), "v_0", derivation.vF_71,
             deps=(rid(70, "momentum"),), printed=printed.eq71, readings=(READ_FOCUS_VELOCITY,),
             check=truth.velocity_of_F()),
        Spec(rid(72, "A"), "amplitude of F after the blow: A = v0/n", src(19, "72"), "A", derivation.A_blow_72,
             printed=printed.eq72_A, readings=(READ_FOCUS_VELOCITY,), check=truth.amplitude("A"),
             note="n is the frequency of the principal oscillation (34), in which F moves (F' fixed)."),
        Spec(rid(72, "Ap"), "amplitude of F' after the blow: A' = v'0/n'", src(19, "72"), "A'", derivation.Ap_blow_72,
             printed=printed.eq72_Ap, readings=(READ_FOCUS_VELOCITY,), check=truth.amplitude("Ap")),
        Spec(rid(73, "ratio"), "A/A' after the blow", src(19, "73"), "A/A'", derivation.ratio_blow_73,
             deps=(rid(71, "vF"), rid(72, "A"), rid(72, "Ap")), printed=printed.eq73, readings=READ_73, defs=POSITIVE,
             check=truth.amplitude_ratio(),
             note="β1 > 0 (17) and a − a1 > 0 (40) are applied (defs) so that the square roots are real."),
        Spec(rid(74, "theta0"), "θ'0 after the blow of a mass m' with restitution h", src(20, "74"), r"\theta'_0",
             derivation.theta_dot0_74, deps=(rid(70, "momentum"),), printed=printed.eq74, check=truth.blow(1, "θ'0")),
        Spec(rid(75, "Vp"), "velocity V' of m' after the blow", src(20, "75"), "V'", derivation.V_after_75,
             deps=(rid(70, "momentum"),), printed=printed.eq75, check=truth.blow(2, "V'"), readings=(READ_75,),
             note="The derived denominator is (a − b)² + R²(1 + m/m'), that of (74); the printed "
                  "R²(1 + h m/m') gives V' = V for h = 0 (no momentum given to the pendulum), which "
                  "contradicts the momentum equation printed just before (74)."),
        Spec(rid(76, "vF"), "velocity of F after the blow of m'", src(20, "76"), "v_0", derivation.vF_mass_76,
             deps=(rid(71, "vF"), rid(74, "theta0")), printed=printed.eq76, readings=(READ_FOCUS_VELOCITY,),
             check=truth.velocity_of_F_after_mass()),
    )
