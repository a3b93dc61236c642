"""Haag 1935, chapter VI: the independent truth of the short blade, the exact 2×2 eigenproblem.

A blade of :mod:`..profiles` (λ = 0.1 m) carries a pendulum whose length grows as λ/a = ε
decreases: a = λ/ε, and R either in a fixed ratio to a (R = 3a/10: the R²/a terms that
Haag keeps are tested) or fixed (R = 0.08 m: R²/a² → 0 too, for the formulas where Haag
"neglects R² before a²").  The truth is the eigenproblem K q = n² 𝕄 q of the pendulum on
the directly solved blade (:func:`pendsym.suspension.modes`, no v, w): its modes give the
foci z (node of the parasitic mode), z' (node of the principal one), n², n'², K = −n²z'/g,
K' = −n'²z/g (34); the suppleness W'/W from the principal mode's deflection by quadrature.
Haag's formulas take the shot v_0, v_λ, w_0, w_λ, β1 of :mod:`pendsym.blade` and, where
they hold F_2 or G_2, its quadrature of (79).  Every approximation is judged by the fitted
order of its residual over a geometric sequence of ε (:class:`pendsym.checks.Order`).
"""
from __future__ import annotations

import functools
from typing import Callable

import mpmath as mp
import sympy as sp

from pendsym import blade, checks, suspension, verify

from .. import profiles
from ..symbols import Fn, x_fork

LENGTH = profiles.LENGTH
G_VALUE = "9.81"
RATIO = "ratio"           # R = 3a/10
FIXED = "fixed"           # R = 0.08 m
R_RATIO, R_FIXED = "0.3", "0.08"
FORK_RATIO = "0.25"       # L = a/4: the fork's length, of the order of a (n°25)
EPSILONS = {"ratio": checks.Geometric("1e-3", "3e-2"),
            # R = 0.08 m is of the order of λ = 0.1 m: R²/a² and λ²/a² are alike, but the first-order
            # coefficient of Δl nearly cancels for the uniform blade, so the sequence starts lower
            "fixed": checks.Geometric("1e-4", "3e-3")}
THIN = checks.Geometric("6e-6", "7e-3")      # q = e^{−u}: u from 5 to 12
UNIFORM_U = {"uniform": sp.Integer(2), "uniform5": sp.Integer(5), "uniform_half": sp.Rational(1, 2)}   # u = λ/√M
MODES = ("pendsym.suspension.modes: the eigenproblem K q = n² 𝕄 q of the pendulum on the directly solved blade "
         "(no v, w), 30 digits, confirmed at 45")
FAMILY_TEXT = {RATIO: "a = λ/ε, R = 3a/10", FIXED: "a = λ/ε, R = 0.08 m"}


def uniform_blade(u_value) -> blade.Blade:
    """The uniform blade λ = 0.1 m with u = λ/√M."""
    u_value = sp.nsimplify(u_value) if not isinstance(u_value, sp.Basic) else u_value
    return blade.Blade(LENGTH, (LENGTH / u_value) ** 2)


def blade_of(name: str) -> blade.Blade:
    """A blade of :mod:`..profiles` by name, or a uniform one of :data:`UNIFORM_U`."""
    if name in UNIFORM_U:
        return uniform_blade(UNIFORM_U[name])
    return profiles.profile(name)


@functools.lru_cache(maxsize=16)
def direct(name: str, dps: int) -> suspension.Suspension:
    return suspension.solve(blade_of(name), dps)


@functools.lru_cache(maxsize=16)
def shot(name: str, dps: int) -> blade.BladeSolution:
    return blade.solve(blade_of(name), dps)


def shot_values(name: str, dps: int) -> dict:
    """Haag's end values of the shot blade by symbol name (and u for a uniform blade)."""
    sol = shot(name, dps)
    env = {"v_0": sol.v0, "v_lambda": sol.vl, "w_0": sol.w0, "w_lambda": sol.wl, "beta_1": sol.beta1,
           "lambda": mp.mpf(LENGTH.p) / LENGTH.q}
    if name in UNIFORM_U:
        env["u"] = mp.mpf(UNIFORM_U[name].p) / UNIFORM_U[name].q
    return env


