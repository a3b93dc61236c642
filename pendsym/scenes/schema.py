"""The hardware scene: a pendulum described as an instrument (TOML, SI units), validated by pydantic.

The schema is written once, here; ``docs/scenes.md`` shows it and :func:`json_schema`
gives it as JSON Schema.  Every number is SI:
kilograms, metres, seconds, radians, newtons, pascals.  Strict types: a string is
never read as a number, a bool never as 0/1; NaN and ±inf are refused; unknown keys
are refused.  The checks that join several keys (an inconsistent input) are in
:meth:`Scene.consistent`.
"""
from __future__ import annotations

import unicodedata
from typing import Annotated, Literal, Union

from pydantic import BaseModel, ConfigDict, Field, model_validator


class Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", strict=True, allow_inf_nan=False, frozen=True)


def num(lo: float, hi: float, unit: str, doc: str, *, open_lo: bool = True, default=...):
    """A float in (lo, hi] (or [lo, hi]), its unit and meaning in the schema's description."""
    bound = {"gt": lo} if open_lo else {"ge": lo}
    return Field(default, **bound, le=hi, description=f"{doc} [{unit}], in {'(' if open_lo else '['}{lo:g}, {hi:g}]")


class Bob(Strict):
    mass: float = num(1e-3, 1e4, "kg", "mass m of the pendulum")
    a: float | None = num(1e-3, 100.0, "m", "distance from the pivot (knife edge, or the blade's lower clamp) "
                          "to the centre of mass; not given with a thread (the thread sets it)", default=None)
    R: float = num(0.0, 10.0, "m", "radius of gyration about the centre of mass", open_lo=False)


class Knife(Strict):
    kind: Literal["knife"]


class Thread(Strict):
    kind: Literal["thread"]
    length: float = num(1e-2, 1e4, "m", "unstretched length λ from the suspension point to the centre of mass")
    EA: float = num(1.0, 1e12, "N", "elasticity e of the thread: the tension that would double its length "
                    "(Young's modulus × cross-section)")


class Hole(Strict):
    shape: Literal["rhombus"] = Field(description="a rhombus whose two opposite vertices are at the middles of the "
                                      "blade's clamped ends (its stiffness M0(1 + k|s|) from the middle)")
    width: float = num(1e-6, 1.0, "m", "the hole's largest width across the blade (its diagonal at the middle)")


class Blade(Strict):
    kind: Literal["blade"]
    E: float = num(1e8, 1e13, "Pa", "Young's modulus of the blade")
    thickness: float = num(1e-6, 1e-2, "m", "thickness of the blade")
    width: float = num(1e-4, 1.0, "m", "total width of the blade(s)")
    length: float = num(1e-3, 10.0, "m", "free length λ of the blade between its clamps")
    mounting: Literal["direct", "inverted"] = Field("direct", description="direct (the bob hangs below the "
                                                    "blade) or inverted (the bob stands on it)")
    density: float | None = num(100.0, 3e4, "kg/m^3", "density of the blade's material (for its inertia and "
                                "weight; without it they are not estimated)", default=None)
    hole: Hole | None = Field(None, description="a hole through the blade (an inverted blade only)")


Suspension = Annotated[Union[Knife, Thread, Blade], Field(discriminator="kind")]


class Support(Strict):
    compliance: float = num(0.0, 1e-3, "m/N", "horizontal compliance K of the support at the pivot", open_lo=False)
    mass: float = num(0.0, 1e6, "kg", "mass M of the support that moves with the pivot", open_lo=False, default=0.0)


class Drift(Strict):
    rate: float = num(-1e3, 1e3, "m/s", "rate dl/dt at which the length grows (negative: shortens)", open_lo=False)


class Clamping(Strict):
    """The clamping errors of a blade (Haag n°31): the clamp's tangent Ox makes the angle i with the vertical,
    and the centre of gravity is off the tangent AT at the blade's lower clamp by the angle i'."""
    i: float = num(-0.1, 0.1, "rad", "i: angle from the vertical to the tangent Ox of the blade at its upper "
                   "clamp (Haag (116))", open_lo=False)
    i_prime: float = num(-0.1, 0.1, "rad", "i': angle from the tangent AT of the blade at its lower clamp to the "
                         "line AG to the centre of mass (Haag (116))", open_lo=False, default=0.0)


class Temperature(Strict):
    """The thermal coefficients of a blade pendulum, per kelvin, named by the memoir's symbols: the blade's length,
    width and thickness grow by α (so that its I = e³h/12 grows by 4α), its modulus E by β, and the pendulum's a and
    R by α' (``alpha_prime``)."""
    alpha: float = num(-2e-5, 1e-4, "1/K", "α: linear expansion coefficient of the blade's material", open_lo=False)
    beta: float = num(-1e-3, 1e-3, "1/K", "β: thermoelastic coefficient of the blade's Young's modulus, dE/(E dϑ)",
                      open_lo=False)
    alpha_prime: float = num(-2e-5, 1e-4, "1/K", "α': linear expansion coefficient of the pendulum (bob and rod: "
                             "its a and R grow by it)", open_lo=False)


