"""Haag 1935, chapter II, n°36–39: the independent truth.

- (135), (136): the principal n² of the pendulum on a blade that has mass (:mod:`pendsym.massive_blade`: the
  linearised blade with its horizontal inertia, or with the tension grown by its weight, and the rigid
  pendulum, an eigenproblem det D(ω²) = 0 shot by odefun at 30 digits), T/T0 − 1 against the formula:
  the residual must fall like (m'/m)² (rule 3).  The density follows the blade's width: uniform, or halved
  over the hole (the ``hole`` profile halves I, hence the width, in its middle third).  The formula's I_λ
  and J are quadratures on the shot blade (v, w of pendsym.blade) with K, z, z' of the massless modes.
- (141) at q = 0 and n°39: the linear eigenproblem (pendsym.suspension) on the blade M(1 + a0), whose
  T/T0 − 1 must differ from the formula by O(a0²).
- (141) at q = 2: the exact large-deflection blade with the law M(c + a2c³) (:mod:`pendsym.bending_law` in
  :mod:`pendsym.nonlinear_blade`'s collocation), T(θ0; a2)/T(θ0; 0) − 1 at the four amplitudes of (111) (whose
  linear-law orbits it shares), residual O(θ0⁴).

Cost (cold): each massive-blade n² with inertia is about 1–2 s CPU (a root at 15 digits, then at 30 by the
secant method from it: pendsym.massive_blade.principal_n2), with the weight only a single integration of the
blade; each (141) point 0.3 s; the mass checks five roots (four points and the confirmation at 36 digits),
the others five: (135) ≈ 7 s on the hole blade (its second form, with Q, on the same roots), (136) ≈ 2 s.  (141) at q = 2: four
orbits with the law (about 2.3 s each, started from the linear law's first rung) and one at 33 digits; the
linear-law orbits are (111)'s.
"""
from __future__ import annotations

import functools

import mpmath as mp
import sympy as sp

from pendsym import bending_law, blade, checks, massive_blade, nonlinear_blade, suspension, verify
from .. import profiles
from ..ch2_general import truth as general_truth
from ..symbols import G_2
from .derivation import a_q, g_fn, i_fn

PENDULUM = "compact"
MASSES = ("0.0001", "0.01")          # m'/m: four points in geometric progression (the O((m'/m)²) residual
MASS_POINTS = 4                      # changes 10⁴-fold over them; each point with inertia is a 1–2 s root)
YOUNG = ("0.0001", "0.01")           # ΔE/E = a0
POINTS = 4
CONFIRM_DPS = 36                     # the truth at the first point recomputed at 36 digits
MASSIVE_TRUTH = ("pendsym.massive_blade: the linearised blade with {what} carrying the rigid pendulum, the principal "
                 "root of det D(ω²) (odefun shooting, findroot), T/T0 − 1 against the massless blade")


@functools.lru_cache(maxsize=8)
def density(name: str) -> sp.Expr:
    """μ(s)/m' of the blade (per unit length, ∫ = 1): uniform, or in proportion to the width (M/M0 on the hole)."""
    bl = profiles.profile(name)
    shape = sp.S.One if name == "uniform" else bl.M / bl.M.subs(bl.var, 0)
    return sp.nsimplify(shape / sp.integrate(shape, (bl.var, 0, bl.length)))


def massive(name: str, ratio: str, inertia: bool) -> massive_blade.MassiveBlade:
    """The blade ``name`` of mass m' = ratio·m, with its inertia only (``inertia``) or its weight only."""
    return massive_blade.MassiveBlade(profiles.profile(name), sp.Rational(ratio) * density(name), inertia,
                                      not inertia)


def period_change(name: str, inertia: bool):
    """truth(m'/m, dps): T/T0 − 1 of the pendulum on the blade with mass."""
    def truth(ratio, dps):
        a, R, g = profiles.PENDULUMS[PENDULUM]
        return massive_blade.relative_period_change(massive(name, mp.nstr(mp.mpf(ratio), 20), inertia), a, R, g, dps)
    return truth


