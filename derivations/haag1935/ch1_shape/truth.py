"""Haag 1935, chapter I, n°21–25: the independent truth of (77)–(87).

:mod:`pendsym.suspension`: the shape and the curvature of the directly solved blade
for an end position, the principal mode's deflection integrated by Gauss–Legendre
quadrature (∫φ² ds, the strain energy), its node F' (the centre of flexion); the
geometry of the fork by mpmath hypot; and the fork's glide r(θ), the exact root of
(84) with α, β of the principal mode, whose residual against the formulas is
fitted in θ (fourth order).  Haag's formulas take the shot blade's quantities
(:func:`..ch1_launch.truth.haag_env`).
"""
from __future__ import annotations

import functools
from dataclasses import dataclass

import mpmath as mp
import sympy as sp

from pendsym import checks, suspension, verify
from pendsym.result import Evidence, Result
from .. import ch1_model, profiles
from ..ch1_launch.truth import (DIRECT, MODES, base_env, at_s, direct_modes, haag_env, mode_points, s_points, s_value,
                                values_at)
from ..ch2_general import truth as period_truth
from ..common import CONFIRM_DPS, DPS
from ..symbols import Fn, Gn, K, L, M_of_s, a, c_axis, lam, s, x_fork, z, zp

END = {"beta": "0.0031", "theta": "-0.047"}        # an arbitrary end position (β, θ)
FATIGUE = {"E": "2.1", "e": "0.37", "mg": "1.7"}
GEOMETRY = ({"alpha": "0.0998", "beta": "0.0071", "theta": "0.13", "r": "0.61", "c": "-0.23"},
            {"alpha": "0.1", "beta": "-0.02", "theta": "-0.4", "r": "1.1", "c": "0.35"})
FORK = {"L": "0.4", "x": "0.05"}                      # CM = L and λ − c = x
FORK_PAIRS = {"quick": (("tapered", "clock"),), "full": (("tapered", "clock"), ("hole", "compact"))}
THETAS = {"quick": ("1e-3", "1e-2", 4), "full": ("1e-3", "1e-2", 6)}


@functools.lru_cache(maxsize=64)
def haag_integrals(name: str, pend: str, dps: int = DPS) -> dict:
    """F2, G2 of (79) by quadrature on the shot blade, K of the principal oscillation."""
    shot, K_v = profiles.shot_blade(name, dps), haag_env(name, pend, dps)["K"]
    return {Fn(2): shot.F(2, K_v), Gn(2): shot.G(2, K_v)}


@functools.lru_cache(maxsize=64)
def direct_integrals(name: str, pend: str, dps: int = DPS) -> dict:
    """For the principal mode (θ = 1) of the direct blade: ∫φ² ds and W/(mg) = ½∫Mφ'² ds."""
    direct, principal, _ = direct_modes(name, pend, dps)
    with mp.workdps(direct.wdps):
        return {"phi2": direct.integrate(lambda x: direct.deflection(x, principal.beta, 1)[1] ** 2),
                "W": suspension.energy(direct, principal.beta, 1)}


# ---------------------------------------------------------------- n°21–22: (77), (78)
def end_env(pt, **extra) -> dict:
    """The shot blade at s, the end position END and its end load Y by (23) (the formula's own Y)."""
    env = {**base_env(pt["profile"], pt["pend"]), **at_s(pt["profile"], s_value(pt["profile"], pt["s"]))}
    env.update({k: mp.mpf(x) for k, x in END.items()})
    env.update(extra)
    env["Y"] = verify.value_at(ch1_model.Y_of_end(), env)                     # (23)
    return env


def direct_deflection(pt, dps, index: int):
    direct = profiles.direct_blade(pt["profile"], dps)
    return direct.deflection(s_value(pt["profile"], pt["s"]), mp.mpf(END["beta"]), mp.mpf(END["theta"]))[index]


