"""The independent truth for Cellérier: a rigid pendulum whose knife edge rides on a spring;
the free pendulum, whose integrated swing gives Newton's pressures on a fixed knife edge; and a
pendulum under a test forcing, for the general formulas of the earlier memoir.

Model: a rigid body (mass m, centre of gravity at distance h from the knife
edge, moment of inertia C about it) swings about a knife edge O' that moves
horizontally, y1(t), on a support of compliance K (restoring force −y1/K) and
mass M (M = 0: Cellérier's massless, static support).  The equations are the
Euler–Lagrange equations of

    L = ½ m |v_G|² + ½ (C − m h²) θ'² + m g h cos θ + ½ M y1'² − y1²/(2K),

derived by SymPy; the 2×2 mass matrix is solved for (θ'', y1'') (the
constraint y1 = K Q with Q = −m (y1 + h sin θ)'' reduced to an explicit ODE).
Nothing here uses the memoir's perturbation formulas.

The system has a fast mode (the support vibrating, ω_f² ≈ 1/(K m_eff)) that
Cellérier discards (its vibrations "se disperseraient dans le sol").  The start
is placed on the slow (quasi-static) manifold y1 = K Y0 + K² Y1 + O(K³),
computed here by SymPy from the same equations, so the fast mode is excited
only at O(K³).  The start is at rest, θ = α, y1' = 0 (the slow manifold is
symmetric under time reversal); the swing time is the next zero of θ'.

State vector for mpmath: [sin θ, cos θ, θ', y1, y1'] (no trigonometric calls:
odefun works at a very high internal precision).
"""
from __future__ import annotations

from functools import lru_cache

import mpmath as mp
import sympy as sp

from pendsym import truth
from .symbols import C, K, M, g, h, m

time = sp.Symbol("t", real=True)
theta_f, y_f = sp.Function("theta")(time), sp.Function("y1")(time)
sin_th, cos_th, w_th, y1_s, y1dot_s = sp.symbols("S C_theta W Y V", real=True)   # sin θ, cos θ, θ', y1, y1'
theta_acc, y1_acc = sp.symbols("A_theta A_y", real=True)                              # θ'', y1''


@lru_cache(maxsize=None)
def equations() -> tuple[sp.Expr, sp.Expr]:
    """Euler–Lagrange equations E_θ = 0, E_y = 0 in the symbols θ'' → A_θ, y1'' → A_y."""
    xG = h * sp.cos(theta_f)                      # vertical (downward) coordinate of G
    yG = y_f + h * sp.sin(theta_f)
    kin = m / 2 * (sp.diff(xG, time) ** 2 + sp.diff(yG, time) ** 2) + (C - m * h**2) / 2 * sp.diff(theta_f, time) ** 2
    kin += M / 2 * sp.diff(y_f, time) ** 2
    pot = -m * g * xG + y_f**2 / (2 * K)
    L = kin - pot
    eqs = []
    for q in (theta_f, y_f):
        e = sp.diff(sp.diff(L, sp.diff(q, time)), time) - sp.diff(L, q)
        eqs.append(e)
    rep = {sp.diff(theta_f, time, 2): theta_acc, sp.diff(y_f, time, 2): y1_acc}
    rep2 = {sp.diff(theta_f, time): w_th, sp.diff(y_f, time): y1dot_s}
    out = []
    for e in eqs:
        e = e.subs(rep).subs(rep2).subs(y_f, y1_s)
        e = e.subs({sp.sin(theta_f): sin_th, sp.cos(theta_f): cos_th})
        out.append(sp.expand(e))
    return tuple(out)


@lru_cache(maxsize=None)
def accelerations() -> tuple[sp.Expr, sp.Expr]:
    """(θ'', y1'') solved from the Euler–Lagrange equations (mass matrix inverted)."""
    sol = sp.solve(list(equations()), [theta_acc, y1_acc], dict=True)
    if len(sol) != 1:
        raise ValueError("singular mass matrix")
    return sp.simplify(sol[0][theta_acc]), sp.simplify(sol[0][y1_acc])


def lie_derivative(expr: sp.Expr, th_dd: sp.Expr) -> sp.Expr:
    """d/dt of a function of (θ, θ') along a flow with θ'' = th_dd (θ kept as sin, cos)."""
    return sp.diff(expr, sin_th) * cos_th * w_th - sp.diff(expr, cos_th) * sin_th * w_th + sp.diff(expr, w_th) * th_dd


