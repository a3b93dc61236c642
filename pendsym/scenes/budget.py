"""Select → estimate → drop → choose the cheapest adequate model → budget, for a hardware scene.

1. Select every declared effect that applies to the instrument (:mod:`pendsym.scenes.effects`).
2. Estimate each from the memoir's printed statement; drop the smallest while their sum stays
   within half the tolerance (a dropped effect's Result is never built).
3. Build only the closure of the kept effects' Results (:mod:`pendsym.scenes.index`) and evaluate each
   derived form as a numeric program (:mod:`pendsym.scenes.program`: its distinct nodes once each, by mpmath at
   GUARD = 45 digits, rounded to 30, then to a double); ``pendsym derive`` stores the programs.
4. For each kept effect take the first-order Result when its next-order error is within a
   share of the tolerance, else the effect's more complete model (e.g. the exact swing).
5. The swing time T = T0 Π(1 + ΔT/T); its estimated error is the sum of the kept effects'
   errors, the dropped effects' sizes and the products of the kept effects (their interaction,
   which no Result gives).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import sympy as sp

from .. import registry
from ..scene import SceneError
from . import index, schema
from .evaluate import _log_slope, _value, programs
from .effects import Coefficient, Effect, Instrument, coefficients, effects, pending

SECONDS_PER_DAY = 86400.0


@dataclass(frozen=True)
class Row:
    key: str
    title: str
    source: str
    result: str
    estimate: float
    value: float | None           # ΔT/T used (None: dropped, not built)
    error: float                  # estimated error of the value (or the dropped size)
    status: str                   # "kept", "dropped", "not available"
    model: str


@dataclass(frozen=True)
class Budget:
    scene: schema.Scene
    inst: Instrument
    swing: float
    error: float                  # relative, estimated
    rows: tuple[Row, ...]
    interaction: float
    built: int
    total: int
    T0: float                     # the linear base's swing time (the rigid pendulum's, or a base effect's)
    base: str                     # what the base is, for the output
    sensitivity: float | None = None          # d log T/d log g at fixed hardware
    sensitivity_error: float | None = None
    temperature: float | None = None          # d log T/dϑ, per kelvin (when asked)
    temperature_error: float | None = None
    temperature_model: str = ""

    @property
    def period(self) -> float:
        return 2 * self.swing

    @property
    def rate(self) -> float | None:
        """Seconds gained per day (negative: lost) against the target period."""
        target = self.scene.wanted.target_period
        return None if target is None else -(self.period - target) / target * SECONDS_PER_DAY

    @property
    def within(self) -> bool:
        return self.error <= self.scene.wanted.tolerance


def instrument(sc: schema.Scene) -> Instrument:
    """The hardware as numbers, with the rigid pendulum's linear base T0 = π√(l/g), l = (a² + R²)/a."""
    sus, bob = sc.suspension, sc.bob
    extra: dict = {}
    if isinstance(sus, schema.Thread):
        mu = bob.mass * sc.g / sus.EA
        a = sus.length * (1 + mu)            # the static stretch, l0 = λ(1 + mg/e) (the thread law)
        extra = {"thread_length": sus.length, "thread_EA": sus.EA}
    else:
        a = bob.a
    if isinstance(sus, schema.Blade):
        extra = {"blade_length": sus.length, "blade_EI": sus.E * sus.width * sus.thickness**3 / 12,
                 "blade_width": sus.width}
        if sus.hole is not None:
            extra["blade_hole"] = sus.hole.width
        if sus.density is not None:
            extra["blade_mass"] = sus.density * sus.width * sus.thickness * sus.length
    if sc.clamping is not None:
        extra.update(clamping_i=sc.clamping.i, clamping_i_prime=sc.clamping.i_prime)
    if sc.support is not None:
        extra.update(support_K=sc.support.compliance, support_M=sc.support.mass)
    if sc.drift is not None:
        extra["drift_rate"] = sc.drift.rate
    if sc.temperature is not None:
        extra.update(thermal_alpha=sc.temperature.alpha, thermal_beta=sc.temperature.beta,
                     thermal_alpha_prime=sc.temperature.alpha_prime)
    if isinstance(sus, schema.Blade) and sus.mounting == "inverted":
        # the rigid pendulum stands above its pivot: it has no period; a base effect gives it
        l = k = T0 = math.nan
        extra["inverted"] = True
    else:
        l = (a * a + bob.R**2) / a
        k = math.sqrt(sc.g / l)
        T0 = math.pi / k
    inst = Instrument(sus.kind, bob.mass, a, bob.R, sc.g, sc.amplitude, l, k, T0, **extra)
    _within_theories(inst)
    return inst


