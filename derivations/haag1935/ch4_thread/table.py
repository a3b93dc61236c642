"""Haag 1935, chapter IV, n°58–63: the thread as the limit u → ∞ of the uniform blade, (184)–(197)."""
from __future__ import annotations

import mpmath as mp
import sympy as sp

from pendsym import checks, verify
from pendsym.result import Spec

from ..common import READ_VW, rid, src
from ..symbols import theta_ddot
from . import derivation, printed, truth
from .symbols import psi_ddot

CH3_ENDS = (rid(159, "v0"), rid(159, "vl"), rid(159, "w0"), rid(159, "wl"), rid(159, "beta1"), rid(159, "beta2"),
            rid(160, "U"), rid(160, "U1"), rid(160, "U2"))


def theta_acc(expr, env):
    """θ'' of the linear equations (190) at env (solved with ψ'')."""
    return _solve_linear(expr, env)[0]


def psi_acc(expr, env):
    return _solve_linear(expr, env)[1]


def _solve_linear(expr, env):
    rows = [sp.Poly(e, theta_ddot, psi_ddot) for e in expr]
    A = mp.matrix([[verify.value_at(r.coeff_monomial(v), env) for v in (theta_ddot, psi_ddot)] for r in rows])
    b = mp.matrix([-verify.value_at(r.coeff_monomial(1), env) for r in rows])
    return mp.lu_solve(A, b)


def combination_acc(expr, env):
    return verify.value_at(sp.solve(expr, theta_ddot)[0], env)


