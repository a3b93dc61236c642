"""Haag 1935, chapter VII, n°98: the checks of (295)–(301) against the truth of :mod:`.truth`.

Along the order checks ε_E is the small parameter and θ0 = √(ε_E/RATIO), j = (j/θ0)·θ0: every first-order term of
(295) (ε_E G, GCθ0², GCj²) is then of order ε_E and the residual of a right form of order ε_E², while the shape
parameter tan α = 2ε_E/(πCθ0²) stays fixed (so the extremes stay where they are, in units of θ0).
"""
from __future__ import annotations

import dataclasses

import mpmath as mp
import sympy as sp

from pendsym import checks, verify
from ..ch2_dissymmetry.derivation import eps_E as eps_E_fn
from ..ch2_perturbations.derivation import g_fn
from ..symbols import s
from . import truth

PARAMS = (("G", truth.G_VALUE), ("C", truth.C_VALUE), ("ε_E/θ0²", truth.RATIO), ("n", "1"))
MODEL = ("θ'' = −V'(θ), V = ½θ² − Fθ + (GC/24)θ⁴ + ½ε_E Gθ²[θ > 0], F = j + (GC/6)j³ (the reduced gravity "
         "pendulum: one-sided stiffness of the blade, cubic of (283), couple of the clamping errors), one period by "
         "quadrature of the energy integral (smooth after θ = θ_t ∓ u²), 30 digits, 45 to confirm")
G1 = g_fn(1, eps_E_fn(s))


def _env(eps, ratio: str = truth.RATIO) -> dict:
    """ε_E, θ0 (θ0² = ε_E/ratio), G, C as mpf."""
    e = mp.mpf(eps)
    return {"varepsilon_E": e, "theta_0": mp.sqrt(e / mp.mpf(ratio)), "G": mp.mpf(truth.G_VALUE),
            "C": mp.mpf(truth.C_VALUE), G1: e, "G_2": mp.mpf(1),
            eps_E_fn(s): 0}                    # ε(s) only inside g1 = ε_E G2 (G2 = 1)


def _eps_str(eps) -> str:
    return mp.nstr(mp.mpf(eps), 25)


def dT_order(j_over_theta0: str, in_j: bool = False) -> checks.Order:
    """(295) (in φ1) or the line before it (in j, ``in_j``: the form is (4/G)ΔT/T) against the truth's
    ΔT/T(j, ε_E) − ΔT/T(0, 0) at the same θ0: residual O(ε_E²)."""
    ratio = mp.mpf(j_over_theta0)

    def at(expr, eps):
        env = _env(eps)
        env["j"] = ratio * env["theta_0"]
        env["varphi_1"] = mp.asin(-ratio)
        value = verify.value_at(expr, env)
        return value * env["G"] / 4 if in_j else value

    def true(eps, dps):
        st = truth.state(_eps_str(eps), dps)
        return truth.relative_change(st, ratio * mp.mpf(st["theta0"]), dps)
    return checks.Order(param="ε_E", values=checks.Geometric(*truth.EPS_RANGE), truth=true, at=at, expected=2,
                        truth_desc=MODEL + ": ΔT/T(j, ε_E) − ΔT/T(0, 0)",
                        params=PARAMS + (("j/θ0", j_over_theta0),),
                        note=f"θ0 = √(ε_E/{truth.RATIO}), j = {j_over_theta0}·θ0, φ1 = asin(−j/θ0)"
                             + ("; the form times G/4" if in_j else ""))


def _jmax_ratio(eps, dps: int) -> mp.mpf:
    """The truth's j of the maximum of T, over θ0."""
    st = truth.state(_eps_str(eps), dps)
    return truth.j_of_maximum(st["eps"], st["theta0"], dps) / mp.mpf(st["theta0"])


def jmax_order() -> checks.Order:
    """(297): j of the maximum over θ0, against the truth's (findroot of its dT/dj): residual O(ε_E)."""
    def at(expr, eps):
        env = _env(eps)
        return verify.value_at(expr, env) / env["theta_0"]
    return checks.Order(param="ε_E", values=checks.Geometric(*truth.EPS_RANGE), truth=_jmax_ratio, at=at, expected=1,
                        truth_desc=MODEL + "; j of the largest T by findroot (secant) of the truth's dT/dj (five-point "
                                           "central difference), over θ0", params=PARAMS,
                        note="j/θ0 fixed at first order (tan α fixed); the residual is the next order")


def gamma_order() -> checks.Order:
    """(300): the γ at which the form gives back the model's ε_E (findroot in γ), against γ = asin(−j/θ0) of the
    truth's maximum: residual O(ε_E)."""
    def at(expr, eps):
        env = _env(eps)
        gamma = sp.Symbol("gamma", real=True)
        f = verify.lambdify_mp(expr.subs({sp.Symbol("C", positive=True): env["C"],
                                          sp.Symbol("theta_0", positive=True): env["theta_0"]}), [gamma])
        guess = mp.atan(2 * env["varepsilon_E"] / (mp.pi * env["C"] * env["theta_0"] ** 2))
        return mp.findroot(lambda g: f(g) - env["varepsilon_E"], (guess, guess * mp.mpf("1.01")), solver="secant")

    def true(eps, dps):
        return mp.asin(-_jmax_ratio(eps, dps))
    return checks.Order(param="ε_E", values=checks.Geometric(*truth.EPS_RANGE), truth=true, at=at, expected=1,
                        truth_desc=MODEL + "; γ = asin(−j/θ0) at the truth's largest T", params=PARAMS,
                        note="the form solved for γ at the model's ε_E (findroot), compared with the truth's γ")


