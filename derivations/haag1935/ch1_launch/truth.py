"""Haag 1935, chapter I, n°16–20: the independent truth of (64)–(76).

:mod:`pendsym.suspension` (the linearised blade solved directly for a prescribed end
position, its eigenmodes and static offset), and an mpmath linear solve of the blow
written from the mechanics (momentum and angular momentum of the free rigid pendulum,
the law of restitution).  Haag's formulas are evaluated with the shot v0, vλ, w0, wλ,
β1 (and v, w, φ1, φ2 at s) of :func:`..profiles.shot_blade`, the foci z, z' as the
roots of (30) with these values, K and K' by (35): :func:`haag_env`, which n°21–25
(:mod:`..ch1_shape`) use too.
"""
from __future__ import annotations

import functools

import mpmath as mp
import sympy as sp

from pendsym import checks, suspension
from pendsym.checks import Point
from .. import ch1_model, profiles
from ..common import DPS
from ..symbols import M_of_s, R, a, beta1, s, v, varphi1, varphi2, vl, w, wl

PAIRS = {"quick": (("hole", "compact"), ("tapered", "clock")),
         "full": (("hole", "compact"), ("tapered", "clock"), ("tapered", "compact"), ("uniform", "clock"),
                  ("bulged", "compact"), ("hole", "clock"))}
S_FRACTIONS = ("0.23", "0.5", "0.83")          # one point in each third of the blade (the hole's jumps)
IMPACT = {"m": "1", "m'": "0.37", "h": "0.62", "V": "0.8"}   # the blow of n°20
STATIC_Q = "0.013"                                           # Q/(mg) of n°18
DIRECT = "pendsym.suspension: the linearised blade (2)–(3) solved directly (no v, w)"
MODES = DIRECT + ", normal modes of K q = n² 𝕄 q (mpmath eig)"


def pairs(level: str, heavy: bool = False) -> tuple:
    """(profile, pendulum) pairs; ``heavy`` checks (quadratures) take three at level full."""
    chosen = PAIRS[level]
    return chosen[:2] + chosen[3:4] if heavy and level == "full" else chosen


# ---------------------------------------------------------------- Haag's quantities on the shot blade
@functools.lru_cache(maxsize=1)
def foci_coefficients():
    """The coefficients of the monic quadratic (30) (by (31), (32)), as mpmath functions of (a, R, β1, vλ, wλ)."""
    product, total = ch1_model.vieta()            # z² − (z + z')z + zz' = 0
    args = (a, R, beta1, vl, wl)
    return sp.lambdify(args, -total, "mpmath"), sp.lambdify(args, product, "mpmath")


@functools.lru_cache(maxsize=64)
def haag_env(name: str, pend: str, dps: int = DPS) -> dict:
    """Haag's quantities from the shot v, w: ends, β1, the foci z, z' (roots of (30)), K, K' (35)."""
    shot = profiles.shot_blade(name, dps)
    a_v, R_v, g_v = (mp.mpf(x) for x in profiles.PENDULUMS[pend])
    with mp.workdps(shot.wdps):
        b1, vl_v, wl_v = shot.beta1, shot.vl, shot.wl
        c1, c0 = (f(a_v, R_v, b1, vl_v, wl_v) for f in foci_coefficients())
        disc = mp.sqrt(c1 * c1 - 4 * c0)
        z_v, zp_v = (-c1 + disc) / 2, (-c1 - disc) / 2          # z > 0 > z'
        K_v, Kp_v = -(a_v + zp_v - vl_v) / b1, -(a_v + z_v - vl_v) / b1
        return {"a": a_v, "R": R_v, "g": g_v, "lambda": mp.mpf(profiles.profile(name).length), "v_0": shot.v0,
                "v_lambda": vl_v, "w_0": shot.w0, "w_lambda": wl_v, "beta_1": b1, "a_1": -wl_v,
                "z": z_v, "z'": zp_v, "K": K_v, "K'": Kp_v, "a-a_1": a_v + wl_v}


def base_env(name: str, pend: str, dps: int = DPS, **extra) -> dict:
    return dict(haag_env(name, pend, dps), **extra)


