"""Haag 1935, chapter VIII, n°103: the inverted blade's inertia and weight (319)–(320), the Results."""
from __future__ import annotations

from pendsym.result import Spec

from ..common import rid, src
from . import derivation, printed, truth

INVERTED = ("Order in ε against the inverted blade with mass (M < 0, g < 0, u = 1) at a = a1 − ελ (312), m'/m = "
            "10⁻²⁰.")


def specs() -> tuple[Spec, ...]:
    return (
        Spec(rid(319, "inertia"), "ΔT/T of the inverted blade's inertia", src(103, "319"), r"\frac{\Delta T}{T}",
             derivation.inertia_319, deps=(rid(291, "inertia"),), printed=printed.inertia_319,
             check=truth.mass_order("inertia", "u=1", sign=-1), note="(291) with u → iu (n°101). " + INVERTED),
        Spec(rid(320, "weight"), "ΔT/T = −(m'/(8mε))(1/u² − 1/sin²u), inverted", src(103, "320"),
             r"\frac{\Delta T}{T}", derivation.weight_320, deps=(rid(293, "weight"), rid(312, "epsilon")),
             printed=printed.weight_320, check=truth.mass_order("weight", "u=1", sign=-1, scaled=True),
             note="(293) with u → iu and ε → −ε (312). " + INVERTED),
    )
