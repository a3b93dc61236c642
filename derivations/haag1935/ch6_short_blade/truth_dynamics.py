"""Haag 1935, chapter VI, n°70–75: the truth of the temperature, the launches, the stresses at the clamps
and the bounds of n°70, on the exact eigenproblem of :mod:`.truth` as a = λ/ε grows.

The temperature reuses chapter I's varied blades (ch1_variations: λ(1 + kH), M(1 + kH)) and its
5-point stencil; the blow reuses chapter I's solution of the blow (ch1_launch: impact_truth,
modal_amplitudes); the static offset and the curvature of the blade are those of the directly
solved blade (:mod:`pendsym.suspension`).
"""
from __future__ import annotations

import mpmath as mp

from pendsym import checks, suspension

from .. import profiles
from .truth import FIXED, Quantity, direct, order, shot


# ---------------------------------------------------------------- n°70: temperature
def temperature_inputs(env, name, dps):
    """G_2 of (79) at the mode's K by quadrature on the shot blade, M_λ, the coefficients of n°70."""
    from ..ch1_variations.truth import TEMPERATURE
    values = {key: mp.mpf(text) for key, text in TEMPERATURE.items()}
    values.update({"G_2": shot(name, dps).G(2, env["K"]), "M_lambda": shot(name, dps).M_at(env["lambda"])})
    return values


def temperature_truth(name: str):
    """d log T per degree of the principal mode: α'(a∂_a + R∂_R) + αλ∂_λ + (β + 4α)∂_ε log T, the λ and ε
    derivatives by the 5-point stencil on the varied direct blades of chapter I's truth (ch1_variations:
    λ(1 + kH), M(1 + kH)), the a, R one by the stencil at a fixed blade (step 1e-9)."""
    from ..ch1_variations import truth as variations

    def quantity(env):
        dps = env["dps"]
        a_v, R_v, g_v = env["a"], env["R"], env["g"]
        with mp.workdps(dps + 12):
            def log_T(sus, scale=1):
                return -mp.log(suspension.modes(sus, a_v * scale, R_v * scale, g_v)[0].n2) / 2
            h = mp.mpf("1e-9")
            scaling = variations.stencil(lambda k: log_T(direct(name, dps), 1 + k * h), h)
            along = {kind: variations.stencil(lambda k, kind=kind: log_T(variations.direct(name, kind, k, dps)),
                                              variations.step_size(name, kind, dps)) for kind in ("lam", "one")}
            return (env["alpha'"] * scaling + env["alpha"] * env["lambda"] * along["lam"]
                    + (env["beta_t"] + 4 * env["alpha"]) * along["one"])
    return quantity


def with_dps(inputs):
    """inputs that also hand the working precision to the quantity (its stencils solve new blades)."""
    return lambda env, name, dps: {**inputs(env, name, dps), "dps": dps}


def temperature_order(name: str) -> checks.Order:
    from ..ch1_variations.truth import TEMPERATURE
    return order(temperature_truth(name), lambda env: env["alpha'"], 2, f"d log T per degree {TEMPERATURE}, over α'",
                 name=name, family=FIXED, inputs=with_dps(temperature_inputs))


# ---------------------------------------------------------------- n°71: the launches
ATTACK = {"tapered": "0.45", "uniform": "1.35"}     # AB = b over a: between the foci, below F


def attack_inputs(env, name, dps):
    return {"b": env["a"] * mp.mpf(ATTACK[name])}


def static_ratio(name: str) -> Quantity:
    """A'/A after release from the static deviation (n°18): the ordinates of F' and F (the nodes of the
    modes) at the equilibrium of the direct blade under a force at AB = b (pendsym.suspension.static_offset)."""
    def quantity(env):
        with mp.workdps(env["dps"] + 12):
            beta0, theta0 = suspension.static_offset(direct(name, env["dps"]), env["a"], env["b"], mp.mpf("0.01"))
            return (beta0 + (env["a"] + env["z'"]) * theta0) / (beta0 + (env["a"] + env["z"]) * theta0)
    return quantity


def blow_ratio(name: str) -> Quantity:
    """A'/A after a blow at AB = b (n°19–20): the blow solved from the mechanics and the initial velocity
    decomposed on the modes (chapter I's truth, ch1_launch: impact_truth, modal_amplitudes)."""
    from ..ch1_launch import truth as launch

    def quantity(env):
        with mp.workdps(env["dps"] + 12):
            principal, parasitic = suspension.modes(direct(name, env["dps"]), env["a"], env["R"], env["g"])
            solution = launch.impact_truth(env["a"], env["R"], env["b"], mp.mpf(1), mp.mpf("0.37"), mp.mpf("0.62"),
                                           mp.mpf("0.8"))
            A, Ap = launch.modal_amplitudes(principal, parasitic, env["a"], solution[0], solution[1])
            return Ap / A
    return quantity


def launch_order(kind: str, name: str) -> checks.Order:
    quantity = static_ratio(name) if kind == "static" else blow_ratio(name)
    what = ("A'/A after release from the static deviation, the ordinates of the nodes at the equilibrium "
            "(pendsym.suspension.static_offset)" if kind == "static" else
            "A'/A after a blow (m' = 0.37m, h = 0.62), the blow solved from the mechanics and decomposed on the modes")
    return order(quantity, quantity, 1, f"{what}, AB = {ATTACK[name]}a (relative residual)", name=name,
                 inputs=with_dps(attack_inputs))


def launch_ratio_order(name: str) -> checks.Order:
    """(228)/(227): the ratio of the blow's A'/A to the static release's, relative residual."""
    static, blow = static_ratio(name), blow_ratio(name)

    def quantity(env):
        return blow(env) / static(env)
    return order(quantity, quantity, 1, f"(A'/A after the blow)/(A'/A after the static release), AB = "
                 f"{ATTACK[name]}a (relative residual)", name=name, inputs=with_dps(attack_inputs))


