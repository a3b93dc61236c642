"""Haag 1935, chapter VIII, n°100–102: the figure of the stability windows of the inverted uniform blade.

Both n² of the eigenproblem K q = n² 𝕄 q (:mod:`.truth`: the blade solved directly, g < 0) against the
pendulum's weight in units of P, the limit (311): mg ∝ u² at a given blade (156) and P is the weight at
u = π/2, so mg/P = (2u/π)².  The pendulum is stable where both n² are positive, (304) and (305); Haag's
window ends (309) and the footnote of n°102 (4P, 32.7P, 36P) are marked.
"""
from __future__ import annotations

import functools

import mpmath as mp

from pendsym.figure import Axis, Curve, Figure, Mark
from ..common import rid
from . import truth

A_FIGURE = "-1"       # a (m): far below the blade, so that the upper ends approach (2n + 1)π (they tend to it as a → −∞)

# mg/P: dense where an n² crosses zero or passes through infinity (3.92, 32.73, 35.92 at a = −1 m, and about
# u = 2π, mg/P = 16, where w0 is infinite), never at u = 2π itself
POINTS = ("0.25", "0.5", "1", "1.5", "2", "2.5", "3", "3.4", "3.7", "3.85", "3.9", "3.93", "3.96", "4", "4.05",
          "4.2", "4.6", "5.5", "7", "9", "11", "13", "14.5", "15.5", "15.8", "15.9", "15.95", "15.99", "16.01", "16.05",
          "16.2", "16.6", "17.5", "19", "22", "25", "28", "30", "31.5", "32.3", "32.6",
          "32.7", "32.76", "32.85", "33.1", "33.6", "34.3", "35", "35.5", "35.8", "35.9", "35.93", "35.96", "36",
          "36.05", "36.3", "37", "38.5", "40")


def u_of(weight_ratio) -> mp.mpf:
    """u = (π/2)√(mg/P): (156) with P the weight at u = π/2 (311)."""
    return mp.pi / 2 * mp.sqrt(weight_ratio)


@functools.lru_cache(maxsize=256)
def modes(weight_ratio: str, dps: int) -> tuple:
    """The two n² (increasing) of the inverted uniform blade at mg/P, a = A_FIGURE (s⁻²)."""
    with mp.workdps(dps):
        return tuple(sorted(truth.eigenvalues(u_of(mp.mpf(weight_ratio)), mp.mpf(A_FIGURE), dps)))


def n2(which: int):
    def value(x, dps):
        return modes(mp.nstr(x, 12), dps)[which]
    return value


MODEL = (f"the eigenproblem K q = n² 𝕄 q of the inverted uniform blade solved directly (chapter VIII truth: "
         f"pendsym.suspension, mpmath eig), λ = 10 cm, R = 5 cm, a = {A_FIGURE} m, g = −9.81 m/s²")

WINDOWS = Figure(
    id="haag1935.fig.windows", module=__name__,
    title="Stability windows of the inverted blade: n² against the weight",
    caption=("The inverted uniform blade (n°100–102, (304)–(311)): the two n² of the pendulum against its weight mg "
             "in units of P, the limit (311) (mg/P = (2u/π)², (156)). Both vibrations exist, and the pendulum is "
             "stable, where the smaller n² is positive ((304) β₁ < 0 and (305) a < a₁). The smaller n² crosses zero at "
             "the upper end of each window and passes through −∞ at the lower end 2x₁ (β₁ = 0), where the larger "
             "comes down from +∞; values off the frame are drawn at its edge. Dotted: Haag's ends 4P, 32.7P, 36P "
             "(u = π, 2x₁, 3π, the footnote of n°102); the upper ends (2n + 1)π are those of (308) alone and are "
             "reached as a → −∞: at a = −1 m, (305) closes each window slightly before them. Near 16P (u = 2π, where w₀ is infinite) the larger n² "
             "also dips below zero and passes through infinity, inside the unstable band."),
    x=Axis("mg/P", lo=0, hi=40), y=Axis(r"n^2\ (\mathrm{s}^{-2})", lo=-15, hi=20),
    curves=(Curve("smaller n²", "truth", POINTS, truth=n2(0), describe=f"the smaller eigenvalue of {MODEL}",
                  style="line"),
            Curve("larger n²", "truth", POINTS, truth=n2(1), describe="the larger eigenvalue of the same",
                  style="dashed")),
    marks=(Mark(4, "4P"), Mark(32.7, "32.7P"), Mark(36, "36P")),
    after=rid(309, "weights"), dps=15)

FIGURES = (WINDOWS,)
