"""Haag 1935, chapter VII, n°86, 88–90: g' − g (269), the launching (274)–(276), the shape (277) and the
fatigue (279) of the gravity pendulum with direct suspension."""
from __future__ import annotations

from pendsym.result import Spec

from ..common import rid, src
from . import checks_launch, derivation_launch as derivation, printed_launch as printed
from .printed import READ_GPRIME


def specs() -> tuple[Spec, ...]:
    return (
        Spec(rid(269, "dg"), "g' − g = lπ²(1/T'² − 1/T²), u small", src(86, "269"), "g' - g",
             derivation.g_difference_269, deps=(rid(268, "period"), rid(159, "wl")), printed=printed.g_difference_269,
             check=checks_launch.g_difference(),
             note="(268) is linear in g: g' − g = π²(1/T'² − 1/T²)/c, c = (1/l)(1 + λ/(3a)) with the derived "
                  "gλ/(3al) of (267); λ/(3a) → −u²/3 as u → 0 (a ≈ a1 = −λ/u²), so that cl → 1: the printed form "
                  "is the limit, with a relative error u²/3 (fitted order 2). l < 0 here (Haag's footnote)."),
        Spec(rid(274, "A"), "A = (Q/mg)FF'·BF'/(ελ), release from the static deviation", src(88, "274"), "A",
             derivation.amplitude_274, deps=(rid(68, "A"), rid(260, "K_foci")), printed=printed.amplitude_274,
             readings=(printed.READ_MG_PRIME, printed.READ_BARS), check=checks_launch.launch_order("A"),
             note="(68) with K of (260); FF' = z' − z, BF' = a + z' − b."),
        Spec(rid(274, "Ap"), "A' = (Q/mg)β1·FB/FF'", src(88, "274"), "A'", derivation.amplitude_prime_274,
             deps=(rid(68, "Ap"), rid(261, "Kp")), printed=printed.amplitude_prime_274,
             readings=(printed.READ_MG_PRIME, printed.READ_BARS), check=checks_launch.launch_order("Ap")),
        Spec(rid(275, "ratio"), "A/A' = (BF'/FB)FF'²/(ελβ1)", src(88, "275"), "A/A'", derivation.ratio_275,
             deps=(rid(274, "A"), rid(274, "Ap")), printed=printed.ratio_275, readings=(printed.READ_BARS,),
             check=checks_launch.launch_order("ratio")),
        Spec(rid(276, "ratio"), "A/A' = (BF'/FB)R·FF'/(z'√(ελβ1)) after a blow", src(88, "276"), "A/A'",
             derivation.ratio_276, deps=(rid(73, "ratio"),), printed=printed.ratio_276, readings=(printed.READ_BARS,),
             check=checks_launch.launch_order("blow"),
             note="(73) with a − a1 = ελ and a + z − vλ = z − z' + O(ε) ((33): a + z' − vλ = −β1ελ/(a + z − vλ))."),
        Spec(rid(277, "y"), "y = θ(w − w0): the shape when Y is negligible", src(89, "277"), "y", derivation.shape_277,
             deps=(rid(77, "y"),), printed=printed.shape_277, readings=(printed.READ_SHAPE,),
             check=checks_launch.along("shape"), note="(77) with Y = Kθ → 0 (K = O(ε), (260))."),
        Spec(rid(279, "T_I"), "T' = θmg·ew/(2I)", src(90, "279"), "T'", derivation.fatigue_279_I, deps=(rid(78, "T_I"),),
             printed=printed.fatigue_279_I, readings=(printed.READ_OMEGA,), check=checks_launch.along("stress"),
             note="(78) with Y → 0; I = mgM/E (1) in the check."),
        Spec(rid(279, "T_M"), "T' = θE(e/2)w/M", src(90, "279"), "T'", derivation.fatigue_279_M, deps=(rid(78, "T_M"),),
             printed=printed.fatigue_279_M, readings=(printed.READ_OMEGA,), check=checks_launch.along("stress")),
    )
