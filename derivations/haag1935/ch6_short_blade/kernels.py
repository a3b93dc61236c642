"""Haag 1935, chapter VI: the kernel asked of the emitters, the length correction Δl of the short blade.

Δl = λ(1 − U_2/u) (220) for given λ and u: the lengthening of the synchronous pendulum due to a
uniform blade when λ²/a² and R²/a² are neglected.  It is −λ/u² + 2λ/3 + O(u²) as u → 0 (the
1/u² of U_2/u dominates: no cancellation), vanishes at u = 1.19968 (u th u = 1, where only its
condition number is large) and tends to λ − λ/u as u → ∞.  Measured (kernel engine of this
branch, 225 points): 3.45 ulp, 1.32 × max(1, κ); the naive printed form 17.8 ulp.
"""
from __future__ import annotations

from pendsym.result import KernelSpec

from ..ch3_uniform.kernels import LAMBDA_ARG, NAIVE, U_ARG

DL_KERNEL = KernelSpec(args=(LAMBDA_ARG, U_ARG), unit="m", naive_defs=NAIVE,
                       doc="Δl = λ(1 − U_2/u) (220), the length correction of the short uniform blade (λ²/a², "
                           "R²/a² neglected); zero at u = 1.19968.")
