"""Haag 1935 in scenes: the uniform blade's effect on the period (chapter III, n°50: n² = Kgz/R²
with K of (36) and z of (30)), against a knife edge at the blade's lower clamp; and, for a short
blade (λ/a ≤ 0.1, chapter VI), its isochronism error (244), its inertia (251) and weight (253), and its
clamping errors (249).

ΔT/T = k/n − 1 with k² = ga/(a² + R²) the rigid pendulum pivoting at the clamp.  The short blade's
Results neglect λ² and R² before a² (n°78–81); their errors are estimated as that next order.  The
isochronism error (244) contains the circular error θ0²/16 of the rigid pendulum, which Charbonnier's
effect already counts: the blade's part is (244) − θ0²/16.  What the engine does not give for a blade
is listed by :func:`pending`: the clamping errors when the scene gives no angles (with them, (249) and (247) for
a short blade), and the finite-amplitude terms, the blade's mass and the clamping errors for a blade that is not
short.

The inverted blade (chapter VIII: a gravity meter) has no rigid-pendulum base: the base is the slow vibration's
n² of the inverted uniform blade (eq034.n2_inverted: n°101's u → iu, g → −g on (34), (36), (30)), whose derivative
in g (u ∝ √g) gives the sensitivity d log T/d log g; its finite amplitude is (283) ΔT/T = −(θ0²/16)GC with G of
(314) and C of (317) (n°103), ε = (a1 − a)/λ (312) with a1 of (310); it replaces the circular error θ0²/16 of a
hanging pendulum.  A scene outside the stability windows (u ≥ π/2, where no a > 0 is stable (311), or a ≥ a1 (305),
(310)) is refused before any build.
"""
from __future__ import annotations

import math

from pendsym.scenes.effects import Coefficient, Effect, Instrument, Pending

SHORT = 0.1          # λ/a at most: chapter VI's short blade


def _direct(inst: Instrument) -> bool:
    return inst.kind == "blade" and not inst.inverted


def _inverted_any(inst: Instrument) -> bool:
    """An inverted blade, with or without a hole."""
    return inst.kind == "blade" and inst.inverted


def _inverted(inst: Instrument) -> bool:
    """The inverted uniform blade (chapter VIII)."""
    return _inverted_any(inst) and inst.blade_hole is None


def _rhombus(inst: Instrument) -> bool:
    """The inverted blade with a rhombus hole (chapter IX, n°107–110)."""
    return _inverted_any(inst) and inst.blade_hole is not None


def _critical(inst: Instrument) -> float:
    """a1 = λ/(u tan u), (310) as printed: the guard of the refusal and the estimate only (the values come from
    the Results)."""
    u = inst.blade_u
    return inst.blade_length / (u * math.tan(u))


def _epsilon(inst: Instrument) -> float:
    """ε = (a1 − a)/λ (312), from the printed (310) (for the estimates)."""
    return (_critical(inst) - inst.a) / inst.blade_length


def _G_printed(inst: Instrument) -> float:
    """G of (314) as printed (for the estimates)."""
    u = inst.blade_u
    return (1 / math.sin(u) ** 2 + 1 / (u * math.tan(u))) / (2 * _epsilon(inst))


MAX_AMPLITUDE_TERM = 0.01     # θ0²G/16 at most: (283) is the first term in θ0²G


def _unstable(inst: Instrument) -> str | None:
    """The inverted pendulum is stable only when the blade's couple exceeds the weight's (n°100–101)."""
    u = inst.blade_u
    if u >= math.pi / 2:
        return (f"suspension: u = λ√(mg/EI) = {u:.4g} ≥ π/2: the inverted blade cannot hold the bob at any a > 0 "
                "(Haag (311): mg < π²EI/(4λ²)); make the blade stiffer or shorter, or the bob lighter")
    a1 = _critical(inst)
    if inst.a >= a1:
        return (f"bob.a = {inst.a:g} is not below the critical distance a1 = λ/(u tan u) = {a1:.6g} m (Haag (305), "
                "(310)): the blade's couple does not exceed the weight's, the inverted pendulum is unstable")
    term = inst.alpha**2 * _G_printed(inst) / 16
    if term > MAX_AMPLITUDE_TERM:
        return (f"amplitude = {inst.alpha:g}: θ0²G/16 = {term:.3g} near the critical distance (ε = {_epsilon(inst):.3g}), "
                f"beyond the perturbation theory of (283) (expected ≤ {MAX_AMPLITUDE_TERM:g})")
    return None


