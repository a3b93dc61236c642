"""Haag 1935, chapter VII, n°92–93 and n°97: the check declarations (order in ε against :mod:`.truth`).

The forms hold integrals over the blade (∫ww'' ds, ∫εw'' ds, ∫w'^n ds …): :func:`blade_value` values each by
Gauss–Legendre quadrature on the shot blade (pendsym.blade) before the form is evaluated.
"""
from __future__ import annotations

import functools

import mpmath as mp
import sympy as sp

from pendsym import checks, verify
from ..ch2_common import eps1, eps2, eps3
from ..ch7_gravity import truth as gravity
from ..symbols import Fn, M_of_s, epsilon_of_s, s, v, w
from . import truth

PATH = ("1e-3", "1e-2")            # ε of the isochronism checks (4 points at both levels: each is a nonlinear orbit)
EPS = checks.Geometric("1e-6", "1e-3")
ISOCHRONISM_BLADE = "u=2"          # the uniform blade (the cheapest elastica to integrate)
PERTURBED_BLADE = "tapered"        # chapter I's tapered blade (any M(s))


def path(level: str) -> list:
    return verify.geometric(*PATH, 4)


def integral_value(integral: sp.Integral, shot, eps_fn=None) -> mp.mpf:
    """∫_0^λ of a polynomial in w, w', w'', v, M, ε(s) by quadrature on the shot blade (w'' = w/M (9))."""
    (var, lo, hi), = integral.limits
    body = integral.function.subs({w(var).diff(var, 2): w(var) / M_of_s(var), v(var).diff(var, 2): v(var) / M_of_s(var)})
    V, Vp, W, Wp, Mv, Ev = sp.symbols("V_ Vp_ W_ Wp_ M_ E_")
    body = body.subs({v(var).diff(var): Vp, w(var).diff(var): Wp}).subs(
        {v(var): V, w(var): W, M_of_s(var): Mv, epsilon_of_s(var): Ev})
    if body.free_symbols - {V, Vp, W, Wp, Mv, Ev, var}:
        raise ValueError(f"unknown symbols in {integral}")
    f = verify.lambdify_mp(body, (V, Vp, W, Wp, Mv, Ev, var))
    eps_fn = eps_fn or (lambda x: 0)

    def integrand(x):
        st = shot.state(x)
        return f(st[0], st[1], st[2], st[3], shot.M_at(x), eps_fn(x), x)
    return shot.integrate(integrand)


def blade_value(expr: sp.Expr, env: dict, shot, eps_fn=None):
    """expr at env, its integrals over the blade by quadrature on ``shot``."""
    values = {i: sp.Symbol(f"_I{k}") for k, i in enumerate(sorted(expr.atoms(sp.Integral), key=sp.srepr))}
    env = dict(env, **{sym.name: integral_value(i, shot, eps_fn) for i, sym in values.items()})
    return verify.value_at(expr.xreplace(values), env)


@functools.lru_cache(maxsize=8)
def blade_env(key: str, dps: int) -> dict:
    """λ, w0, wλ (numbers of the shot blade), F2, F4, G2 at K = 0 (79) by quadrature, C = (wλ − F4)/G2."""
    sol = gravity.shot(key, 1, dps)
    env = gravity.numbers(key, 1, dps)
    with mp.workdps(sol.wdps):
        out = {"lambda": env["lambda"], "w_0": sol.w0, "w_lambda": sol.wl, Fn(2): sol.F(2, 0), Fn(4): sol.F(4, 0),
               "G_2": sol.G(2, 0)}
        out["C"] = (out["w_lambda"] - out[Fn(4)]) / out["G_2"]
        return out


# ---------------------------------------------------------------- (281) and n°97: linear perturbations
PERTURBATION = {"eps1": "a vertical force mgε1 on the pendulum, ε1 = κ (X = 1 + κ)",
                "eps2": "a horizontal force mgε2, ε2 = κθ", "eps3": "a couple mgε3 about G, ε3 = κθ",
                "stiffer": "the law EIc(1 + a0) (137), q = 0: E(1 + a0), ε(s) = −a0Mφ' = −a0θw"}


def perturbation_order(kind: str, key: str = PERTURBED_BLADE) -> checks.Order:
    """(281): −(f/(z − z'))/(n²θ) per unit κ is the change of log n² of the slow mode (θ'' + n²θ = f/(z − z'));
    the truth is :func:`.truth.log_n2_slope`; both times ε (they grow like 1/ε): residual O(ε)."""
    values = {"eps1": {eps1: 1}, "eps2": {eps2: 1}, "eps3": {eps3: 1}, "stiffer": {}}[kind]

    def at(expr, p):
        sol = gravity.shot(key, 1, checks.DPS)
        env = dict(blade_env(key, checks.DPS), varepsilon=p, theta=1, **{"n^2": 1})
        env.update({x.name: 0 for x in (eps1, eps2, eps3)})
        env.update({x.name: val for x, val in values.items()})
        eps_fn = (lambda x: -sol.w(x)) if kind == "stiffer" else None
        return -blade_value(expr, env, sol, eps_fn) * mp.mpf(p)

    def value(p, dps):
        return truth.log_n2_slope(key, kind, p, dps) * mp.mpf(p)
    return checks.Order(param="varepsilon", values=EPS, truth=value, at=at, expected=1,
                        truth_desc=f"{gravity.MODEL}; ε·d log n²/dκ of the slow mode (5-point stencil) for "
                                   f"{PERTURBATION[kind]}; blade {key}",
                        params=(("blade", key), ("perturbation", kind)))


