"""Haag 1935, chapter II, n°27 and n°30: the Results of (95)–(100), (101) by the variation of constants, (113),
(115) and the remarks of n°30–31 (the rest of n°26–30 is in :mod:`.table`)."""
from __future__ import annotations

import sympy as sp

from pendsym import checks
from pendsym.result import Spec
from ..common import READ_VW, rid, src, step
from . import derivation, printed, truth, variation
from .printed import READ_97_Y, READ_98_W, READ_115_EPS

EXACT = "symbolic proof (SymPy)"
BY_CONSTANTS = rid(101, "by_constants")
THROUGH_101 = checks.Chain((BY_CONSTANTS,))
_x = sp.Symbol("x_test")
# test functions for the comparison of forms holding the arbitrary ε(s), y(s), M(s), v(s), w(s)
INSTANCES = (((variation.eps_f, sp.Lambda(_x, 1 + _x + _x**2)), (variation.y_f, sp.Lambda(_x, sp.exp(_x / 3))),
              (variation.M_of_s, sp.Lambda(_x, 2 + _x)), (variation.v, sp.Lambda(_x, sp.cos(_x))),
              (variation.w, sp.Lambda(_x, _x + sp.sin(_x)))),)


def _zero(expr) -> bool:
    return all(sp.simplify(x) == 0 for x in (expr if isinstance(expr, sp.Tuple) else (expr,)))


def _98_holds(expr) -> bool:
    """Both forms of (98) vanish at s = 0 and have the derivatives A', B' of the variation of constants."""
    ok = True
    for form, d in zip(expr, variation.derivatives_of_constants()):
        at0 = form.subs(variation.s, 0).subs({variation.eps_f(0): variation.eps0, variation.v(0): variation.v0,
                                              variation.w(0): variation.w0}).doit()
        ok &= sp.simplify(at0) == 0
        ok &= sp.simplify(sp.expand(form.diff(variation.s).doit() - d).subs(
            {variation.v(variation.s).diff(variation.s): variation.varphi1(variation.s) - 1,
             variation.w(variation.s).diff(variation.s): variation.varphi2(variation.s)})) == 0
    return bool(ok)


