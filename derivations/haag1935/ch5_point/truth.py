"""Haag 1935, chapter V: the independent truth of n°64–67.

The blades of :mod:`..profiles` solved directly (:mod:`pendsym.suspension`, no v, w) under
the rigid pendulum's mass matrix: the eigenproblem det(S − n²𝕄) = 0, solved as a polynomial
in n² so that R = 0 (𝕄 singular) keeps its one finite mode; each mode's node z on the rod
(z = −β/θ − a, n°7).  Haag's formulas take the shot v0, vλ, w0, wλ, β1 of
:mod:`pendsym.blade`.  The beats are also measured in the time domain: the linear system
𝕄q'' = −Sq integrated by mpmath odefun over a fraction of a period, the two pulsations read
off the eigenvalues e^{±iωt} of its flow map.
"""
from __future__ import annotations

import functools

import mpmath as mp
import sympy as sp

from pendsym import blade, checks, suspension, verify

from .. import profiles

LAMBDA_VALUE = sp.Rational(13, 10)
POINT = ("det(S − n²𝕄) = 0 of the pendulum on the directly solved blade (pendsym.suspension, no v, w), "
         "30 digits")


def pulsations(sus, a, R, g) -> list:
    """(n², z) of each finite mode of det(S − n²𝕄) = 0, sorted by n²; z = ∞ for a mode with θ = 0."""
    with mp.workdps(sus.wdps):
        S = suspension.stiffness_matrix(sus, a, 1, g)
        Mq = suspension.mass_matrix(a, R)
        coeffs = [Mq[0, 0] * Mq[1, 1] - Mq[0, 1] ** 2,
                  -(S[0, 0] * Mq[1, 1] + S[1, 1] * Mq[0, 0] - S[0, 1] * Mq[1, 0] - S[1, 0] * Mq[0, 1]),
                  S[0, 0] * S[1, 1] - S[0, 1] * S[1, 0]]
        scale = max(abs(c) for c in coeffs)
        if abs(coeffs[0]) <= scale * mp.mpf(10) ** (-sus.wdps + 5):
            roots = [-coeffs[2] / coeffs[1]]
        else:
            roots = sorted(mp.re(r) for r in mp.polyroots(coeffs, maxsteps=400, extraprec=4 * mp.mp.prec))
        out = []
        for x in roots:
            # first row of (S − x𝕄)(β, θ) = 0: (S00 − x)β + (S01 − x a)θ = 0
            pivot = S[0, 0] - x * Mq[0, 0]
            if abs(pivot) <= abs(x) * mp.mpf(10) ** (-sus.dps):
                out.append((x, mp.inf))          # θ = 0: the node is at infinity
                continue
            out.append((x, (S[0, 1] - x * Mq[0, 1]) / pivot - mp.mpf(a)))
        return out


def principal_and_parasitic(sus, a, R, g) -> tuple:
    """((n², z') of the mode whose node is above G, (n'², z) of the other)."""
    modes = pulsations(sus, a, R, g)
    principal = min(modes, key=lambda md: md[1])
    other = max(modes, key=lambda md: md[1])
    return principal, other


def env_of(name: str, pend: str, dps: int = 30, **pendulum) -> dict:
    """The shot ends of the profile and a, R, g of the pendulum (overridden by ``pendulum``)."""
    a, R, g = profiles.pendulum(pend)
    env = dict(profiles.shot_env(name, dps), a=a, R=R, g=g)
    env.update({key: mp.mpf(value) for key, value in pendulum.items()})
    return env


def on_profiles(what: str, rows) -> checks.Values:
    """checks.Values over the level's profiles and pendulums; ``rows(name, pend, dps)`` yields Points."""
    def points(level, dps):
        for name in profiles.LEVEL_PROFILES[level]:
            for pend in profiles.LEVEL_PENDULUMS[level]:
                yield from rows(name, pend, dps)

    def confirm(dps):
        first = next(iter(rows(profiles.CONFIRM_PROFILE, "clock", dps)))
        return {"truth": first.truth}
    return checks.Values(truth=f"{POINT}: {what}", points=points, confirm=confirm)


# ================================================================ n°64: the point pendulum
def upper_focus_at_R_zero() -> checks.Values:
    def rows(name, pend, dps):
        env = env_of(name, pend, dps, R=0)
        (n2, z_prime), = pulsations(profiles.direct_blade(name, dps), env["a"], 0, env["g"])
        yield checks.Point(f"{name}/{pend}", env, z_prime, component=1)
    return on_profiles("the node of the one mode at R = 0", rows)


