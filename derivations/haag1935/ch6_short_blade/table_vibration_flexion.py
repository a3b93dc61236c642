"""Haag 1935, chapter VI, n°71, 76–77: the parasitic vibration, the suppleness and the centre of flexion
of the short blade, (224)–(226), (235)–(240)."""
from __future__ import annotations

from pendsym import checks
from pendsym.result import Reading, Spec

from ..ch1_shape.printed import eq87 as optimum_87
from ..ch3_uniform.printed import T_DEFINITION
from ..common import READ_VW, rid, src
from . import derivation, printed, truth, truth_dynamics
from .printed import DEFINITIONS

FORK = "x = λ − c, the root of smaller modulus of (87) (verified in n°25 against the fork's glide) with z', K of the modes"


def specs() -> tuple[Spec, ...]:
    both = ("tapered", "uniform")
    thin = "n°77, u > 4"
    return (
        # ------------------------------------------------------------ n°71
        Spec(rid(224, "Kp"), "K' ≈ −l/β1", src(71, "224"), "K'", derivation.Kp_224,
             deps=(rid(35, "K"), rid(214, "z")), printed=printed.Kp_224, defs=DEFINITIONS,
             check=truth.orders(*both, quantity=truth.relative("K'"), scale=truth.relative("K'"), expected=1,
                                what="K' = −n'²z/g of the parasitic mode (relative residual)")),
        Spec(rid(225, "np2"), "n'² ≈ gal/(β1R²)", src(71, "225"), "n'^2", derivation.np2_225,
             deps=(rid(224, "Kp"), rid(214, "z")), printed=printed.np2_225, defs=DEFINITIONS,
             check=truth.orders(*both, quantity=truth.relative("n'^2"), scale=truth.relative("n'^2"), expected=1,
                                what="n'² of the parasitic mode (relative residual)")),
        Spec(rid(226, "ratio"), "n'/n ≈ (l/R)√(a/β1)", src(71, "226"), "n'/n", derivation.ratio_226,
             deps=(rid(225, "np2"), rid(217, "n2")), printed=printed.ratio_226, defs=DEFINITIONS,
             check=truth.orders(*both, quantity=truth.frequency_ratio, scale=truth.frequency_ratio, expected=1,
                                what="√(n'²/n²) of the two modes (relative residual)")),
        Spec(rid(226, "bound"), "n'/n > (l/R)√(a/λ), since β1 < λ", src(71, "226"),
             r"\frac{n'}{n} - \frac{l}{R}\sqrt{\frac{a}{\lambda}}", derivation.bound_226, deps=(rid(226, "ratio"),),
             printed=printed.bound_226, defs=DEFINITIONS, check=truth.bound()),
        Spec(rid(227, "ratio"), "A'/A after release from the static deviation", src(71, "227"), "A'/A",
             derivation.amplitude_ratio(69), deps=(rid(69, "ratio"), rid(41, "a1"), rid(214, "z"), rid(215, "zp")),
             printed=printed.ratio_227, defs=DEFINITIONS, readings=(printed.READ_BARS,),
             check=checks.All((truth_dynamics.launch_order("static", "tapered"), truth_dynamics.launch_order("static", "uniform"))),
             note="1/(69) with a1 = −w_λ (41); FB/F'B kept, the rest at its leading order in λ/a."),
        Spec(rid(228, "ratio"), "A'/A after a blow at B", src(71, "228"), "A'/A", derivation.amplitude_ratio(73),
             deps=(rid(73, "ratio"), rid(41, "a1"), rid(214, "z"), rid(215, "zp")), printed=printed.ratio_228,
             defs=DEFINITIONS, readings=(printed.READ_BARS,),
             check=checks.All((truth_dynamics.launch_order("blow", "tapered"), truth_dynamics.launch_order("blow", "uniform"))),
             note="1/(73) with a1 = −w_λ (41); FB/F'B kept, the rest at its leading order in λ/a."),
        Spec(rid(228, "over227"), "(228) over (227) = (l/R)√(a/β1)", src(71, None), r"\frac{(228)}{(227)}",
             derivation.ratio_228_227, deps=(rid(227, "ratio"), rid(228, "ratio")), printed=printed.ratio_228_227,
             defs=DEFINITIONS, check=checks.All((truth_dynamics.launch_ratio_order("tapered"),
                                                 truth_dynamics.launch_ratio_order("uniform")))),
        # ------------------------------------------------------------ n°73–75
        *(Spec(rid(229, at), f"largest {text} after release from the static deviation", src(73, "229"), label,
               derivation.fatigue_229(at), deps=(rid(180, at),), printed=printed.fatigue_229(at), defs=DEFINITIONS,
               check=checks.All((truth_dynamics.static_launch_order("uniform", at), truth_dynamics.static_launch_order("uniform_half", at))),
               note="(180) with K = 1, 1/K' = 0 (224), the principal term at t = 0 and the parasitic one at n't = 0 "
                    "or π: the amplitudes add; distances in absolute value.")
          for at, text, label in (("T0", "T'_0", "T'_0"), ("Tl", "T'_λ", r"T'_\lambda"))),
        *(Spec(rid(eq, "T0"), f"largest T'_0, B {where}", src(73, str(eq)), "T'_0", derivation.fatigue_by_attack(case),
               deps=(rid(229, "T0"), rid(67, "theta0"), rid(41, "a1")), printed=printed.fatigue_by_attack(case),
               defs=DEFINITIONS, check=checks.All(tuple(truth_dynamics.attack_order(name, attack)
                                                        for name in ("uniform", "uniform_half"))),
               note="(229) with θ0 of (67) at the leading order, F' at A, F at G (R² ≪ a²).")
          for eq, case, where, attack in ((230, "between", "between F' and F", "0.45"),
                                          (231, "below", "below F", "1.35"))),
        Spec(rid(232, "Tprime"), "T'_0 = √(3ET)U_2θ0, the fatigue at the fixed clamp", src(75, "232"), "T'_0",
             derivation.fatigue_232, deps=(rid(178, "Tprime"),), printed=printed.fatigue_232,
             defs=DEFINITIONS + (T_DEFINITION,),
             check=checks.All((truth_dynamics.fatigue_order("uniform"), truth_dynamics.fatigue_order("uniform_half"))),
             note="(178) at s = 0 with K = 1 (n°75); Haag reaches it also from (229)–(231) with B at F, which "
                  "rest on (180)–(181), not built."),
        # ------------------------------------------------------------ n°76
        Spec(rid(235, "S"), "suppleness S ≈ a/G_2", src(76, "235"), "S", derivation.S_235, deps=(rid(82, "S"),),
             printed=printed.S_235,
             check=checks.All((truth.suppleness_order("uniform", True), truth.suppleness_order("tapered", True))),
             note="The leading term in λ/a of (82); G_2 of the formula by quadrature of (79) at the mode's K."),
        Spec(rid(235, "S_uniform"), "S = 2a/(λ(U_1² + U_2/u)) for the uniform blade", src(76, "235"), "S",
             derivation.S_uniform_235, deps=(rid(235, "S"), rid(166, "Gamma2")), printed=printed.S_uniform_235,
             defs=DEFINITIONS, check=truth.suppleness_order("uniform", False),
             note="G_2 = λΓ_2 (163) with Γ_2 of (166) at K = 1 (k = 0)."),
        Spec(rid(235, "S_sh"), "S = (2a/λ)·u sh²u/(u + sh u ch u)", src(76, "235"), "S", derivation.S_uniform_235,
             deps=(rid(235, "S"), rid(166, "Gamma2")), printed=printed.S_sh_235, check=truth.suppleness_order("uniform", False)),
        Spec(rid(235, "u_factor"), "the factor of (235) that depends on u: S·λ/(2a)", src(76, "235"),
             r"\frac{u\,\mathrm{sh}^2u}{u + \mathrm{sh}\,u\,\mathrm{ch}\,u}", derivation.u_factor_235,
             deps=(rid(235, "S_uniform"),), printed=printed.u_factor_235, check=truth.factor_check(True)),
        Spec(rid(235, "increasing"), "u sh²u/(u + sh u ch u) increases with u", src(76, "235"),
             r"\frac{d}{du}\,\frac{u\,\mathrm{sh}^2u}{u + \mathrm{sh}\,u\,\mathrm{ch}\,u}",
             derivation.growing((235, "u_factor")), deps=(rid(235, "u_factor"),),
             check=truth.increasing("the derived derivative of u sh²u/(u + sh u ch u)")),
        Spec(rid(236, "factor"), "(236): sh²u/(u + sh u ch u), S over (2a/λ)u", src(76, "236"),
             r"\frac{\mathrm{sh}^2u}{u + \mathrm{sh}\,u\,\mathrm{ch}\,u}", derivation.factor_236,
             deps=(rid(235, "S_uniform"),), printed=printed.factor_236, check=truth.factor_check(False)),
        Spec(rid(236, "increasing"), "(236) increases with u", src(76, "236"),
             r"\frac{d}{du}\,\frac{\mathrm{sh}^2u}{u + \mathrm{sh}\,u\,\mathrm{ch}\,u}",
             derivation.growing((236, "factor")), deps=(rid(236, "factor"),),
             check=truth.increasing("the derived derivative of sh²u/(u + sh u ch u)")),
        Spec(rid(236, "value"), "(236) at u = 4 (\"elle vaut déjà 0,993\")", src(76, None), r"(236)_{u=4}",
             derivation.value_236, deps=(rid(236, "factor"),), printed=printed.value_236, printed_decimals=3,
             readings=(Reading("0,993", "0.993 (a decimal comma)"),),
             check=truth.number_check(truth.suppleness_factor_truth, "λ/(2uG_2) at u = 4, G_2 of (79) at K = 1 by "
                                      "quadrature on the shot uniform blade"),
             note="The value is 0.99399…: the printed 0,993 is truncated, not rounded (0,994)."),
        # ------------------------------------------------------------ n°77
        Spec(rid(237, "OFp_l"), "OF' = λ + v_λ − (a/l)β1", src(77, "83, 215"), r"\overline{OF'}",
             derivation.OFp_237_l, deps=(rid(83, "OFp"), rid(215, "zp")), printed=printed.OFp_237_l,
             defs=DEFINITIONS, readings=(READ_VW,),
             check=truth.orders(*both, quantity=truth.centre_of_flexion, scale=truth.by_lambda, expected=1,
                                what="OF' = a + λ + z', z' the node of the principal mode, over λ")),
        Spec(rid(237, "OFp"), "OF' = v_0 (l = a)", src(77, "237"), r"\overline{OF'}", derivation.OFp_237,
             deps=(rid(237, "OFp_l"), rid(22, "beta1")), printed=printed.OFp_237, readings=(READ_VW,),
             check=truth.orders(*both, quantity=truth.centre_of_flexion, scale=truth.by_lambda, expected=1,
                                family=truth.FIXED, what="OF' = a + λ + z', z' the node of the principal mode, over λ")),
        Spec(rid(237, "OFp_thin"), "OF' = λ/u for the thin uniform blade (u > 4)", src(thin, "237"),
             r"\overline{OF'}", derivation.thin_limit(159, "v0"), deps=(rid(159, "v0"),), printed=printed.OFp_thin_237,
             check=truth.thin_order(truth.thin_v0, 1, "v_0 of the shot blade (= OF' by (237)), over λ"),
             note="The leading term of v_0 = λU/u as u → ∞; the residual is O(e^{−u}) (fitted order 1 + O(1/u))."),
        Spec(rid(238, "x_root"), "x = −F_2 − 2(a + z'), the small root of (87)", src(77, "238"), "x",
             derivation.x_238_root, deps=(rid(87, "optimum"),), printed=printed.x_238_root,
             check=truth.orders(*both, quantity=truth.fork_root(optimum_87()), scale=truth.by_lambda, expected=1,
                                inputs=truth.fork_inputs, what=f"{FORK}, F_2 by quadrature at that K, L = a/4; over λ"),
             note="The root of (87) that tends to 0 as λ/L → 0 (L = a/4 in the check)."),
        Spec(rid(238, "x"), "x = −F_2 − 2v_λ + 2(a/l)β1", src(77, "238"), "x", derivation.x_238,
             deps=(rid(238, "x_root"), rid(215, "zp")), printed=printed.x_238, defs=DEFINITIONS,
             readings=(printed.READ_V2,),
             check=truth.orders(*both, quantity=truth.fork_root(optimum_87()), scale=truth.by_lambda, expected=1,
                                inputs=truth.fork_inputs, what=f"{FORK}, F_2 by quadrature at that K, L = a/4; over λ")),
        Spec(rid(239, "F2"), "F_2/λ of the uniform blade at K = 1", src(77, "239"), r"F_2/\lambda", derivation.F2_239,
             deps=(rid(169, "F2"),), printed=printed.F2_239, defs=DEFINITIONS, check=truth.F2_at_one()),
        Spec(rid(240, "x"), "x = λ(1 − U_2/(2u) + U_1²/2) for the uniform blade", src(77, "240"), "x",
             derivation.x_240, deps=(rid(238, "x"), rid(239, "F2"), rid(159, "vl"), rid(159, "beta1")),
             printed=printed.x_240, defs=DEFINITIONS,
             check=truth.orders("uniform", "uniform5", quantity=truth.fork_root(optimum_87()), scale=truth.by_lambda,
                                expected=1, family=truth.FIXED, inputs=truth.fork_inputs,
                                what=f"{FORK}, F_2 by quadrature at that K, L = a/4; over λ"),
             note="Unnumbered, between (239) and (240): (238) with l = a, K = 1."),
        Spec(rid(240, "c"), "c = λ − x = (λ/2)(U_2/u − U_1²)", src(77, "240"), "c", derivation.c_240,
             deps=(rid(240, "x"),), printed=printed.c_240, defs=DEFINITIONS,
             check=truth.orders("uniform", "uniform5", quantity=truth.fork_c(optimum_87()), scale=truth.by_lambda,
                                expected=1, family=truth.FIXED, inputs=truth.fork_inputs,
                                what=f"c = λ − x, {FORK}, F_2 by quadrature at that K, L = a/4; over λ")),
        Spec(rid(240, "c_thin"), "c = λ/(2u) for the thin uniform blade (u > 4)", src(thin, "240"), "c",
             derivation.thin_limit(240, "c"), deps=(rid(240, "c"),), printed=printed.c_thin_240,
             check=truth.thin_order(truth.thin_c, 2, "c = λ + F_2 + 2v_λ − 2β1 ((238) with l = a, K = 1), F_2 by "
                                    "quadrature of (79) on the shot blade, over λ"),
             note="The residual is O(e^{−2u}): the axis of the fork in the middle of OF' = λ/u."),
    )

