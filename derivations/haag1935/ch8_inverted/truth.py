"""Haag 1935, chapter VIII: the truth of the inverted blade (M < 0, g < 0), solved directly.

The stiffness of the directly solved blade (:mod:`pendsym.suspension`, |M| v'' + v = 0 in effect) gives
β1 = 1/S00, a1 where det K = 0, and the eigenproblem of the pendulum; the stability windows' ends are the u
where an eigenvalue n² of K q = n² 𝕄 q crosses zero (the slow one, at a = a1(u)) or passes through
infinity (β1 = 0: 1/n'² crosses zero), found by mpmath findroot on the truth.  The shot blade (pendsym.blade
with M < 0) gives v0, w0, wλ.  Never u → iu.
"""
from __future__ import annotations

from dataclasses import dataclass

import mpmath as mp
import sympy as sp

from pendsym import blade, checks, suspension, verify
from pendsym.result import Evidence
from ..ch7_gravity import truth

SIGN = -1


def key(x) -> str:
    return f"u={sp.nsimplify(x)}"


def direct_at(u_value, dps: int) -> suspension.Suspension:
    """The inverted uniform blade at a real u (not cached: findroot visits many)."""
    length = truth.LAMBDA
    M = -(length / sp.Float(str(u_value), dps + 15)) ** 2
    return suspension.solve(blade.Blade(length, M), dps)


def eigenvalues(u_value, a, dps: int) -> list:
    sus = direct_at(u_value, dps)
    return [n2 for n2, _ in truth.eigenmodes(sus, a, truth.R_VALUE, -mp.mpf(truth.G_VALUE))]


def lower_end(guess: str, dps: int = 30, a="-1") -> mp.mpf:
    """The u where 1/n'² (the eigenvalue of largest modulus) crosses zero near ``guess`` (β1 = 0).

    There the blade clamped at both ends buckles (tan(u/2) = u/2 is its antisymmetric buckling condition):
    the direct solve is singular at the root itself, where 1/n'² = 0."""
    with mp.workdps(dps + 10):
        def f(x):
            try:
                values = eigenvalues(x, mp.mpf(a), dps)
            except blade.SingularBlade:     # at the end itself the clamped blade buckles: 1/n'² = 0
                return mp.mpf(0)
            return 1 / max(values, key=abs)
        return mp.findroot(f, (mp.mpf(guess) - mp.mpf("0.01"), mp.mpf(guess) + mp.mpf("0.01")), solver="secant")


def upper_end(guess: str, a, dps: int = 30) -> mp.mpf:
    """The u where the slow n² crosses zero near ``guess``, at a fixed a (det K = 0: a = a1(u))."""
    with mp.workdps(dps + 10):
        def f(x):
            return min(eigenvalues(x, a, dps), key=abs)
        return mp.findroot(f, (mp.mpf(guess) - mp.mpf("0.001"), mp.mpf(guess)), solver="secant")


def beta1(k: str, dps: int = 30) -> mp.mpf:
    sus = truth.direct(k, SIGN, 0, dps)
    with mp.workdps(sus.wdps):
        return 1 / sus.stiffness[0, 0]


def critical(k: str, dps: int = 30) -> mp.mpf:
    return truth.critical_distance(truth.direct(k, SIGN, 0, dps))


SHOT = "pendsym.blade: v, w of (9)–(10) shot (mpmath odefun) for M = −(λ/u)² < 0, 30 digits, confirmed at 45"


def on_u(quantity, what: str, us=("1/2", "1", "5/2"), model: str = truth.MODEL) -> checks.Values:
    def points(level, dps):
        for x in us:
            yield checks.Point(f"u={x}", {"u": suspension.number(sp.Rational(x)), "lambda": mp.mpf("0.1")},
                               quantity(f"u={x}", dps))
    return checks.Values(truth=f"{model}; inverted uniform blade λ = 1/10, M = −(λ/u)²; {what}",
                         points=points, confirm=lambda dps: {"q": quantity(f"u={us[0]}", dps)})


def shot_end(name: str):
    return lambda k, dps: getattr(truth.shot(k, SIGN, dps), name)


# ---------------------------------------------------------------- n°100: existence of the vibrations
EXISTENCE_BLADES = ("u=1", "u=5/2", "u=6", "u=46/5", "tapered")     # M < 0 for each (sign −1)
EXISTENCE_OFFSETS = ("-0.05", "0.05", "-1", "0.3")                  # a − a1 (m), and below/above


