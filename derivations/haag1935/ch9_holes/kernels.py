"""Haag 1935, chapter IX: the kernels asked of the emitters, with their declared domains (issue #14).

* G_2/λ of the blade with a **concentric rectangular hole** (n°105, (333) with s_0 = (λ − p)/2, the hole of n°106's
  footnote), a function of three dimensionless arguments: u = ωλ (the blade, as in chapter III), u_p = ω'p (the
  hole's own phase, ω' = 1/√M' across it) and ρ = p/λ (the hole's height).  Three instead of the five lengths and
  frequencies of (333) (G_2 is λ times a function of these), and a box domain: an off-centre hole would need
  s_0 + p ≤ λ, which a box of (s_0/λ, p/λ) cannot state.  Declared domain: u, u_p ≤ 1.5 < π/2, the footnote's
  sufficient condition of stability (β_1 < 0); u, u_p ≥ 1e-2 and 0.05 ≤ ρ ≤ 0.95 (a hole of 5 % to 95 % of the
  blade; as ρ → 0 or 1 the hole or the blade off it vanishes and the form cancels).

The rhombus hole's v_0, w_0, w_λ and G_2 are not emitted yet: see :mod:`.kernel_forms` and the
"Bessel functions" section of docs/kernel-accuracy.md (the engine prints no Bessel function and no
double-double argument, and (346) cancels terms of order 1/k).
"""
from __future__ import annotations

import mpmath as mp
import sympy as sp

from pendsym import checks
from pendsym.result import KernelArg, KernelSpec, Spec

from ..common import TOL, rid, src
from ..symbols import lam, omega
from . import rectangle_derivation as rd, rectangle_truth as truth
from .rhombus_truth import G2 as G2_of

u = sp.Symbol("u", positive=True)              # u = ωλ (156)
u_p = sp.Symbol("u_p", positive=True)          # u_p = ω'p, the hole's phase
rho = sp.Symbol("rho", positive=True)          # ρ = p/λ

RECTANGLE_G2_KERNEL = KernelSpec(
    args=(KernelArg("u", 1e-2, 1.5), KernelArg("u_p", 1e-2, 1.5), KernelArg("rho", 0.05, 0.95, log=False)),
    doc="G_2/λ of the inverted blade with a concentric rectangular hole (333), u = ωλ, u_p = ω'p, ρ = p/λ; "
        "u, u_p < π/2 is the sufficient stability condition of n°106's footnote.")


def concentric_G2() -> sp.Expr:
    """(333) with s_0 = (λ − p)/2, divided by λ, in u = ωλ, u_p = ω'p, ρ = p/λ (an error if λ remains)."""
    g2 = rd.G2().subs(rd.s0, (lam - rd.p) / 2)
    g2 = g2.subs({omega: u / lam, rd.omega_p: u_p / (rho * lam)}).subs(rd.p, rho * lam) / lam
    at = {u: sp.Rational(7, 5), u_p: sp.Rational(1, 2), rho: sp.Rational(3, 10)}
    values = [sp.N(g2.subs(at).subs(lam, length), 30) for length in (sp.Rational(1, 3), 7)]
    if abs(values[0] - values[1]) > 1e-25 * abs(values[1]):
        raise ValueError(f"G_2/λ depends on λ: {values}")
    # each trigonometric argument in one product (sin(ρu + u(1/2 − ρ/2) − u) is −sin(u(1 − ρ)/2))
    return g2.subs(lam, 1).replace(lambda e: isinstance(e, (sp.sin, sp.cos)), lambda e: e.func(sp.factor(e.args[0])))


def _points(level: str, dps: int):
    """The concentric cases of :mod:`.rectangle_truth` (and, at full level, one more), G_2/λ of the shot blade."""
    cases = [c for c in truth.CASES[level] if sp.Rational(c[2]) == 2 * sp.Rational(c[3]) + sp.Rational(c[4])]
    cases.append(("6/5", "3", "1", "9/20", "1/10"))
    for case in cases:
        om, omp, length, _, height = (sp.Rational(t) for t in case)
        sol = truth.shot(tuple(case), dps)
        with mp.workdps(dps):
            value = G2_of(sol) / mp.mpf(length.p) * length.q
        env = {"u": om * length, "u_p": omp * height, "rho": height / length}
        yield checks.Point(f"(ω, ω', λ, s_0, p) = ({', '.join(case)})", env, value)


def specs() -> tuple[Spec, ...]:
    return (
        Spec(rid(333, "G2_concentric_scaled"), "G_2/λ of a concentric rectangular hole in u = ωλ, u_p = ω'p, ρ = p/λ",
             src("n°105–106", "333"), r"G_2/\lambda", lambda deps: concentric_G2(), deps=(rid(333, "G2"),),
             check=checks.Values(truth=f"G_2/λ of the {truth.BLADE}; concentric holes", points=_points, tol=TOL,
                                 kind="quadrature"),
             kernel=RECTANGLE_G2_KERNEL,
             note="(333) for the concentric hole of n°106's footnote, in dimensionless arguments for its kernel."),
    )
