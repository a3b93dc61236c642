"""Haag 1935, chapter VIII: the truth of the inverted blade (M < 0, g < 0), solved directly.

The stiffness of the directly solved blade (:mod:`pendsym.suspension`, |M| v'' + v = 0 in effect) gives
β1 = 1/S00, a1 where det K = 0, and the eigenproblem of the pendulum; the stability windows' ends are the u
where an eigenvalue n² of K q = n² 𝕄 q crosses zero (the slow one, at a = a1(u)) or passes through
infinity (β1 = 0: 1/n'² crosses zero), found by mpmath findroot on the truth.  The shot blade (pendsym.blade
with M < 0) gives v0, w0, wλ.  Never u → iu.
"""
from __future__ import annotations

import mpmath as mp
import sympy as sp

from pendsym import blade, checks, suspension
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