def s_value(name: str, fraction: str):
    return mp.mpf(fraction) * mp.mpf(profiles.profile(name).length)


def at_s(name: str, s_v, dps: int = DPS) -> dict:
    """v, w, φ1, φ2, M at s on the shot blade."""
    shot = profiles.shot_blade(name, dps)
    v_v, dv, w_v, dw = shot.state(s_v)
    return {v(s): v_v, w(s): w_v, varphi1(s): 1 + dv, varphi2(s): dw, M_of_s(s): shot.M_at(s_v), "s": s_v}


@functools.lru_cache(maxsize=64)
def direct_modes(name: str, pend: str, dps: int = DPS):
    """(direct blade, principal mode, parasitic mode) of the directly solved blade."""
    direct = profiles.direct_blade(name, dps)
    return (direct,) + suspension.modes(direct, *profiles.PENDULUMS[pend])


# ---------------------------------------------------------------- the points and the comparison
def mode_points(level: str, heavy: bool = False) -> list[dict]:
    return [{"profile": name, "pend": pend} for name, pend in pairs(level, heavy)]


def s_points(level: str) -> list[dict]:
    return [{"profile": name, "pend": pend, "s": S_FRACTIONS[i % 3]} for i, (name, pend) in enumerate(pairs(level))]


def attack_points(level: str) -> list[dict]:
    """Points with the index i of the point of attack b (point_b)."""
    return [{"profile": name, "pend": pend, "i": i} for i, (name, pend) in enumerate(pairs(level))]


def values_at(truth_desc: str, points, truth, env, scale=None, note: str = "") -> checks.Values:
    """checks.Values at the points (dicts) of ``points(level)``: the formula at env(pt) against truth(pt, dps),
    relative to |truth| (to scale(pt) where the truth is 0); the first point confirms at 45 digits."""
    def generate(level, dps):
        for pt in points(level):
            value = truth(pt, dps)
            yield Point(str(pt), env(pt), value, abs(value) if scale is None else scale(pt))
    return checks.Values(truth=truth_desc, points=generate, note=note,
                         confirm=lambda dps: {"truth": truth(points("full")[0], dps)},
                         params=lambda level: (("points", "; ".join(str(pt) for pt in points(level))),))


# ---------------------------------------------------------------- n°16: (64)–(66)
def beta_principal() -> checks.Values:
    return values_at(f"β/θ of the principal mode (node above G); {MODES}", mode_points,
                     lambda pt, dps: direct_modes(pt["profile"], pt["pend"], dps)[1].beta,
                     lambda pt: base_env(pt["profile"], pt["pend"], theta=1),
                     note="z' of the formula: the negative root of (30) with the shot vλ, wλ, β1")


def end_load(which: str) -> checks.Values:
    """(65), (66): the end load Y of the principal or parasitic mode (θ = 1)."""
    def truth(pt, dps):
        direct, principal, parasitic = direct_modes(pt["profile"], pt["pend"], dps)
        mode = principal if which == "principal" else parasitic
        return direct.loads(mode.beta, 1)[1]
    return values_at(f"end load Y of the {which} mode (θ = 1); {MODES}", mode_points, truth,
                     lambda pt: base_env(pt["profile"], pt["pend"], theta=1))


def deflection(index: int, what: str) -> checks.Values:
    """(66): φ (index 1) or φ' (2) of the principal mode (θ = 1) at s/λ ∈ S_FRACTIONS."""
    def truth(pt, dps):
        direct, principal, _ = direct_modes(pt["profile"], pt["pend"], dps)
        return direct.deflection(s_value(pt["profile"], pt["s"]), principal.beta, 1)[index]

    def env(pt):
        return {**base_env(pt["profile"], pt["pend"], theta=1), **at_s(pt["profile"], s_value(pt["profile"], pt["s"]))}
    return values_at(f"{what} of the principal mode (θ = 1) at s/λ ∈ {S_FRACTIONS}; {MODES}", s_points, truth, env,
                     note="v, w, φ1, φ2 at s from the shot blade")


