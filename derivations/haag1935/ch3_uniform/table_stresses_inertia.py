"""Haag 1935, chapter III, n°54–57: the stresses of both vibrations (180)–(181), I_λ (182) and J (183)."""
from __future__ import annotations

from pendsym import checks
from pendsym.result import Spec

from ..common import rid, src
from . import derivation_pendulum as derivation, kernels, printed, truth, truth_modes
from .printed import DEFINITIONS, DEFINITIONS_WITH_k

NOTE_180 = ("Only the second (n't) term differs: the derivation has K' where the text shows K; T and mg stand for "
            "Haag's T = mg/(eh) (n°51) and the weight; the truth uses m = 1.")
NOTE_181 = ("m' is the striking mass of n°20 (not the blade's m' of n°56); h is the restitution coefficient "
            "(not the blade's width).")


def by_modal_solution(at: int, shock: bool) -> checks.Values:
    """T'_0 or T'_λ against (78) at the end, from the normal-mode solution launched by the shock or the
    static deviation."""
    launch = "shock (70), (74)" if shock else "static deviation (67)"
    return truth.on_blade(f"(78) at the end with (β, θ) at time t of the normal-mode solution of (25)–(26) "
                          f"(mpmath eig), launched by the {launch}", truth_modes.end_stress(at, shock),
                          with_K=False, extra=truth_modes.LAUNCH, inputs=truth_modes.launch_inputs)


def launch_spec(eq: int, at: int, transcription, readings=()) -> Spec:
    """T'_0 (at = 0) or T'_λ (at = 1) of (180), launch by the static deviation, or of (181), by a shock."""
    shock = eq == 181
    what = "Stress at the ends, launch by a shock" if shock else "Stress at the ends, static launch"
    label, lhs = ("T'_0", "T'_0") if at == 0 else ("T'_λ", r"T'_\lambda")
    derive = derivation.shock_launch(at) if shock else derivation.static_launch(at)
    return Spec(rid(eq, "T0" if at == 0 else "Tl"), f"{what}: {label}", src("n°54", str(eq)), lhs, derive,
                printed=transcription, defs=DEFINITIONS, readings=readings, note=NOTE_181 if shock else NOTE_180,
                check=by_modal_solution(at, shock))


def specs() -> tuple[Spec, ...]:
    return (
        launch_spec(180, 0, printed.static_launch_T0, readings=(printed.READ_K_PRIME_T0,)),
        launch_spec(180, 1, printed.static_launch_T_lambda, readings=(printed.READ_K_PRIME_T_LAMBDA,)),
        launch_spec(181, 0, printed.shock_launch_T0),
        launch_spec(181, 1, printed.shock_launch_T_lambda),
        # ---------------------------------------------------------------- n°56–57
        Spec(rid(182, "I"), "Moment of inertia I_λ of the blade", src("n°56", "182"), r"I_\lambda",
             derivation.inertia,
             deps=(rid(157, "v"), rid(157, "w")), printed=printed.inertia, defs=DEFINITIONS,
             check=truth.on_blade("(1/λ)∫y² ds, y of (77) with Y = K, θ = 1, by quadrature", truth.inertia,
                                  extra={"m'": "1"}),
             kernel=kernels.INERTIA_KERNEL),
        Spec(rid(182, "aux"), "∫(Ks − x_0)x'' ds (n°56)", src("n°56", "before (182)"),
             r"\int_0^\lambda (Ks - x_0)x''\,ds", derivation.inertia_auxiliary, deps=(rid(157, "v"), rid(157, "w")),
             printed=printed.inertia_auxiliary, defs=DEFINITIONS_WITH_k,
             check=truth.on_blade("mpmath quad of (Ks − x_0)(Kv + w)/M", truth.inertia_auxiliary)),
        Spec(rid(183, "s_minus_x"), "s − x along the blade (n°57)", src("n°57", "before (183)"), "s - x",
             derivation.s_minus_x, deps=(rid(158, "phi1"), rid(158, "phi2")), printed=printed.s_minus_x,
             defs=DEFINITIONS,
             check=truth.on_blade("½∫_0^s (Kφ1 + φ2)² by quadrature", truth.half_integral_of_x_prime_squared,
                                  along=True)),
        Spec(rid(183, "J"), "J (n°57)", src("n°57", "183"), "J", derivation.J_of_blade, deps=(rid(183, "s_minus_x"),),
             printed=printed.J, defs=DEFINITIONS,
             check=truth.on_blade("(1/2λ)∫(λ − s)(Kφ1 + φ2)² ds by quadrature", truth.weight_integral),
             kernel=kernels.J_KERNEL),
    )
