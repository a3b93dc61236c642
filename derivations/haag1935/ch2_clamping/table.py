"""Haag 1935, chapter II, n°31–35, eqs. (116)–(134): the Results, joining derivation, print and truth."""
from __future__ import annotations

import sympy as sp

from pendsym import checks
from pendsym.result import Spec
from ..ch2_common import h_127, h_132
from ..common import rid, src, step
from . import derivation, printed, truth
from .printed import READ_129_2, READ_129_THETA1, READ_BETA1, READ_DELTA_F, READ_H_TWICE, READ_J_PRIME

PERIOD = rid(134, "dT")
# the Results whose checks solve the same tilted blades (scheduled together)
TILT_RESULTS = (rid(116, "first_order"), rid(117, "loads"), rid(117, "j"), rid(117, "h"), rid(118, "j_prime"),
                rid(129, "f"), rid(132, "delta_f"), rid(133, "sum"), PERIOD)
THROUGH_PERIOD = checks.Chain((PERIOD,))
EXACT = "symbolic proof (SymPy)"
DEF_H = ((h_127, printed.eq127()), (h_132, printed.eq132()))      # (127), (132) in moments


def _equals(target):
    return lambda expr: sp.simplify(sp.expand(expr - target)) == 0


def specs() -> tuple[Spec, ...]:
    return (
        # ---------------------------------------------------------------- n°31
        Spec(rid(116, "eps"), "ε1, ε2, ε3 of the clamping errors i, i'", src(31, "116"),
             r"(\varepsilon_1, \varepsilon_2, \varepsilon_3)", step(derivation.eq116), printed=printed.eq116,
             check=checks.All(tuple(truth.errors_order(k) for k in range(3)),
                              truth="the exact tilted (4)–(6) with mpmath's sin and cos"),
             note="The tilted (4)–(6) (gravity g(cos i, −sin i) in the blade's axes, x_G = α + a cos(θ + i')) minus "
                  "the untilted, to the second order in i, i'."),
        Spec(rid(116, "first_order"), "the first-order terms in i, i' do not change the period", src(31, None),
             r"\frac{\Delta T}{T}\Big|_{i, i'}", step(derivation.first_order_odd_part),
             check=checks.All((checks.Proof("the bracket of (104) with the first-order (116) is even in "
                                            "(θ, θ', θ'', Y): its odd part is 0", truth=EXACT),
                               truth.order("period", 2)), truth="symbolic proof, and the exact tilted blade"),
             note="Derived form: the odd part (0); against the exact blade ΔT/T is of the second order in i."),
        # ---------------------------------------------------------------- n°32
        Spec(rid(117, "loads"), "X = 1, Y = −i, N = −a(θ + i + i') at the equilibrium", src(32, None),
             "(X, Y, N)", step(derivation.equilibrium_loads), printed=printed.loads,
             check=checks.All((truth.order("Y", 3, pick=1), truth.order("N", 3, pick=2)),
                              truth=truth.TILT_TRUTH),
             note="The tilted (4)–(6) at rest, to the first order; N against the exact N at the exact θ."),
        Spec(rid(117, "j"), "j = −[(a − vλ)i + ai']/(a − a1)", src(32, "117"), "j", step(derivation.eq117_j),
             printed=printed.eq117_j, check=truth.order("theta", 3),
             note="(23), (24) with the loads at rest, solved for θ; wλ = −a1 (41)."),
        Spec(rid(117, "h"), "h = −β1 i − vλ j", src(32, "117"), r"h_\beta", step(derivation.eq117_h),
             printed=printed.eq117_h, readings=(READ_H_TWICE,), check=truth.order("beta", 3),
             note="β from (23) with Y = −i; j of (117)."),
        Spec(rid(118, "j_prime"), "j' = i + j = (w0 i − ai')/(a − a1)", src(32, "118"), "j'",
             step(derivation.eq118), printed=printed.eq118, readings=(READ_J_PRIME,), check=truth.order("j'", 3),
             note="vλ = w0 − wλ (16), wλ = −a1 (41)."),
        # ---------------------------------------------------------------- n°33
        Spec(rid(119, "shift"), "θ = j + θ1, β = h + β1", src(33, "119"), r"(\theta, \beta)", step(derivation.eq119),
             printed=printed.eq119, readings=(READ_BETA1, READ_H_TWICE), check=checks.Definition(), definition=True),
        Spec(rid(120, "same_motion"), "in θ1, β1 the equations are (25), (26): θ1'' = −n²θ1", src(33, "120"),
             r"(25), (26)\ \text{in}\ (\tilde\beta_1, \theta_1)", step(derivation.eq120_residual),
             readings=(READ_BETA1,),
             check=checks.Proof("(25), (26) plus the first-order errors at (h + β1, j + θ1), minus (25), (26) at "
                                "(β1, θ1), β1 of (119): (0, 0) by (117)", holds=lambda e: all(sp.simplify(x) == 0 for x in e),
                                truth=EXACT)),
        Spec(rid(121, "beta1"), "β1 = −(a + z')θ1", src(33, "121"), r"\tilde\beta_1", step(derivation.eq121),
             printed=printed.eq121, readings=(READ_BETA1,),
             check=checks.Proof("(26) with θ1'' = −n²θ1, n² of (34), R² from (30) at z'", _equals(printed.eq121()),
                                truth=EXACT)),
        Spec(rid(122, "Y"), "Y = Kθ1 − i", src(33, "122"), "Y", step(derivation.eq122), printed=printed.eq122,
             check=checks.Proof("(23) at (h + β1, j + θ1) with (117), (121), (35), β1 of (119)", _equals(printed.eq122()),
                                truth=EXACT)),
        # ---------------------------------------------------------------- n°34
        Spec(rid(123, "eps12"), "θε1 and ε2, quadratic in i, j", src(34, "123"),
             r"(\theta\varepsilon_1, \varepsilon_2)",
             step(derivation.eq123), printed=printed.eq123, check=THROUGH_PERIOD,
             note="(116) at θ = j + θ1, Y = Kθ1 − i, θ'' = −n²θ1 (n²/g = −K/z'), linear in θ1, quadratic in i, i', j."),
        Spec(rid(124, "eps3"), "ε3 = (aθ1/2)[(1 − K)(i'² + 2i'j) + 2ii'] − ai'ΔX", src(34, "124"), r"\varepsilon_3",
             step(derivation.eq124), printed=printed.eq124, check=THROUGH_PERIOD),
        Spec(rid(125, "dX"), "ΔX = (Ka/z')i'θ1", src(34, "125"), r"\Delta X", step(derivation.eq125),
             printed=printed.eq125, check=THROUGH_PERIOD),
        Spec(rid(126, "euler"), "½(K∂H2/∂Y + ∂H2/∂θ) = θ1F2 + h", src(34, "126"),
             r"\tfrac12(K\partial_Y + \partial_\theta)H_2", step(derivation.eq126), printed=printed.eq126,
             check=checks.Proof("in moments along θ = j + θ1, Y = Kθ1 − i: θ1F2 plus (127)", _equals(printed.eq126()),
                                truth=EXACT)),
        Spec(rid(127, "h"), "h = ½(K∂H2/∂Y + ∂H2/∂θ) at Y = −i, θ = j", src(34, "127"), "h", step(derivation.eq127),
             printed=printed.eq127, readings=(READ_H_TWICE,), check=checks.Definition(), definition=True),
        Spec(rid(128, "eps1_H2"), "ε1·(126), quadratic part", src(34, "128"),
             r"\tfrac12\varepsilon_1(K\partial_Y + \partial_\theta)H_2",
             step(derivation.eq128), printed=printed.eq128, check=THROUGH_PERIOD),
        Spec(rid(129, "f"), "f of the clamping errors alone", src(34, "129"), "f", step(derivation.eq129),
             printed=printed.eq129, readings=(READ_129_THETA1, READ_129_2), check=truth.step_in_Q1("129"),
             note="−(n²/K)·the bracket of (104) with (123)–(128); judged with the derived Δf against the truth."),
        # ---------------------------------------------------------------- n°35
        Spec(rid(130, "alpha_dd"), "α'' = n²θ1h", src(35, "130"), r"\alpha''", step(derivation.eq130),
             printed=printed.eq130, check=THROUGH_PERIOD, note="(107) along the oscillation; moments as h (127)."),
        Spec(rid(130, "eps1"), "ε1 = (K/z')(aj + h)θ1", src(35, None), r"\varepsilon_1",
             step(derivation.eps1_isochronism), printed=printed.eps1_isochronism, check=THROUGH_PERIOD,
             note="ε1 of (106) with (130), linear in i, j."),
        Spec(rid(131, "dX_more"), "−Kf/n² increases by (Ka/z')i'(aj + h)θ1", src(35, "131"), r"-\frac{K}{n^2}\Delta f",
             step(derivation.eq131), printed=printed.eq131, check=THROUGH_PERIOD),
        Spec(rid(132, "bracket"), "(109) at Y = Kθ1 − i, θ = θ1 + j: the five terms and (h'/24)θ1", src(35, None),
             r"-\frac{K}{n^2}f_{(109)}", step(lambda: derivation.in_h(derivation.isochronism_bracket())),
             printed=printed.isochronism_bracket, check=THROUGH_PERIOD,
             note="The derived bracket of (109) (with (K/6)H3), moments rewritten in h (127), h' (132) and F_n."),
        Spec(rid(132, "hp"), "h' = [K²∂²H/∂Y² + 2K∂²H/∂Y∂θ + ∂²H/∂θ²] at Y = −i, θ = j", src(35, "132"), "h'",
             step(derivation.eq132), printed=printed.eq132, check=checks.Definition(), definition=True),
        Spec(rid(132, "delta_f"), "Δf of the mutual repercussion", src(35, None), r"\Delta f",
             step(derivation.eq132_delta_f), printed=printed.delta_f, readings=(READ_DELTA_F,),
             check=truth.step_in_Q1("delta_f"),
             note="−(n²/K)[(131) + the bracket of (109) at the shifted point]; judged with the derived (129)."),
        Spec(rid(133, "Q1"), "Q1 = a(i + i' + j)²/4 − aK(i' + j)²/2 − K(ai' + aj + h)²/(2z') + i²F2/4 − h'/48",
             src(35, "133"), "Q_1", step(derivation.eq133), printed=printed.eq133, check=THROUGH_PERIOD,
             note="Q1 = Kf/(2n²θ1), f = (129) + Δf (derived)."),
        Spec(rid(133, "sum"), "(129) + Δf gives f = (2Q1/K)n²θ1", src(35, None), "Q_1", step(derivation.eq133),
             printed=printed.q1_from_parts, readings=(READ_129_THETA1, READ_129_2, READ_DELTA_F),
             check=truth.order("period", 4, over_Q=True),
             note="Haag's 'en ajoutant ceci à (129)': Kf/(2n²θ1) from the derived f and from the printed (129) "
                  "and Δf."),
        Spec(rid(134, "dT"), "ΔT/T = Q1/Q", src(35, "134"), r"\frac{\Delta T}{T}", step(derivation.eq134),
             printed=printed.eq134, defs=printed.DEFS_134, check=truth.order("period", 4), show_values=True,
             note="f/(z − z') averaged by (114) along θ1 = θ0 cos φ; Q = K(z − z') (45); (133) applied to the "
                  "printed form. Against the period of the small oscillation about the exact tilted equilibrium."),
    )
