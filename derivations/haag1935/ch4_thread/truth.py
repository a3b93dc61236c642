"""Haag 1935, chapter IV: the independent truths of the thread.

* The limits u → ∞ of n°58: the uniform blade shot by :mod:`pendsym.blade` (chapter III's
  truth, :func:`..ch3_uniform.truth.blade_solution`) at u = 27, 18, 12, 8, the difference
  to the limit fitted for its order in 1/u (or in e^{−u} where it is exponentially small).
* n°59–63: :mod:`pendsym.thread_pendulum`, the exact double pendulum (a body on a thread),
  its energies from the Cartesian positions, its exact accelerations, its linear modes and,
  for the isochronism, the period of its principal nonlinear oscillation (shooting).
"""
from __future__ import annotations

import functools

import mpmath as mp

from pendsym import checks, thread_pendulum, verify

from ..ch3_uniform import truth as blade_truth

U_LARGE = ("27", "18", "12", "8")
BLADE = "the uniform blade λ = 13/10 shot by pendsym.blade (odefun) and mpmath quad, at u = 8, 12, 18, 27"
THREAD = "pendsym.thread_pendulum: the exact double pendulum (body on an inextensible thread), mpmath"
PENDULUMS = {"long": ("1", "1", "0.6", "9.81"), "short": ("0.13", "0.9", "0.35", "9.81")}


def pendulum(name: str, thread_mass="0", thread_weight=None) -> thread_pendulum.Pendulum:
    lam, a, R, g = PENDULUMS[name]
    return thread_pendulum.Pendulum(mp.mpf(lam), mp.mpf(a), mp.mpf(R), mp.mpf(g), mp.mpf(thread_mass),
                                    None if thread_weight is None else mp.mpf(thread_weight))


def base_env(name: str) -> dict:
    lam, a, R, g = PENDULUMS[name]
    return {"lambda": mp.mpf(lam), "a": mp.mpf(a), "R": mp.mpf(R), "g": mp.mpf(g), "m": mp.mpf(1)}


def mode_env(name: str) -> dict:
    """base_env with K = ψ/θ, z' (node), n² of the principal mode and z (node) of the other."""
    p = pendulum(name)
    modes = thread_pendulum.linear_modes(p)
    principal = next(md for md in modes if md.z < 0)
    other = next(md for md in modes if md is not principal)
    return dict(base_env(name), K=principal.ratio, **{"z'": principal.z, "z": other.z, "n^2": principal.n2})


# ================================================================ n°58: limits against the blade
def large_u(param: str):
    """(values, to_u) of an order check in 1/u ("1/u") or in e^{−u} ("exp(-u)")."""
    if param == "1/u":
        return (lambda level: [1 / mp.mpf(x) for x in U_LARGE]), (lambda p: str(int(mp.nint(1 / p))))
    return (lambda level: [mp.exp(-mp.mpf(x)) for x in U_LARGE]), (lambda p: str(int(mp.nint(-mp.log(p)))))


def blade_env(u_text: str, K_text: str = "0.83") -> dict:
    lam = blade_truth.as_mpf(blade_truth.LAMBDA_VALUE)
    return {"u": mp.mpf(u_text), "lambda": lam, "K": mp.mpf(K_text), "m'": mp.mpf(1), "Y": mp.mpf("0.7"),
            "theta": mp.mpf("1.3"), "n": 0, "s": INNER * lam}


INNER = mp.mpf("0.3")        # the inner point s = 0.3λ of the limits along the blade


def limit_order(quantity, param: str, what: str, component: int | None = None, scale=None,
                expected: float = 1.0, K_text: str = "0.83") -> checks.Order:
    """The limit form (a component of it) against ``quantity(solution, env)`` of the shot blade at
    large u; ``scale(env)`` multiplies both (a relative residual)."""
    values, to_u = large_u(param)

    def truth(p, dps):
        u_text = to_u(p)
        env = blade_env(u_text, K_text)
        value = quantity(blade_truth.blade_solution(u_text, dps), env)
        return value * (scale(env) if scale else 1)

    def at(expr, p):
        env = blade_env(to_u(p), K_text)
        form = expr[component] if component is not None else expr
        return mp.mpf(verify.value_at(form, env)) * (scale(env) if scale else 1)
    return checks.Order(param=param, values=values, truth=truth, at=at, expected=expected,
                        truth_desc=f"{what}; {BLADE}", params=(("lambda", "13/10"), ("K", K_text)))