def state(name: str, family: str, epsilon, dps: int) -> dict:
    """The pendulum a = λ/ε (R of the family) on the blade: the modes of the direct blade and the shot
    end values, by symbol name."""
    with mp.workdps(dps + 10):
        env = shot_values(name, dps)
        a_v = env["lambda"] / mp.mpf(epsilon)
        R_v = a_v * mp.mpf(R_RATIO) if family == RATIO else mp.mpf(R_FIXED)
        g_v = mp.mpf(G_VALUE)
        principal, parasitic = suspension.modes(direct(name, dps), a_v, R_v, g_v)
        env.update({"a": a_v, "R": R_v, "g": g_v, "l": a_v + R_v**2 / a_v, "z": parasitic.z, "z'": principal.z,
                    "n^2": principal.n2, "n'^2": parasitic.n2})
        env["K"] = -principal.n2 * principal.z / g_v
        env["K'"] = -parasitic.n2 * parasitic.z / g_v
        return env


Quantity = Callable[[dict], object]


def order(quantity: Quantity, scale: Quantity, expected: int, what: str, name: str = "tapered",
          family: str = RATIO, inputs: Callable[[dict, str, int], dict] | None = None) -> checks.Order:
    """The fitted order in ε = λ/a of (quantity(truth) − formula)/scale, on the blade ``name``.

    ``inputs(env, name, dps)`` adds what the formula takes from the blade besides its end values
    (F_2, G_2 by quadrature …)."""
    def environment(epsilon, dps):
        env = state(name, family, epsilon, dps)
        return {**env, **inputs(env, name, dps)} if inputs else env

    def truth(epsilon, dps):
        env = environment(epsilon, dps)
        return quantity(env) / scale(env)

    def at(expr, epsilon):
        env = environment(epsilon, checks.DPS)
        return verify.value_at(expr, env) / scale(env)
    return checks.Order(param="lambda/a", values=EPSILONS[family], truth=truth, at=at, expected=expected, band=0.3,
                        truth_desc=f"{what}; {MODES}; blade {name}, {FAMILY_TEXT[family]}",
                        params=(("blade", name), ("family", FAMILY_TEXT[family])))


def orders(*names: str, **options) -> checks.All:
    """:func:`order` on each of the blades ``names``."""
    parts = tuple(order(name=name, **options) for name in names)
    return checks.All(parts, truth=parts[0].truth_desc)


def by_a(env):
    return env["a"]


def by_lambda(env):
    return env["lambda"]


def relative(key: str) -> Quantity:
    return lambda env: env[key]


def one(env):
    return mp.mpf(1)


# ---------------------------------------------------------------- n°68: (212), the foci
def foci_points(level: str, dps: int):
    """Both foci of the eigenproblem put for z in (212): the two sides must agree (an exact rewriting
    of (30)); blades tapered and uniform, ε = 0.1 and 0.01, R = 3a/10."""
    names = ("tapered", "uniform") if level == "full" else ("tapered",)
    for name in names:
        for epsilon in ("0.1", "0.01"):
            env = state(name, RATIO, epsilon, dps)
            for focus in ("z", "z'"):
                at_focus = dict(env, z=env[focus])
                z_v, a_v, R_v = at_focus["z"], env["a"], env["R"]
                yield checks.Point(f"{name}/ε={epsilon}/{focus}", at_focus, (z_v + a_v) * (z_v - R_v**2 / a_v),
                                   denom=abs(z_v) * env["lambda"])


def foci_identity() -> checks.Values:
    def confirm(dps):
        env = state("tapered", RATIO, "0.1", dps)
        return {"z": env["z"], "z'": env["z'"]}
    return checks.Values(truth=f"(z + a)(z − R²/a) at the foci z, z' of the modes; {MODES}", points=foci_points,
                         confirm=confirm, kind="eigenproblem")


