"""Haag 1935, chapter I, n°5–9, eqs. (21)–(41): the Results, joining derivation, print and truth."""
from __future__ import annotations

from pendsym import checks
from pendsym.result import Spec
from .. import profiles
from ..common import READ_VW, rid, src, step
from ..symbols import K, a, beta1, beta2, lam, v0, vl, w0, wl, zp
from . import derivation, printed, truth

BETA1_BY_17 = ((beta1, lam + vl - v0),)                # (17)
BETAS_BY_17_22 = BETA1_BY_17 + ((beta2, -vl),)          # (17), (22): applied to both forms where the text mixes them
K_BY_35 = ((K, -(a + zp - vl) / beta1),)                # (35), applied to the printed (34)
FOCI = "each focus z with the n² of the mode whose node is the other focus"
K_TRUTH = "K = −n²z'/g of the principal mode"


def shifted_product(env):
    return (env["a"] + env["z"] - env["v_lambda"]) * (env["a"] + env["z'"] - env["v_lambda"])


def K_of_modes(env):
    return -env["n^2"] * env["z'"] / env["g"]


def specs() -> tuple[Spec, ...]:
    return (
        # ---------------------------------------------------------------- n°5
        Spec(rid(21, "beta"), "β = ∫φ ds = Yβ1 + θβ2", src(5, "21"), r"\beta", step(derivation.beta_integral),
             printed=printed.eq21, defs=((beta1, lam + vl - v0), (beta2, wl - w0)),
             check=truth.loads("beta", "β for its end load Y")),
        Spec(rid(22, "beta1"), "β1 = λ + vλ − v0", src(5, "22"), r"\beta_1", step(derivation.beta1_def),
             printed=printed.eq22_beta1, readings=(READ_VW,), check=truth.loads("beta1", "β1 = 1/(∂Y/∂β)")),
        Spec(rid(22, "beta2"), "β2 = wλ − w0", src(5, "22"), r"\beta_2", step(derivation.beta2_unreduced),
             printed=printed.eq22_beta2, readings=(READ_VW,),
             check=truth.loads("beta2", "β2 = −(∂Y/∂θ)/(∂Y/∂β)")),
        Spec(rid(22, "beta2_vl"), "β2 = −vλ", src(5, "22"), r"\beta_2", step(derivation.beta2_def),
             printed=printed.eq22_beta2_vl, readings=(READ_VW,),
             check=truth.loads("beta2", "β2 = −(∂Y/∂θ)/(∂Y/∂β)")),
        Spec(rid(23, "Y"), "Y = (β + θvλ)/β1", src(5, "23"), "Y", step(derivation.Y_of_end), printed=printed.eq23,
             readings=(READ_VW,), check=truth.loads("Y", "its end load Y")),
        Spec(rid(24, "N_Y"), "N = M_λφ'_λ = Yvλ + θwλ", src(5, "24"), "N", step(derivation.end_couple),
             printed=printed.eq24_N_Y, readings=(READ_VW,), check=truth.loads("N", "its end couple N")),
        Spec(rid(24, "N"), "N = (βvλ + θ(vλ² + β1wλ))/β1", src(5, "24"), "N", step(derivation.N_of_end),
             printed=printed.eq24, readings=(READ_VW,), check=truth.loads("N", "its end couple N")),
        # ---------------------------------------------------------------- n°6
        Spec(rid(25, "motion"), "β'' + aθ'' = g(β2θ − β)/β1", src(6, "25"), r"\beta'' + a\theta''",
             step(derivation.motion_25), printed=printed.eq25, defs=BETAS_BY_17_22, check=truth.motion(25)),
        Spec(rid(26, "motion"), "R²θ'' = g[β(a − vλ) − θ(a(λ − v0) + vλ² + β1wλ)]/β1", src(6, "26"), r"R^2\theta''",
             step(derivation.motion_26), printed=printed.eq26, defs=BETAS_BY_17_22, readings=(READ_VW,),
             check=truth.motion(26), note="β1 = λ + vλ − v0 (17) applied to both forms for the comparison."),
        # ---------------------------------------------------------------- n°7
        Spec(rid(27, "y"), "y = β + (a + z)θ", src(7, "27"), "y", step(derivation.focal_ordinate),
             printed=printed.eq27, definition=True, check=checks.Definition()),
        Spec(rid(28, "focal"), "(n²/g)β1 = 1 − (z/R²)(a − vλ)", src(7, "28"),
             r"\frac{n^2}{g}\beta_1 - 1 + \frac{z}{R^2}(a - v_\lambda)", step(derivation.focal_28),
             printed=printed.eq28, check=truth.at_foci(FOCI, swap=True)),
        Spec(rid(29, "focal"), "(n²/g)(a + z)β1 = −β2 + (z/R²)[a(λ − v0) + vλ² + β1wλ]", src(7, "29"),
             r"\frac{n^2}{g}(a + z)\beta_1 + \beta_2 - \frac{z}{R^2}[\dots]", step(derivation.focal_29),
             printed=printed.eq29, defs=BETAS_BY_17_22, readings=(printed.READ_29,),
             check=truth.at_foci(FOCI, swap=True),
             note="Derived as the negative of ch1_model.focal_conditions()[1] (the same condition = 0)."),
        Spec(rid(30, "quadratic"), "z² + z(a² + aλ − R² − a(v0 + vλ) + vλ² + β1wλ)/(a − vλ) − R² = 0",
             src(7, "30"), r"z^2 + z\frac{\dots}{a - v_\lambda} - R^2", step(derivation.quadratic_30),
             printed=printed.eq30, defs=BETA1_BY_17, readings=(READ_VW,),
             check=truth.at_foci("both foci (nodes of the modes) are roots", swap=True),
             note="Monic quadratic in z: coefficients compared with (17) applied."),
        Spec(rid(31, "product"), "zz' = −R²", src(7, "31"), "zz'", step(derivation.product_31), printed=printed.eq31,
             check=truth.modes(lambda env: env["z"] * env["z'"], "product of the nodes of the two modes")),
        Spec(rid(32, "sum"), "(a − vλ)(z + z') + a² + aλ − R² − a(v0 + vλ) + vλ² + β1wλ = 0", src(7, "32"),
             r"(a - v_\lambda)(z + z') + \dots", step(derivation.sum_relation), printed=printed.eq32, defs=BETA1_BY_17,
             readings=(READ_VW,), check=truth.at_foci("z, z' = nodes of the two modes")),
        Spec(rid(33, "shifted"), "(a + z − vλ)(a + z' − vλ) = −β1(a + wλ)", src(7, "33"),
             r"(a + z - v_\lambda)(a + z' - v_\lambda)", step(derivation.product_shifted), printed=printed.eq33,
             readings=(READ_VW,),
             check=truth.modes(shifted_product, "(a + z − vλ)(a + z' − vλ) with the nodes of the two modes")),
        # ---------------------------------------------------------------- n°8
        Spec(rid(34, "n2"), "n² = −Kg/z'", src(8, "34"), "n^2", step(derivation.n2_of_focus), printed=printed.eq34,
             defs=K_BY_35, check=truth.modes(lambda env: env["n^2"], "n² of the principal mode (node z' = F')"),
             note="K of (35) applied to the printed form."),
        Spec(rid(35, "K"), "K = −(a + z' − vλ)/β1", src(8, "35"), "K", step(derivation.K_of_zp), printed=printed.eq35,
             readings=(READ_VW,), check=truth.modes(K_of_modes, K_TRUTH)),
        Spec(rid(36, "K"), "K = (a + wλ)/(a + z − vλ)", src(8, "36"), "K", step(derivation.K_of_z),
             printed=printed.eq36, readings=(READ_VW,), check=truth.modes(K_of_modes, K_TRUTH)),
        Spec(rid(37, "KKp"), "KK' = −(a + wλ)/β1", src(8, "37"), "KK'", step(derivation.K_product),
             printed=printed.eq37, readings=(READ_VW,),
             check=truth.modes(lambda env: env["n^2"] * env["z'"] * env["n'^2"] * env["z"] / env["g"] ** 2,
                               "K = −n²z'/g, K' = −n'²z/g of the two modes")),
        # ---------------------------------------------------------------- n°9
        Spec(rid(38, "upper"), "a + z' − vλ < 0", src(9, "38"), r"-(a + z' - v_\lambda) > 0",
             step(derivation.upper_38), printed=printed.eq38, readings=(READ_VW,),
             check=profiles.positive_on_modes("−(a + z' − vλ) with the node z' of the principal mode"),
             note="Derived as β1K (35): K > 0 with β1 > 0."),
        Spec(rid(39, "lower"), "a + z − vλ > 0", src(9, "39"), r"a + z - v_\lambda > 0", step(derivation.lower_39),
             printed=printed.eq39, readings=(READ_VW,),
             check=profiles.positive_on_modes("a + z − vλ with the node z of the parasitic mode"),
             note="Derived as −β1K' (K' of (35) with z' → z): K' < 0."),
        Spec(rid(40, "a_wl"), "a + wλ > 0", src(9, "40"), r"a + w_\lambda > 0", step(derivation.a_plus_wl_40),
             printed=printed.eq40, readings=(READ_VW,), check=profiles.positive_on_modes("a + wλ"),
             note="Derived from (33): −(38)·(39)/β1."),
        Spec(rid(41, "a1"), "a1 = −wλ (critical distance)", src(9, "41"), "a_1", step(derivation.critical_distance),
             printed=printed.eq41, readings=(READ_VW,), check=truth.critical_distance(),
             note="Truth: the a at which det K(a) = 0 for the suspension's stiffness (an n² crosses 0); n² signs "
                  "at a1 ± 1 cm and at a = −0.1 m."),
        Spec(rid(41, "unstable"), "for a < a1, (38) holds and (39) fails", src(9, "41"),
             r"a < a_1:\ a + z' - v_\lambda < 0,\ a + z - v_\lambda < 0", step(derivation.product_shifted),
             check=truth.UnstableBelow(), note="The derived form is (33); for a < a1 both factors are negative."),
        Spec(rid(41, "below_vl"), "−wλ < vλ", src(9, "41"), r"v_\lambda + w_\lambda > 0",
             step(derivation.wronskian_at_lambda), printed=printed.eq41_below_vl, readings=(READ_VW,),
             check=profiles.positive_on_blades("vλ + wλ (= w0 by (16))")),
    )
