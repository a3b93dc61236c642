"""Haag 1935, chapter IX, n°107–110: the independent truth of the rhombus hole, no Bessel function involved.

The inverted blade (n°100: g → −g, so M < 0 in (9) of :mod:`pendsym.blade`) of length λ with
|M| = M0(1 + k|s − λ/2|) on 0 ≤ s ≤ λ (the origin of the memoir's s at the middle) is solved by shooting
(:func:`pendsym.blade.solve`: mpmath ``odefun`` on each half, the break at the middle) at ``dps`` digits;
v_0, v_λ, w_0, w_λ are its end values and G_2 = ∫ w²/|M| ds its mpmath quadrature (n°110, M taken in absolute
value as in footnote (2) of n°107).  The formulas are evaluated at ω = 1/√M0, k, λ and x_0, x_1 of (334).
"""
from __future__ import annotations

import functools
from typing import Callable

import mpmath as mp
import sympy as sp

from pendsym import blade, checks, verify

from ..common import TOL

S = blade.S
CASES = {"quick": (("1/2", "3/5", "6/5"), ("1", "1/10", "1")),
         "full": (("1/2", "3/5", "6/5"), ("1", "1/10", "1"), ("2/5", "2", "3/2"))}
BLADE = ("inverted blade |M| = M0(1 + k|s − λ/2|) solved by shooting (mpmath odefun, break at the middle) and "
         "mpmath quad of G_2 = ∫ w²/|M| ds")
WHERE = "(M0, k, λ) = (1/2, 3/5, 6/5), (1, 1/10, 1) and, at full level, (2/5, 2, 3/2)"


def rhombus_blade(M0: str, k: str, lam: str) -> blade.Blade:
    """The inverted blade with a rhombus hole: M = −M0(1 + k|s − λ/2|) (g → −g, n°100 and n°107)."""
    M0_, k_, lam_ = (sp.Rational(t) for t in (M0, k, lam))
    half = lam_ / 2
    M = sp.Piecewise((-M0_ * (1 + k_ * (half - S)), S < half), (-M0_ * (1 + k_ * (S - half)), True))
    return blade.Blade(lam_, M)


@functools.lru_cache(maxsize=64)
def shot(M0: str, k: str, lam: str, dps: int) -> blade.BladeSolution:
    return blade.solve(rhombus_blade(M0, k, lam), dps)


def G2(solution: blade.BladeSolution):
    """G_2 = ∫_0^λ w²/|M| ds (n°110) by quadrature on the shot blade."""
    with mp.workdps(solution.wdps):
        return solution.integrate(lambda s: solution.w(s) ** 2 / abs(solution.M_at(s)))


QUANTITIES: dict[str, Callable] = {
    "v0": lambda sol: sol.v0, "vl": lambda sol: sol.vl, "w0": lambda sol: sol.w0, "wl": lambda sol: sol.wl,
    "G2": G2,
}


def environment(M0: str, k: str, lam: str) -> dict:
    """ω, k, λ and x_0, x_1 of (334), at 60 digits."""
    with mp.workdps(60):
        M0_, k_, lam_ = (mp.mpf(sp.Rational(t).p) / sp.Rational(t).q for t in (M0, k, lam))
        omega = 1 / mp.sqrt(M0_)
        x0 = 2 * omega / k_
        return {"omega": omega, "k": k_, "lambda": lam_, "M_0": M0_, "x_0": x0, "x_1": x0 * mp.sqrt(1 + k_ * lam_ / 2)}


def on_rhombus(name: str, with_ends: bool = False) -> checks.Values:
    """A Values check of a formula for ``name`` (v0, vl, w0, wl, G2) against the shot blade; with ``with_ends``
    the environment also holds the shot w_0, w_λ (for a form written with them)."""
    quantity = QUANTITIES[name]

    def points(level: str, dps: int):
        for case in CASES[level]:
            sol = shot(*case, dps)
            env = environment(*case)
            if with_ends:
                env.update({"w_0": sol.w0, "w_lambda": sol.wl})
            yield checks.Point(f"(M0, k, λ) = ({', '.join(case)})", env, quantity(sol))

    def confirm(dps: int):
        case = CASES["quick"][0]
        return {f"{name} at {case}": quantity(shot(*case, dps))}

    return checks.Values(truth=f"{name} of the {BLADE}; {WHERE}", points=points, confirm=confirm, tol=TOL,
                         kind="quadrature")


def uniform_limit(name: str, M0: str = "1/2", lam: str = "6/5", expected: float = 1.0,
                  lo: str = "1e-5", hi: str = "1e-3") -> checks.Order:
    """The hole vanishing: |truth(k) − uniform formula| over k → 0 must be O(k) (the truth is the rhombus blade
    shot at k; the formula, the Result's derived form, the inverted uniform blade's value)."""
    def truth(p, dps):
        text = sp.nsimplify(mp.nstr(p, 20), rational=True)
        return QUANTITIES[name](shot(M0, str(text), lam, dps))

    def at(expr, p):
        env = environment(M0, "1", lam)
        env["k"] = p
        return verify.value_at(expr, env)
    return checks.Order(param="k", values=checks.Geometric(lo, hi), truth=truth, at=at, expected=expected,
                        truth_desc=f"{name} of the {BLADE}, M0 = {M0}, λ = {lam}, k → 0")
