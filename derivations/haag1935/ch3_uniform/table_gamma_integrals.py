"""Haag 1935, chapter III, n°48: the integrals G_n and Γ_n of the uniform blade, (162)–(166)."""
from __future__ import annotations

from pendsym import checks
from pendsym.result import Spec

from ..common import TOL, rid, src
from ..symbols import a1, vl, w0, wl
from . import derivation_functions as derivation, derivation_pendulum, kernels, printed, truth, truth_modes
from .printed import DEFINITIONS, DEFINITIONS_WITH_k, X0_DEFINITION

N48 = "n°48"
FOOTNOTE_166 = "footnote of (166)"


def Gamma_spec(m: int, transcription, readings=(), note="") -> Spec:
    """Γ_m of (166), from the recurrence (164), against Γ_m of the shot blade."""
    return Spec(rid(166, f"Gamma{m}"), f"Γ_{m}", src(N48, "166"), rf"\Gamma_{m}", derivation.Gamma_n_of(m),
                deps=(rid(164, "recurrence"), rid(157, "v"), rid(157, "w")), printed=transcription,
                check=truth.on_blade(f"Γ_{m} = G_{m}/(λ(u/λ)^{m - 2}) with G_{m} by quadrature of (79)",
                                     truth.Gamma_of(m)),
                defs=DEFINITIONS, kernel=kernels.GAMMA_KERNELS.get(m), note=note, readings=readings)


def specs() -> tuple[Spec, ...]:
    return (
        Spec(rid(162, "first_integral"), "M x'² − x² is constant for x = Kv + w", src(N48, "162"),
             r"Mx'^2 - x^2", derivation.first_integral_G, deps=(rid(157, "v"), rid(157, "w")),
             printed=printed.first_integral_G, defs=DEFINITIONS + (X0_DEFINITION,),
             check=truth.on_blade("the shot v, w at two abscissae", truth.first_integral_G, along=True),
             note="x_0 = Kv_0 + w_0 with (159); x'_0 = −K by (10)."),
        Spec(rid(162, "Gn_recurrence"), "Recurrence of G_n (between (162) and (163))", src(N48, "162–163"),
             r"nG_n", derivation.G_recurrence, printed=printed.G_recurrence, defs=DEFINITIONS,
             check=truth.on_blade("n·G_n by quadrature of (79); the right side with the quadrature of the lower "
                                  "index and the shot x_0, x_λ; n = 2…5", truth.n_times_G,
                                  environments=truth.with_index((2, 3, 4, 5), keep=4),
                                  inputs=truth.G_recurrence_inputs),
             note="Unnumbered in the memoir; holds for any constant M."),
        Spec(rid(163, "Gamma"), "G_n = λ(u/λ)^{n−2}Γ_n", src(N48, "163"), r"\Gamma_n", derivation.Gamma_definition,
             definition=True),
        Spec(rid(164, "recurrence"), "Recurrence of Γ_n", src(N48, "164"), r"n\Gamma_n", derivation.Gamma_recurrence,
             deps=(rid(162, "Gn_recurrence"), rid(159, "v0"), rid(159, "vl"), rid(159, "w0"), rid(159, "wl")),
             printed=printed.Gamma_recurrence, readings=(printed.READ_BARS,), defs=DEFINITIONS_WITH_k,
             check=truth.on_blade("n·Γ_n = G_n/(λ(u/λ)^{n−2}) by quadrature of (79); the right side with the "
                                  "quadrature of the lower index; n = 2…5", truth.n_times_Gamma,
                                  environments=truth.with_index((2, 3, 4, 5), keep=4),
                                  inputs=truth.Gamma_recurrence_inputs)),
        Spec(rid(165, "k"), "k = K(1 − K) in terms of the foci", src(N48, "165"), "k", derivation_pendulum.k_of_foci,
             printed=printed.k_of_foci, defs=((a1, -wl), (w0, vl + wl)),
             check=truth.on_blade(truth_modes.MODES, truth_modes.mode_quantity("k"), with_K=False,
                                  extra=truth_modes.DYNAMIC, inputs=truth_modes.foci_inputs),
             note="Derived from K of (36); compared under a1 = −w_λ (41) and w_0 = v_λ + w_λ (16)."),
        Spec(rid(166, "Gamma_integral"), "Γ_n as an integral (footnote of n°48)", src(N48, "footnote of (164)"),
             r"\Gamma_n", derivation.Gamma_integral, deps=(rid(157, "v"), rid(157, "w")),
             printed=printed.Gamma_integral, defs=DEFINITIONS,
             check=truth.on_blade("Γ_n from G_n by quadrature of (79), n = 2, 3, 5; the integral by mpmath quad",
                                  truth.Gamma_of_n, environments=truth.Gamma_integral_environments)),
        Gamma_spec(1, printed.Gamma1),
        Gamma_spec(2, printed.Gamma2),
        Gamma_spec(3, printed.Gamma3),
        Gamma_spec(4, printed.Gamma4),
        Gamma_spec(5, printed.Gamma5, readings=(printed.READ_GAMMA5,),
                   note="Only the k⁰ term differs from the derivation: "
                        "derived − printed = (1/(5u))·4(U_1^4 − U_1^3)."),
        Spec(rid(166, "Sp_recurrence"), "S_p = S_{p−1} − kS_{p−2} (footnote of (166))", src(N48, FOOTNOTE_166),
             r"S_p - S_{p-1} + kS_{p-2}", derivation.S_p_recurrence, printed=printed.zero,
             check=checks.All((checks.Proof("S_p − S_{p−1} + kS_{p−2} = 0 for symbolic p"),
                               checks.Values(truth="direct powers K^p + (1−K)^p", points=truth.power_sum_points,
                                             tol=TOL)))),
        Spec(rid(166, "Sp_top"), "Leading terms 2(−k)^p of S_{2p}, (2p+1)(−k)^p of S_{2p+1}",
             src(N48, FOOTNOTE_166),
             r"(\mathrm{lc}\,S_{2q}, \mathrm{lc}\,S_{2q+1})_{q=1..6}/(-1)^q", derivation.S_p_leading,
             printed=printed.S_p_leading,
             check=checks.Proof("leading coefficients of S_{2q}, S_{2q+1} (q = 1…6) from the explicit roots of "
                                "t² − t + k = 0 agree with the recurrence",
                                holds=truth.leading_coefficients_from_roots,
                                truth="SymPy expansion of ((1+√(1−4k))/2)^m + ((1−√(1−4k))/2)^m"),
             note="Shown for p = 1…6 (the memoir's claim is for every p)."),
        Spec(rid(166, "Gamma_top"), "Leading term U^{2p}(−k)^p/u of Γ_{2p+1}", src(N48, FOOTNOTE_166),
             r"(\mathrm{lc}_k\Gamma_3, \mathrm{lc}_k\Gamma_5)", derivation.Gamma_leading,
             deps=(rid(166, "Gamma3"), rid(166, "Gamma5")), printed=printed.Gamma_leading, defs=DEFINITIONS,
             check=checks.All((truth.leading_order(1, 3, 0), truth.leading_order(2, 5, 1))),
             note="Shown for p = 1, 2 (the list (166)); the memoir claims every p."),
    )
