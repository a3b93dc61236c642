"""Haag 1935, chapter I, n°10–15: the independent truth of (42)–(63).

Logarithmic derivatives of the principal period T = 2π/√n² of the directly solved
suspension (pendsym.suspension.modes, no v, w) and derivatives of the shot end values
v0, vλ, w0, wλ (pendsym.blade), both by the 5-point central stencil
[8(f(h) − f(−h)) − (f(2h) − f(−2h))]/(12h) (error O(h⁴)) on blades of length
λ(1 + kH) with the same M(s), or of stiffness M(s)(1 + kHε(s)), k = ±1, ±2,
H = 10⁻⁷ (λ) or 10⁻⁸ (ε), solved at 30 digits (42 working digits).  The
confirmation recomputes a truth of the uniform blade at 45 digits with step 2H: the
agreement bounds both the truncation (16 times larger at 2H) and the rounding of
the 30-digit value.  Variations of a, R, g at a fixed blade need no new solve.
"""
from __future__ import annotations

import functools

import mpmath as mp
import sympy as sp

from pendsym import blade, checks, suspension
from pendsym.checks import Point
from .. import profiles
from ..check_kinds import OnShotBlade
from ..common import CONFIRM_DPS, DPS
from ..symbols import s, v, w

STENCIL_PROFILES = {"quick": ("uniform", "hole"), "full": ("uniform", "hole", "tapered")}   # blades per level
# step H (relative for λ); the 45-digit confirmation takes 2H, so that agreement bounds both the rounding
# and the O(H⁴) truncation of the 30-digit value (pendsym.blade.Blade rounds a length through a float by
# nsimplify, which loses or garbles most other steps: the λ family keeps H at 45 digits, which
# confirms its rounding only)
STEP = {DPS: sp.Rational(1, 10**8), CONFIRM_DPS: sp.Rational(2, 10**8)}
LAMBDA_STEP = sp.Rational(1, 10**7)
TEMPERATURE = {"alpha": "1.1e-5", "alpha'": "0.9e-5", "beta_t": "-2.4e-4"}   # steel blade, brass-like rod, per degree
EPSILON_KINDS = {"lin": lambda length: 1 + s / length, "one": lambda length: sp.Integer(1)}
KIND = "quadrature"                               # the kind of evidence these checks report
FRACTIONS = ("0.3", "0.8")                       # s/λ where v(s), w(s), v'(s) are differentiated
COMBINATIONS = ({"a": 1, "R": mp.mpf("0.5"), "lam": mp.mpf("0.3"), "lin": 1},
                {"lam": 1, "one": mp.mpf("-0.7")})
TRUTH = ("principal period T = 2π/√n² of the directly solved suspension (pendsym.suspension.modes, no v, w) "
         "and shot end values (pendsym.blade), differentiated by the 5-point central stencil on blades "
         "λ(1 + kH) or M(s)(1 + kHε(s)), k = ±1, ±2, H = 1e-7 for λ (relative), 1e-8 for ε, at 30 digits")


def stencil(f, h):
    """[8(f(1) − f(−1)) − (f(2) − f(−2))]/(12h): the derivative to O(h⁴) from f at k = ±1, ±2."""
    return (8 * (f(1) - f(-1)) - (f(2) - f(-2))) / (12 * h)


def forward_stencil(f, h):
    """[−25f(0) + 48f(1) − 36f(2) + 16f(3) − 3f(4)]/(12h): the derivative to O(h⁴) from one side."""
    return (-25 * f(0) + 48 * f(1) - 36 * f(2) + 16 * f(3) - 3 * f(4)) / (12 * h)