def end_quantity(name: str):
    """v0, vλ, w0, wλ, β1, β2 of the shot blade, or U = u v0/λ, U1 = u w0/λ, U2 = u wλ/λ (159)."""
    def quantity(solution, env):
        scale = env["u"] / env["lambda"]
        return {"v0": solution.v0, "vl": solution.vl, "w0": solution.w0, "wl": solution.wl,
                "beta1": solution.beta1, "beta2": solution.beta2, "U": scale * solution.v0,
                "U1": scale * solution.w0, "U2": scale * solution.wl}[name]
    return quantity


END_NAMES = ("v0", "vl", "w0", "wl", "beta1", "beta2", "U", "U1", "U2")
EXPONENTIAL = {"w0", "U", "U1", "U2"}


def ends_check() -> checks.All:
    return checks.All(tuple(
        limit_order(end_quantity(name), "exp(-u)" if name in EXPONENTIAL else "1/u", f"{name} of the shot blade",
                    component=i, expected=2.0 if name == "U2" else 1.0) for i, name in enumerate(END_NAMES)),
        truth=f"each end value of the shot blade at large u, its difference to the limit of order 1 "
              f"in 1/u (in e^{{−u}} for w0, U, U1; order 2 in e^{{−u}} for U2 = 1/th u); {BLADE}")


def F_check() -> checks.All:
    quantities = (lambda sol, env: sol.F(1, env["K"]) / env["lambda"],
                  lambda sol, env: sol.F(2, env["K"]) / env["lambda"],
                  lambda sol, env: (4 * env["K"] * sol.F(3, env["K"]) - sol.F(4, env["K"])) / env["lambda"])
    return checks.All(tuple(limit_order(q, "1/u", f"F_{i + 1}/λ by quadrature of (79)" if i < 2 else
                                        "(4KF_3 − F_4)/λ by quadrature", component=i)
                            for i, q in enumerate(quantities)))


def G_check() -> checks.All:
    """G_n (λ/u)^{n−3} by quadrature, n = 2, 3, 4, against the limit form at that n (same scale)."""
    return checks.All(tuple(G_order(index) for index in (2, 3, 4)))


def G_order(index: int) -> checks.Order:
    values, to_u = large_u("exp(-u)")

    def scale(env):
        return (env["lambda"] / env["u"]) ** (index - 3)

    def truth(p, dps):
        env = blade_env(to_u(p))
        return blade_truth.blade_solution(to_u(p), dps).G(index, env["K"]) * scale(env)

    def at(expr, p):
        env = dict(blade_env(to_u(p)), n=index)
        return mp.mpf(verify.value_at(expr, env)) * scale(env)
    return checks.Order(param="exp(-u)", values=values, truth=truth, at=at, expected=1.0,
                        truth_desc=f"G_{index}(λ/u)^{index - 3} by quadrature of (79); {BLADE}",
                        params=(("lambda", "13/10"), ("K", "0.83"), ("n", str(index))))


def I_J_check() -> checks.All:
    return checks.All((limit_order(lambda sol, env: sol.inertia(env["K"]), "1/u", "I_λ/m' by quadrature (n°36)",
                                   component=0),
                       limit_order(lambda sol, env: sol.weight_integral(env["K"]), "1/u", "J by quadrature (n°37)",
                                   component=1)))


def along_check() -> checks.All:
    """v, w, φ1, φ2 of the shot blade at s = 0.3λ: they reach their limits like e^{−0.3u} (v, φ1: the
    distance to O) or e^{−0.7u} (w, φ2: the distance to A)."""
    names = ("v", "w", "phi1", "phi2")
    return checks.All(tuple(
        limit_order(lambda sol, env, name=name: getattr(sol, name)(env["s"]), "exp(-u)",
                    f"{name}(0.3λ) of the shot blade", component=i,
                    expected=float(INNER if name in ("v", "phi1") else 1 - INNER))
        for i, name in enumerate(names)))


def shape_check() -> checks.Order:
    """y = Y(s + v − v0) + θ(w − w0) (77) of the shot blade at s = 0.3λ."""
    return limit_order(lambda sol, env: sol.y(env["s"], env["Y"], env["theta"]), "1/u",
                       "y(0.3λ) of the shot blade (77), Y = 0.7, θ = 1.3")


