"""Haag 1935, chapter II, n°26–30: the independent truth.

- The period against the amplitude of the principal oscillation on the exact (large-deflection) blade,
  :mod:`pendsym.nonlinear_blade` (no expansion), against (111)–(112): the residual of
  T(θ0)/T_lin − 1 − (Q'/Q)θ0²/16 must fall like θ0⁴ (rule 3).  T_lin is the linear eigenproblem's
  2π/n (:mod:`pendsym.suspension`); K, z, z' come from its modes and F_n from the shot blade
  (:mod:`..profiles`).
- (114) on the rigid pendulum θ'' + n² sin θ = 0: Φ = n²(θ − sin θ), against its exact period
  4K(sin²(θ0/2))/n (mpmath's ellipk, an AGM).
- (106): the exact terms of (4)–(7) beyond the first approximation, evaluated with mpmath's sin and
  cos at a point scaled by p, against the series: residual of the next order.

Cost: each nonlinear period is one collocation solve at four nodes (about 2.2 s CPU at 30 digits, on the
precision ladder of pendsym.nonlinear_blade.orbit); the order checks use four amplitudes on one blade and a
33-digit confirmation at the first, cached on disk by pendsym.nonlinear_blade.track and shared by (111),
(112) and n°25's (64), (85) (one worker: the memoir's affinity group), about 12 s CPU cold in all.  α = λ − ½H2:
four exact elastica on the tapered blade and a 36-digit confirmation, about 2.3 s.
"""
from __future__ import annotations

import functools

import mpmath as mp
import sympy as sp

from pendsym import checks, nonlinear_blade, verify
from .. import profiles
from ..symbols import Fn

NONLINEAR_TRUTH = ("pendsym.nonlinear_blade: the principal periodic oscillation of the rigid pendulum on the exact "
                   "large-deflection blade (collocation on the quarter period, 30 digits), T(θ0)/T_lin − 1")
# θ0 (radians): four points in geometric progression (the project's least for a fitted order), a factor 4 in all
# (the θ0⁴ residual changes 256-fold).  Small
# enough that four collocation nodes give 30 digits (pendsym.nonlinear_blade.nodes_for; at θ0 = 0.0016 four
# nodes agree with six at 40 digits to 3e-32), large enough that the residual (≈ 2.6e-3 θ0⁴ ≥ 6e-17) stands
# 13 orders above the truth's precision
AMPLITUDES = ("0.0004", "0.0016")
ORDER_POINTS = 4
# the blade and pendulum of the order checks: the uniform blade (the cheapest to integrate: 1/M has no
# singularity to limit odefun's steps) under the short pendulum, where the blade matters most
CASE = ("uniform", "compact")


def amplitudes(level: str) -> list:
    """θ0 of the order checks (the same four points at both levels: each costs a nonlinear solve)."""
    return verify.geometric(*AMPLITUDES, ORDER_POINTS)


@functools.lru_cache(maxsize=8)
def blade_env(name: str, pend: str, dps: int) -> dict:
    """a, R, g, z, z', n², K = −n²z'/g (34) of the modes, and F2, F3, F4 (79) of the shot blade at K."""
    with mp.workdps(dps + 10):
        env = profiles.shot_and_mode_env(name, pend, dps)
        K = -env["n^2"] * env["z'"] / env["g"]
        shot = profiles.shot_blade(name, dps)
        env = dict(env, K=K)
        for k in (2, 3, 4):
            env[Fn(k)] = shot.F(k, K)
        return env


def track(name: str, pend: str, theta0, dps: int) -> nonlinear_blade.Track:
    """The principal oscillation of amplitude θ0 of the pendulum ``pend`` on the exact blade ``name`` (its
    period and the end's positions; cached on disk, so every check that asks for the same orbit shares it)."""
    a, R, g = profiles.PENDULUMS[pend]
    return nonlinear_blade.track(profiles.profile(name), a, R, g, mp.nstr(mp.mpf(theta0), 40), dps)


def relative_change(name: str, pend: str):
    """truth(θ0, dps): T(θ0)/T_lin − 1 of the exact blade."""
    def truth(theta0, dps):
        bl = profiles.profile(name)
        a, R, g = profiles.PENDULUMS[pend]
        T = track(name, pend, theta0, dps).period
        T_lin = nonlinear_blade.linear_period(bl, a, R, g, dps)
        with mp.workdps(dps + 10):
            return T / T_lin - 1
    return truth


