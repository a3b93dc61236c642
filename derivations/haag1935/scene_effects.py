"""Haag 1935 in scenes: the uniform blade's effect on the period (chapter III, n°50: n² = Kgz/R²
with K of (36) and z of (30)), against a knife edge at the blade's lower clamp.

ΔT/T = k/n − 1 with k² = ga/(a² + R²) the rigid pendulum pivoting at the clamp.  The theory
is linear in the blade (small oscillations): what it leaves out (the blade's mass, the
finite-amplitude terms of chapter II) is not in the engine yet and is listed by the budget.
"""
from __future__ import annotations

import math

from pendsym.scenes.effects import Effect, Instrument, Pending


def _blade(inst: Instrument) -> dict[str, float]:
    return {"a": inst.a, "R": inst.R, "lambda": inst.blade_length, "u": inst.blade_u, "g": inst.g}


def effects() -> tuple[Effect, ...]:
    return (
        Effect("blade", "elastic blade instead of a knife edge (small oscillations)",
               "Haag 1935, ch. III n°50, eq. (34) with (36), (30)", "haag1935.eq034.n2_z_uniform",
               applies=lambda i: i.kind == "blade",
               estimate=lambda i: math.inf,           # it defines the suspension: always kept
               symbols=_blade, relative=lambda n2, i: i.k / math.sqrt(n2) - 1,
               error=lambda rel, i: 1e-14 * abs(rel), order=5,
               model="linear theory of the blade, exact for small oscillations (evaluated at 30 digits)"),
    )


def pending() -> tuple[Pending, ...]:
    """What Haag treats for a blade that the engine has not built yet (other chapters)."""
    is_blade = lambda i: i.kind == "blade"
    return (Pending("blade_isochronism", "blade at finite amplitude (isochronism error)", "Haag 1935, ch. II, VII",
                    is_blade),
            Pending("blade_clamping", "clamping errors of the blade", "Haag 1935, ch. II, VII", is_blade),
            Pending("blade_inertia", "inertia and weight of the blade", "Haag 1935, ch. II", is_blade))
