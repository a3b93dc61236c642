"""Clamping errors of the exact blade: the tilted equilibrium and the small oscillations about it.

The blade and the pendulum of :mod:`pendsym.nonlinear_blade` (exact large-deflection elastica, rigid
pendulum m, a, R), with two assembly errors:

- the clamp's tangent Ox makes the angle i with the vertical (the vertical OV is at −i from Ox), so that
  in the blade's axes gravity is g(cos i, −sin i);
- the centre of gravity G is off the tangent AT at the blade's end by the angle i': x_G = α + a cos(θ + i'),
  y_G = β + a sin(θ + i').

Everything is written in the blade's axes, where the clamp stays φ(0) = 0, so the elastica
(:func:`pendsym.nonlinear_blade.end_state`) is unchanged; only the pendulum's equations change:

    ẍ_G = g(cos i − X),    ÿ_G = −g(sin i + Y),    R²θ̈ = g(−N + a(Y cos(θ + i') − X sin(θ + i'))).

:func:`equilibrium` solves the statics exactly (X = cos i, Y = −sin i, and the clamping couple c0 that
makes the blade's end couple N equal the pendulum's moment), by mpmath's ``findroot`` from a start on the
straight blade's branch found by multiple shooting (a blade of large u = ∫ M^{−1/2} ds has other equilibria,
looped elastic lines, that Newton from c0 = 0 can reach: it did at u ≈ 13; a looped end is refused, and so is a
principal eigenvalue more than 1 % off the untilted n²).  Tested from u = 0.5 to u = 20.
:func:`tilted` linearises the exact equations about that equilibrium in the loads
(X, Y, c0) — the positions follow by the elastica's variational equations — and solves the 3 × 3
generalised eigenproblem B q = Ω A q (mpmath ``eig``); the principal mode is the eigenvalue nearest the
untilted principal n² of :mod:`pendsym.suspension`.  Its period 2π/√Ω is the limit θ0 → 0 of the period
of the tilted blade: no expansion in i, i'.  At i = i' = 0 it is the linear period of the straight blade
(the first row of A then vanishes: the axial mode is infinitely stiff).  Quantities in SI units, m = 1.
"""
from __future__ import annotations

from dataclasses import dataclass

import mpmath as mp
import sympy as sp

from . import blade as linear_blade
from . import cache, keys, nonlinear_blade, suspension

VERSION = "2"        # bump when the meaning of a cached value changes


@dataclass(frozen=True)
class Equilibrium:
    """The exact tilted equilibrium: the loads (X, Y, c0), the blade's end (α, β, θ, N) and the 4×3
    Jacobian ∂(α, β, θ, N)/∂(X, Y, c0) there."""

    X: mp.mpf
    Y: mp.mpf
    c0: mp.mpf
    alpha: mp.mpf
    beta: mp.mpf
    theta: mp.mpf
    N: mp.mpf
    jacobian: tuple


def _moment_mismatch(end, X, Y, a, i_prime):
    """N − a(Y cos(θ + i') − X sin(θ + i')): the moment about G that the statics must cancel."""
    th = end.theta + i_prime
    return end.N - a * (Y * mp.cos(th) - X * mp.sin(th))


def equilibrium(blade: linear_blade.Blade, a, g, i, i_prime, dps: int = 30) -> Equilibrium:
    """The equilibrium with the clamp tilted by i and G off the tangent by i' (n°31–32), exactly.

    The pendulum at rest: X = cos i, Y = −sin i (the force on G balances its weight), and c0 solves
    N(c0) = a(Y cos(θ(c0) + i') − X sin(θ(c0) + i')) (the moment about G).  A precision ladder: Newton from
    the multiple shooting's c0 (:func:`_multiple_shooting`: on the straight blade's branch, where the end angle
    depends on c0 through e^u) at ``nonlinear_blade.LADDER_DPS`` digits with the elastica's variation in c0 as
    derivative, then the chord method at ``dps`` digits with that derivative (the elastica without its
    variations), and the end's state with its Jacobian at the root found; the moment residual is tested there,
    at ``dps`` digits, and the end angle must be on the straight blade's branch (:func:`check_branch`; else
    NoConvergence).
    """
    low = min(dps, nonlinear_blade.LADDER_DPS)
    c0, slope = _newton(blade, a, i, i_prime, low, _multiple_shooting(blade, a, i, i_prime, low))
    if dps > low:
        c0, slope = _newton(blade, a, i, i_prime, dps, c0, slope)
    wdps = nonlinear_blade.working_dps(blade, dps)
    with mp.workdps(wdps):
        a, i, i_prime = (suspension.number(x) for x in (a, i, i_prime))
        X, Y = mp.cos(i), -mp.sin(i)
        end = nonlinear_blade.end_state(blade, X, Y, c0, wdps, variations=True)
        mismatch = _moment_mismatch(end, X, Y, a, i_prime)
        check_branch(end.theta, i, i_prime)
        if not abs(mismatch) < mp.mpf(10) ** (-(dps + 3)) * (1 + abs(a)):
            raise nonlinear_blade.NoConvergence(f"tilted equilibrium: moment residual {mp.nstr(mismatch, 5)}")
        return Equilibrium(X, Y, c0, end.alpha, end.beta, end.theta, end.N, end.jacobian)


