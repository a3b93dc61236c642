"""Haag 1935, chapter I, n°10–15, eqs. (42)–(63): the Results, joining derivation, print and truth."""
from __future__ import annotations

import sympy as sp

from pendsym import checks
from pendsym.result import Spec
from ..ch1_motion import printed as ch1_printed
from ..common import READ_VW, rid, src
from ..symbols import G, G_2, K, M_lambda, P_lambda, Q, a, a1, beta1, v, vl, w, wl, z
from . import derivation, printed, truth
from .printed import INSTANCES, READ_43, READ_44, READ_51, READ_60

THROUGH_54 = checks.Chain((rid(54, "x"),))


def z_by_36() -> sp.Expr:
    """z by (36) as printed, K = (a + wλ)/(a + z − vλ), solved for z: z = (a + wλ)/K − a + vλ.

    The definition under which the printed forms (they hold z) are compared with the derived ones (which
    eliminate z by the derived (36), :func:`derivation.z_of_K`).  Solved from the printed relation, a solve of
    one linear equation, so that building the Specs derives nothing (the derived (36) takes ~1.3 s of CPU);
    the two are the same expression (tests/test_haag1935_ch1_variations_table.py), and the printed (36)
    is checked against the derived one by haag1935.eq036.K.
    """
    return sp.solve(sp.Eq(K, ch1_printed.eq36()), z)[0]


def haag_definitions():
    """Haag's definitions used by the printed forms: Q (45), a1 = −wλ (41), z by (36), Pλ (59)."""
    return ((Q, a + wl + K**2 * beta1), (a1, -wl), (z, z_by_36()), (P_lambda, (K * vl + wl) ** 2 / M_lambda))


