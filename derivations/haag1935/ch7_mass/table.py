"""Haag 1935, chapter VII, n°96: the blade's inertia and weight in the gravity pendulum (291)–(294), the Results."""
from __future__ import annotations

from pendsym import checks
from pendsym.result import Spec

from ..common import READ_VW, rid, src
from ..symbols import DEFS, a, wl
from . import derivation, printed, truth
from .printed import READ_294, READ_BETA, READ_K

NEAR_ZERO = ("Order in ε of the residual against the blade with mass at a = a1 + ελ (m'/m = 10⁻²⁰, its second order "
             "negligible): the principal part leaves O(ε) relative.")
PRINCIPAL_A = ((a, -wl),)          # α'a at its principal part: a → a1 = −wλ (41), (256)


def specs() -> tuple[Spec, ...]:
    return (
        Spec(rid(291, "inertia"), "ΔT/T of the blade's inertia, uniform blade, ε → 0", src(96, "291"),
             r"\frac{\Delta T}{T}", derivation.inertia_291,
             deps=(rid(135, "inertia"), rid(260, "K_foci"), rid(260, "K"), rid(257, "zp"), rid(182, "I"),
                   rid(159, "w0")),
             printed=printed.inertia_291, defs=DEFS, check=truth.mass_order("inertia", "u=2"),
             note="(135) with z − z' = ελ/K (260), K of (260) → 0, z' → w0 (257), I_λ of (182) at K → 0, w0 of (159): "
                  "the limit ε → 0 is finite (\"indépendante du coefficient de sensibilité\"). " + NEAR_ZERO),
        Spec(rid(292, "weight"), "ΔT/T = −(m'/m)J/(ελ) of the blade's weight", src(96, "292"), r"\frac{\Delta T}{T}",
             derivation.weight_292, deps=(rid(136, "weight"), rid(45, "Q"), rid(260, "K_foci")),
             printed=printed.weight_292,
             check=truth.mass_order("weight", "u=2", scaled=True),
             note="(136) with Q = K(z − z') (45) = ελ by (260). J by quadrature at K = 0 on the shot blade (uniform "
                  "density); chapter I's tapered blade would cost 50 s more (odefun on a varying M). " + NEAR_ZERO),
        Spec(rid(293, "weight"), "ΔT/T = −(m'/(8mε))(1/u² − U1²), uniform blade", src(96, "293"),
             r"\frac{\Delta T}{T}", derivation.weight_293, deps=(rid(292, "weight"), rid(183, "J"), rid(260, "K")),
             printed=printed.weight_293, defs=DEFS, check=truth.mass_order("weight", "u=2", scaled=True),
             note="(292) with J of (183) at K of (260): the principal part keeps J at K = 0. " + NEAR_ZERO),
        Spec(rid(294, "dwl"), "dwλ = αλ(1 − wλ²/Mλ) + (β + 4α)G2 per degree", src(96, None), r"dw_\lambda",
             derivation.dwl_warming, deps=(rid(52, "dwl"), rid(57, "dwl")), printed=printed.dwl_warming,
             readings=(READ_K, READ_BETA, READ_VW), check=checks.Chain((rid(294, "depsilon"),)),
             note="(52)·αλ + (57) with ε(s) = β + 4α; ∫w²/M = G2 at K = 0 (79)."),
        Spec(rid(294, "depsilon"), "dε/ε = (α'a + dwλ)/(ελ) per degree, principal part", src(96, None),
             r"\frac{d\varepsilon}{\varepsilon}", derivation.depsilon_294, deps=(rid(294, "dwl"),),
             printed=printed.depsilon, defs=PRINCIPAL_A, readings=(READ_K, READ_BETA, READ_VW),
             check=truth.critical_change(),
             note="ε = (a + wλ)/λ differentiated (da = α'a, dλ = αλ), a = a1 + ελ: the principal part has α'a1 = "
                  "−α'wλ, so the printed α'a is compared with a → a1 = −wλ. The truth: ε = (a − a1)/λ with a1 of "
                  "the warmed massless blade."),
        Spec(rid(294, "minus2"), "dε/ε = −2 dT/T", src(96, None), r"\frac{d\varepsilon}{\varepsilon}",
             derivation.depsilon_minus2, deps=(rid(294, "depsilon"), rid(270, "dT")), printed=printed.depsilon_minus2,
             check=truth.critical_change(),
             note="\"En comparant avec (270)\": the derived dε/ε over (270) is the number found here. dT/T of the "
                  "truth in the form."),
        Spec(rid(294, "dT"), "d(ΔT)/T = 3(ΔT/T)(dT/T), the weight's perturbation warmed", src(96, "294"),
             r"\frac{d(\Delta T)}{T}", derivation.period_294, deps=(rid(292, "weight"), rid(294, "minus2")),
             printed=printed.period_294, readings=(READ_294,), check=truth.temperature_order("relation"),
             note="d log ΔT = dT/T + d log(ΔT/T), ΔT/T ∝ 1/ε by (292) (J, λ, m'/m vary by O(α), dropped: \"partie "
                  "principale\"). Truth: ΔT = T − T0 of the blade with weight, warmed by ε/1000 degree, against "
                  "the form at the truth's ΔT/T and dT/T; relative residual."),
        Spec(rid(294, "ratio"), "[d(ΔT)/T]/(dT/T) = −3m'J/(mελ)", src(96, None),
             r"\frac{d(\Delta T)/T}{dT/T}", derivation.ratio_294, deps=(rid(294, "dT"), rid(292, "weight")),
             printed=printed.ratio_294, check=truth.temperature_order("ratio"),
             note="\"Le rapport de la nouvelle perturbation thermique à l'ancienne\": (294) over dT/T with (292)."),
    )
