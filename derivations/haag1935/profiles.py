"""The blades and pendulums on which chapter I (any M(s)) is checked, and their numbers.

Haag's chapter I holds for any positive stiffness ratio M(s) = EI/(mg) (1).
Its results are checked on blades of four kinds (lengths and M in metres and
square metres; u = λ/√M is between 1 and 3, as for real clock springs):

- ``uniform``: M constant (chapter III's case);
- ``hole``: a rectangular hole in the middle third, where I (hence M) is halved
  (chapter IX's first example; M jumps);
- ``tapered``: M = M0(1 + s/λ)³, a blade whose thickness grows linearly from O to A
  (unsymmetric: the identities of n°4 must fail for it, those of n°3 hold);
- ``bulged``: M = M0(1 + 4(s/λ − ½)²), symmetric about the middle but not uniform (n°4).

The pendulums (a = AG, R the radius of gyration, g) are chosen with a above the
critical distance a1 = −wλ (41), so that both vibrations exist (n°9).

Two independent solutions of each blade: :func:`shot_blade` (Haag's v, w of
(9)–(10), shot by :mod:`pendsym.blade`) and :func:`direct_blade` (the linearised
blade (2)–(3) solved for a prescribed end position, no v, w:
:mod:`pendsym.suspension`).  :func:`shot_env` and :func:`mode_env` give their
numbers by symbol name, ready for :func:`pendsym.verify.value_at`.
"""
from __future__ import annotations

import functools

import mpmath as mp
import sympy as sp

from pendsym import blade, checks, suspension

s = blade.S
LENGTH = sp.Rational(1, 10)         # 10 cm blade


def _profiles() -> dict[str, blade.Blade]:
    M0 = sp.Rational(1, 400)        # u = λ/√M0 = 2
    third = LENGTH / 3
    return {
        "uniform": blade.Blade(LENGTH, M0),
        "hole": blade.Blade(LENGTH, sp.Piecewise((M0, s < third), (M0 / 2, s < 2 * third), (M0, True))),
        "tapered": blade.Blade(LENGTH, M0 / 2 * (1 + s / LENGTH) ** 3),
        "bulged": blade.Blade(LENGTH, M0 * (1 + 4 * (s / LENGTH - sp.Rational(1, 2)) ** 2)),
    }


PROFILE_NAMES = ("uniform", "hole", "tapered", "bulged")
SYMMETRIC = ("uniform", "hole", "bulged")
UNSYMMETRIC = ("tapered",)


def profile(name: str) -> blade.Blade:
    """The blade called ``name`` (one of PROFILE_NAMES)."""
    return _profiles()[name]


# Pendulums: (a, R, g) in metres and m/s²; a ≫ a1 = −wλ (a few cm) in both.
PENDULUMS = {
    "clock": ("0.9", "0.08", "9.81"),        # a seconds-like pendulum with a heavy bob
    "compact": ("0.12", "0.05", "9.81"),     # a short pendulum: the blade matters more
}


# which blades and pendulums a check visits, per level; the end positions (β/λ, θ) of the load checks
LEVEL_PROFILES = {"quick": ("uniform", "tapered"), "full": PROFILE_NAMES}
LEVEL_PENDULUMS = {"quick": ("clock",), "full": ("clock", "compact")}
END_POSITIONS = (("1", "0"), ("0", "1"), ("0.3", "-0.7"))
CONFIRM_PROFILE = "hole"            # the blade whose truth is recomputed at 45 digits

SHOT_TRUTH = "shot v, w of pendsym.blade (odefun shooting, 30 digits)"
DIRECT_TRUTH = ("pendsym.suspension: the linearised blade (2)–(3) solved directly for the end position (β, θ), "
                "no v, w (30 digits)")
MODES_TRUTH = ("pendsym.suspension.modes: the eigenproblem K q = n² 𝕄 q of the pendulum on the directly solved "
               "blade, no v, w (30 digits)")


@functools.lru_cache(maxsize=16)
def shot_blade(name: str, dps: int = 30) -> blade.BladeSolution:
    """Haag's v, w of (9)–(10) for the profile, shot by pendsym.blade."""
    return blade.solve(profile(name), dps)


@functools.lru_cache(maxsize=16)
def direct_blade(name: str, dps: int = 30) -> suspension.Suspension:
    """The directly solved blade (no v, w): the independent truth of pendsym.suspension."""
    return suspension.solve(profile(name), dps)


