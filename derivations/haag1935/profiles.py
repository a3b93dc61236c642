"""The blades and pendulums on which chapter I (any M(s)) is checked.

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
"""
from __future__ import annotations

import functools

import sympy as sp

from pendsym import blade as B
from pendsym import suspension as SU

s = B.S
_LAM = sp.Rational(1, 10)           # 10 cm blade


def _profiles() -> dict[str, B.Blade]:
    M0 = sp.Rational(1, 400)        # u = λ/√M0 = 2
    third = _LAM / 3
    return {
        "uniform": B.Blade(_LAM, M0),
        "hole": B.Blade(_LAM, sp.Piecewise((M0, s < third), (M0 / 2, s < 2 * third), (M0, True))),
        "tapered": B.Blade(_LAM, M0 / 2 * (1 + s / _LAM) ** 3),
        "bulged": B.Blade(_LAM, M0 * (1 + 4 * (s / _LAM - sp.Rational(1, 2)) ** 2)),
    }


PROFILE_NAMES = ("uniform", "hole", "tapered", "bulged")
SYMMETRIC = ("uniform", "hole", "bulged")
UNSYMMETRIC = ("tapered",)


def profile(name: str) -> B.Blade:
    """The blade called ``name`` (one of PROFILE_NAMES)."""
    return _profiles()[name]


# Pendulums: (a, R, g) in metres and m/s²; a ≫ a1 = −wλ (a few cm) in both.
PENDULUMS = {
    "clock": ("0.9", "0.08", "9.81"),        # a seconds-like pendulum with a heavy bob
    "compact": ("0.12", "0.05", "9.81"),     # a short pendulum: the blade matters more
}


@functools.lru_cache(maxsize=16)
def blade_solution(name: str, dps: int = 30) -> B.BladeSolution:
    """Haag's v, w of (9)–(10) for the profile, shot by pendsym.blade."""
    return B.solve(profile(name), dps)


@functools.lru_cache(maxsize=16)
def suspension(name: str, dps: int = 30) -> SU.Suspension:
    """The directly solved blade (no v, w): the independent truth of pendsym.suspension."""
    return SU.solve(profile(name), dps)
