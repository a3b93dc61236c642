"""Haag 1935, chapter IX, n°104–106, eqs. (321)–(333): the rectangular hole, joining derivation, print and truth."""
from __future__ import annotations

import sympy as sp

from pendsym import checks, verify
from pendsym.result import Spec

from ..common import READ_VW, rid, src
from ..symbols import lam, omega
from . import limits, rectangle_derivation as derivation, rectangle_printed as printed, rectangle_truth as truth
from .rectangle_printed import READ_G2, READ_LAMBDA

V0, W0 = rid(329, "v0"), rid(332, "w0")
DEFS = printed.definition()
NO_HOLE = "p = 0 and ω' = ω (n°104: “on retrouve les formules (313)”; n°105: “(314)”)"


def solves_piece(freq) -> checks.Proof:
    return checks.Proof(f"M f'' + f = 0 with M = 1/{freq}²",
                        holds=lambda e: sp.simplify(e.diff(derivation.s, 2) / freq**2 + e) == 0)


def same(statement: str, transcription) -> checks.Proof:
    return checks.Proof(statement, holds=lambda d: verify.exactly_equal(d, transcription()), truth="exact algebra")


def no_hole(name: str, exact_at_omega: bool = True) -> checks.All:
    """Haag's claim (p = 0 or ω' = ω gives the uniform blade), exactly, and the hole vanishing ω' → ω on the truth.
    For G_2 the exact proof at ω' = ω takes SymPy about 90 s: there the fitted order on the truth stands alone."""
    cases = ({derivation.p: 0}, {derivation.omega_p: omega}) if exact_at_omega else ({derivation.p: 0},)
    said = "at p = 0 and at ω' = ω" if exact_at_omega else "at p = 0"

    def holds(d):       # the uniform blade's dsolve runs when the check runs, not when the table is read
        uniform = limits.uniform(name)
        return all(verify.exactly_equal(d.subs(sub), uniform) for sub in cases)
    return checks.All((
        checks.Proof(f"{name} {said} equals the inverted uniform blade's (dsolve)", holds=holds),
        truth.uniform_limit(name)))


