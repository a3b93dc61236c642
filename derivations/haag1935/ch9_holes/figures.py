"""Haag 1935, chapter IX, n°110: the figure of G_2 against k for the rhombus hole, (346).

The printed (346), the derived (346) and the truth (G_2 = ∫ w²/|M| ds on the shot blade, :mod:`.rhombus_truth`, no
Bessel function) at ω, λ fixed, k from 10⁻⁸ to 10³, on log axes; and the emitted kernel of G_2/λ in u = ωλ, q = kλ
(Result eq346.G2_u_q, :mod:`.rhombus_g2_kernel`) over its domain q ≤ 5 (no points beyond: it raises there).
λ = 1, so that G_2/λ is G_2.
"""
from __future__ import annotations

import mpmath as mp
import sympy as sp

from pendsym.figure import Axis, Curve, Figure
from ..common import rid
from . import rhombus_truth as truth

M0, LAMBDA = "1/2", "1"       # ω = √2, ωλ = 1.41 < π; λ = 1 so that the kernel of G_2/λ draws G_2
FORM_POINTS = tuple(mp.nstr(mp.mpf(10) ** (-8 + 11 * mp.mpf(i) / 32), 6) for i in range(33))     # k = 1e-8 … 1e3
TRUTH_POINTS = ("1e-8", "1e-6", "1e-4", "0.001", "0.01", "0.1", "1", "10", "100", "1000")


def rational(x) -> str:
    return str(sp.nsimplify(mp.nstr(x, 12), rational=True))


def env(k) -> dict:
    """ω, k, λ and x_0, x_1 of (334) at k (the memoir's symbols, as the forms take them), and the kernel's u = ωλ, q = kλ."""
    out = truth.environment(M0, "1", LAMBDA)
    out["k"] = k
    out["x_0"] = 2 * out["omega"] / k
    out["x_1"] = out["x_0"] * mp.sqrt(1 + k * out["lambda"] / 2)
    out["u"], out["q"] = out["omega"] * out["lambda"], k * out["lambda"]
    return out


def G2(k, dps) -> mp.mpf:
    """G_2 of the shot blade at k (:func:`.rhombus_truth.G2`)."""
    return truth.G2(truth.shot(M0, rational(k), LAMBDA, dps))


def beta1(k, dps) -> mp.mpf:
    """β_1 of the shot blade at k: the blade is stable while it is negative (304)."""
    sol = truth.shot(M0, rational(k), LAMBDA, dps)
    with mp.workdps(sol.wdps):
        return sol.beta1


G2_RHOMBUS = Figure(
    id="haag1935.fig.rhombus_G2", module=__name__,
    title="G₂ of the rhombus hole against k: printed, derived, stable kernel, truth",
    caption=("The inverted blade with a rhombus hole, M = M₀(1 + k|s|) (n°107–110), ω = 1/√M₀ = √2, λ = 1: the "
             "sensitivity integral G₂ of (346) against k. The printed (346) is wrong (a finding: its terms ω²/k and "
             "½(D₁/D + D'₁/D') are not lengths): it grows like (ω² − 1)/k as k → 0, where the derived form and the "
             "truth tend to the uniform blade's G₂. The derived form, evaluated at enough digits, agrees with the "
             "truth; in double precision it loses about log10(1/k) digits as k → 0: the arguments x₀ ~ 2ω/k of the Bessel "
             "functions are rounded (a phase error of x₀·2⁻⁵³) and the terms of (346) cancel (those of order 1/k). "
             "With the arguments as double-doubles, v₀, w₀, w_λ hold to a few ulp down to k = 1e-8, but (346) still "
             "cancels. A stable form of G₂/λ in u = ωλ, q = kλ is derived (a sum of positive terms: quadratures of "
             "squared cross products of Bessel functions over the gap x₁ − x₀, every sum and product after the cross "
             "products compensated) and emitted as a kernel within 4 ulp × max(1, κ) for q = kλ from 1e-8 to 5; "
             "the stable-kernel curve ends at the last k below 5, its domain's end, where its 12-point quadrature "
             "stops being shown accurate (its cross products hold further, the kernels of (343) are declared to "
             "q = 1000: a gap of the kernel, not of the blade: see below). "
             "The blade stays stable (β₁ < 0, (304)) for every k: "
             "at ω, λ fixed the hole only stiffens it away from its middle, so there is no largest stable k; the "
             "axis stops at k = 1000 (M at the ends 501 M₀)."),
    x=Axis("k", log=True, lo=1e-8, hi=1e3), y=Axis("G_2", log=True),
    curves=(Curve("(346) printed", "printed", FORM_POINTS, result=rid(346, "G2"), env=env, style="dashed"),
            Curve("(346) derived", "derived", FORM_POINTS, result=rid(346, "G2"), env=env),
            Curve("stable kernel", "kernel", FORM_POINTS, result=rid(346, "G2_u_q"), env=env),
            Curve("truth", "truth", TRUTH_POINTS, truth=G2, style="marks",
                  describe=f"G₂ of the {truth.BLADE}, M₀ = {M0}, λ = {LAMBDA}")),
    dps=15, form_dps=40)

FIGURES = (G2_RHOMBUS,)
