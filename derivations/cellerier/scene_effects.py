"""Cellérier in scenes: the sway of a compliant support (δ, the static support) and the
correction for the support's mass (the lumped dynamic model), as effects on the swing time.

δ = T/T0 − 1 is already relative.  The pendulum's h is the distance from the pivot to the
centre of mass and l = C/(mh) = (a² + R²)/a its equivalent length.
"""
from __future__ import annotations

from pendsym.scenes.effects import Effect, Instrument


def _sway(inst: Instrument) -> dict[str, float]:
    return {"K": inst.support_K, "m": inst.m, "g": inst.g, "h": inst.a, "l": inst.l}


def _sway_error(rel: float, inst: Instrument) -> float:
    """Next orders: δ² (second order in K) and δα² (cos θ replaced by 1); for a blade the
    pivot is not a knife edge: a relative λ/a is left to the blade's own theory."""
    err = abs(rel) * (abs(rel) + inst.alpha**2)
    if inst.kind == "blade":
        err += abs(rel) * inst.blade_length / inst.a
    return err


def effects() -> tuple[Effect, ...]:
    return (
        Effect("support_sway", "sway of the compliant support", "Cellérier, static support (δ = Kmgh/(2l²))",
               "cellerier.delta_static", applies=lambda i: bool(i.support_K),
               estimate=lambda i: i.support_K * i.m * i.g * i.a / (2 * i.l**2),
               symbols=_sway, relative=lambda v, i: v, error=_sway_error, order=30),
        Effect("support_mass", "inertia of the support (its mass)", "Cellérier, lumped support (δ_M/δ − 1 = KMg/l)",
               "cellerier.lumped_dynamic", applies=lambda i: bool(i.support_K) and i.support_M > 0,
               estimate=lambda i: i.support_K * i.m * i.g * i.a / (2 * i.l**2) * i.support_K * i.support_M * i.g / i.l,
               symbols=lambda i: {"K": i.support_K, "M": i.support_M, "g": i.g, "l": i.l},
               relative=lambda v, i: v, error=lambda rel, i: abs(rel) * i.support_K * i.support_M * i.g / i.l,
               scale_by="support_sway", order=31),
    )