def specs() -> tuple[Spec, ...]:
    return (
        Spec(rid(95, "x"), "x = y' − ε + ΔY", src(27, "95"), "x", step(variation.eq95), printed=printed.eq95,
             readings=(READ_97_Y, printed.READ_94), check=THROUGH_101, instances=INSTANCES, note="(93) with y = Mx'."),
        Spec(rid(96, "y"), "My'' − y = Mε'", src(27, "96"), "My'' - y", step(variation.eq96), printed=printed.eq96,
             check=THROUGH_101, instances=INSTANCES, note="The derivative of (95) with x' = y/M."),
        Spec(rid(97, "y"), "y = Av + Bw + Cv + C'w", src(27, "97"), "y", step(variation.eq97), printed=printed.eq97,
             readings=(READ_VW, READ_98_W), instances=INSTANCES,
             check=checks.Proof("y of (97) with A, B of (98) solves My'' − y = Mε' (v'' = v/M, w'' = w/M, "
                                "vw' − wv' = w0 (15))", holds=lambda e: variation.eq97_solves_96() == 0, truth=EXACT),
             note="A, B in their first forms (98); the solution is checked, not only the form."),
        Spec(rid(98, "AB_integrals"), "A = −(1/w0)∫ε'w ds, B = (1/w0)∫ε'v ds", src(27, "98"), "(A, B)",
             step(variation.eq98_integrals), printed=printed.eq98_integrals, readings=(READ_VW, READ_98_W),
             check=checks.Proof("A(0) = B(0) = 0 and (A', B') solve A'v + B'w = 0, A'v' + B'w' = ε'",
                                holds=_98_holds, truth=EXACT)),
        Spec(rid(98, "AB"), "A = ε0 − εw/w0 + (1/w0)∫εφ2 ds, B = −ε0v0/w0 + εv/w0 + (1/w0)∫ε(1 − φ1) ds",
             src(27, "98"), "(A, B)", step(variation.eq98), printed=printed.eq98, readings=(READ_VW, READ_98_W),
             check=checks.Proof("A(0) = B(0) = 0 and A', B' are those of the variation of constants",
                                holds=_98_holds, truth=EXACT),
             note="The first forms integrated by parts, φ1 = 1 + v', φ2 = w' (11)."),
        Spec(rid(99, "C"), "C = ΔY − ε0", src(27, "99"), "C", step(variation.eq99), printed=printed.eq99,
             check=THROUGH_101, note="x(0) = 0: y'(0) = ε0 − ΔY, v'(0) = −1, w'(0) = 0 (10)."),
        Spec(rid(100, "Cp"), "−Aλ + Bλ − C + C' = ελ − ΔY", src(27, "100"), "y'(\\lambda)", step(variation.eq100),
             printed=printed.eq100, check=THROUGH_101, note="x(λ) = 0: y'(λ) with v'(λ) = −1, w'(λ) = 1 (10)."),
        Spec(BY_CONSTANTS, "β1ΔY = ∫εφ1 ds by the variation of constants", src(27, "101"), r"\Delta Y",
             step(variation.eq101_by_constants), printed=printed.eq101, readings=(printed.READ_101,),
             check=checks.All((checks.Proof("equal to ΔY of the Green identity (haag1935.eq101.dY)",
                                            holds=lambda e: sp.simplify(e - derivation.Delta_Y()) == 0,
                                            truth=EXACT),
                               truth.delta_Y_direct()),
                              truth="symbolic proof, and the boundary-value problem (93) solved directly"),
             note="∫x ds = λΔY − ∫ε ds + y_λ − y_0 = 0 with (97)–(100) and (16); I_1 = ∫εφ1 ds."),
        # ---------------------------------------------------------------- n°30
        Spec(rid(113, "theta"), "θ = θ1(1 + ε), θ1 = θ0 cos φ, φ = nt", src(30, "113"), r"\theta",
             step(variation.eq113), printed=printed.eq113, check=checks.Definition(), definition=True),
        Spec(rid(115, "dT"), "ΔT = (1/(n³θ0))∫Aθ1^pθ1'^q(1 + β + α) cos φ dφ", src(30, "115"), r"\Delta T",
             step(variation.eq115), printed=printed.eq115, readings=(READ_115_EPS,),
             check=checks.Proof("(114) with θ = θ1(1 + ε), θ' = θ1'(1 + ε'): the integrand is "
                                "Aθ1^pθ1'^q(1 + β)(1 + α), and αβ is of the third order", truth=EXACT,
                                holds=lambda e: sp.simplify(e - printed.eq115()) == 0)),
        Spec(rid(115, "beta"), "β = (1 + ε)^p(1 + ε')^q − 1 = pε + qε' + …", src(30, None), r"\beta",
             step(variation.beta_30_series), printed=printed.beta_30, readings=(READ_115_EPS,),
             check=checks.Proof("the first-order Taylor polynomial", truth=EXACT,
                                holds=lambda e: sp.expand(e - printed.beta_30()) == 0)),
        Spec(rid(115, "calculable"), "one calculable term at most has a nonzero average; none if p even, q odd",
             src(30, None), r"\#\{\int\theta_1^a\theta_1'^b\cos\varphi\,d\varphi \neq 0\}",
             step(variation.nonzero_calculable),
             check=checks.Proof("for 0 ≤ p, q ≤ 5: the averages of θ1^pθ1'^q, θ1^{p+1}θ1'^q, θ1^pθ1'^{q+1} "
                                "times cos φ: none nonzero when p is even and q odd, exactly one otherwise",
                                holds=_zero, truth=EXACT)),
        Spec(rid(114, "next_term"), "(114) gives only the θ0²/16 of the simple pendulum: its θ0⁴ term is false",
             src(31, None), r"[\theta_0^4]\,\frac{\Delta T}{T}", step(variation.pendulum_next_term),
             check=truth.next_term_false(),
             note="The footnote of n°31: (114) with the whole F = n²(θ − sin θ) gives −θ0⁴/384; the true "
                  "coefficient of the simple pendulum's period is 11/3072."),
    )