def reduced_member(env):
    """(z + a)(z − R²/a)/z at the lower focus of the modes."""
    z_v, a_v, R_v = env["z"], env["a"], env["R"]
    return (z_v + a_v) * (z_v - R_v**2 / a_v) / z_v


# ---------------------------------------------------------------- n°69: Δl and its zero
def length_increase(env):
    """Δl = g/n² − l: the synchronous pendulum's length minus l = a + R²/a."""
    return env["g"] / env["n^2"] - env["l"]


def dl_zero_truth(dps: int):
    """The u where λ − v0 − w0 changes sign, v0, w0 of the shot uniform blade (no closed form), by
    mpmath findroot (secant) from u = 1.1, 1.3."""
    with mp.workdps(dps + 10):
        def f(u_value):
            sol = blade.solve(uniform_blade(sp.Float(mp.nstr(u_value, dps + 15), dps + 15)), dps)
            return (mp.mpf(LENGTH.p) / LENGTH.q - sol.v0 - sol.w0) / (mp.mpf(LENGTH.p) / LENGTH.q)
        return mp.findroot(f, (mp.mpf("1.1"), mp.mpf("1.3")), tol=mp.mpf(10) ** (-dps - 2))


def number_check(truth: Callable[[int], object], what: str) -> checks.Values:
    """A number of the text against its truth at the working and the confirming precision."""
    def points(level, dps):
        yield checks.Point(what, {}, truth(dps))
    return checks.Values(truth=what, points=points, confirm=lambda dps: {"truth": truth(dps)}, kind="shooting")


def suppleness_factor_truth(dps: int):
    """λ/(2uG_2) at u = 4, G_2 of (79) at K = 1 by quadrature on the shot uniform blade (the factor (236))."""
    with mp.workdps(dps + 10):
        sol = blade.solve(uniform_blade(4), dps)
        return mp.mpf(LENGTH.p) / LENGTH.q / (8 * sol.G(2, 1))


# ---------------------------------------------------------------- n°71: the parasitic vibration
def frequency_ratio(env):
    return mp.sqrt(env["n'^2"] / env["n^2"])


def bound_points(level: str, dps: int):
    """(226)'s bound: the end values of each blade with a = 0.9, R = 0.08 (clock pendulum)."""
    for name in ("uniform", "hole", "tapered", "bulged", "uniform5"):
        env = shot_values(name, dps)
        env.update({"a": mp.mpf("0.9"), "R": mp.mpf("0.08")})
        yield name, env


def bound() -> checks.Inequality:
    return checks.Inequality(truth="the shot end values of the blades uniform (u = 2, 5), hole, tapered, bulged; "
                                   "a = 0.9, R = 0.08", points=bound_points)


# ---------------------------------------------------------------- n°76: suppleness
@functools.lru_cache(maxsize=64)
def suppleness(name: str, epsilon, dps: int) -> dict:
    """W'/W of the principal mode (θ = 1) of the direct blade: W'/(mg) = ½(a + ∫φ² ds), W/(mg) =
    ½∫Mφ'² ds (n°23), and G_2 of (79) at the mode's K by quadrature on the shot blade."""
    env = state(name, FIXED, epsilon, dps)
    sus = direct(name, dps)
    with mp.workdps(sus.wdps):
        principal = suspension.modes(sus, env["a"], env["R"], env["g"])[0]
        phi2 = sus.integrate(lambda x: sus.deflection(x, principal.beta, 1)[1] ** 2)
        energy = suspension.energy(sus, principal.beta, 1)
        G2 = shot(name, dps).G(2, env["K"])
    return {"S": (env["a"] + phi2) / (2 * energy), "G_2": G2}