# ---------------------------------------------------------------- the blades of the stencils
def varied_blade(name: str, kind: str, k: int, dps: int) -> blade.Blade:
    """The blade ``name`` with λ → λ(1 + kH) (kind "lam") or M → M(1 + kHε), ε of EPSILON_KINDS[kind]."""
    base = profiles.profile(name)
    H = k * (LAMBDA_STEP if kind == "lam" else STEP[dps])
    if kind == "lam":
        return blade.Blade(base.length * (1 + H), base.M)
    if kind == "base":
        return base
    return blade.Blade(base.length, base.M * (1 + H * EPSILON_KINDS[kind](base.length)))


@functools.lru_cache(maxsize=128)
def shot(name: str, kind: str = "base", k: int = 0, dps: int = DPS) -> blade.BladeSolution:
    return blade.solve(varied_blade(name, kind, k, dps), dps)


@functools.lru_cache(maxsize=128)
def direct(name: str, kind: str = "base", k: int = 0, dps: int = DPS) -> suspension.Suspension:
    return suspension.solve(varied_blade(name, kind, k, dps), dps)


def step_size(name: str, kind: str, dps: int):
    H = suspension.number(LAMBDA_STEP if kind == "lam" else STEP[dps])
    return H * suspension.number(profiles.profile(name).length) if kind == "lam" else H


def epsilon_function(name: str, kind: str, coefficient=1):
    """ε(s) of the kind as an mpmath function (the ε of the varied blades)."""
    length = suspension.number(profiles.profile(name).length)
    return (lambda x: coefficient * (1 + x / length)) if kind == "lin" else (lambda x: coefficient * mp.mpf(1))


def modes_at(direct_solution, a, R, g):
    """(log T, z', z, K, principal mode) of the suspension (K = −n²z'/g (34) read on the truth)."""
    principal, parasitic = suspension.modes(direct_solution, a, R, g)
    return -mp.log(principal.n2) / 2, principal.z, parasitic.z, -principal.n2 * principal.z / g, principal


def pendulum(name: str):
    """(a, R, g) of the pendulum, exact to 60 digits."""
    with mp.workdps(60):
        return tuple(mp.mpf(x) for x in profiles.PENDULUMS[name])


# ---------------------------------------------------------------- derivatives of the truth
@functools.lru_cache(maxsize=256)
def partials(name: str, pendulum_name: str, kind: str, dps: int = DPS) -> dict:
    """d/dp of log T, log|z'|, z along kind ∈ a, R, g (fixed blade), lam, lin, one (new blades)."""
    a, R, g = pendulum(pendulum_name)
    with mp.workdps(dps + 12):
        if kind in ("a", "R", "g"):
            fixed = direct(name, dps=dps)
            x0 = {"a": a, "R": R, "g": g}[kind]
            h = x0 * mp.mpf("1e-9")

            def f(k, i):
                args = {"a": a, "R": R, "g": g}
                args[kind] = x0 + k * h
                result = modes_at(fixed, args["a"], args["R"], args["g"])
                return (result[0], mp.log(-result[1]), result[2])[i]
        else:
            h = step_size(name, kind, dps)

            def f(k, i):
                result = modes_at(direct(name, kind, k, dps), a, R, g)
                return (result[0], mp.log(-result[1]), result[2])[i]
        return {key: stencil(lambda k: f(k, i), h) for i, key in enumerate(("logT", "logzp", "z"))}


@functools.lru_cache(maxsize=64)
def blade_partials(name: str, kind: str, dps: int = DPS, at: tuple = ()) -> dict:
    """d/dp of v0, vλ, w0, wλ, β1 and of v(s), w(s), v'(s) at the fractions ``at`` of λ (fixed s)."""
    with mp.workdps(dps + 12):
        length = suspension.number(profiles.profile(name).length)
        h = step_size(name, kind, dps)
        get = {"v0": lambda sol: sol.v0, "vl": lambda sol: sol.vl, "w0": lambda sol: sol.w0,
               "wl": lambda sol: sol.wl, "beta1": lambda sol: sol.beta1}
        for fr in at:
            get[f"v@{fr}"] = lambda sol, fr=fr: sol.v(length * mp.mpf(fr))
            get[f"w@{fr}"] = lambda sol, fr=fr: sol.w(length * mp.mpf(fr))
            get[f"v'@{fr}"] = lambda sol, fr=fr: sol.state(length * mp.mpf(fr))[1]
        return {key: stencil(lambda k: fn(shot(name, kind, k, dps)), h) for key, fn in get.items()}