def shape() -> checks.Values:
    """(77): y(s) of the direct blade for the end position END."""
    return values_at(f"y(s) of the direct blade for the end position {END}; {DIRECT}", s_points,
                     lambda pt, dps: direct_deflection(pt, dps, 0), end_env,
                     note="Y of the formula by (23) with the shot vλ, β1")


def tension() -> checks.Values:
    """(78): E(e/2)φ' with φ' the curvature of the direct blade for the end position END."""
    def truth(pt, dps):
        return mp.mpf(FATIGUE["E"]) * mp.mpf(FATIGUE["e"]) / 2 * direct_deflection(pt, dps, 2)

    def env(pt):
        values = end_env(pt, **{k: mp.mpf(x) for k, x in FATIGUE.items()})
        values["I_s"] = values[M_of_s(s)] * values["mg"] / values["E"]          # (1)
        return values
    return values_at(f"E(e/2)φ' with φ' the curvature of the direct blade for the end position {END}, {FATIGUE}; "
                     f"{DIRECT}", s_points, truth, env)


# ---------------------------------------------------------------- n°23: (80)–(82)
ENERGY = f"principal mode (θ = 1) of the direct blade, Gauss–Legendre quadrature of its deflection; {MODES}"


def heavy_points(level):
    return mode_points(level, heavy=True)


def energy_env(pt, **extra) -> dict:
    values = base_env(pt["profile"], pt["pend"], theta=1, mg=1, **extra)
    values.update(haag_integrals(pt["profile"], pt["pend"]))
    return values


def pendulum_energy_truth(pt, dps):
    """W'/(mg) = ½(aθ² + ∫φ² ds) at θ = 1."""
    return (mp.mpf(profiles.PENDULUMS[pt["pend"]][0]) + direct_integrals(pt["profile"], pt["pend"], dps)["phi2"]) / 2


def suppleness_truth(pt, dps):
    return pendulum_energy_truth(pt, dps) / direct_integrals(pt["profile"], pt["pend"], dps)["W"]


def pendulum_energy() -> checks.Values:
    return values_at(f"W'/(mg) = ½(aθ² + ∫φ² ds), {ENERGY}", heavy_points, pendulum_energy_truth, energy_env,
                     note="F2 of the formula by quadrature of (79) on the shot blade")


def blade_energy() -> checks.Values:
    return values_at(f"W/(mg) = ½∫Mφ'² ds (pendsym.suspension.energy), {ENERGY}", heavy_points,
                     lambda pt, dps: direct_integrals(pt["profile"], pt["pend"], dps)["W"], energy_env,
                     note="G2 of the formula by quadrature of (79) on the shot blade")


def suppleness() -> checks.Values:
    return values_at(f"S = W'/W, {ENERGY}", heavy_points, suppleness_truth, energy_env)


def F2_plus_G2() -> checks.All:
    """(81): ∫φ² + ∫Mφ'² of the direct principal mode, and F2 + G2 by quadrature of (79) for other K."""
    def direct_truth(pt, dps):
        integrals = direct_integrals(pt["profile"], pt["pend"], dps)
        return integrals["phi2"] + 2 * integrals["W"]

    def other_K_points(level):
        return [{"profile": "tapered", "K": "0.3"}, {"profile": "hole", "K": "-1.7"}][: 1 if level == "quick" else 2]

    def quadrature_truth(pt, dps):
        shot = profiles.shot_blade(pt["profile"], dps)
        return shot.F(2, mp.mpf(pt["K"])) + shot.G(2, mp.mpf(pt["K"]))
    on_modes = values_at(f"∫φ² ds + ∫Mφ'² ds, {ENERGY}", heavy_points, direct_truth,
                         lambda pt: base_env(pt["profile"], pt["pend"]))
    for_any_K = values_at("F2 + G2 by quadrature of (79) on the shot blade for any K", other_K_points,
                          quadrature_truth, lambda pt: base_env(pt["profile"], "clock", K=mp.mpf(pt["K"])))
    return checks.All((on_modes, for_any_K))