def R_order(quantity, what: str, expected: float = 2.0, scaled: bool = False,
            component: int | None = None) -> checks.Order:
    """A quantity of the modes at small R (uniform blade, clock pendulum's a, g) against the formula
    (its ``component``); ``scaled`` multiplies both by R²."""
    name, pend = "uniform", "clock"

    def truth(R, dps):
        env = env_of(name, pend, dps, R=R)
        value = quantity(principal_and_parasitic(profiles.direct_blade(name, dps), env["a"], R, env["g"]))
        return value * (R**2 if scaled else 1)

    def at(expr, R):
        env = env_of(name, pend, R=R)
        form = expr if component is None else expr[component]
        return mp.mpf(verify.value_at(form, env)) * (R**2 if scaled else 1)
    return checks.Order(param="R", values=lambda level: verify.geometric("0.0005", "0.004", 4), truth=truth,
                        at=at, expected=expected, truth_desc=f"{POINT}: {what} (uniform blade, a = 0.9)")


def roots_check() -> checks.All:
    zero_focus = R_order(lambda modes: modes[1][1], "the node z of the parasitic mode as R → 0", component=0)
    return checks.All((upper_focus_at_R_zero(), zero_focus))


def parasitic_check() -> checks.Order:
    return R_order(lambda modes: modes[1][0], "R²n'² of the parasitic mode", scaled=True)


# ================================================================ n°65: the point mass on the uniform blade
@functools.lru_cache(maxsize=32)
def uniform_direct(u_text: str, dps: int = 30):
    u_value = sp.Rational(u_text)
    return suspension.solve(blade.Blade(LAMBDA_VALUE, (LAMBDA_VALUE / u_value) ** 2), dps)


def point_mass_n2_truth(u_text: str, dps: int, g="9.81") -> mp.mpf:
    (n2, _z), = pulsations(uniform_direct(u_text, dps), 0, 0, mp.mpf(g))
    return n2


def uniform_env(u_value) -> dict:
    return {"u": mp.mpf(u_value), "lambda": mp.mpf(13) / 10, "g": mp.mpf("9.81")}


def point_mass_check() -> checks.Values:
    def points(level, dps):
        for u_text in ("7/10", "43/10", "13"):
            yield checks.Point(f"u={u_text}", uniform_env(sp.Rational(u_text)), point_mass_n2_truth(u_text, dps))
    return checks.Values(truth=f"{POINT}: the one mode of a = R = 0 on the uniform blade λ = 13/10",
                         points=points, confirm=lambda dps: {"n2": point_mass_n2_truth("7/10", dps)})


def point_mass_order(param: str) -> checks.Order:
    """n² of a = R = 0 at large u (param "1/u", the thread) or small u ("u", scaled by u²)."""
    if param == "1/u":
        values = lambda level: [1 / mp.mpf(x) for x in ("27", "18", "12", "8")]
        to_u = lambda p: str(int(mp.nint(1 / p)))
    else:
        values = lambda level: [mp.mpf(1) / x for x in (80, 40, 20, 10)]
        to_u = lambda p: f"1/{int(mp.nint(1 / p))}"
    scale = (lambda uu: 1) if param == "1/u" else (lambda uu: uu**2)

    def truth(p, dps):
        u_text = to_u(p)
        return point_mass_n2_truth(u_text, dps) * scale(mp.mpf(sp.Rational(u_text)))

    def at(expr, p):
        u_value = mp.mpf(sp.Rational(to_u(p)))
        env = dict(uniform_env(u_value), m=mp.mpf(2), e=mp.mpf("0.1"), h=mp.mpf(1))
        # E such that u² = 12mgλ²/(Ee³h) (156)
        env["E"] = 12 * env["m"] * env["g"] * env["lambda"] ** 2 / (u_value**2 * env["e"] ** 3 * env["h"])
        return mp.mpf(verify.value_at(expr, env)) * scale(u_value)
    return checks.Order(param=param, values=values, truth=truth, at=at, expected=1.0 if param == "1/u" else 2.0,
                        truth_desc=f"{POINT}: the one mode of a = R = 0 on the uniform blade λ = 13/10"
                                   + ("" if param == "1/u" else ", times u²; E from u by (156) (m = 2, e = 0.1, h = 1)"))


# ================================================================ n°66: equal periods
def stiffness(name: str, dps: int) -> mp.matrix:
    """S/(mg) of the direct blade (a = 0): (Y, N) = S(β, θ)."""
    return profiles.direct_blade(name, dps).stiffness


