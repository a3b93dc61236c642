"""Haag 1935, chapter VII, n°86, 88–90: the checks of (269), (274)–(277), (279) against the eigenproblem of
:mod:`.truth` (the directly solved blade, a = a1 + ελ placed on the truth).

- (269): the slow n² at g and at g(1 + h), EI, m, a, R, λ fixed (the blade's M divided by 1 + h), T = π/n;
  the formula's lπ²(1/T'² − 1/T²) over g' − g = gh, along u → 0 (ε = u).
- (274)–(275): the equilibrium of the directly solved blade under a force Q at AB = b
  (pendsym.suspension.static_offset): the ordinates of F (the fast mode's node z) and F' (the slow mode's
  node z') are the amplitudes A and A' of the slow and fast vibrations after release (n°18).
- (276): the blow solved from the mechanics (ch1_launch.impact_truth), its velocity decomposed on the modes,
  A = d(z − z')/n and A' = d'(z' − z)/n' the amplitudes of F and F'.
- (277), (279): the deflection y and the bending stress E(e/2)φ' of the directly solved blade in the slow mode
  (θ = 1, β = −(a + z')) at s = 0.6λ, against θ(w − w0) and the stresses with w(s) of the shot blade.
"""
from __future__ import annotations

import mpmath as mp
import sympy as sp

from pendsym import checks, suspension, verify
from ..symbols import I_s, M_of_s, s, w
from . import truth
from .checks_gravity import EPS, U_PATH

LAUNCH = {"Q": "0.01", "mg": "9.81", "m": "1", "m'": "0.37", "h": "0.62", "V": "0.8"}
ATTACK = "0.5"              # AB = b over a
G_STEP = "1e-12"            # relative change of g in (269)
SECTION = {"E": "2.1e11", "e": "0.0003", "theta": "1", "mg": "9.81"}
FRACTION = "0.6"


def launch_env(key: str, p, dps: int = 30) -> dict:
    env = truth.state(key, 1, p, dps)
    env.update({name: mp.mpf(text) for name, text in LAUNCH.items()})
    env["b"] = env["a"] * mp.mpf(ATTACK)
    return env


def static_amplitudes(env, key: str, dps: int) -> tuple:
    """(A, A'): the ordinates of F and F' at the equilibrium under Q at AB = b."""
    sus = truth.direct(key, 1, 0, dps)
    with mp.workdps(sus.wdps):
        beta0, theta0 = suspension.static_offset(sus, env["a"], env["b"], env["Q"] / env["mg"])
        return beta0 + (env["a"] + env["z"]) * theta0, beta0 + (env["a"] + env["z'"]) * theta0


def blow_ratio(env, key: str, dps: int):
    """A/A' after a blow at AB = b: (β'0, θ'0) of the blow on the modes (β, θ) = (−(a + node), 1)."""
    from ..ch1_launch import truth as launch
    with mp.workdps(dps + 12):
        speeds = launch.impact_truth(env["a"], env["R"], env["b"], env["m"], env["m'"], env["h"], env["V"])
        slow, fast = -(env["a"] + env["z'"]), -(env["a"] + env["z"])
        d = mp.lu_solve(mp.matrix([[slow, fast], [1, 1]]), mp.matrix([speeds[0], speeds[1]]))
        A = d[0] * (env["z"] - env["z'"]) / mp.sqrt(env["n^2"])
        Ap = d[1] * (env["z'"] - env["z"]) / mp.sqrt(env["n'^2"])
        return A / Ap


LAUNCH_QUANTITY = {
    "A": lambda env, key, dps: static_amplitudes(env, key, dps)[0],
    "Ap": lambda env, key, dps: static_amplitudes(env, key, dps)[1],
    "ratio": lambda env, key, dps: (lambda pair: pair[0] / pair[1])(static_amplitudes(env, key, dps)),
    "blow": blow_ratio,
}
LAUNCH_TEXT = {
    "A": "A = ordinate of F (node of the fast mode) at the equilibrium under Q",
    "Ap": "A' = ordinate of F' (node of the slow mode) at the equilibrium under Q",
    "ratio": "A/A', the ordinates of F and F' at the equilibrium under Q",
    "blow": "A/A' after a blow, the blow solved from the mechanics and decomposed on the modes",
}