# ---------------------------------------------------------------- n°24–25: (83)–(85)
def centre_of_flexion() -> checks.Values:
    """(83): λ + AF' with F' the node of the principal mode."""
    return values_at(f"λ + AF' with F' the node of the principal mode ({MODES})", mode_points,
                     lambda pt, dps: mp.mpf(profiles.profile(pt["profile"]).length)
                     + mp.mpf(profiles.PENDULUMS[pt["pend"]][0]) + direct_modes(pt["profile"], pt["pend"], dps)[1].z,
                     lambda pt: base_env(pt["profile"], pt["pend"]))


def geometry() -> checks.Values:
    """(84): 0 for M = A + r(cos θ, sin θ), C = (c, 0) and L = |CM|."""
    def env(pt):
        values = {k: mp.mpf(x) for k, x in pt.items()}
        x_M = values["alpha"] + values["r"] * mp.cos(values["theta"])
        y_M = values["beta"] + values["r"] * mp.sin(values["theta"])
        values["L"] = mp.hypot(x_M - values["c"], y_M)               # the distance CM
        return values
    return values_at("0 for M = A + r(cos θ, sin θ), C = (c, 0) and L = |CM| computed by mpmath hypot",
                     lambda level: list(GEOMETRY), lambda pt, dps: mp.mpf(0), env, scale=lambda pt: env(pt)["L"] ** 2)


def alpha_second_order() -> checks.Values:
    """(85): λ − ½∫φ² ds at θ = 1, the θ² coefficient only."""
    return values_at(f"λ − ½∫φ² ds at θ = 1 (the second-order coefficient), {ENERGY}", heavy_points,
                     lambda pt, dps: mp.mpf(profiles.profile(pt["profile"]).length)
                     - direct_integrals(pt["profile"], pt["pend"], dps)["phi2"] / 2, energy_env,
                     note="only the θ² coefficient is checked here (F2 = ∫φ²/θ² of the direct deflection); the "
                          "claim that (85) is exact to the fourth order is eq085.fourth_order, on the exact blade")


# ---------------------------------------------------------------- n°25: the fork, orders in θ
def fork_model(name, pend, dps):
    """(λ, F2, z', a) of the principal oscillation from the direct blade (∫φ²/θ², node of the mode)."""
    return (mp.mpf(profiles.profile(name).length), direct_integrals(name, pend, dps)["phi2"],
            direct_modes(name, pend, dps)[1].z, mp.mpf(profiles.PENDULUMS[pend][0]))


def _alpha_beta(theta_v, model):
    length, F2, zp_v, a_v = model
    return length - F2 * theta_v**2 / 2, -(a_v + zp_v) * theta_v       # α = λ − F2θ²/2 (85), β = −(a + z')θ (64)


def lhs84(r_v, theta_v, c_v, L_v, model):
    """The left side of (84) with α = λ − F2θ²/2 (85) and β = −(a + z')θ (64), exact in θ."""
    alpha_v, beta_v = _alpha_beta(theta_v, model)
    return (r_v**2 + 2 * r_v * ((alpha_v - c_v) * mp.cos(theta_v) + beta_v * mp.sin(theta_v)) + (alpha_v - c_v) ** 2
            + beta_v**2 - L_v**2)


def root84(theta_v, c_v, L_v, model):
    """The root r of (84) near L + c − λ."""
    alpha_v, beta_v = _alpha_beta(theta_v, model)
    B = (alpha_v - c_v) * mp.cos(theta_v) + beta_v * mp.sin(theta_v)
    return -B + mp.sqrt(B**2 - ((alpha_v - c_v) ** 2 + beta_v**2 - L_v**2))


def fork_env(name, pend, **extra):
    values = dict(base_env(name, pend), **{k: mp.mpf(x) for k, x in FORK.items()})
    values["c"] = values["lambda"] - values["x"]
    values.update(haag_integrals(name, pend))
    values.update(extra)
    return values