def critical_a_truth(name: str, dps: int) -> mp.mpf:
    """The a at which a mode has θ = 0 (node at infinity): S(1, 0) = n²𝕄(1, 0) gives a = S10/S00."""
    S = stiffness(name, dps)
    return S[1, 0] / S[0, 0]


def critical_a_check() -> checks.Values:
    def rows(name, pend, dps):
        yield checks.Point(name, profiles.shot_env(name, dps), critical_a_truth(name, dps))
    return on_profiles("the a at which one mode has θ = 0 (a = S10/S00)", rows)


def decoupled_check() -> checks.Values:
    """At a = S10/S00: β'' + aθ'' = −n²(β + aθ) in the mode θ = 0 (β = 1), and R²θ'' = −n²R²θ in the
    other mode (θ = 1), per unit of the coordinate."""
    def rows(name, pend, dps):
        a_value = critical_a_truth(name, dps)
        env = env_of(name, pend, dps, a=a_value)
        modes = pulsations(profiles.direct_blade(name, dps), a_value, env["R"], env["g"])
        translation = max(modes, key=lambda md: abs(md[1]))
        rotation = min(modes, key=lambda md: abs(md[1]))
        yield checks.Point(f"{name}/{pend}/θ=0", dict(env, beta=1, theta=0), -translation[0], component=0)
        yield checks.Point(f"{name}/{pend}/node G", dict(env, beta=-a_value, theta=1), -rotation[0] * env["R"] ** 2,
                           component=1)
    return on_profiles("the two modes at a = S10/S00", rows)


def equal_radius_truth(name: str, dps: int) -> mp.mpf:
    """At a = S10/S00 the θ = 0 mode has n² = gS00 and the product of the n² is g²det S/R²: they meet
    at R = √det S / S00."""
    a_value = critical_a_truth(name, dps)
    S = suspension.stiffness_matrix(profiles.direct_blade(name, dps), a_value, 1, 1)
    return mp.sqrt(mp.det(S)) / S[0, 0]


def equal_radius_check() -> checks.Values:
    def rows(name, pend, dps):
        yield checks.Point(name, profiles.shot_env(name, dps), equal_radius_truth(name, dps))
    return on_profiles("the R at which both n² meet at a = S10/S00", rows)


def synchronous_check() -> checks.Values:
    def rows(name, pend, dps):
        env = env_of(name, pend, dps)
        yield checks.Point(name, env, env["g"] * stiffness(name, dps)[0, 0])
    return on_profiles("n² = gS00 of the θ = 0 mode", rows)


# ================================================================ n°67: beats
def rho_truth(env, name, dps) -> mp.mpf:
    principal, other = principal_and_parasitic(profiles.direct_blade(name, dps), env["a"], env["R"], env["g"])
    return -(principal[1] + other[1]) / (2 * env["R"])


def rho_check() -> checks.Values:
    """ρ = −(z + z')/(2R) of the nodes of both modes ((208): the sum of its roots)."""
    def rows(name, pend, dps):
        env = env_of(name, pend, dps)
        yield checks.Point(f"{name}/{pend}", env, rho_truth(env, name, dps))
    return on_profiles("ρ = −(z + z')/(2R) from the nodes of the two modes", rows)


def beat_n2_check() -> checks.Values:
    """n² of the principal mode, with z the other mode's node and ε = (a − vλ)/R."""
    def rows(name, pend, dps):
        env = env_of(name, pend, dps)
        principal, other = principal_and_parasitic(profiles.direct_blade(name, dps), env["a"], env["R"], env["g"])
        env.update(z=other[1], varepsilon=(env["a"] - env["v_lambda"]) / env["R"])
        yield checks.Point(f"{name}/{pend}", env, principal[0])
    return on_profiles("n² of the principal mode; z the other node", rows)


KAPPA = mp.mpf("0.7")
BEAT_BLADE, BEAT_PENDULUM = "uniform", "clock"


def beat_env(eps, dps: int) -> dict:
    """a = a0 + εR, R = R0(1 + κε) near the conditions (202), (205) (a0, R0 of the shot blade), with the
    nodes z, z' of the modes, ρ = −(z + z')/(2R) and F0 = √(g/β1)/2π."""
    env = env_of(BEAT_BLADE, BEAT_PENDULUM, dps)
    R0 = mp.sqrt(env["beta_1"] * env["w_0"])
    R = R0 * (1 + KAPPA * eps)
    a = env["v_lambda"] + eps * R
    principal, other = principal_and_parasitic(profiles.direct_blade(BEAT_BLADE, dps), a, R, env["g"])
    env.update(a=a, R=R, varepsilon=eps, z=other[1], **{"z'": principal[1]}, rho=-(principal[1] + other[1]) / (2 * R),
               a_0=env["v_lambda"], R_0=R0)
    env["principal"], env["parasitic"] = principal[0], other[0]
    return env