def _slope_over_epsilon(rel: float, inst: Instrument, S: float) -> tuple[float, float]:
    """d(ΔT/T)/d log g of an effect ∝ 1/ε (G of (314), (320)): ε ∝ n² to the leading order, so d log ε/d log g =
    d log n²/d log g = −2S and d(ΔT/T)/d log g = 2S ΔT/T; its error: the next order in ε, and the effect's other
    dependence on g (through u ∝ √g, of relative size 1/|2S|)."""
    slope = 2 * S * rel
    return slope, abs(slope) * (_epsilon(inst) + 1 / max(abs(2 * S), 1))


def _inverted_symbols(inst: Instrument) -> dict[str, float]:
    """The blade's symbols (:func:`_blade`) and the amplitude θ0 of (283)."""
    return {**_blade(inst), "theta_0": inst.alpha}


A1, G314, C317 = "haag1935.eq310.a1", "haag1935.eq314.G", "haag1935.eq317.C"


def _given_for_283(a1: str, G: str, C: str):
    """The symbols of (283) from the Results that give them: ε from a1 (312), then G and C."""
    def given(inst: Instrument, used: dict[str, float]) -> dict[str, float]:
        out: dict[str, float] = {}
        if a1 in used:
            out["varepsilon"] = (used[a1] - inst.a) / inst.blade_length
        if G in used:
            out["G"] = used[G]
        if C in used:
            out["C"] = used[C]
        return out
    return given


# ε from a1 of (310) (312), then G of (314) and C of (317)
_isochronism_given = _given_for_283(A1, G314, C317)


def _inverted_massive(inst: Instrument) -> bool:
    return _inverted(inst) and inst.blade_mass is not None


def _inverted_mass_symbols(inst: Instrument) -> dict[str, float]:
    """The symbols of (319), (320): m, m', u, λ, R (ε comes from a1 of (310))."""
    return {"m": inst.m, "m'": inst.blade_mass, "u": inst.blade_u, "lambda": inst.blade_length, "R": inst.R}


def _weight_estimate(inst: Instrument) -> float:
    """(320) as printed: (m'/(8mε))(1/u² − 1/sin²u), in absolute value."""
    u = inst.blade_u
    return abs(inst.blade_mass / (8 * inst.m * _epsilon(inst)) * (1 / u**2 - 1 / math.sin(u) ** 2))


MAX_WEIGHT_TERM = 0.1        # (320) at most: beyond it the weight is no perturbation (at 1/2 it overturns the bob)


def _too_heavy(inst: Instrument) -> str | None:
    """The blade's weight moves the critical distance by 2ε(ΔT/T) of (320): refused beyond a perturbation."""
    term = _weight_estimate(inst)
    if term > MAX_WEIGHT_TERM:
        return (f"suspension.density: the blade's weight (m'/m = {inst.blade_mass / inst.m:.3g}) changes "
                f"the period by {term:.3g} (Haag (320)), beyond a perturbation (expected ≤ {MAX_WEIGHT_TERM:g}; at 1/2 "
                "it overturns the bob): the inverted pendulum is too close to its critical distance for this blade")
    return None


def _inertia_estimate(inst: Instrument) -> float:
    """(319) as printed: (m'/m)λ²(6u − 8 sin u + sin 2u)/(8u(R²u² sin²u + λ²)), in absolute value."""
    u, lam = inst.blade_u, inst.blade_length
    return abs(inst.blade_mass / inst.m * lam**2 * (6 * u - 8 * math.sin(u) + math.sin(2 * u))
               / (8 * u * (inst.R**2 * u**2 * math.sin(u) ** 2 + lam**2)))


def _blade(inst: Instrument) -> dict[str, float]:
    return {"a": inst.a, "R": inst.R, "lambda": inst.blade_length, "u": inst.blade_u, "g": inst.g}


def _short(inst: Instrument) -> bool:
    return _direct(inst) and inst.blade_short <= SHORT


def _massive(inst: Instrument) -> bool:
    return _short(inst) and inst.blade_mass is not None


def _short_symbols(inst: Instrument) -> dict[str, float]:
    """The symbols of (244), (251), (253): θ0, λ, a, u, m, m'."""
    return {"theta_0": inst.alpha, "lambda": inst.blade_length, "a": inst.a, "u": inst.blade_u, "m": inst.m,
            "m'": inst.blade_mass if inst.blade_mass is not None else math.nan}