def thetas(level):
    return verify.geometric(*THETAS[level])


def fork_params(name, pend) -> tuple:
    return (("profile", name), ("pendulum", pend), ("L", FORK["L"]), ("x", FORK["x"]))


def A_fork() -> checks.All:
    """(86) A: the residual of r² + 2r(λ − c) + (λ − c)² − L² − Aθ² against the exact left side of (84) at
    r = L + c − λ, of the fourth order in θ."""
    def order(name, pend):
        def geometry_at():
            with mp.workdps(40):
                env = fork_env(name, pend)
                r_v = env["L"] + env["c"] - env["lambda"]
                x_v = env["lambda"] - env["c"]
                return env, r_v, r_v**2 + 2 * r_v * x_v + x_v**2 - env["L"] ** 2

        def at(expr, theta_v):
            env, r_v, base = geometry_at()
            with mp.workdps(40):
                A_v = mp.mpf(verify.value_at(expr, dict(env, r=r_v)))
            return base - A_v * theta_v**2

        def truth(theta_v, dps):
            env, r_v, _ = geometry_at()
            return lhs84(r_v, theta_v, env["c"], env["L"], fork_model(name, pend, dps))
        return checks.Order(param="theta", values=thetas, truth=truth, at=at, expected=4,
                            params=fork_params(name, pend), dps=DPS, confirm_dps=CONFIRM_DPS,
                            truth_desc=f"the left side of (84) evaluated exactly at r = L + c − λ with α = λ − F2θ²/2, "
                                       f"β = −(a + z')θ, F2 = ∫φ²/θ² and z' from the direct blade ({MODES}); residual "
                                       f"of r² + 2r(λ − c) + (λ − c)² − L² − Aθ²")
    return checks.All(tuple(order(name, pend) for name, pend in FORK_PAIRS["full"]))


def r_fork() -> checks.All:
    """(86) r: against the root of (84) near L + c − λ, exact in θ, of the fourth order."""
    def order(name, pend):
        def at(expr, theta_v):
            with mp.workdps(40):
                env = fork_env(name, pend)
            return verify.value_at(expr, dict(env, theta=theta_v))

        def truth(theta_v, dps):
            with mp.workdps(40):
                env = fork_env(name, pend)
            return root84(theta_v, env["c"], env["L"], fork_model(name, pend, dps))
        return checks.Order(param="theta", values=thetas, truth=truth, at=at, expected=4,
                            params=fork_params(name, pend), dps=DPS, confirm_dps=CONFIRM_DPS,
                            truth_desc=f"the root of (84) near L + c − λ, exact in θ, with α = λ − F2θ²/2, "
                                       f"β = −(a + z')θ, F2 and z' from the direct blade ({MODES})")
    return checks.All(tuple(order(name, pend) for name, pend in FORK_PAIRS["full"]))


def fork_substitutions(env: dict) -> dict:
    """Numeric substitutions for a fork formula (SymPy Floats at 45 digits)."""
    out = {}
    for key, value in env.items():
        symbol = sp.Symbol(key) if isinstance(key, str) else key
        out[symbol] = sp.Float(mp.nstr(value, 45), 45) if not isinstance(value, str) else value
    by_name = {str(k): value for k, value in out.items()}
    return {symbol: by_name[symbol.name] for symbol in (a, zp, lam, c_axis, L, x_fork, z, K)} | {Fn(2): out[Fn(2)]}


def optimum_x(expr: sp.Expr, env: dict) -> mp.mpf:
    """The root x of (87) (quadratic in x) of smaller modulus, with the shot values."""
    poly = sp.Poly(expr.subs({k: value for k, value in fork_substitutions(env).items() if k != x_fork}), x_fork)
    roots = mp.polyroots([mp.mpf(str(cf)) for cf in poly.all_coeffs()], extraprec=60)
    real = [mp.re(x) for x in roots if abs(mp.im(x)) < mp.mpf(10) ** (-20)]
    return min(real, key=abs)


