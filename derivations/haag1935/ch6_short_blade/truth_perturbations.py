"""Haag 1935, chapter VI, n°74 and n°79: the truth of the fatigue after a blow and of the isochronism
error of the short blade, on the exact eigenproblem of :mod:`.truth` as a = λ/ε grows.

- n°74: the blow is solved from the mechanics and its initial velocity decomposed on the modes
  (chapter I's truth, ch1_launch: impact_truth); the parasitic mode's share of the motion,
  (d'/n') e' sin n't, bends the directly solved blade (:mod:`pendsym.suspension`), whose curvature at
  the clamps gives the stress E(e/2)φ' = √(3ET)(λ/u)φ' (T = mg/(eh), EI = mgM).
- n°79: Q'/Q, (112) over (45) at the exact modes (K, z, z' of the eigenproblem) with F_2, F_3, F_4 of
  (79) by quadrature on the shot blade: (112) itself is checked against the nonlinear blade in
  chapter II; here the expansion of n°79 in λ/a is judged by its fitted order.
"""
from __future__ import annotations

import mpmath as mp

from pendsym import checks, suspension

from .truth import FIXED, RATIO, Quantity, direct, order, shot

BLOW = {"m": "1", "m'": "0.37", "h": "0.62", "V": "0.8", "E": "2.1", "T": "0.4"}
BLOW_ATTACK = "0.45"          # AB = b over a: B between F' (at A) and F (near G)


def blow_inputs(env, name, dps):
    """The blow's constants, b = 0.45a, n' and the precision."""
    values = {key: mp.mpf(text) for key, text in BLOW.items()}
    return values | {"b": env["a"] * mp.mpf(BLOW_ATTACK), "n'": mp.sqrt(env["n'^2"]), "dps": dps}


def blow_stress(name: str, at: str) -> Quantity:
    """|T'| at O (at = "T0") or at A ("Tl") of the parasitic vibration after a blow at AB = b: the blow
    solved from the mechanics (ch1_launch.impact_truth: momentum, angular momentum about G, impulse of m',
    restitution), its velocity (β'0, θ'0) = d e + d' e' on the modes, the parasitic share (d'/n')e' at
    n't = π/2, and the curvature of the directly solved blade at the clamp."""
    from ..ch1_launch import truth as launch

    def quantity(env):
        with mp.workdps(env["dps"] + 12):
            sus = direct(name, env["dps"])
            principal, parasitic = suspension.modes(sus, env["a"], env["R"], env["g"])
            speeds = launch.impact_truth(env["a"], env["R"], env["b"], env["m"], env["m'"], env["h"], env["V"])
            weights = mp.lu_solve(mp.matrix([[principal.beta, parasitic.beta], [1, 1]]),
                                  mp.matrix([speeds[0], speeds[1]]))
            share = weights[1] / mp.sqrt(parasitic.n2)
            where = 0 if at == "T0" else env["lambda"]
            scale = mp.sqrt(3 * env["E"] * env["T"]) * env["lambda"] / env["u"]
            return abs(scale * sus.deflection(where, share * parasitic.beta, share)[2])
    return quantity


def blow_order(name: str, at: str, family: str = RATIO, over: Quantity | None = None) -> checks.Order:
    """The fitted order in λ/a of the relative residual of |T'| of the parasitic vibration after a blow
    (or of |T'|/over(env), e.g. Θ = T' over the factor of (233))."""
    stress = blow_stress(name, at)
    quantity = stress if over is None else (lambda env: stress(env) / over(env))
    what = "|T'| at " + ("O" if at == "T0" else "A") + (" over √(3ET)(1 + h)V/((a − b)² + R²(1 + m/m'))"
                                                        if over else "")
    return order(quantity, quantity, 1, f"{what}, of the parasitic vibration after a blow ({BLOW}, AB = "
                 f"{BLOW_ATTACK}a), the blow solved from the mechanics and decomposed on the modes; the stress "
                 "√(3ET)(λ/u)φ' of the direct blade's curvature (relative residual)", name=name, family=family,
                 inputs=blow_inputs)


def shock_factor(env):
    """√(3ET)(1 + h)V/((a − b)² + R²(1 + m/m')) at env."""
    return (mp.sqrt(3 * env["E"] * env["T"]) * (1 + env["h"]) * env["V"]
            / ((env["a"] - env["b"]) ** 2 + env["R"] ** 2 * (1 + env["m"] / env["m'"])))


# ---------------------------------------------------------------- n°79: the isochronism error
EXACT_112 = ("Q'/Q: Q' = a(1 − 4K) − (4K/z')(a + F_2)² − (4KF_3 − F_4) (112), Q = K(z − z') (45), at the "
             "exact modes (K = −n²z'/g, z, z'), F_n of (79) by quadrature on the shot blade at that K")
THETA_0 = "0.1"


def isochronism_inputs(env, name, dps):
    """F_2, F = 4KF_3 − F_4 (110) of (79) at the mode's K by quadrature, and θ0."""
    sol = shot(name, dps)
    with mp.workdps(dps + 10):
        F2, F3, F4 = (sol.F(k, env["K"]) for k in (2, 3, 4))
    return {"F_2": F2, "F_3": F3, "F_4": F4, "F": 4 * env["K"] * F3 - F4, "theta_0": mp.mpf(THETA_0)}


def exact_ratio(env):
    """Q'/Q of (112) and (45) at the exact modes (chapter II's result, checked there on the nonlinear blade)."""
    K, zp = env["K"], env["z'"]
    Q_prime = env["a"] * (1 - 4 * K) - 4 * K / zp * (env["a"] + env["F_2"]) ** 2 - env["F"]
    return Q_prime / (K * (env["z"] - zp))


