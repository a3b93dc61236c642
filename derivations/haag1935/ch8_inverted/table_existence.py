"""Haag 1935, chapter VIII, n°100–102: the steps of the existence condition (302), (303), the positive distance
(306), the inequality (308) and the definition of ε (312)."""
from __future__ import annotations

from pendsym import checks
from pendsym.result import Spec

from ..common import READ_VW, rid, src
from . import derivation, printed, truth


def specs() -> tuple[Spec, ...]:
    return (
        Spec(rid(302, "signs"), "K < 0, K' > 0 when both vibrations exist (g → −g)", src(100, "302"),
             r"(K, -K') < 0", derivation.signs_302, deps=(rid(34, "n2"), rid(35, "K"), rid(30, "quadratic")),
             printed=printed.signs_302,
             check=truth.NegativeIffExists("K, −K', K = Y/θ of each mode (Y = S00β + S01θ of the direct stiffness)"),
             note="The derivation finds K = −n²R²/(gz) < 0 and K' = n'²z/g > 0 from (34) with g → −g and zz' = −R² "
                  "(30); the check takes K, K' of the modes from the stiffness, not from (34)."),
        Spec(rid(303, "signs"), "a + z' − vλ < 0 < a + z − vλ", src(100, "303"), r"(a + z' - v_\lambda, -(a + z - v_\lambda)) < 0",
             derivation.signs_303, deps=(rid(36, "K"),), printed=printed.signs_303, readings=(printed.READ_NU,),
             check=truth.NegativeIffExists("a + z' − vλ and −(a + z − vλ), z' < z the nodes of the modes, vλ of "
                                           "the shot blade", iff=False),
             note="The denominators of K and K' of (36), which share the numerator a + wλ: KK' < 0 (302) gives "
                  "them opposite signs.  A necessary condition only: with β1 > 0 and a + wλ > 0 (both n² < 0) "
                  "(33) gives them opposite signs too, so the check is the implication."),
        Spec(rid(306, "wl"), "wλ < 0 for a positive a", src(100, "306"), r"w_\lambda", derivation.sign_306,
             deps=(rid(304, "existence"),), printed=printed.sign_306, readings=(printed.READ_NU, READ_VW),
             check=truth.PositiveDistanceIff(),
             note="(305) a + wλ < 0 with a > 0; claimed negative."),
        Spec(rid(308, "inequality"), "tan(u/2) > u/2, the inverted uniform blade", src(101, "308"),
             r"\tan\frac{u}{2} - \frac{u}{2}", derivation.inequality_308, deps=(rid(307, "beta1"),),
             printed=printed.inequality_308, check=truth.PositiveIffStable(),
             note="(304) β1 < 0 with β1 of (307), times −u/(2λ); claimed positive."),
        Spec(rid(312, "epsilon"), "a1 − a = ελ (the inverted blade)", src(102, "312"), "a_1 - a",
             derivation.distance_312, printed=printed.distance_312, definition=True, check=checks.Definition()),
    )