def specs() -> tuple[Spec, ...]:
    definitions = haag_definitions()
    return (
        Spec(rid(42, "dT"), "dT/T with dK from (35)", src(10, "42"), r"\frac{dT}{T}", derivation.dT_42,
             printed=printed.eq42, check=truth.period(),
             note="Printed as 2dT/T = …; dz'/z' and dR/R are log-differentials. The derived form eliminates z' by "
                  "(35)."),
        Spec(rid(43, "dT"), "dT/T with dK from (36) and dz from (31)", src(10, "43"), r"\frac{dT}{T}", derivation.dT_43,
             printed=printed.eq43, defs=definitions, readings=(READ_43,), check=truth.period(),
             note="The derived form eliminates z by (36) (the printed one is compared with z = (a + wλ)/K − a + vλ)."),
        Spec(rid(44, "dT"), "dT/T: dz'/z' eliminated", src(10, "44"), r"\frac{dT}{T}", derivation.dT_44,
             deps=(rid(42, "dT"), rid(43, "dT")), printed=printed.eq44, defs=definitions, readings=(READ_VW, READ_44),
             check=truth.period()),
        Spec(rid(45, "Q"), "Q = a − a1 + K²β1 = K(z − z')", src(10, "45"), "Q", derivation.Q_45, printed=printed.eq45,
             check=truth.Q_of_truth(), note="Q is defined by a − a1 + K²β1; the derived form uses (35), (36), (41)."),
        Spec(rid(49, "dv_dlam"), "∂v/∂λ", src(11, "49"), r"\frac{\partial v}{\partial\lambda}",
             derivation.dv_dlambda_49,
             printed=printed.eq49, check=truth.lambda_derivative(function="v"),
             note="(46)–(48): u = ∂v/∂λ solves (9) with u'_0 = 0, u'_λ = −vλ/Mλ; M(s) given, λ varies."),
        Spec(rid(46, "du_ds"), "∂u/∂s = ∂v'/∂λ, u = ∂v/∂λ", src(11, "46"), r"\frac{\partial u}{\partial s}",
             derivation.du_ds_46, deps=(rid(49, "dv_dlam"),), check=truth.slope_lambda_derivative(),
             note="(46) states ∂u/∂s = ∂v'/∂λ; the derived ∂u/∂s (the s-derivative of (49)) is checked against "
                  "the λ-derivative of the shot v'(s), which is (46) itself in numbers."),
        Spec(rid(47, "du_ds_0"), "(∂u/∂s)_0 = dv'_0/dλ = 0", src(11, "47"),
             r"\left(\frac{\partial u}{\partial s}\right)_0", derivation.du_ds_at_0_47, deps=(rid(46, "du_ds"),),
             printed=printed.eq47, check=checks.Proof("(46) at s = 0 with w'_0 = 0 (10) is 0: v'_0 = −1 for every λ")),
        Spec(rid(48, "du_ds_l"), "(∂u/∂s)_λ = −vλ/Mλ", src(11, "48"),
             r"\left(\frac{\partial u}{\partial s}\right)_\lambda", derivation.du_ds_at_lambda_48, printed=printed.eq48,
             check=truth.end_slope_lambda_derivative(),
             note="From d/dλ v'_λ = 0 (10) and v'' = v/M (9), as in the memoir."),
        Spec(rid(50, "dw_dlam"), "∂w/∂λ", src(11, "50"), r"\frac{\partial w}{\partial\lambda}",
             derivation.dw_dlambda_50,
             printed=printed.eq50, check=truth.lambda_derivative(function="w"), readings=(READ_VW,)),
        Spec(rid(51, "dv0"), "dv0/dλ", src(11, "51"), r"\frac{dv_0}{d\lambda}", derivation.at_0_51(rid(49, "dv_dlam")),
             deps=(rid(49, "dv_dlam"),), printed=printed.eq51_dv0, readings=(READ_51,),
             check=truth.lambda_derivative("v0")),
        Spec(rid(51, "dw0"), "dw0/dλ", src(11, "51"), r"\frac{dw_0}{d\lambda}", derivation.at_0_51(rid(50, "dw_dlam")),
             deps=(rid(50, "dw_dlam"),), printed=printed.eq51_dw0, readings=(READ_51, READ_VW),
             check=truth.lambda_derivative("w0")),
        Spec(rid(52, "dvl"), "dvλ/dλ", src(11, "52"), r"\frac{dv_\lambda}{d\lambda}",
             derivation.at_lambda_52(rid(49, "dv_dlam"), -1), deps=(rid(49, "dv_dlam"),), printed=printed.eq52_dvl,
             check=truth.lambda_derivative("vl")),
        Spec(rid(52, "dwl"), "dwλ/dλ", src(11, "52"), r"\frac{dw_\lambda}{d\lambda}",
             derivation.at_lambda_52(rid(50, "dw_dlam"), 1), deps=(rid(50, "dw_dlam"),), printed=printed.eq52_dwl,
             check=truth.lambda_derivative("wl")),
        Spec(rid(52, "wronskian"), "d/dλ of (16) holds identically", src(11, None),
             r"\frac{d}{d\lambda}(w_0 - v_\lambda - w_\lambda)", derivation.wronskian_dlambda,
             deps=(rid(51, "dw0"), rid(52, "dvl"), rid(52, "dwl")),
             check=checks.Proof("dw0/dλ − dvλ/dλ − dwλ/dλ with the derived (51), (52) and w0 = vλ + wλ (16) is 0"),
             note="Holds with the derived dw0/dλ = −wλw0/Mλ; with the printed −w0²/Mλ it would need w0 = wλ."),
        Spec(rid(53, "x_ode"), "Mx'' − x = −εMv'' for the increment x of v", src(12, "53"), "Mx'' - x",
             derivation.x_ode_53, printed=printed.eq53, instances=INSTANCES, check=THROUGH_54,
             note="(9) with M → M(1 + ε), v → v + x to the first order; x'_0 = x'_λ = 0 by (10)."),
        Spec(rid(55, "A"), "A = (1/w0)∫_0^s εwv'' ds", src(12, "55"), "A", derivation.A_B_55("A"),
             printed=printed.eq55_A, instances=INSTANCES, readings=(READ_VW,), check=THROUGH_54,
             note="Variation of constants for (53) with the Wronskian w0 (15)."),
        Spec(rid(55, "B"), "B = −(1/w0)∫_0^s εvv'' ds", src(12, "55"), "B", derivation.A_B_55("B"),
             printed=printed.eq55_B, instances=INSTANCES, readings=(READ_VW,), check=THROUGH_54),
        Spec(rid(54, "x"), "x = Av + (B + Aλ − Bλ)w", src(12, "54"), "x", derivation.x_54,
             deps=(rid(55, "A"), rid(55, "B")),
             printed=printed.eq54, instances=INSTANCES, readings=(READ_VW,), check=truth.increment(),
             note="A_λ, B_λ are A, B at s = λ; the printed form is (54) with (55) written out."),
        Spec(rid(56, "dv0"), "dv0 for M → M(1 + ε)", src(12, "56"), "dv_0", derivation.d_at_0_56(v),
             printed=printed.eq56_dv0, instances=INSTANCES, readings=(READ_VW,), check=truth.stiffness_derivative("v0"),
             note="(53)–(55) by variation of constants with the Wronskian w0 (15)."),
        Spec(rid(56, "dw0"), "dw0 for M → M(1 + ε)", src(12, "56"), "dw_0", derivation.d_at_0_56(w),
             printed=printed.eq56_dw0, instances=INSTANCES, readings=(READ_VW,),
             check=truth.stiffness_derivative("w0")),
        Spec(rid(57, "dvl"), "dvλ for M → M(1 + ε)", src(12, "57"), r"dv_\lambda", derivation.d_at_lambda_57(v),
             printed=printed.eq57_dvl, instances=INSTANCES, readings=(READ_VW,),
             check=truth.stiffness_derivative("vl")),
        Spec(rid(57, "dwl"), "dwλ for M → M(1 + ε)", src(12, "57"), r"dw_\lambda", derivation.d_at_lambda_57(w),
             printed=printed.eq57_dwl, instances=INSTANCES, readings=(READ_VW,),
             check=truth.stiffness_derivative("wl")),
        Spec(rid(57, "wronskian"), "the differential of (16) holds identically", src(12, None),
             r"dw_0 - dv_\lambda - dw_\lambda", derivation.wronskian_differential,
             deps=(rid(56, "dw0"), rid(57, "dvl"), rid(57, "dwl")),
             check=checks.Proof("dw0 − dvλ − dwλ with the derived (56), (57): the integrands cancel")),
        Spec(rid(59, "P"), "P = (Kv + w)²/M", src(13, "59"), "P", derivation.P_59, definition=True,
             readings=(READ_VW,)),
        Spec(rid(58, "dT"), "dT/T for da, dR, dλ and M → M(1 + ε)", src(13, "58"), r"\frac{dT}{T}", derivation.dT_58,
             deps=(rid(44, "dT"), rid(51, "dv0"), rid(52, "dvl"), rid(52, "dwl"), rid(56, "dv0"), rid(57, "dvl"),
                   rid(57, "dwl")), printed=printed.eq58, defs=definitions, instances=INSTANCES,
             check=truth.combined_period(),
             note="Derived with the derived (51) (−vλw0/Mλ); the printed (51) would not give (58)."),
        Spec(rid(60, "dT"), "dT/T per degree of temperature", src(14, "60"), r"\frac{dT}{T}", derivation.dT_60,
             deps=(rid(58, "dT"),), printed=printed.eq60, defs=definitions, check=truth.temperature(),
             readings=(READ_60,),
             note="da/a = dR/R = α', dλ/λ = α, ε = β + 4α constant (dE/E = β, dI/I = 4α); G2 of (79)."),
        Spec(rid(61, "dT"), "dT/T for a variation of g", src(15, "61"), r"\frac{dT}{T}", derivation.dT_61,
             deps=(rid(58, "dT"),), printed=printed.eq61, defs=definitions + ((G, -1 + G_2 / (a + wl + K**2 * beta1)),),
             check=truth.gravity("T"), note="ε = −dg/g (M = EI/(mg)) and −½dg/g from the factor g of (34)."),
        Spec(rid(62, "G"), "coefficient of sensitivity G", src(15, "62"), "G", derivation.G_62, deps=(rid(61, "dT"),),
             printed=printed.eq62, defs=definitions, check=truth.gravity("G")),
        Spec(rid(63, "G"), "G = −1 + 2W/(mgQ)", src(15, "63"), "G", derivation.G_63, deps=(rid(62, "G"),),
             printed=printed.eq63, defs=definitions, check=truth.gravity("G"),
             note="W/(mg) = ½∫Mφ'² ds with φ' = (Kv + w)/M (66), θ = 1; checked with pendsym.suspension.energy "
                  "of the principal mode, not with G2."),
    )