# ---------------------------------------------------------------- numbers by symbol name
def as_mpf(x) -> mp.mpf:
    """A SymPy number (or a float-like) as an mpf at the working precision."""
    return suspension.number(sp.nsimplify(x))


def pendulum(name: str) -> tuple:
    """(a, R, g) of the pendulum, as mpf at the working precision."""
    return tuple(mp.mpf(x) for x in PENDULUMS[name])


@functools.lru_cache(maxsize=64)
def M_range(name: str) -> tuple:
    """(M1, M2) = min and max of M on [0, λ]: ends of each smooth piece and its critical points (n°3)."""
    cands = []
    for lo, hi, expr in blade.segments(profile(name)):
        xs = [lo, hi] + [root for root in sp.solve(sp.diff(expr, s), s) if root.is_real and lo < root < hi]
        cands += [expr.subs(s, x) for x in xs]
    return min(cands), max(cands)


def shot_env(name: str, dps: int = 30) -> dict:
    """v0, vλ, w0, wλ, β1, β2, λ of the shot blade, and M1, M2, μ = M2/M1 (n°3), by symbol name."""
    sol = shot_blade(name, dps)
    M1, M2 = M_range(name)
    return {"v_0": sol.v0, "v_lambda": sol.vl, "w_0": sol.w0, "w_lambda": sol.wl, "beta_1": sol.beta1,
            "beta_2": sol.beta2, "lambda": as_mpf(sol.blade.length),
            "M_1": as_mpf(M1), "M_2": as_mpf(M2), "mu": as_mpf(M2 / M1)}


def mode_env(name: str, pend: str, dps: int = 30) -> dict:
    """a, R, g and, from suspension.modes (no v, w): the foci z (lower, node of the parasitic mode),
    z' (upper, node of the principal mode), n² (principal) and n'² (parasitic)."""
    a, R, g = pendulum(pend)
    principal, parasitic = suspension.modes(direct_blade(name, dps), a, R, g)
    return {"a": a, "R": R, "g": g, "z": parasitic.z, "z'": principal.z,
            "n^2": principal.n2, "n'^2": parasitic.n2}


def shot_and_mode_env(name: str, pend: str | None, dps: int = 30) -> dict:
    """:func:`shot_env`, and :func:`mode_env` of the pendulum ``pend`` when one is given."""
    env = shot_env(name, dps)
    if pend:
        env.update(mode_env(name, pend, dps))
    return env


def confirmation_env(dps: int) -> dict:
    """The truth the confirmation recomputes: the shot hole blade and its modes under the clock pendulum."""
    return shot_and_mode_env(CONFIRM_PROFILE, "clock", dps)


def values_on_profiles(truth: str, rows, pend: bool = False, **options) -> checks.Values:
    """checks.Values over the level's profiles (and pendulums, with ``pend``): ``rows(name, pend, dps)``
    yields the Points of one blade; the first Point of the hole blade (clock pendulum), recomputed at
    45 digits with its environment, confirms the truth."""
    def points(level: str, dps: int):
        for name in LEVEL_PROFILES[level]:
            for pendulum_name in (LEVEL_PENDULUMS[level] if pend else (None,)):
                yield from rows(name, pendulum_name, dps)

    def confirm(dps: int) -> dict:
        first = next(iter(rows(CONFIRM_PROFILE, "clock" if pend else None, dps)))
        return {"truth": first.truth, **first.env}
    return checks.Values(truth=truth, points=points, confirm=confirm, **options)


def positive_on_blades(what: str) -> checks.Inequality:
    """A quantity the memoir claims positive, with the shot end values of every blade."""
    def points(level: str, dps: int):
        return ((name, shot_env(name, dps)) for name in PROFILE_NAMES)
    return checks.Inequality(truth=f"{SHOT_TRUTH}; {what}", points=points, confirm=confirmation_env)


def positive_on_modes(what: str) -> checks.Inequality:
    """A quantity the memoir claims positive, with the shot end values and the modes of every blade
    under both pendulums."""
    def points(level: str, dps: int):
        return ((f"{name}/{pend}", shot_and_mode_env(name, pend, dps))
                for name in PROFILE_NAMES for pend in LEVEL_PENDULUMS["full"])
    return checks.Inequality(truth=f"{MODES_TRUTH}; {what}", points=points, confirm=confirmation_env)