def _isochronism_estimate(inst: Instrument) -> float:
    """(θ0²/16)(λ/a)(7/(4u) + 1/u²): (245)'s 7λ/(4au) for u > 4, bounded by 1/u² as u → 0 (where the
    bracket of (244) grows like 1/u², i.e. like M/λ²)."""
    u = inst.blade_u
    return inst.alpha**2 / 16 * inst.blade_short * (7 / (4 * u) + 1 / u**2)


def _next_order(rel: float, inst: Instrument, *extra: float) -> float:
    """|ΔT/T| × (λ/a + R²/a² + extra): the terms the short blade's Results neglect (n°78–81)."""
    return abs(rel) * (inst.blade_short + (inst.R / inst.a) ** 2 + sum(extra))


CLAMP_SUM = "haag1935.eq247.sum"


def _clamped(inst: Instrument) -> bool:
    return _short(inst) and inst.clamping_i is not None


def _clamping_symbols(inst: Instrument) -> dict[str, float]:
    """The symbols of (247) and (249): i, i', λ, a, u (j comes from (247))."""
    return {"i": inst.clamping_i, "i'": inst.clamping_i_prime, "lambda": inst.blade_length, "a": inst.a,
            "u": inst.blade_u}


def _clamping_j(inst: Instrument, used: dict[str, float]) -> dict[str, float]:
    """j of (247): j + i + i' = (λ/(au))(iU_1 + i'U_2), the pendulum's tilt at equilibrium (n°32)."""
    if CLAMP_SUM not in used:
        return {}
    return {"j": used[CLAMP_SUM] - inst.clamping_i - inst.clamping_i_prime}


def _clamping_estimate(inst: Instrument) -> float:
    """(λ/(16a))(3.8i² + 4.7|ij| + 2j²)/max(u, 1): (250)'s −(λ/(16au))(3i² + 4ij + 2j²) for u > 5, each
    coefficient bounded over all u by the derived c_ii, c_ij, c_jj of (249) (16u|c| ≤ 3.7, 4.6, 2 and |c| ≤ 0.17,
    0.21, 0.075 as u → 0); j from (247)."""
    i, ip, u = inst.clamping_i, inst.clamping_i_prime, inst.blade_u
    j = inst.blade_short / u * (i / math.sinh(u) + ip / math.tanh(u)) - i - ip
    return inst.blade_short * (3.8 * i * i + 4.7 * abs(i * j) + 2 * j * j) / (16 * max(u, 1.0))


def _clamping_error(rel: float, inst: Instrument) -> float:
    """|ΔT/T| × (2R²/a² + (λ/a)(1 + 8/u²) + i² + i'²).  (249) is first order in λ/a with R² neglected before a²
    (n°80), and i³, i'³ are neglected in (116) (ΔT/T is even in the angles: the next order is theirs squared).  The
    coefficients of the next order in λ/a and R²/a² are not given by a Result: they were measured against the exact
    tilted blade (pendsym.nonlinear_tilt, i = 0.02, i' = 0.01): the relative residual is 1.9R²/a² + c(λ/a) with
    c = 1.07 at u = 3.46 and 3.1 at u = 1.73, which 1 + 8/u² bounds; tests/test_scene_clamping.py checks the bound at
    another u."""
    u = inst.blade_u
    return abs(rel) * (2 * (inst.R / inst.a) ** 2 + inst.blade_short * (1 + 8 / u**2)
                       + inst.clamping_i**2 + inst.clamping_i_prime**2)


