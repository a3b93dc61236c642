"""Haag 1935, chapter IX: the independent truth of the gravity meter on a rhombus-holed blade, no Bessel function.

The inverted blade |M| = M0(1 + k|s − λ/2|) (:func:`.rhombus_truth.rhombus_blade`, M < 0, g → −g) is

* solved directly for a prescribed end position (:mod:`pendsym.suspension`: the linearised (2)–(3), no v, w):
  β1 = 1/S00 of its stiffness, a1 where det K(a) = 0, and the eigenproblem K q = n² 𝕄 q of the rigid pendulum on
  it (g < 0), whose slow mode (node z' above the bob) gives n²; the sensitivity G = −d log n²/d log g at fixed
  EI, m, a, R, λ by a 5-point stencil (g(1 + jh), M/(1 + jh), h = 1e-16, j = ±1, ±2; 42 working digits or more);
* shot (:mod:`pendsym.blade`, mpmath odefun on each half): wλ and F_n = ∫ w'^n ds by quadrature.
"""
from __future__ import annotations

import functools

import mpmath as mp
import sympy as sp

from pendsym import blade, checks, suspension, verify

from ..ch7_gravity import truth as gravity
from . import rhombus_truth

CASES = {"quick": (("1/2", "3/5", "6/5"), ("1", "1/10", "1")),
         "full": (("1/2", "3/5", "6/5"), ("1", "1/10", "1"), ("2/5", "2", "3/2"))}
WHERE = "(M0, k, λ) = (1/2, 3/5, 6/5), (1, 1/10, 1) and, at full level, (2/5, 2, 3/2)"
R_VALUE, G_VALUE = "0.3", "9.81"
OFFSETS = ("-0.01", "-0.2")             # a − a1 (m): near the critical distance and far below it
STEP = sp.Rational(1, 10**16)           # relative step of the stencil in g
DIRECT = ("pendsym.suspension: the inverted rhombus blade |M| = M0(1 + k|s − λ/2|) solved directly (no v, w), "
          "the rigid pendulum's eigenproblem K q = n² 𝕄 q (g < 0) by mpmath eig")


@functools.lru_cache(maxsize=64)
def direct(M0: str, k: str, lam: str, j: int = 0, dps: int = 30) -> suspension.Suspension:
    """The inverted rhombus blade solved directly, at g(1 + j·STEP): M divided by 1 + j·STEP."""
    base = rhombus_truth.rhombus_blade(M0, k, lam)
    return suspension.solve(blade.Blade(base.length, base.M / (1 + j * STEP)), dps)


def beta1(case: tuple, dps: int) -> mp.mpf:
    sus = direct(*case, dps=dps)
    with mp.workdps(sus.wdps):
        return 1 / sus.stiffness[0, 0]


def critical(case: tuple, dps: int) -> mp.mpf:
    return gravity.critical_distance(direct(*case, dps=dps))


def slow_n2(case: tuple, a, dps: int, j: int = 0) -> mp.mpf:
    """n² of the mode whose node z' is above the bob (the smaller node, zz' = −R²), g < 0."""
    sus = direct(*case, j=j, dps=dps)
    with mp.workdps(sus.wdps):
        g = -mp.mpf(G_VALUE) * (1 + j * suspension.number(STEP))
        modes = sorted(gravity.eigenmodes(sus, a, mp.mpf(R_VALUE), g), key=lambda pair: pair[1])
        return modes[0][0]


def sensitivity(case: tuple, eps, dps: int) -> mp.mpf:
    """G = −d log n²/d log g of the slow mode at a = a1 − ελ (312), 5-point stencil (error O((G·STEP)⁴))."""
    with mp.workdps(direct(*case, dps=dps).wdps):
        a = critical(case, dps) - mp.mpf(eps) * suspension.number(sp.Rational(case[2]))
        h = suspension.number(STEP)
        logs = {j: mp.log(slow_n2(case, a, dps, j)) for j in (-2, -1, 1, 2)}
        return -(8 * (logs[1] - logs[-1]) - (logs[2] - logs[-2])) / (12 * h)


def env_of(case: tuple, **extra) -> dict:
    env = rhombus_truth.environment(*case)
    env.update({"R": mp.mpf(R_VALUE), "g": mp.mpf(G_VALUE), **extra})
    return env


def on_direct(quantity, what: str) -> checks.Values:
    """A Values check against ``quantity(case, dps)`` of the directly solved blade."""
    def points(level, dps):
        for case in CASES[level]:
            yield checks.Point(f"(M0, k, λ) = ({', '.join(case)})", env_of(case), quantity(case, dps))
    return checks.Values(truth=f"{DIRECT}; {what}; {WHERE}", points=points,
                         confirm=lambda dps: {what: quantity(CASES["quick"][0], dps)})


def n2_check() -> checks.Values:
    """n² of the derived form against the slow eigenvalue, a = a1 + offset (a1 of the direct stiffness)."""
    def points(level, dps):
        for case in CASES[level]:
            for offset in OFFSETS:
                a = critical(case, dps) + mp.mpf(offset)
                yield checks.Point(f"(M0, k, λ) = ({', '.join(case)}), a − a1 = {offset}", env_of(case, a=a),
                                   slow_n2(case, a, dps))

    def confirm(dps):
        case = CASES["quick"][0]
        return {"n2": slow_n2(case, critical(case, dps) + mp.mpf(OFFSETS[0]), dps)}
    return checks.Values(truth=f"{DIRECT}; the slow eigenvalue (node above the bob), R = {R_VALUE}, |g| = {G_VALUE}, "
                               f"a = a1 − 0.01 and a1 − 0.2; {WHERE}", points=points, confirm=confirm)


def on_shot(quantity, what: str) -> checks.Values:
    """A Values check against ``quantity(solution)`` of the shot blade (quadrature)."""
    def points(level, dps):
        for case in CASES[level]:
            sol = rhombus_truth.shot(*case, dps)
            with mp.workdps(sol.wdps):
                yield checks.Point(f"(M0, k, λ) = ({', '.join(case)})", env_of(case), quantity(sol))

    def confirm(dps):
        sol = rhombus_truth.shot(*CASES["quick"][0], dps)
        with mp.workdps(sol.wdps):
            return {what: quantity(sol)}
    return checks.Values(truth=f"{rhombus_truth.BLADE}; {what} by quadrature; {WHERE}", points=points, confirm=confirm,
                         kind="quadrature")


def F(n: int):
    return lambda sol: sol.F(n, 0)


def C(sol) -> mp.mpf:
    """(284): (wλ − F4)/(wλ − F2) on the shot blade."""
    return (sol.wl - sol.F(4, 0)) / (sol.wl - sol.F(2, 0))


def G_order(case: tuple = CASES["quick"][0]) -> checks.Order:
    """Order in ε of |εG(truth) − εG(formula)| at a = a1 − ελ, G = −d log n²/d log g (stencil)."""
    def at(expr, p):
        return verify.value_at(expr, env_of(case, varepsilon=mp.mpf(p))) * mp.mpf(p)

    def value(p, dps):
        return sensitivity(case, p, dps) * mp.mpf(p)
    return checks.Order(param="varepsilon", values=checks.Geometric("1e-6", "1e-3"), truth=value, at=at, expected=1,
                        truth_desc=f"{DIRECT}; εG, G = −d log n²/d log g of the slow mode by a 5-point stencil in g "
                                   f"(h = 1e-16); (M0, k, λ) = ({', '.join(case)}), R = {R_VALUE}, |g| = {G_VALUE}",
                        params=(("M0", case[0]), ("k", case[1]), ("lambda", case[2])))