def specs() -> tuple[Spec, ...]:
    N58, N59, N60 = "n°58", "n°59", "n°60"
    mode_K = truth.modes_values(lambda name, env: -env["n^2"] * env["z'"] / env["g"],
                                "K = −n²z'/g (34) of the principal mode, z' its node")
    return (
        Spec(rid(184, "ends"), "Limits u → ∞ of v0, vλ, w0, wλ, β1, β2, U, U1, U2", src(N58, None),
             r"\lim (v_0, v_\lambda, w_0, w_\lambda, \beta_1, \beta_2, U, U_1, U_2)", derivation.ends_limits,
             deps=CH3_ENDS, printed=printed.ends, readings=(READ_VW,), check=truth.ends_check()),
        Spec(rid(184, "along"), "v, w → 0, φ1 → 1, φ2 → 0 inside the blade (0 < s < λ)", src(N58, None),
             r"\lim (v, w, \varphi_1, \varphi_2)", derivation.along_limits,
             deps=(rid(157, "v"), rid(157, "w"), rid(158, "phi1"), rid(158, "phi2")), printed=printed.along,
             readings=(READ_VW, printed.READ_PHI2), check=truth.along_check(),
             note="At the ends φ1 = 0 and φ2(λ) = 1 for every u: the conditions (12) of chapter I."),
        Spec(rid(184, "F"), "F_n → K^n λ (F_1/λ, F_2/λ; F = 4KF_3 − F_4 → 3K⁴λ)", src(N58, None),
             r"\lim (F_1, F_2, F)/\lambda", derivation.F_limits,
             deps=(rid(168, "F1"), rid(169, "F2"), rid(170, "F")), printed=printed.F_limits, check=truth.F_check(),
             note="The text states F_n → K^nλ; F's limit 3K⁴λ follows from it by (110)."),
        Spec(rid(184, "Gn"), "Asymptotic G_n of the thread", src(N58, "184"), "G_n", derivation.G_asymptotic,
             deps=(rid(164, "recurrence"),), printed=printed.G_asymptotic, readings=(printed.READ_G_EXPONENT,),
             check=truth.G_check(),
             note="Derived (u/λ)^{n−3}; printed (u/λ)^{n−1}. The memoir's next sentence (G_2 → 0) needs n − 3."),
        Spec(rid(185, "I_J"), "I_λ and J of the thread", src(N58, "185"), r"(I_\lambda, J)", derivation.I_J_limits,
             deps=(rid(182, "I"), rid(183, "J")), printed=printed.I_J, check=truth.I_J_check()),
        Spec(rid(186, "T"), "Kinetic energy of the body on a massless thread", src(N59, "186"), "2T",
             derivation.kinetic, printed=printed.kinetic, check=truth.energy_values("T")),
        Spec(rid(187, "U"), "Force function of the weight", src(N59, "187"), "U", derivation.force_function,
             printed=printed.force_function, check=truth.energy_values("U")),
        Spec(rid(188, "T"), "2T to the second order", src(N59, "188"), "2T", derivation.kinetic_quadratic,
             deps=(rid(186, "T"),), printed=printed.kinetic_quadratic, readings=(printed.READ_M_BRACKET,),
             check=truth.energy_order("T", 4.0)),
        Spec(rid(189, "U"), "U to the second order (constant dropped)", src(N59, "189"), "U",
             derivation.force_quadratic, deps=(rid(187, "U"),), printed=printed.force_quadratic,
             check=truth.energy_order("U", 4.0)),
        Spec(rid(190, "motion"), "Linear equations of the thread pendulum", src(N59, "190"), "(190)",
             derivation.linear_equations, deps=(rid(188, "T"), rid(189, "U")), printed=printed.linear_equations,
             readings=(printed.READ_ALPHA,),
             check=checks.All((truth.acceleration_order(0, theta_acc), truth.acceleration_order(1, psi_acc)))),
        Spec(rid(191, "combination"), "R²θ'' + ga(θ − ψ) = 0", src(N59, "191"), "(191)", derivation.combination,
             deps=(rid(190, "motion"),), printed=printed.combination, readings=(printed.READ_ALPHA,),
             check=truth.acceleration_order(0, combination_acc)),
        Spec(rid(30, "thread"), "The quadratic (30) of the foci for the thread (v0 = vλ = wλ = 0, β1 = λ)",
             src(N59, "30"), "(30)", derivation.foci_thread, deps=(rid(184, "ends"),),
             check=truth.nodes_on_quadratic()),
        Spec(rid(41, "thread"), "Critical distance a1 = 0 for the thread", src(N59, "41"), "a_1",
             derivation.critical_distance, deps=(rid(184, "ends"),), printed=printed.critical_distance,
             check=truth.critical_distance_check()),
        Spec(rid(193, "K"), "ψ = −(a + z')θ/λ = Kθ in the principal oscillation", src(N59, "193"), "K",
             derivation.K_thread, deps=(rid(184, "ends"),), printed=printed.K_thread, check=mode_K),
        Spec(rid(192, "n2"), "n² = −Kg/z' of the thread", src(N59, "34"), "n^2", derivation.n2_thread,
             deps=(rid(30, "thread"), rid(193, "K")),
             check=truth.modes_values(lambda name, env: env["n^2"], "the principal n²")),
        Spec(rid(192, "dT"), "2Q dT/T = 2Kz dR/R + (2K − 1)da + K²dλ (coefficients)", src(N59, "192"),
             r"2Q\,dT/T", derivation.period_differentials, deps=(rid(192, "n2"), rid(197, "Q")), printed=printed.period_differentials,
             defs=derivation.thread_defs(), check=truth.differential_check(),
             note="Q = a + λK² (197); K, z of the thread in terms of a, R, λ for the comparison."),
        Spec(rid(192, "from_58"), "(58) of chapter I at the limit reduces to (192)", src(N59, "192"),
             r"2Q\,dT/T", derivation.period_differentials_of_58,
             deps=(rid(58, "dT"), rid(192, "footnote"), rid(159, "vl"), rid(159, "wl"), rid(159, "beta1")),
             printed=printed.period_differentials, defs=derivation.thread_defs(), check=truth.differential_check(),
             note="The derivation from (58) gives 2a(1 − K) for the coefficient of dR/R; it is 2Kz by (36) at the "
                  "limit, z = a(1 − K)/K."),
        Spec(rid(192, "from_44"), "(44) of chapter I at the limit reduces to (192)", src(N59, "192"),
             r"2Q\,dT/T", derivation.period_differentials_of_44,
             deps=(rid(44, "dT"), rid(159, "v0"), rid(159, "vl"), rid(159, "wl"), rid(159, "beta1")),
             printed=printed.period_differentials, defs=derivation.thread_defs(), check=truth.differential_check(),
             note="dv0, dvλ, dwλ = (∂/∂λ)_M of (159) dλ, which vanish as u → ∞."),
        Spec(rid(192, "G"), "G = −1: the thread's sensitivity coefficient (62)", src(N59, "62"), "G",
             derivation.sensitivity, deps=(rid(192, "n2"),), printed=printed.sensitivity,
             check=truth.sensitivity_check()),
        Spec(rid(193, "shape"), "The limit shape of the blade: y = Yx, a straight line through O", src(N59, None),
             "y", derivation.shape_limit, deps=(rid(171, "shape"),), printed=printed.shape,
             check=truth.shape_check(), note="x = s to the first order (n°10)."),
        Spec(rid(192, "footnote"), "P_λ → (1 − K)² and the integral of (58) (∫P ds = G_2) → 0",
             src(N59, "footnote of (192)"), r"(P_\lambda, G_2)", derivation.footnote_limits,
             deps=(rid(159, "vl"), rid(159, "wl"), rid(184, "Gn")), printed=printed.footnote,
             check=truth.footnote_check()),
        Spec(rid(197, "Q"), "Q = a + λK² (45) for the thread", src(N60, "197"), "Q", derivation.Q_thread,
             deps=(rid(41, "thread"), rid(184, "ends")), printed=printed.Q_thread,
             check=checks.Chain((rid(192, "dT"),))),
        Spec(rid(193, "end_stresses"), "T'_0 = √(3ET)Y, T'_λ = √(3ET)(θ − Y) at the limit (over √(3ET))",
             src(N59, None), r"T'/\sqrt{3ET}", derivation.end_stress_limits,
             deps=(rid(177, "Gamma0"), rid(177, "Gammal")), printed=printed.end_stresses,
             check=truth.end_stress_check()),
        Spec(rid(194, "T4"), "2T along ψ = Kθ to the fourth order", src(N60, None), "2T", derivation.kinetic_quartic,
             deps=(rid(186, "T"),), printed=printed.kinetic_quartic, check=truth.energy_order("T", 6.0, on_mode=True)),
        Spec(rid(194, "U4"), "U along ψ = Kθ to the fourth order", src(N60, None), "U", derivation.force_quartic,
             deps=(rid(187, "U"),), printed=printed.force_quartic, check=truth.energy_order("U", 6.0, on_mode=True)),
        Spec(rid(194, "equation"), "Lagrange's equation of the reduced energies", src(N60, "194"), "(194)",
             derivation.reduced_equation, deps=(rid(194, "T4"), rid(194, "U4")), printed=printed.reduced_equation,
             check=checks.Chain((rid(196, "dT"),))),
        Spec(rid(195, "acceleration"), "Perturbing acceleration of the isochronism", src(N60, "195"),
             r"\Delta\theta''", derivation.perturbing_acceleration, deps=(rid(194, "equation"),),
             printed=printed.perturbing_acceleration, defs=printed.LINEAR_N2, check=checks.Chain((rid(196, "dT"),)),
             note="n² = g(a + λK²)/[R² + (a + λK)²], the frequency of the linear part of (194), in both forms: the "
                  "derivation substitutes it, the text keeps the letter n². Without that definition the forms "
                  "differed by Kaλθ³(K − 1)²[n²(R² + (a + λK)²) − g(a + λK²)]/(R² + (a + λK)²)², zero for that n²."),
        Spec(rid(196, "dT"), "Isochronism error of the thread pendulum", src(N60, "196"), r"\Delta T/T",
             derivation.isochronism, deps=(rid(195, "acceleration"),), printed=printed.isochronism,
             check=truth.isochronism_check()),
        Spec(rid(135, "thread_acceleration"), "Perturbing acceleration of the thread's inertia", src(62, None),
             r"\Delta\theta''", derivation.inertia_acceleration, printed=printed.inertia_acceleration,
             readings=(printed.READ_K2,), check=checks.Chain((rid(135, "thread_dT"),))),
        Spec(rid(135, "thread_dT"), "ΔT/T due to the thread's inertia", src(62, None), r"\Delta T/T",
             derivation.inertia_period, deps=(rid(135, "thread_acceleration"),), printed=printed.inertia_period,
             readings=(printed.READ_K2,), check=truth.heavy_thread_check(True),
             note="Derived K³ (the memoir's own first form of Δθ''); printed K²."),
        Spec(rid(136, "thread_acceleration"), "Perturbing acceleration of the thread's weight", src(63, None),
             r"\Delta\theta''", derivation.weight_acceleration, printed=printed.weight_acceleration,
             check=checks.Chain((rid(136, "thread_dT"),))),
        Spec(rid(136, "thread_dT"), "ΔT/T due to the thread's weight", src(63, None), r"\Delta T/T",
             derivation.weight_period, deps=(rid(136, "thread_acceleration"),), printed=printed.weight_period,
             check=truth.heavy_thread_check(False)),
    )