def footnote_check() -> checks.All:
    """P_λ = (Kvλ + wλ)²/M with the shot ends, and G_2 = ∫P ds by quadrature (79)."""
    P_lambda = limit_order(lambda sol, env: (env["K"] * sol.vl + sol.wl) ** 2 / (env["lambda"] / env["u"]) ** 2,
                           "exp(-u)", "(Kvλ + wλ)²/M of the shot blade", component=0)
    G2 = limit_order(lambda sol, env: sol.G(2, env["K"]), "1/u", "G_2 by quadrature of (79)", component=1)
    return checks.All((P_lambda, G2))


def end_stress_check() -> checks.All:
    """T'/√(3ET) = (u/λ)(Yv + θw) (78) at s = 0 and λ with the shot v, w."""
    def at_end(end):
        def quantity(sol, env):
            v, w = (sol.v0, sol.w0) if end == 0 else (sol.vl, sol.wl)
            return env["u"] / env["lambda"] * (env["Y"] * v + env["theta"] * w)
        return quantity
    return checks.All(tuple(limit_order(at_end(i), "exp(-u)", f"(u/λ)(Yv + θw) at s = {('0', 'λ')[i]}",
                                        component=i) for i in (0, 1)))


# ================================================================ n°59: energies and motion of the double pendulum
STATES = (("0.3", "-0.2", "0.7", "1.1"), ("-1.2", "0.5", "-0.4", "0.9"))


def energy_values(which: str) -> checks.Values:
    """2T (186) or U (187) against the engine's energies from the Cartesian positions."""
    def points(level, dps):
        for name in PENDULUMS:
            p = pendulum(name)
            for state in STATES:
                th, ps, dth, dps_ = (mp.mpf(x) for x in state)
                truth = (2 * thread_pendulum.kinetic_energy(p, th, ps, dth, dps_) if which == "T"
                         else -thread_pendulum.potential_energy(p, th, ps))
                env = dict(base_env(name), theta=th, psi=ps, **{"theta'": dth, "psi'": dps_})
                yield checks.Point(f"{name}/{state}", env, truth)

    def confirm(dps):
        return {"truth": next(iter(points("quick", dps))).truth}
    return checks.Values(truth=f"{THREAD}: {'2T, |v_G|² by mpmath diff of the position' if which == 'T' else '−V'}"
                               f" at large angles", points=points, confirm=confirm, kind="value")


SMALL = ("0.1", "0.02")
DIRECTION = ("0.8", "0.5", "-0.6", "0.9")


def small_state(p_value) -> tuple:
    return tuple(mp.mpf(x) * p_value for x in DIRECTION)


def energy_order(which: str, expected: float, on_mode: bool = False) -> checks.Order:
    """(188)/(189) (or n°60's quartic energies along ψ = Kθ) against the exact energies at
    amplitude ε in a fixed direction of (θ, ψ, θ', ψ')."""
    name = "long"
    p = pendulum(name)

    def state(eps):
        th, ps, dth, dps_ = small_state(eps)
        if on_mode:
            K_value = mode_env(name)["K"]
            ps, dps_ = K_value * th, K_value * dth
        return th, ps, dth, dps_

    def truth(eps, dps):
        th, ps, dth, dps_ = state(eps)
        if which == "T":
            return 2 * thread_pendulum.kinetic_energy(p, th, ps, dth, dps_)
        return -thread_pendulum.potential_energy(p, th, ps) - p.numbers()[3] * (p.numbers()[0] + p.numbers()[1])

    def at(expr, eps):
        th, ps, dth, dps_ = state(eps)
        env = dict(mode_env(name), theta=th, psi=ps, **{"theta'": dth, "psi'": dps_})
        return verify.value_at(expr, env)
    return checks.Order(param="ε (amplitude)", values=lambda level: verify.geometric(SMALL[1], SMALL[0], 4),
                        truth=truth, at=at, expected=expected,
                        truth_desc=f"{THREAD}: the exact {'2T' if which == 'T' else 'U − mg(λ + a)'} at "
                                   f"(θ, ψ, θ', ψ') = ε{DIRECTION}" + (" with ψ = Kθ" if on_mode else ""),
                        params=tuple((k, v) for k, v in zip(("lambda", "a", "R", "g"), PENDULUMS[name])))


