"""Haag 1935, chapter II, n°29: the figure of the period against the amplitude.

T(θ0)/T_lin − 1 of the principal oscillation on the exact large-deflection blade (:mod:`pendsym.nonlinear_blade`),
against chapter II's (111) derived (ΔT/T = (Q'/Q)θ0²/16 with Q' of (112)) and the rigid pendulum's exact period
(θ0²/16 at the first order: what the blade changes is the coefficient Q'/Q).  The case is (111)'s check
(:data:`.truth.CASE`: the uniform blade under the compact pendulum, where the blade matters most); the truth's
amplitudes are those its order check solves (cached by their inputs, :func:`pendsym.nonlinear_blade.track`) and
two more, θ0 = 0.01 and 0.05, which alone cost cold solves.
"""
from __future__ import annotations

import mpmath as mp

from pendsym import checks
from pendsym.figure import Axis, Curve, Figure

from ..common import rid
from . import truth

EXTRA = ("0.01", "0.05")             # the amplitudes the check does not solve (it stays below 0.002)
FORM_POINTS = tuple(mp.nstr(mp.mpf("0.0003") * mp.mpf("200") ** (mp.mpf(i) / 29), 6) for i in range(30))  # 3e-4 … 0.06


CHECK_DPS = 15     # checks.Order draws its amplitudes outside any workdps: at mpmath's default 15 digits


def _check_amplitudes() -> list:
    """The amplitudes of (111)'s order check, as the check makes them (the figure samples its truths inside
    workdps(30), where verify.geometric would give other numbers, and other cache keys)."""
    with mp.workdps(CHECK_DPS):
        return list(truth.amplitudes("full"))


def truth_points() -> tuple[str, ...]:
    """The abscissae of the exact blade: the order check's amplitudes (as 17-digit decimals) and EXTRA."""
    return tuple(mp.nstr(x, 17) for x in _check_amplitudes()) + EXTRA


def _amplitude(x):
    """The order check's own amplitude object nearest x (so that the cached solve is found), or x itself."""
    for theta0 in _check_amplitudes():
        if abs(mp.mpf(theta0) - x) <= mp.mpf(10) ** -12 * x:
            return theta0
    return x


def exact_blade(x, dps):
    """T(θ0)/T_lin − 1 on the exact blade (the truth of (111))."""
    return truth.relative_change(*truth.CASE)(_amplitude(x), dps)


def formula_env(x) -> dict:
    """The modes' K, z, z', a and the shot blade's F_n of (111)'s check, at θ0 = x."""
    return dict(truth.blade_env(*truth.CASE, checks.DPS), theta_0=x)


PERIOD = Figure(
    id="haag1935.fig.period_amplitude", module=__name__,
    title="The period against the amplitude on an elastic blade",
    caption=("T(θ0)/T_lin − 1 of the principal oscillation, the uniform blade u = 2 (λ = 10 cm) under the compact "
             "pendulum (a = 12 cm, R = 5 cm): the exact large-deflection blade (marks), chapter II's (111) with Q' of "
             "(112) (line) and the rigid pendulum's exact period (dashed). The blade lowers the coefficient of θ0²/16 "
             "from 1 to Q'/Q; the residual of (111) falls as θ0⁴ (its check)."),
    x=Axis(r"\theta_0", log=True, lo=0.0003, hi=0.06), y=Axis(r"T/T_{\mathrm{lin}} - 1", log=True),
    curves=(Curve("(111) derived", "derived", FORM_POINTS, result=rid(111, "dT"), env=formula_env),
            Curve("rigid pendulum, exact", "truth", FORM_POINTS, truth=truth.rigid_relative, style="dashed",
                  describe="2K(sin²(θ0/2))/π − 1, the rigid pendulum θ'' + n² sin θ = 0 (mpmath ellipk)"),
            Curve("exact blade", "truth", truth_points(), truth=exact_blade, style="marks",
                  describe=truth.NONLINEAR_TRUTH + "; uniform blade u = 2, compact pendulum")),
    after=rid(112, "Qp"), dps=checks.DPS)

FIGURES = (PERIOD,)
