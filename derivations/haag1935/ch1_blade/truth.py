"""Haag 1935, chapter I, n°1–4: the independent truth of (1)–(20).

What is compared, on the blades of :mod:`..profiles` (uniform, hole, tapered,
bulged) at 30 digits, the truth confirmed by a 45-digit solve of the hole blade:

- the directly solved blade (:mod:`pendsym.suspension`, no v, w): its φ, φ' along
  the blade for an end position and its end load (13), (14); (8) integrated;
  its stiffness and the eigenproblem of the pendulum for (5), (6);
- the shot v, w of :mod:`pendsym.blade`: the Wronskian (15), (16), the end values
  behind the inequalities of n°3, quadratures of (18), (19), the identities (20)
  (which must hold on the symmetric blades and fail on the tapered one).
"""
from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import mpmath as mp
import sympy as sp

from pendsym import checks, verify
from pendsym.checks import Point
from pendsym.result import Evidence, Result
from .. import ch1_model, profiles

from ..profiles import DIRECT_TRUTH, MODES_TRUTH, SHOT_TRUTH
from ..symbols import N, Y, beta_ddot, m, theta, theta_ddot, varphi, s
from . import derivation

FRACTIONS = ("0", "0.37", "0.81", "1")            # s/λ where φ, φ' are compared


# ---------------------------------------------------------------- (13), (14): the deflection
def deflection_rows(which: int, fractions=FRACTIONS):
    """φ (which = 1) or φ' (which = 2) of the direct blade at s = fraction·λ, end position (0.3λ, −0.7),
    with its end load Y and the shot φ1, φ2, v, w, M at s in the environment."""
    def rows(name, pend, dps):
        direct, shot = profiles.direct_blade(name, dps), profiles.shot_blade(name, dps)
        env0 = profiles.shot_env(name, dps)
        beta_v, theta_v = mp.mpf("0.3") * env0["lambda"], mp.mpf("-0.7")
        _, Y_v, _ = direct.loads(beta_v, theta_v)
        for fraction in fractions:
            s_v = mp.mpf(fraction) * env0["lambda"]
            v_v, dv_v, w_v, dw_v = shot.state(s_v)
            env = dict(env0, Y=Y_v, theta=theta_v, varphi_1=1 + dv_v, varphi_2=dw_v, v_s=v_v, w_s=w_v,
                       M_s=shot.M_at(s_v))
            truth = direct.deflection(s_v, beta_v, theta_v)[which]
            scale = abs(theta_v) * (1 if which == 1 else 1 / env0["lambda"])
            yield Point(f"s={fraction}λ", env, truth, max(abs(mp.mpf(truth)), mp.mpf(scale)))
    return rows


def deflection(which: int, what: str) -> checks.Values:
    return profiles.values_on_profiles(f"{DIRECT_TRUTH}: {what}", deflection_rows(which))


def solution_residual(fractions, statement: str) -> checks.All:
    """(13) solves (8): φ = Yφ1 + θφ2 with the shot φ1, φ2 minus the direct φ (the residual the derived
    form claims 0) at interior points, and the symbolic proof of the derived form."""
    rows = deflection_rows(1, fractions)

    def points(level, dps):
        for name in profiles.LEVEL_PROFILES[level]:
            for pt in rows(name, None, dps):
                by_13 = mp.mpf(verify.value_at(derivation.phi_solution(), pt.env))
                yield Point(pt.label, pt.env, by_13 - mp.mpf(pt.truth), pt.denom)
    values = checks.Values(truth=DIRECT_TRUTH + ": φ by (13) with the shot φ1, φ2 minus the direct φ",
                           points=points, confirm=profiles.confirmation_env)
    return checks.All((values, checks.Proof(statement)), truth=DIRECT_TRUTH + " + symbolic proof")


def solution_ends(statement: str) -> checks.All:
    """(φ_0, φ_λ) of (13) against the direct φ at s = 0, λ, and the proof that they are (0, θ)."""
    rows = deflection_rows(1, ("0", "1"))

    def points(level, dps):
        for name in profiles.LEVEL_PROFILES[level]:
            for index, point in enumerate(rows(name, None, dps)):
                yield dataclasses.replace(point, component=index)
    ends = checks.Values(truth=DIRECT_TRUTH + ": φ at s = 0, λ", points=points, confirm=profiles.confirmation_env)
    proof = checks.Proof(statement, holds=lambda derived: sp.simplify(derived[0]) == 0
                         and sp.simplify(derived[1] - theta) == 0)
    return checks.All((ends, proof), truth=DIRECT_TRUTH + " + symbolic proof")