def acceleration_order(index: int, solve_for) -> checks.Order:
    """θ'' (index 0) or ψ'' (1) of the linear equations, ``solve_for(expr, env)``, against the exact
    accelerations at amplitude ε: the difference is O(ε³)."""
    name = "long"
    p = pendulum(name)

    def truth(eps, dps):
        return thread_pendulum.accelerations(p, *small_state(eps))[index]

    def at(expr, eps):
        th, ps, dth, dps_ = small_state(eps)
        env = dict(base_env(name), theta=th, psi=ps, **{"theta'": dth, "psi'": dps_})
        return solve_for(expr, env)
    return checks.Order(param="ε (amplitude)", values=lambda level: verify.geometric(SMALL[1], SMALL[0], 4),
                        truth=truth, at=at, expected=3.0,
                        truth_desc=f"{THREAD}: the exact {('θ', 'ψ')[index]}'' at (θ, ψ, θ', ψ') = ε{DIRECTION}",
                        params=tuple((k, v) for k, v in zip(("lambda", "a", "R", "g"), PENDULUMS[name])))


def modes_values(quantity, what: str, inputs=None, denom=None) -> checks.Values:
    """A quantity of the principal mode of the linearised double pendulum, at both pendulums."""
    def points(level, dps):
        for name in PENDULUMS:
            env = mode_env(name)
            if inputs:
                env.update(inputs(env))
            yield checks.Point(name, env, quantity(name, env), denom)

    def confirm(dps):
        return {"truth": next(iter(points("quick", dps))).truth}
    return checks.Values(truth=f"{THREAD}: linear modes (det(V − n²𝕋) = 0); {what}", points=points,
                         confirm=confirm, kind="value")


def nodes_on_quadratic() -> checks.Values:
    """The thread's (30) vanishes at both nodes of the double pendulum's modes."""
    def points(level, dps):
        for name in PENDULUMS:
            env = mode_env(name)
            for key in ("z", "z'"):
                yield checks.Point(f"{name}/{key}", dict(env, z=env[key]), 0, denom="terms")
    return checks.Values(truth=f"{THREAD}: the nodes of both linear modes", points=points,
                         confirm=lambda dps: {"z": mode_env("long")["z"]}, kind="value")


def critical_distance_check() -> checks.Values:
    """The a at which the lower n² of the double pendulum vanishes (findroot from a = 0.05)."""
    def a_critical(name):
        lam, _a, R, g = PENDULUMS[name]
        return mp.findroot(lambda a: thread_pendulum.squared_pulsations(
            thread_pendulum.Pendulum(mp.mpf(lam), a, mp.mpf(R), mp.mpf(g)))[0], mp.mpf("0.05"))

    def points(level, dps):
        for name in PENDULUMS:
            yield checks.Point(name, base_env(name), a_critical(name), mp.mpf(1))
    return checks.Values(truth=f"{THREAD}: the a where the lower n² vanishes (findroot)", points=points,
                         confirm=lambda dps: {"a1 + 1": a_critical("long") + 1}, kind="value")


def log_period(p: thread_pendulum.Pendulum) -> mp.mpf:
    return -mp.log(thread_pendulum.principal_mode(p).n2) / 2


def differential_check() -> checks.Values:
    """(192): R ∂log T/∂R, ∂log T/∂a, ∂log T/∂λ of the double pendulum (mpmath diff), times 2Q with
    Q = a + λK², K, z of its modes."""
    def points(level, dps):
        for name in PENDULUMS:
            lam, a, R, g = (mp.mpf(x) for x in PENDULUMS[name])
            env = mode_env(name)
            Q = env["a"] + env["lambda"] * env["K"] ** 2
            make = thread_pendulum.Pendulum
            truths = (R * mp.diff(lambda x: log_period(make(lam, a, x, g)), R),
                      mp.diff(lambda x: log_period(make(lam, x, R, g)), a),
                      mp.diff(lambda x: log_period(make(x, a, R, g)), lam))
            for i, t in enumerate(truths):
                yield checks.Point(f"{name}/{('dR/R', 'da', 'dλ')[i]}", dict(env, Q=Q), 2 * Q * t, component=i)
    return checks.Values(truth=f"{THREAD}: d log T along R, a, λ (mpmath diff of the principal n²), times 2Q",
                         points=points, confirm=lambda dps: {"K": mode_env("long")["K"]}, kind="value")


def sensitivity_check() -> checks.Values:
    def points(level, dps):
        for name in PENDULUMS:
            lam, a, R, g = (mp.mpf(x) for x in PENDULUMS[name])
            truth = 2 * g * mp.diff(lambda x: log_period(thread_pendulum.Pendulum(lam, a, R, x)), g)
            yield checks.Point(name, base_env(name), truth)
    return checks.Values(truth=f"{THREAD}: 2 g ∂log T/∂g (mpmath diff of the principal n²)", points=points,
                         confirm=lambda dps: {"n2": mode_env("long")["n^2"]}, kind="value")