@dataclass(frozen=True)
class ForkOptimum:
    """(87): with λ − c = x the root of the form (of smaller modulus), the glide r(θ) − r(0) of the fork (the
    exact root of (84)) is of the fourth order in θ (of the second for any other x); the printed form's root
    likewise (printed_agrees).  Custom: the truth depends on the form (its root places the axis), which
    checks.Order cannot express."""

    def __call__(self, result: Result, level: str) -> Evidence:
        runs = {"derived": [], "printed": []}
        description = (f"the glide r(θ) − r(0) of the fork (root of (84) exact in θ, F2, z' from the direct blade, "
                       f"{MODES}) with λ − c = x the root of (87) of smaller modulus, L = {FORK['L']}: of the fourth "
                       f"order (second order for any other x)")
        with mp.workdps(40):
            for name, pend in FORK_PAIRS[level]:
                env = fork_env(name, pend)
                for which, form in (("derived", result.derived_value), ("printed", result.printed_value)):
                    if form is None:
                        continue
                    c_v = env["lambda"] - optimum_x(form, env)
                    r0 = env["L"] + c_v - env["lambda"]

                    def glide(theta_v, dps, c_v=c_v, name=name, pend=pend, env=env):
                        return root84(theta_v, c_v, env["L"], fork_model(name, pend, dps))
                    runs[which].append(verify.order_check(
                        param="theta", values=thetas(level), truth=glide, derived=lambda theta_v, r0=r0: r0,
                        expected=4, truth_desc=description, params=fork_params(name, pend), dps=DPS,
                        confirm_dps=CONFIRM_DPS))
        first, printed = runs["derived"][0], runs["printed"]
        return Evidence(kind="order", passed=all(run.passed for run in runs["derived"]), truth=first.truth,
                        max_residual=first.max_residual, order=first.order, expected_order=first.expected_order,
                        band=first.band, param=first.param, params=first.params, series=first.series,
                        printed_agrees=all(run.passed for run in printed) if printed else None,
                        confirm_digits=first.confirm_digits, values=first.values,
                        note=f"glide orders {[run.order for run in runs['derived']]}; printed (87): glide orders "
                             f"{[run.order for run in printed]}")


# ---------------------------------------------------------------- n°25: (64) to the third order, (85) to the fourth
# The orbits are chapter II's (111) check's (its blade, pendulum, amplitudes and digits): one computation, shared
# through pendsym.cache.
ORBIT = ("pendsym.nonlinear_blade: the principal periodic oscillation of the rigid pendulum on the exact "
         "large-deflection blade (collocation, 30 digits); the end A's (θ, α, β) at the collocation node of largest θ")


def end_order(coordinate: str) -> checks.Order:
    """n°25: (85) α = λ − (F2/2)θ² is exact to the fourth order in θ, (64) β = −(a + z')θ to the third: the
    end's exact position at a node of the exact orbit against the formula at that node's θ (α even and β odd
    in θ, footnote (2))."""
    name, pend = period_truth.CASE
    expected = 4.0 if coordinate == "alpha" else 3.0

    def truth(theta0, dps):
        return getattr(period_truth.track(name, pend, theta0, dps), coordinate)[0]

    def at(expr, theta0):
        theta = period_truth.track(name, pend, theta0, DPS).theta[0]
        env = {**haag_env(name, pend), **haag_integrals(name, pend), "theta": theta}
        return verify.value_at(expr, env)
    return checks.Order(param="θ0", values=period_truth.amplitudes, truth=truth, at=at,
                        expected=expected, truth_desc=ORBIT, confirm_dps=33,
                        params=(("blade", name), ("pendulum", pend)),
                        note="F2 (79) by quadrature on the shot blade at the linear mode's K; a, z' of the foci (30)")