# ---------------------------------------------------------------- n°18: (67)–(69)
def point_b(i: int, a_v) -> mp.mpf:
    """The point of attack AB = b: below G for even i, above for odd i."""
    return a_v * mp.mpf("1.35" if i % 2 == 0 else "0.45")


def static_env(pt) -> dict:
    a_v = mp.mpf(profiles.PENDULUMS[pt["pend"]][0])
    return base_env(pt["profile"], pt["pend"], Q=mp.mpf(STATIC_Q), mg=1, b=point_b(pt["i"], a_v))


def static_truth(pt, dps):
    """(β0, θ0, A, A'): static offset of the direct blade, A and A' the ordinates of the foci (nodes)."""
    direct, principal, parasitic = direct_modes(pt["profile"], pt["pend"], dps)
    a_v = mp.mpf(profiles.PENDULUMS[pt["pend"]][0])
    beta0, theta0 = suspension.static_offset(direct, a_v, point_b(pt["i"], a_v), mp.mpf(STATIC_Q))
    return beta0, theta0, beta0 + (a_v + parasitic.z) * theta0, beta0 + (a_v + principal.z) * theta0


STATIC = (f"pendsym.suspension.static_offset (equilibrium of the direct blade under Q = {STATIC_Q}·mg at AB = b, "
          f"b = 1.35a or 0.45a)")


def static(index: int, what: str) -> checks.Values:
    """(67)–(69): β0 (0), θ0 (1), A (2), A' (3) or A/A' (4) of the static offset."""
    if index == 4:
        def truth(pt, dps):
            offset = static_truth(pt, dps)
            return offset[2] / offset[3]
    else:
        def truth(pt, dps):
            return static_truth(pt, dps)[index]
    return values_at(f"{what}; {STATIC}; foci = nodes of the modes ({MODES})", attack_points, truth, static_env)


# ---------------------------------------------------------------- n°19–20: (70)–(76)
def impact_truth(a_v, R_v, b_v, m_v, m_striking_v, h_v, V_v):
    """The blow of n°19–20 from the mechanics: unknowns (β'0, θ'0, V', P), P the impulse on the rod.

    m(β'0 + aθ'0) = P (momentum, the blade's impulsive reaction zero), mR²θ'0 = (b − a)P (angular
    momentum about G), m'(V' − V) = −P, and the law of restitution β'0 + bθ'0 − V' = hV.
    """
    A = mp.matrix([[m_v, m_v * a_v, 0, -1], [0, m_v * R_v**2, 0, -(b_v - a_v)], [0, 0, m_striking_v, 1],
                   [1, b_v, -1, 0]])
    return mp.lu_solve(A, mp.matrix([0, 0, m_striking_v * V_v, h_v * V_v]))


def modal_amplitudes(principal, parasitic, a_v, beta_dot, theta_dot):
    """Amplitudes of F and F' after a blow giving (β'0, θ'0) from rest: q' = d_pr e_pr + d_pa e_pa,
    q(t) = Σ (d_i/n_i) e_i sin n_i t; F (node of the parasitic mode) moves with the principal mode."""
    d = mp.lu_solve(mp.matrix([[principal.beta, parasitic.beta], [1, 1]]), mp.matrix([beta_dot, theta_dot]))

    def ordinate(mode, focus):
        return mode.beta + (a_v + focus) * mode.theta
    return (d[0] * ordinate(principal, parasitic.z) / mp.sqrt(principal.n2),
            d[1] * ordinate(parasitic, principal.z) / mp.sqrt(parasitic.n2))


def impact(pt, dps):
    """(principal, parasitic, a, b, (β'0, θ'0, V', P)) for the blow of n°20 at the point's b."""
    _, principal, parasitic = direct_modes(pt["profile"], pt["pend"], dps)
    a_v, R_v, _ = (mp.mpf(x) for x in profiles.PENDULUMS[pt["pend"]])
    b_v = point_b(pt["i"], a_v)
    with mp.workdps(dps + 10):
        solution = impact_truth(a_v, R_v, b_v, *(mp.mpf(IMPACT[k]) for k in ("m", "m'", "h", "V")))
    return principal, parasitic, a_v, b_v, solution