def end_values_12() -> checks.Values:
    """(12): φ1 = 1 + v', φ2 = w' of the shot blade at 0 and λ (a check of the shooting against (10)–(11))."""
    def points(level, dps):
        for name in profiles.LEVEL_PROFILES[level]:
            shot = profiles.shot_blade(name, dps)
            length = profiles.as_mpf(shot.blade.length)
            values = (shot.phi1(0), shot.phi1(length), shot.phi2(0), shot.phi2(length))
            for i, value in enumerate(values):
                yield Point(f"{name}[{i}]", {}, value, 1, component=i)
    return checks.Values(truth=SHOT_TRUTH + ": φ1 = 1 + v', φ2 = w' at 0 and λ", points=points,
                         confirm=profiles.confirmation_env)


@dataclass(frozen=True)
class IntegratedBending:
    """(8) integrated over the direct blade: ∫(φ − Y) ds = [Mφ']_0^λ by quadrature (the form is not
    evaluated: it must be φ − Y exactly, a symbolic check).  Custom: the truth here is a property of
    the model that the derived right side of (8) names, not a value of the form."""

    def __call__(self, result: Result, level: str) -> Evidence:
        worst, n = mp.mpf(0), 0
        with mp.workdps(40):
            for name in profiles.LEVEL_PROFILES[level]:
                direct = profiles.direct_blade(name, checks.DPS)
                length = profiles.as_mpf(direct.blade.length)
                for beta_fraction, theta_text in profiles.END_POSITIONS:
                    beta_v, theta_v = mp.mpf(beta_fraction) * length, mp.mpf(theta_text)
                    _, Y_v, _ = direct.loads(beta_v, theta_v)
                    lhs = direct.integrate(lambda x: direct.deflection(x, beta_v, theta_v)[1] - Y_v)
                    moments = [direct.M_at(x) * direct.deflection(x, beta_v, theta_v)[2] for x in (0, length)]
                    scale = length * abs(Y_v) + abs(theta_v) * length
                    worst = max(worst, abs(lhs - (moments[1] - moments[0])) / scale)
                    n += 1
        right_side = varphi(s) - Y
        derived_ok = sp.simplify(result.derived - right_side) == 0
        printed_ok = result.printed is not None and sp.simplify(result.printed - right_side) == 0
        digits = checks.confirmation_digits(profiles.confirmation_env)
        passed = worst < checks.TOL and derived_ok and digits >= checks.MIN_DIGITS
        return Evidence(kind="quadrature", passed=bool(passed),
                        truth=DIRECT_TRUTH + "; mpmath quad of φ − Y", max_residual=verify.rounded(worst),
                        printed_agrees=bool(printed_ok), confirm_digits=verify.rounded(digits),
                        note=f"{n} end positions; the right side of (8) is φ − Y: {derived_ok}; "
                             f"truth confirmed to {digits:.1f} digits at {checks.CONFIRM_DPS}")


@dataclass(frozen=True)
class NewtonEulerModes:
    """(5) and (6) linearised, with (Y, N) from the direct blade's stiffness: the n² of 𝕄q'' + Kq = 0
    against suspension.modes.  ``equation`` (5 or 6) is taken from the Result, the other from the
    derivation.  Custom: the compared quantity is an eigenvalue of the system, not a value of the form."""

    equation: int

    def __call__(self, result: Result, level: str) -> Evidence:
        forms = {5: derivation.centre_of_gravity(1), 6: derivation.angular_momentum()}
        forms[self.equation] = result.derived
        e5, e6 = ch1_model.linearized(forms[5] / m), ch1_model.linearized(forms[6])
        coefficients = [[e.coeff(x) for x in (beta_ddot, theta_ddot, Y, N, theta)] for e in (e5, e6)]
        worst = mp.mpf(0)
        with mp.workdps(40):
            for name in profiles.LEVEL_PROFILES[level]:
                S = profiles.direct_blade(name, checks.DPS).stiffness
                for pend in profiles.LEVEL_PENDULUMS[level]:
                    env = profiles.mode_env(name, pend, checks.DPS)
                    c = [[mp.mpf(verify.value_at(x, env)) for x in row] for row in coefficients]
                    mass = mp.matrix([[c[i][0], c[i][1]] for i in range(2)])
                    stiffness = mp.matrix([[c[i][2] * S[0, j] + c[i][3] * S[1, j] + c[i][4] * j for j in range(2)]
                                           for i in range(2)])
                    got = sorted(mp.re(x) for x in mp.eig(mp.inverse(mass) * stiffness)[0])
                    want = sorted((env["n^2"], env["n'^2"]))
                    worst = max(worst, *(abs(x - y) / y for x, y in zip(got, want)))
        digits = checks.confirmation_digits(profiles.confirmation_env)
        return Evidence(kind="value", passed=bool(worst < checks.TOL and digits >= checks.MIN_DIGITS),
                        truth=MODES_TRUTH + "; stiffness of the suspension", max_residual=verify.rounded(worst),
                        confirm_digits=verify.rounded(digits),
                        note="the first-order parts of (5), (6), with (Y, N) from the suspension's stiffness: the n² "
                             f"of 𝕄q'' + Kq = 0 against suspension.modes; truth confirmed to {digits:.1f} digits")


