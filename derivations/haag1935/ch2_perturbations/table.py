"""Haag 1935, chapter II, n°36–39, eqs. (135)–(143): the Results, joining derivation, print and truth."""
from __future__ import annotations

import sympy as sp

from pendsym import checks
from pendsym.result import Spec
from ..common import READ_VW, rid, src, step
from ..symbols import K, Q, z, zp
from . import derivation, printed, truth
from .printed import READ_139, READ_EPS, READ_F_36, READ_G0, READ_LIMITS_36, READ_WEIGHT_M

EXACT = "symbolic proof (SymPy)"
INERTIA, WEIGHT, YOUNG = rid(135, "inertia"), rid(136, "weight"), rid(141, "dT")
Q_DEF = ((Q, K * (z - zp)),)


def _all_zero(expr) -> bool:
    return all(sp.simplify(x) == 0 for x in expr)


def _is(target):
    return lambda expr: sp.simplify(expr - target) == 0


def _same_as_60(deps):
    return derivation.same_as_60(deps[rid(60, "dT")].derived)


def specs() -> tuple[Spec, ...]:
    q = derivation.q
    n = sp.Symbol("n", integer=True, nonnegative=True)
    return (
        # ---------------------------------------------------------------- n°36
        Spec(rid(135, "inertia_moment"), "ε of the blade's inertia: mgε = −∫μ'ÿ'(s' − s) ds'", src(36, None),
             r"\varepsilon", step(derivation.inertia_moment), printed=printed.inertia_moment,
             readings=(READ_EPS, READ_LIMITS_36), check=checks.Chain((INERTIA,)),
             note="Derived from the horizontal momentum of the part below s (the shear), ε(λ) = 0, the order of "
                  "the two integrals changed; s_1 is Haag's s'."),
        Spec(rid(135, "inertia_eps"), "ε in the principal oscillation", src(36, None), r"\varepsilon",
             step(lambda: derivation.as_phi(derivation.inertia_moment_principal())),
             printed=printed.inertia_moment_principal, readings=(READ_EPS,), check=checks.Chain((INERTIA,)),
             note="ÿ = −n²y, y = θ∫_0^s'(Kφ1 + φ2) ds'', n²/g = −K/z' (34)."),
        Spec(rid(135, "parts"), "∫_0^s'(Kv + w)/M (s' − s) ds = ∫_0^s'(Kφ1 + φ2) ds", src(36, None),
             r"(\partial_{s'}^2\Delta, \partial_{s'}\Delta(0), \Delta(0))", step(derivation.parts_identity),
             printed=printed.parts_identity, readings=(READ_VW,),
             check=checks.Proof("the difference has second derivative 0 (by (9)) and vanishes with its slope at "
                                "s' = 0 (by (10))", holds=_all_zero, truth=EXACT)),
        Spec(rid(135, "I_lambda"), "I_λ = ∫μy² ds (y for θ = 1)", src(36, None), r"I_\lambda",
             step(lambda: derivation.as_phi(derivation.I_lambda_def())), printed=printed.I_lambda_def,
             check=checks.Definition(), definition=True),
        Spec(rid(135, "inertia_f"), "f = −(n²/(mz'))θI_λ", src(36, None), "f", step(derivation.inertia_f),
             printed=printed.inertia_f, readings=(READ_F_36, READ_VW), check=checks.Chain((INERTIA,)),
             note="(104)–(105) with ε of the inertia; ∫ds∫ds' reordered and reduced by the parts identity."),
        Spec(INERTIA, "ΔT/T of the blade's inertia", src(36, "135"), r"\frac{\Delta T}{T}", step(derivation.eq135),
             printed=printed.eq135, check=truth.mass_order("hole", True), show_values=True,
             note="f of n°36 by (114); density ∝ width (halved over the hole)."),
        Spec(rid(135, "inertia_Q"), "ΔT/T = −KI_λ/(2mQz')", src(36, "135"), r"\frac{\Delta T}{T}",
             step(derivation.eq135), printed=printed.eq135_Q, defs=Q_DEF, check=truth.mass_order("uniform", True),
             note="The second form of (135), Q = K(z − z') (45)."),
        Spec(rid(135, "delay"), "the inertia always delays: ΔT/T > 0", src(36, None), r"\frac{\Delta T}{T}",
             lambda deps: deps[INERTIA].derived, deps=(INERTIA,),
             check=truth.sign_on_blades("ΔT/T of (135) > 0 (z' < 0 < z − z', I_λ > 0)")),
        # ---------------------------------------------------------------- n°37
        Spec(rid(136, "weight_moment"), "ε of the blade's weight: mε = −∫μ'(y' − y) ds'", src(37, None),
             r"\varepsilon", step(derivation.weight_moment), printed=printed.weight_moment,
             readings=(READ_EPS, READ_WEIGHT_M), check=checks.Chain((WEIGHT,)),
             note="Derived from the tension mg + g∫_s^λμ ds', ε(λ) = 0, the order changed."),
        Spec(rid(136, "slope"), "∫_0^s''(Kv + w)/M ds = Kφ1'' + φ2''", src(37, None), r"(\Delta', \Delta(0))",
             step(derivation.slope_identity), printed=printed.slope_identity, readings=(READ_VW,),
             check=checks.Proof("the difference has derivative 0 (by (9)) and vanishes at 0 (by (10))",
                                holds=_all_zero, truth=EXACT)),
        Spec(rid(136, "J"), "J = (1/m')∫μ(s − x) ds (θ = 1)", src(37, None), "J",
             step(lambda: derivation.as_phi(derivation.J_def())), printed=printed.J_def, defs=printed.DEFS_J,
             check=checks.Definition(), definition=True,
             note="s − x = ½∫_0^sφ² ds from x' = cos φ (3) to the second order (the text's ∫φ''² = 2(s' − x'))."),
        Spec(rid(136, "weight_f"), "f = −(2m'J/(Km))n²θ", src(37, None), "f", step(derivation.weight_f),
             printed=printed.weight_f, check=checks.Chain((WEIGHT,)),
             note="(104)–(105) with ε of the weight; the three integrals reordered (0 < s < s'' < s' < λ)."),
        Spec(WEIGHT, "ΔT/T of the blade's weight", src(37, "136"), r"\frac{\Delta T}{T}", step(derivation.eq136),
             printed=printed.eq136, check=truth.mass_order("hole", False), show_values=True,
             note="f of n°37 by (114), Q = K(z − z') (45)."),
        Spec(rid(136, "advance"), "the weight always advances: −ΔT/T > 0", src(37, None), r"-\frac{\Delta T}{T}",
             lambda deps: -deps[WEIGHT].derived, deps=(WEIGHT,),
             check=truth.sign_on_blades("−ΔT/T of (136) > 0 (J > 0, Q > 0)")),
        # ---------------------------------------------------------------- n°38–39
        Spec(rid(137, "eps"), "ε = −Ma_q(dφ/ds)^{q+1} of the law EIc(1 + a_qc^q)", src(38, "137"), r"\varepsilon",
             step(derivation.law_moment), printed=printed.law_moment, readings=(READ_EPS,),
             check=checks.Chain((YOUNG,)), note="c = dφ/ds; a_q may depend on s (a(q, s))."),
        Spec(rid(138, "f"), "f_q = −(n²/K)θ^{q+1}g_{q+1}(a_q)", src(38, "138"), "f_q", step(derivation.eq138),
             printed=printed.eq138, check=checks.Chain((YOUNG,)),
             note="(104)–(105), c = θ(Kv + w)/M; the integral recognised as g_{q+1} of (139)."),
        Spec(rid(139, "g"), "g_q(x) = ∫(Kv + w)^{q+1}x/M^q ds", src(38, "139"), "g_q(x)", step(derivation.eq139),
             printed=printed.eq139, readings=(READ_139, READ_VW), check=checks.Definition(), definition=True),
        Spec(rid(140, "g"), "g_q = xG_{q+1} for x constant", src(38, "140"), "g_q", step(derivation.eq140),
             printed=printed.eq140,
             check=checks.Proof("x out of (139); the rest is G_{q+1} of (79)", holds=_is(printed.eq140()),
                                truth=EXACT)),
        Spec(YOUNG, "ΔT/T of the term a_q|c|^q", src(38, "141"), r"\frac{\Delta_q T}{T}", step(derivation.eq141),
             printed=printed.eq141, readings=(READ_G0,), check=truth.young_order("uniform", True),
             note="First harmonic of f along θ = θ0 cos φ, |cos φ|^q cos²φ over four quarters; checked at q = 0 "
                  "only (q ≥ 1 would need the exact blade with the modified law)."),
        Spec(rid(141, "odd"), "an odd term in algebraic value leaves T unchanged", src(38, None),
             r"\cos^{q+2}(\pi - \varphi)/\cos^{q+2}\varphi", step(derivation.odd_terms_vanish),
             printed=printed.odd_terms,
             check=checks.Proof("q odd: cos^{q+2}(π − φ) = −cos^{q+2}φ, the half-periods cancel in (114)",
                                holds=lambda e: e == -1, truth=EXACT)),
        Spec(rid(142, "i_even"), "i_q = 1·3·5…(q − 1)/(2·4·6…q), q even", src(38, "142"), "i_q",
             step(derivation.eq142), printed=printed.eq142, defs=((q, 2 * n),),
             check=checks.Proof("the recurrence qi_q = (q − 1)i_{q−2} solved by rsolve equals the product (Gamma "
                                "functions)", holds=lambda e: sp.simplify(sp.gammasimp(
                                    (e - printed.eq142()).subs(q, 2 * n).rewrite(sp.gamma))) == 0, truth=EXACT)),
        Spec(rid(143, "i_odd"), "i_q = (2/π)·2·4·6…(q − 1)/(3·5·7…q), q odd", src(38, "143"), "i_q",
             step(derivation.eq143), printed=printed.eq143, defs=((q, 2 * n + 1),),
             check=checks.Proof("the recurrence solved by rsolve from i_1 = 2/π equals the product",
                                holds=lambda e: sp.simplify(sp.gammasimp(
                                    (e - printed.eq143()).subs(q, 2 * n + 1).rewrite(sp.gamma))) == 0, truth=EXACT)),
        Spec(rid(141, "young"), "ΔT/T = −(G2/(2Q))ΔE/E (q = 0)", src(39, None), r"\frac{\Delta T}{T}",
             step(derivation.eq139_q0), printed=printed.young, check=truth.young_order("hole", False),
             note="(141) at q = 0, i_2 = 1/2, g_1 = a0G2 (140), a0 = ΔE/E."),
        Spec(rid(141, "as_60"), "n°39 is (60) with α = α' = 0, β = ΔE/E", src(39, None), r"\Delta", _same_as_60,
             deps=(rid(60, "dT"),), printed=None,
             check=checks.Proof("(60) with α = α' = 0, β = ΔE/E minus the derived n°39 is 0", truth=EXACT)),
    )
