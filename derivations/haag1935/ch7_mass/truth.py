"""Haag 1935, chapter VII n°96 and chapter VIII n°103: the independent truth, the gravity pendulum on a blade
with mass.

The blade of chapter VII's truth (:mod:`..ch7_gravity.truth`: λ = 1/10, M = ±(λ/u)², or chapter I's tapered
profile; M < 0 and g < 0 for the inverted blade) is given a uniform density μ = m'/λ, m'/m = 10⁻²⁰, and either
its horizontal inertia or its weight (:mod:`pendsym.massive_blade`: the linearised blade with mass carrying the
rigid pendulum, det D(ω²) = 0 shot by odefun); the pendulum stands at a = a1 + ελ (a1 − ελ inverted), a1 where
det K = 0 for the massless blade (placed on the truth, never on a formula).  ΔT/T = √(n0²/n²) − 1 of the slow
mode (the root next to the smaller massless n²), n0² on the massless blade by the same determinant.

m'/m = 10⁻²⁰: the part of second order in m'/m is (m'/(mε))² relative to the first, ≤ 10⁻¹⁰ for ε ≥ 10⁻⁵,
far below the O(ε) remainders that the checks fit; ΔT/T is then ~10⁻¹⁵ and the determinant is solved at
dps + 12 digits, so that its first-order part keeps 25 digits or more.

The temperature (294): per degree dλ/λ = α, da/a = dR/R = α', M → M(1 + β + 4α) (n°14, the coefficients of
:mod:`..ch7_gravity.truth`), the blade's mass m' unchanged (μ = m'/λ), a placed at a1 + ελ before the warming;
a forward difference over h = ε/1000 degree (the quantities vary by α/ε per degree: the O(h) error is
hα/ε ~ 10⁻⁸ relative, far below the O(ε) remainder fitted).

Cost (cold, 30 digits): a massless n² 0.45 s, a massive one 1–1.3 s; each ε point of a check needs one or two.
"""
from __future__ import annotations

import functools

import mpmath as mp
import sympy as sp

from pendsym import blade, checks, massive_blade, suspension, verify
from ..ch7_gravity import truth as gravity
from .derivation import DT_T

DT_NAME = DT_T.name                               # ΔT/T in an environment

MASS_RATIO = sp.Rational(1, 10**20)              # m'/m
EPS = ("1e-5", "1e-3")                           # ε: four points in geometric progression at every level
POINTS = 4
STEP = sp.Rational(1, 1000)                      # h/ε, the temperature step in degrees over ε
MODEL = ("pendsym.massive_blade: the linearised blade with uniform mass m' = 10⁻²⁰m and {what} carrying the rigid "
         "pendulum at a = a1 {sign} ελ (a1 where det K = 0 on the massless blade), the slow root of det D(ω²) "
         "(odefun shooting, findroot); ΔT/T = √(n0²/n²) − 1 against the massless blade")


def rational(x, dps: int) -> sp.Rational:
    """An mpf as an exact Rational of its decimal digits (a hashable cache key)."""
    return sp.Rational(mp.nstr(x, dps + 15))


@functools.lru_cache(maxsize=64)
def placed(key: str, sign: int, eps: str, dps: int) -> sp.Rational:
    """a = a1 + sign·ελ on the massless blade ``key`` (chapter VII's truth)."""
    env = gravity.numbers(key, sign, dps)
    with mp.workdps(dps + 15):
        return rational(env["a_1"] + sign * mp.mpf(eps) * env["lambda"], dps)


def warmed_blade(key: str, sign: int, h: sp.Rational) -> blade.Blade:
    """The blade ``key`` after h degrees: λ(1 + αh), M(1 + (β + 4α)h) (M = EI/(mg), (1), n°14)."""
    base = gravity.base_blade(key, sign)
    return blade.Blade(base.length * (1 + gravity.ALPHA * h), base.M * (1 + (gravity.BETA_T + 4 * gravity.ALPHA) * h))