def effects() -> tuple[Effect, ...]:
    return (
        Effect("blade", "elastic blade instead of a knife edge (small oscillations)",
               "Haag 1935, ch. III n°50, eq. (34) with (36), (30)", "haag1935.eq034.n2_z_uniform",
               applies=_direct,
               estimate=lambda i: math.inf,           # it defines the suspension: always kept
               symbols=_blade, relative=lambda n2, i: i.k / math.sqrt(n2) - 1,
               error=lambda rel, i: 1e-14 * abs(rel), order=5,
               model="linear theory of the blade, exact for small oscillations (evaluated at 30 digits)"),
        Effect("blade_isochronism", "short blade at finite amplitude (its part of the isochronism error)",
               "Haag 1935, ch. VI n°79, eq. (244) less θ0²/16", "haag1935.eq244.dT",
               applies=lambda i: _short(i) and i.alpha > 0, estimate=_isochronism_estimate,
               symbols=_short_symbols, relative=lambda value, i: value - i.alpha**2 / 16,
               # first order in λ/a (its bracket, 16|rel|/θ0², is the true small parameter when u is
               # small), R² neglected before a², and the next order in θ0²
               error=lambda rel, i: _next_order(rel, i, 16 * abs(rel) / i.alpha**2, i.alpha**2),
               model="short uniform blade, first order in λ/a and in θ0²", order=15,
               # (244) is (Q'/Q)θ0²/16 (111) relative to the blade's linear period: the circular error of the
               # pendulum on the blade; its product with the circular error is in its error (the θ0² term)
               couples=("blade", "circular")),
        Effect("blade_inertia", "inertia of the short blade (its mass m')",
               "Haag 1935, ch. VI n°81, eq. (251)", "haag1935.eq251.dT", applies=_massive,
               estimate=lambda i: i.blade_mass / i.m * i.blade_short**2 / 6,     # (252)'s bracket ≤ 1/3
               symbols=_short_symbols, relative=lambda value, i: value,
               error=lambda rel, i: _next_order(rel, i, i.blade_mass / i.m),
               model="short uniform blade, first order in m'/m, leading order in λ/a", order=16,
               couples=("blade",)),        # relative to the blade's linear period
        Effect("blade_weight", "weight of the short blade (its mass m')",
               "Haag 1935, ch. VI n°81, eq. (253)", "haag1935.eq253.dT", applies=_massive,
               estimate=lambda i: i.blade_mass / i.m * i.blade_short / 4,         # (254)'s bracket → 2
               symbols=_short_symbols, relative=lambda value, i: value,
               error=lambda rel, i: _next_order(rel, i, i.blade_mass / i.m),
               model="short uniform blade, first order in m'/m, leading order in λ/a", order=17,
               couples=("blade",)),
        Effect("blade_clamping", "clamping errors of the short blade (angles i, i')",
               "Haag 1935, ch. VI n°80, eq. (249) with j of (247) (ch. II n°31–34)", "haag1935.eq249.dT",
               applies=_clamped, estimate=_clamping_estimate, symbols=_clamping_symbols,
               uses=(CLAMP_SUM,), given=_clamping_j, relative=lambda value, i: value,
               error=_clamping_error,
               model="short uniform blade, first order in λ/a, second order in the angles", order=18,
               couples=("blade",)),     # relative to the blade's linear period
        Effect("inverted_blade", "inverted blade, its slow vibration (linear theory)",
               "Haag 1935, ch. VIII n°101 with ch. III n°50: (34), (36), (30), u → iu, g → −g",
               "haag1935.eq034.n2_inverted", applies=_inverted, estimate=lambda i: math.inf,
               symbols=_inverted_symbols, relative=lambda n2, i: math.pi / math.sqrt(n2) if n2 > 0 else math.nan,
               error=lambda rel, i: 1e-14, base=True, g_exponents={"g": 1.0, "u": 0.5},
               sensitivity=lambda slope, i: -slope / 2, refuse=_unstable, order=5,
               model="linear theory of the inverted blade, exact for small oscillations (evaluated at 30 digits)"),
        Effect("inverted_isochronism", "inverted blade at finite amplitude (isochronism near a1)",
               "Haag 1935, ch. VII n°93 (283) with G of (314), C of (317) (ch. VIII n°103), ε of (312), a1 of (310)",
               "haag1935.eq283.dT", applies=lambda i: _inverted(i) and i.alpha > 0,
               estimate=lambda i: -i.alpha**2 * _G_printed(i) / 16, symbols=_inverted_symbols,   # C ≈ 1 (317)
               uses=(A1, G314, C317), given=_isochronism_given, relative=lambda value, i: value,
               # leading order in ε (G of (314) is its 1/ε term) and first order in θ0²G
               error=lambda rel, i: abs(rel) * (_epsilon(i) + 16 * abs(rel)), replaces=("circular",),
               couples=("inverted_blade",), order=15, g_slope=_slope_over_epsilon,
               model="leading order in ε and first order in θ0²G (relative to the linear period on the blade)"),
        Effect("inverted_weight", "weight of the inverted blade (its mass m')",
               "Haag 1935, ch. VIII n°103, eq. (320), ε of (312), a1 of (310)", "haag1935.eq320.weight",
               applies=_inverted_massive, estimate=_weight_estimate, symbols=_inverted_mass_symbols,
               uses=(A1,), given=_isochronism_given, relative=lambda value, i: value,
               # leading order in ε; first order in m'/(mε): the weight moves the critical distance, so that
               # T ∝ (1 − 2ΔT/T)^(−1/2) and the next term is (3/2)(ΔT/T)²
               error=lambda rel, i: abs(rel) * (_epsilon(i) + 2 * abs(rel)), couples=("inverted_blade",), order=16,
               g_slope=_slope_over_epsilon, refuse=_too_heavy,
               model="leading order in ε, first order in m'/(mε) (relative to the linear period on the blade)"),
        Effect("inverted_inertia", "inertia of the inverted blade (its mass m')",
               "Haag 1935, ch. VIII n°103, eq. (319)", "haag1935.eq319.inertia", applies=_inverted_massive,
               estimate=_inertia_estimate, symbols=_inverted_mass_symbols, relative=lambda value, i: value,
               error=lambda rel, i: abs(rel) * (_epsilon(i) + i.blade_mass / i.m), couples=("inverted_blade",),
               order=17, model="leading order in ε, first order in m'/m (relative to the linear period on the blade)"),
        *rhombus_effects(),
    )