@functools.lru_cache(maxsize=8)
def blade_env(name: str, dps: int) -> dict:
    """K = −n²z'/g (34), z, z', Q = K(z − z'), m = 1, and per unit m'/m: I_λ (n°36) and J (n°37) by quadrature on
    the shot blade with y = K(s + v − v0) + w − w0 (θ = 1) and s − x = ½∫_0^s(Kφ1 + φ2)², by Fubini
    ∫ρ(s − x) ds = ½∫(Kφ1 + φ2)²(t)·∫_t^λ ρ ds dt."""
    env = profiles.shot_and_mode_env(name, PENDULUM, dps)
    shot = profiles.shot_blade(name, dps)
    with mp.workdps(shot.wdps):
        K = -env["n^2"] * env["z'"] / env["g"]
        rho_expr = density(name)
        rho = sp.lambdify(blade.S, rho_expr, modules="mpmath")
        lam = profiles.as_mpf(shot.blade.length)
        cuts = [profiles.as_mpf(x) for x in blade.breakpoints(shot.blade)]

        def tail(t):
            pts = [t] + [c for c in cuts if c > t]
            return mp.quad(rho, pts) if len(pts) > 1 else mp.mpf(0)

        def psi(t):
            st = shot.state(t)
            return K * (1 + st[1]) + st[3]
        I_unit = shot.integrate(lambda t: rho(t) * shot.y(t, K, 1) ** 2)
        J_unit = shot.integrate(lambda t: psi(t) ** 2 * tail(t)) / 2
        G2 = shot.G(2, K)
    return dict(env, K=K, Q=K * (env["z"] - env["z'"]), m=1, I_unit=I_unit, J_unit=J_unit, G_2=G2)


def mass_order(name: str, inertia: bool) -> checks.Order:
    """(135) (``inertia``) or (136) against the blade with mass: residual O((m'/m)²)."""
    def at(expr, ratio):
        env = blade_env(name, checks.DPS)
        p = mp.mpf(ratio)
        env = dict(env, **{"m'": p, "I_lambda": p * env["I_unit"], "J": env["J_unit"]})
        return verify.value_at(expr, env)
    what = "its horizontal inertia (no weight)" if inertia else "its weight in the tension (no inertia)"
    return checks.Order(param="m'/m", values=lambda level: verify.geometric(*MASSES, MASS_POINTS),
                        truth=period_change(name, inertia), at=at, expected=2, confirm_dps=CONFIRM_DPS,
                        truth_desc=MASSIVE_TRUTH.format(what=what) + f"; {name} blade, {PENDULUM} pendulum",
                        params=(("blade", name), ("pendulum", PENDULUM)),
                        note="I_λ = (m'/m)∫ρy² ds and J = ∫ρ(s − x) ds by quadrature on the shot blade (ρ = μ/m'); "
                             "K, z, z' of the massless modes")


def sign_on_blades(what: str) -> checks.Inequality:
    """A sign the memoir states ((135) a delay, (136) an advance), on the uniform and the hole blades."""
    def points(level, dps):
        for name in ("uniform", "hole"):
            env = blade_env(name, dps)
            yield name, dict(env, **{"m'": 1, "I_lambda": env["I_unit"], "J": env["J_unit"]})
    return checks.Inequality(truth=f"quadrature on the shot blade and the massless modes ({PENDULUM} pendulum); {what}",
                             points=points)


# ---------------------------------------------------------------- (141) at q = 0, n°39
def young_change(name: str):
    """truth(a0, dps): T/T0 − 1 of the pendulum on the blade M(1 + a0) (pendsym.suspension.modes)."""
    def truth(a0, dps):
        bl = profiles.profile(name)
        stiffer = blade.Blade(bl.length, bl.M * (1 + sp.Rational(mp.nstr(mp.mpf(a0), 20))), bl.var)
        a, R, g = profiles.pendulum(PENDULUM)
        with mp.workdps(dps + 10):
            n2 = suspension.modes(suspension.solve(stiffer, dps), a, R, g)[0].n2
            n2_0 = suspension.modes(suspension.solve(bl, dps), a, R, g)[0].n2
            return mp.sqrt(n2_0 / n2) - 1
    return truth


def young_order(name: str, general: bool) -> checks.Order:
    """(141) at q = 0 (``general``: i_2 by quadrature of its definition, g_1(a0) = ∫(Kv + w)²a0/M ds (139)) or
    n°39 (G2 of (79)), against the stiffer blade: residual O(a0²)."""
    def at(expr, a0):
        env = blade_env(name, checks.DPS)
        a0 = mp.mpf(a0)
        with mp.workdps(checks.DPS + 10):
            i2 = 2 / mp.pi * mp.quad(lambda x: mp.cos(x) ** 2, [0, mp.pi / 2])
        env = dict(env, **{"dE/E": a0, G_2.name: env["G_2"]})
        if general:
            expr = expr.subs(sp.Symbol("q", integer=True, nonnegative=True), 0)
            a_0 = a_q(0, sp.Symbol("s", real=True))
            env.update({i_fn(2): i2, g_fn(1, a_0): a0 * env["G_2"], a_0: a0})
        return verify.value_at(expr, env)
    return checks.Order(param="ΔE/E", values=lambda level: verify.geometric(*YOUNG, POINTS), truth=young_change(name),
                        at=at, expected=2,
                        truth_desc=f"pendsym.suspension.modes on the blade M(1 + a0) against M; {name} blade, "
                                   f"{PENDULUM} pendulum",
                        params=(("blade", name), ("pendulum", PENDULUM)),
                        note=("q = 0, a0 constant; i_2 by quadrature, g_1(a0) = a0∫(Kv + w)²/M ds on the shot blade"
                              if general else "G2 = ∫(Kv + w)²/M ds on the shot blade"))


