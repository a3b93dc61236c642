"""Haag 1935, chapter VI, n°80–81: the truth of the clamping errors and of the blade's inertia and weight
of the short blade, as a = λ/ε grows (R = 0.08 m fixed: R²/a² is O(ε²)).

Each truth is chapter II's general result, checked there against the exact models (pendsym.nonlinear_tilt
for (117), (133)–(134); pendsym.massive_blade for (135), (136)), evaluated here at the exact modes of the
pendulum on the directly solved blade (K = −n²z'/g, z, z') with the blade's integrals by quadrature on the
shot blade: those checks judge chapter VI's expansion step in λ/a (and the step u > 5), not chapter II.
The inertia and the weight (251), (253) are also judged against the exact blade with mass itself
(:func:`massive_order`).
"""
from __future__ import annotations

import mpmath as mp
import sympy as sp

from pendsym import blade, checks, verify

from ..symbols import Fn
from .truth import FIXED, LENGTH, THIN, order, shot, uniform_blade

ANGLES = {"i": "1", "i'": "-0.6"}     # the clamping errors (any size: Q1 is a quadratic form in i, i', j)
EXACT_117 = "j + i + i', j = −[(a − v_λ)i + ai']/(a − a1) (117), a1 = −w_λ (41), v_λ, w_λ of the shot blade"
EXACT_133 = ("Q1 = a(i + i' + j)²/4 − aK(i' + j)²/2 − K(ai' + aj + h)²/(2z') + i²F_2/4 − h'/48 (133), j of (117), "
             "h = ∫φψ ds (127), h' = ∫(24Kψ²φ − 24iψφ² − 12ψ²φ²) ds (132), φ = Kφ1 + φ2, ψ = −iφ1 + jφ2, F_2 "
             "(79), all by quadrature on the shot blade at the mode's K")


def j_117(env):
    """j of (117) with a1 = −w_λ (41)."""
    i, ip = mp.mpf(ANGLES["i"]), mp.mpf(ANGLES["i'"])
    return -((env["a"] - env["v_lambda"]) * i + env["a"] * ip) / (env["a"] + env["w_lambda"])


def clamping_inputs(env, name, dps):
    """i, i', j (117), and h (127), h' (132), F_2 (79) by quadrature at the mode's K."""
    i, ip, j = mp.mpf(ANGLES["i"]), mp.mpf(ANGLES["i'"]), j_117(env)
    sol, K = shot(name, dps), env["K"]
    with mp.workdps(dps + 10):
        def moments(s):
            v, dv, w, dw = sol.state(s)
            phi, psi = K * (1 + dv) + dw, -i * (1 + dv) + j * dw
            return phi, psi
        h = sol.integrate(lambda s: (lambda p: p[0] * p[1])(moments(s)))
        hp = sol.integrate(lambda s: (lambda p: 24 * K * p[1] ** 2 * p[0] - 24 * i * p[1] * p[0] ** 2
                                      - 12 * p[1] ** 2 * p[0] ** 2)(moments(s)))
        F2 = sol.F(2, K)
    return {"i": i, "i'": ip, "j": j, "h": h, "h'": hp, Fn(2): F2, "F_2": F2}


def exact_Q1(env):
    a, K, zp, i, ip, j, h = env["a"], env["K"], env["z'"], env["i"], env["i'"], env["j"], env["h"]
    return (a * (i + ip + j) ** 2 / 4 - a * K * (ip + j) ** 2 / 2 - K * (a * ip + a * j + h) ** 2 / (2 * zp)
            + i**2 * env["F_2"] / 4 - env["h'"] / 48)


def exact_dT(env):
    """ΔT/T = Q1/Q (134), Q = K(z − z') (45)."""
    return exact_Q1(env) / (env["K"] * (env["z"] - env["z'"]))


def sum_order(name: str) -> checks.Order:
    def quantity(env):
        return j_117(env) + mp.mpf(ANGLES["i"]) + mp.mpf(ANGLES["i'"])
    return order(quantity, quantity, 1, f"{EXACT_117}; {ANGLES} (relative residual)", name=name, family=FIXED,
                 inputs=lambda env, name, dps: {"i": mp.mpf(ANGLES["i"]), "i'": mp.mpf(ANGLES["i'"])})


def Q1_order(name: str, period: bool = False) -> checks.Order:
    """Q1 of (133) (or ΔT/T = Q1/Q (134)) at the exact modes against its leading term in λ/a: relative O(λ/a)."""
    quantity = exact_dT if period else exact_Q1
    what = ("ΔT/T = Q1/Q (134), Q = K(z − z'), " if period else "") + EXACT_133
    return order(quantity, quantity, 1, f"{what}; {ANGLES} (relative residual)", name=name, family=FIXED,
                 inputs=clamping_inputs)


def mass_inputs(env, name, dps):
    """I_λ/m' and J of (135)–(136) by quadrature on the shot blade at the mode's K (uniform density)."""
    sol = shot(name, dps)
    with mp.workdps(dps + 10):
        return {"I_unit": sol.inertia(env["K"]), "J_unit": sol.weight_integral(env["K"]), "m": 1, "m'": 1}


def exact_inertia(env):
    """(135): ΔT/T = −I_λ/(2mz'(z − z')), m'/m = 1."""
    return -env["I_unit"] / (2 * env["z'"] * (env["z"] - env["z'"]))


def exact_weight(env):
    """(136): ΔT/T = −Jm'/(Qm), Q = K(z − z') (45), m'/m = 1."""
    return -env["J_unit"] / (env["K"] * (env["z"] - env["z'"]))


