"""Haag 1935, chapter I, n°5–9: the independent truth of (21)–(41).

The directly solved blade (:mod:`pendsym.suspension`, no v, w) under the
pendulums of :mod:`..profiles`: its end loads for prescribed end positions
(21)–(26), and the eigenproblem K q = n² 𝕄 q of the pendulum on it, whose modes
give the foci (their nodes), n², K = −n²z'/g and the stability boundary (n°9).
Haag's formulas take the shot v0, vλ, w0, wλ, β1 of :mod:`pendsym.blade`.  At 30
digits, the truth confirmed by a 45-digit solve of the hole blade.
"""
from __future__ import annotations

from dataclasses import dataclass

import mpmath as mp

from pendsym import checks, suspension, verify
from pendsym.checks import Point
from pendsym.result import Evidence, Result
from .. import profiles
from ..profiles import DIRECT_TRUTH, MODES_TRUTH


# ---------------------------------------------------------------- n°5–6: end loads and motion
def load_rows(quantity: str):
    """At the end positions of profiles.END_POSITIONS: the direct blade's β, end load Y, couple N, or
    β1 = 1/(∂Y/∂β), β2 = −(∂Y/∂θ)/(∂Y/∂β) from its stiffness."""
    def rows(name, pend, dps):
        direct = profiles.direct_blade(name, dps)
        env0 = profiles.shot_env(name, dps)
        stiffness = direct.stiffness
        for beta_fraction, theta_text in profiles.END_POSITIONS:
            beta_v, theta_v = mp.mpf(beta_fraction) * env0["lambda"], mp.mpf(theta_text)
            _, Y_v, N_v = direct.loads(beta_v, theta_v)
            env = dict(env0, beta=beta_v, theta=theta_v, Y=Y_v, N=N_v)
            truth = {"beta": beta_v, "Y": Y_v, "N": N_v, "beta1": 1 / stiffness[0, 0],
                     "beta2": -stiffness[0, 1] / stiffness[0, 0]}[quantity]
            scale = env0["lambda"] if quantity == "beta" else mp.mpf(0)
            yield Point(f"β={beta_fraction}λ,θ={theta_text}", env, truth, max(abs(mp.mpf(truth)), mp.mpf(scale)))
    return rows


def loads(quantity: str, what: str) -> checks.Values:
    return profiles.values_on_profiles(f"{DIRECT_TRUTH}: {what}", load_rows(quantity))


def motion(equation: int) -> checks.All:
    """(25) (β'' + aθ'') or (26) (R²θ''): −gY and g(aY − N − aθ) of the direct blade at the end positions,
    and, in each normal mode (θ = 1, β of the mode), −n²(β + a) and −n²R²."""
    def rows(name, pend, dps):
        direct = profiles.direct_blade(name, dps)
        env0 = profiles.shot_and_mode_env(name, pend, dps)
        for beta_fraction, theta_text in profiles.END_POSITIONS:
            beta_v, theta_v = mp.mpf(beta_fraction) * env0["lambda"], mp.mpf(theta_text)
            _, Y_v, N_v = direct.loads(beta_v, theta_v)
            a_v, g_v = env0["a"], env0["g"]
            truth = -g_v * Y_v if equation == 25 else g_v * (a_v * Y_v - N_v - a_v * theta_v)
            yield Point(f"β={beta_fraction}λ,θ={theta_text}", dict(env0, beta=beta_v, theta=theta_v), truth,
                        abs(mp.mpf(truth)))

    def modal_points(level, dps):
        for name in profiles.LEVEL_PROFILES[level]:
            for pend in profiles.LEVEL_PENDULUMS[level]:
                env = profiles.shot_and_mode_env(name, pend, dps)
                a_v, R_v, g_v = profiles.pendulum(pend)
                for mode in suspension.modes(profiles.direct_blade(name, dps), a_v, R_v, g_v):
                    truth = -mode.n2 * (mode.beta + a_v) if equation == 25 else -mode.n2 * R_v**2
                    yield Point(f"{name}/{pend}/z={mp.nstr(mode.z, 3)}", dict(env, beta=mode.beta, theta=1), truth)
    loaded = profiles.values_on_profiles(DIRECT_TRUTH + "; the linearised (5), (6) with its end loads", rows,
                                         pend=True)
    modal = checks.Values(truth=MODES_TRUTH + ": q'' = −n²q in each normal mode", points=modal_points)
    return checks.All((loaded, modal), truth=loaded.truth)


# ---------------------------------------------------------------- n°7–8: foci and periods
def mode_rows(quantity):
    """quantity(env) of the shot blade and the modes of the direct blade, per pendulum."""
    def rows(name, pend, dps):
        env = profiles.shot_and_mode_env(name, pend, dps)
        truth = quantity(env)
        yield Point(pend, env, truth, abs(mp.mpf(truth)))
    return rows


def modes(quantity, what: str) -> checks.Values:
    return profiles.values_on_profiles(f"{MODES_TRUTH}: {what}", mode_rows(quantity), pend=True)


