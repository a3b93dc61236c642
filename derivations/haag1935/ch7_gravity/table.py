"""Haag 1935, chapter VII, n°82–93: the Results of the gravity pendulum with direct suspension."""
from __future__ import annotations

import mpmath as mp
import sympy as sp

from pendsym import checks
from pendsym.result import Spec

from ..ch1_motion import truth as ch1_truth
from ..common import READ_VW, rid, src
from ..symbols import DEFS, a1, lam, u, wl
from . import derivation, kernels, printed
from .checks_gravity import (U_SMALL, C_values, along_blade, g_correction, inverse_eps, on, order, sensitivity,
                             suppleness, temperature, u_path)
from .symbols import eps, eps_p, l_syn, a_r

EPS_PRIME = ((eps_p, printed.eq258()),)
SYNCHRONOUS = ((l_syn, (derivation.R**2 + a_r**2) / a_r),)
TAPERED = "tapered"


def both(make):
    """The same order check on the uniform blade u = 2 and on chapter I's tapered blade (any M(s))."""
    return checks.All((make("u=2"), make(TAPERED)))


def scaled_eps(env):
    return env["varepsilon"]


def n2_scale(env):
    """g ε u⁴/λ: the size of n² as u → 0 (n° 86)."""
    return env["g"] * env["varepsilon"] * env["u"] ** 4 / env["lambda"]


