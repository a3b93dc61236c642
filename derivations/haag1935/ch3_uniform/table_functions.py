"""Haag 1935, chapter III, n°47: v, w and the functions U, U1, U2 of the uniform blade, (156)–(161)."""
from __future__ import annotations

import sympy as sp

from pendsym import checks
from pendsym.result import Spec

from ..common import READ_VW, rid, src
from ..symbols import U, U1, U2, lam, u
from . import derivation_functions as derivation, kernels, printed, truth
from .printed import DEFINITIONS

N47 = "n°47"


def along(name: str) -> checks.Values:
    return truth.on_blade(f"{name} shot", truth.function_along(name), along=True, with_K=False)


def at_end(name: str) -> checks.Values:
    return truth.on_blade(f"{name} shot", truth.end_value(name), with_K=False)


def identity(statement: str) -> checks.Proof:
    return checks.Proof(f"{statement} (exponential form)")


def equals_printed(statement: str, transcription) -> checks.Proof:
    """Exact algebra: the derived form simplifies to the transcription."""
    return checks.Proof(statement, holds=lambda derived: sp.simplify(derived - transcription()) == 0,
                        truth="exact algebra")


def specs() -> tuple[Spec, ...]:
    return (
        Spec(rid(156, "omega2"), "ω² = 1/M for a rectangular blade", src(N47, "156"), r"\omega^2",
             derivation.omega_squared, printed=printed.omega_squared,
             check=equals_printed("1/M with M = EI/(mg) (1), I = e³h/12", printed.omega_squared),
             note="I = e³h/12 (rectangular section of thickness e, width h) is implied by (156), not stated."),
        Spec(rid(156, "u"), "u = λω", src(N47, "156"), "u", derivation.u_of_omega, deps=(rid(156, "omega2"),),
             printed=printed.u_of_blade,
             check=equals_printed("λ√(ω²)", printed.u_of_blade)),
        Spec(rid(157, "v"), "v for the uniform blade", src(N47, "157"), "v", derivation.closed_form("v"),
             printed=printed.v, readings=(READ_VW,), check=along("v"), defs=DEFINITIONS),
        Spec(rid(157, "w"), "w for the uniform blade", src(N47, "157"), "w", derivation.closed_form("w"),
             printed=printed.w, readings=(READ_VW,), check=along("w"), defs=DEFINITIONS),
        Spec(rid(158, "phi1"), "φ1 = 1 + v'", src(N47, "158"), r"\varphi_1", derivation.closed_form("phi1"),
             printed=printed.phi1, check=along("phi1"), defs=DEFINITIONS),
        Spec(rid(158, "phi2"), "φ2 = w'", src(N47, "158"), r"\varphi_2", derivation.closed_form("phi2"),
             printed=printed.phi2, check=along("phi2"), defs=DEFINITIONS),
        Spec(rid(160, "U"), "U = th(u/2)", src(N47, "160"), "U", derivation.definition_of(sp.tanh(u / 2)),
             definition=True),
        Spec(rid(160, "U1"), "U1 = 1/sh u", src(N47, "160"), "U_1", derivation.definition_of(1 / sp.sinh(u)),
             definition=True),
        Spec(rid(160, "U2"), "U2 = 1/th u", src(N47, "160"), "U_2", derivation.definition_of(1 / sp.tanh(u)),
             definition=True),
        Spec(rid(159, "v0"), "v_0", src(N47, "159"), "v_0", derivation.end_value(157, "v", 0), deps=(rid(157, "v"),),
             printed=printed.v0, check=at_end("v0"), defs=DEFINITIONS, readings=(READ_VW,),
             kernel=kernels.V0_KERNEL),
        Spec(rid(159, "vl"), "v_λ", src(N47, "159"), r"v_\lambda", derivation.end_value(157, "v", lam),
             deps=(rid(157, "v"),), printed=printed.v_lambda, check=at_end("vl"), defs=DEFINITIONS),
        Spec(rid(159, "w0"), "w_0", src(N47, "159"), "w_0", derivation.end_value(157, "w", 0), deps=(rid(157, "w"),),
             printed=printed.w0, check=at_end("w0"), defs=DEFINITIONS, readings=(READ_VW,),
             kernel=kernels.W0_KERNEL),
        Spec(rid(159, "wl"), "w_λ", src(N47, "159"), r"w_\lambda", derivation.end_value(157, "w", lam),
             deps=(rid(157, "w"),), printed=printed.w_lambda, check=at_end("wl"), defs=DEFINITIONS,
             readings=(READ_VW,), kernel=kernels.W_LAMBDA_KERNEL),
        Spec(rid(159, "beta1"), "β1 = λ + v_λ − v_0", src(N47, "159"), r"\beta_1", derivation.beta1,
             deps=(rid(159, "v0"), rid(159, "vl")), printed=printed.beta1, check=at_end("beta1"), defs=DEFINITIONS,
             kernel=kernels.BETA1_KERNEL),
        Spec(rid(159, "beta2"), "β2 = w_λ − w_0", src(N47, "159"), r"\beta_2", derivation.beta2,
             deps=(rid(159, "w0"), rid(159, "wl")), printed=printed.beta2, check=at_end("beta2"), defs=DEFINITIONS),
        Spec(rid(161, "sum"), "U2 = U + U1", src(N47, "161"), r"U_2 - U - U_1",
             derivation.identity_difference(U2 - U - U1), printed=printed.zero,
             check=identity("th(u/2) + 1/sh u − 1/th u = 0")),
        Spec(rid(161, "square"), "1 − U² = 2UU1", src(N47, "161"), r"1 - U^2 - 2UU_1",
             derivation.identity_difference(1 - U**2 - 2 * U * U1), printed=printed.zero,
             check=identity("1 − th²(u/2) − 2 th(u/2)/sh u = 0")),
        Spec(rid(161, "difference"), "U2² − U1² = 1", src(N47, "161"), r"U_2^2 - U_1^2 - 1",
             derivation.identity_difference(U2**2 - U1**2 - 1), printed=printed.zero,
             check=identity("coth²u − csch²u − 1 = 0")),
    )