def j301_order() -> checks.Order:
    """(301): the form solved for j at ε_E = RATIO_301·θ0³ (γ → 0 with θ0), over θ0, against the truth's j of the
    maximum over θ0: residual O(θ0³) (γ², ε_E G, GCθ0² relative)."""
    def state(theta0):
        t0 = mp.mpf(theta0)
        return _eps_str(mp.mpf(truth.RATIO_301) * t0**3), mp.nstr(t0, 25)

    def at(expr, theta0):
        eps, t0 = (mp.mpf(x) for x in state(theta0))
        j = sp.Symbol("j", real=True)
        env = {"C": mp.mpf(truth.C_VALUE), "theta_0": t0}
        f = verify.lambdify_mp(expr.subs({sp.Symbol("C", positive=True): env["C"],
                                          sp.Symbol("theta_0", positive=True): t0}), [j])
        return mp.findroot(lambda x: f(x) - eps, -eps / t0) / t0

    def true(theta0, dps):
        eps, t0 = state(theta0)
        return truth.j_of_maximum(eps, t0, dps) / mp.mpf(t0)
    return checks.Order(param="θ0", values=checks.Geometric(*truth.THETA0_RANGE), truth=true, at=at, expected=3,
                        truth_desc=MODEL + "; j of the largest T (findroot of dT/dj), over θ0",
                        params=PARAMS[:2] + (("ε_E/θ0³", truth.RATIO_301),),
                        note="γ ~ ε_E/(Cθ0²) → 0 with θ0; the form solved for j at the model's ε_E")


def side_order() -> checks.Order:
    """n°98, the side of the larger modulus: θ0·d(ΔT/T)/dj at j = 0 against the truth's (central difference):
    residual O(ε_E²)."""
    def at(expr, eps):
        env = _env(eps)
        return verify.value_at(expr, env) * env["theta_0"]

    def true(eps, dps):
        st = truth.state(_eps_str(eps), dps)
        return truth.slope(st, 0, dps) * mp.mpf(st["theta0"])
    return checks.Order(param="ε_E", values=checks.Geometric(*truth.EPS_RANGE), truth=true, at=at, expected=2,
                        truth_desc=MODEL + "; dT/dj at j = 0 by five-point central difference, times θ0", params=PARAMS,
                        note="its sign, opposite to ε_E's, is the claim")


def minimum_check():
    """(298): the truth's T on j/θ0 from just below the printed (298) to 1 (the end of the range, the derived
    minimum): its smallest value on the grid is at the end j = θ0 (the derived j), not at the printed j."""
    def run(result, level):
        pairs, notes, printed_ok, printed_off = [], [], True, []
        with mp.workdps(40):
            for eps in ("1e-4", "1e-3"):
                env = _env(eps)
                t0 = env["theta_0"]
                j_printed = verify.value_at(result.printed_value, env)
                j_derived = verify.value_at(result.derived_value, env)
                st = truth.state(eps, 30)
                grid = [j_printed * (1 - mp.mpf("0.05")), j_printed] + [
                    j_printed + (t0 - j_printed) * k / 4 for k in (1, 2, 3)] + [t0]
                values = [truth.period_change(st["G"], st["C"], st["eps"], st["theta0"], mp.nstr(jv, 30), 30)
                          for jv in grid]
                least = grid[min(range(len(grid)), key=lambda k: values[k])]
                pairs.append((f"ε_E = {eps}", j_derived / t0, least / t0))
                printed_ok &= abs(least - j_printed) < mp.mpf(10) ** -20 * t0
                printed_off.append(abs(least - j_printed) / t0)
                slope = truth.slope(st, j_printed, 30)
                notes.append(f"ε_E = {eps}: printed j/θ0 = {mp.nstr(j_printed / t0, 6)}, truth dT/dj there "
                             f"{mp.nstr(slope, 4)} (T still falling); truth's least T of the grid at j/θ0 = "
                             f"{mp.nstr(least / t0, 6)}")
        ev = verify.value_check(truth_desc=MODEL + "; T on a grid of j from 0.95× the printed (298) to θ0: where it "
                                                   "is least", pairs=pairs, tol=mp.mpf(10) ** -20, params=PARAMS,
                                kind="quadrature",
                                note="; ".join(notes) + f"; printed form: max residual {mp.nstr(max(printed_off), 6)} "
                                                        "(|j/θ0| from the truth's least T)")
        return dataclasses.replace(ev, printed_agrees=bool(printed_ok))
    return run