def end_partial(name: str, dps: int = DPS) -> mp.mpf:
    """∂v'/∂λ at s = λ0, the end of the base blade: v'(λ0) on blades λ0(1 + kH), k = 0 … 4 (all
    of them reach s = λ0), by the one-sided stencil."""
    with mp.workdps(dps + 12):
        length = suspension.number(profiles.profile(name).length)
        return forward_stencil(lambda k: shot(name, "lam", k, dps).state(length)[1], step_size(name, "lam", dps))


def g_truth(name: str, pendulum_name: str, dps: int = DPS):
    """d log T/d log g: g∂_g at fixed blade minus ∂_ε with ε = 1 (M = EI/(mg) ∝ 1/g)."""
    g = pendulum(pendulum_name)[2]
    return g * partials(name, pendulum_name, "g", dps)["logT"] - partials(name, pendulum_name, "one", dps)["logT"]


# ---------------------------------------------------------------- Haag's quantities at a point
def base_values(name: str, pendulum_name: str, dps: int = DPS) -> dict:
    """Haag's quantities at the unperturbed point: shot v0 … β1, Mλ and the truth's z, z', K."""
    sol = shot(name, dps=dps)
    a, R, g = pendulum(pendulum_name)
    _, zp, z, K, _ = modes_at(direct(name, dps=dps), a, R, g)
    length = suspension.number(profiles.profile(name).length)
    return {"a": a, "R": R, "g": g, "lambda": length, "v_0": sol.v0, "v_lambda": sol.vl, "w_0": sol.w0,
            "w_lambda": sol.wl, "beta_1": sol.beta1, "M_lambda": sol.M_at(length), "K": K, "z": z, "z'": zp}


DIFFERENTIALS = ("da", "dlambda", "dv_0", "dv_lambda", "dw_0", "dw_lambda", "dbeta_1", "dR/R", "dz'/z'", "dg/g")


def direction_values(name: str, pendulum_name: str, kind: str, dps: int = DPS) -> dict:
    """The differentials along one direction (per unit of its parameter) and the truth d log T."""
    base = base_values(name, pendulum_name, dps)
    d = dict.fromkeys(DIFFERENTIALS, mp.mpf(0))
    pt = partials(name, pendulum_name, kind, dps)
    d["dz'/z'"] = pt["logzp"]
    d["truth"] = pt["logT"]
    if kind == "a":
        d["da"] = mp.mpf(1)
    elif kind == "R":
        d["dR/R"] = 1 / base["R"]
    elif kind in ("lam", "lin", "one"):
        bp = blade_partials(name, kind, dps)
        d.update({"dv_0": bp["v0"], "dv_lambda": bp["vl"], "dw_0": bp["w0"], "dw_lambda": bp["wl"],
                  "dbeta_1": bp["beta1"]})
        if kind == "lam":
            d["dlambda"] = mp.mpf(1)
    return {**base, **d}


def combination_values(name, pendulum_name, combination, dps=DPS):
    """Differentials and truth of a linear combination {kind: coefficient} of directions (d log T is linear)."""
    out = None
    for kind, c in combination.items():
        dv = direction_values(name, pendulum_name, kind, dps)
        if out is None:
            out = {k: (c * x if k in DIFFERENTIALS or k == "truth" else x) for k, x in dv.items()}
        else:
            for k in list(DIFFERENTIALS) + ["truth"]:
                out[k] += c * dv[k]
    return out


def epsilon_of_combination(name, combination):
    functions = [epsilon_function(name, k, c) for k, c in combination.items() if k in EPSILON_KINDS]
    return lambda x: sum((f(x) for f in functions), mp.mpf(0))


