"""Haag 1935, chapter IX with chapters I, VII, VIII: the gravity meter on a rhombus-holed blade (not printed).

Derived only (Haag stops at (346)): β1, a1, n² of the slow vibration, G, F2, F4 and C of the inverted rhombus blade,
each built by SymPy from the derived Results it names (:mod:`.rhombus_scene_derivation`) and checked against the
blade solved directly or shot, no Bessel function (:mod:`.rhombus_scene_truth`).  The scenes use them
(``scenes/gravity_meter_rhombus_blade.toml``).
"""
from __future__ import annotations

from pendsym.result import Spec

from ..common import rid, src
from . import rhombus_derivation, rhombus_scene_derivation as derivation, rhombus_scene_truth as truth

V0, VL, WL, G2 = rid(343, "v0"), rid(343, "vl"), rid(343, "wl"), rid(346, "G2")
CONSTANTS = (rid(340, "A1"), rid(340, "B1"), rid(342, "A2"), rid(342, "B2"))
NOTE = "Not printed: Haag stops at G_2 (346); {what}, as the scenes need it (a gravity meter on this blade)."


def _d(deps, key):
    return deps[key].derived


def _constants(deps) -> dict:
    names = (rhombus_derivation.A1, rhombus_derivation.B1, rhombus_derivation.A2, rhombus_derivation.B2)
    return {name: _d(deps, key) for name, key in zip(names, CONSTANTS)}


def specs() -> tuple[Spec, ...]:
    n109, n110 = "n°109 with n°5 (22)", "n°110 with n°84 (262), n°102 (312)"
    return (
        Spec(rid(343, "beta1"), "β1 = λ + vλ − v0 of the rhombus blade", src(n109, None), r"\beta_1",
             lambda deps: derivation.beta1_rhombus(_d(deps, V0), _d(deps, VL)), deps=(V0, VL),
             check=truth.on_direct(truth.beta1, "β1 = 1/S00 of the direct stiffness"),
             note=NOTE.format(what="(22) with v0, vλ of (343); the existence condition (304) is β1 < 0")),
        Spec(rid(343, "a1"), "a1 = −wλ of the rhombus blade (critical distance)", src("n°109 with n°100 (305)", None),
             "a_1", lambda deps: derivation.a1_rhombus(_d(deps, WL)), deps=(WL,),
             check=truth.on_direct(truth.critical, "a1 where det K(a) = 0"),
             note=NOTE.format(what="(305) with wλ of (343)")),
        Spec(rid(343, "n2"), "n² of the slow vibration, inverted rhombus blade ((34), (36), (30), g → −g)",
             src("n°109 with n°7–8, n°100", None), "n^2",
             lambda deps: derivation.n2_slow(_d(deps, VL), _d(deps, rid(343, "beta1")), _d(deps, WL)),
             deps=(VL, rid(343, "beta1"), WL), check=truth.n2_check(),
             note=NOTE.format(what="(34) n² = −Kg/z' with g → −g (n°100), K of (36), z of (30), with vλ, β1, wλ of "
                                   "the rhombus blade (as eq034.n2_inverted for the uniform one)")),
        Spec(rid(346, "G"), "G = G_2/(ελ) of the inverted rhombus blade", src(n110, None), "G",
             lambda deps: derivation.G_inverted(_d(deps, rid(262, "G")), _d(deps, G2)), deps=(rid(262, "G"), G2),
             check=truth.G_order(),
             note=NOTE.format(what="(262) with ε → −ε (312) and the signed G_2 = −(346) (M in absolute value, "
                                   "footnote (2) of n°107)")),
        Spec(rid(346, "F2"), "F2 = ∫w'² ds = wλ + G_2 of the rhombus blade", src("n°110 with n°23 (81)", None), "F_2",
             lambda deps: derivation.F2_rhombus(_d(deps, rid(81, "F2G2")), _d(deps, WL), _d(deps, G2)),
             deps=(rid(81, "F2G2"), WL, G2), check=truth.on_shot(truth.F(2), "F2 = ∫w'² ds"),
             note=NOTE.format(what="(81) at K = 0 with the signed G_2 = −(346)")),
        Spec(rid(346, "F4"), "F4 = ∫w'⁴ ds of the rhombus blade (an integral in x)", src("n°110 with n°93 (282)", None),
             "F_4", lambda deps: derivation.slope_integral(4, _constants(deps)), deps=CONSTANTS,
             check=truth.on_shot(truth.F(4), "F4 = ∫w'⁴ ds"),
             note=NOTE.format(what="w' of (336) with the constants (340), (342), ds from (334) on each half; no closed "
                                   "form: the form is the integral over x_0 ≤ x ≤ x_1, evaluated by quadrature")),
        Spec(rid(346, "C"), "C = (wλ − F4)/(wλ − F2) of the rhombus blade", src("n°110 with n°93 (284)", None), "C",
             lambda deps: derivation.C_rhombus(_d(deps, rid(284, "C_F2")), _d(deps, WL), _d(deps, rid(346, "F2")),
                                               _d(deps, rid(346, "F4"))),
             deps=(rid(284, "C_F2"), WL, rid(346, "F2"), rid(346, "F4")),
             check=truth.on_shot(truth.C, "C = (wλ − F4)/(wλ − F2)"),
             note=NOTE.format(what="(284) with wλ of (343), F2, F4 above")),
    )
