"""Haag 1935, chapters VII–VIII, n°94–95 and n°103: the independent truth of the clamping errors near the critical
distance.

The exact tilted blade (:mod:`pendsym.nonlinear_tilt`: the large-deflection elastica under the exact statics with
gravity at the angle i from the clamp's tangent and G at the angle i' from the tangent AT, and the exact
linearisation about that equilibrium, a 3 × 3 eigenproblem in the loads), with the pendulum at a = a1 + ελ (256)
— or a = a1 − ελ for the inverted blade (312), M < 0 and g < 0 (n°100) — a1 found on the truth itself (det K = 0
of the directly solved blade, :func:`..ch7_gravity.truth.critical_distance`).  Near a1 the principal oscillation
of :func:`pendsym.nonlinear_tilt.tilted` (nearest the mode of :mod:`pendsym.suspension` whose node is above G)
is the fast one; the slow one, whose period the memoir's (286)–(290) and (318) give, is picked here by
:func:`slow_tilted` from the same matrices (nearest the slow n² of the untilted pendulum).

ΔT/T is quadratic in the errors: it is taken at errors of 10⁻⁹ (relative quartic part ~10⁻¹⁸) and divided by
i²; two regimes (n°95):

- not regulated: i = 10⁻⁹ε, i' = −0.6i, so that j ~ i/ε ~ 10⁻⁹ (:data:`LOOSE`);
- regulated: i = 10⁻⁹ and i' placed by (117) so that j ≈ −0.7i (:data:`REGULATED`); the formulas are then
  given the exact θ as j, never the j of (117).

Cost: one tilted solve (Newton on the exact elastica, then one eigenproblem) is about 1.4 s at 30 digits; the
checks share them through :func:`point` (lru_cache) and the result cache.
"""
from __future__ import annotations

import functools

import mpmath as mp
import sympy as sp

from pendsym import cache, checks, keys, nonlinear_blade, nonlinear_tilt, verify
from ..ch2_common import J
from ..ch7_gravity import truth as gravity
from . import derivation

DIRECT, INVERTED = "u=2", "u=1/2"       # the uniform blades λ = 0.1 m (chapter VII's u = 2; u = 1/2 < π/2, n°101)
EPS = checks.Geometric("1e-6", "1e-3")   # as chapter VII's order checks in ε
DELTA, RATIO, KAPPA = "1e-9", "-0.6", "-0.7"   # the size of the errors; i'/i not regulated; j/i regulated
LOOSE, REGULATED = "not regulated", "regulated"
VERSION = "1"
MODEL = ("the exact tilted blade (pendsym.nonlinear_tilt: exact elastica and statics with the errors i, i', the "
         "exact linearisation about the equilibrium, eigenproblem), its slow mode, at a = a1 {sign} ελ with a1 "
         "where det K = 0 of the directly solved blade; 30 digits, confirmed at 45")


