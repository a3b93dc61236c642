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