@lru_cache(maxsize=None)
def slow_manifold() -> tuple[sp.Expr, sp.Expr]:
    """(Y0, Y1) with y1 = K Y0 + K² Y1 + O(K³) invariant under the flow (SymPy, from the equations).

    The y1-equation is linear in y1 with coefficient 1/K: y1 = K·(…) is solved
    with y1'' = K D²Y0 + O(K²), D the time derivative along the free pendulum
    (K → 0), and θ'' taken from the θ-equation with that y1''.  Y1 is the
    K²-coefficient (second derivative at K = 0, no simplification needed).
    """
    E_th, E_y = equations()
    th_dd0 = sp.solve(E_th.subs(y1_acc, 0), theta_acc)[0]
    Y_of = sp.solve(E_y, y1_s)[0]
    Y0 = sp.factor(sp.cancel(Y_of.subs({y1_acc: 0, theta_acc: th_dd0, y1dot_s: 0}) / K))
    D2Y0 = lie_derivative(lie_derivative(Y0, th_dd0), th_dd0)
    th_dd1 = sp.solve(E_th.subs(y1_acc, K * D2Y0), theta_acc)[0]
    Yk = Y_of.subs({y1_acc: K * D2Y0, theta_acc: th_dd1, y1dot_s: 0})
    Y1 = sp.diff(Yk, K, 2).subs(K, 0) / 2
    # structure: Yk = K Y0 + K² Y1 exactly (checked at a rational point with S² + C² = 1)
    point = {sin_th: sp.Rational(3, 5), cos_th: sp.Rational(4, 5), w_th: sp.Rational(2, 7), m: sp.Rational(3, 2),
             h: sp.Rational(1, 3), C: sp.Rational(5, 7), g: sp.Rational(9, 8), M: sp.Rational(1, 4)}
    kk = sp.Rational(1, 11)
    if sp.nsimplify(Yk.subs(point).subs(K, kk) - (kk * Y0 + kk**2 * Y1).subs(point)) != 0:
        raise ValueError("slow manifold: unexpected structure")
    return Y0, Y1


@lru_cache(maxsize=None)
def _numeric():
    ath, ay = accelerations()
    args = (sin_th, cos_th, w_th, y1_s, y1dot_s, m, h, C, g, K, M)
    acc = sp.lambdify(args, (ath, ay), "mpmath")
    Y0, Y1 = slow_manifold()
    ic = sp.lambdify((sin_th, cos_th, m, h, C, g, K, M), (K * Y0 + K**2 * Y1).subs(w_th, 0), "mpmath")
    return acc, ic


def rhs(params: dict):
    acc, _ = _numeric()
    pv = [mp.mpf(params[k]) for k in ("m", "h", "C", "g", "K", "M")]

    def f(t, y):
        s, c, w, yy, v = y
        a1, a2 = acc(s, c, w, yy, v, *pv)
        return [c * w, -s * w, a1, v, a2]
    return f


def free_swing_time(alpha_val, params: dict):
    """T0 = 2 K(sin²(α/2))/ω0 with ω0² = m g h / C: the free pendulum's swing time."""
    w0 = mp.sqrt(mp.mpf(params["m"]) * mp.mpf(params["g"]) * mp.mpf(params["h"]) / mp.mpf(params["C"]))
    return 2 * mp.ellipk(mp.sin(mp.mpf(alpha_val) / 2) ** 2) / w0


@lru_cache(maxsize=None)
def _start(alpha_val: str, K_val: str, M_val: str, dps: int, h_val: str, m_val: str, g_val: str, l_val: str):
    """The trajectory from rest at θ = α on the slow manifold: (trajectory, y1 at 0, T0), l = C/(m h)."""
    with mp.workdps(dps):
        params = {"m": mp.mpf(m_val), "h": mp.mpf(sp.Rational(h_val).p) / sp.Rational(h_val).q,
                  "g": mp.mpf(g_val), "K": mp.mpf(K_val),
                  "M": mp.mpf(M_val)}
        params["C"] = mp.mpf(l_val) * params["m"] * params["h"]
        _, ic = _numeric()
        a = mp.mpf(alpha_val)
        s0, c0 = mp.sin(a), mp.cos(a)
        y0 = ic(s0, c0, params["m"], params["h"], params["C"], params["g"], params["K"], params["M"])
        traj = truth.integrate(rhs(params), [s0, c0, 0, y0, 0], dps)
        return traj, y0, free_swing_time(a, params)


def _key(alpha_val, K_val, M_val, dps, h_val="0.2", m_val="1", g_val="1", l_val="1"):
    return alpha_val, K_val, M_val, dps, h_val, m_val, g_val, l_val


@lru_cache(maxsize=None)
def lowest_time(alpha_val: str, K_val: str, M_val: str = "0", dps: int = 30, h_val: str = "0.2",
                m_val: str = "1", g_val: str = "1", l_val: str = "1") -> tuple:
    """(t at θ = 0, T0) of the swing from rest at α: only the first half swing is integrated."""
    traj, _, T0 = _start(*_key(alpha_val, K_val, M_val, dps, h_val, m_val, g_val, l_val))
    with mp.workdps(dps):
        return truth.event(traj, lambda y, t: y[0], T0 / 2, width=T0 / 8), T0