BRANCH = 1            # rad: |φ| along the blade above this is another equilibrium (a looped elastica)


def check_branch(theta, i, i_prime):
    """Refuse an equilibrium off the branch of the straight blade: the tilted blade's end stays within about
    |i| + |i'| of the clamp's tangent, a looped elastica (θ shifted by 2πk) is another equilibrium."""
    if not abs(theta) < BRANCH:
        raise nonlinear_blade.NoConvergence(
            f"tilted equilibrium: θ = {mp.nstr(theta, 8)} at i = {mp.nstr(i, 5)}, i' = {mp.nstr(i_prime, 5)} is not "
            "the branch of the straight blade (a looped elastica); the tilt is too large for this solver")


def _shooting_segments(blade: linear_blade.Blade, nepers=1):
    """(s_a, s_b, M) covering the blade, split at the jumps of M and into pieces of at most ``nepers`` of growth
    ∫ M^{−1/2} ds: across one the elastica's variations grow by at most about e^nepers."""
    out = []
    for a, b, expr in linear_blade.segments(blade):
        Mf = sp.lambdify(blade.var, expr, modules="mpmath")
        a, b = mp.mpf(a), mp.mpf(b)
        k = 1 + int(mp.quad(lambda x: 1 / mp.sqrt(abs(Mf(x))), [a, b]) / nepers)
        out += [(a + (b - a) * j / k, a + (b - a) * (j + 1) / k, Mf) for j in range(k)]
    return out


def _segment(X, Y, seg, phi, mu, tol):
    """The elastica φ' = μ/M, μ' = X sin φ − Y cos φ across one segment from (φ, μ), with its 2×2 variation
    in (φ, μ): ((φ, μ) at the end, ∂(φ, μ)_end/∂(φ, μ)_start).  Written with C = cos φ, S = sin φ carried
    (C' = −Sφ', S' = Cφ') as :func:`pendsym.nonlinear_blade.end_state` does: no sine in the Taylor solver."""
    a, b, Mf = seg

    def rhs(s, u):
        inv = 1 / Mf(s)
        rate, cs, sn = u[1] * inv, u[2], u[3]
        k = X * cs + Y * sn
        return [rate, X * sn - Y * cs, -sn * rate, cs * rate, u[5] * inv, k * u[4], u[7] * inv, k * u[6]]
    start = [phi, mu, mp.cos(phi), mp.sin(phi), mp.mpf(1), mp.mpf(0), mp.mpf(0), mp.mpf(1)]
    end = mp.odefun(rhs, a, start, tol=tol)(b)
    return (end[0], end[1]), ((end[4], end[6]), (end[5], end[7]))


