"""Small oscillations of a rigid pendulum on an elastic blade that has mass: its inertia and its weight.

The independent truth for the first-order effect of the blade's own mass.  The blade (length λ, stiffness
ratio M(s) = EI/(mg) as in :mod:`pendsym.blade`, clamped vertically at s = 0) carries at s = λ a rigid
pendulum (mass m, AG = a along the tangent at A, radius of gyration R about G).  The blade now has a linear
density μ(s); here ``mu`` is μ(s)/m (per unit length).  Linearised (small slope φ = y', x = s), with
mg(X(s), Y(s)) the force that the part below s exerts on the part above, Mφ' the bending moment over mg:

    y' = φ,   (Mφ')' = X(s) φ − Y(s),
    X(s) = 1 + [weight] ∫_s^λ μ/m ds'                (the tension grows by the weight of the blade below s)
    Y(s)' = [inertia] (μ/m) ÿ/g = −[inertia] (ω²/g)(μ/m) y   (the horizontal inertia of the element at s)

with y(0) = φ(0) = 0 and, at A, (β, θ, N, Y) = (y, φ, Mφ', Y)(λ).  The pendulum obeys the theorem of the
centre of gravity and of the angular momentum about G, linearised,

    ω²(β + aθ) − gY = 0,     −ω²R²θ + g(N − aY + aθ) = 0

(X = 1 at A to the first order).  The blade's state is linear in the two free values at the clamp, the couple
c0 = (Mφ')(0) and the shear Y(0): two initial-value integrations (mpmath's Taylor solver ``odefun``, segment
by segment across the jumps of M and μ) give the 2×2 matrix D(ω²) of the two pendulum equations, and the
principal mode is the root of det D(ω²) = 0 next to the massless principal n² (:mod:`pendsym.suspension`),
found by mpmath's ``findroot`` (secant); with ``slowest`` the root next to the smaller massless n² instead
(the slow mode of a pendulum near its critical distance).  g < 0 with M < 0 (an inverted blade: every force
in units of mg changes sign with g) needs no change in the equations.  With the inertia the blade depends on
ω² and is integrated again at each iterate; with the weight only it is integrated once.  The axial inertia
(ẍ, of the second order) and the rotary inertia of the sections are not modelled.  Units: SI with m = 1.
"""
from __future__ import annotations

import functools
from dataclasses import dataclass

import mpmath as mp
import sympy as sp

from . import blade as linear_blade
from . import suspension

LADDER_DPS = 15      # digits of the first root of det D (see principal_n2)


@dataclass(frozen=True)
class MassiveBlade:
    """A blade with mass: its stiffness (a :class:`pendsym.blade.Blade`) and its density μ(s)/m, a number or a
    SymPy expression in the blade's variable (jumps as Piecewise, at the same abscissae as M's or others).
    ``inertia`` and ``weight`` say which effects of the mass are kept."""

    blade: linear_blade.Blade
    mu: sp.Expr
    inertia: bool = True
    weight: bool = True

    def __post_init__(self):
        object.__setattr__(self, "mu", sp.sympify(self.mu))
        extra = self.mu.free_symbols - {self.blade.var}
        if extra:
            raise ValueError(f"μ depends on {sorted(map(str, extra))}, not only on {self.blade.var}")


def _pieces(mb: MassiveBlade):
    """(a, b, M, μ as mpmath functions) for the pieces where both M and μ are smooth."""
    var = mb.blade.var
    pts = set(linear_blade.breakpoints(mb.blade))
    pts |= set(linear_blade.breakpoints(linear_blade.Blade(mb.blade.length, mb.mu, var)))
    pts = sorted(pts, key=float)
    out = []
    for lo, hi in zip(pts, pts[1:]):
        mid = (lo + hi) / 2
        M_e = linear_blade._branch(mb.blade.M, var, mid)
        mu_e = linear_blade._branch(mb.mu, var, mid)
        out.append((lo, hi, sp.lambdify(var, M_e, modules="mpmath"), sp.lambdify(var, mu_e, modules="mpmath")))
    return tuple(out)


def mass_ratio(mb: MassiveBlade) -> mp.mpf:
    """m'/m = ∫_0^λ μ/m ds (mpmath quad on each smooth piece)."""
    return sum((mp.quad(mu, [mp.mpf(lo), mp.mpf(hi)]) for lo, hi, _, mu in _pieces(mb)), mp.mpf(0))


def working_dps(mb: MassiveBlade, dps: int) -> int:
    """dps, guard digits and the growth ∫|M|^{−1/2} ds of the solutions (as :func:`pendsym.blade.solve`)."""
    return dps + 12 + int(linear_blade.growth(mb.blade) / mp.log(10))