def pending() -> tuple[Pending, ...]:
    """What Haag treats for a blade that scenes cannot use yet."""
    is_blade = _direct
    long_blade = lambda i: is_blade(i) and i.blade_short > SHORT
    return (Pending("blade_isochronism_long", "blade at finite amplitude, λ/a > 0.1 (isochronism error)",
                    "Haag 1935, ch. II (111)–(112)", lambda i: long_blade(i) and i.alpha > 0),
            Pending("blade_clamping", "clamping errors of the blade (give clamping.i and clamping.i_prime)",
                    "Haag 1935, ch. II n°31–35, ch. VI n°80", lambda i: is_blade(i) and i.clamping_i is None),
            Pending("blade_clamping_long", "clamping errors of a blade that is not short (λ/a > 0.1; no scene effect "
                    "evaluates chapter II's (133))", "Haag 1935, ch. II n°34 (133)",
                    lambda i: long_blade(i) and i.clamping_i is not None),
            Pending("blade_mass", "inertia and weight of the blade (give suspension.density; λ/a ≤ 0.1)",
                    "Haag 1935, ch. II n°36–37, ch. VI n°81", lambda i: is_blade(i) and not _massive(i)),
            Pending("inverted_clamping", "clamping errors of the inverted blade (their angles are not in the scene)",
                    "Haag 1935, ch. VIII n°103 (318)", _inverted_any),
            Pending("rhombus_mass", "inertia and weight of the blade with a rhombus hole (no Result treats them)",
                    "Haag 1935, ch. VII n°96 (291)–(292) (not worked out for the holed blade)", _rhombus),
            Pending("inverted_mass", "inertia and weight of the inverted blade (give suspension.density)",
                    "Haag 1935, ch. VIII n°103 (319)–(320)", lambda i: _inverted(i) and not _inverted_massive(i)),
            Pending("blade_temperature_long", "temperature coefficient of a blade that is not short (λ/a > 0.1; "
                    "no scene effect evaluates chapter I's general (60))", "Haag 1935, ch. I n°14 (60)", long_blade),
            Pending("rhombus_temperature", "temperature coefficient of the blade with a rhombus hole (no Result "
                    "treats it)", "Haag 1935, ch. VIII n°103 (315) (the uniform blade only)", _rhombus))


# ---------------------------------------------------------------- the temperature coefficient (n°14, (223), (315))
def _thermal(inst: Instrument) -> dict[str, float]:
    """Haag's α (the blade's expansion), α' (the pendulum's), β_t (dE/E) of n°14, per kelvin."""
    return {"alpha": inst.thermal_alpha, "alpha'": inst.thermal_alpha_prime, "beta_t": inst.thermal_beta}


def _has_thermal(inst: Instrument) -> bool:
    return inst.thermal_alpha is not None


def _short_thermal_symbols(inst: Instrument) -> dict[str, float]:
    """The symbols of (223): a, λ, u and the thermal coefficients."""
    return {"a": inst.a, "lambda": inst.blade_length, "u": inst.blade_u, **_thermal(inst)}