def specs() -> tuple[Spec, ...]:
    N = lambda number: f"n°{number}"    # noqa: E731
    return (
        Spec(rid(255, "Q"), "Q = (a − a1)(z² + R²)/(z(z + a − vλ))", src(82, "255"), "Q", derivation.Q_255,
             deps=(rid(45, "Q"),), printed=printed.eq255, readings=(printed.READ_V1, READ_VW), defs=((a1, -wl),),
             check=ch1_truth.modes(lambda env: env["a"] + env["w_lambda"] + (env["n^2"] * env["z'"] / env["g"]) ** 2
                                   * env["beta_1"], "Q = a + wλ + K²β1 with K = −n²z'/g of the principal mode "
                                   "(chapter I naming, z the parasitic node)"),
             note="Chapter I naming (z: node of the parasitic mode), at the pendulums of chapter I."),
        Spec(rid(256, "epsilon"), "a − a1 = ελ", src(83, "256"), "a - a_1", lambda deps: eps * derivation.lam,
             printed=printed.eq256, definition=True, check=checks.Definition()),
        Spec(rid(257, "zp"), "z' = w0(1 + ε')", src(83, "257"), "z'", derivation.zp_257, printed=printed.eq257,
             defs=EPS_PRIME, readings=(READ_VW,),
             check=both(lambda key: order(on("z'"), "z' = node of the slow mode", 2, key))),
        Spec(rid(258, "epsilon_prime"), "ε' = ελ(β1w0 − w0² − R²)/(w0(w0² + R²))", src(83, "258"), "\\varepsilon'",
             derivation.epsilon_prime_258, printed=printed.eq258, readings=(READ_VW,),
             check=order(lambda env, *_: env["z'"] / env["w_0"] - 1, "(z' − w0)/w0, z' the slow node", 2, TAPERED)),
        Spec(rid(258, "ends"), "ε' = ελ(λ − v0 − wλ − R²/w0)/(w0² + R²)", src(83, "258"), "\\varepsilon'",
             derivation.epsilon_prime_258_ends, deps=(rid(258, "epsilon_prime"),), printed=printed.eq258_ends,
             readings=(READ_VW,),
             check=order(lambda env, *_: env["z'"] / env["w_0"] - 1, "(z' − w0)/w0, z' the slow node", 2, TAPERED)),
        Spec(rid(259, "z"), "z = −(R²/w0)(1 − ε')", src(83, "259"), "z", derivation.z_259, printed=printed.eq259,
             defs=EPS_PRIME, readings=(READ_VW,),
             check=both(lambda key: order(on("z"), "z = node of the fast mode", 2, key))),
        Spec(rid(260, "K"), "K = −ελw0/(w0² + R²)", src(83, "260"), "K", derivation.K_260, printed=printed.eq260,
             readings=(READ_VW,), check=both(lambda key: order(on("K"), "K = −n²z'/g of the slow mode", 2, key))),
        Spec(rid(260, "K_foci"), "K = ελ/(z − z')", src(83, "260"), "K", derivation.K_260_foci,
             deps=(rid(260, "K"),), printed=printed.eq260_foci,
             check=order(on("K"), "K = −n²z'/g of the slow mode; z, z' its nodes", 2, TAPERED)),
        Spec(rid(261, "Kp"), "K' = (z' − z)/β1", src(83, "261"), "K'", derivation.Kp_261, deps=(rid(260, "K_foci"),),
             printed=printed.eq261,
             check=both(lambda key: order(on("K'"), "K' = −n'²z/g of the fast mode; z, z' its nodes", 1, key))),
        Spec(rid(262, "G"), "G = G2/(ελ) (principal part)", src(84, "262"), "G", derivation.G_262,
             deps=(rid(62, "G"), rid(260, "K")), printed=printed.eq262,
             check=both(lambda key: order(sensitivity, "εG, G = −d log n²/d log g (stencil); G2(0) by "
                                          "quadrature", 1, key, scale=inverse_eps, with_energy=True)),
             note="Order check of εG (truth ε·G, formula ε·G2/(ελ)); G2 = ∫w²/M at K = 0, its ε → 0 value."),
        Spec(rid(262, "G_energy"), "G = 2W/(mgλε)", src(84, "262"), "G", derivation.G_262_energy,
             deps=(rid(262, "G"),), printed=printed.eq262_energy,
             check=order(sensitivity, "εG, W/(mg) = suspension.energy of the slow mode (θ = 1)", 1,
                         TAPERED, scale=inverse_eps, with_energy=True)),
        Spec(rid(263, "G"), "G = (U1² + U2/u)/(2ε), uniform blade", src(85, "263"), "G", derivation.G_263,
             deps=(rid(262, "G"), rid(166, "Gamma2")), printed=printed.eq263,
             check=order(sensitivity, "εG, G = −d log n²/d log g (stencil)", 1, "u=2", scale=inverse_eps,
                         with_energy=True), kernel=kernels.G_KERNEL),
        Spec(rid(264, "G"), "G = 1/(εu²), u small", src(85, "264"), "G", derivation.G_264, deps=(rid(263, "G"),),
             printed=printed.eq264,
             note="(263) is 1/(εu²)(1 + u⁴/45 + …); G − G2/Q = −1 is relative εu², made u⁸/100 by the path.",
             check=u_path(sensitivity, "εu²G along ε = u⁶/100", 4, lambda x: x**6 / 100,
                          lambda env: 1 / (env["varepsilon"] * env["u"] ** 2))),
        Spec(rid(264, "G_distance"), "G = −a/(a − a1), u small", src(85, "264"), "G", derivation.G_264_distance,
             deps=(rid(264, "G"), rid(159, "wl")), printed=printed.eq264_distance,
             check=u_path(sensitivity, "εu²G along ε = u⁶/100, a = a1 + ελ of the truth", 2,
                          lambda x: x**6 / 100, lambda env: 1 / (env["varepsilon"] * env["u"] ** 2)),
             note="Relative error u²/3 (a1 = −λ/u² − λ/3 + …): order 2 where 1/(εu²) has order 4."),
        Spec(rid(265, "n2"), "n² = εgλ/(R² + w0²)", src(86, "265"), "n^2", derivation.n2_265, deps=(rid(260, "K"),),
             printed=printed.eq265, readings=(READ_VW,),
             check=both(lambda key: order(on("n^2"), "n² of the slow mode", 2, key))),
        Spec(rid(266, "n2p"), "n'² = (g/β1)(1 + w0²/R²)", src(86, "266"), "n'^2", derivation.n2p_266,
             deps=(rid(261, "Kp"),), printed=printed.eq266, readings=(printed.READ_GPRIME, READ_VW),
             check=both(lambda key: order(on("n'^2"), "n'² of the fast mode", 1, key))),
        Spec(rid(267, "n2"), "n² = gελ/(R² + a²), u small", src(86, "267"), "n^2", derivation.n2_267_distance,
             deps=(rid(265, "n2"), rid(159, "w0"), rid(159, "wl")), printed=printed.eq267,
             check=u_path(on("n^2"), "n²/(gεu⁴/λ) along ε = u", 2, lambda x: x, n2_scale),
             note="w0 + a = −λ/2 + ελ + O(λu²): w0² → a² has relative error u²; the ε-correction of (265) is εu²."),
        Spec(rid(267, "n2_l"), "n² = gελ/(al), l = (R² + a²)/a", src(86, "267"), "n^2",
             derivation.n2_267_synchronous, deps=(rid(267, "n2"),), printed=printed.eq267_l, defs=SYNCHRONOUS,
             check=u_path(on("n^2"), "n²/(gεu⁴/λ) along ε = u", 2, lambda x: x, n2_scale)),
        Spec(rid(267, "n2_expanded"), "n² = g/l + gλ/(alu²) (+ gλ/(3al) derived)", src(86, "267"), "n^2",
             derivation.n2_267_expanded, deps=(rid(267, "n2_l"), rid(159, "wl")), printed=printed.eq267_expanded,
             defs=SYNCHRONOUS, readings=(printed.READ_GPRIME,),
             check=u_path(on("n^2"), "n²/(gεu⁴/λ) along ε = u, u from 1e-4 to 3.2e-3 (n'²/n² ~ 1e28: 60 digits)", 1, lambda x: x, n2_scale,
                          path=U_SMALL, dps=60),
             note="a1 = −wλ = −λ/u² − λ/3 − λu²/45 + … (159): the printed form keeps only −λ/u² and so drops −λ/3 "
                  "against ελ, a relative error 1/(3ε) that does not vanish as u → 0 (the printed order is negative). "
                  "The derived form keeps −λ/3; its remainder λu²/45 against ελ is u/45, of order 1 once u ≪ 1/45."),
        Spec(rid(268, "period"), "π²/T² = g/l + Ee³h/(12malλ) (+ gλ/(3al) derived)", src(86, "268"),
             r"\pi^2/T^2", derivation.period_268, deps=(rid(267, "n2_expanded"),), printed=printed.eq268,
             defs=SYNCHRONOUS, readings=(printed.READ_GPRIME, printed.READ_E2),
             check=u_path(on("n^2"), "π²/T² = n² over gεu⁴/λ along ε = u, u from 1e-4 to 3.2e-3; m = 1 kg, "
                          "e = 0.3 mm, h = 1 cm, E from EI = mgλ²/u² (156)", 1, lambda x: x, n2_scale, path=U_SMALL,
                          dps=60)),
        Spec(rid(270, "dT"), "dT/T per degree, ε → 0", src(87, "270"), r"\frac{dT}{T}", derivation.dT_270,
             deps=(rid(60, "dT"), rid(260, "K")), printed=printed.eq270,
             readings=(printed.READ_BETA, printed.READ_EPS, READ_VW),
             check=order(temperature, "εdT/T, d log T per degree by a 5-point stencil in the temperature (λ, M, a, R "
                                      "warmed)", 1, "u=2", scale=inverse_eps, with_energy=True)),
        Spec(rid(271, "dg"), "dg/g correction per degree", src(87, "271"), r"\frac{dg}{g}", derivation.dg_271,
             deps=(rid(270, "dT"), rid(262, "G")), printed=printed.eq271, readings=(printed.READ_BETA, READ_VW),
             check=order(g_correction, "dg/g = −(2/G)dT/T, both from the truth", 1, "u=2", with_energy=True)),
        Spec(rid(272, "dg"), "dg/g correction, uniform blade", src(87, "272"), r"\frac{dg}{g}", derivation.dg_272,
             deps=(rid(271, "dg"), rid(166, "Gamma2"), rid(159, "wl")), printed=printed.eq272,
             readings=(printed.READ_BETA,), defs=DEFS,
             check=order(g_correction, "dg/g = −(2/G)dT/T, both from the truth", 1, "u=2")),
        Spec(rid(273, "dg"), "dg/g = β + 3α − α', u small", src(87, "273"), r"\frac{dg}{g}", derivation.dg_273,
             deps=(rid(272, "dg"),), printed=printed.eq273, readings=(printed.READ_BETA,),
             check=u_path(g_correction, "dg/g = −(2/G)dT/T along ε = u⁴/10", 2, lambda x: x**4 / 10,
                          lambda env: 1),
             note="(272) = β + 3α − α' + (α − α')u²/3 + …: the u² term is small unless α − α' is not (brass rod)."),
        Spec(rid(278, "shape"), "ωy = θ(ch ωx − 1)/sh u", src(89, "278"), r"\omega y", derivation.shape_278,
             deps=(rid(157, "w"),), printed=printed.eq278, defs=((printed.omega, u / lam),), readings=(printed.READ_X,),
             check=along_blade("ωy", "shape", "u=2")),
        Spec(rid(280, "fatigue"), "T' = θ√(3ET) ch ωs/sh u", src(90, "280"), "T'", derivation.fatigue_280,
             deps=(rid(157, "w"),), printed=printed.eq280, defs=printed.FATIGUE_DEFS,
             check=along_blade("the bending stress E(e/2)φ'", "stress", "u=2"),
             note="T = mg/(eh) (n°51) is written Ee²u²/(12λ²) by (156) to compare the forms."),
        Spec(rid(82, "S_gravity"), "S = −1 as ε → 0 (n°91)", src(91, None), "S", derivation.S_91,
             deps=(rid(82, "S"), rid(260, "K")), printed=printed.suppleness_91,
             check=both(lambda key: order(suppleness, "S = W'/W of the slow mode: W = strain energy, W + W' = "
                                          "½ q·(Kq)", 1, key))),
        Spec(rid(285, "C"), "C of the uniform blade", src(93, "285"), "C", derivation.C_285,
             deps=(rid(284, "C_F2"), rid(158, "phi2"), rid(159, "wl")), printed=printed.C_285, check=C_values(1),
             kernel=kernels.C_KERNEL,
             note="C = (wλ − F4)/(wλ − F2) of (284) (eq284.C_F2, from (111) through (283)), F_n of (79) at K = 0."),
        Spec(rid(285, "C_exponential"), "C = (3/8)(sh 4u − 4u)/(sh²u(sh 2u + 2u))", src(93, "285"), "C",
             derivation.C_285_same, deps=(rid(285, "C"),), printed=printed.C_285_exponential, check=C_values(1)),
    )