# ================================================================ what is compared
def relative(truth) -> mp.mpf:
    """The denominator of a relative residual (absolute below 1e-40)."""
    return max(abs(mp.mpf(truth)), mp.mpf("1e-40"))


def level_params(level: str) -> tuple:
    return (("profiles", ",".join(STENCIL_PROFILES[level])),)


def stencil_values(truth: str, points, confirm, **options) -> checks.Values:
    """checks.Values of a stencil truth, reported as quadrature evidence, with the level's blades as parameters."""
    return checks.Values(truth=truth, points=points, confirm=confirm, kind=KIND, params=level_params, **options)


def stencil_values_on_blade(truth: str, points, confirm) -> OnShotBlade:
    """The same for forms holding integrals over the blade (or v', w' at a point): see check_kinds.OnShotBlade."""
    return OnShotBlade(truth=truth, points=points, confirm=confirm, kind=KIND, params=level_params)


def confirming(truth_at):
    """The confirmation of a truth: its value at a precision (with step 2H at 45 digits)."""
    return lambda dps: {"truth": truth_at(dps)}


LAMBDA_STENCIL = "on blades λ(1 + kH) with the same M(s) (pendsym.blade, 30 digits)"
EPSILON_STENCIL = "on blades M(s)(1 + hε(s)) (pendsym.blade)"


def period(kinds=("a", "R", "lam")) -> checks.Values:
    """(42)–(44): dT/T of the formula against the truth's d log T along each direction."""
    def points(level, dps):
        for name in STENCIL_PROFILES[level]:
            for pendulum_name in profiles.PENDULUMS:
                for kind in kinds:
                    values = direction_values(name, pendulum_name, kind)
                    yield Point(f"{name}/{pendulum_name}/d{kind}", values, values["truth"], relative(values["truth"]))
    return stencil_values(f"d log T along {', '.join(kinds)}: " + TRUTH, points,
                          confirming(lambda dps: partials("uniform", "clock", "lam", dps)["logT"]))


def Q_of_truth() -> checks.Values:
    """(45): a − a1 + K²β1 with the shot wλ, β1 and K of the truth."""
    def value(name, pendulum_name, dps=DPS):
        base = base_values(name, pendulum_name, dps)
        return base, base["a"] + base["w_lambda"] + base["K"] ** 2 * base["beta_1"]

    def points(level, dps):
        for name in STENCIL_PROFILES[level]:
            for pendulum_name in profiles.PENDULUMS:
                base, truth = value(name, pendulum_name)
                yield Point(f"{name}/{pendulum_name}", base, truth, relative(truth))
    return stencil_values("a − a1 + K²β1 with the shot wλ, β1 and K = −n²z'/g of the truth; K(z − z') with z, z' "
                          "the nodes of the two modes of pendsym.suspension", points,
                          confirming(lambda dps: value("uniform", "clock", dps)[1]))


def lambda_derivative(key: str | None = None, function: str | None = None) -> checks.Values:
    """(49)–(52): ∂/∂λ of a shot end value ``key``, or of v(s), w(s) (``function``) at fixed s, against the
    formula with the base shot values."""
    fractions = FRACTIONS if function else ()

    def points(level, dps):
        for name in STENCIL_PROFILES[level]:
            sol = shot(name)
            derivatives = blade_partials(name, "lam", DPS, fractions)
            base = base_values(name, "clock")
            if not function:
                yield Point(name, base, derivatives[key], relative(derivatives[key]))
            for fr in fractions:
                state = sol.state(base["lambda"] * mp.mpf(fr))
                env = dict(base)
                env.update({v(s): state[0], w(s): state[2]})
                truth = derivatives[f"{function}@{fr}"]
                yield Point(f"{name} {fr}", env, truth, relative(truth))
    first = f"{function}@{FRACTIONS[0]}" if function else key
    what = f"{function}(s), s = 0.3λ, 0.8λ fixed" if function else key
    return stencil_values(f"5-point stencil in λ of the shot {what} {LAMBDA_STENCIL}", points,
                          confirming(lambda dps: blade_partials("uniform", "lam", dps, fractions)[first]))


