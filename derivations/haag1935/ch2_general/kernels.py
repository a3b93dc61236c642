"""Haag 1935, chapter II: the kernels of the designer's coefficients of the uniform short blade (issue #12).

Each is a function of u = λ/√M alone (:mod:`.designer`), declared on u ∈ [1e-6, 700]; the period's change is
the coefficient times a power of λ/a (and of θ0, i, j or m'/m), which the caller multiplies in.  They hold for
the short blade (λ ≪ a, K → 1) of the direct pendulum; the inverted pendulum (a < 0) is outside them: it needs
a + w_λ > 0 (40) with a < 0, i.e. |a| < λ/(u th u) < λ, where λ/a is not small.  The damping per period of
n°42 for the uniform blade is Γ_{p+q+1}(u, k) of (166) times constants (g_{p+q} = a_pq G_{p+q+1} (140), G_n of
(163)), emitted in chapter III for n = 2…5 at any K; c_D is its short blade (K = 1) at p + q = 1, Le Rolland's
law (Δθ0 ∝ θ0: a constant logarithmic decrement).

The derived forms cancel as u → 0 (terms of order 1/u⁴ … 1/u² in th(u/2) and 1/sh u leave an O(1) limit); the
emitter's series pieces handle it.  c_Q takes F of (170) at K = 1: the over-contract points of F's kernel
(issue #11) lie near the stationary points of its quartic in K, which K = 1 does not reach.

The gravity pendulum near its critical distance (chapters VII–VIII) gives the blade's weight as (m'/(mε))c, c of
u alone, for the direct blade (293) and the inverted one (320) (first window 0 < u < π, declared to u = 3).

Audit (session 9, ≥ 20,000 points each, worst ulp/max(1, κ), Python / C): c_Q 2.74 / 2.51 (u = 3.293), c_ii 1.74
(u = 30.42), c_ij 1.20 / 1.17 (u ≈ 2.7), c_jj 1.42 / 1.62 (u = 2.995), c_I 2.35 / 2.48 (u = 671 / 65.6), c_J 3.38
(u = 3.102), gravity c 1.0 (u = 4.01), inverted c 2.17 (u = 1.526); all but c_Q accept u down to 0.
c_D (session 12, Python, before the audit): 1.55 on the emitter's 210-point sample (u = 1.5), 0.80 on the test
points against the blade's G_2/λ; like c_Q it grows as 1/u² and keeps u ≥ 1e-6; it reaches +inf (far form).
"""
from __future__ import annotations

from pendsym.result import KernelArg, KernelSpec

from ..ch3_uniform.kernels import NAIVE, U_ARG


def kernel(doc: str) -> KernelSpec:
    return KernelSpec(args=(U_ARG,), naive_defs=NAIVE, doc=doc)


ISOCHRONISM_KERNEL = kernel("c_Q = (a/λ)(Q'/Q − 1), the isochronism coefficient of the short uniform blade: "
                            "ΔT/T = (θ0²/16)(1 + (λ/a)c_Q) (244); c_Q → −7/(4u) as u → ∞ (245).")
CLAMPING_KERNELS = {m: kernel(f"c_{m}, the coefficient of {m[0]}{m[1] if m[1] != m[0] else '²'} in the clamping "
                              "error of the short uniform blade: ΔT/T = (λ/a)(c_ii i² + c_ij ij + c_jj j²) (249).")
                    for m in ("ii", "ij", "jj")}
INERTIA_KERNEL = kernel("c_I, the blade's inertia for the short uniform blade: ΔT/T = (m'/m)(λ/a)²c_I (251); "
                        "c_I → 1/6 as u → ∞ (252).")
WEIGHT_KERNEL = kernel("c_J, the blade's weight for the short uniform blade: ΔT/T = (m'/m)(λ/a)c_J (253); "
                       "c_J → −1/4 as u → ∞ (254).")
DAMPING_KERNEL = kernel("c_D = Γ_2(u, 0), the damping per period of the short uniform blade for a friction of degree "
                        "p + q = 1 (Le Rolland's law): Δθ0 = −(π/2)i_{p,q+1}(a_pq + b_pq + a'_pq + b'_pq)n^qθ0(λ/a)c_D "
                        "(149); c_D ~ 1/u² as u → 0, → 1/(2u) as u → ∞.")

# the gravity pendulum near its critical distance (chapters VII–VIII): ΔT/T = (m'/(mε))c, a = a1 ± ελ
GRAVITY_WEIGHT_KERNEL = kernel("c = −(1/u² − U_1²)/8, the blade's weight for the gravity pendulum on a uniform blade, "
                               "direct suspension: ΔT/T = (m'/(mε))c (293), a = a1 + ελ; c → −1/24 as u → 0, "
                               "c ~ −1/(8u²) as u → ∞.")
INVERTED_U_ARG = KernelArg("u", 1e-6, 3.0, log=True)
INVERTED_WEIGHT_KERNEL = KernelSpec(args=(INVERTED_U_ARG,), naive_defs=NAIVE,
                                    doc="c = −(1/u² − 1/sin²u)/8, the blade's weight for the inverted gravity "
                                        "pendulum (a < 0 side: g → −g, n°103): ΔT/T = (m'/(mε))c (320), a1 − a = ελ; "
                                        "the first window of stability, 0 < u < π (309), declared up to u = 3; "
                                        "c → −1/24 as u → 0 and → +∞ as u → π.")