# ---------------------------------------------------------------- (141) at q = 2: the exact blade with the law
# the law EIc(1 + a2c²) = EI(c + a2c³) (137) at q = 2 with a2 constant (m²): a2(c/θ)² ≈ 4·10⁻⁴ on this blade,
# a small law whose period change (≈ −1.2·10⁻⁵θ0²) the 30-digit truth resolves to 18 digits at the smallest θ0,
# and whose elastica odefun integrates in as many Taylor steps as the linear law's (a2 = 10⁻² takes five
# steps for three: the law's complex singularity, 1 + 3a2c² = 0, comes nearer)
LAW_A2 = sp.Rational(1, 10**6)
LAW_TRUTH = ("pendsym.nonlinear_blade with pendsym.bending_law.CubicLaw: the principal periodic oscillation of the "
             "rigid pendulum on the exact large-deflection blade with the bending moment M(c + a2c³), against the same "
             "blade with the linear law Mc at the same amplitude (collocation on the quarter period, 30 digits): "
             "T(θ0; a2)/T(θ0; 0) − 1")


def law_change(name: str, pend: str):
    """truth(θ0, dps): T(θ0; a2)/T(θ0; 0) − 1 on the exact blade ``name`` under the pendulum ``pend``: the law's
    part of the period, the isochronism of the linear law taken out by the ratio (the linear-law orbits are those
    of (111), :func:`..ch2_general.truth.track`, cached by their inputs and shared)."""
    def truth(theta0, dps):
        a, R, g = profiles.PENDULUMS[pend]
        theta0 = mp.nstr(mp.mpf(theta0), 40)
        # the law moves the orbit by about 10⁻¹² (the first rung holds 12–14 digits): the linear law's first rung
        # (shared with (111)) starts its chord steps
        law = nonlinear_blade.track(profiles.profile(name), a, R, g, theta0, dps, law=bending_law.CubicLaw(LAW_A2),
                                    linear_ladder=True).period
        linear = general_truth.track(name, pend, theta0, dps).period
        with mp.workdps(dps + 10):
            return law / linear - 1
    return truth


@functools.lru_cache(maxsize=4)
def law_env(name: str, pend: str, dps: int) -> dict:
    """K, z, z', n² of the modes, Q = K(z − z') (45) and G4 = ∫(Kv + w)⁴/M³ ds (79) on the shot blade, i_4 by
    quadrature of its definition (2/π)∫cos⁴φ dφ."""
    env = general_truth.blade_env(name, pend, dps)
    with mp.workdps(dps + 10):
        G4 = profiles.shot_blade(name, dps).G(4, env["K"])
        i4 = 2 / mp.pi * mp.quad(lambda x: mp.cos(x) ** 4, [0, mp.pi / 2])
        return dict(env, Q=env["K"] * (env["z"] - env["z'"]), G_4=G4, i_4=i4)


def law_order() -> checks.Order:
    """(141) at q = 2 against the exact blade with the law M(c + a2c³): g_3(a2) = a2G4 (140), residual O(θ0⁴) (the
    law's interaction with the isochronism; a wrong θ0^q, i_{q+2} or g_{q+1} would leave O(θ0²))."""
    name, pend = general_truth.CASE

    def at(expr, theta0):
        env = law_env(name, pend, checks.DPS)
        q = sp.Symbol("q", integer=True, nonnegative=True)
        a_2 = a_q(2, sp.Symbol("s", real=True))
        expr = expr.subs(q, 2)
        a2 = mp.mpf(LAW_A2.p) / LAW_A2.q
        values = dict(env, theta_0=mp.mpf(theta0))
        values.update({i_fn(4): env["i_4"], g_fn(3, a_2): a2 * env["G_4"], a_2: a2})
        return verify.value_at(expr, values)
    return checks.Order(param="θ0", values=general_truth.amplitudes, truth=law_change(name, pend), at=at,
                        expected=4, confirm_dps=33,
                        truth_desc=f"{LAW_TRUTH}; a2 = {LAW_A2} m², {name} blade, {pend} pendulum",
                        params=(("blade", name), ("pendulum", pend), ("q", "2"), ("a2", str(LAW_A2))),
                        note="q = 2, a2 constant: g_3(a2) = a2G4 (140), G4 = ∫(Kv + w)⁴/M³ ds on the shot blade, i_4 "
                             "by quadrature; K, z, z' of the modes; the θ0 of (111)")