def slope_lambda_derivative() -> OnShotBlade:
    """(46): ∂v'/∂λ at s = 0.3λ, 0.8λ (the λ-stencil of the shot v'(s), s fixed) against the derived
    ∂u/∂s with the shot w'(s) and the base end values."""
    def points(level, dps):
        for name in STENCIL_PROFILES[level]:
            derivatives = blade_partials(name, "lam", DPS, FRACTIONS)
            base = base_values(name, "clock")
            for fr in FRACTIONS:
                truth = derivatives[f"v'@{fr}"]
                yield Point(f"{name} {fr}", base, truth, relative(truth)), shot(name), None, base["lambda"] * mp.mpf(fr)

    def confirm(dps):
        return blade_partials("uniform", "lam", dps, FRACTIONS)[f"v'@{FRACTIONS[0]}"]
    return stencil_values_on_blade(f"5-point stencil in λ of the shot v'(s), s = 0.3λ, 0.8λ fixed, {LAMBDA_STENCIL}",
                                   points, confirming(confirm))


def end_slope_lambda_derivative() -> checks.Values:
    """(48): the one-sided λ-stencil of the shot v'(λ0) (s = λ0 fixed) on blades λ0(1 + kH), k = 0 … 4."""
    def points(level, dps):
        for name in STENCIL_PROFILES[level]:
            truth = end_partial(name)
            yield Point(name, base_values(name, "clock"), truth, relative(truth))
    return stencil_values("one-sided 5-point stencil in λ of the shot v'(λ0) (s = λ0 fixed) on blades λ0(1 + kH), "
                          "k = 0 … 4 (pendsym.blade, 30 digits)", points,
                          confirming(lambda dps: end_partial("uniform", dps)))


def epsilon_kinds(name):
    """The ε(s) of the stiffness stencils on a blade (ε = 1 is skipped on the tapered one)."""
    return [kind for kind in ("lin", "one") if not (kind == "one" and name == "tapered")]


def increment() -> OnShotBlade:
    """(54): x(s) = ∂v/∂h at s = 0.3λ, 0.8λ, the h-stencil of the shot v(s) on blades M(1 + hε), against
    (54) with A, B of (55) by quadrature on the unperturbed shot."""
    def points(level, dps):
        for name in STENCIL_PROFILES[level]:
            base = base_values(name, "clock")
            for kind in epsilon_kinds(name):
                derivatives = blade_partials(name, kind, DPS, FRACTIONS)
                for fr in FRACTIONS:
                    truth = derivatives[f"v@{fr}"]
                    yield (Point(f"{name}/ε={kind} {fr}", base, truth, relative(truth)), shot(name),
                           epsilon_function(name, kind), base["lambda"] * mp.mpf(fr))

    def confirm(dps):
        return blade_partials("uniform", "lin", dps, FRACTIONS)[f"v@{FRACTIONS[0]}"]
    return stencil_values_on_blade(f"5-point stencil in h of the shot v(s), s = 0.3λ, 0.8λ fixed, {EPSILON_STENCIL}, "
                                   "ε = 1 + s/λ and ε = 1; A, B by Gauss–Legendre quadrature on the shot",
                                   points, confirming(confirm))


def stiffness_derivative(key: str) -> OnShotBlade:
    """(56), (57): d(key) for M → M(1 + hε), ε = 1 + s/λ and ε = 1, against the integral by quadrature."""
    def points(level, dps):
        for name in STENCIL_PROFILES[level]:
            for kind in epsilon_kinds(name):
                truth = blade_partials(name, kind)[key]
                yield (Point(f"{name}/ε={kind}", base_values(name, "clock"), truth, relative(truth)), shot(name),
                       epsilon_function(name, kind), None)
    return stencil_values_on_blade(f"5-point stencil in h of the shot {key} {EPSILON_STENCIL}, the integral by "
                                   "Gauss–Legendre quadrature on the unperturbed shot v, w", points,
                                   confirming(lambda dps: blade_partials("uniform", "lin", dps)[key]))


