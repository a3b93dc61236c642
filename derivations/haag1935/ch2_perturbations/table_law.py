"""Haag 1935, chapter II, n°38–43, eqs. (137)–(150): Le Rolland's moment law and internal friction, the Results."""
from __future__ import annotations

import sympy as sp

from pendsym import checks
from pendsym.result import Spec
from ..common import READ_VW, rid, src, step
from . import derivation, derivation_experiment, derivation_friction, printed, truth
from .printed import READ_139, READ_145, READ_147_I, READ_ALPHA, READ_BETA, READ_EPS, READ_G0

EXACT = "symbolic proof (SymPy)"
YOUNG = rid(141, "dT")
FRICTION_T, FRICTION_AMP = rid(147, "dT"), rid(149, "amplitude")


def _is(target):
    return lambda expr: sp.simplify(expr - target) == 0


def _zero(expr) -> bool:
    return all(sp.simplify(e) == 0 for e in expr)


def _means_hold(expr) -> bool:
    """The half-sums from α, β are ½(a + a'), ½(b + b') once α, β are put back (:func:`derivation_experiment.alpha_beta`)."""
    alpha, beta = derivation_experiment.alpha_beta()
    back = expr.subs({derivation_experiment.alpha_f: alpha, derivation_experiment.beta_f: beta})
    f = derivation_friction
    return _zero(sp.Tuple(back[0] - (f.a_f + f.ap_f) / 2, back[1] - (f.b_f + f.bp_f) / 2))


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
             printed=printed.eq141, readings=(READ_G0,),
             check=checks.All((truth.law_order(), truth.young_order("uniform", True))),
             note="First harmonic of f along θ = θ0 cos φ, |cos φ|^q cos²φ over four quarters; checked at q = 2 on "
                  "the exact blade with the law M(c + a2c³) (order in θ0) and at q = 0 on the stiffer linear blade "
                  "(order in a0).  q odd with |c|^q is not checked: the law is not analytic at c = 0, out of reach "
                  "of the collocation."),
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
        Spec(rid(145, "eps"), "ε of the incoming friction: +Mb_pq c^p|c'|^q (θ > 0, θ' < 0)", src(40, "145"),
             r"\varepsilon", step(derivation_experiment.eq145), printed=printed.eq145, readings=(READ_145,),
             check=checks.Chain((FRICTION_T, FRICTION_AMP)),
             note="n°41's replacement a → −b, c' → −c' = |c'| in one term of (144); b_pq is the coefficient of the "
                  "truth's quadrant 'right, going back'."),
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
        # ---------------------------------------------------------------- n°43
        Spec(rid(150, "alpha_beta"), "α_pq = b + b' − a − a', β_pq = b + b' + a + a'", src(43, None),
             r"(\alpha_{pq}, \beta_{pq})", step(derivation_experiment.alpha_beta), printed=printed.alpha_beta,
             readings=(READ_ALPHA,), check=checks.Definition(), definition=True,
             note="Read off the derived (147) and (149): the only combinations of a, a', b, b' they hold."),
        Spec(rid(150, "means"), "½(a + a') and ½(b + b') follow from α, β", src(43, None),
             r"(\tfrac12(a + a'), \tfrac12(b + b'))", step(derivation_experiment.means), printed=None,
             check=checks.Proof("the sums solved from α, β, with α, β of (147), (149) put back, are ½(a + a'), "
                                "½(b + b')", holds=_means_hold, truth=EXACT)),
        Spec(rid(150, "no_dissymmetry"), "no dissymmetry of the friction can be seen in T(θ0), Δθ0(θ0)", src(43, None),
             r"(\Delta(147), \Delta(149))", step(derivation_experiment.no_dissymmetry), printed=printed.no_dissymmetry,
             check=checks.Proof("(147), (149) (derived) unchanged by a → a + d, a' → a' − d, b → b + e, b' → b' − e",
                                holds=_zero, truth=EXACT)),
        Spec(rid(150, "dT"), "ΔT/T = a/θ0 + bθ0^{p−1} + cθ0^p + …", src(43, "150"), r"\frac{\Delta T}{T}",
             step(derivation_experiment.eq150_period), printed=printed.eq150_period,
             check=checks.Proof("θ0^{p+q−1} of (147) (derived) at the degrees p + q = 0, p, p + 1",
                                holds=lambda e: sp.simplify(e - printed.eq150_period()) == 0, truth=EXACT),
             note="p: the degree of the first non-constant friction term; a, b, c stand for the sums of (147)'s "
                  "coefficients at each degree."),
        Spec(rid(150, "amplitude"), "Δθ0 = a' + b'θ0^p + c'θ0^{p+1} + …", src(43, "150"), r"\Delta\theta_0",
             step(derivation_experiment.eq150_amplitude), printed=printed.eq150_amplitude,
             check=checks.Proof("θ0^{p+q} of (149) (derived) at the degrees p + q = 0, p, p + 1",
                                holds=lambda e: sp.simplify(e - printed.eq150_amplitude()) == 0, truth=EXACT)),
        Spec(rid(150, "alpha00"), "Le Rolland's aθ0 + bθ0² + cθ0³ means α_00 = 0: a_00 + a'_00 = b_00 + b'_00",
             src(43, None), r"a_{00} + a'_{00} - b_{00} - b'_{00}", step(derivation_experiment.alpha00),
             printed=printed.alpha00,
             check=checks.Proof("(147) at p = q = 0 is the only term in 1/θ0; its factor other than g_0(1)i_{1,0} is "
                                "a_00 + a'_00 − b_00 − b'_00", truth=EXACT,
                                holds=lambda e: sp.simplify(e - printed.alpha00()) == 0)),
    )