def period_order(quantity: str) -> checks.Order:
    """(111) (the form is ΔT/T) or (112) (the form is Q', ΔT/T = (Q'/Q)θ0²/16 with Q = K(z − z') (45))
    against the exact blade: residual O(θ0⁴)."""
    name, pend = CASE

    def at(expr, theta0):
        env = dict(blade_env(name, pend, checks.DPS), theta_0=theta0)
        value = verify.value_at(expr, env)
        if quantity == "Qp":
            Q = env["K"] * (env["z"] - env["z'"])
            value = value / Q * mp.mpf(theta0) ** 2 / 16
        return value
    return checks.Order(param="θ0", values=amplitudes, truth=relative_change(name, pend), at=at, expected=4,
                        truth_desc=f"{NONLINEAR_TRUTH}; {name} blade, {pend} pendulum", confirm_dps=33,
                        params=(("blade", name), ("pendulum", pend)),
                        note="T_lin = 2π/n of pendsym.suspension.modes; K, z, z' of the modes, F_n of the shot blade")


# ---------------------------------------------------------------- (114) on the rigid pendulum
def rigid_relative(theta0, dps):
    """T/T0 − 1 of θ'' + n² sin θ = 0: 2K(sin²(θ0/2))/π − 1 (exact)."""
    with mp.workdps(dps + 10):
        return 2 * mp.ellipk(mp.sin(mp.mpf(theta0) / 2) ** 2) / mp.pi - 1


def classical_order() -> checks.Order:
    """(114) with Φ = n²(θ − sin θ) ≈ n²θ³/6: ∫Φ cos φ dφ along θ = θ0 cos φ, against the exact period."""
    n2 = sp.Symbol("n^2", positive=True)

    def at(expr, theta0):
        th0 = mp.mpf(theta0)
        with mp.workdps(50):
            # ∫_0^{2π} n²(θ0 cos φ)³/6 · cos φ dφ with n² = 1 (the form is homogeneous of degree 0 in n²)
            C = mp.quad(lambda ph: (th0 * mp.cos(ph)) ** 3 / 6 * mp.cos(ph), [0, mp.pi, 2 * mp.pi])
            return verify.value_at(expr, {"C": C, "n^2": 1, "theta_0": th0, n2.name: 1})
    return checks.Order(param="θ0", values=checks.Geometric("0.001", "0.05"), truth=rigid_relative, at=at,
                        expected=4, truth_desc="the rigid pendulum's exact period 4K(sin²(θ0/2))/n (mpmath ellipk)")


# ---------------------------------------------------------------- (106): the neglected terms
# the exact quantities of which (106) gives the third-order part, at a point scaled by p
_POINT = {"a": mp.mpf("0.7"), "g": mp.mpf("9.81"), "theta": mp.mpf("0.9"), "theta'": mp.mpf("-1.3"),
          "theta''": mp.mpf("0.6"), "alpha''": mp.mpf("0.4"), "Y": mp.mpf("0.35"), "varphi": mp.mpf("0.8")}
_ORDER = {"theta", "theta'", "theta''", "Y", "varphi"}       # first-order quantities (α'' is of the second)


def _scaled(p) -> dict:
    env = {k: (v * p if k in _ORDER else v) for k, v in _POINT.items()}
    env["alpha''"] = _POINT["alpha''"] * p * p
    return env


def _exact(component: int, env: dict):
    a, g, th, thd, thdd = env["a"], env["g"], env["theta"], env["theta'"], env["theta''"]
    if component == 0:        # gε1 = −g(1 − X) − (…)… : −ẍ_G = a(θ'' sin θ + θ'² cos θ) − α''
        return a * (thdd * mp.sin(th) + thd**2 * mp.cos(th)) - env["alpha''"]
    if component == 1:        # gε2 = β'' + aθ'' − ÿ_G = a(θ'' − θ'' cos θ + θ'² sin θ)
        return a * (thdd - thdd * mp.cos(th) + thd**2 * mp.sin(th))
    if component == 2:        # ε3 = a(Y cos θ − sin θ) − aY + aθ (X = 1)
        return a * (env["Y"] * mp.cos(th) - mp.sin(th)) - a * env["Y"] + a * th
    ph = env["varphi"]        # ε' = sin φ − Y cos φ − (φ − Y) (X = 1)
    return mp.sin(ph) - env["Y"] * mp.cos(ph) - ph + env["Y"]


