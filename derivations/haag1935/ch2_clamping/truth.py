"""Haag 1935, chapter II, n°31–35: the independent truth.

- The exact tilted equilibrium and the period of the principal small oscillation about it
  (:mod:`pendsym.nonlinear_tilt`: the large-deflection elastica under the exact statics with gravity at the
  angle i from the clamp's tangent and G at the angle i' from the tangent AT; the linearisation about that
  equilibrium, a 3 × 3 eigenproblem in the loads), at 30 digits, confirmed at 45.
  The equilibrium formulas (117)–(118) are first-order: the residual against the exact θ, β must fall like
  i³ (the equilibrium is odd in (i, i') by the mirror symmetry).  The change of period (134) is a quadratic
  form in i, i', j: the residual of T(i, i')/T(0, 0) − 1 − Q1/Q must fall like i⁴ (the period is even).
  i' = RATIO·i along the sequence, so that both errors and their product are exercised.
- (116): the exact trigonometric terms of the tilted (4)–(6) at a point scaled by p: residual O(p³).

The formulas take K, z, z' of the linear modes, F2 and the moments J(p, q) (for h (127) and h' (132)) of the
shot blade, and vλ, wλ, β1 of the shot blade (:mod:`..ch2_general.truth`).

Cost: one tilted solve (the equilibrium on the precision ladder of :func:`pendsym.nonlinear_tilt.equilibrium`,
then one Jacobian) is about 1 s CPU at 30 digits on the uniform blade; the checks share the four points of
the sequence and one 36-digit confirmation, cached by :func:`pendsym.nonlinear_tilt.tilted` (about 5 s CPU
cold for the group); T0 of the straight blade is the linear eigenproblem's (no tilted solve).
"""
from __future__ import annotations

import mpmath as mp
import sympy as sp

from pendsym import checks, nonlinear_blade, nonlinear_tilt, verify
from .. import profiles
from ..ch2_general import truth as general_truth
from . import derivation

CASE = ("uniform", "compact")           # as chapter II's other nonlinear checks
RATIO = mp.mpf("-0.6")                  # i' = RATIO·i
CONFIRM_DPS = 36                        # the truth at the first i recomputed at 36 digits


def tilts(level: str) -> list:
    """i of the order checks: four points in geometric progression (a factor 8), at both levels."""
    return verify.geometric("0.0005", "0.004", 4)
TILT_TRUTH = ("pendsym.nonlinear_tilt: the exact tilted equilibrium of the large-deflection blade and the "
              "principal small oscillation about it (eigenproblem of the exact linearisation), 30 digits")


def _tilted(i, dps):
    name, pend = CASE
    a, R, g = profiles.PENDULUMS[pend]
    i = mp.mpf(i)
    return nonlinear_tilt.tilted(profiles.profile(name), a, R, g, mp.nstr(i, 40), mp.nstr(RATIO * i, 40), dps)


def env_at(i) -> dict:
    """The formulas' inputs at the point i (i' = RATIO·i): the blade, the modes, the moments, j of (117)
    (derived) and h, h' of (127), (132) from the moments."""
    name, pend = CASE
    dps = checks.DPS
    env = dict(general_truth.blade_env(name, pend, dps))
    env.update(profiles.shot_env(name, dps))
    env.update(general_truth.moments(name, dps))           # J(p, q), by the applied function
    i = mp.mpf(i)
    env.update({"i": i, "i'": RATIO * i, "a_1": -env["w_lambda"]})
    env["j"] = verify.value_at(derivation.eq117_j(), env)
    env["h"] = verify.value_at(derivation.eq127(), env)
    env["h'"] = verify.value_at(derivation.eq132(), env)
    return env


def untilted_period(dps: int):
    """T0, the period of the small oscillation about the straight blade (i = i' = 0): the linear eigenproblem of
    pendsym.suspension, the limit the tilted solver reaches at i = i' = 0 (tests/test_nonlinear_tilt.py), without
    its two tilted solves (at 30 digits and at the confirmation's)."""
    name, pend = CASE
    return nonlinear_blade.linear_period(profiles.profile(name), *profiles.PENDULUMS[pend], dps)


def _exact(quantity: str):
    def truth(i, dps):
        st = _tilted(i, dps)
        with mp.workdps(dps + 10):
            if quantity == "period":
                return st.period / untilted_period(dps) - 1
            if quantity == "j'":
                return st.theta + mp.mpf(i)
            return getattr(st, quantity)
    return truth


