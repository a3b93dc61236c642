"""Haag 1935, chapter VIII, n°103, eq. (318): the clamping errors of the inverted uniform blade, the Result."""
from __future__ import annotations

from pendsym.result import Spec

from ..common import rid, src
from . import derivation, printed, truth
from .truth import INVERTED, REGULATED


def specs() -> tuple[Spec, ...]:
    return (
        Spec(rid(318, "dT"), "ΔT/T of the clamping errors, regulated, the inverted uniform blade", src(103, "318"),
             r"\frac{\Delta T}{T}", derivation.dT_318, deps=(rid(289, "dT"),), printed=printed.dT_318,
             readings=(printed.READ_318_IJ, printed.READ_EPS_318),
             check=truth.period_order(INVERTED, -1, REGULATED, "j = the exact θ"),
             note="(289) with u → iu (n°101, M < 0) and ε → −ε (312), in tan(u/2) and u. The truth is the inverted "
                  "blade itself (M < 0, g < 0, a = a1 − ελ), on u = 1/2: at u = 1 the printed and the derived ij "
                  "coefficients happen to coincide (tan(u/2)/(u sin³u) = tan(u/2)/sin³u)."),
    )
