"""Haag 1935, chapter VII, n°98: the independent truth of the dissymmetric blade of the gravity pendulum.

The model is the reduced equation of the gravity pendulum (one degree of freedom, n = 1), written in the angle θ
of the rod from the vertical:

    θ'' = −V'(θ),   V(θ) = ½θ² − Fθ + (GC/24)θ⁴ + ½ε_E G θ² [θ > 0],   F = j + (GC/6)j³,

- the blade's modulus is larger by ΔE = ε_E E on the side θ > 0 (n°44): the blade's restoring moment, G times
  the net one (G = G2/Q, (262)), gains ε_E G θ there — chapter II's f (151) at K → 0, B = g1 = ε_E G2, i → 0;
- the cubic term (GC/6)θ³ is the nonlinearity that gives the isochronism error (283), −GCθ0²/16; about the
  tilted equilibrium it gives (286), −GCj²/4, by itself (the ratio 4 is that of a cubic restoring law);
- the constant couple F of the clamping errors puts the equilibrium of the symmetric blade (ε_E = 0) at θ = j.

It is conservative, so one period is T = 2∫dθ/√(2(E − V)) between the turning points θ_min, θ_max, E = V(θ_max),
for the swing of half-width θ0 = (θ_max − θ_min)/2 (Haag's amplitude of θ1 = θ − j; starting instead from
θ = j + θ0 would make the symmetric pendulum's T uneven in j at second order, which moves the maximum of T by about
GCθ0³/10: as much as (301)'s own correction when γ is of order θ0).  The turning point below is a root of the branch's quartic (mpmath's polyroots);
E − V(θ) is written (θ_t − θ)·S(θ_t, θ) without cancellation and θ = θ_t ∓ u² removes the inverse square roots,
so that each piece (split at θ = 0 where the stiffness jumps) is a smooth quadrature (mpmath's quad) at 30 digits
(45 to confirm).  ΔT/T = T/(2π) − 1.

What it tests: Haag's first-harmonic averaging (114) of the one-sided force over the half-period θ > 0 ((153),
(154)), the specialisation to the gravity pendulum, the sum with (286) and the extremes drawn from it.  What it
does not test: the reduction to one degree of freedom (the one-sided stiffness ε_E G and the cubic GC/6 are put in
from (151), (262) and (283)); chapter II's truths and chapter VII's eigenproblem judge those.
"""
from __future__ import annotations

import functools

import mpmath as mp

# G, C: the sensitivity and the coefficient of (284) (C of the uniform blade lies in (1, 3/2), (285));
# RATIO = ε_E/θ0², so that tan α = 2ε_E/(πCθ0²) stays fixed along the order checks (α ≈ 0.47 rad derived).
G_VALUE, C_VALUE, RATIO = "10", "1.25", "1"
PHASE_J = ("-0.4", "0.5")              # j/θ0 of the two cases of (295): on the soft side and on the stiff side
EPS_RANGE = ("1e-5", "1e-3")           # ε_E along the order checks (θ0 = √(ε_E/RATIO))
THETA0_RANGE = ("0.004", "0.03")       # θ0 along the check of (301), ε_E = RATIO_301·θ0³
RATIO_301 = "2"


def _mpf(x) -> mp.mpf:
    return mp.mpf(x)


def _S(A, F, B, x, y):
    """(V(x) − V(y))/(x − y) for V = Aθ²/2 − Fθ + Bθ⁴/4."""
    return A * (x + y) / 2 - F + B * (x + y) * (x * x + y * y) / 4