def suppleness_order(name: str, with_G2: bool) -> checks.Order:
    """The residual of S·λ/a against W'/W·λ/a of the principal mode, in ε = λ/a (R fixed)."""
    def truth(epsilon, dps):
        return suppleness(name, epsilon, dps)["S"]

    def at(expr, epsilon):
        env = state(name, FIXED, epsilon, checks.DPS)
        if with_G2:
            env["G_2"] = suppleness(name, epsilon, checks.DPS)["G_2"]
        return verify.value_at(expr, env)

    def scaled_truth(epsilon, dps):
        return truth(epsilon, dps) * mp.mpf(epsilon)

    def scaled_at(expr, epsilon):
        return at(expr, epsilon) * mp.mpf(epsilon)
    return checks.Order(param="lambda/a", values=EPSILONS[FIXED], truth=scaled_truth, at=scaled_at, expected=1,
                        band=0.3, params=(("blade", name), ("family", FAMILY_TEXT[FIXED])),
                        truth_desc=(f"S = W'/W of the principal mode (θ = 1) of the direct blade, W' = ½mg(a + ∫φ²), "
                                    f"W = ½∫Mφ'² by quadrature, times λ/a; {MODES}; blade {name}, "
                                    f"{FAMILY_TEXT[FIXED]}"))


def factor_check(with_u: bool) -> checks.Values:
    """u·(236) = λ/(2G_2) (or (236) = λ/(2uG_2)), G_2 of (79) at K = 1 by quadrature on the shot uniform
    blades u = 2, 5."""
    def points(level, dps):
        for name in ("uniform", "uniform5"):
            u_v = mp.mpf(UNIFORM_U[name].p) / UNIFORM_U[name].q
            value = mp.mpf(LENGTH.p) / LENGTH.q / (2 * shot(name, dps).G(2, 1))
            yield checks.Point(name, {"u": u_v}, value if with_u else value / u_v)
    return checks.Values(truth="λ/(2G_2)" + ("" if with_u else "/u") + ", G_2 of (79) at K = 1 by quadrature on the "
                               "shot uniform blade, u = 2 and 5", points=points,
                         confirm=lambda dps: {"G2": shot("uniform", dps).G(2, 1)}, kind="quadrature")


def increasing_points(level: str, dps: int):
    for text in ("0.05", "0.3", "1", "2", "4", "8", "20"):
        yield f"u={text}", {"u": mp.mpf(text)}


def increasing(what: str) -> checks.Inequality:
    return checks.Inequality(truth=f"{what}: its derivative in u at u = 0.05 … 20", points=increasing_points)


# ---------------------------------------------------------------- n°77: centre of flexion, fork
def centre_of_flexion(env):
    """OF' = a + λ + z' (n°24), z' the node of the principal mode."""
    return env["a"] + env["lambda"] + env["z'"]


def fork_inputs(env, name, dps):
    """F_2 of (79) at the mode's K by quadrature on the shot blade, L = a/4."""
    return {"F_2": shot(name, dps).F(2, env["K"]), "L": env["a"] * mp.mpf(FORK_RATIO)}


def fork_root(optimum: sp.Expr) -> Quantity:
    """x = λ − c: the root of smaller modulus of (87) (a quadratic in x) with the modes' z', K and F_2 by
    quadrature at that K, L = a/4."""
    def quantity(env):
        poly = sp.Poly(optimum.subs({Fn(2): sp.Symbol("F_2")}), x_fork)
        coefficients = [verify.value_at(cf, env) for cf in poly.all_coeffs()]
        roots = mp.polyroots(coefficients, extraprec=60)
        return min((mp.re(x) for x in roots), key=abs)
    return quantity


def fork_c(optimum: sp.Expr) -> Quantity:
    root = fork_root(optimum)
    return lambda env: env["lambda"] - root(env)