def at_foci(what: str, swap: bool = False) -> checks.Values:
    """A condition on the foci, at the nodes z, z' of the two modes with the n² of the principal one; with
    ``swap``, also z ↔ z' with the n'² of the parasitic mode (y_F vanishes in the mode whose node is the other
    focus)."""
    def points(level, dps):
        for name in profiles.LEVEL_PROFILES[level]:
            for pend in profiles.LEVEL_PENDULUMS[level]:
                env = profiles.shot_and_mode_env(name, pend, dps)
                yield Point(f"{name}/{pend}", env, 0, denom="terms")
                if swap:
                    swapped = dict(env, z=env["z'"], **{"z'": env["z"], "n^2": env["n'^2"]})
                    yield Point(f"{name}/{pend}/swapped", swapped, 0, denom="terms")
    return checks.Values(truth=f"{MODES_TRUTH}: {what}", points=points, confirm=profiles.confirmation_env)


# ---------------------------------------------------------------- n°9: existence
def critical_distance() -> checks.All:
    """(41): a1 against the a where det K(a) = 0 (K is linear in a), and the sign pattern of the n²."""
    def points(level, dps):
        for name in profiles.LEVEL_PROFILES[level]:
            S = profiles.direct_blade(name, dps).stiffness
            a_critical = S[0, 1] * S[1, 0] / S[0, 0] - S[1, 1]
            yield Point(name, profiles.shot_env(name, dps), a_critical, abs(a_critical))
    values = checks.Values(truth=MODES_TRUTH + "; the a where det K = 0", points=points,
                           confirm=profiles.confirmation_env, work_dps=42)
    return checks.All((values, StabilityBoundary()), truth=values.truth)


def _n_squared(direct, a_v, R_v, g_v) -> list:
    matrix = mp.inverse(suspension.mass_matrix(a_v, R_v)) * suspension.stiffness_matrix(direct, a_v, 1, g_v)
    return sorted(mp.re(x) for x in mp.eig(matrix)[0])


@dataclass(frozen=True)
class StabilityBoundary:
    """n°9 at a = a1 of the formula: an n² of the eigenproblem vanishes there; 1 cm above both are positive,
    1 cm below and at a = −0.1 m one is negative.  Custom: a sign pattern of the model at points the
    formula places (no engine kind)."""

    def __call__(self, result: Result, level: str) -> Evidence:
        ok, notes = True, []
        for name in profiles.LEVEL_PROFILES[level]:
            direct = profiles.direct_blade(name, checks.DPS)
            env = profiles.shot_env(name, checks.DPS)
            with mp.workdps(direct.wdps):
                a1 = mp.mpf(verify.value_at(result.derived_value, env))
                for pend in profiles.LEVEL_PENDULUMS[level]:
                    _, R_v, g_v = profiles.pendulum(pend)
                    n2 = {tag: _n_squared(direct, a_v, R_v, g_v) for tag, a_v in (
                        ("a1", a1), ("a1+1cm", a1 + mp.mpf("0.01")), ("a1-1cm", a1 - mp.mpf("0.01")),
                        ("a=-0.1", mp.mpf("-0.1")))}
                    zero = min(abs(x) for x in n2["a1"]) / (g_v / env["beta_1"])
                    ok &= bool(zero < checks.TOL and n2["a1"][1] > 0 and min(n2["a1+1cm"]) > 0)
                    ok &= bool(n2["a1-1cm"][0] < 0 < n2["a1-1cm"][1] and n2["a=-0.1"][0] < 0 < n2["a=-0.1"][1])
                    notes.append(f"{name}/{pend}: |n²|/(g/β1) at a1 = {mp.nstr(zero, 3)}, n² at a1−1cm = "
                                 f"{mp.nstr(n2['a1-1cm'][0], 5)}, at a1+1cm = {mp.nstr(n2['a1+1cm'][0], 5)}")
        return Evidence(kind="inequality", passed=ok, truth=MODES_TRUTH + ": the sign of the n² about a1",
                        note="; ".join(notes))


@dataclass(frozen=True)
class UnstableBelow:
    """n°9: for a < a1, (38) holds and (39) fails: a + z' − vλ and a + z − vλ, with the foci of the
    eigenproblem at a = a1 − 1 cm, are both negative, and their product is (33), the derived form.
    Custom: signs of the model, no engine kind."""

    def __call__(self, result: Result, level: str) -> Evidence:
        ok, notes = True, []
        with mp.workdps(40):
            for name in profiles.LEVEL_PROFILES[level]:
                direct = profiles.direct_blade(name, checks.DPS)
                env = profiles.shot_env(name, checks.DPS)
                for pend in profiles.LEVEL_PENDULUMS[level]:
                    _, R_v, g_v = profiles.pendulum(pend)
                    a_v = -env["w_lambda"] - mp.mpf("0.01")
                    foci = sorted(mode.z for mode in suspension.modes(direct, a_v, R_v, g_v))
                    upper, lower = a_v + foci[0] - env["v_lambda"], a_v + foci[1] - env["v_lambda"]
                    product = mp.mpf(verify.value_at(result.derived_value, dict(env, a=a_v)))
                    ok &= bool(upper < 0 and lower < 0 and abs(product - upper * lower) < checks.TOL * abs(product))
                    notes.append(f"{name}/{pend}: a + z' − vλ = {mp.nstr(upper, 5)}, a + z − vλ = {mp.nstr(lower, 5)}")
        digits = checks.confirmation_digits(profiles.confirmation_env)
        return Evidence(kind="inequality", passed=bool(ok and digits >= checks.MIN_DIGITS),
                        truth=MODES_TRUTH + " at a = a1 − 1 cm", confirm_digits=verify.rounded(digits),
                        note="; ".join(notes) + f" | truth confirmed to {digits:.1f} digits at {checks.CONFIRM_DPS}")
