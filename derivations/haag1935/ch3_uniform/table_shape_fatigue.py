"""Haag 1935, chapter III, n°50–53: the shape of the uniform blade and its fatigue, (171)–(179)."""
from __future__ import annotations

import dataclasses

from pendsym import checks
from pendsym.result import Source, Spec

from ..common import rid, src
from ..symbols import lam
from . import derivation_pendulum as derivation, printed, truth
from .printed import A1_DEFINITION, C_DEFINITION, DEFINITIONS, T_DEFINITION

N50 = "n°50"
FOOTNOTE_PAGE = 159     # the memoir cites the footnote of n°51 as "la note de la page 159"


def n51(eq: str) -> Source:
    """A source in n°51, on page 159."""
    return dataclasses.replace(src("n°51", eq), page=FOOTNOTE_PAGE)


def stress_by_78(kind: str) -> checks.Values:
    return truth.on_blade("(78) with the shot v, w", truth.bending_stress_of(kind), along=True, extra=truth.FATIGUE)


def stress_at_end(where: int, kind: str) -> checks.Values:
    return truth.on_blade("ω(Yv + θw)/Y or ω(Kv + w) at the end, shot", truth.stress_bracket_at(where, kind),
                          extra={"Y": "0.8", "theta": "0.37"})


def static_ends(sign: int) -> checks.Values:
    return truth.on_blade("ω(v + θw/Y) at both ends, θ/Y = (b − v_λ)/(a + w_λ) (67)", truth.static_ends(sign),
                          extra=truth.STATIC, with_K=False)


def specs() -> tuple[Spec, ...]:
    return (
        Spec(rid(171, "shape"), "Shape of the blade ωy", src(N50, "171"), r"\omega y", derivation.shape,
             deps=(rid(157, "v"), rid(157, "w")), printed=printed.shape, readings=(printed.READ_SHAPE,),
             defs=DEFINITIONS + (C_DEFINITION,),
             check=truth.on_blade("ω y of (77)", truth.omega_y, along=True, with_K=False,
                                  extra={"Y": "0.8", "theta": "0.37"})),
        Spec(rid(172, "c"), "c = U + U1 θ/Y", src(N50, "172"), "c", derivation.c_of_shape, deps=(rid(171, "shape"),),
             printed=printed.c_of_shape, defs=DEFINITIONS, check=truth.c_on_blade("c"),
             readings=(printed.READ_C,)),
        Spec(rid(173, "c"), "c for the principal oscillation", src(N50, "173"), "c", derivation.c_principal,
             deps=(rid(172, "c"),), printed=printed.c_principal, defs=DEFINITIONS,
             check=truth.c_on_blade("principal")),
        Spec(rid(174, "c"), "c for the static deviation", src(N50, "174"), "c", derivation.c_static,
             deps=(rid(172, "c"), rid(159, "vl"), rid(159, "wl")), printed=printed.c_static,
             defs=DEFINITIONS + (A1_DEFINITION,), check=truth.c_on_blade("static")),
        # ---------------------------------------------------------------- n°51–53
        Spec(rid(175, "Tprime"), "Bending stress T' = √(3ET) YΓ", n51("175"), "T'", derivation.bending_stress,
             deps=(rid(157, "v"), rid(157, "w")), printed=printed.bending_stress,
             defs=DEFINITIONS + (C_DEFINITION, T_DEFINITION), check=stress_by_78("T"),
             note="T = mg/(eh) = Ee²u²/(12λ²) by (156); Γ of (176) written out."),
        Spec(rid(176, "Gamma_f"), "Γ = c ch ωs − sh ωs", n51("176"), r"\Gamma", derivation.fatigue_Gamma,
             deps=(rid(175, "Tprime"),), printed=printed.fatigue_Gamma, readings=(printed.READ_FATIGUE_GAMMA,),
             defs=DEFINITIONS + (C_DEFINITION,), check=stress_by_78("Gamma")),
        Spec(rid(177, "Gamma0"), "Γ_0 = c", n51("177"), r"\Gamma_0", derivation.fatigue_Gamma_at(0),
             deps=(rid(176, "Gamma_f"),), printed=printed.fatigue_Gamma_0, defs=DEFINITIONS + (C_DEFINITION,),
             check=stress_at_end(0, "Gamma")),
        Spec(rid(177, "Gammal"), "Γ_λ = c ch u − sh u", n51("177"), r"\Gamma_\lambda",
             derivation.fatigue_Gamma_at(lam),
             deps=(rid(176, "Gamma_f"),), printed=printed.fatigue_Gamma_lambda,
             readings=(printed.READ_FATIGUE_GAMMA_LAMBDA,), defs=DEFINITIONS + (C_DEFINITION,),
             check=stress_at_end(1, "Gamma")),
        Spec(rid(177, "static_diff"), "Γ_0 − Γ_λ for the static deviation (n°52)", src("n°52", None),
             r"\Gamma_0-\Gamma_\lambda", derivation.static_ends(-1), deps=(rid(174, "c"),),
             printed=printed.static_difference, defs=DEFINITIONS + (A1_DEFINITION,), check=static_ends(-1)),
        Spec(rid(177, "static_sum"), "Γ_0 + Γ_λ for the static deviation (n°52)", src("n°52", None),
             r"\Gamma_0+\Gamma_\lambda", derivation.static_ends(+1), deps=(rid(174, "c"),),
             printed=printed.static_sum, defs=DEFINITIONS + (A1_DEFINITION,), check=static_ends(+1)),
        Spec(rid(178, "Tprime"), "T' in the principal oscillation", src("n°53", "178"), "T'",
             derivation.principal_stress, deps=(rid(175, "Tprime"),), printed=printed.principal_stress,
             defs=DEFINITIONS + (T_DEFINITION,), check=stress_by_78("principal")),
        Spec(rid(179, "C0"), "C_0 = KU + U1", src("n°53", "179"), "C_0", derivation.bracket_at(0),
             deps=(rid(178, "Tprime"),), printed=printed.C0, defs=DEFINITIONS, check=stress_at_end(0, "C")),
        Spec(rid(179, "Cl"), "C_λ = U2 − KU = U1 + U(1 − K)", src("n°53", "179"), r"C_\lambda",
             derivation.bracket_at(lam), deps=(rid(178, "Tprime"),), printed=printed.C_lambda, defs=DEFINITIONS,
             check=stress_at_end(1, "C"), note="The second printed form U1 + U(1 − K) equals the first by (161)."),
    )