class Wanted(Strict):
    quantities: list[Literal["period", "swing", "rate", "sensitivity", "temperature"]] = Field(
        ["period"], min_length=1, max_length=5,
        description="what to report (sensitivity: d log T/d log g, dT/T per dg/g at fixed hardware; temperature: "
                    "d log T/dϑ per kelvin, dT/T per degree, from the scene's temperature coefficients)")
    tolerance: float = num(1e-15, 1e-1, "1", "relative tolerance on the period")
    target_period: float | None = num(1e-3, 1e4, "s", "the period the instrument is meant to have (for "
                                      "the rate in s/day)", default=None)


class Scene(Strict):
    name: str = Field("", max_length=200, description="a title")
    g: float = num(9.7, 9.9, "m/s^2", "local acceleration of gravity", open_lo=False)
    amplitude: float = num(0.0, 1.0, "rad", "semi-amplitude α of the swing", open_lo=False)
    bob: Bob
    suspension: Suspension
    support: Support | None = None
    drift: Drift | None = None
    clamping: Clamping | None = Field(None, description="the clamping errors of a direct blade (Haag n°31, "
                                      "(247), (249))")
    temperature: Temperature | None = Field(None, description="the thermal coefficients of a blade suspension and "
                                            "of the pendulum, for the temperature coefficient")
    wanted: Wanted

    @model_validator(mode="after")
    def consistent(self) -> "Scene":
        """Inputs that contradict each other are errors (each message names the keys)."""
        sus = self.suspension
        if self.clamping is not None and not (isinstance(sus, Blade) and sus.mounting == "direct"):
            why = ("no scene effect evaluates the inverted blade's (318) yet" if isinstance(sus, Blade) else
                   "the clamping errors are those of a blade (a thread's clamps play no part, Haag n°58)")
            raise ValueError(f"clamping is given with a{'n inverted blade' if isinstance(sus, Blade) else ' ' + sus.kind}"
                             f": {why} (remove clamping)")
        if self.temperature is not None and not isinstance(sus, Blade):
            raise ValueError(f"temperature is given with a {sus.kind} suspension: the memoirs' temperature "
                             "coefficients are those of a pendulum on a blade; remove "
                             "temperature")
        if "temperature" in self.wanted.quantities and self.temperature is None:
            raise ValueError("temperature: required when wanted.quantities asks for 'temperature' (the coefficients "
                             "alpha, beta, alpha_prime, per kelvin)")
        if self.temperature is not None and "temperature" not in self.wanted.quantities:
            raise ValueError("temperature is given but wanted.quantities does not ask for 'temperature'")
        if any(unicodedata.category(ch) in ("Cc", "Cf", "Cs", "Co", "Cn") for ch in self.name):
            raise ValueError("name: must be text without control or format characters")
        if isinstance(sus, Thread):
            if self.bob.a is not None:
                raise ValueError(f"bob.a = {self.bob.a:g} is given with a thread suspension: the thread's length "
                                 "sets it (remove bob.a)")
        elif self.bob.a is None:
            raise ValueError(f"bob.a: required with a {sus.kind} suspension (the distance from the pivot to "
                             "the centre of mass, m)")
        if isinstance(sus, Blade) and sus.mounting == "inverted":
            for key, given in (("support", self.support), ("drift", self.drift)):
                if given is not None:
                    raise ValueError(f"{key} is given with an inverted blade: no Result of the engine treats the "
                                     f"inverted blade with a {'compliant support' if key == 'support' else 'length drift'}"
                                     f" (remove {key})")
        if isinstance(sus, Blade) and sus.hole is not None:
            if sus.mounting != "inverted":
                raise ValueError("suspension.hole is given with a direct blade: the Results treat the rhombus hole for "
                                 "the inverted blade only (make mounting \"inverted\" or remove hole)")
            if not sus.hole.width <= 0.9 * sus.width:
                raise ValueError(f"suspension.hole.width = {sus.hole.width:g} leaves less than a tenth of "
                                 f"suspension.width = {sus.width:g} at the middle (expected ≤ 0.9 × width)")
        if isinstance(sus, Blade) and sus.thickness >= sus.width:
            raise ValueError(f"suspension.thickness = {sus.thickness:g} is not smaller than suspension.width = "
                             f"{sus.width:g}: not a blade")
        if "rate" in self.wanted.quantities and self.wanted.target_period is None:
            raise ValueError("wanted.target_period: required when wanted.quantities asks for 'rate' (s)")
        if self.wanted.target_period is not None and "rate" not in self.wanted.quantities:
            raise ValueError("wanted.target_period is given but wanted.quantities does not ask for 'rate'")
        if len(set(self.wanted.quantities)) != len(self.wanted.quantities):
            raise ValueError(f"wanted.quantities = {self.wanted.quantities} repeats a quantity")
        return self


def json_schema() -> dict:
    """The schema as JSON Schema (for editors and for docs/scenes.md)."""
    return Scene.model_json_schema()

