"""Haag 1935, chapter II, n°44–45: the independent truth.

The reduced equation of n°28 about the tilted equilibrium, θ1'' + n²θ1 = f/(z − z'), with the blade's
dissymmetry acting only on the side θ = j + θ1 > 0: θ1'' = −n²θ1 − (n²/Q)[g_1θ1 − Ai + Bj]·[θ1 > −j], a
restoring force whose stiffness and offset jump where the pendulum crosses the vertical.  It is integrated by
mpmath's odefun piece by piece (the switch found by findroot on the dense solution) over one period from a
maximum to the next, and Tn/(2π) − 1 is compared with (154) (and with P/(4Q) of (155) at C = 0): the residual
must fall like ε² (g_1, A, B ∝ ε).  This is the step from (151), not (151) itself; (151) is judged through it.

Cost (cold): three odefun pieces per point, four points and a confirmation, about 1 s per check.
"""
from __future__ import annotations

import mpmath as mp

from pendsym import checks, verify
from ..ch2_perturbations.derivation import g_fn
from ..symbols import s
from .derivation import eps_E

# (154): any i, j; (155): i of (117) with i' = 0 and B = g_1 − AK, K = (a + wλ)/(a − vλ + z) (36)
BASE = {"n": "1.3", "Q": "0.8", "theta_0": "0.05", "j": "-0.02"}
CASE_154 = dict(BASE, i="0.03", g1="1", A="0.6", B="0.4")
CASE_155 = dict(BASE, a="0.9", v_lambda="0.2", z="0.5", K="1.1", g1="1", A="0.6")
STRENGTHS = ("0.0005", "0.05")          # the scale ε of g_1, A, B
POINTS = 4
CONFIRM_DPS = 36                        # the truth at the first point recomputed at 36 digits


def _case(name: str) -> dict:
    """The numbers of a case as mpf; for (155) wλ from (36), i from (117), B = g_1 − AK."""
    c = {k: mp.mpf(v) for k, v in (CASE_154 if name == "154" else CASE_155).items()}
    if name == "155":
        c["w_lambda"] = c["K"] * (c["a"] - c["v_lambda"] + c["z"]) - c["a"]
        c["i"] = -c["j"] * (c["a"] + c["w_lambda"]) / (c["a"] - c["v_lambda"])
        c["B"] = c["g1"] - c["A"] * c["K"]
    return c


def period_change(name: str, eps, dps: int):
    """Tn/(2π) − 1 of θ1'' = −n²θ1 − (n²/Q)ε[g1θ1 − Ai + Bj]·[θ1 > −j] from θ1 = θ0, θ1' = 0 to the next
    maximum: odefun on the side θ1 > −j until θ1 = −j, on the other side until θ1 = −j again, then until θ1' = 0."""
    with mp.workdps(dps + 10):
        c = _case(name)
        e = mp.mpf(eps)
        n, Qv, j = c["n"], c["Q"], c["j"]
        offset = -c["A"] * c["i"] + c["B"] * j

        def active(_, y):
            return [y[1], -n**2 * y[0] - n**2 / Qv * e * (c["g1"] * y[0] + offset)]

        def free(_, y):
            return [y[1], -n**2 * y[0]]
        tol = mp.mpf(10) ** (-(dps + 8))
        root_tol = mp.mpf(10) ** (-2 * (dps + 6))
        cross = mp.acos(-j / c["theta_0"]) / n               # the unperturbed crossing of θ1 = −j
        sol = mp.odefun(active, 0, [c["theta_0"], mp.mpf(0)], tol=tol)
        t1 = mp.findroot(lambda t: sol(t)[0] + j, cross, tol=root_tol)
        sol = mp.odefun(free, t1, [-j, sol(t1)[1]], tol=tol)
        t2 = mp.findroot(lambda t: sol(t)[0] + j, t1 + 2 * (mp.pi / n - cross), tol=root_tol)
        sol = mp.odefun(active, t2, [-j, sol(t2)[1]], tol=tol)
        t3 = mp.findroot(lambda t: sol(t)[1], t2 + cross, tol=root_tol)
        return t3 * n / (2 * mp.pi) - 1