def law_order(key: str = PERTURBED_BLADE) -> checks.Order:
    """n°97 at q = 0: ΔT/T per unit a0 of the stiffer blade, −½ d log n²/d log E (truth), against the form with
    a0 = 1, i_2 by quadrature of its definition, G from the truth's stencil: both times ε, residual O(ε)."""
    from ..ch2_perturbations.derivation import a_q, i_fn
    q = sp.Symbol("q", integer=True, nonnegative=True)

    def at(expr, p):
        sol = gravity.shot(key, 1, checks.DPS)
        with mp.workdps(checks.DPS + 10):
            i2 = 2 / mp.pi * mp.quad(lambda x: mp.cos(x) ** 2, [0, mp.pi / 2])
        G = gravity.sensitivity(key, 1, p, checks.DPS)
        form = expr.subs(q, 0).subs(a_q(0, s), 1).subs(i_fn(2), sp.Symbol("i_2"))
        env = dict(blade_env(key, checks.DPS), G=G, i_2=i2, theta_0=1)
        return blade_value(form, env, sol) * mp.mpf(p)

    def value(p, dps):
        return -truth.log_n2_slope(key, "stiffer", p, dps) / 2 * mp.mpf(p)
    return checks.Order(param="varepsilon", values=EPS, truth=value, at=at, expected=1,
                        truth_desc=f"{gravity.MODEL}; ε·ΔT/T per unit a0 = −(ε/2) d log n²/d log E of the slow mode "
                                   f"(5-point stencil in E); G of the form by the stencil in g; blade {key}",
                        params=(("blade", key), ("q", "0")))


# ---------------------------------------------------------------- (283), (284): the isochronism error
def _orbit_env(p, dps):
    r = truth.relative_change(ISOCHRONISM_BLADE, p, dps)
    G = gravity.sensitivity(ISOCHRONISM_BLADE, 1, p, dps)
    return r, truth.amplitude(p), G


def isochronism_order() -> checks.Order:
    """(283): ε(T/T_lin − 1)/θ0² of the exact blade against ε(ΔT/T)/θ0² of the form with G from the truth's
    stencil and C = (wλ − F4)/G2 by quadrature; along θ0 = ε/10: residual O(ε)."""
    def at(expr, p):
        env = dict(blade_env(ISOCHRONISM_BLADE, checks.DPS), G=gravity.sensitivity(ISOCHRONISM_BLADE, 1, p, checks.DPS),
                   theta_0=truth.amplitude(p))
        return verify.value_at(expr, env) * mp.mpf(p) / truth.amplitude(p) ** 2

    def value(p, dps):
        r, theta0, _ = _orbit_env(p, dps)
        return r * mp.mpf(p) / theta0**2
    return checks.Order(param="varepsilon", values=path, truth=value, at=at, expected=1,
                        truth_desc=f"{truth.ORBIT_TRUTH}; ε(T/T_lin − 1)/θ0²; blade {ISOCHRONISM_BLADE}",
                        params=(("blade", ISOCHRONISM_BLADE), ("theta_0", "ε/10")),
                        note="G of the form: −d log n²/d log g of the slow mode (stencil); C by quadrature")


def coefficient_order(minus_one: bool = False) -> checks.Order:
    """(284): C of the truth, −16(T/T_lin − 1)/(θ0²G) (G by the stencil), against the form's C (its wλ, F_n, G2,
    w0 and integrals by quadrature on the shot blade; C − 1 with ``minus_one``): residual O(ε)."""
    def at(expr, p):
        sol = gravity.shot(ISOCHRONISM_BLADE, 1, checks.DPS)
        return blade_value(expr, blade_env(ISOCHRONISM_BLADE, checks.DPS), sol)

    def value(p, dps):
        r, theta0, G = _orbit_env(p, dps)
        return -16 * r / (theta0**2 * G) - (1 if minus_one else 0)
    what = "C − 1" if minus_one else "C"
    return checks.Order(param="varepsilon", values=path, truth=value, at=at, expected=1,
                        truth_desc=f"{truth.ORBIT_TRUTH}; {what} = −16(T/T_lin − 1)/(θ0²G){' − 1' if minus_one else ''}, "
                                   f"G = −d log n²/d log g (stencil); blade {ISOCHRONISM_BLADE}",
                        params=(("blade", ISOCHRONISM_BLADE), ("theta_0", "ε/10")))


def Qp_order() -> checks.Order:
    """n°93: Q' of the truth, 16Q(T/T_lin − 1)/θ0² with Q = K(z − z') of the linear modes (K = −n²z'/g),
    against F4 − wλ by quadrature: residual O(ε)."""
    def at(expr, p):
        return verify.value_at(expr, blade_env(ISOCHRONISM_BLADE, checks.DPS))

    def value(p, dps):
        r, theta0, _ = _orbit_env(p, dps)
        env = gravity.state(ISOCHRONISM_BLADE, 1, p, dps)
        return 16 * env["K"] * (env["z"] - env["z'"]) * r / theta0**2
    return checks.Order(param="varepsilon", values=path, truth=value, at=at, expected=1,
                        truth_desc=f"{truth.ORBIT_TRUTH}; Q' = 16Q(T/T_lin − 1)/θ0², Q = K(z − z') of the linear "
                                   f"modes (111); blade {ISOCHRONISM_BLADE}",
                        params=(("blade", ISOCHRONISM_BLADE), ("theta_0", "ε/10")))
