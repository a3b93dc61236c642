"""Haag 1935, chapter I, n°1–4, eqs. (1)–(20): the Results, joining derivation, print and truth."""
from __future__ import annotations

import sympy as sp

from pendsym import checks
from pendsym.result import Spec
from .. import profiles
from ..common import READ_VW, rid, src, step
from ..symbols import M1, M2, mu, vl, w0, wl
from . import derivation, printed, truth
from .printed import INSTANCES, READ_4, READ_5

W0_BY_16 = ((w0, vl + wl),)                 # (16), applied to both forms
M2_BY_MU = ((M2, mu * M1),)            # μ = M2/M1


def same_as_printed(statement: str, printed_form) -> checks.Proof:
    return checks.Proof(statement, holds=lambda derived: sp.simplify(derived - printed_form()) == 0)


def claim(eq: int, name: str, title: str, lhs: str, derive, printed_form, what: str, readings=(READ_VW,),
          **extra) -> Spec:
    """An inequality of n°3: the quantity the memoir claims positive, on every blade."""
    return Spec(rid(eq, name), title, src(3, str(eq)), lhs, step(derive), printed=printed_form, readings=readings,
                check=profiles.positive_on_blades(what), **extra)


def specs() -> tuple[Spec, ...]:
    definition = {"definition": True, "check": checks.Definition()}
    return (
        # ---------------------------------------------------------------- n°1
        Spec(rid(1, "M"), "M = EI/(mg)", src(1, "1"), "M", step(derivation.stiffness_ratio), printed=printed.eq1,
             **definition),
        Spec(rid(2, "bending"), "M dφ/ds = N + (α − x)Y − (β − y)X (plane bending)", src(1, "2"),
             r"M\varphi' - [N + (\alpha - x)Y - (\beta - y)X]", step(derivation.bending_law), printed=printed.eq2,
             instances=INSTANCES, note="Governing equation (bending law).", **definition),
        Spec(rid(3, "dx"), "dx/ds = cos φ", src(1, "3"), "x'", step(derivation.slope_x), printed=printed.eq3_dx,
             instances=INSTANCES, **definition),
        Spec(rid(3, "dy"), "dy/ds = sin φ", src(1, "3"), "y'", step(derivation.slope_y), printed=printed.eq3_dy,
             instances=INSTANCES, **definition),
        Spec(rid(4, "gx"), "theorem of the centre of gravity, along Ox", src(1, "4"),
             r"m\alpha'' - ma\theta'^2\cos\theta - ma\theta''\sin\theta - mg(1 - X)",
             step(lambda: derivation.centre_of_gravity(0)), printed=printed.eq4, readings=(READ_4,),
             check=same_as_printed("(4) ≡ m x_G'' − mg(1 − X) with x_G = α + a cos θ", printed.eq4),
             note="Derived by differentiating x_G = α + a cos θ twice in t."),
        Spec(rid(5, "gy"), "theorem of the centre of gravity, along Oy", src(1, "5"),
             r"m\beta'' - ma\theta'^2\sin\theta + ma\theta''\cos\theta + mgY",
             step(lambda: derivation.centre_of_gravity(1)), printed=printed.eq5, readings=(READ_5,),
             check=truth.NewtonEulerModes(5),
             note="Derived from y_G = β + a sin θ; checked with (6) against the eigenproblem of the suspension."),
        Spec(rid(6, "moment"), "theorem of the angular momentum about G", src(1, "6"),
             r"\frac{R^2}{g}\theta'' + N - a(Y\cos\theta - X\sin\theta)", step(derivation.angular_momentum),
             printed=printed.eq6, check=truth.NewtonEulerModes(6),
             note="Derived: moment about G of the couple −mgN and of (−mgX, −mgY) applied at A − G "
                  "= −a(cos θ, sin θ)."),
        # ---------------------------------------------------------------- n°2
        Spec(rid(7, "dbending"), "d/ds(Mφ') = X sin φ − Y cos φ", src(2, "7"), r"\frac{d}{ds}(M\varphi')",
             step(derivation.differentiated_bending), printed=printed.eq7, instances=INSTANCES,
             check=same_as_printed("d/ds of the right side of (2), with (3), minus the printed right side of (7)",
                                   printed.eq7)),
        Spec(rid(8, "linear"), "d/ds(Mφ') = φ − Y (small oscillations)", src(2, "8"), r"\frac{d}{ds}(M\varphi')",
             step(derivation.linearised_bending), printed=printed.eq8, instances=INSTANCES,
             check=truth.IntegratedBending(), note="First-order part of (7) with φ, Y = O(ε), X = 1 + O(ε²)."),
        Spec(rid(9, "v"), "M v'' − v = 0", src(2, "9"), "Mv'' - v", step(derivation.equation_of_v),
             printed=printed.eq9, instances=INSTANCES, **definition),
        Spec(rid(10, "bc"), "v'_0 = v'_λ = −1, w'_0 = 0, w'_λ = 1", src(2, "10"),
             r"(v'_0, v'_\lambda, w'_0, w'_\lambda)", step(derivation.end_slopes), printed=printed.eq10,
             definition=True, check=checks.Definition()),
        Spec(rid(11, "phi12"), "φ1 = 1 + v', φ2 = w'", src(2, "11"), r"(\varphi_1, \varphi_2)",
             step(derivation.phi1_phi2), printed=printed.eq11, definition=True, check=checks.Definition()),
        Spec(rid(12, "ends"), "φ10 = φ1λ = 0, φ20 = 0, φ2λ = 1", src(2, "12"),
             r"(\varphi_{10}, \varphi_{1\lambda}, \varphi_{20}, \varphi_{2\lambda})", step(derivation.phi_end_values),
             printed=printed.eq12, check=truth.end_values_12(),
             note="Checked on the shot φ1, φ2 (a check of the shooting against (10)–(11))."),
        Spec(rid(13, "phi"), "φ = Yφ1 + θφ2", src(2, "13"), r"\varphi", step(derivation.phi_solution),
             printed=printed.eq13,
             check=truth.deflection(1, "its φ(s) for the end position (0.3λ, −0.7) and its end load Y"),
             note="Y·φ1(s) + θ·φ2(s) with the shot φ1, φ2 against the directly solved φ(s), at s = 0, 0.37λ, 0.81λ, λ "
                  "(so also φ_0 = 0, φ_λ = θ)."),
        Spec(rid(13, "satisfies8"), "φ = Yφ1 + θφ2 satisfies (8) for all Y, θ", src(2, "13"),
             r"\frac{d}{ds}(M\varphi') - (\varphi - Y)", step(derivation.eq8_residual), printed=printed.eq13_satisfies8,
             check=truth.solution_residual(("0.37", "0.81"),
                                           "d/ds(Mφ') − (φ − Y) = 0 for φ = Y(1 + v') + θw' with Mv'' = v, Mw'' = w"),
             note="'On vérifie aisément que cette fonction satisfait à l'équation (8)': symbolic proof, and the shot φ "
                  "against the directly solved blade at interior points."),
        Spec(rid(13, "phi_ends"), "φ_0 = 0, φ_λ = θ", src(2, "13"), r"(\varphi_0, \varphi_\lambda)",
             step(derivation.phi_ends), printed=printed.eq13_ends,
             check=truth.solution_ends("φ(0) = 0 and φ(λ) = θ from (10), (11), (13)"),
             note="Numerically: (0, θ) against the suspension's φ at s = 0, λ."),
        Spec(rid(14, "phip"), "φ' = (Yv + θw)/M", src(2, "14"), r"\varphi'", step(derivation.phi_prime_at_point),
             printed=printed.eq14, readings=(READ_VW,),
             check=truth.deflection(2, "its φ'(s) for the end position (0.3λ, −0.7)"),
             note="v_s, w_s, M_s stand for v(s), w(s), M(s)."),
        # ---------------------------------------------------------------- n°3
        Spec(rid(15, "wronskian"), "v w' − w v' = w0", src(3, "15"), r"vw' - wv'", step(derivation.wronskian),
             printed=printed.eq15, readings=(READ_VW,), check=truth.wronskian_15(),
             note="Derived: d/ds(vw' − wv') = vw'' − wv'' = 0 by (9) (ch1_model), the constant at s = 0 by (10)."),
        Spec(rid(16, "w0"), "vλ + wλ = w0", src(3, "16"), "w_0", step(derivation.wronskian_at_lambda),
             printed=printed.eq16, readings=(READ_VW,), check=truth.shot_value("w_0", "w(0)")),
        claim(17, "v0_pos", "v0 > 0", "v_0 > 0", derivation.v0_positive, printed.eq17_v0, "v0"),
        claim(17, "w0_pos", "w0 > 0", "w_0 > 0", derivation.w0_positive, printed.eq17_w0, "w0"),
        claim(17, "wl_gt_w0", "wλ > w0", r"w_\lambda - w_0 > 0", derivation.wl_minus_w0, printed.eq17_wl_gt_w0,
              "wλ − w0"),
        claim(17, "beta1_pos", "β1 = λ + vλ − v0 > 0", r"\beta_1 > 0", derivation.beta1_def, printed.eq17_beta1, "β1"),
        claim(17, "vl_neg", "vλ < 0", r"-v_\lambda > 0", derivation.minus_vl, printed.eq17_vl, "−vλ"),
        claim(17, "beta1_lt", "β1 < λ", r"\lambda - \beta_1 > 0", derivation.lam_minus_beta1, printed.eq17_beta1_lt,
              "λ − β1", readings=()),
        claim(17, "v0_lt", "v0 < λ", r"\lambda - v_0 > 0", derivation.lam_minus_v0, printed.eq17_v0_lt, "λ − v0"),
        claim(17, "vl_gt", "−vλ < λ", r"\lambda + v_\lambda > 0", derivation.lam_plus_vl, printed.eq17_vl_gt, "λ + vλ"),
        Spec(rid(18, "integral"), "v0/w0 − vλ/wλ = ∫ w0/w² ds", src(3, "18"), r"\int_0^\lambda w_0/w^2\,ds",
             step(derivation.ratio_integral), printed=printed.eq18_integral, readings=(READ_VW,),
             check=truth.quadrature(lambda shot, x, env: env["w_0"] / shot.w(x) ** 2, "w0/w²"),
             note="The equality before (18): derived from (15), d/ds(v/w) = −w0/w²."),
        claim(18, "step0", "v0/w0 − vλ/wλ > λw0/wλ²",
              r"\frac{v_0}{w_0} - \frac{v_\lambda}{w_\lambda} - \frac{\lambda w_0}{w_\lambda^2} > 0",
              derivation.step0_of_18, printed.eq18_step0, "v0/w0 − vλ/wλ − λw0/wλ²"),
        claim(18, "first", "β1wλ + vλ² < −λvλ(1 + w0/wλ)",
              r"-\lambda v_\lambda(1 + w_0/w_\lambda) - (\beta_1 w_\lambda + v_\lambda^2) > 0",
              derivation.first_of_18, printed.eq18_first, "the first inequality of (18)", defs=W0_BY_16,
              note="Derived: the inequality before (18) times w0wλ, with (16) (w0 = vλ + wλ, applied to both forms) "
                   "and β1 of (17)."),
        claim(18, "second", "−λvλ(1 + w0/wλ) < −2λvλ",
              r"-2\lambda v_\lambda + \lambda v_\lambda(1 + w_0/w_\lambda) > 0",
              derivation.second_of_18, printed.eq18_second, "the second inequality of (18)"),
        claim(18, "third", "−2λvλ < 2λ²", r"2\lambda^2 + 2\lambda v_\lambda > 0", derivation.third_of_18,
              printed.eq18_third, "the third inequality of (18)"),
        Spec(rid(19, "unit"), "∫ w/M ds = 1", src(3, "19"), r"\int_0^\lambda w/M\,ds", step(derivation.unit_integral),
             printed=printed.eq19_unit, readings=(READ_VW,),
             check=truth.quadrature(lambda shot, x, env: shot.w(x) / shot.M_at(x), "w/M")),
        claim(19, "M1", "M1 < λwλ", r"\lambda w_\lambda - M_1 > 0", derivation.M1_below, printed.eq19_M1,
              "λwλ − min M"),
        claim(19, "M2", "M2 > λw0", r"M_2 - \lambda w_0 > 0", derivation.M2_above, printed.eq19_M2, "max M − λw0"),
        claim(19, "lower", "λw0/μ < M (at the minimum M1 of M)", r"M_1 - \lambda w_0/\mu > 0", derivation.lower_of_19,
              printed.eq19_lower, "min M − λw0/μ", defs=M2_BY_MU),
        claim(19, "upper", "M < λμwλ (at the maximum M2 of M)", r"\lambda\mu w_\lambda - M_2 > 0",
              derivation.upper_of_19, printed.eq19_upper, "λμwλ − max M", defs=M2_BY_MU),
        # ---------------------------------------------------------------- n°4
        Spec(rid(20, "vl"), "vλ = −v0 (symmetric blade)", src(4, "20"), r"v_\lambda", step(derivation.symmetric_vl),
             printed=printed.eq20_vl, readings=(READ_VW,), check=truth.symmetric("v_lambda")),
        Spec(rid(20, "beta1"), "β1 = λ − 2v0 (symmetric blade)", src(4, "20"), r"\beta_1",
             step(derivation.symmetric_beta1), printed=printed.eq20_beta1, readings=(READ_VW,),
             check=truth.symmetric("beta_1")),
        Spec(rid(20, "wl"), "wλ = w0 + v0 (symmetric blade)", src(4, "20"), r"w_\lambda", step(derivation.symmetric_wl),
             printed=printed.eq20_wl, readings=(READ_VW,), check=truth.symmetric("w_lambda")),
    )