def beat_frequency_order(component: int) -> checks.Order:
    def truth(eps, dps):
        env = beat_env(eps, dps)
        return mp.sqrt(env["principal" if component == 0 else "parasitic"]) / (2 * mp.pi)

    def at(expr, eps):
        return verify.value_at(expr[component], beat_env(eps, 30))
    return checks.Order(param="ε", values=lambda level: verify.geometric("0.002", "0.02", 4), truth=truth, at=at,
                        expected=2.0, truth_desc=f"{POINT}: the {('principal', 'parasitic')[component]} "
                        f"frequency near a = vλ, R = √(β1w0) (a = a0 + εR, R = R0(1 + 0.7ε); uniform blade, g = 9.81)")


def flow_pulsations(eps, dps: int) -> tuple:
    """The two pulsations of 𝕄q'' = −Sq from its flow map over t1 = π/(2n0), integrated by odefun."""
    env = beat_env(eps, dps)
    sus = profiles.direct_blade(BEAT_BLADE, dps)
    with mp.workdps(sus.wdps):
        A = mp.inverse(suspension.mass_matrix(env["a"], env["R"])) * suspension.stiffness_matrix(
            sus, env["a"], 1, env["g"])
        t1 = mp.pi / (2 * mp.sqrt(env["g"] / env["beta_1"]))

        def rhs(_t, y):
            acc = A * mp.matrix([y[0], y[1]])
            return [y[2], y[3], -acc[0], -acc[1]]
        columns = []
        for i in range(4):
            start = [mp.mpf(1) if j == i else mp.mpf(0) for j in range(4)]
            columns.append(mp.odefun(rhs, 0, start, tol=mp.mpf(10) ** (-sus.wdps))(t1))
        flow = mp.matrix([[columns[j][i] for j in range(4)] for i in range(4)])
        values = mp.eig(flow, left=False, right=False)
        omegas = sorted({mp.nstr(abs(mp.arg(v)) / t1, 25): abs(mp.arg(v)) / t1 for v in values}.values())
        return omegas[0], omegas[-1]


def beat_time_domain() -> checks.Order:
    def truth(eps, dps):
        low, high = flow_pulsations(eps, dps)
        return (high - low) / (2 * mp.pi)

    def at(expr, eps):
        return verify.value_at(expr, beat_env(eps, 30))
    return checks.Order(param="ε", values=lambda level: verify.geometric("0.002", "0.02", 4), truth=truth, at=at,
                        expected=2.0, truth_desc="time domain: 𝕄q'' = −Sq of the directly solved uniform blade "
                        "integrated by mpmath odefun over π/(2n0), the pulsations from the eigenvalues e^{±iωt} of "
                        "its flow map; f = (ω' − ω)/2π near a = vλ, R = √(β1w0) (a = a0 + εR, R = R0(1 + 0.7ε))")



def rho_order() -> checks.Order:
    """ρ = −(z + z')/(2R) of the nodes near the conditions (202), (205)."""
    return checks.Order(param="ε", values=lambda level: verify.geometric("0.002", "0.02", 4),
                        truth=lambda eps, dps: beat_env(eps, dps)["rho"],
                        at=lambda expr, eps: verify.value_at(expr, beat_env(eps, 30)), expected=1.0,
                        truth_desc=f"{POINT}: ρ = −(z + z')/(2R) from the nodes near a = vλ, R = √(β1w0) "
                                   "(a = a0 + εR, R = R0(1 + 0.7ε); uniform blade)")


def log_period_R_order() -> checks.Order:
    """R ∂log T/∂R of the principal mode as R → 0 (mpmath diff of its n², uniform blade, clock pendulum)."""
    name, pend = "uniform", "clock"

    def truth(R, dps):
        env = env_of(name, pend, dps)
        sus = profiles.direct_blade(name, dps)
        return R * mp.diff(lambda x: -mp.log(principal_and_parasitic(sus, env["a"], x, env["g"])[0][0]) / 2, R)

    def at(expr, R):
        return verify.value_at(expr, env_of(name, pend, R=R))
    return checks.Order(param="R", values=lambda level: verify.geometric("0.0005", "0.004", 4), truth=truth, at=at,
                        expected=2.0, truth_desc=f"{POINT}: R ∂log T/∂R of the principal mode (mpmath diff) as R → 0")
