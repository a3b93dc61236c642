"""Charbonnier 1908 in scenes: the circular error (n°21), the elastic thread (n°24–26) and the
length that grows at a constant rate (n°27–32), as effects on the swing time.

Every Result here gives an absolute ΔT of one swing with T = π/k (k² = g/l0): ΔT/T = ΔT·k/π.
The ``estimate`` of each effect is the printed statement's size (used to drop it unbuilt);
the value reported is the derived Result's.
"""
from __future__ import annotations

import math

import mpmath as mp

from pendsym.scenes.effects import Effect, Instrument


def _per_swing(value: float, inst: Instrument) -> float:
    """ΔT/T with T = π/k."""
    return value * inst.k / math.pi


def _circular_exact(inst: Instrument) -> tuple[float, float, str]:
    """T/T_lin − 1 = 2K(sin²(α/2))/π − 1 (the exact swing of θ'' + k² sin θ = 0; Gauss's AGM)."""
    with mp.workdps(30):
        rel = 2 * mp.ellipk(mp.sin(mp.mpf(inst.alpha) / 2) ** 2) / mp.pi - 1
    return float(rel), 1e-16, "exact swing of θ'' + k² sin θ = 0, 2K(sin²½α)/k (Gauss's AGM)"


def _drift_exact(inst: Instrument) -> tuple[float, float, str]:
    """T/T_lin − 1 for l = l0(1 + at), θ'' + (2/l)l'θ' + (g/l)θ = 0 integrated (n°27–28's governing model)."""
    from . import scene_drift        # the integration, imported only by a scene that needs it
    a = inst.drift_a
    with mp.workdps(20):
        T = scene_drift.swing_time(repr(inst.alpha), repr(inst.k), 20, repr(a))
        rel = T * mp.mpf(inst.k) / mp.pi - 1
    return float(rel), 1e-15, "θ'' + (2/l)l'θ' + (g/l)θ = 0 with l = l0(1 + at) integrated (mpmath odefun, 20 digits)"


def effects() -> tuple[Effect, ...]:
    return (
        Effect("circular", "circular error (finite amplitude)", "Charbonnier 1908, n°21 (ΔT = α²T/16)",
               "charbonnier1908.n21.dT", applies=lambda i: i.alpha > 0,
               estimate=lambda i: i.alpha**2 / 16,
               symbols=lambda i: {"alpha": i.alpha, "k": i.k}, relative=_per_swing,
               error=lambda rel, i: 11 * i.alpha**4 / 3072,      # the next term of 2K(sin²½α)/π
               exact=_circular_exact, order=10),
        Effect("thread_elasticity", "elastic thread (stretch under the centrifugal tension)",
               "Charbonnier 1908, n°26 (ΔT = (11/16) mg/(e + mg) α² T)", "charbonnier1908.n26.dT",
               applies=lambda i: i.kind == "thread" and i.alpha > 0,
               estimate=lambda i: 11 / 16 * i.mu / (1 + i.mu) * i.alpha**2,
               symbols=lambda i: {"alpha": i.alpha, "k": i.k, "mu": i.mu}, relative=_per_swing,
               # first order in μα²: the next orders are O(μα⁴) and O(μ²α²)
               error=lambda rel, i: abs(rel) * (i.alpha**2 + i.mu), order=20),
        Effect("length_drift", "length growing at a constant rate (one swing from rest)",
               "Charbonnier 1908, n°32 (ΔT = aT²/4, l = l0(1 + at))", "charbonnier1908.n32.dT",
               applies=lambda i: bool(i.drift_rate),
               estimate=lambda i: abs(i.drift_a) * i.T0 / 4,
               symbols=lambda i: {"a": i.drift_a, "k": i.k}, relative=_per_swing,
               # first order in a: the next is O((aT)²)
               error=lambda rel, i: (i.drift_a * i.T0) ** 2, exact=_drift_exact, order=40),
    )
