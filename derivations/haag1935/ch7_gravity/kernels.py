"""Haag 1935, chapter VII: the kernels asked of the emitters, with their declared domains (issue #13).

* G of (263), the sensitivity coefficient of the gravity pendulum on a uniform blade with direct
  suspension, G = (U_1² + U_2/u)/(2ε) = (1/sh²u + coth u/u)/(2ε): the principal part in ε of
  G = −d log n²/d log g (62) at a = a1 + ελ (256).  It is physically meaningful for ε ≪ 1 (its relative
  error is O(ε): 0.93ε at u = 2 in the Result's order check), hence ε ≤ 0.1 declared.  As u → 0 it
  grows as 1/(εu²) (264) (no finite limit: u ≥ 1e-6); as u → ∞ it falls as 1/(2εu).
* C of (285), the isochronism coefficient of the same pendulum (ΔT/T = −(θ0²/16)GC, (283)),
  C = (3/8)(sh 4u − 4u)/(sh²u(sh 2u + 2u)), a function of u alone, meaningful for every u > 0:
  C → 1 as u → 0 (the short-blade limit, where C − 1 = O(u²)) and C → 3/2 as u → ∞ (the thread).
  The derived form is rational in e^u (e^{8u} overflows above u ≈ 88.7) and cancels as u → 0
  (e^{8u} − 8ue^{4u} − 1 = O(u³)).

Both Results live in this package's :mod:`.table` (n°85 and n°93): the isochronism package
(:mod:`..ch7_isochronism`) holds only the general-blade forms of (281)–(284), which are not closed.

The inverted blade's (chapter VIII, n°103) G of (314) and C of (317) are declared here too, on the stability
window n = 0 of (309), 0 < u < π (β1 < 0 (304)): u ∈ [1e-6, π] (π the double below π).  Both grow as
1/sin²u towards the window's end (a pole at u = π, where κ ~ 2π/(π − u) lets the error grow with it).
The window n = 1 (2x1 < u < 3π) has a1 < 0 throughout (tan u < 0 there, (310)): no body with a > 0 is
critical there.  One kernel is emitted per Result: C on that window is chapter VIII's Result eq317.C_window1
(:mod:`..ch8_inverted.table_kernels`, its kernel declared in :mod:`..ch8_inverted.kernels`).
"""
from __future__ import annotations

import math

from pendsym.result import KernelArg, KernelSpec

from ..ch3_uniform.kernels import NAIVE, U_ARG

# a − a1 = ελ (256): the distance to the critical point in blade lengths; (262)–(263) are its principal part
EPS_ARG = KernelArg("varepsilon", 1e-9, 0.1, log=True)

G_KERNEL = KernelSpec(args=(U_ARG, EPS_ARG), naive_defs=NAIVE,
                      doc="G = (U_1² + U_2/u)/(2ε) (263), the sensitivity coefficient −d log n²/d log g of the "
                          "gravity pendulum on a uniform blade, direct suspension, principal part in ε (ε ≪ 1); "
                          "G ~ 1/(εu²) as u → 0 (264), G ~ 1/(2εu) as u → ∞.")
C_KERNEL = KernelSpec(args=(U_ARG,), naive_defs=NAIVE,
                      doc="C = (3/8)(sh 4u − 4u)/(sh²u(sh 2u + 2u)) (285), the isochronism coefficient of the "
                          "gravity pendulum on a uniform blade (ΔT/T = −(θ0²/16)GC, (283)); C → 1 as u → 0, "
                          "C → 3/2 as u → ∞ (the thread).")

# (309), n = 0: the window 0 < u < π of the inverted uniform blade (math.pi is the double below π)
U_WINDOW = KernelArg("u", 1e-6, math.pi, log=True)
G_INVERTED_KERNEL = KernelSpec(args=(U_WINDOW, EPS_ARG),
                               doc="G = (1/sin²u + cot u/u)/(2ε) (314), the sensitivity coefficient of the gravity "
                                   "pendulum on an inverted uniform blade at a = a1 − ελ (312), principal part in ε; "
                                   "G ~ 1/(εu²) as u → 0, G ~ 1/(2ε sin²u) as u → π (the window's end).")
C_INVERTED_KERNEL = KernelSpec(args=(U_WINDOW,),
                               doc="C = (3/8)(4u − sin 4u)/(sin²u(2u + sin 2u)) (317), the isochronism coefficient "
                                   "of the gravity pendulum on an inverted uniform blade; C → 1 as u → 0, "
                                   "C ~ 3/(4 sin²u) as u → π (the window's end).")