def _within_theories(inst: Instrument) -> None:
    """Refuse a scene outside the perturbation theories' reach, naming the keys (before any build)."""
    if inst.kind == "blade":
        u = inst.blade_u
        if not 1e-6 <= u <= 700:
            raise SceneError(f"suspension: u = λ√(mg/EI) = {u:.4g} is outside [1e-06, 700] (the uniform blade's "
                             "Results are declared there): change suspension.length, thickness, width or E")
        if not (1e-2 <= inst.a <= 5 and 1e-3 <= inst.R <= 2):
            raise SceneError(f"bob.a = {inst.a:g}, bob.R = {inst.R:g}: with a blade, a must be in [0.01, 5] m and "
                             "R in [0.001, 2] m (the blade's Results are declared there)")
    if inst.kind == "thread" and inst.mu > 0.1:
        raise SceneError(f"suspension.EA = {inst.thread_EA:g}: the thread stretches by mg/e = {inst.mu:.3g} "
                         "under the bob, beyond a perturbation (expected mg/e ≤ 0.1)")
    if inst.support_K:
        delta = inst.support_K * inst.m * inst.g * inst.a / (2 * inst.l**2)
        if delta > 1e-2:
            raise SceneError(f"support.compliance = {inst.support_K:g}: the support's sway would change the period "
                             f"by {delta:.3g}, beyond a perturbation (expected ≤ 0.01)")
        dyn = inst.support_K * inst.support_M * inst.g / inst.l
        if dyn > 0.1:
            raise SceneError(f"support.mass = {inst.support_M:g}: K M g/l = {dyn:.3g}, the support's own vibration "
                             "is not slow beside the pendulum (expected ≤ 0.1)")
    if inst.drift_rate:
        aT = abs(inst.drift_a * inst.T0)
        if aT > 0.1:
            raise SceneError(f"drift.rate = {inst.drift_rate:g}: the length changes by {aT:.3g} of itself in one "
                             "swing, beyond a perturbation (expected ≤ 0.1)")


# No Result gives the coupling of two effects (e.g. the circular error of a pendulum whose length
# grows: its amplitude decays as it swings).  The product of the factors (1 + ΔT_i/T) keeps the
# product terms; what they miss is bounded by COUPLING Σ|ΔT_i/T · ΔT_j/T|.  Measured: the bucket
# scene's integration (tests/test_scene_instruments.py) shows a coupling of circular error and
# length drift of −2.1 × the product, so 1 would be too small.
COUPLING = 4.0


def _unaccounted_pairs(kept: list[Effect], rels: dict[str, float]) -> list[tuple[str, str]]:
    """The pairs of kept effects whose coupling no kept Result gives (see ``Effect.couples``)."""
    given = {frozenset((x, y)) for e in kept for x in (e.key, *e.couples) for y in (e.key, *e.couples) if x != y}
    names = list(rels)
    return [(x, y) for n, x in enumerate(names) for y in names[n + 1:] if frozenset((x, y)) not in given]


def _drop(applicable: list[tuple[Effect, float]], tol: float) -> set[str]:
    """Drop the smallest estimates while their sum stays within half the tolerance."""
    dropped, total = set(), 0.0
    for eff, est in sorted(applicable, key=lambda p: abs(p[1])):
        if math.isinf(est) or total + abs(est) > tol / 2:
            break
        dropped.add(eff.key)
        total += abs(est)
    return dropped


def _values(eff: Effect | Coefficient, inst: Instrument, built: dict[str, sp.Basic]) -> dict[str, float]:
    """The Result's symbols at this scene: the effect's map, then what the Results it uses give (in order)."""
    values = dict(eff.symbols(inst))
    used: dict[str, float] = {}
    for rid in eff.uses:
        values.update(eff.given(inst, used) if eff.given else {})
        used[rid] = _value(built[rid], values, rid)
    values.update(eff.given(inst, used) if eff.given else {})
    return values