# ---------------------------------------------------------------- (147), (149): the damped oscillation
# the reduced equation θ'' + n²θ = f/(z − z') of n°28 with a dissipative friction of degrees p, q whose
# magnitude depends on the quadrant: C_out on the way out (|θ| growing), C_in on the way back, on each side
FRICTION = {"p": 1, "q": 1, "n": "1.3", "Q": "0.8", "theta_0": "0.05",
            "a_pq": "0.3", "b_pq": "0.7", "a'_pq": "0.2", "b'_pq": "0.5"}
STRENGTHS = ("0.001", "0.1")            # the scale ε of the four coefficients


@functools.lru_cache(maxsize=16)
def friction_cycle(eps: str, dps: int) -> tuple:
    """(T n/(2π) − 1, θ(T) − θ0) over one period from the maximum θ0 (θ' = 0) to the next maximum, for
    θ'' = −n²θ − sign(θ')(n²/Q)C|θ|^p|θ'|^q (a force that always opposes the motion), C = ε·(b, a', b', a) in
    the quadrants (θ > 0 back, θ < 0 out, θ < 0 back, θ > 0 out); odefun on each quadrant, its end (θ = 0 or
    θ' = 0) found by findroot on the dense solution.  Cached in the process: (147) and (149) read the two
    components of the same cycles."""
    with mp.workdps(dps + 10):
        F = {k: mp.mpf(v) if isinstance(v, str) else v for k, v in FRICTION.items()}
        e = mp.mpf(eps)
        n, Q, p, q = F["n"], F["Q"], F["p"], F["q"]
        # (coefficient, ends at θ' = 0, sign of θ'): back on the right, out on the left, back on the left, out on the right
        quadrants = ((F["b_pq"], 0, -1), (F["a'_pq"], 1, -1), (F["b'_pq"], 0, 1), (F["a_pq"], 1, 1))
        t, state = mp.mpf(0), [F["theta_0"], mp.mpf(0)]
        tol = mp.mpf(10) ** (-(dps + 8))
        for C, ends_on_rate, sign_rate in quadrants:
            def rhs_q(_, y, C=C, sg=sign_rate):
                return [y[1], -n**2 * y[0] - sg * n**2 / Q * e * C * abs(y[0]) ** p * abs(y[1]) ** q]
            sol = mp.odefun(rhs_q, t, state, tol=tol)
            k = 1 if ends_on_rate else 0
            t = mp.findroot(lambda x: sol(x)[k], t + mp.pi / (2 * n), tol=mp.mpf(10) ** (-2 * (dps + 6)))
            state = list(sol(t))
            state[k] = mp.mpf(0)
        return t * n / (2 * mp.pi) - 1, state[0] - F["theta_0"]


def friction_order(component: int) -> checks.Order:
    """(147) (component 0: ΔT/T) or (149) (component 1: Δθ0) against the integrated damped oscillation:
    residual O(ε²)."""
    def truth(eps, dps):
        return friction_cycle(mp.nstr(mp.mpf(eps), 20), dps)[component]

    def at(expr, eps):
        e = mp.mpf(eps)
        F = FRICTION
        p, q = F["p"], F["q"]
        m_, n_ = (p + 1, q) if component == 0 else (p, q + 1)
        with mp.workdps(checks.DPS + 10):
            i_mn = 2 / mp.pi * mp.quad(lambda x: mp.cos(x) ** m_ * mp.sin(x) ** n_, [0, mp.pi / 2])
        pq = sp.Symbol("p", integer=True, nonnegative=True), sp.Symbol("q", integer=True, nonnegative=True)
        expr = expr.subs({pq[0]: p, pq[1]: q})
        env = {"n": F["n"], "Q": F["Q"], "theta_0": F["theta_0"],
               **{k: e * mp.mpf(F[k]) for k in ("a_pq", "b_pq", "a'_pq", "b'_pq")},
               g_fn(p + q, 1): 1, i_fn(m_, n_): i_mn}
        return verify.value_at(expr, env)
    what = "ΔT/T = Tn/(2π) − 1" if component == 0 else "Δθ0 = θ(T) − θ0"
    return checks.Order(param="ε", values=lambda level: verify.geometric(*STRENGTHS, POINTS), truth=truth, at=at,
                        confirm_dps=CONFIRM_DPS,
                        expected=2,
                        truth_desc="θ'' + n²θ = −sign(θ')(n²/Q)C|θ|^p|θ'|^q (the reduced equation of n°28 with a "
                                   "friction opposing the motion, C by quadrant: b right going back, a' left going out, b' left going "
                                   "back, a right going out) "
                                   f"integrated by odefun over one period from a maximum to the next: {what}",
                        params=tuple((k, str(v)) for k, v in FRICTION.items()),
                        note="g_{p+q}(1) = 1 (the coefficients stand for g_{p+q}(a_pq) …); i_mn by quadrature")
