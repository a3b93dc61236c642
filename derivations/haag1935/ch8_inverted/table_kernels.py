"""Haag 1935, chapter VIII: n² and K of the inverted uniform blade stated in ε = (a1 − a)/λ (312), for the
kernels (:mod:`.kernels`); checked against the eigenproblem of the directly solved inverted blade."""
from __future__ import annotations

import functools

import mpmath as mp
import sympy as sp

from pendsym import checks, suspension
from pendsym.result import Spec

from ..common import rid, src
from . import kernels, truth

EPS_POINTS = ("1/1000", "1/10", "2/5")     # ε: near the critical distance, and up to the kernel's ε ≤ 1/2
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
             note="Not printed: (36) with u → iu (n°101), z as for n², a = a1 − ελ: K = −ελS/(D(2R² + S)) < 0 (302). "
                  "Its kernel (kernels.K_EPS_KERNEL) is not asked for: the form the engine emits measured 0.83 scaled "
                  "on the derive's sample but 5.02 in make audit (ε = 9.1e-7, u = 2.066), 3.5–3.9 ulp on random "
                  "points of every part of the window."),
    )
