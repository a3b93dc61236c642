"""Haag 1935, chapter V, n°64–67: the point pendulum, the point mass at the end of the blade, beats, (198)–(211)."""
from __future__ import annotations

from pendsym import checks
from pendsym.result import Spec

from ..common import READ_VW, rid, src
from ..symbols import a, vl
from . import derivation, printed, truth

UNIFORM_ENDS = (rid(159, "v0"), rid(159, "vl"), rid(159, "wl"), rid(159, "beta1"))


def specs() -> tuple[Spec, ...]:
    return (
        Spec(rid(198, "roots"), "Foci of the point pendulum (R = 0): z = 0 and z'", src(64, "198"), "(z, z')",
             derivation.roots_at_R_zero, printed=printed.roots_at_R_zero, defs=printed.BETA1_DEF,
             readings=(READ_VW,), check=truth.roots_check()),
        Spec(rid(199, "n2p"), "Pulsation of the parasitic vibration for R/a small", src(64, "199"), "n'^2",
             derivation.parasitic_n2, deps=(rid(198, "roots"),), printed=printed.parasitic_n2,
             defs=printed.BETA1_DEF, readings=(READ_VW,), check=truth.parasitic_check()),
        Spec(rid(198, "dR"), "For R = 0 the first term of (58) (dR/R) drops out", src(64, None), r"\partial(dT/T)/\partial(dR/R)",
             derivation.first_term_of_58, deps=(rid(58, "dT"), rid(198, "roots")), printed=printed.first_term_of_58,
             check=truth.log_period_R_order(), note="(58)'s dR/R coefficient with K of (36) at z = 0."),
        Spec(rid(200, "n2"), "Point mass at the end of the uniform blade (a = 0)", src(65, "200"), "n^2",
             derivation.point_mass_n2, deps=(rid(198, "roots"), *UNIFORM_ENDS), printed=printed.point_mass_n2,
             check=truth.point_mass_check()),
        Spec(rid(200, "thread"), "(200) at u = ∞: the simple pendulum of length λ", src(65, "after 200"), "n^2",
             derivation.point_mass_thread, deps=(rid(200, "n2"),), printed=printed.point_mass_thread,
             check=truth.point_mass_order("1/u")),
        Spec(rid(201, "n2"), "(200) for u small: n² = 3g/(λu²)", src(65, "201"), "n^2",
             derivation.point_mass_stiff, deps=(rid(200, "n2"),), printed=printed.point_mass_stiff,
             check=truth.point_mass_order("u")),
        Spec(rid(201, "elastic"), "(201): n² = Ee³h/(4λ³m), gravity gone", src(65, "201"), "n^2",
             derivation.point_mass_stiff_elastic, deps=(rid(201, "n2"), rid(156, "omega2")),
             printed=printed.point_mass_stiff_elastic, check=truth.point_mass_order("u")),
        Spec(rid(202, "a0"), "Equal periods: a = vλ", src(66, "202"), "a", derivation.critical_a,
             printed=printed.critical_a, readings=(READ_VW,), check=truth.critical_a_check()),
        Spec(rid(203, "motion"), "(25)–(26) at a = vλ: β'' + aθ'' (203) and R²θ'' (204)", src(66, "203–204"),
             r"(\beta'' + a\theta'', R^2\theta'')", derivation.decoupled_motion, deps=(rid(202, "a0"),),
             printed=printed.decoupled_motion, defs=((a, vl),), readings=(READ_VW, printed.READ_V0_IN_204),
             check=truth.decoupled_check(),
             note="(204): derived −g w0 θ ((16): vλ + wλ = w0); printed −g ν0 θ."),
        Spec(rid(205, "R0"), "R0 of equal periods", src(66, "205"), "R_0", derivation.equal_period_radius,
             deps=(rid(203, "motion"),), printed=printed.equal_period_radius, defs=printed.POSITIVE_ENDS,
             readings=(READ_VW, printed.READ_V0_IN_204), check=truth.equal_radius_check(),
             note="Derived √(β1 w0); printed √(β1 ν0). (211) prints √(β1/ω0), consistent with w0."),
        Spec(rid(206, "n0"), "Pulsation of the synchronous vibration n0² = g/β1", src(66, "206"), "n_0^2",
             derivation.synchronous_n2, deps=(rid(203, "motion"),), printed=printed.synchronous_n2,
             check=truth.synchronous_check()),
        Spec(rid(207, "rho"), "ρ of (207) (with εR = a − vλ)", src(67, "207"), r"\rho", derivation.rho_of,
             printed=printed.rho_of, defs=printed.BETA1_DEF, readings=(READ_VW, printed.READ_PLUS_R2),
             check=truth.rho_check(),
             note="Derived with −R² (from (30)); printed +R²: only −R² makes (30) read (208)."),
        Spec(rid(208, "quadratic"), "(30) near equal periods: z² + 2ρRz − R² = 0", src(67, "208"), "(208)",
             derivation.beat_quadratic, printed=printed.beat_quadratic,
             check=checks.Chain((rid(210, "f"),))),
        Spec(rid(209, "n2"), "n² = n0²(1 − εz/R)", src(67, "209"), "n^2", derivation.beat_n2,
             printed=printed.beat_n2, defs=printed.FREQUENCY_DEFS, check=truth.beat_n2_check()),
        Spec(rid(209, "F"), "Frequencies F, F' near equal periods", src(67, "209"), "(F, F')",
             derivation.beat_frequencies, deps=(rid(209, "n2"),), printed=printed.beat_frequencies,
             defs=printed.FREQUENCY_DEFS,
             check=checks.All((truth.beat_frequency_order(0), truth.beat_frequency_order(1)))),
        Spec(rid(210, "f"), "Beat frequency f = F' − F", src(67, "210"), "f", derivation.beat_frequency,
             deps=(rid(209, "F"), rid(208, "quadratic")), printed=printed.beat_frequency,
             defs=printed.FREQUENCY_DEFS, check=truth.beat_time_domain()),
        Spec(rid(211, "rho"), "ρ near equal periods", src(67, "211"), r"\rho", derivation.rho_near_equal_periods,
             deps=(rid(207, "rho"),), printed=printed.rho_near_equal_periods, defs=printed.RHO_211_DEFS,
             readings=(READ_VW,), check=truth.rho_order(),
             note="a0 = vλ, the critical value (202); R0 = √(β1w0) (205, derived)."),
    )
