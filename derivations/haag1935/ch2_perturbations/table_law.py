"""Haag 1935, chapter II, n°38–42, eqs. (137)–(149): Le Rolland's moment law and internal friction, the Results."""
from __future__ import annotations

import sympy as sp

from pendsym import checks
from pendsym.result import Spec
from ..common import READ_VW, rid, src, step
from . import derivation, derivation_friction, printed, truth
from .printed import READ_139, READ_147_I, READ_BETA, READ_EPS, READ_G0

EXACT = "symbolic proof (SymPy)"
YOUNG = rid(141, "dT")
FRICTION_T, FRICTION_AMP = rid(147, "dT"), rid(149, "amplitude")


def _is(target):
    return lambda expr: sp.simplify(expr - target) == 0


def _same_as_60(deps):
    return derivation.same_as_60(deps[rid(60, "dT")].derived)


def specs() -> tuple[Spec, ...]:
    q = derivation.q
    n = sp.Symbol("n", integer=True, nonnegative=True)
    return (
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
        # ---------------------------------------------------------------- n°40–42
        Spec(rid(144, "eps"), "ε of the outgoing friction: −Ma_pq c^p c'^q", src(40, "144"), r"\varepsilon",
             step(derivation_friction.friction_moment), printed=printed.friction_moment, readings=(READ_BETA,),
             check=checks.Chain((FRICTION_T,)), note="One term of (144); c' = dc/dt."),
        Spec(rid(146, "f"), "f = −(n²/K)g_{p+q}(a_pq)θ^pθ'^q", src(41, "146"), "f", step(derivation_friction.eq146),
             printed=printed.eq146, check=checks.Chain((FRICTION_T, FRICTION_AMP)),
             note="(104)–(105) with c = θ(Kv + w)/M, c' = θ'(Kv + w)/M; the integral recognised as g_{p+q}."),
        Spec(rid(148, "symmetric"), "i_mn = i_nm", src(41, None), r"\cos^m\sin^n(\tfrac{\pi}{2} - u) - \cos^n\sin^m u",
             step(derivation_friction.i_symmetric), printed=printed.i_symmetric,
             check=checks.Proof("the substitution φ = π/2 − u exchanges cos and sin", truth=EXACT)),
        Spec(FRICTION_T, "ΔT/T of internal friction", src(41, "147"), r"\frac{\Delta T}{T}", step(derivation_friction.eq147),
             printed=printed.eq147, defs=printed.DEFS_147, readings=(READ_147_I,), check=truth.friction_order(0),
             note="(146) in the four quadrants by Haag's replacements, first harmonic (114); checked at p = q = 1 on "
                  "the reduced equation θ'' + n²θ = f/(z − z') (the step from (146), not (146) itself)."),
        Spec(rid(149, "energy"), "Δθ0 = (1/(n²(z − z')θ0))∫f dθ", src(42, None), r"\Delta\theta_0",
             step(derivation_friction.first_line_149), printed=printed.first_line_149, check=checks.Chain((FRICTION_AMP,)),
             note="From the energy of y'' + n²y = f over a period; I_f stands for ∫f dθ."),
        Spec(FRICTION_AMP, "Δθ0 per period (damping)", src(42, "149"), r"\Delta\theta_0", step(derivation_friction.eq149),
             printed=printed.eq149, defs=printed.DEFS_149, readings=(READ_147_I,), check=truth.friction_order(1),
             note="Checked at p = q = 1 on the reduced equation, as (147)."),
    )
