"""Haag 1935, chapter III, n°50: the foci, K and n² of a pendulum on the uniform blade, (30)–(37)."""
from __future__ import annotations

from pendsym import checks
from pendsym.result import Spec

from ..common import rid, src
from . import derivation_pendulum as derivation, kernels, printed, truth, truth_modes
from .printed import DEFINITIONS

N50 = "n°50"


def by_normal_modes(name: str) -> checks.Values:
    """z, z', K or n² against the principal mode of (25)–(26) on the shot blade."""
    return truth.on_blade(truth_modes.MODES, truth_modes.mode_quantity(name), with_K=False,
                          extra=truth_modes.DYNAMIC)


def specs() -> tuple[Spec, ...]:
    return (
        Spec(rid(30, "uniform"), "v_λ² + β1 w_λ for the uniform blade (n°50)", src(N50, "30"),
             r"v_\lambda^2 + \beta_1 w_\lambda", derivation.foci_combination,
             deps=(rid(159, "vl"), rid(159, "beta1"), rid(159, "wl")), printed=printed.foci_combination,
             defs=DEFINITIONS, readings=(printed.READ_FOCI_COMBINATION,),
             check=truth.on_blade("v_λ² + β1 w_λ shot", truth.foci_combination, with_K=False)),
        Spec(rid(30, "zp_uniform"), "z' (negative root of (30)) for the uniform blade", src(N50, "30"), "z'",
             derivation.z_prime, deps=(rid(159, "v0"), rid(159, "vl"), rid(30, "uniform")),
             check=by_normal_modes("zp"), defs=DEFINITIONS),
        Spec(rid(35, "K_uniform"), "K of (35) for the uniform blade", src(N50, "35"), "K", derivation.K_of_35,
             deps=(rid(30, "zp_uniform"), rid(159, "vl"), rid(159, "beta1")), check=by_normal_modes("K"),
             defs=DEFINITIONS),
        Spec(rid(34, "n2_uniform"), "n² = −Kg/z' for the uniform blade", src(N50, "34"), "n^2", derivation.n2_of_34,
             deps=(rid(35, "K_uniform"), rid(30, "zp_uniform")), check=by_normal_modes("n2"), defs=DEFINITIONS),
        Spec(rid(30, "z_uniform"), "z (positive root of (30)) for the uniform blade, without cancellation",
             src(N50, "30"), "z", derivation.z_positive_root, deps=(rid(159, "vl"), rid(159, "beta1"), rid(159, "wl")),
             check=by_normal_modes("z"), defs=DEFINITIONS),
        Spec(rid(36, "K_uniform"), "K of (36) for the uniform blade", src(N50, "36"), "K", derivation.K_of_36,
             deps=(rid(30, "z_uniform"), rid(159, "vl"), rid(159, "wl")), check=by_normal_modes("K"),
             defs=DEFINITIONS, kernel=kernels.K_KERNEL),
        Spec(rid(34, "n2_z_uniform"), "n² = Kgz/R² ((34) with (31)) for the uniform blade, K of (36)",
             src(N50, "34"), "n^2", derivation.n2_of_z, deps=(rid(36, "K_uniform"), rid(30, "z_uniform")),
             check=by_normal_modes("n2"), defs=DEFINITIONS, kernel=kernels.N2_KERNEL),
    )