def isochronism_order(name: str, with_theta: bool = False) -> checks.Order:
    """Q'/Q (or ΔT/T = (Q'/Q)θ0²/16, θ0 = 0.1) against its series to the first order in λ/a: residual O(λ²/a²)."""
    def quantity(env):
        ratio = exact_ratio(env)
        return ratio * env["theta_0"] ** 2 / 16 if with_theta else ratio
    what = f"ΔT/T = (Q'/Q)θ0²/16, θ0 = {THETA_0}, with " if with_theta else ""
    return order(quantity, lambda env: mp.mpf(1), 2, what + EXACT_112, name=name, family=FIXED,
                 inputs=isochronism_inputs)


def F_points(level: str, dps: int):
    """F/λ = (4F_3 − F_4)/λ (110) of (79) at K = 1 by quadrature on the shot uniform blades u = 2, 5."""
    from .truth import LENGTH, UNIFORM_U
    for name in ("uniform", "uniform5"):
        sol = shot(name, dps)
        with mp.workdps(dps + 10):
            value = (4 * sol.F(3, 1) - sol.F(4, 1)) / (mp.mpf(LENGTH.p) / LENGTH.q)
        yield checks.Point(name, {"u": mp.mpf(UNIFORM_U[name].p) / UNIFORM_U[name].q}, value)


def F_at_one() -> checks.Values:
    return checks.Values(truth="F/λ = (4F_3 − F_4)/λ (110), F_n = ∫(φ1 + φ2)^n ds (79) at K = 1 by quadrature on "
                               "the shot uniform blade, u = 2 and 5", points=F_points,
                         confirm=lambda dps: {"F3": shot("uniform", dps).F(3, 1), "F4": shot("uniform", dps).F(4, 1)},
                         kind="quadrature")


def thin_isochronism() -> checks.Order:
    """(245) against ΔT/T = (θ0²/16)(1 + (λ/a)c), c = (−5λ + 5v_0 − w_0 + 8F_2 − F)/λ of (242) with the shot
    blade's v_0, w_0 and F_2, F by quadrature at K = 1, λ/a = 1/10, θ0 = 1: residual O(e^{−u})."""
    from pendsym import blade, verify
    import sympy as sp
    from .truth import LENGTH, THIN, uniform_blade
    ratio = mp.mpf(1) / 10

    def truth(q, dps):
        u_value = -mp.log(q)
        sol = blade.solve(uniform_blade(sp.Float(mp.nstr(u_value, dps + 15), dps + 15)), dps)
        with mp.workdps(dps + 10):
            lam_v = mp.mpf(LENGTH.p) / LENGTH.q
            c = (-5 * lam_v + 5 * sol.v0 - sol.w0 + 8 * sol.F(2, 1) - (4 * sol.F(3, 1) - sol.F(4, 1))) / lam_v
            return (1 + ratio * c) / 16

    def at(expr, q):
        lam_v = mp.mpf(LENGTH.p) / LENGTH.q
        return verify.value_at(expr, {"u": -mp.log(q), "lambda": lam_v, "a": lam_v / ratio, "theta_0": 1})
    return checks.Order(param="exp(-u)", values=THIN, truth=truth, at=at, expected=1, band=0.3,
                        truth_desc="ΔT/T = (θ0²/16)(1 + (λ/a)c), c of (242) from the shot uniform blade λ = 0.1 "
                                   "(pendsym.blade: v_0, w_0; F_2, F_3, F_4 of (79) at K = 1 by quadrature), "
                                   "λ/a = 1/10, θ0 = 1, u = 5 … 12",
                        params=(("lambda", "0.1"), ("lambda/a", "0.1")))


# ---------------------------------------------------------------- n°78: the perturbing acceleration (241)
PERTURBATION = {"epsilon_1": "0.3", "epsilon_2": "0.2", "epsilon_3": "0.1", "theta": "0.1"}
EXACT_104 = ("f = −(n²/K)[ε2z' + aθε1 − ε3 + ε1(KYJ(2,0) + (Kθ + Y)J(1,1) + θJ(0,2))] ((104) for forces on the "
             "pendulum only, checked in chapter II through (111)–(112)) at the exact modes (K = −n²z'/g, z', n²), "
             "Y = Kθ, J(i, j) = ∫φ1^iφ2^j ds by quadrature on the shot blade")


def perturbation_inputs(env, name, dps):
    values = {key: mp.mpf(text) for key, text in PERTURBATION.items()}
    sol = shot(name, dps)
    with mp.workdps(dps + 10):
        for i, j in ((2, 0), (1, 1), (0, 2)):
            values[f"J{i}{j}"] = sol.integrate(lambda s, i=i, j=j: (lambda st: (1 + st[1]) ** i * st[3] ** j)(sol.state(s)))
    return values


def exact_perturbation(env):
    K, theta, e1 = env["K"], env["theta"], env["epsilon_1"]
    Y = K * theta
    bracket = (env["epsilon_2"] * env["z'"] + env["a"] * theta * e1 - env["epsilon_3"]
               + e1 * (K * Y * env["J20"] + (K * theta + Y) * env["J11"] + theta * env["J02"]))
    return -env["n^2"] / K * bracket


def perturbation_order(name: str) -> checks.Order:
    return order(exact_perturbation, exact_perturbation, 1, f"{EXACT_104}; {PERTURBATION} (relative residual)",
                 name=name, family=FIXED, inputs=perturbation_inputs)
