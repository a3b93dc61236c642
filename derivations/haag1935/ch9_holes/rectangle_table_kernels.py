"""Haag 1935, chapter IX, n°105–106: G_2/λ of the concentric rectangular hole in u = ωλ, u_p = ω'p, ρ = p/λ, the
Result the kernel of G_2 is emitted from (:mod:`.rectangle_kernels`: a supplied form, derived and tested, its
operations compensated since session 12; without that it measured 4.4 scaled ulp in the audit).

The Result is the derived (333) (:mod:`.rectangle_derivation`) with s_0 = (λ − p)/2, ω = u/λ, ω' = u_p/(ρλ),
p = ρλ, divided by λ (:func:`.rectangle_kernels.concentric_scaled`: an error if λ remains); it is checked against
the concentric blade shot with the piecewise M and the quadrature of ∫w²/|M| ds (:mod:`.rectangle_truth`, no
trigonometric closed form), at u = ωλ, u_p = ω'p, ρ = p/λ, one case with ω' = ω (the hole vanished).
"""
from __future__ import annotations

import sympy as sp

from pendsym import checks
from pendsym.result import Spec

from ..common import TOL, rid, src
from . import rectangle_kernels as kernels, rectangle_truth as truth

# (ω, ω', λ, s_0, p), concentric (λ = 2s_0 + p): (u, u_p, ρ) = (1, 0.6, 0.4), (1.2, 1.2, 0.3); at full level
# (1.5, 0.15, 0.1) with ω' = ω and a narrow soft hole (1, 0.75, 0.05)
CASES = {"quick": (("1", "3/2", "1", "3/10", "2/5"), ("3/5", "2", "2", "7/10", "3/5")),
         "full": (("1", "3/2", "1", "3/10", "2/5"), ("3/5", "2", "2", "7/10", "3/5"), ("3/2", "3/2", "1", "9/20", "1/10"),
                  ("1", "15", "1", "19/40", "1/20"))}


def scaled_point(case: tuple) -> dict:
    """(u, u_p, ρ) = (ωλ, ω'p, p/λ) of a concentric case; an error if the hole is not concentric."""
    env = truth.environment(case)
    if env["lambda"] != 2 * env["s_0"] + env["p"]:
        raise ValueError(f"{case} is not a concentric hole")
    return {kernels.u.name: env["omega"] * env["lambda"], kernels.u_p.name: env["omega'"] * env["p"],
            kernels.rho.name: env["p"] / env["lambda"]}


def on_concentric_blade() -> checks.Values:
    """G_2/λ at (u, u_p, ρ) against ∫w²/|M| ds of the shot concentric blade over λ."""
    def points(level: str, dps: int):
        for case in CASES[level]:
            yield checks.Point(f"(ω, ω', λ, s_0, p) = ({', '.join(case)})", scaled_point(case),
                               truth.QUANTITIES["G2"](truth.shot(case, dps)) / sp.Rational(case[2]))

    def confirm(dps: int):
        case = CASES["quick"][1]
        return {f"G2 at {case}": truth.QUANTITIES["G2"](truth.shot(case, dps))}

    return checks.Values(truth=f"G_2/λ of the {truth.BLADE}; concentric holes (ω, ω', λ, s_0, p) = "
                               + "; ".join(", ".join(c) for c in CASES["full"]) + " (the last two at full level)",
                         points=points, confirm=confirm, tol=TOL, kind="quadrature")


def specs() -> tuple[Spec, ...]:
    return (
        Spec(rid(333, "G2_concentric_u"), "G_2/λ of the concentric rectangular hole in u = ωλ, u_p = ω'p, ρ = p/λ",
             src("n°105–106 (333), concentric hole (footnote of n°106)", None), r"G_2/\lambda",
             lambda deps: kernels.concentric_scaled(deps[rid(333, "G2")].derived), deps=(rid(333, "G2"),),
             check=on_concentric_blade(), kernel=kernels.kernel(),
             note="(333) over λ with s_0 = (λ − p)/2, ω = u/λ, ω' = u_p/(ρλ), p = ρλ: G_2/λ of a concentric hole is "
                  "a function of u, u_p, ρ, the three arguments of its kernel; n°106's footnote (stable for "
                  "ωλ < π/2, ω'p < π/2) is then a box."),
    )