@functools.lru_cache(maxsize=256)
def slow_n2(key: str, sign: int, eps: str, what: str, dps: int, h: sp.Rational = sp.Integer(0)) -> mp.mpf:
    """n² of the slow mode of the pendulum at a = a1 ± ελ on the blade ``key`` warmed by h degrees (a, R by α'h):
    ``what`` "none" (the massless blade), "inertia" or "weight" (the blade's mass with that effect alone)."""
    bl = warmed_blade(key, sign, h)
    mb = massive_blade.MassiveBlade(bl, 0 if what == "none" else MASS_RATIO / bl.length,
                                    inertia=what == "inertia", weight=what == "weight")
    grown = 1 + gravity.ALPHA_ROD * h
    a = placed(key, sign, eps, dps) * grown
    R = sp.Rational(gravity.R_VALUE) * grown
    g = sign * sp.Rational(gravity.G_VALUE)
    return massive_blade.principal_n2(mb, a, R, g, dps, True)


def period_change(key: str, sign: int, eps: str, what: str, dps: int, h: sp.Rational = sp.Integer(0)) -> mp.mpf:
    """ΔT/T = √(n0²/n²) − 1 of the blade's inertia or weight (:func:`slow_n2`), at h degrees."""
    with mp.workdps(dps + 10):
        return mp.sqrt(slow_n2(key, sign, eps, "none", dps, h) / slow_n2(key, sign, eps, what, dps, h)) - 1


def temperature_changes(key: str, sign: int, eps: str, dps: int) -> dict:
    """Per degree, by a forward difference over h = ε/1000 degree: dT/T of the massless pendulum, d(ΔT)/T of the
    weight's perturbation ΔT = T − T0 (T0 the massless period at the temperature, T the massive one), both over
    T0 at h = 0; and ΔT/T at h = 0 (shared with the (292)–(293) truth)."""
    h = STEP * sp.Rational(eps)
    with mp.workdps(dps + 10):
        def period(what, k):                          # T/(2π) = 1/n
            return 1 / mp.sqrt(slow_n2(key, sign, eps, what, dps, k * h))
        T0 = period("none", 0)
        hh = mp.mpf(h.p) / h.q
        dT = (period("none", 1) - T0) / (hh * T0)
        gap = {k: period("weight", k) - period("none", k) for k in (0, 1)}
        return {"dT/T": dT, "d(Delta T)/T": (gap[1] - gap[0]) / (hh * T0),
                DT_NAME: period_change(key, sign, eps, "weight", dps)}


@functools.lru_cache(maxsize=16)
def blade_numbers(key: str, sign: int, dps: int) -> dict:
    """λ, R, u, m = 1, m' (the ratio), and J = (1/λ)∫(s − x) ds at K = 0 (the ε → 0 mode) by quadrature on the
    shot blade (uniform density), by symbol name."""
    env = gravity.numbers(key, sign, dps)
    sol = gravity.shot(key, sign, dps)
    with mp.workdps(sol.wdps):
        out = {name: env[name] for name in ("lambda", "R", "w_lambda", "M_lambda", "alpha", "alpha'", "beta_t")}
        if "u" in env:
            out["u"] = env["u"]
        out.update({"m": mp.mpf(1), "m'": mp.mpf(MASS_RATIO.p) / MASS_RATIO.q, "J": sol.weight_integral(0),
                    "G_2": sol.G(2, 0)})
    return out


def eps_values(level: str) -> list:
    return verify.geometric(*EPS, POINTS)


def mass_order(what: str, key: str, sign: int = 1, scaled: bool = False) -> checks.Order:
    """ΔT/T of the blade's ``what`` ("inertia" or "weight") at a = a1 ± ελ against a form of chapter VII/VIII,
    per unit m'/m (times ε when ``scaled``: the forms of order 1/ε): residual O(ε)."""
    def scale(p):
        ratio = mp.mpf(MASS_RATIO.p) / MASS_RATIO.q
        return ratio / mp.mpf(p) if scaled else ratio

    def truth(p, dps):
        return period_change(key, sign, mp.nstr(mp.mpf(p), 20), what, dps) / scale(p)

    def at(expr, p):
        env = dict(blade_numbers(key, sign, checks.DPS), varepsilon=mp.mpf(p))
        return verify.value_at(expr, env) / scale(p)
    effect = "its horizontal inertia (no weight)" if what == "inertia" else "its weight in the tension (no inertia)"
    per = "ε(ΔT/T)/(m'/m)" if scaled else "(ΔT/T)/(m'/m)"
    return checks.Order(param="varepsilon", values=eps_values, truth=truth, at=at, expected=1,
                        truth_desc=MODEL.format(what=effect, sign="+" if sign > 0 else "−")
                        + f"; {per}; blade {key}, {'direct' if sign > 0 else 'inverted (M < 0, g < 0)'}",
                        params=(("blade", key), ("m'/m", "1e-20"), ("R", gravity.R_VALUE),
                                ("g", str(sign * float(gravity.G_VALUE)))),
                        note="J (where a form has it) = (1/λ)∫(s − x) ds at K = 0 by quadrature on the shot blade")


