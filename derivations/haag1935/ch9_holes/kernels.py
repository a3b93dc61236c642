"""Haag 1935, chapter IX, n°109: kernels of the rhombus blade's v_0, w_0, w_λ (343), with supplied forms (issue #14).

The kernels are of two dimensionless arguments, u = ωλ and q = kλ (:func:`.kernel_forms.scaled`: each of (343) is
λ times a function of them); the Results they are emitted from are :mod:`.rhombus_table_kernels`.

**Why a supplied form.**  (343) is v_0 = k x_1 D_1/(2ω²D), w_0 = −k x_1 W_1/(4ω²x_0 D D'), w_λ =
(k x_1/4ω²)(D'_1/D' + D_1/D) (derived by SymPy from the Result, :func:`end_forms`), where D, D', D_1, D'_1 are
cross products Y_a(x_0)J_b(x_1) − J_a(x_0)Y_b(x_1) at x_0 = 2u/q and x_1 = x_0√(1 + q/2).  As q → 0 both
arguments grow like 2u/q and each cross product is a difference of two products of size 1/x_0 that agree to
log10(x_0) digits; x_0 rounded to a double alone shifts the phase by x_0·2⁻⁵³.  No rewrite of the derived form
repairs this, so the derivation supplies the form: the same (343), with each cross product computed by
:class:`pendsym.emit.kernels.supplied.BesselCross` from x_0 (a double-double, its low part the exact residual of
2u/q) and the gap h = x_1 − x_0 = u/(1 + √(1 + q/2)) (no cancellation), by Hankel's expansion (x_0 ≥ 25) or
the Taylor series of Bessel's equation in h, in steps (no Bessel function is called).

**Domain.**  q ∈ [1e-8, 1000] (M at the ends from M_0(1 + 5e-9) to 501 M_0: from no hole to a middle 1/501 as
stiff as the ends); u ∈ [0.05, π]: the inverted blade exists while D ≠ 0, whose first zero is u = π as q → 0
(chapter VIII's window (309)) and moves above π as q grows (the gap h, the phase the cross products turn through,
shrinks), so the box lies in the stable region at every q; near u = π at small q the values grow as 1/D and κ with
them.  Up to q = 2.5 (h = x_0/2) each cross product is Hankel's expansion or one Taylor step about x_0; above it
(session 13) the Taylor series is continued in steps of at most half the centre (the singular point x = 0 of
Bessel's equation bounds the radius by the centre: terms fall as 2^−m at least), carrying c and c' in double-double
from one centre to the next, the last step landing on x_1 through the remaining gap (never x_1 rounded): about
log(x_1/x_0)/log 1.5 steps, 8 at q = 1000 (x_1/x_0 = √501), 17 at q = 1e6.  The recessive solution (Y_1-like,
c ~ x_0/x) loses to the dominant one (J_1-like) a relative error that grows as (x/x_0)²; the terms' tolerance is
therefore 1e-20·(x_0/x_1)² (with 1e-20 alone the prototype measured 10 ulp at q = 2e4, 565 at 2e6).  Measured
(a scratch prototype in double-double against mpmath at 40 digits; then the emitted helper, C and Python alike, on
4 random (u, q) per band of q in [1e-8, 1e8], the four cross products each): at most 0.89 ulp at every q, 0.50 for
q ≥ 2.5.  The kernels are declared to q = 1000, not to where the route holds (1e8): the end is what the audit
could afford to show (Python's double-double stepping costs ~20 ms a cross product at q = 1000; the blade, stable
at every q for u ≤ π, has q → ∞ only for a full rhombus whose middle width vanishes).  The audit's figures are in
docs/kernel-accuracy.md.  Below u = 0.05 the forms are not measured.
"""
from __future__ import annotations

import functools
import math

import sympy as sp

from pendsym.emit.kernels.supplied import BesselCross, QuotientLow, RootQuotient, SuppliedKernelSpec
from pendsym.result import KernelArg

from ..symbols import lam, omega, u
from . import kernel_forms, rhombus_derivation as derivation

q = kernel_forms.q
U_ARG = KernelArg("u", 0.05, math.pi, log=False)
Q_ARG = KernelArg("q", 1e-8, 1e3, log=True)       # Hankel, or Taylor steps in the gap: no Bessel call (see Domain)


def end_forms() -> dict[str, sp.Expr]:
    """v_0, w_0, w_λ of (343) written with Haag's D, D', D_1, D'_1 (and the Wronskian W(x_1) = 1/x_1 where w_0 uses
    it).  Their equality with the derived form is :func:`checked_end_forms` (a test), and the kernel stage measures
    each supplied form against the derived one on its sample; neither runs when the Specs are built (it costs about
    50 s of evalf, which every command that lists the memoir would pay)."""
    D, Dp, D1, D1p = derivation.D_symbols()
    k, x0, x1 = derivation.k, derivation.x0, derivation.x1
    return {"v0": k * x1 * D1 / (2 * omega**2 * D), "w0": -k / (4 * omega**2 * x0 * D * Dp),
            "wl": k * x1 / (4 * omega**2) * (D1p / Dp + D1 / D)}


