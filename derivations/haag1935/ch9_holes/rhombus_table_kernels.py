"""Haag 1935, chapter IX, n°109–110: v_0/λ, w_0/λ, w_λ/λ (343) and G_2/λ (346) of the rhombus blade in u = ωλ, q = kλ,
with their kernels.

Each Result is the derived (343) with x_0, x_1 of (334), ω = u/λ, k = q/λ, divided by λ (:func:`.kernel_forms.scaled_from`:
an error if λ remains); checked against the inverted blade shot at (M0, k, λ), no Bessel function
(:mod:`.rhombus_truth`), at u = λ/√M0, q = kλ.  The kernels' supplied forms: :mod:`.kernels` for (343),
:mod:`.rhombus_g2_kernel` for (346) (a positive quadrature of cross products, its sums compensated).
"""
from __future__ import annotations

import mpmath as mp

from pendsym import checks
from pendsym.result import Spec

from ..common import TOL, rid, src
from ..symbols import u
from . import kernel_forms, kernels, rhombus_g2_kernel, rhombus_truth as truth

NAMES = {"v0": ("v_0", "v0"), "w0": ("w_0", "w0"), "wl": (r"w_\lambda", "wl")}
TITLES = {"v0": "v_0", "w0": "w_0", "wl": "w_λ"}        # (plain text: a title is not TeX)


def on_shot_blade(name: str) -> checks.Values:
    """name/λ at (u, q) = (λ/√M0, kλ) against the shot blade's end value over λ."""
    quantity = truth.QUANTITIES[name]

    def points(level: str, dps: int):
        for case in truth.CASES[level]:
            sol = truth.shot(*case, dps)
            env = truth.environment(*case)
            with mp.workdps(dps + 10):
                at = {u.name: env["lambda"] * env["omega"], kernel_forms.q.name: env["k"] * env["lambda"]}
                yield checks.Point(f"(M0, k, λ) = ({', '.join(case)})", at, quantity(sol) / env["lambda"])

    def confirm(dps: int):
        case = truth.CASES["quick"][0]
        return {f"{name} at {case}": quantity(truth.shot(*case, dps))}

    return checks.Values(truth=f"{name}/λ of the {truth.BLADE}; {truth.WHERE}", points=points, confirm=confirm,
                         tol=TOL, kind="quadrature")


def specs() -> tuple[Spec, ...]:
    return ends() + (
        Spec(rid(346, "G2_u_q"), "G_2/λ of the rhombus blade in u = ωλ, q = kλ", src("n°110 (346) in u = ωλ, q = kλ", None),
             r"G_2/\lambda", lambda deps: kernel_forms.scaled_from(deps[rid(346, "G2")].derived, "G2"),
             deps=(rid(346, "G2"),), check=on_shot_blade("G2"), kernel=rhombus_g2_kernel.kernel(),
             note="(346) over λ with x_0 = 2u/q, x_1 = (u/q)√(2q + 4) ((334), λ = 1): G_2 is λ times a function of u "
                  "and q. Its kernel is the stable form of rhombus_g2_kernel: a sum of positive terms derived from "
                  "(346), which subtracts terms of order 1/k, every operation after the Bessel cross products "
                  "compensated (module compensated)."),)


def ends() -> tuple[Spec, ...]:
    return tuple(
        Spec(rid(343, f"{name}_u_q"), f"{TITLES[name]}/λ of the rhombus blade in u = ωλ, q = kλ",
             src("n°109 (343) in u = ωλ, q = kλ", None), NAMES[name][0] + r"/\lambda",
             lambda deps, name=name: kernel_forms.scaled_from(deps[rid(343, name)].derived, name),
             deps=(rid(343, name),), check=on_shot_blade(name), kernel=kernels.kernel(name),
             note="(343) over λ with x_0 = 2u/q, x_1 = (u/q)√(2q + 4) ((334), λ = 1): each end value is λ times a "
                  "function of u and q, the two arguments of its kernel.")
        for name in ("v0", "w0", "wl"))