def _short_thermal_error(c: float, inst: Instrument) -> float:
    """(223) is (60) to the first order in λ/a with R = 0: its blade terms c − α'/2 (α'/2 is exact: l ∝ a when a
    and R grow alike) have a relative error λ/a + R²/a², and a floor (λ/a)²(|α| + |α'| + |β|) for a cancellation."""
    lam_a = inst.blade_short
    size = abs(inst.thermal_alpha) + abs(inst.thermal_alpha_prime) + abs(inst.thermal_beta)
    return abs(c - inst.thermal_alpha_prime / 2) * (lam_a + (inst.R / inst.a) ** 2) + lam_a**2 * size


def _inverted_thermal_symbols(inst: Instrument) -> dict[str, float]:
    """The symbols of (315), (314) and (310): u, λ and the thermal coefficients (ε from a1 of (310))."""
    return {"u": inst.blade_u, "lambda": inst.blade_length, **_thermal(inst)}


def coefficients() -> tuple[Coefficient, ...]:
    """The temperature coefficient of the linear period, d log T/dϑ per kelvin: (223) for the short hanging blade,
    −(G/2)(dg/g) of (315) for the inverted blade (n°87: the correction dg/g = −(2/G)dT/T, G of (314) = 2 d log T/d
    log g)."""
    return (
        Coefficient("blade_temperature", "temperature", "temperature coefficient of the pendulum on a short blade",
                    "Haag 1935, ch. VI n°70, eq. (223) (from (60), ch. I n°14)", "haag1935.eq223.dT",
                    applies=lambda i: _short(i) and _has_thermal(i), symbols=_short_thermal_symbols,
                    coefficient=lambda value, i, values: value, error=_short_thermal_error,
                    model="uniform short blade, first order in λ/a, R neglected before a", covers=("blade",)),
        Coefficient("inverted_temperature", "temperature", "temperature coefficient of the inverted blade's period",
                    "Haag 1935, ch. VIII n°103, eq. (315) with G of (314), ε of (312), a1 of (310)",
                    "haag1935.eq315.dg", applies=lambda i: _inverted(i) and _has_thermal(i),
                    symbols=_inverted_thermal_symbols, uses=(A1, G314), given=_isochronism_given,
                    coefficient=lambda value, i, values: -values["G"] / 2 * value,
                    error=lambda c, i: abs(c) * _epsilon(i),
                    model="leading order in ε (dT/T = −(G/2) dg/g, n°87)"),
    )


# ---------------------------------------------------------------- the inverted blade with a rhombus hole (chapter IX)
RH_BETA1, RH_A1, RH_N2 = "haag1935.eq343.beta1", "haag1935.eq343.a1", "haag1935.eq343.n2"
RH_G, RH_C = "haag1935.eq346.G", "haag1935.eq346.C"


def _rhombus_symbols(inst: Instrument) -> dict[str, float]:
    """ω = 1/√M0, k, λ and x_0 = 2ω/k, x_1 = x_0√(1 + kλ/2) of (334); a, R, g; θ0 for (283)."""
    omega, k, lam = inst.hole_M0 ** -0.5, inst.hole_k, inst.blade_length
    x0 = 2 * omega / k
    return {"omega": omega, "k": k, "lambda": lam, "x_0": x0, "x_1": x0 * math.sqrt(1 + k * lam / 2),
            "a": inst.a, "R": inst.R, "g": inst.g, "theta_0": inst.alpha}


def _rhombus_printed_ends(inst: Instrument) -> tuple[float, float]:
    """(β1, a1) from v0 and wλ of (343) as printed (ratios of D's: the scale of Y_n cancels), in double precision:
    the refusal's guard and the estimates only (the values come from the Results)."""
    import mpmath as mp
    sym = _rhombus_symbols(inst)
    x0, x1, k, om2 = sym["x_0"], sym["x_1"], sym["k"], sym["omega"] ** 2
    J, Y = mp.besselj, mp.bessely
    D = Y(1, x0) * J(0, x1) - Y(0, x1) * J(1, x0)
    Dp = Y(0, x0) * J(0, x1) - Y(0, x1) * J(0, x0)
    D1 = Y(1, x0) * J(1, x1) - J(1, x0) * Y(1, x1)
    D1p = Y(0, x0) * J(1, x1) - Y(1, x1) * J(0, x0)
    v0 = k * x1 / (2 * om2) * D1 / D
    wl = k * x1 / (4 * om2) * (D1p / Dp + D1 / D)
    return float(inst.blade_length - 2 * v0), float(-wl)