def end_columns(mb: MassiveBlade, omega2, g, wdps: int) -> tuple:
    """(β, θ, N, Y) at A for the clamp values (c0, Y(0)) = (1, 0) and (0, 1), at the frequency ω²."""
    with mp.workdps(wdps):
        omega2, g = mp.mpf(omega2), mp.mpf(g)
        k = omega2 / g if mb.inertia else mp.mpf(0)
        tol = mp.mpf(10) ** (-wdps)
        # state: W = ∫_s^λ μ/m (with the weight only: X = 1 without it), then (y, φ, Mφ', Y) for each of the two
        # fundamental solutions
        w = 1 if mb.weight else 0
        state = ([mass_ratio(mb)] if mb.weight else []) + [mp.mpf(x) for x in (0, 0, 1, 0, 0, 0, 0, 1)]
        for lo, hi, Mf, muf in _pieces(mb):
            def rhs(s, u, Mf=Mf, muf=muf):
                m, rho = Mf(s), muf(s)
                X = 1 + u[0] if mb.weight else 1
                out = [-rho] if mb.weight else []
                for j in (w, w + 4):
                    y, phi, c, Y = u[j:j + 4]
                    out += [phi, c / m, X * phi - Y, -k * rho * y]
                return out
            sol = mp.odefun(rhs, mp.mpf(lo), state, tol=tol)
            state = sol(mp.mpf(hi))
        return tuple(tuple(state[j:j + 4]) for j in (w, w + 4))


@functools.lru_cache(maxsize=64)
def _static_columns(mb: MassiveBlade, g, wdps: int) -> tuple:
    """:func:`end_columns` when they do not depend on ω² (no inertia, or no mass): computed once."""
    return end_columns(mb, 0, g, wdps)


def determinant(mb: MassiveBlade, a, R, g, omega2, wdps: int):
    """det D(ω²): the two pendulum equations on the two fundamental solutions of the blade (integrated once
    for all ω² when the blade's inertia is not modelled or it has no mass)."""
    with mp.workdps(wdps):
        a, R, g, omega2 = (mp.mpf(x) for x in (a, R, g, omega2))
        static = not mb.inertia or mb.mu == 0
        rows = []
        for beta, theta, N, Y in (_static_columns(mb, g, wdps) if static else end_columns(mb, omega2, g, wdps)):
            rows.append((omega2 * (beta + a * theta) - g * Y, -omega2 * R * R * theta + g * (N - a * Y + a * theta)))
        (p, q), (r, t) = rows
        return p * t - q * r


def _root(mb: MassiveBlade, a, R, g, start, dps: int, scale, spread, tested: bool = True):
    """The root of det D next to ``start`` at ``dps`` digits: the secant method (mpmath's findroot) from
    (start, start·(1 + spread)), stopped when a step falls below 10^−(dps + 6)/2 relative (the error of the
    next iterate is then of the order of that step times the error of the last: converged); with ``tested``,
    the determinant there, over ``scale``, must be below 10^−(dps + 3) (one more integration of the blade)."""
    wdps = working_dps(mb, dps)
    with mp.workdps(wdps):
        a, R, g, start = (mp.mpf(x) for x in (a, R, g, start))

        def det(x):
            return determinant(mb, a, R, g, x, wdps) / scale
        pair = (start, start * (1 + spread))
        root = mp.findroot(det, pair, solver="secant", tol=mp.mpf(10) ** (-(dps + 6) / 2), verify=False,
                           maxsteps=60)
        if tested and not abs(det(root)) < mp.mpf(10) ** (-(dps + 3)):
            raise ValueError(f"massive blade: det D = {mp.nstr(det(root), 5)} at the root found")
        return +root


@functools.lru_cache(maxsize=64)
def principal_n2(mb: MassiveBlade, a, R, g, dps: int = 30, slowest: bool = False) -> mp.mpf:
    """n² of the principal oscillation of the pendulum on the blade with mass (see the module).

    a, R, g are strings or exact numbers (the cache key).  The root of det D is sought next to the massless
    principal n² (pendsym.suspension.modes), which is the limit μ → 0; with ``slowest``, next to the smaller
    massless n² of the two modes.  A precision ladder: the root at LADDER_DPS digits from the massless n², then
    at ``dps`` digits from that one (:func:`_root`)."""
    sus = suspension.solve(mb.blade, dps)
    with mp.workdps(working_dps(mb, dps)):
        a_, R_, g_ = (suspension.number(x) for x in (a, R, g))
        pair = suspension.modes(sus, a_, R_, g_)
        n2_0 = min(md.n2 for md in pair) if slowest else pair[0].n2
        low = min(dps, LADDER_DPS)
        scale = abs(determinant(mb, a_, R_, g_, n2_0, working_dps(mb, low))) + 1   # det is O(1) in units of g, n²
        # the first rung is only a start for the second, whose root is tested
        root = _root(mb, a_, R_, g_, n2_0, low, scale, mp.mpf(10) ** -6, tested=dps <= low)
        return _root(mb, a_, R_, g_, root, dps, scale, mp.mpf(10) ** -low) if dps > low else root


def relative_period_change(mb: MassiveBlade, a, R, g, dps: int = 30) -> mp.mpf:
    """T/T0 − 1 = √(n0²/n²) − 1, T0 the period of the same pendulum on the massless blade."""
    massless = MassiveBlade(mb.blade, 0, mb.inertia, mb.weight)
    n2 = principal_n2(mb, a, R, g, dps)
    n2_0 = principal_n2(massless, a, R, g, dps)
    with mp.workdps(dps + 10):
        return mp.sqrt(n2_0 / n2) - 1