def solve(sc: schema.Scene) -> Budget:
    inst = instrument(sc)
    tol = sc.wanted.tolerance
    found = [e for e in effects() if e.applies(inst)]
    for e in found:                      # outside a Result's reach (e.g. unstable): refused before any build
        reason = e.refuse(inst) if e.refuse else None
        if reason:
            raise SceneError(reason)
    coefs = [c for c in coefficients() if c.quantity in sc.wanted.quantities and c.applies(inst)]
    for q in ("temperature",):
        if q in sc.wanted.quantities and not any(c.quantity == q for c in coefs):
            why = next((p.title for p in pending() if p.applies(inst) and q in p.key), "no Result gives it")
            raise SceneError(f"wanted.quantities asks for '{q}', which the engine cannot give for this scene: {why} "
                             f"(remove '{q}')")
    replaced = {k for e in found for k in e.replaces}
    applicable = [(e, float(e.estimate(inst))) for e in found if e.key not in replaced]
    dropped = _drop(applicable, tol)
    kept = [e for e, _ in applicable if e.key not in dropped]
    kept_keys = {e.key for e in kept}
    for e in kept:
        if e.scale_by and e.scale_by not in kept_keys:
            raise SceneError(f"effect {e.key} is kept but {e.scale_by}, which it scales, is dropped")
    try:
        ids = [e.result for e in kept] + [u for e in kept for u in e.uses] + [c.result for c in coefs] + \
            [u for c in coefs for u in c.uses]
        built, closure_size, total = programs(ids) if ids else ({}, 0, len(index.entries()))
    except registry.UnknownResult as exc:
        raise SceneError(f"a memoir's scene effect names {exc}") from None
    share = tol / (4 * max(1, len(kept)))
    rels: dict[str, float] = {}
    rows: list[Row] = []
    T0, base = inst.T0, f"rigid {inst.kind} pendulum, l = (a² + R²)/a = {inst.l:.9g} m, T0 = π√(l/g)"
    sens, sens_err, base_err = (-0.5, 0.0, 0.0) if not inst.inverted else (None, None, 0.0)
    for eff, est in applicable:
        if eff.key in dropped:
            rows.append(Row(eff.key, eff.title, eff.source, eff.result, est, None, abs(est), "dropped",
                            "estimated from the printed statement, below the tolerance"))
            continue
        values = _values(eff, inst, built)
        value = _value(built[eff.result], values, eff.result)
        if eff.base:
            T0 = float(eff.relative(value, inst))
            if not (math.isfinite(T0) and T0 > 0):
                raise SceneError(f"{eff.result} gives no real period for this scene (unstable)")
            base_err = float(eff.error(0.0, inst))
            base = f"{eff.title}, T0 from {eff.result}"
            if eff.g_exponents and eff.sensitivity:
                slope = _log_slope(built[eff.result], values, eff.g_exponents, eff.result)
                sens, sens_err = float(eff.sensitivity(slope, inst)), 0.0
            rows.append(Row(eff.key, eff.title, eff.source, eff.result, est, math.inf, base_err, "kept",
                            f"{eff.model} ({eff.result}): the base, T0 = {T0:.12g} s"))
            continue
        rel = float(eff.relative(value, inst))
        if eff.scale_by:
            rel *= rels[eff.scale_by]
        err = float(eff.error(rel, inst))
        model = f"{eff.model} ({eff.result}), estimated error {err:.2g} ≤ {share:.2g}"
        if err > share:
            if eff.exact is not None:
                first_err = err
                rel, err, how = eff.exact(inst)
                if eff.scale_by:
                    rel *= rels[eff.scale_by]
                model = f"{how}: the {eff.model}'s error {first_err:.2g} exceeds {share:.2g}"
            else:
                model = f"{eff.model} ({eff.result}); its error {err:.2g} exceeds the share {share:.2g} " \
                        "and the engine has no more complete model"
        rels[eff.key] = rel
        rows.append(Row(eff.key, eff.title, eff.source, eff.result, est, rel, err, "kept", model))
    for p in pending():
        if p.applies(inst):
            rows.append(Row(p.key, p.title, p.source, "", math.nan, None, math.nan, "not available",
                            "not in the engine yet: not counted in the error"))
    factor = math.prod(1 + r for r in rels.values())
    interaction = COUPLING * sum(abs(rels[x] * rels[y]) for x, y in _unaccounted_pairs(kept, rels))
    error = sum(r.error for r in rows if r.status != "not available") + interaction
    if sens is not None:
        # the base's sensitivity is exact for it; each kept effect adds its d(ΔT/T)/d log g when it gives it, and
        # is bounded by 2|S||ΔT/T| when not (an effect ∝ 1/ε near a critical distance varies with g as fast as the
        # base); a dropped effect by 2|S| × its size
        base_sens = sens
        for eff, _ in applicable:
            if eff.base:
                continue
            if eff.key not in rels:
                sens_err += 2 * abs(base_sens) * abs(next(r.error for r in rows if r.key == eff.key))
            elif eff.g_slope is not None:
                slope, slope_err = eff.g_slope(rels[eff.key], inst, base_sens)
                sens += float(slope)
                sens_err += float(slope_err)
            else:
                sens_err += 2 * abs(base_sens) * abs(rels[eff.key])
    temp, temp_err, temp_model = _coefficient(coefs, "temperature", inst, built, rels)
    return Budget(sc, inst, T0 * factor, error, tuple(rows), interaction, closure_size, total, T0, base, sens, sens_err,
                  temp, temp_err, temp_model)