def order(name: str) -> checks.Order:
    """(154) (``name`` "154") or P/(4Q) of (155) at C = 0 (``name`` "155") against the integrated reduced
    equation: residual O(ε²)."""
    def at(expr, eps):
        c = _case(name)
        e = mp.mpf(eps)
        env = {"n": c["n"], "Q": c["Q"], "theta_0": c["theta_0"], "j": c["j"], "i": c["i"], "A": e * c["A"],
               "B": e * c["B"], g_fn(1, eps_E(s)): e * c["g1"], eps_E(s): 0}   # ε(s) only inside g_1
        if name == "155":
            env.update({"a": c["a"], "v_lambda": c["v_lambda"], "w_lambda": c["w_lambda"], "z": c["z"], "K": c["K"],
                        "C": 0, "varphi_1": mp.asin(-c["j"] / c["theta_0"])})
            return verify.value_at(expr, env) / (4 * c["Q"])
        env["varphi_1"] = mp.asin(-c["j"] / c["theta_0"])
        return verify.value_at(expr, env)
    case = CASE_154 if name == "154" else CASE_155
    return checks.Order(param="ε", values=lambda level: verify.geometric(*STRENGTHS, POINTS), confirm_dps=CONFIRM_DPS,
                        truth=lambda eps, dps: period_change(name, mp.nstr(mp.mpf(eps), 20), dps), at=at, expected=2,
                        truth_desc="θ1'' = −n²θ1 − (n²/Q)ε[g1θ1 − Ai + Bj] where θ = j + θ1 > 0, free elsewhere (the "
                                   "reduced equation of n°28 with the dissymmetric blade), integrated by odefun piece by "
                                   "piece over one period: Tn/(2π) − 1",
                        params=tuple((k, str(v)) for k, v in case.items()),
                        note=("φ1 = asin(−j/θ0); g_1, A, B scaled by ε" if name == "154" else
                              "C = 0 (the (134) part is checked in n°35); wλ from K of (36), i of (117) with i' = 0, "
                              "B = g_1 − AK; P/(4Q) compared"))


# ---------------------------------------------------------------- n°46: friction with clamping errors
FRICTION_46 = {"p": 1, "q": 1, "n": "1.3", "Q": "0.8", "theta_0": "0.05", "j": "0.02",
               "a_pq": "0.3", "b_pq": "0.7", "a'_pq": "0.2", "b'_pq": "0.5"}
FRICTION_STRENGTHS = ("0.001", "0.1")


def friction_period(j: str, eps, dps: int):
    """Tn/(2π) − 1 of θ1'' = −n²θ1 − sign(θ1')(n²/Q)εC|j + θ1|^p|θ1'|^q from the maximum θ1 = θ0 to the next,
    C = b (right, back), a' (left, out), b' (left, back), a (right, out), the sides parted at θ1 = −j: odefun on
    each arc, its end (θ1 = −j or θ1' = 0) by findroot on the dense solution."""
    with mp.workdps(dps + 10):
        F = {k: mp.mpf(v) if isinstance(v, str) else v for k, v in FRICTION_46.items()}
        e, jv = mp.mpf(eps), mp.mpf(j)
        n, Qv, p, q = F["n"], F["Q"], F["p"], F["q"]
        cross = mp.acos(-jv / F["theta_0"]) / n
        # (coefficient, sign of θ1', ends at θ1' = 0, guess of the end)
        arcs = ((F["b_pq"], -1, False, cross), (F["a'_pq"], -1, True, mp.pi / n),
                (F["b'_pq"], 1, False, 2 * mp.pi / n - cross), (F["a_pq"], 1, True, 2 * mp.pi / n))
        t, state = mp.mpf(0), [F["theta_0"], mp.mpf(0)]
        tol = mp.mpf(10) ** (-(dps + 8))
        for C, sg, on_rate, guess in arcs:
            def rhs(_, y, C=C, sg=sg):
                return [y[1], -n**2 * y[0] - sg * n**2 / Qv * e * C * abs(jv + y[0]) ** p * abs(y[1]) ** q]
            sol = mp.odefun(rhs, t, state, tol=tol)
            k = 1 if on_rate else 0
            t = mp.findroot(lambda x: sol(x)[k] + (0 if on_rate else jv), guess, tol=mp.mpf(10) ** (-2 * (dps + 6)))
            state = list(sol(t))
            if on_rate:
                state[1] = mp.mpf(0)
        return t * n / (2 * mp.pi) - 1


def friction_odd_order() -> checks.Order:
    """n°46: the odd part [ΔT/T(j) − ΔT/T(−j)]/2 at p = q = 1 against the integrated reduced equation at j and
    −j: residual O(ε²)."""
    def truth(eps, dps):
        e = mp.nstr(mp.mpf(eps), 20)
        j = FRICTION_46["j"]
        return (friction_period(j, e, dps) - friction_period("-" + j, e, dps)) / 2

    def at(expr, eps):
        e = mp.mpf(eps)
        F = FRICTION_46
        env = {"n": F["n"], "Q": F["Q"], "theta_0": F["theta_0"], "j": F["j"],
               **{k: e * mp.mpf(F[k]) for k in ("a_pq", "b_pq", "a'_pq", "b'_pq")}}
        return verify.value_at(expr, env)
    return checks.Order(param="ε", values=lambda level: verify.geometric(*FRICTION_STRENGTHS, POINTS), truth=truth,
                        confirm_dps=CONFIRM_DPS,
                        at=at, expected=2,
                        truth_desc="θ1'' = −n²θ1 − sign(θ1')(n²/Q)εC|j + θ1|^p|θ1'|^q (C = b right back, a' left out, "
                                   "b' left back, a right out; sides parted at θ = j + θ1 = 0) integrated by odefun "
                                   "arc by arc over one period at j and at −j: [Tn/(2π)(j) − Tn/(2π)(−j)]/2",
                        params=tuple((k, str(v)) for k, v in FRICTION_46.items()),
                        note="the friction of (146) written in θ = j + θ1 (curvature in proportion to θ)")
