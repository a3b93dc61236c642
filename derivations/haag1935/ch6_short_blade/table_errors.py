"""Haag 1935, chapter VI, n°80–81: the clamping errors (246)–(250) and the inertia and weight of the blade
(251)–(254) of the short blade, the Results."""
from __future__ import annotations

from pendsym import checks
from pendsym.result import Spec

from ..common import rid, src
from . import derivation_errors as derivation, printed_errors as printed, truth_errors as truth
from .printed import DEFINITIONS

SHORT = (rid(216, "K"), rid(214, "z"), rid(215, "zp"))
UNIFORM = ("uniform", "uniform_half")
STEP_NOTE = ("The truth is chapter II's {eq} (checked there on {model}) at the exact modes, the blade's integrals "
             "by quadrature: it judges the expansion in λ/a, not {eq}.")
TILT = "the exact tilted blade, pendsym.nonlinear_tilt"
MASS_NOTE = ("Judged against the blade with mass (pendsym.massive_blade, m'/m = 10⁻⁸, the uniform blade u = 2) as "
             "a = λ/ε grows, and on the blade u = 1/2 by chapter II's {eq} at the exact modes (the expansion step).")


def specs() -> tuple[Spec, ...]:
    return (
        # ------------------------------------------------------------ n°80
        Spec(rid(246, "sum"), "j + i + i' = (iw_0 + i'w_λ)/a", src(80, "246"), "j + i + i'", derivation.sum_246,
             deps=(rid(117, "j"), rid(41, "a1")), printed=printed.sum_246, readings=(printed.READ_W_LAMBDA,),
             check=checks.All((truth.sum_order("tapered"), truth.sum_order("uniform"))),
             note="(117) with a1 = −w_λ (41), at its leading order in λ/a, v_λ = w_0 − w_λ (16). "
                  + STEP_NOTE.format(eq="(117)", model=TILT)),
        Spec(rid(247, "sum"), "j + i + i' = (λ/(au))(iU_1 + i'U_2), the uniform blade", src(80, "247"), "j + i + i'",
             derivation.sum_247, deps=(rid(246, "sum"), rid(159, "w0"), rid(159, "wl")), printed=printed.sum_247,
             defs=DEFINITIONS, check=checks.All(tuple(truth.sum_order(name) for name in UNIFORM))),
        Spec(rid(248, "Q1"), "Q1 = (i²/2)(v_0 − λ) − hi + (i²/4)F_2 − h'/48", src(80, "248"), "Q_1",
             derivation.Q1_248, deps=(rid(133, "Q1"), rid(117, "j"), rid(41, "a1"), rid(22, "beta1")) + SHORT,
             printed=printed.Q1_248, readings=(printed.READ_NU, printed.READ_LAMBDA_CUBE),
             check=checks.All((truth.Q1_order("tapered"), truth.Q1_order("uniform"))),
             note="(133) with j of (117), K → 1, z' → −a, R = 0; h (127), h' (132) and F_2 counted as lengths of the "
                  "blade, so that i + i' + j and h/a are O(λ/a): the terms in a cancel and i' drops out. "
                  + STEP_NOTE.format(eq="(133)", model=TILT)),
        Spec(rid(249, "dT"), "ΔT/T of the clamping errors, the short uniform blade", src(80, "249"),
             r"\frac{\Delta T}{T}", derivation.dT_249,
             deps=(rid(248, "Q1"), rid(221, "Q"), rid(127, "h"), rid(132, "hp"), rid(169, "F2"), rid(170, "F"),
                   rid(159, "v0"), rid(239, "F2")),
             printed=printed.dT_249, defs=DEFINITIONS,
             check=checks.All(tuple(truth.Q1_order(name, period=True) for name in UNIFORM)),
             note="Q1/Q with Q → a (221); h and h' at K = 1 from the moments J(i, j) read off the polynomials in K "
                  "of (169) and (170) (h' needs only the coefficients of F = 4KF_3 − F_4). "
                  + STEP_NOTE.format(eq="(134)", model=TILT)),
        Spec(rid(250, "dT"), "ΔT/T = −(λ/(16au))(3i² + 4ij + 2j²), u > 5", src("n°80, u > 5", "250"),
             r"\frac{\Delta T}{T}", derivation.dT_250, deps=(rid(249, "dT"),), printed=printed.dT_250,
             check=truth.thin(truth.thin_clamping, "Q1/a of (248), h (127), h' (132), F_2 (79) by quadrature, "
                                                  "i = 1, j = −0.4"),
             note="(249) with the terms in e^{−u} dropped."),
        # ------------------------------------------------------------ n°81
        Spec(rid(251, "dT"), "ΔT/T of the blade's inertia, the short uniform blade", src(81, "251"),
             r"\frac{\Delta T}{T}", derivation.inertia_251, deps=(rid(135, "inertia"), rid(182, "I")) + SHORT,
             printed=printed.inertia_251, defs=DEFINITIONS, readings=(printed.READ_M_PRIME,),
             check=checks.All((truth.massive_order("uniform", True), truth.mass_order("uniform_half", True))),
             note="(135) with I_λ of (182) at K = 1, z' → −a, z − z' → a. " + MASS_NOTE.format(eq="(135)")),
        Spec(rid(252, "dT"), "ΔT/T = (m'/2m)(λ²/a²)(1/3 − 1/u + 1/u² + 1/(2u³)), u > 5", src("n°81, u > 5", "252"),
             r"\frac{\Delta T}{T}", derivation.inertia_252, deps=(rid(251, "dT"),), printed=printed.inertia_252,
             readings=(printed.READ_M_PRIME,),
             check=truth.thin(truth.thin_inertia, "I_λ/(2ma²) ((135) at K = 1), I_λ by quadrature, m'/m = 1",
                              power=3),
             note="(251) with the terms in e^{−u} dropped: the largest, (U − 3U_1)/(2u³) − 1/(2u³) ≈ −4e^{−u}/u³, "
                  "hence the residual taken times u³ (U_2 − 1 and U_1² are O(e^{−2u}))."),
        Spec(rid(253, "dT"), "ΔT/T of the blade's weight, the short uniform blade", src(81, "253"),
             r"\frac{\Delta T}{T}", derivation.weight_253, deps=(rid(136, "weight"), rid(183, "J"), rid(221, "Q")) + SHORT,
             printed=printed.weight_253, defs=DEFINITIONS, readings=(printed.READ_M_PRIME,),
             check=checks.All((truth.massive_order("uniform", False), truth.mass_order("uniform_half", False))),
             note="(136) with J of (183) at K = 1, Q → a (221). " + MASS_NOTE.format(eq="(136)")),
        Spec(rid(254, "dT"), "ΔT/T = −(m'/8m)(λ/a)(2 − 6/u + 7/u²), u > 5", src("n°81, u > 5", "254"),
             r"\frac{\Delta T}{T}", derivation.weight_254, deps=(rid(253, "dT"),), printed=printed.weight_254,
             readings=(printed.READ_M_PRIME,),
             check=truth.thin(truth.thin_weight, "−Jm'/(ma) ((136) at K = 1, Q = a), J by quadrature, m'/m = 1",
                              expected=2),
             note="(253) with the terms in e^{−u} dropped: they are O(e^{−2u}) (U_2 − 1 ≈ 2e^{−2u}, "
                  "U_1² ≈ 4e^{−2u}), so the residual falls as e^{−2u}."),
    )