@dataclass(frozen=True)
class ExistenceIff:
    """n°100: both n² of the eigenproblem (g < 0) are positive if and only if the derived (β1, a + wλ) are
    both negative, on inverted blades (uniform u = 1, 5/2, 6, 9.2, and the tapered profile with M < 0) at
    a = a1 ± 5 cm, a1 − 1 m, a1 + 30 cm.  Custom: an equivalence of signs at points of the model."""

    def __call__(self, result, level: str) -> Evidence:
        ok, notes, kinds = True, [], set()
        for k in EXISTENCE_BLADES:
            env0 = truth.numbers(k, SIGN)
            sus = truth.direct(k, SIGN, 0)
            for offset in EXISTENCE_OFFSETS:
                with mp.workdps(sus.wdps):
                    a = env0["a_1"] + mp.mpf(offset)
                    n2 = [x for x, _ in truth.eigenmodes(sus, a, env0["R"], env0["g"])]
                    exists = min(n2) > 0
                    values = [verify.value_at(part, dict(env0, a=a)) for part in result.derived_value]
                    claimed = all(x < 0 for x in values)
                ok &= exists == claimed
                kinds.add(exists)
                notes.append(f"{k}, a − a1 = {offset}: n² = {mp.nstr(min(n2), 4)}, {mp.nstr(max(n2), 4)}; "
                             f"β1 = {mp.nstr(values[0], 4)}, a + wλ = {mp.nstr(values[1], 4)}")
        ok &= kinds == {True, False}
        return Evidence(kind="inequality", passed=bool(ok),
                        truth=f"{truth.MODEL}: the signs of both n² against those of β1 and a + wλ (g < 0)",
                        note="; ".join(notes))


# ---------------------------------------------------------------- n°101: the largest weight (311)
def quarter_turn(dps: int = 30) -> mp.mpf:
    """The u where a1 of the direct stiffness crosses zero (a > 0 possible below it), by findroot."""
    with mp.workdps(dps + 10):
        return mp.findroot(lambda x: truth.critical_distance(direct_at(x, dps)), (mp.mpf("1.5"), mp.mpf("1.6")),
                           solver="secant")


BLADE_SECTION = {"E": "2.1e11", "e": "0.0003", "h": "0.01", "lambda": "0.1"}   # steel, 0.3 mm × 1 cm × 10 cm


def largest_weight(dps: int = 30) -> checks.Values:
    """(311): the weight mg = EIu²/λ² (156) at the u where a1 = 0, I = e³h/12."""
    def weight(dps_):
        with mp.workdps(dps_ + 10):
            env = {k: mp.mpf(x) for k, x in BLADE_SECTION.items()}
            return env["E"] * env["e"] ** 3 * env["h"] / 12 * quarter_turn(dps_) ** 2 / env["lambda"] ** 2

    def points(level, dps_):
        yield checks.Point("steel 0.3 mm × 1 cm × 10 cm", {k: mp.mpf(x) for k, x in BLADE_SECTION.items()},
                           weight(dps_))
    return checks.Values(truth=f"{truth.MODEL}; the u where a1 of the inverted uniform blade vanishes (findroot), "
                               "mg = EIu²/λ² (156)", points=points, confirm=lambda dps_: {"mg": weight(dps_)})


# ---------------------------------------------------------------- n°101: the windows of stability (309)
def transverse_stiffness(u_value, dps: int = 30) -> mp.mpf:
    """S00 = ∂Y/∂β of the directly solved inverted blade (= 1/β1): det K/((mg)²a) → S00 as a → −∞."""
    sus = direct_at(u_value, dps)
    with mp.workdps(sus.wdps):
        return sus.stiffness[0, 0]


def far_upper_end(guess: str, dps: int = 30) -> mp.mpf:
    """The upper end of a window as a → −∞: det K = (mg)²[S00(S11 + a) − S01S10], so that the u where the slow
    n² crosses zero tends to the zero of S00 (β1 → ∞ changes sign); found by findroot on S00."""
    with mp.workdps(dps + 10):
        return mp.findroot(lambda x: transverse_stiffness(x, dps), (mp.mpf(guess) - mp.mpf("0.01"),
                                                                    mp.mpf(guess) + mp.mpf("0.01")), solver="secant")


WINDOW_SAMPLES = ("2", "3", "5", "8.5", "9.2", "9.6", "13")     # u = λ√(mg/EI): weight ratios mg/P = (2u/π)²
FAR_BELOW = "-1"                                                # a − a1 (m): a far below its critical value


