"""Haag 1935, chapter VIII: n² and K of the inverted uniform blade stated in ε = (a1 − a)/λ (312), for the
kernels (:mod:`.kernels`), checked against the eigenproblem of the directly solved inverted blade; and C of (317)
on the window n = 1 of (309), checked against the shot blade's quadratures."""
from __future__ import annotations

import functools

import mpmath as mp
import sympy as sp

from pendsym import checks, suspension
from pendsym.result import Spec

from ..ch7_gravity import truth as gravity_truth
from ..common import rid, src
from . import kernels, truth

EPS_POINTS = ("1/1000", "1/10", "2/5")     # ε: near the critical distance, and above the kernels' ε ≤ 1/4
BLADES = truth.N2_BLADES + ("u=5/2",)      # and above π/2, where a1 < 0 (311): the kernels' window is (0, π)


@functools.lru_cache(maxsize=32)
def node_mode(key: str, eps: str, dps: int = 30) -> tuple:
    """(n², K) of the vibration whose node is z' < 0 at a = a1 − ελ: the eigenproblem K q = n² 𝕄 q of the
    rigid pendulum on the directly solved inverted blade ``key`` (g < 0), K = −n²z'/g (34)."""
    sus = truth.truth.direct(key, truth.SIGN, 0, dps)
    with mp.workdps(sus.wdps):
        env = truth.truth.numbers(key, truth.SIGN, dps)
        a = env["a_1"] - mp.mpf(sp.Rational(eps)) * env["lambda"]
        n2, zp = min(truth.truth.eigenmodes(sus, a, env["R"], env["g"]), key=lambda pair: pair[1])
        return n2, -n2 * zp / env["g"]


def eps_check(which: int, what: str) -> checks.Values:
    def points(level, dps):
        for k in BLADES:
            for eps in EPS_POINTS:
                yield checks.Point(f"{k}, ε = {eps}", {"u": suspension.number(sp.Rational(k[2:])),
                                                       "lambda": suspension.number(truth.truth.LAMBDA),
                                                       "varepsilon": mp.mpf(sp.Rational(eps)),
                                                       "R": mp.mpf(truth.truth.R_VALUE),
                                                       "g": mp.mpf(truth.truth.G_VALUE)},
                                   node_mode(k, eps, dps)[which])
    return checks.Values(truth=f"{truth.truth.MODEL}; g < 0, M = −(λ/u)², λ = 1/10, R = {truth.truth.R_VALUE}, "
                               f"a = a1 − ελ (a1 where det K = 0); {what} of the mode whose node is above G (z' < 0)",
                         points=points, confirm=lambda dps: {"n2": node_mode(truth.N2_BLADES[0], EPS_POINTS[0], dps)[which]})


WINDOW1_US = ("9", "46/5", "47/5")     # inside the window n = 1, 2x1 = 8.987 < u < 3π = 9.425 (309); 9.4 near its end


@functools.lru_cache(maxsize=8)
def C_shot(key: str, dps: int = 30) -> mp.mpf:
    """(284): C = (wλ − ∫w'^4 ds)/(wλ − ∫w'^2 ds) of the shot inverted uniform blade ``key`` (M = −(λ/u)²)."""
    sol = gravity_truth.shot(key, -1, dps)
    with mp.workdps(sol.wdps):
        return (sol.wl - sol.F(4, 0)) / (sol.wl - sol.F(2, 0))


def window1_check() -> checks.Values:
    def points(level, dps):
        for x in WINDOW1_US:
            yield checks.Point(f"u={x}", {"u": suspension.number(sp.Rational(x)), "lambda": mp.mpf("0.1")},
                               C_shot(f"u={x}", dps))
    return checks.Values(truth="shot inverted uniform blade (pendsym.blade, M = −(λ/u)², λ = 1/10) at u inside the "
                               "window n = 1 (2x1 < u < 3π), wλ and ∫w'^n by Gauss–Legendre quadrature",
                         points=points, confirm=lambda dps: {"C": C_shot(f"u={WINDOW1_US[0]}", dps)}, kind="quadrature")


def C_window1(deps) -> sp.Expr:
    """(317) on the window n = 1 of (309): the derived C of (317) (dsolve with M < 0), whose kernel is declared on
    2x1 < u < 3π (:data:`.kernels.C_WINDOW1_KERNEL`); the claim checked is that (317) holds there too."""
    return deps[rid(317, "C")].derived


def specs() -> tuple[Spec, ...]:
    ends = (rid(159, "vl"), rid(159, "beta1"), rid(159, "wl"), rid(310, "a1"))
    return (
        Spec(rid(34, "n2_inverted_eps"), "n² of the inverted uniform blade at a = a1 − ελ (312), for the kernel",
             src(101, None), "n^2", kernels.n2_eps, deps=ends, check=eps_check(0, "the eigenvalue n²"),
             kernel=kernels.N2_EPS_KERNEL,
             note="Not printed: eq034.n2_inverted ((34), (36), (30), u → iu, g → −g) with a = a1 − ελ, its root z "
                  "written 2R²D/S (D = a − vλ > 0, S = P + √(P² + 4R²D²) without cancellation): n² = 2gελ/(2R² + S). "
                  "Stated in ε the existence condition (305) is ε > 0 for every u of the window (309)."),
        Spec(rid(36, "K_inverted_eps"), "K of (36) of the inverted uniform blade at a = a1 − ελ (312), for the kernel",
             src(101, "36"), "K", kernels.K_eps, deps=ends, check=eps_check(1, "K = −n²z'/g"),
             kernel=kernels.K_EPS_KERNEL,
             note="Not printed: (36) K = (a + wλ)/(a + z − vλ) with u → iu (n°101), a = a1 − ελ (a + wλ = −ελ) and "
                  "z = λζ, ζ the positive root of (30) over λ³ written without cancellation: K = −ε/(d + ζ) < 0 (302), "
                  "d = 1/(u sin u) − ε, r = R/λ.  Session 9's form −ελS/(D(2R² + S)) was split by the kernel engine "
                  "into a polynomial in ε, R, λ whose leaves in u cancel (make audit 5.02 scaled at ε = 9.1e-7, "
                  "u = 2.066): not emitted then."),
        Spec(rid(317, "C_window1"), "C of (317) on the window n = 1 (2x1 < u < 3π) of the inverted uniform blade",
             src(103, "317"), "C", C_window1, deps=(rid(317, "C"),), check=window1_check(),
             kernel=kernels.C_WINDOW1_KERNEL,
             note="Not printed as such: (317) is stated for the inverted blade, whose windows of stability are "
                  "2x_n < u < (2n + 1)π (309); the Result eq317.C carries the kernel of the window n = 0, this one "
                  "the kernel of the window n = 1 (one kernel per Result), checked there against the shot blade."),
    )