def specs() -> tuple[Spec, ...]:
    n104, n105, n106 = "n°104", "n°105", "n°106"
    rd = derivation
    return (
        Spec(rid(321, "v"), "v = A cos ωs + B sin ωs (s < s_0)", src(n104, "321"), "v",
             lambda deps: rd.pieces()[0], printed=printed.piece_321, readings=(READ_VW,), check=solves_piece(omega)),
        Spec(rid(322, "v"), "v = A' cos ω'(s − s_0) + B' sin ω'(s − s_0) (s_0 < s < s_1)", src(n104, "322"), "v",
             lambda deps: rd.pieces()[1], printed=printed.piece_322, readings=(READ_VW,),
             check=solves_piece(rd.omega_p)),
        Spec(rid(323, "A1"), "A' (v, v' continuous at s_0)", src(n104, "323"), "A'",
             lambda deps: rd.carried_constant("A'"), deps=(rid(321, "v"), rid(322, "v")), printed=printed.A1_323,
             check=checks.Chain((V0,))),
        Spec(rid(323, "B1"), "B' (v, v' continuous at s_0)", src(n104, "323"), "B'",
             lambda deps: rd.carried_constant("B'"), deps=(rid(321, "v"), rid(322, "v")), printed=printed.B1_323,
             check=checks.Chain((V0,))),
        Spec(rid(324, "v"), "v = A'' cos ω(s − s_1) + B'' sin ω(s − s_1) (s > s_1)", src(n104, "324"), "v",
             lambda deps: rd.pieces()[2], printed=printed.piece_324, readings=(READ_VW,), check=solves_piece(omega)),
        Spec(rid(324, "A2"), "A'' from A', B' (v, v' continuous at s_1)", src(n104, None), "A''",
             lambda deps: rd.across_s1("A''"), deps=(rid(322, "v"), rid(324, "v")), printed=printed.A2_of_A1,
             readings=(READ_LAMBDA,), check=checks.Chain((V0,))),
        Spec(rid(324, "B2"), "B'' from A', B' (v, v' continuous at s_1)", src(n104, None), "B''",
             lambda deps: rd.across_s1("B''"), deps=(rid(322, "v"), rid(324, "v")), printed=printed.B2_of_A1,
             readings=(READ_LAMBDA,), check=checks.Chain((V0,))),
        Spec(rid(325, "A2"), "A'' (v, v' continuous at s_1)", src(n104, "325"), "A''",
             lambda deps: rd.carried_constant("A''"), deps=(rid(323, "A1"), rid(323, "B1")), printed=printed.A2_325,
             readings=(READ_LAMBDA,), check=checks.Chain((V0,))),
        Spec(rid(325, "B2"), "B'' (v, v' continuous at s_1)", src(n104, "325"), "B''",
             lambda deps: rd.carried_constant("B''"), deps=(rid(323, "A1"), rid(323, "B1")), printed=printed.B2_325,
             readings=(READ_LAMBDA,), check=checks.Chain((V0,))),
        Spec(rid(326, "B"), "B = −1/ω (v'(0) = −1)", src(n104, "326"), "B", lambda deps: rd.constant("v", "B"),
             deps=(rid(325, "A2"), rid(325, "B2")), printed=printed.B_326, check=same("B = −1/ω", printed.B_326)),
        Spec(rid(327, "A"), "A of v (v'(λ) = −1)", src(n104, "327"), "A", lambda deps: rd.constant("v", "A"),
             deps=(rid(325, "A2"), rid(325, "B2")), printed=printed.A_327, defs=DEFS, readings=(READ_LAMBDA,),
             check=checks.Chain((V0,))),
        Spec(rid(328, "D"), "D, the denominator of (327)", src(n104, "328"), "D", lambda deps: rd.denominator(),
             deps=(rid(327, "A"),), printed=printed.D_definition,
             check=same("the denominator of the solved A, scaled to sin ωλ at p = 0, is the printed D",
                        printed.D_definition)),
        Spec(V0, "v_0 = A (rectangular hole)", src(n104, "329"), "v_0", lambda deps: rd.end_value("v", "0"),
             deps=(rid(327, "A"),), printed=printed.v0_329, defs=DEFS, readings=(READ_VW,),
             check=truth.on_rectangle("v0")),
        Spec(rid(329, "vl"), "v_λ (rectangular hole)", src(n104, "329"), r"v_\lambda", lambda deps: rd.end_value("v", "l"),
             deps=(rid(327, "A"),), printed=printed.vl_329, defs=DEFS, readings=(READ_VW,),
             check=truth.on_rectangle("vl")),
        Spec(rid(330, "v0"), "−v_λ = v_0 for a concentric hole (λ − s_1 = s_0)", src(n104, "330"), "v_0",
             lambda deps: rd.concentric(rd.end_value("v", "0")), deps=(V0,), printed=printed.v0_330,
             readings=(READ_VW,), check=truth.on_rectangle("v0", concentric=True), defs=((lam, 2 * rd.s0 + rd.p),),
             note="Compared under λ = 2s_0 + p (the printed form keeps λ)."),
        Spec(rid(331, "A"), "A = −1/(ωD) of w (B = 0)", src(n104, "331"), "A", lambda deps: rd.constant("w", "A"),
             deps=(rid(328, "D"),), printed=printed.A_331, defs=DEFS, check=checks.Chain((W0,))),
        Spec(W0, "w_0 (rectangular hole)", src(n104, "332"), "w_0", lambda deps: rd.end_value("w", "0"),
             deps=(rid(331, "A"),), printed=printed.w0_332, defs=DEFS, readings=(READ_VW,),
             check=truth.on_rectangle("w0")),
        Spec(rid(332, "wl"), "w_λ (rectangular hole)", src(n104, "332"), r"w_\lambda", lambda deps: rd.end_value("w", "l"),
             deps=(rid(331, "A"),), printed=printed.wl_332, defs=DEFS, readings=(READ_VW,),
             check=truth.on_rectangle("wl")),
        Spec(rid(332, "identity16"), "(16) w_0 = v_λ + w_λ holds (“on vérifie facilement”)", src(n104, "332"),
             r"w_0 - v_\lambda - w_\lambda", lambda deps: rd.identity_16(), deps=(V0, W0),
             check=checks.Proof("w_0 − v_λ − w_λ = 0", holds=lambda d: verify.exactly_equal(d, sp.Integer(0)))),
        *(Spec(rid(332, f"{name}_no_hole"), f"{name} → the uniform blade (313) when p = 0 or ω' = ω", src(n104, "332"),
               {"v0": "v_0", "w0": "w_0", "wl": r"w_\lambda"}[name],
               lambda deps, name=name: rd.end_value(name[0], name[1:]), deps=(V0, W0),
               check=no_hole(name), note=NO_HOLE) for name in ("v0", "w0", "wl")),
        # ---------------------------------------------------------------- n°105
        Spec(rid(333, "G2"), "G_2 = ∫ w²/M ds of the rectangular hole (2D²G_2 printed)", src(n105, "333"), "G_2",
             lambda deps: rd.G2(), deps=(rid(331, "A"),), printed=printed.G2_333, defs=DEFS, readings=(READ_G2,),
             check=truth.on_rectangle("G2")),
        Spec(rid(333, "G2_no_hole"), "G_2 → the uniform blade's when p = 0 or ω' = ω (cf. (314))", src(n105, "333"),
             "G_2", lambda deps: rd.G2(), deps=(rid(333, "G2"),), check=no_hole("G2", exact_at_omega=False), note=NO_HOLE),
        # ---------------------------------------------------------------- n°106, footnote
        Spec(rid(333, "stable_concentric"), "concentric hole: β_1 < 0 when ωλ < π/2 and ω'p < π/2 (n°106 footnote)",
             src(f"{n106}, footnote", None), r"-\beta_1 = v_0 - v_\lambda - \lambda",
             lambda deps: rd.end_value("v", "0") - rd.end_value("v", "l") - lam, deps=(V0, rid(329, "vl")),
             check=checks.Inequality(truth="−β_1 of the derived v_0, v_λ (verified against the shot blade) on a grid "
                                           "of concentric holes up to 0.9999 of both bounds", points=truth.stability_points),
             note="The stability conditions are (304) β_1 < 0 and (305) a < a_1; the footnote's bounds secure (304). "
                  "They do not secure a_1 = −w_λ > 0 ((306)): a narrow hole can make w_λ > 0 (e.g. ωλ = 0.3, "
                  "ω'p = 1, p = 0.3λ), so that a < a_1 then forbids a > 0."),
    )
