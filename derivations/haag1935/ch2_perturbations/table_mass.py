"""Haag 1935, chapter II, n°36–37, eqs. (135)–(136): the blade's inertia and weight, the Results."""
from __future__ import annotations

import sympy as sp

from pendsym import checks
from pendsym.result import Spec
from ..common import READ_VW, rid, src, step
from ..symbols import K, Q, z, zp
from . import derivation, printed, truth
from .printed import READ_EPS, READ_F_36, READ_LIMITS_36, READ_WEIGHT_M

EXACT = "symbolic proof (SymPy)"
INERTIA, WEIGHT = rid(135, "inertia"), rid(136, "weight")
Q_DEF = ((Q, K * (z - zp)),)


def _all_zero(expr) -> bool:
    return all(sp.simplify(x) == 0 for x in expr)


def specs() -> tuple[Spec, ...]:
    return (
        # ---------------------------------------------------------------- n°36
        Spec(rid(135, "inertia_moment"), "ε of the blade's inertia: mgε = −∫μ'ÿ'(s' − s) ds'", src(36, None),
             r"\varepsilon", step(derivation.inertia_moment), printed=printed.inertia_moment,
             readings=(READ_EPS, READ_LIMITS_36), check=checks.Chain((INERTIA,)),
             note="Derived from the horizontal momentum of the part below s (the shear), ε(λ) = 0, the order of "
                  "the two integrals changed; s_1 is Haag's s'."),
        Spec(rid(135, "inertia_eps"), "ε in the principal oscillation", src(36, None), r"\varepsilon",
             step(lambda: derivation.as_phi(derivation.inertia_moment_principal())),
             printed=printed.inertia_moment_principal, readings=(READ_EPS,), check=checks.Chain((INERTIA,)),
             note="ÿ = −n²y, y = θ∫_0^s'(Kφ1 + φ2) ds'', n²/g = −K/z' (34)."),
        Spec(rid(135, "parts"), "∫_0^s'(Kv + w)/M (s' − s) ds = ∫_0^s'(Kφ1 + φ2) ds", src(36, None),
             r"(\partial_{s'}^2\Delta, \partial_{s'}\Delta(0), \Delta(0))", step(derivation.parts_identity),
             printed=printed.parts_identity, readings=(READ_VW,),
             check=checks.Proof("the difference has second derivative 0 (by (9)) and vanishes with its slope at "
                                "s' = 0 (by (10))", holds=_all_zero, truth=EXACT)),
        Spec(rid(135, "I_lambda"), "I_λ = ∫μy² ds (y for θ = 1)", src(36, None), r"I_\lambda",
             step(lambda: derivation.as_phi(derivation.I_lambda_def())), printed=printed.I_lambda_def,
             check=checks.Definition(), definition=True),
        Spec(rid(135, "inertia_f"), "f = −(n²/(mz'))θI_λ", src(36, None), "f", step(derivation.inertia_f),
             printed=printed.inertia_f, readings=(READ_F_36, READ_VW), check=checks.Chain((INERTIA,)),
             note="(104)–(105) with ε of the inertia; ∫ds∫ds' reordered and reduced by the parts identity."),
        Spec(INERTIA, "ΔT/T of the blade's inertia", src(36, "135"), r"\frac{\Delta T}{T}", step(derivation.eq135),
             printed=printed.eq135, check=truth.mass_order("hole", True), show_values=True,
             note="f of n°36 by (114); density ∝ width (halved over the hole)."),
        Spec(rid(135, "inertia_Q"), "ΔT/T = −KI_λ/(2mQz')", src(36, "135"), r"\frac{\Delta T}{T}",
             step(derivation.eq135), printed=printed.eq135_Q, defs=Q_DEF, check=truth.mass_order("hole", True),
             note="The second form of (135), Q = K(z − z') (45); on the blades with mass of (135), whose roots it "
                  "shares (the uniform blade's, 5–6 s CPU, went to chapter II's check budget for (141) at q = 2)."),
        Spec(rid(135, "delay"), "the inertia always delays: ΔT/T > 0", src(36, None), r"\frac{\Delta T}{T}",
             lambda deps: deps[INERTIA].derived, deps=(INERTIA,),
             check=truth.sign_on_blades("ΔT/T of (135) > 0 (z' < 0 < z − z', I_λ > 0)")),
        # ---------------------------------------------------------------- n°37
        Spec(rid(136, "weight_moment"), "ε of the blade's weight: mε = −∫μ'(y' − y) ds'", src(37, None),
             r"\varepsilon", step(derivation.weight_moment), printed=printed.weight_moment,
             readings=(READ_EPS, READ_WEIGHT_M), check=checks.Chain((WEIGHT,)),
             note="Derived from the tension mg + g∫_s^λμ ds', ε(λ) = 0, the order changed."),
        Spec(rid(136, "slope"), "∫_0^s''(Kv + w)/M ds = Kφ1'' + φ2''", src(37, None), r"(\Delta', \Delta(0))",
             step(derivation.slope_identity), printed=printed.slope_identity, readings=(READ_VW,),
             check=checks.Proof("the difference has derivative 0 (by (9)) and vanishes at 0 (by (10))",
                                holds=_all_zero, truth=EXACT)),
        Spec(rid(136, "J"), "J = (1/m')∫μ(s − x) ds (θ = 1)", src(37, None), "J",
             step(lambda: derivation.as_phi(derivation.J_def())), printed=printed.J_def, defs=printed.DEFS_J,
             check=checks.Definition(), definition=True,
             note="s − x = ½∫_0^sφ² ds from x' = cos φ (3) to the second order (the text's ∫φ''² = 2(s' − x'))."),
        Spec(rid(136, "weight_f"), "f = −(2m'J/(Km))n²θ", src(37, None), "f", step(derivation.weight_f),
             printed=printed.weight_f, check=checks.Chain((WEIGHT,)),
             note="(104)–(105) with ε of the weight; the three integrals reordered (0 < s < s'' < s' < λ)."),
        Spec(WEIGHT, "ΔT/T of the blade's weight", src(37, "136"), r"\frac{\Delta T}{T}", step(derivation.eq136),
             printed=printed.eq136, check=truth.mass_order("hole", False), show_values=True,
             note="f of n°37 by (114), Q = K(z − z') (45)."),
        Spec(rid(136, "advance"), "the weight always advances: −ΔT/T > 0", src(37, None), r"-\frac{\Delta T}{T}",
             lambda deps: -deps[WEIGHT].derived, deps=(WEIGHT,),
             check=truth.sign_on_blades("−ΔT/T of (136) > 0 (J > 0, Q > 0)")),
    )
