"""Haag 1935, chapter III: the kernels asked of the emitters, with their declared domains.

The printed forms cancel as u → 0 (1/u² − U1², u − 2 th(u/2) …): the naive kernels
lose up to 1e24 ulp there.  pendsym.emit.kernels generates piecewise stable forms
(series in u, a middle Taylor piece, e^{−u}/expm1 forms) and measures them;
pendsym.derive withholds any kernel over 4 ulp × max(1, κ) (listed in the report
with its figures).  K and n² are emitted from (36) with the stable root z of (30):
through (35) and z' they lose everything as u → 0 (a + z' − v_λ and β1 are both O(u²)).
"""
from __future__ import annotations

import sympy as sp

from pendsym.result import KernelArg, KernelSpec

from ..symbols import M, U, U1, U2, lam, omega, u

KERNELS_READY = True     # the uniform blade's kernels are emitted

U_ARG = KernelArg("u", 1e-6, 700.0, log=True)
LAMBDA_ARG = KernelArg("lambda", 1e-3, 10.0, log=True, unit="m")
K_ARG = KernelArg("K", -3.0, 3.0, log=False)
k_ARG = KernelArg("k", -12.0, 0.25, log=False)
# K and n² of the suspension: a the distance from the blade's end to the centre of mass, R the
# radius of gyration, λ and u of the blade (a > 0: the direct pendulum, where K > 0 (n°9)).
A_ARG = KernelArg("a", 1e-2, 5.0, log=True, unit="m")
R_ARG = KernelArg("R", 1e-3, 2.0, log=True, unit="m")
G_ARG = KernelArg("g", 9.7, 9.9, log=False, unit="m/s^2")
BLADE_MASS_ARG = KernelArg("m'", 1e-4, 10.0, unit="kg")

CANCEL = ("Printed forms cancel badly as u → 0: 1 − 2U/u, U_1 − 1/u, 1/u² − U_1², U_2/u − U_1² "
          "(each O(u²) or O(1) from O(1/u²) terms); the derived forms are rational in th(u/2) and u and "
          "cancel likewise; series in u are needed below u ≈ 1e-2.")

# the obvious reading of the printed forms in double precision: (156), (160) as written
NAIVE = ((omega, u / lam), (M, lam**2 / u**2), (U, sp.tanh(u / 2)), (U1, 1 / sp.sinh(u)), (U2, 1 / sp.tanh(u)))


def kernel(doc: str, *args: KernelArg, unit: str = "1") -> KernelSpec:
    """A kernel of the derived form over the declared domain of its arguments."""
    return KernelSpec(args=tuple(args), doc=doc + " " + CANCEL, unit=unit, naive_defs=NAIVE)


V0_KERNEL = kernel("v_0 = λ th(u/2)/u.", LAMBDA_ARG, U_ARG, unit="m")
W0_KERNEL = kernel("w_0 = λ/(u sh u).", LAMBDA_ARG, U_ARG, unit="m")
W_LAMBDA_KERNEL = kernel("w_λ = λ/(u th u).", LAMBDA_ARG, U_ARG, unit="m")
BETA1_KERNEL = kernel("β1 = λ(1 − 2U/u) ~ λu²/12 as u → 0.", LAMBDA_ARG, U_ARG, unit="m")
GAMMA_KERNELS = {m: kernel(f"Γ_{m}(u, k), polynomial in k = K(1 − K).", U_ARG, k_ARG) for m in (2, 3, 4, 5)}
F1_KERNEL = kernel("F_1/λ = U/u + K(1 − 2U/u).", U_ARG, K_ARG)
F2_KERNEL = kernel("F_2/λ.", U_ARG, K_ARG)
F_KERNEL = kernel("F/λ of (110), (170).", U_ARG, K_ARG)
K_KERNEL = kernel("K of (36) for given a, R, λ, u: (a + w_λ)/(a + z − v_λ), z the root of (30) "
                  "written without cancellation.", A_ARG, R_ARG, LAMBDA_ARG, U_ARG)
N2_KERNEL = kernel("n² = Kgz/R² for given a, R, λ, u, g, with K of (36).", A_ARG, R_ARG, LAMBDA_ARG, U_ARG,
                   G_ARG, unit="1/s^2")
INERTIA_KERNEL = kernel("I_λ of (182).", LAMBDA_ARG, U_ARG, K_ARG, BLADE_MASS_ARG, unit="kg m^2")
J_KERNEL = kernel("J of (183).", LAMBDA_ARG, U_ARG, K_ARG, unit="m")