def neglected_terms(component: int) -> checks.Order:
    """(106), one component: the exact term at the point scaled by p, minus the series: O(p⁴) for gε1
    (its α'' is already of the second order and exact), O(p⁵) for the others."""
    def truth(p, dps):
        with mp.workdps(dps + 10):
            return _exact(component, _scaled(mp.mpf(p)))

    def at(expr, p):
        return verify.value_at(expr[component], _scaled(mp.mpf(p)))
    expected = 4 if component == 0 else 5
    return checks.Order(param="p", values=checks.Geometric("0.001", "0.05"), truth=truth, at=at, expected=expected,
                        truth_desc="the exact (4)–(7) with mpmath's sin and cos at a point scaled by p")


# ---------------------------------------------------------------- α = λ − ½H2 on the exact elastica
ALPHA_CASE = "tapered"
_LOADS = (mp.mpf("0.6"), mp.mpf("0.05"))     # (Y, c0) per unit p, X = 1


@functools.lru_cache(maxsize=32)
def _exact_end(name: str, p: str, dps: int):
    bl = profiles.profile(name)
    wdps = nonlinear_blade.working_dps(bl, dps)
    return nonlinear_blade.end_state(bl, 1, _LOADS[0] * mp.mpf(p), _LOADS[1] * mp.mpf(p), wdps, variations=False)


@functools.lru_cache(maxsize=4)
def moments(name: str, dps: int) -> dict:
    """J(i, j) = ∫φ1^iφ2^j ds (i + j ≤ 4) on the shot blade, by the symbol J(i, j)."""
    from ..ch2_common import J
    shot = profiles.shot_blade(name, dps)
    with mp.workdps(shot.wdps):
        return {J(i, j): shot.integrate(lambda x, i=i, j=j: shot.phi1(x) ** i * shot.phi2(x) ** j)
                for i in range(5) for j in range(5) if i + j <= 4}


def alpha_order() -> checks.Order:
    """α = λ − ½H2 (n°29): the exact elastica's α at the loads (1, pY0, pc0), against λ − ½H2(Y, θ) with its
    end angle θ: residual O(p⁴)."""
    def truth(p, dps):
        return _exact_end(ALPHA_CASE, mp.nstr(mp.mpf(p), 40), dps).alpha

    def at(expr, p):
        end = _exact_end(ALPHA_CASE, mp.nstr(mp.mpf(p), 40), checks.DPS)
        env = dict(moments(ALPHA_CASE, checks.DPS), Y=_LOADS[0] * mp.mpf(p), theta=end.theta,
                   **{"lambda": profiles.as_mpf(profiles.profile(ALPHA_CASE).length)})
        return verify.value_at(expr, env)
    return checks.Order(param="p", values=lambda level: verify.geometric("0.002", "0.05", 4), truth=truth, at=at,
                        expected=4, confirm_dps=36,
                        truth_desc=f"the exact elastica (pendsym.nonlinear_blade.end_state), {ALPHA_CASE} blade, "
                                   "X = 1; moments of the shot blade")


# ---------------------------------------------------------------- (105): integration by parts
def parts_on_blades():
    """(105): −∫ε(Kv + w)/M ds on the shot blade, against the unreduced ∫ε'(Kφ1 + φ2) ds − ε_λ computed from
    φ1 = 1 + v', φ2 = w' by quadrature, for a test moment increment ε(s) = (1 + 2s/λ)² and two K."""
    from ..check_kinds import OnShotBlade

    def points(level, dps):
        for name in ("uniform", "tapered"):
            shot = profiles.shot_blade(name, dps)
            with mp.workdps(shot.wdps):
                lam = profiles.as_mpf(shot.blade.length)

                def eps(x, lam=lam):
                    return (1 + 2 * x / lam) ** 2

                def eps_prime(x, lam=lam):
                    return 4 * (1 + 2 * x / lam) / lam
                for K_text in ("0.9", "-0.4"):
                    K = mp.mpf(K_text)
                    truth = shot.integrate(lambda x: eps_prime(x) * (K * shot.phi1(x) + shot.phi2(x))) - eps(lam)
                    yield checks.Point(f"{name}/K={K_text}", {"K": K}, truth, abs(truth)), shot, eps, None
    return OnShotBlade(truth="quadrature on the shot blade of the unreduced ∫ε'(Kφ1 + φ2) ds − ε_λ "
                             "(φ1 = 1 + v', φ2 = w'), ε(s) = (1 + 2s/λ)²", points=points)