def mass_order(name: str, inertia: bool) -> checks.Order:
    quantity = exact_inertia if inertia else exact_weight
    what = ("(135) ΔT/T = −I_λ/(2mz'(z − z')), I_λ = m'(1/λ)∫y² ds" if inertia else
            "(136) ΔT/T = −Jm'/(Qm), Q = K(z − z'), J = (1/2λ)∫(λ − s)(Kφ1 + φ2)² ds")
    return order(quantity, quantity, 1, f"{what} by quadrature at the mode's K, m'/m = 1 (relative residual)",
                 name=name, family=FIXED, inputs=mass_inputs)


MASS_RATIO = "1e-8"      # m'/m: the O((m'/m)²) part of the exact period change is 10⁻⁸ of it, far below O(λ/a)
MASSIVE = ("pendsym.massive_blade: T/T0 − 1 of the pendulum (R = 0.08 m) on the uniform blade with mass m' = {ratio}m "
           "spread uniformly, {what} kept, against the same pendulum on the massless blade (relative residual)")


def massive_change(name: str, inertia: bool):
    """quantity(env): T/T0 − 1 of the pendulum a = env["a"], R = 0.08 m on the blade with mass m' = 10⁻⁸m
    (uniform density), its inertia (or its weight) alone kept: pendsym.massive_blade."""
    from pendsym import massive_blade
    from .truth import R_FIXED, blade_of

    def quantity(env):
        lam_v = env["lambda"]
        mb = massive_blade.MassiveBlade(blade_of(name), sp.Float(MASS_RATIO, 30) / sp.Float(lam_v, 30),
                                        inertia=inertia, weight=not inertia)
        return massive_blade.relative_period_change(mb, mp.nstr(env["a"], 40), R_FIXED, "9.81", env["dps"])
    return quantity


def massive_order(name: str, inertia: bool) -> checks.Order:
    """ΔT/T of the blade's inertia (or weight) from the exact model of the blade with mass as a = λ/ε grows:
    relative residual O(λ/a) (the chapter II formula is not used)."""
    quantity = massive_change(name, inertia)

    def inputs(env, name, dps):
        return {"m": 1, "m'": mp.mpf(MASS_RATIO), "dps": dps}
    what = "the horizontal inertia (no weight)" if inertia else "the weight in the tension (no inertia)"
    return order(quantity, quantity, 1, MASSIVE.format(ratio=MASS_RATIO, what=what), name=name, family=FIXED,
                 inputs=inputs)


# ---------------------------------------------------------------- u > 5: the terms in e^{−u}
A_OVER = 10          # a = 10λ


def thin(quantity, what: str, expected: int = 1, power: int = 0) -> checks.Order:
    """The fitted order in q = e^{−u} of u^power·(quantity − formula)/(λ/a) on the shot uniform blade
    u = 5 … 12, a = 10λ, K = 1 (the leading form in λ/a of the Result before, from the blade's integrals).
    ``power`` takes out a known factor 1/u^power of the dropped terms (q/u³ alone would fit 1 + 3/u)."""
    lam_v = mp.mpf(LENGTH.p) / LENGTH.q

    def env_of(q):
        return {"u": -mp.log(q), "lambda": lam_v, "a": A_OVER * lam_v, "i": mp.mpf(ANGLES["i"]),
                "j": mp.mpf("-0.4"), "m": 1, "m'": 1}

    def truth(q, dps):
        u_value = -mp.log(q)
        sol = blade.solve(uniform_blade(sp.Float(mp.nstr(u_value, dps + 15), dps + 15)), dps)
        with mp.workdps(dps + 10):
            return quantity(sol, env_of(q)) * A_OVER * u_value**power

    def at(expr, q):
        return verify.value_at(expr, env_of(q)) * A_OVER * (-mp.log(q)) ** power
    scaled = f", times u^{power}" if power else ""
    return checks.Order(param="exp(-u)", values=THIN, truth=truth, at=at, expected=expected, band=0.3,
                        truth_desc=f"{what}, on the shot uniform blade λ = 0.1 (pendsym.blade), K = 1, a = 10λ, "
                                   f"u = 5 … 12 (residual over λ/a{scaled})",
                        params=(("lambda", "0.1"), ("a/lambda", str(A_OVER))))


def thin_clamping(sol, env):
    """Q1/a, Q1 of (248) with h (127), h' (132) at K = 1, Y = −i, θ = j, F_2 (79) by quadrature."""
    i, j = env["i"], env["j"]

    def parts(s):
        v, dv, w, dw = sol.state(s)
        return (1 + dv) + dw, -i * (1 + dv) + j * dw
    h = sol.integrate(lambda s: (lambda p: p[0] * p[1])(parts(s)))
    hp = sol.integrate(lambda s: (lambda p: 24 * p[1] ** 2 * p[0] - 24 * i * p[1] * p[0] ** 2
                                  - 12 * p[1] ** 2 * p[0] ** 2)(parts(s)))
    Q1 = i**2 / 2 * (sol.v0 - env["lambda"]) - h * i + i**2 / 4 * sol.F(2, 1) - hp / 48
    return Q1 / env["a"]


def thin_inertia(sol, env):
    """I_λ/(2ma²) ((135) at K = 1, z' = −a, z − z' = a), I_λ/m' by quadrature."""
    return sol.inertia(1) / (2 * env["a"] ** 2)


def thin_weight(sol, env):
    """−Jm'/(ma) ((136) at K = 1, Q = a), J by quadrature."""
    return -sol.weight_integral(1) / env["a"]
