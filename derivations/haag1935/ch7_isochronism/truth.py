"""Haag 1935, chapter VII, n°92–93 and n°97: the independent truths, on chapter VII's gravity pendulum
(:mod:`..ch7_gravity.truth`: a = a1 + ελ with a1 where det K = 0 of the directly solved blade).

- The isochronism error (283): the slow principal oscillation of amplitude θ0 on the exact large-deflection blade
  (``pendsym.nonlinear_blade.orbit(..., mode="slow")``: the collocation started from the *slow* mode of the linear
  eigenproblem, not from the mode whose node is lowest, which near a1 is the fast one); T(θ0)/T_lin − 1 with
  T_lin = 2π/n of that linear slow mode.  Along the path
  θ0 = ε/10 (so that the next amplitude term, relative θ0²G ~ ε/100, falls like ε).  Four collocation nodes:
  five agree with them to 28 digits of T/T_lin at ε = 1e-2 (tests), 35 digits at 45-digit precision and ε = 1e-3;
  ΔT/T ~ 1e-7–1e-6 then holds 21 digits or more, far below the O(ε) residual the checks fit.  Cached on disk
  (pendsym.cache).
- The perturbations of (281) and n°97, made linear in the motion so that each only moves the slow mode's n²:
  d log n²/dκ at κ = 0 by a 5-point stencil of the eigenproblem, for a vertical force on the pendulum (ε1 = κ:
  g(1 + κ), M/(1 + κ), the sensitivity of :func:`..ch7_gravity.truth.sensitivity`), a horizontal one
  (ε2 = κθ), a couple (ε3 = κθ) and a stiffer blade (E(1 + κ), the law (137) at q = 0).
"""
from __future__ import annotations

import functools

import mpmath as mp

from pendsym import cache, keys, nonlinear_blade, suspension
from ..ch7_gravity import truth as gravity

VERSION = "1"
NODES = 4
AMPLITUDE_OVER_EPS = "0.1"            # θ0 = ε/10 along the path
ORBIT_TRUTH = ("the slow principal oscillation on the exact large-deflection blade (pendsym.nonlinear_blade's "
               "elastica and collocation, 4 nodes, started from the slow linear mode), a = a1 + ελ with a1 of the "
               "directly solved blade; T(θ0)/T_lin − 1 along θ0 = ε/10")


def amplitude(eps) -> mp.mpf:
    return mp.mpf(eps) * mp.mpf(AMPLITUDE_OVER_EPS)


def _slow_omega_ratio(key: str, eps: str, theta0: str, dps: int, nodes: int) -> mp.mpf:
    """Ω/Ω_lin of the slow principal oscillation (Ω = ω², Ω_lin = n² of the linear slow mode)."""
    bl = gravity.base_blade(key, 1)
    env = gravity.numbers(key, 1, dps)
    with mp.workdps(nonlinear_blade.working_dps(bl, dps)):
        a = env["a_1"] + mp.mpf(eps) * env["lambda"]
        slow = min(suspension.modes(suspension.solve(bl, dps), a, env["R"], env["g"]), key=lambda mode: mode.n2)
        o = nonlinear_blade.orbit(bl, a, env["R"], env["g"], mp.mpf(theta0), nodes, dps, mode="slow")
        return o.omega2 / slow.n2


def relative_change(key: str, eps, dps: int = 30, nodes: int = NODES) -> mp.mpf:
    """T(θ0)/T_lin − 1 of the slow principal oscillation at a = a1 + ελ, θ0 = ε/10; cached on disk."""
    eps_text = mp.nstr(mp.mpf(eps), 40)
    theta_text = mp.nstr(amplitude(eps), 40)
    digest = keys.digest(("ch7_isochronism.slow_orbit", VERSION, keys.FORMAT, *keys.versions(),
                          keys.file_hash(keys.module_file(__name__)),
                          keys.file_hash(keys.module_file(nonlinear_blade.__name__)),
                          keys.file_hash(keys.module_file(gravity.__name__)), key, eps_text, theta_text, str(dps),
                          str(nodes)))
    ratio = cache.memo(digest, lambda: _slow_omega_ratio(key, eps_text, theta_text, dps, nodes))
    with mp.workdps(dps + 10):
        return 1 / mp.sqrt(ratio) - 1


# ---------------------------------------------------------------- linear perturbations of the slow mode
KINDS = ("eps1", "eps2", "eps3", "stiffer")


def _slow_n2(sus, a, R, g, extra=None) -> mp.mpf:
    """n² of the slow mode of K q = n² 𝕄 q, K the pendulum's stiffness plus ``extra`` (2×2)."""
    with mp.workdps(sus.wdps):
        K = suspension.stiffness_matrix(sus, a, 1, g)
        if extra is not None:
            K = K + extra
        ev, _ = mp.eig(mp.inverse(suspension.mass_matrix(a, R)) * K)
        return min(mp.re(x) for x in ev)


@functools.lru_cache(maxsize=256)
def log_n2_slope(key: str, kind: str, eps, dps: int = 30) -> mp.mpf:
    """d log n²/dκ of the slow mode at κ = 0, a = a1 + ελ, 5-point stencil in κ (step of
    :func:`..ch7_gravity.truth.stencil_step`):

    - eps1: ε1 = κ (X = 1 + κ): g(1 + κ) and M/(1 + κ), i.e. −G of :func:`..ch7_gravity.truth.sensitivity`;
    - eps2: ε2 = κθ in (89): the row of Y loses gκ on θ, the row of the moments about A agκ;
    - eps3: ε3 = κθ in (90): the row of the moments loses gκ on θ;
    - stiffer: E(1 + κ), M(1 + κ) (the blades M/(1 + kh) of the sensitivity's stencil, read backwards)."""
    if kind == "eps1":
        return -gravity.sensitivity(key, 1, eps, dps)
    env = gravity.numbers(key, 1, dps)
    base = gravity.direct(key, 1, 0, dps)
    with mp.workdps(base.wdps):
        a = env["a_1"] + mp.mpf(eps) * env["lambda"]
        R, g = env["R"], env["g"]
        step = gravity.stencil_step(env, eps)
        h = suspension.number(step)

        def log_n2(k):
            if kind == "stiffer":
                # M/(1 + kh): κ = −kh to the first order; the stencil's derivative in k is −d/dκ exactly at 0
                return -mp.log(_slow_n2(gravity.direct(key, 1, k, dps, step), a, R, g))
            pattern = {"eps2": mp.matrix([[0, 1], [0, a]]), "eps3": mp.matrix([[0, 0], [0, 1]])}[kind]
            return mp.log(_slow_n2(base, a, R, g, -g * k * h * pattern))
        return (8 * (log_n2(1) - log_n2(-1)) - (log_n2(2) - log_n2(-2))) / (12 * h)