def _multiple_shooting(blade: linear_blade.Blade, a, i, i_prime, dps: int):
    """A start for :func:`_newton` on the branch of the straight blade: c0 of the equilibrium by multiple
    shooting of the elastica in (φ, μ = Mφ') from the straight blade (all unknowns 0).

    Shooting from the clamp alone, θ(λ) depends on c0 through e^u (u = ∫ M^{−1/2} ds): Newton's basin in c0
    shrinks like e^−u, and at u ≈ 13 Newton from c0 = 0 ran to a looped elastica (θ ≈ −2π − 0.03).  Here
    the blade is cut into segments of at most one neper (:func:`_shooting_segments`); the unknowns are c0 and
    (φ, μ) at each cut, the equations the continuity at the cuts and the moment about G at the end.  Each
    segment is nearly linear for small tilts, so Newton from 0 converges to the straight blade's branch.  The
    root is a start (at ``dps`` digits): :func:`_newton` refines it by single shooting, whose basin it is in."""
    wdps = dps + 10
    with mp.workdps(wdps):
        a, i, i_prime = (suspension.number(x) for x in (a, i, i_prime))
        X, Y = mp.cos(i), -mp.sin(i)
        segs = _shooting_segments(blade)
        K = len(segs)
        if K == 1:                           # less than a neper: the single shooting from c0 = 0 is as good
            return mp.mpf(0)
        tol = mp.mpf(10) ** (-wdps)
        z = [mp.mpf(0)] * (2 * K - 1)        # c0, then (φ_k, μ_k) at the cuts k = 1 … K − 1
        scale = [mp.sqrt(abs(seg[2]((seg[0] + seg[1]) / 2))) for seg in segs]      # μ ~ √M φ
        for _ in range(30):
            F, J = mp.matrix(2 * K - 1, 1), mp.zeros(2 * K - 1, 2 * K - 1)
            for k, seg in enumerate(segs):
                phi, mu = (mp.mpf(0), z[0]) if k == 0 else (z[2 * k - 1], z[2 * k])
                (pe, me), var = _segment(X, Y, seg, phi, mu, tol)
                cols = (None, 0) if k == 0 else (2 * k - 1, 2 * k)
                if k < K - 1:                 # continuity with the next cut's unknowns
                    rows = (2 * k, 2 * k + 1)
                    F[rows[0]], F[rows[1]] = pe - z[2 * k + 1], (me - z[2 * k + 2]) / scale[k]
                    for r in range(2):
                        for c, col in enumerate(cols):
                            if col is not None:
                                J[rows[r], col] += var[r][c] / (scale[k] if r else 1)
                    J[rows[0], 2 * k + 1] -= 1
                    J[rows[1], 2 * k + 2] -= 1 / scale[k]
                else:                          # the moment about G: N − a(Y cos ϑ − X sin ϑ) = 0, ϑ = θ + i'
                    th = pe + i_prime
                    F[2 * K - 2] = (me - a * (Y * mp.cos(th) - X * mp.sin(th))) / a
                    dth = (Y * mp.sin(th) + X * mp.cos(th))
                    for c, col in enumerate(cols):
                        if col is not None:
                            J[2 * K - 2, col] += (var[1][c] + a * dth * var[0][c]) / a
            step = mp.lu_solve(J, -F)
            z = [z[r] + step[r] for r in range(2 * K - 1)]
            if any(abs(z[2 * k - 1]) > BRANCH for k in range(1, K)):
                raise nonlinear_blade.NoConvergence("tilted equilibrium: the multiple shooting left the straight "
                                                    "blade's branch (|φ| > 1 rad at a cut)")
            size = max([abs(step[0]) / scale[0]] + [abs(step[r]) for r in range(1, 2 * K - 1)])
            if size < mp.mpf(10) ** (-(dps + 2)):
                return z[0]
        raise nonlinear_blade.NoConvergence(f"tilted equilibrium: the multiple shooting did not converge ({size})")


def _newton(blade: linear_blade.Blade, a, i, i_prime, dps: int, c0, slope=None):
    """The clamping couple c0 of the equilibrium at ``dps`` digits from c0 and the derivative of the moment
    mismatch there: Newton (mpmath's findroot) without ``slope``; with it, the chord method, stopped when the
    next step is estimated below 10^−(dps + 6) from the contraction of the last two."""
    wdps = nonlinear_blade.working_dps(blade, dps)
    with mp.workdps(wdps):
        a, i, i_prime = (suspension.number(x) for x in (a, i, i_prime))
        X, Y = mp.cos(i), -mp.sin(i)
        c0 = mp.mpf(c0)
        tol = mp.mpf(10) ** (-(dps + 6))
        if slope is not None:
            last = None
            for _ in range(12):
                end = nonlinear_blade.end_state(blade, X, Y, c0, wdps, variations=False)
                step = -_moment_mismatch(end, X, Y, a, i_prime) / slope
                c0 += step
                if step == 0 or (last is not None and abs(step) * abs(step / last) < tol):
                    return c0, slope
                last = step
            raise nonlinear_blade.NoConvergence(f"tilted equilibrium: the chord method did not converge ({step})")
        memo = {}

        def state(c):
            if c not in memo:
                memo.clear()
                memo[c] = nonlinear_blade.end_state(blade, X, Y, c, wdps, variations=True)
            return memo[c]

        def mismatch(c):
            return _moment_mismatch(state(c), X, Y, a, i_prime)

        def derivative(c):
            end = state(c)
            th = end.theta + i_prime
            return end.jacobian[3][2] + a * (Y * mp.sin(th) + X * mp.cos(th)) * end.jacobian[2][2]

        c0 = mp.findroot(mismatch, c0, df=derivative, solver="newton", tol=tol, verify=False, maxsteps=50)
        return c0, derivative(c0)