def checked_end_forms() -> dict[str, sp.Expr]:
    """:func:`end_forms`, each shown equal to the derived (343) at three points to 40 digits (an error otherwise)."""
    forms = end_forms()
    defs = dict(derivation.D_definitions())
    for name, form in forms.items():
        diff = kernel_forms.derived(name) - form.subs(defs)
        if not _vanishes(diff):
            raise ValueError(f"{name}: the D form is not the derived (343)")
    return forms


def _vanishes(expr: sp.Expr) -> bool:
    """expr = 0 at three points (ω, k, λ) to 40 digits, the Bessel functions by mpmath (the identity holds for every
    x_0, x_1, but SymPy does not simplify through the Wronskian)."""
    ends = derivation.x_ends()
    for om, kk, ll in ((sp.Rational(7, 5), sp.Rational(1, 3), 1), (1, sp.Rational(1, 10**6), 2), (sp.Rational(1, 2), 50, 1)):
        env = {omega: om, derivation.k: kk, lam: ll}
        value = sp.N(expr.subs(ends).subs(env), 50)
        if abs(value) > 1e-40:
            return False
    return True


@functools.lru_cache(maxsize=None)
def supplied(name: str) -> sp.Expr:
    """The form of the kernel of name/λ (v0, w0, wl) in u, q: :func:`end_forms` with each cross product N_ab =
    (π√(x_0x_1)/2)·(today's cross product) = √(x_0x_1)·(Haag's) from :class:`BesselCross`, then ω = u, k = q,
    λ = 1 (the form is λ times a function of u, q).  Haag's D = N_10/√(x_0x_1), D' = N_00/…, D_1 = N_11/…,
    D'_1 = N_01/…; the common √(x_0x_1) cancels in v_0 and w_λ, and k x_1/(x_0 x_0 x_1 ω²)… in w_0 leaves
    −√(2q + 4)/(4u N_10 N_00)."""
    x0 = 2 * u / q
    low = QuotientLow(2 * u, q, x0)
    gap = kernel_forms.end_gap()
    if sp.simplify(gap - u / (1 + sp.sqrt(q / 2 + 1))) != 0:
        raise ValueError(f"the gap {gap} is not u/(1 + √(1 + q/2))")
    gap, gap_low = RootQuotient(u, q / 2, 0), RootQuotient(u, q / 2, 1)    # u/(1 + √(1 + q/2)), double-double
    cross = {ab: BesselCross(ab[0], ab[1], x0, low, gap, gap_low) for ab in ((1, 0), (0, 0), (1, 1), (0, 1))}
    D, Dp, D1, D1p = derivation.D_symbols()
    root = sp.sqrt(derivation.x0 * derivation.x1)
    as_cross = {D: cross[(1, 0)] / root, Dp: cross[(0, 0)] / root, D1: cross[(1, 1)] / root, D1p: cross[(0, 1)] / root}
    x0_s, x1_s = kernel_forms.arguments()
    if sp.simplify(x0_s - 2 * u / q) != 0 or sp.simplify(x1_s - u * sp.sqrt(2 * q + 4) / q) != 0:
        raise ValueError(f"(334) in u, q is not x_0 = 2u/q, x_1 = (u/q)√(2q + 4): {x0_s}, {x1_s}")
    form = end_forms()[name].subs(as_cross)
    form = form.subs({derivation.x0: 2 * u / q, derivation.x1: u * sp.sqrt(2 * q + 4) / q})
    return form.subs({omega: u, derivation.k: q, lam: 1})


NOTES = ("The cross products Y_a(x_0)J_b(x_1) − J_a(x_0)Y_b(x_1) (Haag's D, D', D_1, D'_1) by the helper "
         "bessel_cross, from x_0 = 2u/q as a double-double and the gap x_1 − x_0 = u/(1 + √(1 + q/2)): Hankel's "
         "expansion for x_0 ≥ 25, otherwise the Taylor series of Bessel's equation in the gap, in double-double, from "
         "c(x_0), c'(x_0) given by the Wronskian, in steps of at most half the centre (one step for x_1 − x_0 ≤ x_0/2, "
         "8 at q = 1000): no Bessel function is called.",)


def kernel(name: str) -> SuppliedKernelSpec:
    doc = {"v0": "v_0/λ of the inverted rhombus blade (343), v_0 = k x_1 D_1/(2ω²D)",
           "w0": "w_0/λ of the inverted rhombus blade (343), w_0 = −k/(4ω²x_0 D D')",
           "wl": "w_λ/λ of the inverted rhombus blade (343), w_λ = (k x_1/4ω²)(D_1/D + D'_1/D')"}[name]
    return SuppliedKernelSpec(args=(U_ARG, Q_ARG), form=supplied(name), rule="supplied: cross products by bessel_cross",
                              notes=NOTES,
                              doc=doc + ", in u = ωλ and q = kλ (M = M_0(1 + k|s|), M at the ends M_0(1 + q/2)).")