@dataclass(frozen=True)
class WindowSigns:
    """(309): at weight ratios u inside and outside the derived windows (0, π) ∪ (2x1, 3π), with a = a1(u) − 1 m
    (so that a + wλ < 0, (305)), both n² of the eigenproblem (g < 0) are positive if and only if u lies in a
    window.  Custom: an equivalence of signs at points of the model."""

    def __call__(self, result, level: str) -> Evidence:
        lower_1, upper_1, upper_0 = (mp.mpf(sp.N(part, 40)) for part in result.derived_value)
        ok, notes, kinds = True, [], set()
        for text in WINDOW_SAMPLES:
            x = mp.mpf(text)
            sus = direct_at(x, 30)
            with mp.workdps(sus.wdps):
                a = truth.critical_distance(sus) + mp.mpf(FAR_BELOW)
                n2 = [value for value, _ in truth.eigenmodes(sus, a, truth.R_VALUE, -mp.mpf(truth.G_VALUE))]
            stable = min(n2) > 0
            inside = bool(x < upper_0 or lower_1 < x < upper_1)
            ok &= stable == inside
            kinds.add(stable)
            notes.append(f"u = {text}: n² = {mp.nstr(min(n2), 4)}, {mp.nstr(max(n2), 4)}, "
                         f"{'inside' if inside else 'outside'} the windows")
        ok &= kinds == {True, False}
        return Evidence(kind="inequality", passed=bool(ok),
                        truth=f"{truth.MODEL}: the signs of both n² (g < 0, a = a1 − 1 m) at weight ratios u "
                              f"{', '.join(WINDOW_SAMPLES)} against the derived windows",
                        note="; ".join(notes))


# ---------------------------------------------------------------- n°100: the steps (302), (303); (306); (308)
def mode_env(k: str, offset: str) -> dict:
    """The inverted blade ``k`` at a = a1 + offset: the shot end values, both modes of the eigenproblem (g < 0)
    named by their nodes (z' < z: (n², z') and (n'², z)), and K = Y/θ of each mode from the direct stiffness
    (Y = S00β + S01θ, β = −(a + node)θ), which does not use (34) or (36)."""
    env = dict(truth.numbers(k, SIGN))
    sus = truth.direct(k, SIGN, 0)
    with mp.workdps(sus.wdps):
        a = env["a_1"] + mp.mpf(offset)
        modes = sorted(truth.eigenmodes(sus, a, env["R"], env["g"]), key=lambda pair: pair[1])
        S = sus.stiffness
        ratios = [S[0, 0] * (-(a + node)) + S[0, 1] for _, node in modes]
    env.update({"a": a, "n^2": modes[0][0], "z'": modes[0][1], "n'^2": modes[1][0], "z": modes[1][1],
                "K": ratios[0], "K'": ratios[1], "exists": min(modes[0][0], modes[1][0]) > 0})
    return env


@dataclass(frozen=True)
class NegativeIffExists:
    """(302), (303): on the inverted blades and distances of :class:`ExistenceIff`, every component of the
    derived form (the quantities claimed negative) is negative if (``iff``: and only if) both n² of the
    eigenproblem are positive.  The env holds the modes' nodes and K = Y/θ from the direct stiffness.  Custom:
    an implication or equivalence of signs at points of the model."""

    what: str
    iff: bool = True

    def __call__(self, result, level: str) -> Evidence:
        ok, notes, kinds = True, [], set()
        for k in EXISTENCE_BLADES:
            for offset in EXISTENCE_OFFSETS:
                env = mode_env(k, offset)
                with mp.workdps(40):
                    values = [verify.value_at(part, env) for part in result.derived_value]
                claimed = all(x < 0 for x in values)
                ok &= env["exists"] == claimed if self.iff else (claimed or not env["exists"])
                kinds.add(env["exists"])
                notes.append(f"{k}, a − a1 = {offset}: n² = {mp.nstr(env['n^2'], 4)}, {mp.nstr(env[FAST], 4)}; "
                             + ", ".join(mp.nstr(x, 4) for x in values))
        ok &= kinds == {True, False}
        return Evidence(kind="inequality", passed=bool(ok),
                        truth=f"{truth.MODEL}: the signs of both n² (g < 0) against those of {self.what} "
                              f"({'if and only if' if self.iff else 'implied by the existence'})",
                        note="; ".join(notes))


FAST = "n'^2"
POSITIVE_A_BLADES = ("u=1", "u=3/2", "u=5/2", "u=46/5", "tapered")