def impact_env(pt) -> dict:
    _, _, _, b_v, solution = impact(pt, DPS)
    return base_env(pt["profile"], pt["pend"], b=b_v, **{"beta'_0": solution[0], "theta'_0": solution[1]},
                    **{k: mp.mpf(x) for k, x in IMPACT.items()})


IMPACT_DESC = (f"the blow solved from the mechanics (momentum, angular momentum about G of the free pendulum, "
               f"impulse of m', restitution; mpmath lu_solve) with {IMPACT}, b = 1.35a or 0.45a")


def focus_velocity(pt, dps, which="F"):
    principal, parasitic, a_v, _, solution = impact(pt, dps)
    focus = parasitic.z if which == "F" else principal.z
    return solution[0] + (a_v + focus) * solution[1]


def momentum() -> checks.Values:
    """(70): 0, the angular momentum about B after the blow, with the velocities of the solved blow."""
    def scale(pt):
        _, _, a_v, _, solution = impact(pt, DPS)
        return abs(solution[1]) * (mp.mpf(profiles.PENDULUMS[pt["pend"]][1]) ** 2 + a_v**2)
    return values_at(f"0: the angular momentum about B after the blow, with the velocities of {IMPACT_DESC}",
                     attack_points, lambda pt, dps: mp.mpf(0), impact_env, scale=scale,
                     note="residual relative to |θ'0|(R² + a²)")


def velocity_of_F() -> checks.Values:
    """(71): β'0 + (a + z)θ'0, the velocity of the node F of the parasitic mode after the blow."""
    return values_at(f"velocity β'0 + (a + z)θ'0 of the node F of the parasitic mode ({MODES}) after {IMPACT_DESC}",
                     attack_points, focus_velocity, impact_env,
                     note="θ'0 in the formula from the same blow; z, z' from (30) with the shot blade")


def amplitude(which: str) -> checks.Values:
    """(72): the amplitude of F (A) or F' (Ap) by the modal decomposition of the initial velocity."""
    def truth(pt, dps):
        principal, parasitic, a_v, _, solution = impact(pt, dps)
        A, Ap = modal_amplitudes(principal, parasitic, a_v, solution[0], solution[1])
        return A if which == "A" else Ap

    def env(pt):
        values = impact_env(pt)
        n2 = -values["K"] * values["g"] / values["z'"]                           # (34)
        n2_parasitic = -values["K'"] * values["g"] / values["z"]
        return dict(values, **{"v_F": focus_velocity(pt, DPS, "F"), "v_F'": focus_velocity(pt, DPS, "F'"),
                               "n": mp.sqrt(n2), "n'": mp.sqrt(n2_parasitic)})
    return values_at(f"amplitude of {'F' if which == 'A' else 'F′'} by the modal decomposition of the initial "
                     f"velocity ({MODES}) after {IMPACT_DESC}", attack_points, truth, env,
                     note="formula: the focus velocity of the same blow, n² = −Kg/z', n'² = −K'g/z (34) with the "
                          "shot blade")


def amplitude_ratio() -> checks.Values:
    """(73): A/A' by the modal decomposition after the blow."""
    def truth(pt, dps):
        principal, parasitic, a_v, _, solution = impact(pt, dps)
        A, Ap = modal_amplitudes(principal, parasitic, a_v, solution[0], solution[1])
        return A / Ap
    return values_at(f"A/A' by the modal decomposition ({MODES}) after {IMPACT_DESC}", attack_points, truth,
                     impact_env)


def blow(index: int, what: str) -> checks.Values:
    """(74), (75): θ'0 (index 1) or V' (2) of the solved blow."""
    return values_at(f"{what} of {IMPACT_DESC}", attack_points, lambda pt, dps: impact(pt, dps)[4][index],
                     impact_env)


def velocity_of_F_after_mass() -> checks.Values:
    """(76): the velocity of F after the blow of m', the formula without β'0, θ'0 in its environment."""
    def env(pt):
        values = impact_env(pt)
        values.pop("theta'_0"), values.pop("beta'_0")
        return values
    return values_at(f"velocity β'0 + (a + z)θ'0 of the node F of the parasitic mode ({MODES}) after {IMPACT_DESC}",
                     attack_points, focus_velocity, env)
