"""Haag 1935, chapters VII–VIII: the check declarations (order in ε against the eigenproblem of :mod:`.truth`)."""
from __future__ import annotations

import mpmath as mp
import sympy as sp

from pendsym import blade, checks, suspension, verify
from . import truth

EPS = checks.Geometric("1e-6", "1e-3")
U_PATH = {"quick": ("1/10", "3/20", "1/5", "3/10"), "full": ("1/10", "1/8", "3/20", "1/5", "1/4", "3/10")}
# where a remainder of relative size u/45 must dominate one of size u² (n°86): u ≪ 1/45
U_SMALL = {"quick": ("1/10000", "1/5000", "1/2500", "1/1250"),
           "full": ("1/10000", "1/5000", "1/2500", "1/1250", "1/625", "1/312")}


def env_at(key: str, sign: int, eps, dps: int = 30) -> dict:
    """The truth's state at ε, plus G2(K = 0) = ∫w²/M by quadrature on the shot blade and W/(mg) of the slow
    mode (pendsym.suspension.energy, θ = 1)."""
    env = truth.state(key, sign, eps, dps)
    sol = truth.shot(key, sign, dps)
    env["G_2"] = sol.G(2, 0)
    env["W/(mg)"] = suspension.energy(truth.direct(key, sign, 0, dps), -(env["a"] + env["z'"]), 1)
    return env


def order(quantity, what: str, expected: float, key: str = "u=2", sign: int = 1, scale=None,
          with_energy: bool = False) -> checks.Order:
    """Order in ε of |quantity(truth) − formula| at a = a1 + sign·ελ on the blade ``key``; both divided by
    ``scale(env)`` when given."""
    state = env_at if with_energy else truth.state

    def at(expr, p):
        env = state(key, sign, p)
        value = verify.value_at(expr, env)
        return value / scale(env) if scale else value

    def value(p, dps):
        env = state(key, sign, p, dps)
        q = quantity(env, key, sign, p, dps)
        return q / scale(env) if scale else q
    return checks.Order(param="varepsilon", values=EPS, truth=value, at=at, expected=expected,
                        truth_desc=f"{truth.MODEL}; {what}; blade {key}, {'direct' if sign > 0 else 'inverted'}",
                        params=(("blade", key), ("R", truth.R_VALUE), ("g", str(sign * float(truth.G_VALUE)))))


def on(name: str):
    """A quantity of the truth's state, by name."""
    return lambda env, *_: env[name]


def sensitivity(env, key, sign, p, dps):
    """G = −d log n²/d log g of the slow mode (:func:`.truth.sensitivity`)."""
    return truth.sensitivity(key, sign, p, dps)


def g_correction(env, key, sign, p, dps):
    """dg/g = −(2/G) dT/T of a 1° warming, both from the truth (:func:`.truth.g_correction`)."""
    return truth.g_correction(key, sign, p, dps)


def temperature(env, key, sign, p, dps):
    """d log T per degree of the slow mode (:func:`.truth.temperature`)."""
    return truth.temperature(key, sign, p, dps)


def inverse_eps(env):
    """1/ε, the size of G: residuals of εG."""
    return 1 / env["varepsilon"]


def suppleness(env, key, sign, p, dps):
    """S = W'/W of the slow mode: W = mg·energy (θ = 1), W + W' = ½ q·(Kq) the potential (n°23, n°101 note)."""
    sus = truth.direct(key, sign, 0, dps)
    with mp.workdps(sus.wdps):
        q = mp.matrix([-(env["a"] + env["z'"]), 1])
        potential = (q.T * suspension.stiffness_matrix(sus, env["a"], 1, env["g"]) * q)[0] / 2
        strain = env["g"] * suspension.energy(sus, q[0], 1)
        return (potential - strain) / strain