def thin_order(quantity: Callable[[blade.BladeSolution, object], object], expected: int, what: str) -> checks.Order:
    """The fitted order in q = e^{−u} of (quantity − formula)/λ on the shot uniform blade (u = 5 … 12)."""
    def truth(q, dps):
        u_value = -mp.log(q)
        sol = blade.solve(uniform_blade(sp.Float(mp.nstr(u_value, dps + 15), dps + 15)), dps)
        return quantity(sol, u_value) / (mp.mpf(LENGTH.p) / LENGTH.q)

    def at(expr, q):
        lam_v = mp.mpf(LENGTH.p) / LENGTH.q
        return verify.value_at(expr, {"u": -mp.log(q), "lambda": lam_v}) / lam_v
    return checks.Order(param="exp(-u)", values=THIN, truth=truth, at=at, expected=expected, band=0.3,
                        truth_desc=f"{what}, on the shot uniform blade λ = 0.1 (pendsym.blade), u = 5 … 12",
                        params=(("lambda", "0.1"),))


def thin_v0(sol, u_value):
    return sol.v0


def thin_c(sol, u_value):
    """c = λ − x, x = −F_2 − 2v_λ + 2β1 ((238) with l = a, K = 1), F_2 by quadrature of (79)."""
    return mp.mpf(LENGTH.p) / LENGTH.q + sol.F(2, 1) + 2 * sol.vl - 2 * sol.beta1


def F2_points(level: str, dps: int):
    """F_2/λ of (79) at K = 1 by quadrature on the shot uniform blades u = 2, 5."""
    for name in ("uniform", "uniform5"):
        sol = shot(name, dps)
        yield checks.Point(name, {"u": mp.mpf(UNIFORM_U[name].p) / UNIFORM_U[name].q}, sol.F(2, 1) / (mp.mpf(LENGTH.p) / LENGTH.q))


def F2_at_one() -> checks.Values:
    return checks.Values(truth="F_2/λ = (1/λ)∫(φ1 + φ2)² ds (79) at K = 1 by quadrature on the shot uniform blade, "
                               "u = 2 and 5", points=F2_points,
                         confirm=lambda dps: {"F2": shot("uniform", dps).F(2, 1)}, kind="quadrature")


# ---------------------------------------------------------------- n°70: temperature
def temperature_inputs(env, name, dps):
    """G_2 of (79) at the mode's K by quadrature on the shot blade, M_λ, the coefficients of n°70."""
    from ..ch1_variations.truth import TEMPERATURE
    values = {key: mp.mpf(text) for key, text in TEMPERATURE.items()}
    values.update({"G_2": shot(name, dps).G(2, env["K"]), "M_lambda": shot(name, dps).M_at(env["lambda"])})
    return values


def temperature_truth(name: str):
    """d log T per degree of the principal mode: α'(a∂_a + R∂_R) + αλ∂_λ + (β + 4α)∂_ε log T, the λ and ε
    derivatives by the 5-point stencil on the varied direct blades of chapter I's truth (ch1_variations:
    λ(1 + kH), M(1 + kH)), the a, R one by the stencil at a fixed blade (step 1e-9)."""
    from ..ch1_variations import truth as variations

    def quantity(env):
        dps = env["dps"]
        a_v, R_v, g_v = env["a"], env["R"], env["g"]
        with mp.workdps(dps + 12):
            def log_T(sus, scale=1):
                return -mp.log(suspension.modes(sus, a_v * scale, R_v * scale, g_v)[0].n2) / 2
            h = mp.mpf("1e-9")
            scaling = variations.stencil(lambda k: log_T(direct(name, dps), 1 + k * h), h)
            along = {kind: variations.stencil(lambda k, kind=kind: log_T(variations.direct(name, kind, k, dps)),
                                              variations.step_size(name, kind, dps)) for kind in ("lam", "one")}
            return (env["alpha'"] * scaling + env["alpha"] * env["lambda"] * along["lam"]
                    + (env["beta_t"] + 4 * env["alpha"]) * along["one"])
    return quantity