# ================================================================ n°60: the isochronism
SHOOTING_DIGITS = (15, 30)      # the precisions an orbit is shot at before the one asked for


@functools.lru_cache(maxsize=None)
def principal_orbit(name: str, theta0, dps: int) -> tuple:
    """(ψ0, T) of the principal periodic orbit of amplitude θ0 of the exact double pendulum, at ``dps``
    digits: the shooting of :func:`pendsym.thread_pendulum.principal_period` (ψ0 by secant until ψ
    vanishes when θ does; the period is 4t1), started from the orbit shot at the next lower precision of
    SHOOTING_DIGITS (from the linear mode's ratio below them), so that the costly digits are spent on
    the last few secant steps only.  The start changes how many steps the secant takes, not the root:
    each precision's orbit is the root of that precision's shooting.  Each integration is done once
    (findroot asks for the start twice and for the root again)."""
    p = pendulum(name)
    lower = max((d for d in SHOOTING_DIGITS if d < dps), default=None)
    with mp.workdps(dps):
        theta0 = mp.mpf(theta0)
        mode = thread_pendulum.principal_mode(p)
        if lower is None:
            start = mode.ratio * theta0
            second = start * (1 + theta0**2 / 10)
        else:
            start = mp.mpf(principal_orbit(name, theta0, lower)[0])
            second = start * (1 + mp.mpf(10) ** (-(lower + dps) // 2))
        t_guess = [mp.pi / (2 * mp.sqrt(mode.n2))]
        shot: dict = {}

        def quarter(psi0):
            if psi0 not in shot:
                shot[psi0] = thread_pendulum.quarter_residual(p, theta0, psi0, t_guess[0])
                t_guess[0] = shot[psi0][0]
            return shot[psi0]
        psi0 = mp.findroot(lambda x: quarter(x)[1], (start, second), solver="secant")
        return psi0, 4 * quarter(psi0)[0]


def isochronism_check() -> checks.Order:
    """T(θ0)/T0 − 1 of the principal nonlinear oscillation of the exact double pendulum."""
    name = "long"
    p = pendulum(name)

    def truth(theta0, dps):
        T0 = 2 * mp.pi / mp.sqrt(thread_pendulum.principal_mode(p).n2)
        return principal_orbit(name, theta0, dps)[1] / T0 - 1

    def at(expr, theta0):
        return verify.value_at(expr, dict(mode_env(name), theta_0=theta0))
    return checks.Order(param="θ0", values=lambda level: verify.geometric("0.04", "0.16", 4),
                        truth=truth, at=at, expected=4.0,
                        truth_desc=f"{THREAD}: the period of the principal periodic orbit (odefun, shooting "
                                   "on ψ0 until θ and ψ vanish together), T/T0 − 1",
                        params=tuple((k, v) for k, v in zip(("lambda", "a", "R", "g"), PENDULUMS[name])))


# ================================================================ n°62–63: the thread's inertia and weight
def heavy_thread_check(inertia: bool) -> checks.Order:
    """T(m'/m)/T(0) − 1 of the linearised double pendulum with a uniform straight thread of mass m'
    (its moment of inertia m'λ²/3 about O with ``inertia``, else its weight at λ/2 only)."""
    name = "short"

    def truth(mu, dps):
        p = pendulum(name, thread_mass=mu if inertia else 0, thread_weight=0 if inertia else mu)
        return mp.sqrt(thread_pendulum.principal_mode(pendulum(name)).n2 / thread_pendulum.principal_mode(p).n2) - 1

    def at(expr, mu):
        return verify.value_at(expr, dict(mode_env(name), **{"m'": mu}))
    return checks.Order(param="m'/m", values=lambda level: verify.geometric("0.0005", "0.02", 4), truth=truth,
                        at=at, expected=2.0,
                        truth_desc=f"{THREAD} with a heavy straight thread ("
                                   + ("its inertia m'λ²/3 about O only" if inertia else "its weight at λ/2 only")
                                   + "): T/T0 − 1 from the principal n²",
                        params=tuple((k, v) for k, v in zip(("lambda", "a", "R", "g"), PENDULUMS[name])))