def _bottom(top, F, B, right, dps: int):
    """The energy E = V(top), the stiffness of the lower branch and the lower turning point of the swing that
    starts at rest from θ = top > 0: the largest root below the well of the branch's quartic (polyroots)."""
    E = right * top**2 / 2 - F * top + B * top**4 / 4
    crosses = E > 0                       # V(0) = 0: the swing reaches θ < 0
    A_low = mp.mpf(1) if crosses else right
    roots = mp.polyroots([B / 4, 0, A_low / 2, -F, -E], maxsteps=200, extraprec=2 * dps)
    real = [mp.re(r) for r in roots if abs(mp.im(r)) < mp.mpf(10) ** (-dps)]
    below = [r for r in real if (r < 0 if crosses else 0 <= r < top - mp.mpf(10) ** (-dps // 2))]
    return E, crosses, A_low, max(below)


def _swing(G: str, C: str, eps: str, theta0: str, j: str, dps: int) -> dict:
    """The swing of half-width θ0 ((θ_max − θ_min)/2 = θ0, the amplitude of θ1 = θ − j, so that the symmetric
    pendulum's T is even in j): θ_max by findroot from j + θ0, and what the quadrature needs (at dps + 10)."""
    Gv, Cv, e, t0, jv = (_mpf(x) for x in (G, C, eps, theta0, j))
    B = Gv * Cv / 6
    F = jv + B * jv**3
    right = 1 + e * Gv
    if jv + t0 <= 0:
        raise ValueError("the swing must reach the side θ > 0")
    top = mp.findroot(lambda x: x - _bottom(x, F, B, right, dps)[3] - 2 * t0, (jv + t0, jv + t0 * mp.mpf("1.1")),
                      solver="secant", tol=mp.mpf(10) ** (-2 * dps))
    E, crosses, A_low, bottom = _bottom(top, F, B, right, dps)
    return {"top": top, "bottom": bottom, "crosses": crosses, "A_low": A_low, "F": F, "B": B, "right": right}


@functools.lru_cache(maxsize=512)
def period_change(G: str, C: str, eps: str, theta0: str, j: str, dps: int) -> mp.mpf:
    """ΔT/T = T/(2π) − 1 of the model above (n = 1) for the swing of half-width θ0 (:func:`_swing`), arguments as
    strings (cache keys)."""
    with mp.workdps(dps + 10):
        sw = _swing(G, C, eps, theta0, j, dps)
        top, bottom, A_low, F, B, right = (sw[k] for k in ("top", "bottom", "A_low", "F", "B", "right"))
        split = mp.mpf(0) if sw["crosses"] else (top + bottom) / 2

        def upper(u):
            return 2 / mp.sqrt(2 * _S(right, F, B, top, top - u * u))

        def lower(u):
            return 2 / mp.sqrt(-2 * _S(A_low, F, B, bottom, bottom + u * u))
        half = mp.quad(upper, [0, mp.sqrt(top - split)]) + mp.quad(lower, [0, mp.sqrt(split - bottom)])
        return +(2 * half / (2 * mp.pi) - 1)


def period_change_odefun(G: str, C: str, eps: str, theta0: str, j: str, dps: int) -> mp.mpf:
    """The same ΔT/T by integrating θ'' = −V'(θ) with mpmath's odefun from θ_max at rest: on the side θ > 0 until
    θ = 0, then on the side θ < 0 until θ' = 0 (θ_min); T is twice that time (time reversal).  A confirmation of
    :func:`period_change` (slower), for a swing that crosses the vertical."""
    with mp.workdps(dps + 10):
        sw = _swing(G, C, eps, theta0, j, dps)
        F, B, right = sw["F"], sw["B"], sw["right"]
        if not sw["crosses"]:
            raise ValueError("a swing that crosses θ = 0 is expected")
        tol = mp.mpf(10) ** (-(dps + 8))
        root_tol = mp.mpf(10) ** (-2 * (dps + 6))

        def field(stiff):
            return lambda _, y: [y[1], -(stiff * y[0] - F + B * y[0] ** 3)]
        sol = mp.odefun(field(right), 0, [sw["top"], mp.mpf(0)], tol=tol)
        t1 = mp.findroot(lambda t: sol(t)[0], mp.acos(-sw["F"] / sw["top"]) if abs(sw["F"]) < sw["top"] else 1,
                         tol=root_tol)
        sol = mp.odefun(field(mp.mpf(1)), t1, [mp.mpf(0), sol(t1)[1]], tol=tol)
        t2 = mp.findroot(lambda t: sol(t)[1], mp.pi, tol=root_tol)
        return +(2 * t2 / (2 * mp.pi) - 1)


def state(eps, dps: int, ratio: str = RATIO) -> dict:
    """G, C, ε_E, θ0 of a point of the order checks (θ0 = √(ε_E/ratio)), as strings."""
    with mp.workdps(dps + 10):
        t0 = mp.sqrt(mp.mpf(eps) / mp.mpf(ratio))
        return {"G": G_VALUE, "C": C_VALUE, "eps": mp.nstr(mp.mpf(eps), dps + 8), "theta0": mp.nstr(t0, dps + 8)}


def relative_change(st: dict, j, dps: int) -> mp.mpf:
    """ΔT/T(j, ε_E) − ΔT/T(0, 0) at the same θ0: the part of (295) (the isochronism (283) of the symmetric
    pendulum at the vertical taken away, to all orders)."""
    with mp.workdps(dps + 10):
        jj = mp.nstr(mp.mpf(j), dps + 8)
        return (period_change(st["G"], st["C"], st["eps"], st["theta0"], jj, dps)
                - period_change(st["G"], st["C"], "0", st["theta0"], "0", dps))


def slope(st: dict, j, dps: int) -> mp.mpf:
    """d(ΔT/T)/dj by the five-point central difference of step h = θ0·10^(−dps/4) (error ~h⁴, rounding
    ~10^(−dps−10)/h)."""
    with mp.workdps(dps + 10):
        h = mp.mpf(st["theta0"]) * mp.mpf(10) ** (-(dps // 4))
        jv = mp.mpf(j)

        def at(k):
            return period_change(st["G"], st["C"], st["eps"], st["theta0"], mp.nstr(jv + k * h, dps + 8), dps)
        return (8 * (at(1) - at(-1)) - (at(2) - at(-2))) / (12 * h)


@functools.lru_cache(maxsize=64)
def j_of_maximum(eps: str, theta0: str, dps: int) -> mp.mpf:
    """The j where the truth's T is largest: findroot (secant) of the truth's dT/dj, from the derived guess
    −θ0 sin α (the guess only starts the iteration)."""
    st = {"G": G_VALUE, "C": C_VALUE, "eps": eps, "theta0": theta0}
    with mp.workdps(dps + 10):
        t0 = mp.mpf(theta0)
        guess = -t0 * mp.sin(mp.atan(2 * mp.mpf(eps) / (mp.pi * mp.mpf(C_VALUE) * t0**2)))
        return mp.findroot(lambda x: slope(st, x, dps), (guess, guess * mp.mpf("1.01")), solver="secant",
                           tol=mp.mpf(10) ** (-(dps - 4)), verify=False)
