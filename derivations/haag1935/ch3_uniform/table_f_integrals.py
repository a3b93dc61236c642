"""Haag 1935, chapter III, n°49: the integrals F_n and F of the uniform blade, (167)–(170)."""
from __future__ import annotations

from pendsym import checks
from pendsym.result import Spec

from ..common import rid, src
from . import derivation_functions as derivation, kernels, printed, truth
from .printed import DEFINITIONS

N49 = "n°49"
PHI = (rid(158, "phi1"), rid(158, "phi2"))


def by_quadrature(label: str, which) -> checks.Values:
    return truth.on_blade(f"{label} by quadrature of (79)", truth.F_of(which))


def specs() -> tuple[Spec, ...]:
    return (
        Spec(rid(167, "first_integral"), "M x'² = x² − 2Kx + (KU + U1)² for x = Kφ1 + φ2",
             src(N49, "n°49 (before 167)"), r"Mx'^2 - x^2 + 2Kx", derivation.first_integral_F, deps=PHI,
             printed=printed.first_integral_F, defs=DEFINITIONS,
             check=truth.on_blade("the shot v, w at two abscissae", truth.first_integral_F, along=True)),
        Spec(rid(167, "recurrence"), "Recurrence of F_n", src(N49, "167"), r"nF_n", derivation.F_recurrence,
             deps=(rid(167, "first_integral"), rid(159, "vl"), rid(159, "wl")), printed=printed.F_recurrence,
             defs=DEFINITIONS,
             check=truth.on_blade("n F_n by quadrature of (79); right side with F_{n−1}, F_{n−2} by quadrature",
                                  truth.n_times_F, environments=truth.with_index((2, 3, 4), keep=3),
                                  inputs=truth.F_recurrence_inputs)),
        Spec(rid(168, "F0"), "F_0 = λ", src(N49, "168"), "F_0", derivation.F0, deps=PHI, printed=printed.F0,
             check=by_quadrature("F_0", 0), defs=DEFINITIONS),
        Spec(rid(168, "F1"), "F_1/λ", src(N49, "168"), r"F_1/\lambda", derivation.F_over_lambda("F1"),
             deps=(rid(167, "recurrence"), *PHI), printed=printed.F1, check=by_quadrature("F_1", 1),
             defs=DEFINITIONS, kernel=kernels.F1_KERNEL),
        Spec(rid(169, "F2"), "F_2/λ", src(N49, "169"), r"F_2/\lambda", derivation.F_over_lambda("F2"),
             deps=(rid(167, "recurrence"), *PHI), printed=printed.F2, check=by_quadrature("F_2", 2),
             defs=DEFINITIONS, kernel=kernels.F2_KERNEL),
        Spec(rid(170, "intermediate"), "4F in terms of F_1, F_2", src(N49, "before (170)"), "4F",
             derivation.F_in_F1_F2, deps=(rid(167, "recurrence"),), printed=printed.F_in_F1_F2, defs=DEFINITIONS,
             check=truth.on_blade("4(4KF_3 − F_4) by quadrature; F_1, F_2 by quadrature", truth.four_F,
                                  inputs=truth.F1_F2_inputs),
             note="F = 4KF_3 − F_4 is the function of (110)."),
        Spec(rid(170, "F"), "F/λ = (4KF_3 − F_4)/λ", src(N49, "170"), r"F/\lambda", derivation.F_over_lambda("F"),
             deps=(rid(167, "recurrence"), *PHI), printed=printed.F,
             check=by_quadrature("F = 4KF_3 − F_4 (110)", "F"),
             defs=DEFINITIONS, kernel=kernels.F_KERNEL, readings=(printed.READ_F,),
             note="Only the K⁰ term differs from the derivation: derived − printed = −(3/8)(U_1^4 − U_1^3)."),
    )