# ---------------------------------------------------------------- n°73–75: fatigue at the clamp
FATIGUE = {"E": "2.1", "e": "0.3", "theta_0": "0.01"}


def fatigue_inputs(env, name, dps):
    return {key: mp.mpf(text) for key, text in FATIGUE.items()} | {"dps": dps}


def clamp_stress(name: str) -> Quantity:
    """T'_0 of the principal mode of amplitude θ0: E(e/2)φ'(0)θ0 (78) with φ' the curvature at O of the direct
    blade in the mode (θ = 1)."""
    def quantity(env):
        with mp.workdps(env["dps"] + 12):
            sus = direct(name, env["dps"])
            principal = suspension.modes(sus, env["a"], env["R"], env["g"])[0]
            curvature = sus.deflection(0, principal.beta, 1)[2]
            return env["E"] * env["e"] / 2 * curvature * env["theta_0"]
    return quantity


def fatigue_order(name: str) -> checks.Order:
    quantity = clamp_stress(name)
    return order(quantity, quantity, 1, f"T'_0 = E(e/2)φ'(0)θ0 in the principal mode of the direct blade, {FATIGUE} "
                 "(relative residual)", name=name, family=FIXED, inputs=fatigue_inputs)


# ---------------------------------------------------------------- n°70: bounds of P_λ and G_2
def blade_bound_points(level: str, dps: int):
    """The shot end values, M_λ, μ = M2/M1 and G_2 at K = 1 (quadrature of (79)) of the four blades of
    chapter I."""
    for name in profiles.PROFILE_NAMES:
        env = profiles.shot_env(name, dps)
        sol = profiles.shot_blade(name, dps)
        env.update({"M_lambda": sol.M_at(env["lambda"]), "G_2": sol.G(2, 1)})
        yield name, env


def blade_bound(what: str) -> checks.Inequality:
    return checks.Inequality(truth=f"{what}: the shot blades uniform, hole, tapered, bulged (pendsym.blade), G_2 "
                                   "at K = 1 by quadrature", points=blade_bound_points,
                             confirm=profiles.confirmation_env)


STATIC_LAUNCH = {"Q": "0.013", "mg": "9.81", "E": "2.1", "T": "0.4"}
ATTACK_FIXED = {"uniform": "0.45", "uniform_half": "1.35"}    # AB = b over a: between the foci, below F


def static_launch_inputs(env, name, dps, attack=None):
    """The launch's constants, b = (attack or ATTACK_FIXED[name])·a, and θ0 of the static offset of the direct
    blade (what (230), (231) are written with)."""
    values = ({key: mp.mpf(text) for key, text in STATIC_LAUNCH.items()}
              | {"b": env["a"] * mp.mpf(attack or ATTACK_FIXED[name]), "dps": dps})
    with mp.workdps(dps + 12):
        values["theta_0"] = suspension.static_offset(direct(name, dps), env["a"], values["b"],
                                                     values["Q"] / values["mg"])[1]
    return values


def static_launch_stress(name: str, at: str) -> Quantity:
    """The largest |T'| at O (at = "T0") or at A ("Tl") after release from the static deviation: the offset
    of the direct blade under Q at AB = b (pendsym.suspension.static_offset) decomposed on the modes, the
    stress √(3ET)(λ/u)φ' (= E(e/2)φ', T = mg/(eh)) of the direct blade's curvature, at t = 0 and n't = π
    (where the memoir places the maximum)."""
    def quantity(env):
        dps = env["dps"]
        with mp.workdps(dps + 12):
            sus = direct(name, dps)
            principal, parasitic = suspension.modes(sus, env["a"], env["R"], env["g"])
            beta0, theta0 = suspension.static_offset(sus, env["a"], env["b"], env["Q"] / env["mg"])
            c = mp.lu_solve(mp.matrix([[principal.beta, parasitic.beta], [1, 1]]), mp.matrix([beta0, theta0]))
            where = 0 if at == "T0" else env["lambda"]
            scale = mp.sqrt(3 * env["E"] * env["T"]) * env["lambda"] / env["u"]

            def stress(t):
                weights = [c[0] * mp.cos(mp.sqrt(principal.n2) * t), c[1] * mp.cos(mp.sqrt(parasitic.n2) * t)]
                beta_t = weights[0] * principal.beta + weights[1] * parasitic.beta
                return scale * sus.deflection(where, beta_t, weights[0] + weights[1])[2]
            return max(abs(stress(0)), abs(stress(mp.pi / mp.sqrt(parasitic.n2))))
    return quantity


def static_launch_order(name: str, at: str) -> checks.Order:
    quantity = static_launch_stress(name, at)
    return order(quantity, quantity, 1, f"the largest |T'| at {'O' if at == 'T0' else 'A'} (t = 0 or n't = π) after "
                 f"release from the static deviation, {STATIC_LAUNCH}, AB = {ATTACK_FIXED[name]}a (relative residual)",
                 name=name, family=FIXED, inputs=static_launch_inputs)


def attack_order(name: str, attack: str) -> checks.Order:
    """(230), (231): the largest |T'_0| after the static release with B at AB = attack·a."""
    quantity = static_launch_stress(name, "T0")
    return order(quantity, quantity, 1, f"the largest |T'| at O (t = 0 or n't = π) after release from the static "
                 f"deviation, {STATIC_LAUNCH}, AB = {attack}a, θ0 of the static offset (relative residual)",
                 name=name, family=FIXED,
                 inputs=lambda env, blade_name, dps: static_launch_inputs(env, blade_name, dps, attack))