def temperature_order(quantity: str, key: str = "u=2", sign: int = 1) -> checks.Order:
    """(294) (``quantity`` "relation": d(ΔT)/T against the form in ΔT/T and dT/T of the truth, relative residual)
    or its ratio to dT/T ("ratio": against the form in J, ε, times ε/(m'/m)): residual O(ε)."""
    def scale(env, p):
        if quantity == "relation":
            return env[DT_NAME] * env["dT/T"]
        return mp.mpf(MASS_RATIO.p) / MASS_RATIO.q / mp.mpf(p)

    def env_of(p, dps):
        return dict(blade_numbers(key, sign, dps), varepsilon=mp.mpf(p),
                    **temperature_changes(key, sign, mp.nstr(mp.mpf(p), 20), dps))

    def truth(p, dps):
        env = env_of(p, dps)
        value = env["d(Delta T)/T"] if quantity == "relation" else env["d(Delta T)/T"] / env["dT/T"]
        return value / scale(env, p)

    def at(expr, p):
        env = env_of(p, checks.DPS)
        return verify.value_at(expr, env) / scale(env, p)
    what = ("d(ΔT)/T per degree over (ΔT/T)(dT/T), all three from the truth" if quantity == "relation" else
            "[d(ΔT)/T]/(dT/T) per degree, times ε/(m'/m)")
    return checks.Order(param="varepsilon", values=eps_values, truth=truth, at=at, expected=1,
                        truth_desc=MODEL.format(what="its weight in the tension (no inertia)", sign="+")
                        + f"; warmed by h = ε/1000 degree (λ, M, a, R by α, α', M by β + 4α, m' fixed: n°14), forward "
                        f"differences; {what}; "
                        f"blade {key}",
                        params=(("blade", key), ("m'/m", "1e-20"), ("alpha", str(gravity.ALPHA)),
                                ("alpha'", str(gravity.ALPHA_ROD)), ("beta", str(gravity.BETA_T))))


def critical_change(key: str = "u=2", sign: int = 1) -> checks.Order:
    """n°96's dε/ε per degree against the massless truth: ε = (a − a1)/λ with a1 of the warmed blade (det K = 0),
    a, λ warmed; central difference over ±10⁻⁶ degree (chapter VII's warmed blades); dT/T (for a form in it) of
    chapter VII's truth (5-point stencil); times ε: residual O(ε)."""
    def env_of(p, dps):
        env = dict(blade_numbers(key, sign, dps), varepsilon=mp.mpf(p))
        env["a"] = gravity.numbers(key, sign, dps)["a_1"] + sign * mp.mpf(p) * env["lambda"]
        env["dT/T"] = gravity.temperature(key, sign, p, dps)
        return env

    def truth(p, dps):
        env = env_of(p, dps)
        with mp.workdps(dps + 15):
            h = suspension.number(gravity.H_DEGREE)

            def eps_at(k):
                lam = env["lambda"] * (1 + suspension.number(gravity.ALPHA) * k * h)
                a = env["a"] * (1 + suspension.number(gravity.ALPHA_ROD) * k * h)
                return (a - gravity.critical_distance(gravity.warmed(key, sign, k, dps))) / lam
            return (eps_at(1) - eps_at(-1)) / (2 * h) / eps_at(0) * env["varepsilon"]

    def at(expr, p):
        env = env_of(p, checks.DPS)
        return verify.value_at(expr, env) * env["varepsilon"]
    return checks.Order(param="varepsilon", values=eps_values, truth=truth, at=at, expected=1,
                        truth_desc=f"{gravity.MODEL}; ε = (a − a1)/λ of the blade warmed by ±10⁻⁶ degree (λ, M, a "
                                   f"warmed, n°14), central difference, times ε; blade {key}",
                        params=(("blade", key), ("alpha", str(gravity.ALPHA)), ("alpha'", str(gravity.ALPHA_ROD)),
                                ("beta", str(gravity.BETA_T))),
                        note="dT/T (in a form) = d log T per degree of the slow mode, chapter VII's truth "
                             "(5-point stencil)")