def with_dps(inputs):
    """inputs that also hand the working precision to the quantity (its stencils solve new blades)."""
    return lambda env, name, dps: {**inputs(env, name, dps), "dps": dps}


def temperature_order(name: str) -> checks.Order:
    from ..ch1_variations.truth import TEMPERATURE
    return order(temperature_truth(name), lambda env: env["alpha'"], 2, f"d log T per degree {TEMPERATURE}, over α'",
                 name=name, family=FIXED, inputs=with_dps(temperature_inputs))


# ---------------------------------------------------------------- n°71: the launches
ATTACK = {"tapered": "0.45", "uniform": "1.35"}     # AB = b over a: between the foci, below F


def attack_inputs(env, name, dps):
    return {"b": env["a"] * mp.mpf(ATTACK[name])}


def static_ratio(name: str) -> Quantity:
    """A'/A after release from the static deviation (n°18): the ordinates of F' and F (the nodes of the
    modes) at the equilibrium of the direct blade under a force at AB = b (pendsym.suspension.static_offset)."""
    def quantity(env):
        with mp.workdps(env["dps"] + 12):
            beta0, theta0 = suspension.static_offset(direct(name, env["dps"]), env["a"], env["b"], mp.mpf("0.01"))
            return (beta0 + (env["a"] + env["z'"]) * theta0) / (beta0 + (env["a"] + env["z"]) * theta0)
    return quantity


def blow_ratio(name: str) -> Quantity:
    """A'/A after a blow at AB = b (n°19–20): the blow solved from the mechanics and the initial velocity
    decomposed on the modes (chapter I's truth, ch1_launch: impact_truth, modal_amplitudes)."""
    from ..ch1_launch import truth as launch

    def quantity(env):
        with mp.workdps(env["dps"] + 12):
            principal, parasitic = suspension.modes(direct(name, env["dps"]), env["a"], env["R"], env["g"])
            solution = launch.impact_truth(env["a"], env["R"], env["b"], mp.mpf(1), mp.mpf("0.37"), mp.mpf("0.62"),
                                           mp.mpf("0.8"))
            A, Ap = launch.modal_amplitudes(principal, parasitic, env["a"], solution[0], solution[1])
            return Ap / A
    return quantity


def launch_order(kind: str, name: str) -> checks.Order:
    quantity = static_ratio(name) if kind == "static" else blow_ratio(name)
    what = ("A'/A after release from the static deviation, the ordinates of the nodes at the equilibrium "
            "(pendsym.suspension.static_offset)" if kind == "static" else
            "A'/A after a blow (m' = 0.37m, h = 0.62), the blow solved from the mechanics and decomposed on the modes")
    return order(quantity, quantity, 1, f"{what}, AB = {ATTACK[name]}a (relative residual)", name=name,
                 inputs=with_dps(attack_inputs))


def launch_ratio_order(name: str) -> checks.Order:
    """(228)/(227): the ratio of the blow's A'/A to the static release's, relative residual."""
    static, blow = static_ratio(name), blow_ratio(name)

    def quantity(env):
        return blow(env) / static(env)
    return order(quantity, quantity, 1, f"(A'/A after the blow)/(A'/A after the static release), AB = "
                 f"{ATTACK[name]}a (relative residual)", name=name, inputs=with_dps(attack_inputs))


# ---------------------------------------------------------------- n°73–75: fatigue at the clamp
FATIGUE = {"E": "2.1", "e": "0.3", "theta_0": "0.01"}


def fatigue_inputs(env, name, dps):
    return {key: mp.mpf(text) for key, text in FATIGUE.items()} | {"dps": dps}


def clamp_stress(name: str) -> Quantity:
    """T'_0 of the principal mode of amplitude θ0: E(e/2)φ'(0)θ0 (78) with φ' the curvature at O of the direct
    blade in the mode (θ = 1)."""
    def quantity(env):
        with mp.workdps(env["dps"] + 12):
            sus = direct(name, env["dps"])
            principal = suspension.modes(sus, env["a"], env["R"], env["g"])[0]
            curvature = sus.deflection(0, principal.beta, 1)[2]
            return env["E"] * env["e"] / 2 * curvature * env["theta_0"]
    return quantity


