"""What a memoir contributes to scenes: effects on the period, declared by the memoir plug-in.

A memoir package may hold a module ``scene_effects`` whose ``effects()`` returns
:class:`Effect` records.  An Effect names the Result that gives its size, maps the
instrument's hardware to that Result's symbols, and turns the Result's value into a
relative change of the swing time ΔT/T, with an estimate of the error of that first-order
value (its next order).  The engine finds the modules by scanning the memoir packages
(as :mod:`pendsym.registry` finds the memoirs); nothing here names a memoir.
"""
from __future__ import annotations

import importlib
import importlib.util
import pkgutil
from dataclasses import dataclass
from functools import lru_cache
from typing import Callable, Mapping

from .. import registry


@dataclass(frozen=True)
class Instrument:
    """The hardware in plain SI numbers, and the engine's linear base (a rigid pendulum).

    ``a`` is the distance from the pivot to the centre of mass (for a thread, the stretched
    length λ(1 + μ); for a blade, from its lower clamp), ``l`` the length of the equivalent
    simple pendulum (a² + R²)/a, ``k`` = √(g/l) and ``T0`` = π/k the linear swing time of the
    rigid pendulum on a fixed knife edge at that pivot.
    """

    kind: str                    # "knife", "thread" or "blade"
    m: float
    a: float
    R: float
    g: float
    alpha: float
    l: float
    k: float
    T0: float
    thread_length: float | None = None     # λ, unstretched
    thread_EA: float | None = None         # e
    blade_length: float | None = None
    blade_EI: float | None = None
    blade_mass: float | None = None        # m' = density × width × thickness × length, when the density is given
    blade_hole: float | None = None        # the width of a rhombus hole at the middle (its vertices at the clamps)
    blade_width: float | None = None
    clamping_i: float | None = None        # Haag's i and i' (n°31), rad, when the scene gives clamping errors
    clamping_i_prime: float | None = None
    support_K: float | None = None
    support_M: float = 0.0
    drift_rate: float | None = None        # dl/dt, m/s
    # per kelvin (n°14): the blade's linear expansion α, its modulus's thermoelastic coefficient β (dE/E), the
    # pendulum's linear expansion α' (a and R grow by it); None when the scene gives no temperature
    thermal_alpha: float | None = None
    thermal_beta: float | None = None
    thermal_alpha_prime: float | None = None
    inverted: bool = False                 # an inverted blade (the bob above it): l, k, T0 are nan, an effect
                                           # with ``base`` gives the linear swing time instead

    @property
    def mu(self) -> float:
        """μ = mg/e of the thread."""
        return self.m * self.g / self.thread_EA

    @property
    def drift_a(self) -> float:
        """a of l = l0(1 + at): the rate over the length that grows (for a thread, the unstretched
        length paid out: the stretched one grows in the same ratio)."""
        return self.drift_rate / (self.thread_length if self.kind == "thread" else self.l)

    @property
    def blade_M(self) -> float:
        """M = EI/(mg) (m²)."""
        return self.blade_EI / (self.m * self.g)

    @property
    def blade_short(self) -> float:
        """λ/a, the small parameter of the short blade."""
        return self.blade_length / self.a

    @property
    def hole_M0(self) -> float:
        """M0 = EI/(mg) at the middle of a blade with a rhombus hole (I ∝ the width left there)."""
        return self.blade_M * (1 - self.blade_hole / self.blade_width)

    @property
    def hole_k(self) -> float:
        """k of M = M0(1 + k|s|): the width grows linearly from the middle to the full width at s = ±λ/2."""
        return 2 * self.blade_hole / (self.blade_length * (self.blade_width - self.blade_hole))

    @property
    def blade_u(self) -> float:
        """u = λ/√M."""
        return self.blade_length / self.blade_M ** 0.5