def _rhombus_epsilon(inst: Instrument) -> float:
    return (_rhombus_printed_ends(inst)[1] - inst.a) / inst.blade_length


def _rhombus_G(inst: Instrument) -> float:
    """G ≈ (1/sin²u + cot u/u)/(2ε) of (314) at the blade's mean u = ∫ds/√M (an estimate: the hole's G is (346))."""
    u = inst.blade_length * (inst.hole_M0 ** -0.5) * _mean_root(inst.hole_k * inst.blade_length / 2)
    return (1 / math.sin(u) ** 2 + 1 / (u * math.tan(u))) / (2 * _rhombus_epsilon(inst))


def _mean_root(q: float) -> float:
    """The mean of (1 + q t)^(−1/2) over 0 ≤ t ≤ 1."""
    return 2 * (math.sqrt(1 + q) - 1) / q


def _rhombus_unstable(inst: Instrument) -> str | None:
    """n°100: both vibrations exist iff β1 < 0 (304) and a < a1 (305)."""
    beta1, a1 = _rhombus_printed_ends(inst)
    if not beta1 < 0:
        return (f"suspension: β1 = {beta1:.4g} m is not negative for this holed blade (Haag (304)): the inverted blade "
                "cannot hold the bob; make the blade stiffer or shorter, the hole narrower, or the bob lighter")
    if inst.a >= a1:
        return (f"bob.a = {inst.a:g} is not below the critical distance a1 = −wλ = {a1:.6g} m of the blade with its "
                "rhombus hole (Haag (305), (343)): the inverted pendulum is unstable")
    term = inst.alpha**2 * _rhombus_G(inst) / 16
    if term > MAX_AMPLITUDE_TERM:
        return (f"amplitude = {inst.alpha:g}: θ0²G/16 ≈ {term:.3g} near the critical distance (ε = "
                f"{_rhombus_epsilon(inst):.3g}), beyond the perturbation theory of (283) (expected ≤ {MAX_AMPLITUDE_TERM:g})")
    return None


# ε from a1 of the rhombus blade (312), then its G and C
_rhombus_given = _given_for_283(RH_A1, RH_G, RH_C)


def _rhombus_slope(rel: float, inst: Instrument, S: float) -> tuple[float, float]:
    """As :func:`_slope_over_epsilon`: (283) ∝ G ∝ 1/ε and ε ∝ n² to the leading order."""
    slope = 2 * S * rel
    return slope, abs(slope) * (_rhombus_epsilon(inst) + 1 / max(abs(2 * S), 1))


def rhombus_effects() -> tuple[Effect, ...]:
    return (
        Effect("rhombus_blade", "inverted blade with a rhombus hole (slow vibration, linear)",
               "Haag 1935, ch. IX n°107–109 (343) with ch. I (34), (36), (30), g → −g (n°100)", RH_N2,
               applies=_rhombus, estimate=lambda i: math.inf, symbols=_rhombus_symbols,
               relative=lambda n2, i: math.pi / math.sqrt(n2) if n2 > 0 else math.nan,
               error=lambda rel, i: 1e-14, base=True,
               g_exponents={"g": 1.0, "omega": 0.5, "x_0": 0.5, "x_1": 0.5},
               sensitivity=lambda slope, i: -slope / 2, refuse=_rhombus_unstable, order=5,
               model="linear theory of the holed inverted blade, exact for small oscillations (Bessel forms at 30 "
                     "digits)"),
        Effect("rhombus_isochronism", "holed inverted blade at finite amplitude (isochronism)",
               "Haag 1935, ch. VII n°93 (283) with G, C of the rhombus blade (ch. IX (346), (284)), ε of (312)",
               "haag1935.eq283.dT", applies=lambda i: _rhombus(i) and i.alpha > 0,
               estimate=lambda i: -i.alpha**2 * _rhombus_G(i) / 16, symbols=_rhombus_symbols,
               uses=(RH_A1, RH_G, RH_C), given=_rhombus_given, relative=lambda value, i: value,
               error=lambda rel, i: abs(rel) * (_rhombus_epsilon(i) + 16 * abs(rel)), replaces=("circular",),
               couples=("rhombus_blade",), order=15, g_slope=_rhombus_slope,
               model="leading order in ε and first order in θ0²G (relative to the linear period on the blade)"),
    )