# ---------------------------------------------------------------- n°3: the shot v, w
def shot_state_rows(quantity, fractions=("0.3", "0.7", "1")):
    """quantity(v, v', w, w') of the shot blade at s = fraction·λ."""
    def rows(name, pend, dps):
        shot = profiles.shot_blade(name, dps)
        env = profiles.shot_env(name, dps)
        for fraction in fractions:
            truth = quantity(shot.state(mp.mpf(fraction) * env["lambda"]))
            yield Point(f"s={fraction}λ", env, truth, abs(mp.mpf(truth)))
    return rows


def shot_value_rows(key: str):
    """The shot end value called ``key`` itself."""
    def rows(name, pend, dps):
        env = profiles.shot_env(name, dps)
        yield Point(key, env, env[key], abs(mp.mpf(env[key])))
    return rows


def quadrature_rows(integrand):
    """∫_0^λ integrand(shot, s, env) ds by Gauss–Legendre quadrature on the shot blade."""
    def rows(name, pend, dps):
        shot = profiles.shot_blade(name, dps)
        env = profiles.shot_env(name, dps)
        truth = shot.integrate(lambda x: integrand(shot, x, env))
        yield Point("quad", env, truth, abs(mp.mpf(truth)))
    return rows


def wronskian_15() -> checks.All:
    """(15): v w' − w v' of the shot blade at three points, and d/ds(vw' − wv') = 0 by (9) (proof)."""
    rows = shot_state_rows(lambda st: st[0] * st[3] - st[2] * st[1])
    values = profiles.values_on_profiles(SHOT_TRUTH + ": v w' − w v' at s = 0.3λ, 0.7λ, λ", rows)
    proof = checks.Proof("d/ds(vw' − wv') = 0 by (9)",
                         holds=lambda derived: sp.simplify(ch1_model.wronskian_derivative()) == 0)
    return checks.All((values, proof), truth=values.truth)


def shot_value(key: str, what: str) -> checks.Values:
    return profiles.values_on_profiles(f"{SHOT_TRUTH}: {what}", shot_value_rows(key))


def quadrature(integrand, what: str) -> checks.Values:
    return profiles.values_on_profiles(f"{SHOT_TRUTH}; mpmath quad of {what}", quadrature_rows(integrand))


# ---------------------------------------------------------------- n°4: (20)
def symmetric(key: str) -> checks.All:
    """(20) holds on the symmetric blades and fails (by more than 1e-4) on the tapered one."""
    def rows(names):
        def points(level, dps):
            for name in names:
                env = profiles.shot_env(name, dps)
                yield Point(name, env, env[key], abs(mp.mpf(env[key])))
        return points
    holds = checks.Values(truth=f"{SHOT_TRUTH} ({key} of the shot blade, symmetric blades: "
                                f"{', '.join(profiles.SYMMETRIC)})", points=rows(profiles.SYMMETRIC),
                          confirm=profiles.confirmation_env)
    fails = checks.Values(truth=f"{SHOT_TRUTH} ({key} of the unsymmetric tapered blade)",
                          points=rows(profiles.UNSYMMETRIC), fails_by=mp.mpf("1e-4"))
    return checks.All((holds, fails), truth=holds.truth)