@dataclass(frozen=True)
class Effect:
    """One effect on the period, as a memoir gives it.

    ``estimate(inst)``: the size of ΔT/T from the memoir's printed statement, used to drop the
    effect before its Result is built (inf: always kept).
    ``symbols(inst)``: the values of the Result's free symbols, by name.
    ``relative(value, inst)``: ΔT/T from the Result's value.
    ``error(rel, inst)``: the estimated error of ``rel`` at this scene (its next order, or
    what the model leaves out), ≥ 0.
    ``exact``: optional (inst) → ΔT/T by a more complete model the engine has, and its
    error; chosen when the first-order value is not within the tolerance.
    ``couples``: keys of effects whose coupling with this one (and with each other) this effect's
    Result gives: e.g. a blade's isochronism error is the circular error of the pendulum on the
    blade, relative to the blade's linear period, so the products of the three need no bound.
    """

    key: str
    title: str
    source: str
    result: str
    applies: Callable[[Instrument], bool]
    estimate: Callable[[Instrument], float]
    symbols: Callable[[Instrument], Mapping[str, float]]
    relative: Callable[[float, Instrument], float]
    error: Callable[[float, Instrument], float]
    exact: Callable[[Instrument], tuple[float, float, str]] | None = None
    scale_by: str | None = None          # the key of an effect whose ΔT/T multiplies this one's
    couples: tuple[str, ...] = ()
    model: str = "first order"           # what the Result is, for the budget's "model" line
    order: int = 50                      # the budget's row order
    # ``base``: the Result gives the linear swing time itself (``relative(value, inst)`` returns it, in s), in
    # place of the rigid pendulum's π√(l/g) (e.g. an inverted pendulum, unstable without its suspension)
    base: bool = False
    # the base's dependence on g at fixed hardware: each symbol's exponent of g (a symbol ∝ g^p), and the map
    # from d log(value)/d log g to d log T/d log g (the sensitivity a gravity meter's user wants)
    g_exponents: Mapping[str, float] | None = None
    sensitivity: Callable[[float, Instrument], float] | None = None
    # d(ΔT/T)/d log g of this effect and its error, from (ΔT/T, inst, the base's S); without it the budget bounds
    # the effect's part of the sensitivity by 2|S||ΔT/T| (an effect ∝ 1/ε near a critical distance)
    g_slope: Callable[[float, Instrument, float], tuple[float, float]] | None = None
    # keys of effects this one supersedes for this hardware (they are not applied when it applies)
    replaces: tuple[str, ...] = ()
    # Results whose values (at ``symbols`` and what ``given`` returns so far, in order) feed this Result's
    # symbols through ``given(inst, {id: value})``
    uses: tuple[str, ...] = ()
    given: Callable[[Instrument, Mapping[str, float]], Mapping[str, float]] | None = None
    # a one-line reason to refuse the scene (outside the Result's reach, e.g. unstable), or None
    refuse: Callable[[Instrument], str | None] | None = None


@dataclass(frozen=True)
class Coefficient:
    """A coefficient of the period a memoir gives beside it (not a ΔT/T): e.g. d log T per kelvin.

    ``quantity``: the ``wanted.quantities`` name that asks for it (e.g. "temperature").
    ``symbols(inst)``, ``uses``, ``given``: as for :class:`Effect` (the Result's symbols at this scene).
    ``coefficient(value, inst, values)``: the coefficient from the Result's value and the symbols' values (those
    ``given`` added included; for "temperature": per kelvin).
    ``error(coefficient, inst)``: its estimated error at this scene (the orders the Result neglects), ≥ 0.
    """

    key: str
    quantity: str
    title: str
    source: str
    result: str
    applies: Callable[[Instrument], bool]
    symbols: Callable[[Instrument], Mapping[str, float]]
    coefficient: Callable[[float, Instrument, Mapping[str, float]], float]
    error: Callable[[float, Instrument], float]
    uses: tuple[str, ...] = ()
    given: Callable[[Instrument, Mapping[str, float]], Mapping[str, float]] | None = None
    model: str = "first order"
    # keys of effects whose dependence on the quantity the Result already holds (e.g. the blade's linear effect in
    # the blade's temperature coefficient): not bounded again
    covers: tuple[str, ...] = ()


@dataclass(frozen=True)
class Pending:
    """An effect a memoir treats that the engine has not built yet: listed in the budget, no size."""

    key: str
    title: str
    source: str
    applies: Callable[[Instrument], bool]


def _modules(pkgs: tuple[str, ...]):
    for pkg_name in pkgs:
        pkg = importlib.import_module(pkg_name)
        for info in sorted(pkgutil.iter_modules(pkg.__path__), key=lambda i: i.name):
            name = f"{pkg_name}.{info.name}.scene_effects"
            if info.ispkg and importlib.util.find_spec(name) is not None:
                yield importlib.import_module(name)


@lru_cache(maxsize=8)
def discover_pending(pkgs: tuple[str, ...]) -> tuple[Pending, ...]:
    """Every memoir's effects not built yet (``scene_effects.pending()``, optional)."""
    return tuple(p for mod in _modules(pkgs) for p in (mod.pending() if hasattr(mod, "pending") else ()))


def pending() -> tuple[Pending, ...]:
    return discover_pending(registry.packages())


@lru_cache(maxsize=8)
def discover(pkgs: tuple[str, ...]) -> tuple[Effect, ...]:
    """Every memoir's declared effects (``<package>.<memoir>.scene_effects.effects()``)."""
    out: list[Effect] = []
    for mod in _modules(pkgs):
        out.extend(mod.effects())
    keys = [e.key for e in out]
    if len(set(keys)) != len(keys):
        raise ValueError(f"two memoirs declare the same scene effect: {sorted(k for k in keys if keys.count(k) > 1)}")
    return tuple(sorted(out, key=lambda e: (e.order, e.key)))


def effects() -> tuple[Effect, ...]:
    return discover(registry.packages())


@lru_cache(maxsize=8)
def discover_coefficients(pkgs: tuple[str, ...]) -> tuple[Coefficient, ...]:
    """Every memoir's coefficients (``scene_effects.coefficients()``, optional)."""
    return tuple(c for mod in _modules(pkgs) for c in (mod.coefficients() if hasattr(mod, "coefficients") else ()))


def coefficients() -> tuple[Coefficient, ...]:
    return discover_coefficients(registry.packages())