def launch_order(kind: str, key: str = "u=2") -> checks.Order:
    """Relative residual of a launch quantity, order 1 in ε."""
    quantity = LAUNCH_QUANTITY[kind]

    def at(expr, p):
        env = launch_env(key, p)
        return verify.value_at(expr, env) / quantity(env, key, checks.DPS)
    return checks.Order(param="varepsilon", values=EPS, truth=lambda p, dps: _confirmed(quantity, key, p, dps),
                        at=at, expected=1,
                        truth_desc=f"{truth.MODEL}; {LAUNCH_TEXT[kind]} ({LAUNCH}, AB = {ATTACK}a; relative: the "
                                   f"formula over the truth); blade {key}",
                        params=(("blade", key), ("AB/a", ATTACK)))


def _confirmed(quantity, key, p, dps):
    """1, the truth over itself, its quantity recomputed at ``dps`` (so that the engine's confirmation at two
    precisions measures the truth's own digits)."""
    env = launch_env(key, p, dps)
    q = quantity(env, key, dps)
    return q / q


def along(kind: str, key: str = "u=2") -> checks.Order:
    """Order 1 in ε of the deflection (kind "shape") or bending stress ("stress") of the slow mode at s = 0.6λ."""
    def env_of(p, dps=30):
        env = truth.state(key, 1, p, dps)
        env.update({k: mp.mpf(x) for k, x in SECTION.items()})
        env["s"] = mp.mpf(FRACTION) * env["lambda"]
        sol = truth.shot(key, 1, dps)
        with mp.workdps(sol.wdps):
            env[w(s)] = sol.state(env["s"])[2]
            env[M_of_s(s)] = sol.M_at(env["s"])
            env["w_0"] = sol.w0
            env[I_s.name] = env["mg"] * env[M_of_s(s)] / env["E"]      # EI = mgM (1)
        return env

    def value(p, dps):
        env = env_of(p, dps)
        sus = truth.direct(key, 1, 0, dps)
        with mp.workdps(sus.wdps):
            y, _, curvature = sus.deflection(env["s"], -(env["a"] + env["z'"]), 1)
            return y if kind == "shape" else env["E"] * env["e"] / 2 * curvature
    what = "y" if kind == "shape" else "the bending stress E(e/2)φ'"
    return checks.Order(param="varepsilon", values=EPS, truth=value, at=lambda expr, p: verify.value_at(expr, env_of(p)),
                        expected=1, truth_desc=f"{truth.MODEL}; {what} of the directly solved blade at s = {FRACTION}λ "
                                               f"in the slow mode (θ = 1, β = −(a + z')); w(s), w0, M(s) of the shot "
                                               f"blade; blade {key}",
                        params=(("blade", key), ("E", SECTION["E"]), ("e", SECTION["e"])))


def g_difference() -> checks.Order:
    """(269): lπ²(1/T'² − 1/T²) over g' − g = gh, T = π/n of the slow mode at g and g(1 + h), along u → 0."""
    def slow_n2(key, p, k, dps):
        env = truth.numbers(key, 1, dps)
        sus = truth.direct(key, 1, 0, dps)
        with mp.workdps(sus.wdps):
            a = env["a_1"] + mp.mpf(p) * env["lambda"]
            step = sp.Rational(G_STEP)
            blade_k = truth.direct(key, 1, k, dps, step) if k else sus
            return env, a, truth.eigenmodes(blade_k, a, env["R"], env["g"] * (1 + k * mp.mpf(G_STEP)))[0][0]

    def at(expr, p):
        key = f"u={p}"
        env, a, n2 = slow_n2(key, sp.Rational(p), 0, checks.DPS)
        _, _, n2p = slow_n2(key, sp.Rational(p), 1, checks.DPS)
        with mp.workdps(checks.DPS + 10):
            values = {"T": mp.pi / mp.sqrt(n2), "T'": mp.pi / mp.sqrt(n2p), "l": (env["R"] ** 2 + a**2) / a}
            return verify.value_at(expr, values) / (env["g"] * mp.mpf(G_STEP))

    def value(p, dps):
        key = f"u={p}"
        env, _, n2 = slow_n2(key, sp.Rational(p), 0, dps)
        return n2 / n2       # the truth is g' − g itself: 1 in these units; n² computed at dps for the confirmation
    return checks.Order(param="u", values=lambda level: [sp.Rational(x) for x in U_PATH[level]], truth=value, at=at,
                        expected=2, truth_desc=f"{truth.MODEL}; g' − g = gh (h = {G_STEP}) against the formula with "
                                               "T = π/n of the slow mode at g and g' (EI, m, a, R, λ fixed), "
                                               "a = a1 + ελ, ε = u; uniform blade λ = 1/10",
                        params=(("R", truth.R_VALUE), ("h", G_STEP)), dps=30, confirm_dps=45)
