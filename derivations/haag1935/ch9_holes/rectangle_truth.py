"""Haag 1935, chapter IX, n°104–106: the independent truth of the rectangular hole.

The inverted blade (n°100, M < 0 in (9) of :mod:`pendsym.blade`) of length λ with |M| = 1/ω² off the hole and
1/ω'² on s_0 < s < s_0 + p is solved by shooting (:func:`pendsym.blade.solve`: mpmath ``odefun`` piece by piece,
v and v' continuous at the jumps of M) at ``dps`` digits; v_0, v_λ, w_0, w_λ are its end values and
G_2 = ∫ w²/|M| ds its mpmath quadrature.  Nothing here reads a trigonometric closed form.
"""
from __future__ import annotations

import functools

import mpmath as mp
import sympy as sp

from pendsym import blade, checks

from ..common import TOL
from .rhombus_truth import G2

S = blade.S
# (ω, ω', λ, s_0, p): a concentric hole, an asymmetric one and, at full level, a low one
CASES = {"quick": (("1", "3/2", "1", "3/10", "2/5"), ("4/5", "1", "3/2", "1/5", "1/2")),
         "full": (("1", "3/2", "1", "3/10", "2/5"), ("4/5", "1", "3/2", "1/5", "1/2"), ("1/2", "5/4", "2", "13/20", "7/10"))}
NAMES = ("omega", "omega'", "lambda", "s_0", "p")
BLADE = ("inverted blade |M| = 1/ω² with |M| = 1/ω'² on s_0 < s < s_0 + p, solved by shooting (mpmath odefun, "
         "piece by piece) and mpmath quad of G_2 = ∫ w²/|M| ds")
WHERE = "(ω, ω', λ, s_0, p) = (1, 3/2, 1, 3/10, 2/5), (4/5, 1, 3/2, 1/5, 1/2) and, at full level, (1/2, 5/4, 2, 13/20, 7/10)"


def rectangle_blade(omega: str, omega_p: str, lam: str, s0: str, p: str) -> blade.Blade:
    """The inverted blade with a rectangular hole (n°104), M negative (g → −g)."""
    om, omp, L, a, h = (sp.Rational(t) for t in (omega, omega_p, lam, s0, p))
    M = sp.Piecewise((-1 / om**2, S < a), (-1 / omp**2, S < a + h), (-1 / om**2, True))
    return blade.Blade(L, M)


@functools.lru_cache(maxsize=64)
def shot(case: tuple, dps: int) -> blade.BladeSolution:
    return blade.solve(rectangle_blade(*case), dps)


QUANTITIES = {"v0": lambda sol: sol.v0, "vl": lambda sol: sol.vl, "w0": lambda sol: sol.w0,
              "wl": lambda sol: sol.wl, "G2": G2}


def environment(case: tuple) -> dict:
    return {name: sp.Rational(value) for name, value in zip(NAMES, case)}


def on_rectangle(name: str, concentric: bool = False) -> checks.Values:
    """A Values check of a formula for ``name`` against the shot blade (only the concentric cases, λ − s_1 = s_0,
    when ``concentric``)."""
    quantity = QUANTITIES[name]

    def cases(level):
        chosen = CASES[level]
        if concentric:
            chosen = tuple(c for c in chosen if sp.Rational(c[2]) == 2 * sp.Rational(c[3]) + sp.Rational(c[4]))
        return chosen

    def points(level: str, dps: int):
        for case in cases(level):
            yield checks.Point(f"(ω, ω', λ, s_0, p) = ({', '.join(case)})", environment(case), quantity(shot(case, dps)))

    def confirm(dps: int):
        case = cases("quick")[0]
        return {f"{name} at {case}": quantity(shot(case, dps))}

    return checks.Values(truth=f"{name} of the {BLADE}; {WHERE}", points=points, confirm=confirm, tol=TOL,
                         kind="quadrature")


def uniform_limit(name: str, base: tuple = ("1", "1", "1", "3/10", "2/5")) -> checks.Order:
    """The hole vanishing, ω' → ω: |truth(ω' = ω + δ) − uniform formula| must be O(δ)."""
    def truth(delta, dps):
        text = str(sp.nsimplify(mp.nstr(delta, 20), rational=True))
        case = (base[0], str(sp.Rational(base[0]) + sp.Rational(text)), *base[2:])
        return QUANTITIES[name](shot(case, dps))

    def at(expr, delta):
        from pendsym import verify
        return verify.value_at(expr, environment(base))
    return checks.Order(param="δ = ω' − ω", values=checks.Geometric("1e-5", "1e-3"), truth=truth, at=at,
                        expected=1.0, truth_desc=f"{name} of the {BLADE}, ω = λ = 1, s_0 = 3/10, p = 2/5, ω' → ω")


def stability_points(level: str, dps: int):
    """n°106, footnote: concentric holes with ωλ < π/2 and ω'p < π/2 (up to 0.9999 of the bounds), λ = 1."""
    fractions = ("1/20", "3/10", "3/5", "9/10", "99/100") if level == "full" else ("1/20", "3/5", "99/100")
    for u in ("3/10", "6/5", "15707/10000"):
        for up in ("1/2", "3/2", "15707/10000"):
            for frac in fractions:
                pp = sp.Rational(frac)
                om, omp = sp.Rational(u), sp.Rational(up) / pp
                if omp < om:
                    continue
                env = {"omega": om, "omega'": omp, "lambda": 1, "s_0": (1 - pp) / 2, "p": pp}
                yield f"ωλ = {u}, ω'p = {up}, p/λ = {frac}", env
