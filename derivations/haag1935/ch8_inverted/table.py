"""Haag 1935, chapter VIII, n°100–103: the Results of the inverted blade."""
from __future__ import annotations

import functools

import mpmath as mp

from pendsym import checks
from pendsym.result import Spec

from ..ch7_gravity.checks_gravity import C_values, along_blade, g_correction, inverse_eps, order, sensitivity
from ..common import READ_VW, rid, src
from ..ch7_gravity.kernels import C_INVERTED_KERNEL, G_INVERTED_KERNEL
from ..ch7_gravity.printed import FATIGUE_DEFS, READ_X
from ..symbols import lam, omega, u
from . import derivation, printed, truth

A_FAR = "-1"          # a (m) at which the lower ends of the windows are found (they do not depend on a)


@functools.lru_cache(maxsize=8)
def lower(dps: int) -> mp.mpf:
    return truth.lower_end("8.99", dps, A_FAR)


def window_points(level, dps):
    """The lower end of the window n = 1 (β1 = 0) from the eigenproblem: 2x1, x1, and (2x1)²/(π/2)² in P."""
    end = lower(dps)
    yield checks.Point("2x1: 1/n'² = 0", {}, end, component=0)


def x1_points(level, dps):
    end = lower(dps)
    yield checks.Point("x1", {}, end / 2, component=0)
    yield checks.Point("x1 − π", {}, end / 2 - mp.pi, component=1)


def weight_points(level, dps):
    end = lower(dps)
    yield checks.Point("(2x1)²/(π/2)²", {}, (end / (mp.pi / 2)) ** 2, component=0)


@functools.lru_cache(maxsize=8)
def upper(guess: str, dps: int) -> mp.mpf:
    return truth.far_upper_end(guess, dps)


def ends_points(level, dps):
    """The ends of the windows n = 1 and n = 0 from the model: 2x1 where 1/n'² = 0 (β1 = 0), and the upper ends as
    a → −∞, where S00 = 1/β1 of the direct stiffness vanishes (det K/((mg)²a) → S00)."""
    yield checks.Point("2x1: 1/n'² = 0", {}, lower(dps), component=0)
    yield checks.Point("3π: S00 = 0", {}, upper("9.42", dps), component=1)
    yield checks.Point("π: S00 = 0", {}, upper("3.14", dps), component=2)


def values(quantity, what, **kw):
    return checks.Values(truth=f"{truth.truth.MODEL}; {what}", points=quantity,
                         confirm=lambda dps: {"2x1": lower(dps)}, **kw)