@lru_cache(maxsize=None)
def swing(alpha_val: str, K_val: str, M_val: str = "0", dps: int = 30, h_val: str = "0.2",
          m_val: str = "1", g_val: str = "1", l_val: str = "1") -> tuple:
    """One swing from rest at θ = α on the slow manifold: (T, θ at T, y1 at 0, T0, t at θ = 0).

    Returns mpf values; l = C/(m h) fixes C.
    """
    key = _key(alpha_val, K_val, M_val, dps, h_val, m_val, g_val, l_val)
    traj, y0, T0 = _start(*key)
    with mp.workdps(dps):
        t_low, _ = lowest_time(*key)
        T = truth.event(traj, lambda y, t: y[2], T0, width=T0 / 8)
        s, c, _, _, _ = traj(T)
        return T, mp.atan2(s, c), y0, T0, t_low


def delta_measured(alpha_val: str, K_val: str, M_val: str = "0", dps: int = 30, **kw):
    """(T − T0)/T0 of the model (the measured relative lengthening of the swing).

    T is twice the time of the lowest point: on the quasi-static (slow) orbit the swing is
    symmetric, θ(T − t) = −θ(t) (time reversal and the reflection θ, y1 → −θ, −y1), so
    both are the same; at the lowest point the O(K³) support vibration left by the start
    shifts the time by O(K³), at the turning point by O(K^2.5) (θ'' is small there).
    Only the first half swing is integrated.
    """
    t_low, T0 = lowest_time(alpha_val, K_val, M_val, dps, **kw)
    return 2 * t_low / T0 - 1


def amplitude_change(alpha_val: str, K_val: str, M_val: str = "0", dps: int = 30, **kw):
    """|θ(T)| − α: change of the amplitude over one swing."""
    T, th_end, _, _, _ = swing(alpha_val, K_val, M_val, dps, **kw)
    return -th_end - mp.mpf(alpha_val)


# ---------------------------------------------------------------- the free pendulum and Newton's pressures
@lru_cache(maxsize=None)
def free_swing_trajectory(alpha_val: str, dps: int):
    """θ'' = −sin θ (g = l = 1) from rest at θ = α: trajectory with state [θ, θ']."""
    with mp.workdps(dps):
        return truth.integrate(lambda tt, y: [y[1], -mp.sin(y[0])], [mp.mpf(alpha_val), 0], dps)


def newton_pressures(traj, s, hh=1, mm=1):
    """P, Q = −m d²(h cos θ)/dt², −m d²(h sin θ)/dt² by numerical differentiation of the solution at s."""
    # fixed step: the trajectory is evaluated at its own precision (an automatic step would round away)
    step = mp.mpf("1e-7")
    P = -mm * mp.diff(lambda x: hh * mp.cos(traj(x)[0]), s, 2, h=step)
    Q = -mm * mp.diff(lambda x: hh * mp.sin(traj(x)[0]), s, 2, h=step)
    return P, Q


# ---------------------------------------------------------------- the forced pendulum (machinery)
NU = mp.mpf("1.3")   # frequency of the explicit time dependence of the test forcing


@lru_cache(maxsize=None)
def forced_swing(forcing_key: str, alpha_val: str, eps_val: str, dps: int = 30):
    """θ'' = −sin θ + ε F (ω0 = 1) from rest at θ = α: (T/T0 − 1, α1 = α − |θ(T)|).

    State [sin θ, cos θ, θ', cos νt, sin νt] (polynomial right-hand side).
    """
    with mp.workdps(dps):
        a, ev, nu = mp.mpf(alpha_val), mp.mpf(eps_val), +NU
        Fn = FORCINGS[forcing_key](a)

        def f(t, y):
            s, c, w, cn, sn = y
            return [c * w, -s * w, -s + ev * Fn(s, c, w, cn), -nu * sn, nu * cn]
        traj = truth.integrate(f, [mp.sin(a), mp.cos(a), 0, 1, 0], dps)
        T0 = 2 * mp.ellipk(mp.sin(a / 2) ** 2)
        T = truth.event(traj, lambda y, t: y[2], T0, width=T0 / 8)
        s, c = traj(T)[:2]
        return T / T0 - 1, a + mp.atan2(s, c)


def _generic(a):
    """F = sin θ + 0.4 θ' + 0.3 sin θ cos θ + 0.25 α cos(1.3 t): state and time dependent, O(α)."""
    c1, c2, c3 = mp.mpf("0.4"), mp.mpf("0.3"), mp.mpf("0.25") * a
    return lambda s, c, w, cn: s + c1 * w + c2 * s * c + c3 * cn


def _timefree(a):
    """F = sin θ + 0.4 θ' + 0.3 sin θ cos θ (no explicit time)."""
    c1, c2 = mp.mpf("0.4"), mp.mpf("0.3")
    return lambda s, c, w, cn: s + c1 * w + c2 * s * c


def time_form(key: str, a):
    """The same forcing as f(sin θ, cos θ, θ', t) for pendsym.finite_amplitude."""
    Fn = FORCINGS[key](mp.mpf(a))
    return lambda s, c, w, t: Fn(s, c, w, mp.cos(NU * t))


FORCINGS = {"generic": _generic, "timefree": _timefree}
FORCING_TEXT = "F = sin θ + 0.4 θ' + 0.3 sin θ cos θ + 0.25 α cos(1.3 t)"
