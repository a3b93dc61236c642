"""Haag 1935, chapter VII, n°84–85: the figure of the sensitivity coefficient G against u.

G of the uniform blade near the critical distance, (263) and its u-small form (264), derived, against the
truth: G = −d log n²/d log g of the slow mode of the directly solved pendulum at a = a1 + ελ (:mod:`.truth`).
"""
from __future__ import annotations

import mpmath as mp
import sympy as sp

from pendsym.figure import Axis, Curve, Figure
from ..common import rid
from . import truth

EPS = "1e-4"          # a − a1 = ελ (256)
FORM_POINTS = tuple(mp.nstr(mp.mpf(10) ** (-1 + 2 * mp.mpf(i) / 39), 6) for i in range(40))     # u = 0.1 … 10
TRUTH_POINTS = ("0.1", "0.2", "0.4", "0.7", "1", "1.5", "2", "3", "5", "10")


def env(u) -> dict:
    return {"u": u, "varepsilon": mp.mpf(EPS)}


def sensitivity(u, dps) -> mp.mpf:
    """G of the truth at u (the uniform blade "u=<rational>", direct suspension)."""
    return truth.sensitivity(f"u={sp.nsimplify(mp.nstr(u, 12), rational=True)}", 1, EPS, dps)


SENSITIVITY = Figure(
    id="haag1935.fig.sensitivity", module=__name__,
    title="The sensitivity coefficient G against u",
    caption=("The gravity pendulum with direct suspension near the critical distance, a − a₁ = ελ (256) with "
             "ε = 10^(-4) (n°82–85): G = 2 d log T/d log g of the uniform blade against u = λω. The derived (263) is "
             "the principal part in ε: the truth lies below it by about 1 (the −1 of G = −1 + G₂/Q, (62)), "
             "invisible at this scale. (264), G = 1/(εu²), holds for u ≪ 1 only."),
    x=Axis("u", log=True, lo=0.1, hi=10), y=Axis("G", log=True),
    curves=(Curve("(263) derived", "derived", FORM_POINTS, result=rid(263, "G"), env=env),
            Curve("(264) derived, u small", "derived", FORM_POINTS, result=rid(264, "G"), env=env, style="dashed"),
            Curve("truth", "truth", TRUTH_POINTS, truth=sensitivity, style="marks",
                  describe="G = −d log n²/d log g of the slow mode by a 5-point stencil in g, on the blade solved "
                           "directly and the eigenproblem K q = n² 𝕄 q (chapter VII truth: pendsym.suspension, mpmath "
                           "eig); λ = 10 cm, R = 5 cm")),
    after=rid(264, "G"), dps=20)

FIGURES = (SENSITIVITY,)