def specs() -> tuple[Spec, ...]:
    return (
        Spec(rid(304, "existence"), "both vibrations exist iff β1 < 0 (304) and a + wλ < 0 (305), g < 0", src(100, "304–305"),
             r"(\beta_1, a + w_\lambda) < 0", derivation.potential_coefficients, printed=printed.existence,
             readings=(READ_VW,), check=truth.ExistenceIff(),
             note="Derived as the coefficients of Y², θ² in V/(mg) (footnote of n°100); (302), (303) are steps of "
                  "the same reasoning and (306) is (305) with a > 0."),
        Spec(rid(307, "beta1"), "β1 = λ(1 − 2 tan(u/2)/u), inverted uniform blade", src(101, "307"), r"\beta_1",
             derivation.by_rotation(159, "beta1"), deps=(rid(159, "beta1"),), printed=printed.beta1,
             check=truth.on_u(truth.beta1, "β1 = 1/S00 of the direct stiffness", ("1/2", "1", "5/2", "46/5"))),
        Spec(rid(309, "windows"), "windows 2x_n < u < (2n + 1)π: ends 2x1, 3π, π", src(101, "309"),
             r"(2x_1, 3\pi, \pi)", derivation.windows_309, printed=printed.windows,
             defs=((printed.windows()[0].args[1], derivation.x1_of_308()),),
             check=checks.All((
                 checks.Values(truth=f"{truth.truth.MODEL}; the lower end where 1/n'² crosses zero, the upper ends "
                                     "as a → −∞ where S00 = 1/β1 of the direct stiffness vanishes (mpmath findroot)",
                               points=ends_points, confirm=lambda dps: {"2x1": lower(dps), "3pi": upper("9.42", dps)},
                               tol="1e-20"),
                 truth.WindowSigns())),
             note="The upper end of a window at a fixed a (the slow n² crossing zero at a = a1(u)) tends to (2n + 1)π "
                  "only as a → −∞: it is checked there, as the zero of S00 (det K = (mg)²[S00(S11 + a) − S01S10]); "
                  "and the signs of both n² at a = a1 − 1 m are checked at weight ratios inside and outside."),
        Spec(rid(309, "x1"), "x1 ≈ 4,49, x1 − π ≈ 1,35", src(101, None), r"(x_1, x_1 - \pi)", derivation.x1_values,
             printed=printed.x1_numbers, readings=(printed.READ_COMMA,), printed_decimals=(2, 2),
             check=values(x1_points, "x1 = half the lower end of the window n = 1", tol="1e-20"),
             note="The printed numbers are rounded (4.4934…, 1.3518…)."),
        Spec(rid(309, "weights"), "windows in weights: 4P, 32,7P–36P", src("footnote of n°102", None),
             r"(mg_{2x_1}, mg_{3\pi}, mg_{\pi})/P", derivation.weights_309, deps=(rid(309, "windows"),),
             printed=printed.weights, readings=(printed.READ_COMMA,), printed_decimals=(1, 0, 0),
             check=values(weight_points, "(2x1/(π/2))², 2x1 of the eigenproblem", tol="1e-20"),
             note="32.7 is 32.73… rounded; 36 and 4 are exact ((3π)², π² over (π/2)²)."),
        Spec(rid(310, "a1"), "a1 = λ/(u tan u), inverted uniform blade", src(101, "310"), "a_1", derivation.a1_310,
             deps=(rid(159, "wl"),), printed=printed.a1,
             check=truth.on_u(truth.critical, "a1 where det K = 0 (direct stiffness)")),
        Spec(rid(311, "weight"), "mg < π²Ee³h/(48λ²)", src(101, "311"), "mg", derivation.weight_311,
             deps=(rid(156, "u"),), printed=printed.weight, check=truth.largest_weight(),
             note="The truth is the u where a1 of the direct stiffness vanishes (a > 0 possible below), by findroot."),
        Spec(rid(313, "v0"), "v0 = −vλ = (λ/u) tan(u/2)", src(103, "313"), "v_0", derivation.by_rotation(159, "v0"),
             deps=(rid(159, "v0"),), printed=printed.v0, readings=(READ_VW,),
             check=truth.on_u(truth.shot_end("v0"), "v0 of the shot blade", model=truth.SHOT)),
        Spec(rid(313, "w0"), "w0 = −λ/(u sin u)", src(103, "313"), "w_0", derivation.by_rotation(159, "w0"),
             deps=(rid(159, "w0"),), printed=printed.w0, readings=(READ_VW,),
             check=truth.on_u(truth.shot_end("w0"), "w0 of the shot blade", model=truth.SHOT)),
        Spec(rid(313, "wl"), "wλ = −λ/(u tan u)", src(103, "313"), r"w_\lambda", derivation.by_rotation(159, "wl"),
             deps=(rid(159, "wl"),), printed=printed.wl, readings=(printed.READ_313, READ_VW),
             check=truth.on_u(truth.shot_end("wl"), "wλ of the shot blade", model=truth.SHOT)),
        Spec(rid(314, "G"), "G = (1/sin²u + cot u/u)/(2ε), inverted", src(103, "314"), "G", derivation.G_314,
             deps=(rid(263, "G"),), printed=printed.G,
             check=order(sensitivity, "εG, G = −d log n²/d log |g| (stencil), a = a1 − ελ", 1, "u=1",
                         sign=-1, scale=inverse_eps), kernel=G_INVERTED_KERNEL),
        Spec(rid(315, "dg"), "dg/g correction per degree, inverted uniform blade", src(103, "315"), r"\frac{dg}{g}",
             derivation.by_rotation(272, "dg"), deps=(rid(272, "dg"),), printed=printed.dg,
             check=order(g_correction, "dg/g = −(2/G)dT/T of the inverted blade (g < 0), both from the truth", 1,
                         "u=1", sign=-1)),
        Spec(rid(316, "shape"), "ωy = θ(1 − cos ωx)/sin u", src(103, "316"), r"\omega y", derivation.shape_316,
             deps=(rid(278, "shape"),), printed=printed.shape, defs=((omega, u / lam),), readings=(READ_X,),
             check=along_blade("ωy", "shape", "u=1", sign=-1)),
        Spec(rid(316, "fatigue"), "T' = θ√(3E|T|) cos ωs/sin u (n°103, after (316))", src(103, None), "T'",
             derivation.fatigue_inverted, deps=(rid(280, "fatigue"),), printed=printed.fatigue, defs=FATIGUE_DEFS,
             check=along_blade("the bending stress E(e/2)φ'", "stress", "u=1", sign=-1),
             note="Printed as an instruction ('remplacer ch ωs par cos ωs [OCR: ch read cos] et sh u par sin u'); "
                  "the transcription applies it to (280)."),
        Spec(rid(34, "n2_inverted"), "n² = −Kgz/R² of the inverted uniform blade ((34), (36), (30), u → iu, g → −g)",
             src(101, None), "n^2", derivation.n2_inverted, deps=(rid(159, "vl"), rid(159, "beta1"), rid(159, "wl")),
             check=truth.n2_check(),
             note="Not printed: n°101's rule (chapter III's formulas hold with u → iu, and g → −g, n°100) applied to "
                  "(34) n² = −Kg/z', (36) K and (30) z of n°50, as the scenes need it (the period of an inverted-blade "
                  "gravity meter).  It is the mode whose node is z' < 0: near a1 the slow one; n² is proportional to "
                  "a1 − a (310)."),
        Spec(rid(317, "C"), "C = (3/8)(4u − sin 4u)/(sin²u(2u + sin 2u)), inverted", src(103, "317"), "C",
             derivation.C_317, printed=printed.C, check=C_values(-1), kernel=C_INVERTED_KERNEL,
             note="Derived from dsolve with M < 0 (circular functions), not by u → iu."),
    )