def fatigue_order(name: str) -> checks.Order:
    quantity = clamp_stress(name)
    return order(quantity, quantity, 1, f"T'_0 = E(e/2)φ'(0)θ0 in the principal mode of the direct blade, {FATIGUE} "
                 "(relative residual)", name=name, family=FIXED, inputs=fatigue_inputs)


# ---------------------------------------------------------------- n°70: bounds of P_λ and G_2
def blade_bound_points(level: str, dps: int):
    """The shot end values, M_λ, μ = M2/M1 and G_2 at K = 1 (quadrature of (79)) of the four blades of
    chapter I."""
    for name in profiles.PROFILE_NAMES:
        env = profiles.shot_env(name, dps)
        sol = profiles.shot_blade(name, dps)
        env.update({"M_lambda": sol.M_at(env["lambda"]), "G_2": sol.G(2, 1)})
        yield name, env


def blade_bound(what: str) -> checks.Inequality:
    return checks.Inequality(truth=f"{what}: the shot blades uniform, hole, tapered, bulged (pendsym.blade), G_2 "
                                   "at K = 1 by quadrature", points=blade_bound_points,
                             confirm=profiles.confirmation_env)


STATIC_LAUNCH = {"Q": "0.013", "mg": "9.81", "E": "2.1", "T": "0.4"}
ATTACK_FIXED = {"uniform": "0.45", "uniform_half": "1.35"}    # AB = b over a: between the foci, below F


def static_launch_inputs(env, name, dps):
    return ({key: mp.mpf(text) for key, text in STATIC_LAUNCH.items()}
            | {"b": env["a"] * mp.mpf(ATTACK_FIXED[name]), "dps": dps})


def static_launch_stress(name: str, at: str) -> Quantity:
    """The largest |T'| at O (at = "T0") or at A ("Tl") after release from the static deviation: the offset
    of the direct blade under Q at AB = b (pendsym.suspension.static_offset) decomposed on the modes, the
    stress √(3ET)(λ/u)φ' (= E(e/2)φ', T = mg/(eh)) of the direct blade's curvature, at t = 0 and n't = π
    (where the memoir places the maximum)."""
    def quantity(env):
        dps = env["dps"]
        with mp.workdps(dps + 12):
            sus = direct(name, dps)
            principal, parasitic = suspension.modes(sus, env["a"], env["R"], env["g"])
            beta0, theta0 = suspension.static_offset(sus, env["a"], env["b"], env["Q"] / env["mg"])
            c = mp.lu_solve(mp.matrix([[principal.beta, parasitic.beta], [1, 1]]), mp.matrix([beta0, theta0]))
            where = 0 if at == "T0" else env["lambda"]
            scale = mp.sqrt(3 * env["E"] * env["T"]) * env["lambda"] / env["u"]

            def stress(t):
                weights = [c[0] * mp.cos(mp.sqrt(principal.n2) * t), c[1] * mp.cos(mp.sqrt(parasitic.n2) * t)]
                beta_t = weights[0] * principal.beta + weights[1] * parasitic.beta
                return scale * sus.deflection(where, beta_t, weights[0] + weights[1])[2]
            return max(abs(stress(0)), abs(stress(mp.pi / mp.sqrt(parasitic.n2))))
    return quantity


def static_launch_order(name: str, at: str) -> checks.Order:
    quantity = static_launch_stress(name, at)
    return order(quantity, quantity, 1, f"the largest |T'| at {'O' if at == 'T0' else 'A'} (t = 0 or n't = π) after "
                 f"release from the static deviation, {STATIC_LAUNCH}, AB = {ATTACK_FIXED[name]}a (relative residual)",
                 name=name, family=FIXED, inputs=static_launch_inputs)