@dataclass(frozen=True)
class PositiveDistanceIff:
    """(306): on inverted blades with β1 < 0 (304), a pendulum at some a > 0 (a = a1/2 when a1 > 0, else
    a = 1 mm) has both n² positive if and only if the derived wλ is negative (wλ of the shot blade)."""

    def __call__(self, result, level: str) -> Evidence:
        ok, notes, kinds = True, [], set()
        for k in POSITIVE_A_BLADES:
            env = dict(truth.numbers(k, SIGN))
            sus = truth.direct(k, SIGN, 0)
            with mp.workdps(sus.wdps):
                a = env["a_1"] / 2 if env["a_1"] > 0 else mp.mpf("0.001")
                n2 = [x for x, _ in truth.eigenmodes(sus, a, env["R"], env["g"])]
                exists = min(n2) > 0 and env["beta_1"] < 0
                claimed = verify.value_at(result.derived_value, env) < 0
            ok &= env["beta_1"] < 0 and exists == claimed
            kinds.add(exists)
            notes.append(f"{k}: β1 = {mp.nstr(env['beta_1'], 4)}, a = {mp.nstr(a, 4)}: n² = {mp.nstr(min(n2), 4)}, "
                         f"{mp.nstr(max(n2), 4)}; wλ = {mp.nstr(env['w_lambda'], 4)}")
        ok &= kinds == {True, False}
        return Evidence(kind="inequality", passed=bool(ok),
                        truth=f"{truth.MODEL}: both n² at a > 0 (g < 0) against the sign of wλ of the shot blade",
                        note="; ".join(notes))


SIGN_U = ("1", "5/2", "3", "4", "6", "9", "19/2", "12", "31/2")


@dataclass(frozen=True)
class PositiveIffStable:
    """(308): at u = λ√(mg/EI) inside and outside the windows, the derived form is positive if and only if β1 of
    the direct stiffness (1/S00) is negative (304), i.e. 1/n'² has the sign for which the fast vibration can
    exist."""

    def __call__(self, result, level: str) -> Evidence:
        ok, notes, kinds = True, [], set()
        for x in SIGN_U:
            value_u = suspension.number(sp.Rational(x))
            b1 = beta1(f"u={x}")
            with mp.workdps(40):
                claimed = verify.value_at(result.derived_value, {"u": value_u}) > 0
            ok &= claimed == (b1 < 0)
            kinds.add(claimed)
            notes.append(f"u = {x}: β1 = {mp.nstr(b1, 4)}")
        ok &= kinds == {True, False}
        return Evidence(kind="inequality", passed=bool(ok),
                        truth=f"{truth.MODEL}: the sign of β1 = 1/S00 of the direct inverted uniform blade at u "
                              f"{', '.join(SIGN_U)}", note="; ".join(notes))


# ---------------------------------------------------------------- n°101 with n°50: the period (for the scenes)
N2_BLADES = ("u=1/2", "u=1", "u=3/2")          # inside the window (0, π/2) where a > 0 is possible (311)
N2_OFFSETS = ("-0.01", "-0.2")                 # a − a1 (m): near the critical distance and far below it


def node_mode_n2(key: str, offset: str, dps: int = 30) -> tuple:
    """(a, n²) of the mode whose node is z' < 0 (the upper one of the two, zz' = −R²) of the eigenproblem
    K q = n² 𝕄 q of the rigid pendulum on the directly solved inverted blade ``key`` (g < 0), a = a1 + offset."""
    sus = truth.direct(key, SIGN, 0, dps)
    with mp.workdps(sus.wdps):
        env = truth.numbers(key, SIGN, dps)        # g, R read at the working precision
        a = env["a_1"] + mp.mpf(offset)
        modes = sorted(truth.eigenmodes(sus, a, env["R"], env["g"]), key=lambda pair: pair[1])
        return a, modes[0][0]


def n2_check() -> checks.Values:
    """n² of the derived form against the eigenvalue of the truth's mode with node z' (both vibrations exist:
    a < a1, β1 < 0)."""
    def points(level, dps):
        for k in N2_BLADES:
            for offset in N2_OFFSETS:
                a, n2 = node_mode_n2(k, offset, dps)
                yield checks.Point(f"{k}, a − a1 = {offset}", {"u": suspension.number(sp.Rational(k[2:])),
                                                                 "lambda": suspension.number(truth.LAMBDA), "a": a,
                                                                 "R": mp.mpf(truth.R_VALUE),
                                                                 "g": mp.mpf(truth.G_VALUE)}, n2)
    return checks.Values(truth=f"{truth.MODEL}; g < 0, M = −(λ/u)², λ = 1/10, R = {truth.R_VALUE}; the eigenvalue of "
                               "the mode whose node is above G (z' < 0)", points=points,
                         confirm=lambda dps: {"n2": node_mode_n2(N2_BLADES[0], N2_OFFSETS[0], dps)[1]})
