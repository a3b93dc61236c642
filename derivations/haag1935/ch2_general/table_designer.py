"""Haag 1935, chapter II specialised to the uniform short blade: the designer's coefficients, derived-only
Results with kernels (:mod:`.designer`, :mod:`.kernels`)."""
from __future__ import annotations

from pendsym.result import Spec

from ..common import rid, src
from . import designer, kernels

NOTE = ("Derived only (the memoir prints the period's change (Result {eq}), not its coefficient): {eq}'s derived "
        "form divided by its scale. Judged at the exact modes (chapter VI's truth) by the fitted order of the "
        "residual in λ/a on the uniform blade u = 2.")


def specs() -> tuple[Spec, ...]:
    clamping = tuple(
        Spec(rid(134, f"c_{m}_uniform"), f"c_{m}: the clamping coefficient of {m[0]}·{m[1]}, the short uniform "
             "blade: ΔT/T = (λ/a)(c_ii i² + c_ij ij + c_jj j²)", src("n°35, 80", None), f"c_{{{m}}}",
             lambda deps, m=m: designer.clamping_coefficient(deps, m), deps=(designer.CLAMPING,),
             check=designer.clamping_check(m), kernel=kernels.CLAMPING_KERNELS[m],
             note=NOTE.format(eq="(249)") + " i' follows from i, j by (117); c_ij is read as P(1, 1) − P(1, 0) "
                                            "− P(0, 1).")
        for m in ("ii", "ij", "jj"))
    return (
        Spec(rid(112, "c_uniform"), "c_Q = (a/λ)(Q'/Q − 1), the isochronism coefficient of the short uniform blade",
             src("n°29, 79", None), "c_Q", designer.isochronism_coefficient, deps=(designer.ISOCHRONISM,),
             check=designer.isochronism_check(), kernel=kernels.ISOCHRONISM_KERNEL,
             note=NOTE.format(eq="(244)")),
    ) + clamping + (
        Spec(rid(135, "c_uniform"), "c_I = (m/m')(a/λ)²ΔT/T, the blade's inertia, the short uniform blade",
             src("n°36, 81", None), "c_I", designer.inertia_coefficient, deps=(designer.INERTIA,),
             check=designer.inertia_check(), kernel=kernels.INERTIA_KERNEL, note=NOTE.format(eq="(251)")),
        Spec(rid(136, "c_uniform"), "c_J = (m/m')(a/λ)ΔT/T, the blade's weight, the short uniform blade",
             src("n°37, 81", None), "c_J", designer.weight_coefficient, deps=(designer.WEIGHT,),
             check=designer.weight_check(), kernel=kernels.WEIGHT_KERNEL, note=NOTE.format(eq="(253)")),
        Spec(rid(136, "c_gravity_uniform"), "c = ε(m/m')ΔT/T, the blade's weight, the gravity pendulum on a uniform "
             "blade (direct)", src("n°37, 96", None), "c", designer.gravity_weight_coefficient,
             deps=(designer.GRAVITY_WEIGHT,), check=designer.gravity_weight_check(),
             kernel=kernels.GRAVITY_WEIGHT_KERNEL,
             note="Derived only: (293)'s derived form times ε m/m'. Judged against the exact blade with mass "
                  "(pendsym.massive_blade) at a = a1 + ελ, u = 2, by the fitted order of the residual in ε."),
        Spec(rid(136, "c_inverted_uniform"), "c = ε(m/m')ΔT/T, the blade's weight, the inverted gravity pendulum on a "
             "uniform blade", src("n°37, 103", None), "c",
             lambda deps: designer.gravity_weight_coefficient(deps, inverted=True),
             deps=(designer.INVERTED_WEIGHT,), check=designer.gravity_weight_check(inverted=True),
             kernel=kernels.INVERTED_WEIGHT_KERNEL,
             note="Derived only: (320)'s derived form times ε m/m'. Judged against the exact inverted blade with mass "
                  "(M < 0, g < 0) at a = a1 − ελ, u = 1, by the fitted order of the residual in ε."),
        Spec(rid(149, "c_uniform"), "c_D = −(2/π)(a/λ)Δθ0/(i_{p,q+1}βn^qθ0), the damping per period at p + q = 1, "
             "the short uniform blade", src("n°23, 42", None), "c_D", designer.damping_coefficient,
             deps=designer.DAMPING_DEPS, check=designer.damping_check(), kernel=kernels.DAMPING_KERNEL,
             note="Derived only (the memoir does not specialise (149) to the short blade): (149) at p + q = 1 (Le "
                  "Rolland's law of n°23, the energy lost per period in proportion to the blade's energy of "
                  "deformation), β = a_pq + b_pq + a'_pq + b'_pq, with g_1 = βG_2 (140), G_2 = λΓ_2 (163), Γ_2 (166) at "
                  "K = 1, Q → a (221), divided by its scale. Judged at the exact modes (chapter VI's truth) by the "
                  "fitted order of the residual in λ/a on the uniform blade u = 2."),
    )