def combined_period() -> OnShotBlade:
    """(58): d log T along da, dR, dλ and εM combined (COMBINATIONS), the integral by quadrature."""
    def points(level, dps):
        for name in STENCIL_PROFILES[level]:
            for pendulum_name in profiles.PENDULUMS:
                for i, combination in enumerate(COMBINATIONS):
                    values = combination_values(name, pendulum_name, combination)
                    truth = values["truth"]
                    yield (Point(f"{name}/{pendulum_name}/combination{i}", values, truth, relative(truth)), shot(name),
                           epsilon_of_combination(name, combination), None)
    combinations = "; ".join(map(str, COMBINATIONS))
    return stencil_values_on_blade(f"d log T along da, dR, dλ, εM combined ({combinations}): {TRUTH}", points,
                                   confirming(lambda dps: partials("uniform", "clock", "lin", dps)["logT"]))


def temperature() -> checks.Values:
    """(60): d log T per degree: α'(a∂_a + R∂_R) + αλ∂_λ + (β + 4α)∂_ε, G2 by quadrature (79)."""
    def points(level, dps):
        coefficients = {k: mp.mpf(x) for k, x in TEMPERATURE.items()}
        for name in STENCIL_PROFILES[level]:
            sol = shot(name)
            for pendulum_name in profiles.PENDULUMS:
                a, R, _ = pendulum(pendulum_name)
                length = suspension.number(profiles.profile(name).length)
                combination = {"a": coefficients["alpha'"] * a, "R": coefficients["alpha'"] * R,
                               "lam": coefficients["alpha"] * length,
                               "one": coefficients["beta_t"] + 4 * coefficients["alpha"]}
                values = combination_values(name, pendulum_name, combination)
                values.update(coefficients)
                values["G_2"] = sol.G(2, values["K"])
                yield Point(f"{name}/{pendulum_name}", values, values["truth"], relative(values["truth"]))
    return stencil_values(f"d log T per degree, {TEMPERATURE}: α'(a∂_a + R∂_R) + αλ∂_λ + (β + 4α)∂_ε of {TRUTH}",
                          points, confirming(lambda dps: partials("uniform", "clock", "one", dps)["logT"]),
                          note="M(s) kept as a function of s when λ grows (Haag's dλ of n°11), G2 by quadrature")


def gravity(which: str) -> checks.Values:
    """(61) (which = "T"): d log T/d log g; (62), (63) (which = "G"): G = 2 d log T/d log g, with
    W = suspension.energy of the principal mode (θ = 1) and Q = K(z − z') of the truth."""
    factor = 2 if which == "G" else 1

    def points(level, dps):
        for name in STENCIL_PROFILES[level]:
            sol = shot(name)
            for pendulum_name in profiles.PENDULUMS:
                values = base_values(name, pendulum_name)
                truth = g_truth(name, pendulum_name)
                values["dg/g"] = mp.mpf(1)
                values["G_2"] = sol.G(2, values["K"])
                if which == "G":
                    truth = 2 * truth
                    principal = modes_at(direct(name), *pendulum(pendulum_name))[4]
                    values["W/(mg)"] = suspension.energy(direct(name), principal.beta, 1)
                    values["Q"] = values["K"] * (values["z"] - values["z'"])
                yield Point(f"{name}/{pendulum_name}", values, truth, relative(truth))
    what = "2 d log T/d log g" if which == "G" else "d log T/d log g"
    return stencil_values(f"{what}: g∂_g log T at fixed blade − ∂_ε log T (ε = 1, M ∝ 1/g), {TRUTH}", points,
                          confirming(lambda dps: factor * g_truth("uniform", "clock", dps)))