def linearised_matrices(eq: Equilibrium, a, R, g, i_prime):
    """(A, B) of the linearisation about ``eq``: loads δL = (δX, δY, δc0) e^{iωt}, B δL = ω² A δL, from

        δα̈ − a sin ϑ δθ̈ + g δX = 0,   δβ̈ + a cos ϑ δθ̈ + g δY = 0,
        R² δθ̈ + g(δN − a(cos ϑ δY − sin ϑ δX) + a(Y sin ϑ + X cos ϑ) δθ) = 0,   ϑ = θ + i',

    with δ(α, β, θ, N) = Jacobian · δL."""
    Jal, Jbe, Jth, JN = (mp.matrix([list(row)]) for row in eq.jacobian)
    th = eq.theta + i_prime
    sn, cs = mp.sin(th), mp.cos(th)
    rows_A = (Jal - a * sn * Jth, Jbe + a * cs * Jth, R * R * Jth)
    e1, e2 = mp.matrix([[1, 0, 0]]), mp.matrix([[0, 1, 0]])
    rows_B = (g * e1, g * e2, g * (JN - a * (cs * e2 - sn * e1) + a * (eq.Y * sn + eq.X * cs) * Jth))
    A = mp.matrix([[rows_A[r][0, c] for c in range(3)] for r in range(3)])
    B = mp.matrix([[rows_B[r][0, c] for c in range(3)] for r in range(3)])
    return A, B


@dataclass(frozen=True)
class Tilted:
    """The exact tilted equilibrium (θ, β, the loads Y and c0, the couple N) and the period of the
    principal small oscillation about it."""

    theta: mp.mpf
    beta: mp.mpf
    Y: mp.mpf
    c0: mp.mpf
    N: mp.mpf
    period: mp.mpf


def _solve(blade: linear_blade.Blade, a, R, g, i, i_prime, dps: int) -> tuple:
    sus = suspension.solve(blade, dps)
    wdps = nonlinear_blade.working_dps(blade, dps)
    eq = equilibrium(blade, a, g, i, i_prime, dps)
    with mp.workdps(wdps):
        a, R, g, i_prime = (suspension.number(x) for x in (a, R, g, i_prime))
        n2_lin = suspension.modes(sus, a, R, g)[0].n2
        A, B = linearised_matrices(eq, a, R, g, i_prime)
        mu, _ = mp.eig(mp.inverse(B) * A)                  # μ = 1/Ω (μ = 0: the axial mode at i = 0)
        omegas = [1 / m for m in mu if abs(m) > mp.mpf(10) ** (-(wdps // 2))]
        omega2 = min(omegas, key=lambda o: abs(o - n2_lin))
        if abs(mp.im(omega2)) > mp.mpf(10) ** (-(dps + 3)) * abs(omega2):
            raise nonlinear_blade.NoConvergence(f"complex principal eigenvalue {omega2}")
        if abs(mp.re(omega2) / n2_lin - 1) > mp.mpf("0.01"):
            raise nonlinear_blade.NoConvergence(f"no principal eigenvalue within 1 % of the untilted "
                                                f"{mp.nstr(n2_lin, 8)}: {mp.nstr(omega2, 8)}")
        period = 2 * mp.pi / mp.sqrt(mp.re(omega2))
        return (eq.theta, eq.beta, eq.Y, eq.c0, eq.N, period)


def tilted(blade: linear_blade.Blade, a, R, g, i, i_prime, dps: int = 30) -> Tilted:
    """The exact tilted equilibrium and the period of the principal small oscillation about it (see the
    module), cached by its inputs in :mod:`pendsym.cache` (pass i, i' as strings for a stable key)."""
    key = keys.digest(("nonlinear_tilt.tilted", VERSION, keys.FORMAT, *keys.versions(),
                       keys.file_hash(keys.module_file(__name__)),
                       keys.file_hash(keys.module_file(nonlinear_blade.__name__)),
                       sp.srepr(blade.length), sp.srepr(blade.M), str(a), str(R), str(g), str(i), str(i_prime),
                       str(dps)))
    return Tilted(*cache.memo(key, lambda: _solve(blade, a, R, g, i, i_prime, dps)))