def _slow_solve(key: str, sign: int, a: str, i: str, i_prime: str, dps: int) -> tuple:
    blade = gravity.base_blade(key, sign)
    g = str(sign * mp.mpf(gravity.G_VALUE))
    eq = nonlinear_tilt.equilibrium(blade, a, g, i, i_prime, dps)
    with mp.workdps(nonlinear_blade.working_dps(blade, dps)):
        a_v, R, g_v, ip = mp.mpf(a), mp.mpf(gravity.R_VALUE), mp.mpf(g), mp.mpf(i_prime)
        slow = gravity.eigenmodes(gravity.direct(key, sign, 0, dps), a_v, R, g_v)[0][0]
        A, B = nonlinear_tilt.linearised_matrices(eq, a_v, R, g_v, ip)
        mu, _ = mp.eig(mp.inverse(B) * A)
        omegas = [1 / m for m in mu if abs(m) > mp.mpf(10) ** (-(mp.mp.dps // 2))]
        omega2 = min(omegas, key=lambda o: abs(o - slow))
        if abs(mp.im(omega2)) > mp.mpf(10) ** (-(dps + 3)) * abs(omega2) or abs(omega2 / slow - 1) > mp.mpf("0.01"):
            raise nonlinear_blade.NoConvergence(f"no slow eigenvalue near {mp.nstr(slow, 8)}: {omega2}")
        return eq.theta, 2 * mp.pi / mp.sqrt(mp.re(omega2))


def slow_tilted(key: str, sign: int, a: str, i: str, i_prime: str, dps: int) -> tuple:
    """(θ, T): the exact tilted equilibrium's θ and the period of the slow mode about it (the eigenvalue of
    :func:`pendsym.nonlinear_tilt.linearised_matrices` nearest the untilted slow n², within 1 %), on chapter
    VII's blade ``key`` (sign −1: inverted); cached by its inputs (strings)."""
    key_ = keys.digest(("ch7_clamping.slow_tilted", VERSION, keys.FORMAT, *keys.versions(),
                        keys.file_hash(keys.module_file(nonlinear_tilt.__name__)),
                        keys.file_hash(keys.module_file(nonlinear_blade.__name__)),
                        keys.file_hash(keys.module_file(gravity.__name__)),
                        key, str(sign), a, i, i_prime, str(dps)))
    return cache.memo(key_, lambda: _slow_solve(key, sign, a, i, i_prime, dps))


@functools.lru_cache(maxsize=64)
def point(key: str, sign: int, regime: str, eps: str, dps: int) -> dict:
    """The errors (i, i'), a, the exact θ and T/T0 − 1 of the slow mode at a = a1 + sign·ελ."""
    env = gravity.numbers(key, sign, dps)
    digits = dps + 15
    with mp.workdps(digits + 10):
        eps_v, delta, ratio, kappa = (mp.mpf(x) for x in (eps, DELTA, RATIO, KAPPA))
        a = env["a_1"] + sign * eps_v * env["lambda"]
        if regime == LOOSE:
            i = delta * eps_v
            ip = ratio * i
        else:   # (117): j(a − a1) = −(a − vλ)i − ai', solved for i' at j = KAPPA·i
            i = delta
            ip = -(kappa * i * (a - env["a_1"]) + (a - env["v_lambda"]) * i) / a
        a_s, i_s, ip_s = (mp.nstr(x, digits) for x in (a, i, ip))
    theta, T = slow_tilted(key, sign, a_s, i_s, ip_s, dps)
    _, T0 = slow_tilted(key, sign, a_s, "0", "0", dps)
    with mp.workdps(dps + 10):
        return {"a": mp.mpf(a_s), "i": mp.mpf(i_s), "i'": mp.mpf(ip_s), "theta": theta, "ratio": T / T0 - 1}


def _eps_key(p) -> str:
    """ε as a 12-digit string: the sequence's values depend on the precision they were made at; the truth and
    the formulas all take this one value."""
    with mp.workdps(30):
        return mp.nstr(mp.mpf(p), 12)


def _eps(p) -> mp.mpf:
    return mp.mpf(_eps_key(p))


# ---------------------------------------------------------------- the formulas' inputs
@functools.lru_cache(maxsize=8)
def blade_inputs(key: str, sign: int, dps: int = 30) -> dict:
    """The shot blade's integrals at K = 0 by quadrature: G2 = ∫w²/M, F_2, F_4 = ∫w'^n, C = (wλ − F_4)/G2 (284),
    and A_0, A_1, A_2 of (287) from the moments J(p, q) = ∫φ1^pφ2^q ds (φ1 = 1 + v', φ2 = w')."""
    sol = gravity.shot(key, sign, dps)
    out = {}
    with mp.workdps(sol.wdps):
        moments = {}
        for p_, q_ in ((0, 3), (0, 4), (1, 2), (1, 3), (2, 2)):
            moments[J(p_, q_)] = sol.integrate(lambda s, p_=p_, q_=q_: (lambda st: (1 + st[1]) ** p_ * st[3] ** q_)(
                sol.state(s)))
        A = derivation.A_of_moments()
        for k in range(3):
            out[f"A_{k}"] = verify.value_at(A[derivation.A_p[k]].subs(derivation.K, 0), moments)
        out["G_2"] = sol.G(2, 0)
        F2, F4 = sol.F(2, 0), sol.F(4, 0)
        out.update({"F_2": F2, "F_4": F4, sp.Function("F")(2): F2, sp.Function("F")(4): F4,
                    "C": (sol.wl - F4) / out["G_2"]})
    return out


def env_at(key: str, sign: int, regime: str, p, dps: int = 30, sensitivity: bool = False) -> dict:
    """The inputs of a formula at ε = p: the truth's numbers (λ, w0, wλ, vλ, a1, u …), a, i, i' and j = the exact
    θ of :func:`point`, the blade's integrals (:func:`blade_inputs`) and, with ``sensitivity``, G =
    −d log n²/d log g of the slow mode (:func:`..ch7_gravity.truth.sensitivity`)."""
    env = dict(gravity.numbers(key, sign, dps))
    pt = point(key, sign, regime, _eps_key(p), dps)
    env.update({"varepsilon": _eps(p), "a": pt["a"], "i": pt["i"], "i'": pt["i'"], "j": pt["theta"]})
    if sign > 0:
        env.update(blade_inputs(key, sign, dps))
    if sensitivity:
        env["G"] = gravity.sensitivity(key, sign, _eps_key(p), dps)
    return env


def _scale(regime: str, pt: dict, eps) -> mp.mpf:
    """ε³/i² (not regulated: ΔT/T ~ j²G ~ i²/ε³) or ε/i² (regulated: ΔT/T ~ i²/ε)."""
    return (eps**3 if regime == LOOSE else eps) / pt["i"] ** 2


def period_order(key: str, sign: int, regime: str, what: str, sensitivity: bool = False) -> checks.Order:
    """ΔT/T of the slow mode against the form, both times ε³/i² (not regulated) or ε/i² (regulated): the
    residual of a leading term in ε falls like ε."""
    def truth(p, dps):
        pt = point(key, sign, regime, _eps_key(p), dps)
        return pt["ratio"] * _scale(regime, pt, _eps(p))

    def at(expr, p):
        env = env_at(key, sign, regime, p, sensitivity=sensitivity)
        return verify.value_at(expr, env) * _scale(regime, point(key, sign, regime, _eps_key(p), checks.DPS), _eps(p))
    errors = (f"i = 10⁻⁹ε, i' = {RATIO}i" if regime == LOOSE else f"i = 10⁻⁹, i' by (117) for j ≈ {KAPPA}i")
    return checks.Order(param="varepsilon", values=EPS, truth=truth, at=at, expected=1,
                        truth_desc=f"{MODEL.format(sign='+' if sign > 0 else '−')}; T/T0 − 1 of the slow mode, "
                                   f"{regime} ({errors}), times {'ε³' if regime == LOOSE else 'ε'}/i²; {what}; "
                                   f"blade {key}, {'direct' if sign > 0 else 'inverted'}",
                        params=(("blade", key), ("R", gravity.R_VALUE), ("g", str(sign * float(gravity.G_VALUE))),
                                ("regime", regime)))


def tilt_order() -> checks.Order:
    """n°94: j' = θ + i of the exact equilibrium (not regulated) against the form with G of the truth, both
    times ε/i (j' ~ i/ε): residual O(ε)."""
    def truth(p, dps):
        pt = point(DIRECT, 1, LOOSE, _eps_key(p), dps)
        return (pt["theta"] + pt["i"]) * _eps(p) / pt["i"]

    def at(expr, p):
        env = env_at(DIRECT, 1, LOOSE, p, sensitivity=True)
        return verify.value_at(expr, env) * _eps(p) / env["i"]
    return checks.Order(param="varepsilon", values=EPS, truth=truth, at=at, expected=1,
                        truth_desc=f"{MODEL.format(sign='+')}; j' = θ + i of the exact equilibrium, times ε/i; G = "
                                   f"−d log n²/d log g of the slow mode (stencil), G2 = ∫w²/M by quadrature; "
                                   f"i = 10⁻⁹ε, i' = {RATIO}i; blade {DIRECT}",
                        params=(("blade", DIRECT), ("R", gravity.R_VALUE), ("i'/i", RATIO)))


def symmetric_ratio(p, dps) -> mp.mpf:
    """i/j at i' = 0: ∂θ/∂i of the exact equilibrium from its θ at the two tilts of the checks (not regulated and
    regulated, same ε), θ = c·i + c'·i' (the equilibrium is odd in (i, i'): its cubic part is ~10⁻¹⁸ of it);
    1/c."""
    one = point(DIRECT, 1, LOOSE, _eps_key(p), dps)
    two = point(DIRECT, 1, REGULATED, _eps_key(p), dps)
    with mp.workdps(dps + 10):
        c, _ = mp.lu_solve(mp.matrix([[one["i"], one["i'"]], [two["i"], two["i'"]]]),
                           mp.matrix([one["theta"], two["theta"]]))
        return 1 / c


def symmetric_order() -> checks.Order:
    """(290): i/j at i' = 0 of the exact equilibrium against the form's i at j = 1, both over ε: residual O(ε)."""
    def truth(p, dps):
        return symmetric_ratio(p, dps) / _eps(p)

    def at(expr, p):
        env = dict(gravity.numbers(DIRECT, 1), varepsilon=_eps(p), j=1)
        return verify.value_at(expr, env) / _eps(p)
    return checks.Order(param="varepsilon", values=EPS, truth=truth, at=at, expected=1,
                        truth_desc=f"{MODEL.format(sign='+')}; i/j at i' = 0 (∂θ/∂i of the exact equilibrium, from θ "
                                   f"at the two tilts of the period checks), over ε; blade {DIRECT}",
                        params=(("blade", DIRECT), ("R", gravity.R_VALUE)))
