"""Haag 1935, chapter II, n°44–46, eqs. (151)–(155): the dissymmetric blade, friction with clamping errors, the Results."""
from __future__ import annotations

import sympy as sp

from pendsym import checks
from pendsym.result import Spec
from ..common import READ_VW, rid, src, step
from . import derivation, friction, printed, truth
from .printed import READ_152, READ_DPHI, READ_EPS4, READ_LIMITS, READ_NU

EXACT = "symbolic proof (SymPy)"
PERIOD, P_155 = rid(154, "dT"), rid(155, "P")


def _zero(expr) -> bool:
    return all(sp.simplify(e) == 0 for e in (expr if isinstance(expr, sp.Tuple) else (expr,)))


def _odd_nonzero(expr) -> bool:
    """The odd part of P is not 0: at g_1 = 1, A = 0 it is (2φ1 + sin 2φ1)/π, ≠ 0 for φ1 ≠ 0."""
    at = expr.subs({derivation.A_d: 0}).replace(lambda e: isinstance(e, sp.Function) and e.func.__name__ == "g",
                                                 lambda e: sp.S.One)
    return sp.simplify(at.subs(derivation.phi1, sp.Rational(1, 3))) != 0


def _zeros(expr) -> bool:
    return len(expr) > 0 and all(sp.simplify(e) == 0 for e in expr)


def specs() -> tuple[Spec, ...]:
    return (
        Spec(rid(151, "eps"), "ε_4 = −ε[θ1(Kv + w) + wj − vi] on the side θ > 0", src(44, None), r"\varepsilon_4",
             step(derivation.eps_along), printed=printed.eps_along, readings=(READ_EPS4, READ_DPHI, READ_NU),
             check=checks.Chain((PERIOD, P_155)),
             note="−εM dφ/ds with M dφ/ds = Yv + θw ((9), (13)), θ = j + θ1 (119), Y = Kθ1 − i (122); ε_4 = 0 for θ < 0."),
        Spec(rid(151, "f"), "f = −(n²/K)[θ1g_1(ε) − Ai + Bj]", src(44, "151"), "f", step(derivation.eq151),
             printed=printed.eq151, readings=(READ_NU,), check=checks.Chain((PERIOD, P_155)),
             note="(104)–(105) with ε_4; the θ1, i, j parts recognised as g_1(ε) (139), A, B (152)."),
        Spec(rid(152, "AB"), "A = ∫v(Kv + w)ε/M ds, B = ∫w(Kv + w)ε/M ds", src(44, "152"), "(A, B)",
             step(derivation.eq152), printed=printed.eq152, readings=(READ_NU, READ_152, READ_VW),
             check=checks.Definition(), definition=True),
        Spec(rid(152, "half_derivatives"), "A, B are the half-derivatives of g_1 in K and in the homogeneity variable",
             src(44, None), r"(\tfrac12\partial_K g_1 - A, \tfrac12\partial_x g_1 - B)", step(derivation.half_derivatives),
             printed=printed.half_derivatives,
             check=checks.Proof("g_1 = ∫(Kv + xw)²ε/M at x = 1: ½∂/∂K and ½∂/∂x under the integral are the "
                                "integrands of A and B", holds=_zero, truth=EXACT)),
        Spec(rid(153, "phi1"), "θ0 sin φ1 = −j, φ1 in (−π/2, π/2)", src(44, "153"), r"\theta_0\sin\varphi_1 + j", step(derivation.eq153),
             printed=printed.eq153, check=checks.Definition(), definition=True),
        Spec(PERIOD, "ΔT/T of the dissymmetry (with clamping errors)", src(44, "154"), r"\frac{\Delta T}{T}",
             step(derivation.eq154), printed=printed.eq154, readings=(READ_LIMITS,), check=truth.order("154"),
             note="First harmonic (114) of (151) along θ1 = θ0 sin φ over φ1 < φ < π − φ1 (θ > 0); (134) is to be "
                  "added (the dissymmetry leaves ΔX unchanged)."),
        Spec(rid(155, "i"), "i = −j(a + wλ)/(a − vλ) for i' = 0", src(45, None), "i", step(derivation.i_of_j),
             printed=printed.i_of_j,
             check=checks.Proof("(117) (derived) at i' = 0 solved for i, wλ = −a1", truth=EXACT,
                                holds=lambda e: sp.simplify(e - printed.i_of_j()) == 0)),
        Spec(rid(155, "AK_B"), "AK + B = g_1", src(45, None), r"AK + B - g_1", step(derivation.identity_AK_B),
             printed=printed.identity_AK_B, check=checks.Proof("the integrands of (152) and (139)", holds=_zero,
                                                             truth=EXACT)),
        Spec(P_155, "P = 4Q·ΔT/T of the symmetric clock (i' = 0)", src(45, "155"), "P", step(derivation.eq155),
             printed=printed.eq155, check=truth.order("155"),
             note="(154) + Cj²/Q times 4Q, i of (117), B = g_1 − AK, j = −θ0 sin φ1; a + wλ − K(a − vλ) = Kz by (36). "
                  "Checked at C = 0 (the Cj²/Q part is (134), checked in n°35)."),
        Spec(rid(155, "not_even"), "P is not even in j: T differs for equilibria symmetric about the vertical",
             src(45, None), r"\tfrac12[P(\varphi_1) - P(-\varphi_1)]", step(derivation.odd_part_155), printed=None,
             check=checks.Proof("the odd part of P in φ1 (φ1 odd in j) at g_1 = 1, A = 0, φ1 = 1/3 is not 0",
                                holds=_odd_nonzero, truth=EXACT)),
        # ---------------------------------------------------------------- n°46
        Spec(rid(155, "friction_odd"), "friction with clamping errors: the part of ΔT/T odd in j (p = q = 1)",
             src(46, None), r"\tfrac12[\tfrac{\Delta T}{T}(j) - \tfrac{\Delta T}{T}(-j)]", step(friction.odd_p1q1),
             printed=None, check=truth.friction_odd_order(),
             note="(146) about the tilted equilibrium in θ = j + θ1, by (114) over the four arcs; ∝ (b − a) − (b' − a'). "
                  "The text gives no formula (derived only)."),
        Spec(rid(155, "friction_case1"), "T symmetric about the vertical when b − a = b' − a'", src(46, None),
             r"\text{odd parts}", step(friction.case_equal_differences), printed=lambda: sp.Tuple(*[0] * len(friction.DEGREES)),
             check=checks.Proof("the odd parts in j at (p, q) = (1, 0), (1, 1), (2, 0), (2, 1), (1, 2) with b' = b − a + a'",
                                holds=_zeros, truth=EXACT),
             note="First case of n°46, on the reduced equation with the friction in θ = j + θ1 (as friction_odd)."),
        Spec(rid(155, "friction_case2"), "T symmetric about the vertical when the friction is independent of the curvature",
             src(46, None), r"\text{odd parts}", step(friction.case_no_curvature), printed=lambda: sp.Tuple(0, 0, 0, 0),
             check=checks.Proof("the odd parts in j at p = 0, q = 0 … 3, any a, b, a', b'", holds=_zeros, truth=EXACT),
             note="Second case of n°46."),
    )