def _coefficient(coefs: list[Coefficient], quantity: str, inst: Instrument, built: dict[str, sp.Basic],
                 rels: dict[str, float]) -> tuple[float | None, float | None, str]:
    """The coefficient ``quantity`` of the linear period from the one memoir Coefficient that applies, its error, and
    what it is.  The kept effects' own dependence on it (but those the coefficient ``covers``) is not given by a Result:
    bounded by 2|c| Σ|ΔT/T| (an effect
    ∝ 1/ε near a critical distance varies as ε ∝ n², i.e. twice as fast as log T; the others more slowly)."""
    mine = [c for c in coefs if c.quantity == quantity]
    if not mine:
        return None, None, ""
    if len(mine) > 1:
        raise SceneError(f"two memoir coefficients give '{quantity}' for this scene: {[c.key for c in mine]}")
    c = mine[0]
    values = _values(c, inst, built)
    value = _value(built[c.result], values, c.result)
    coef = float(c.coefficient(value, inst, values))
    err = float(c.error(coef, inst)) + 2 * abs(coef) * sum(abs(r) for k, r in rels.items() if k not in c.covers)
    return coef, err, f"{c.title}: {c.model} ({c.result}; {c.source})"


# ----------------------------------------------------------------- output
def _g(x: float | None, digits: int = 3) -> str:
    if x is None:
        return "—"
    if isinstance(x, float) and math.isnan(x):
        return "?"
    if isinstance(x, float) and math.isinf(x):
        return "(defines it)"
    return f"{x:+.{digits}e}"


def text(b: Budget, name: str) -> str:
    sc, tol = b.scene, b.scene.wanted.tolerance
    lines = [f"{name}"]
    q = sc.wanted.quantities
    if "period" in q:
        lines.append(f"  period      {b.period:.12g} s   ± {b.error * b.period:.2g} s (relative {b.error:.2g})")
    if "swing" in q:
        lines.append(f"  swing time  {b.swing:.12g} s   ± {b.error * b.swing:.2g} s")
    if "sensitivity" in q:
        if b.sensitivity is None:
            lines.append("  sensitivity not available for this base")
        else:
            lines.append(f"  sensitivity S = d log T/d log g = {b.sensitivity:+.6g} ± {b.sensitivity_error:.2g} "
                         "(dT/T = S dg/g at fixed hardware)")
    if "temperature" in q:
        lines.append(f"  temperature coefficient d log T/dϑ = {b.temperature:+.6g} ± {b.temperature_error:.2g} per K "
                     f"(dT/T per kelvin: a rate of {-b.temperature * SECONDS_PER_DAY:+.4g} s/day per K)")
    if "rate" in q:
        lines.append(f"  rate        {b.rate:+.4g} s/day against {sc.wanted.target_period:g} s "
                     f"(± {b.error * SECONDS_PER_DAY:.2g} s/day)")
    verdict = "within" if b.within else "NOT within"
    lines.append(f"  estimated error {b.error:.2g} is {verdict} the tolerance {tol:g}; "
                 f"{b.built} of {b.total} Results built (the closure of the kept effects)")
    lines.append(f"  base: {b.base} = {b.T0:.12g} s")
    lines.append("")
    lines.append(f"  {'effect':<58} {'ΔT/T':>12} {'error':>10}  {'status':<13} source")
    for r in b.rows:
        val = r.value if r.status == "kept" else (r.estimate if r.status == "dropped" else None)
        err = "?" if math.isnan(r.error) else f"{r.error:.2g}"
        lines.append(f"  {r.title:<58} {_g(val):>12} {err:>10}  {r.status:<13} {r.source}")
    if b.interaction:
        lines.append(f"  {f'coupling of the kept effects ({COUPLING:g} × products)':<58} {'':>12} {b.interaction:>10.2g}")
    lines.append("")
    for r in b.rows:
        lines.append(f"  {r.key}: {r.model}")
    if b.temperature_model:
        lines.append(f"  temperature: {b.temperature_model}")
    return "\n".join(lines)


def as_json(b: Budget, name: str) -> dict:
    def num(x):
        return None if x is None or (isinstance(x, float) and not math.isfinite(x)) else x
    return {
        "scene": name, "swing_time_s": b.swing, "period_s": b.period, "rate_s_per_day": b.rate,
        "relative_error": b.error, "tolerance": b.scene.wanted.tolerance, "within_tolerance": b.within,
        "results_built": b.built, "results_total": b.total,
        "base": {"kind": b.inst.kind, "inverted": b.inst.inverted, "l_m": num(b.inst.l), "T0_s": b.T0, "model": b.base},
        "sensitivity": num(b.sensitivity), "sensitivity_error": num(b.sensitivity_error),
        "temperature_coefficient_per_K": num(b.temperature), "temperature_coefficient_error": num(b.temperature_error),
        "temperature_model": b.temperature_model or None,
        "interaction": b.interaction,
        "budget": [{"effect": r.key, "title": r.title, "source": r.source, "result": r.result or None,
                    "estimate": num(r.estimate), "value": num(r.value), "error": num(r.error), "status": r.status,
                    "model": r.model} for r in b.rows],
    }