def blade_section(env) -> dict:
    """m = 1 kg, e = 0.3 mm, h = 1 cm and E from EI = mgM = mgλ²/u², I = e³h/12 (156), for forms in E, e, h, m."""
    m, e, h = mp.mpf(1), mp.mpf("0.0003"), mp.mpf("0.01")
    return {"m": m, "e": e, "h": h, "E": 12 * m * abs(env["g"]) * env["lambda"] ** 2 / (env["u"] ** 2 * e**3 * h)}


def u_path(quantity, what: str, expected: float, eps_of_u, scale, sign: int = 1, path=U_PATH,
           dps: int = 30) -> checks.Order:
    """Order in u along ε = eps_of_u(u) on the uniform blade (u → 0 results, n°85–86)."""
    def at(expr, p):
        env = truth.state(f"u={p}", sign, eps_of_u(sp.Rational(p)))
        return verify.value_at(expr, dict(env, **blade_section(env))) / scale(env)

    def value(p, dps):
        key, eps = f"u={p}", eps_of_u(sp.Rational(p))
        env = truth.state(key, sign, eps, dps)
        return quantity(env, key, sign, eps, dps) / scale(env)
    return checks.Order(param="u", values=lambda level: [sp.Rational(x) for x in path[level]], truth=value,
                        at=at, expected=expected, truth_desc=f"{truth.MODEL}; {what}; uniform blade λ = 1/10",
                        params=(("R", truth.R_VALUE),), dps=dps, confirm_dps=dps + 15)


def C_values(sign: int) -> checks.Values:
    """(285)/(317): C = (wλ − ∫w'^4)/(wλ − ∫w'^2) by quadrature on the shot uniform blade (direct or inverted)."""
    us = ("7/10", "2", "43/10") if sign > 0 else ("1/2", "1", "3/2")

    def C_of(key, dps):
        sol = truth.shot(key, sign, dps)
        with mp.workdps(sol.wdps):
            return (sol.wl - sol.F(4, 0)) / (sol.wl - sol.F(2, 0))

    def points(level, dps):
        for x in us:
            yield checks.Point(f"u={x}", {"u": suspension.number(sp.Rational(x)), "lambda": mp.mpf("0.1")},
                               C_of(f"u={x}", dps))
    return checks.Values(truth=f"shot {'inverted ' if sign < 0 else ''}uniform blade (pendsym.blade, M = "
                               f"{'−' if sign < 0 else ''}(λ/u)²), wλ and ∫w'^n by Gauss–Legendre quadrature",
                         points=points, confirm=lambda dps: {"C": C_of(f"u={us[0]}", dps)}, kind="quadrature")


SECTION = {"E": "2.1e11", "e": "0.0003", "theta": "1"}     # steel, 0.3 mm; θ = 1 radian


def along_blade(what: str, kind: str, key: str, sign: int = 1, fraction: str = "0.6") -> checks.Order:
    """Order in ε of a quantity of the blade at s = fraction·λ in the slow mode (θ = 1): ``kind`` "shape"
    (ωy, y of the directly solved blade) or "stress" (E(e/2)φ', the bending stress of n°90)."""
    def env_of(p, dps=30):
        env = truth.state(key, sign, p, dps)
        env.update({k: mp.mpf(x) for k, x in SECTION.items()})
        env["s"] = mp.mpf(fraction) * env["lambda"]
        return env

    def value(p, dps):
        env = env_of(p, dps)
        sus = truth.direct(key, sign, 0, dps)
        with mp.workdps(sus.wdps):
            y, _, curvature = sus.deflection(env["s"], -(env["a"] + env["z'"]), 1)
            if kind == "shape":
                return env["u"] / env["lambda"] * y
            return env["E"] * env["e"] / 2 * curvature

    return checks.Order(param="varepsilon", values=EPS, truth=value, at=lambda expr, p: verify.value_at(expr, env_of(p)),
                        expected=1, truth_desc=f"{truth.MODEL}; {what} at s = {fraction}λ in the slow mode (θ = 1, "
                                                f"β = −(a + z')); blade {key}, {'direct' if sign > 0 else 'inverted'}",
                        params=(("blade", key), ("E", SECTION["E"]), ("e", SECTION["e"])))