# ---------------------------------------------------------------- (101) by the variation of constants
def _test_eps(lam):
    return lambda x: (1 + 2 * x / lam) ** 2


def direct_delta_Y(name: str, dps: int):
    """ΔY of the boundary-value problem (93) solved directly: (Mx')' − x = ε − ΔY, x(0) = x(λ) = 0 and
    ∫x ds = 0 (β given), for the test ε(s) = (1 + 2s/λ)²; state (x, Mx', ∫x) by mpmath's odefun, the
    unknowns (Mx')(0) and ΔY by superposition (the problem is linear)."""
    from pendsym import blade as linear_blade
    bl = profiles.profile(name)
    with mp.workdps(dps + 10):
        lam = profiles.as_mpf(bl.length)
        eps = _test_eps(lam)
        pieces = [(mp.mpf(sp.Rational(a)), mp.mpf(sp.Rational(b)), sp.lambdify(bl.var, expr, modules="mpmath"))
                  for a, b, expr in linear_blade.segments(bl)]

        def end(mu0, dY, with_eps):
            state = [mp.mpf(0), mp.mpf(mu0), mp.mpf(0)]
            for a, b, Mf in pieces:
                def rhs(x, u, Mf=Mf):
                    return [u[1] / Mf(x), u[0] + (eps(x) if with_eps else 0) - dY, u[0]]
                state = mp.odefun(rhs, a, state, tol=mp.mpf(10) ** (-(dps + 8)))(b)
            return state[0], state[2]
        P, U, V = end(0, 0, True), end(1, 0, False), end(0, 1, False)
        # P + c U + d V: x(λ) = 0, ∫x = 0
        sol = mp.lu_solve(mp.matrix([[U[0], V[0]], [U[1], V[1]]]), mp.matrix([-P[0], -P[1]]))
        return sol[1]


def delta_Y_direct() -> checks.Values:
    """(101): I_1/β1 (I_1 = ∫εφ1 ds by quadrature on the shot blade) against :func:`direct_delta_Y`."""
    def points(level, dps):
        for name in ("uniform", "tapered"):
            shot = profiles.shot_blade(name, dps)
            with mp.workdps(shot.wdps):
                eps = _test_eps(profiles.as_mpf(shot.blade.length))
                I1 = shot.integrate(lambda x: eps(x) * shot.phi1(x))
                yield checks.Point(name, {"I_1": I1, "beta_1": shot.beta1}, direct_delta_Y(name, dps))
    return checks.Values(truth="the boundary-value problem (93) with ∫x ds = 0 solved directly (mpmath odefun, "
                               "superposition), ε(s) = (1 + 2s/λ)²; I_1 by quadrature on the shot blade",
                         points=points)


# ---------------------------------------------------------------- footnote of n°31: (114)'s θ0⁴ term
def next_term_false() -> checks.Values:
    """The θ0⁴ coefficient of the simple pendulum's T/T0 − 1, (T/T0 − 1 − θ0²/16)/θ0⁴ at small θ0 from the
    exact period (ellipk), must differ from the form's by more than half of it (a counterexample)."""
    def points(level, dps):
        for th in ("1e-3", "1e-4"):
            with mp.workdps(dps + 20):
                t0 = mp.mpf(th)
                c4 = (rigid_relative(t0, dps + 20) - t0**2 / 16) / t0**4
            yield checks.Point(f"θ0 = {th}", {}, c4, denom=abs(c4))
    return checks.Values(truth="the exact period of the simple pendulum 4K(sin²(θ0/2))/n (mpmath ellipk): "
                               "(T/T0 − 1 − θ0²/16)/θ0⁴ → 11/3072", points=points, fails_by="0.5")