def order(quantity: str, expected: int, pick=None, over_Q: bool = False, to_Q1=None, note: str = "") -> checks.Order:
    """The form (component ``pick`` of a Tuple; made into Q1 by ``to_Q1``; divided by Q = K(z − z') (45) with
    ``over_Q``) at i against the exact tilted blade's ``quantity``: θ, β, j' (θ + i), Y, N, or period
    (T/T0 − 1)."""
    def at(expr, i):
        form = expr[pick] if pick is not None else expr
        form = to_Q1(form) if to_Q1 is not None else form
        env = env_at(i)
        if quantity == "N" and form.has(sp.Symbol("theta", real=True)):
            env = dict(env, theta=_tilted(i, checks.DPS).theta)
        value = verify.value_at(form, env)
        return value / (env["K"] * (env["z"] - env["z'"])) if over_Q else value
    name, pend = CASE
    return checks.Order(param="i", values=tilts, truth=_exact(quantity), at=at, expected=expected, note=note,
                        confirm_dps=CONFIRM_DPS,
                        truth_desc=f"{TILT_TRUTH}; {name} blade, {pend} pendulum, i' = {mp.nstr(RATIO, 3)}i"
                                   + ("; T0 of the straight blade by pendsym.suspension" if quantity == "period" else ""),
                        params=(("blade", name), ("pendulum", pend), ("i'/i", mp.nstr(RATIO, 3))))


def step_in_Q1(part: str) -> checks.Order:
    """A step of f judged alone by the truth: Q1 = Kf/(2n²θ1) with f = the form + the derived other part
    (``part`` "129": the form is (129), Δf derived; "delta_f": the form is Δf, (129) derived), over Q."""
    from ..ch2_common import theta1
    from ..symbols import K, n_squared

    def to_Q1(form):
        # the derived other part is built here, when the check runs, not when the table is read (it costs
        # seconds of SymPy that every `pendsym` command would pay; both derivations are lru_cached)
        other = derivation.eq132_delta_f() if part == "129" else derivation.eq129()
        return sp.cancel(sp.expand(K * (form + other) / (2 * n_squared * theta1)))
    what = "Δf" if part == "129" else "(129)"
    return order("period", 4, over_Q=True, to_Q1=to_Q1,
                 note=f"the form is made into Q1 = Kf/(2n²θ1) with the derived {what}")


# ---------------------------------------------------------------- (116): the exact terms
_POINT = {"a": mp.mpf("0.7"), "g": mp.mpf("1"), "theta": mp.mpf("0.9"), "theta'": mp.mpf("-1.3"),
          "theta''": mp.mpf("0.6"), "X": mp.mpf("1.1"), "Y": mp.mpf("0.35"), "i": mp.mpf("0.8"),
          "i'": mp.mpf("-0.5")}


def _scaled(p) -> dict:
    return dict(_POINT, i=_POINT["i"] * p, **{"i'": _POINT["i'"] * p})


def _errors_exact(component: int, env: dict):
    a, g, th, thd, thdd, X, Y = (env[k] for k in ("a", "g", "theta", "theta'", "theta''", "X", "Y"))
    i, ip = env["i"], env["i'"]
    if component == 0:   # ε1 = cos i − 1 − (ẍ_G(i') − ẍ_G(0))/g
        return mp.cos(i) - 1 + a / g * (thdd * (mp.sin(th + ip) - mp.sin(th)) + thd**2 * (mp.cos(th + ip) - mp.cos(th)))
    if component == 1:   # ε2 = −sin i − (ÿ_G(i') − ÿ_G(0))/g
        return -mp.sin(i) - a / g * (thdd * (mp.cos(th + ip) - mp.cos(th)) - thd**2 * (mp.sin(th + ip) - mp.sin(th)))
    return a * (Y * mp.cos(th + ip) - X * mp.sin(th + ip)) - a * (Y * mp.cos(th) - X * mp.sin(th))


def errors_order(component: int) -> checks.Order:
    """(116), one component, against the exact difference of the tilted and untilted (4)–(6): O(p³)."""
    def truth(p, dps):
        with mp.workdps(dps + 10):
            return _errors_exact(component, _scaled(mp.mpf(p)))

    def at(expr, p):
        return verify.value_at(expr[component], _scaled(mp.mpf(p)))
    return checks.Order(param="p", values=checks.Geometric("0.0005", "0.02"), truth=truth, at=at, expected=3,
                        truth_desc="the exact tilted (4)–(6) minus the untilted, with mpmath's sin and cos, at a "
                                   "point where i, i' are scaled by p")
