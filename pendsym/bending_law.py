"""A bending moment that is not linear in the curvature: the exact elastica under the law M(c + a2c³).

The blade of :mod:`pendsym.nonlinear_blade` (exact large deflection, clamped vertically at s = 0, end loads
mg(X, Y) at s = λ) with the bending moment over mg

    μ = M(s)·(c + a2c³),    c = φ' (the curvature),

instead of Mφ'; a2 (a length squared, a number) is the law's parameter, a2 = 0 the linear law.  The cubic is
the law Mc(1 + a_q|c|^q) at q = 2, the lowest degree at which it is odd in c and analytic, so the orbit stays
analytic in time and the collocation of :mod:`pendsym.nonlinear_blade` converges geometrically.
For a2 ≥ 0, μ is increasing in c and the law invertible; a2 < 0 is accepted while 1 + 3a2c² > 0.

The curvature is the state (no cubic to invert inside the integration): from μ' = X sin φ − Y cos φ,

    φ' = c,    c' = (X sin φ − Y cos φ − M'(c + a2c³)) / D,    D = M(1 + 3a2c²) = ∂μ/∂c,
    x' = cos φ,    y' = sin φ,

with cos φ and sin φ carried in the state (C' = −cS, S' = cC), as in :func:`pendsym.nonlinear_blade.end_state`
(no sine at odefun's raised precision),

and the variations in p ∈ (X, Y, c0) (c0 = μ(0), the clamping couple):

    δφ' = δc,    δc' = ((X cos φ + Y sin φ)δφ + [p = X] sin φ − [p = Y] cos φ
                        − M'(1 + 3a2c²)δc − 6Ma2c·c'·δc) / D,
    δx' = −sin φ δφ,    δy' = cos φ δφ.

The moment μ is continuous where M jumps: at each end of a smooth piece the state passes through
(μ, δμ = Dδc), the curvature found from μ by mpmath's ``findroot`` (c(0) from c0 at the clamp, N = μ(λ) at the
end).  :class:`CubicLaw` is the law as a parameter of :func:`pendsym.nonlinear_blade.orbit` and ``track``.
"""
from __future__ import annotations

import functools
from dataclasses import dataclass

import mpmath as mp
import sympy as sp

from . import blade as linear_blade
from .nonlinear_blade import EndState


@functools.lru_cache(maxsize=16)
def _pieces(blade: linear_blade.Blade):
    """(a, b, M, M') on the smooth pieces of M: mpmath functions of s, or (M, None) on a piece where M is
    constant (M' = 0: the integration then skips two calls and the terms in M')."""
    def piece(a, b, M):
        if blade.var not in M.free_symbols:
            return a, b, M, None
        return (a, b, sp.lambdify(blade.var, M, modules="mpmath"),
                sp.lambdify(blade.var, sp.diff(M, blade.var), modules="mpmath"))
    return tuple(piece(*seg) for seg in linear_blade.segments(blade))


def curvature(mu, M, a2):
    """c with M(c + a2c³) = μ (findroot from the linear law's μ/M)."""
    t = mu / M
    if a2 == 0:
        return t
    c = mp.findroot(lambda c: c + a2 * c ** 3 - t, t)
    if 1 + 3 * a2 * c * c <= 0:
        raise ValueError(f"the law M(c + a2c³) is not invertible at μ = {mp.nstr(mu, 8)} (a2 = {mp.nstr(a2, 8)})")
    return c


@dataclass(frozen=True)
class CubicLaw:
    """The bending moment M(c + a2c³) (over mg), a2 a number (a length squared)."""

    a2: sp.Expr

    def __post_init__(self):
        a2 = sp.nsimplify(sp.sympify(self.a2))
        if not a2.is_Rational:
            raise ValueError(f"a2 must be a number, got {self.a2}")
        object.__setattr__(self, "a2", a2)

    def key(self) -> str:
        """What identifies the law in a cache key."""
        return "cubic " + sp.srepr(self.a2)

    def end_state(self, blade: linear_blade.Blade, X, Y, c0, wdps: int, variations: bool = True) -> EndState:
        """The exact elastica under this law from the clamp (φ = 0, μ = c0) to the end: (α, β, θ, N = μ(λ))
        and, with ``variations``, ∂(α, β, θ, N)/∂(X, Y, c0) (the same record as the linear law's
        :func:`pendsym.nonlinear_blade.end_state`)."""
        with mp.workdps(wdps):
            X, Y, c0 = mp.mpf(X), mp.mpf(Y), mp.mpf(c0)
            A = mp.mpf(self.a2.p) / self.a2.q
            A3, A6 = 3 * A, 6 * A
            tol = mp.mpf(10) ** (-wdps)
            phi, mu, x, y, cos_phi, sin_phi = mp.mpf(0), c0, mp.mpf(0), mp.mpf(0), mp.mpf(1), mp.mpf(0)
            # per parameter (X, Y, c0): (δφ, δμ, δx, δy) at a piece's ends (μ and δμ are continuous)
            dvar = [[mp.mpf(0)] * 4 for _ in range(3)]
            dvar[2][1] = mp.mpf(1)
            for a, b, Mf, dMf in _pieces(blade):
                a, b = mp.mpf(a), mp.mpf(b)
                Mc = None if dMf is not None else mp.mpf(sp.N(Mf, wdps + 5))
                ref = Mf(a) if Mc is None else Mc
                # the state holds κ = ref·c (ref = M at the piece's start), of the size of the linear law's μ
                # (c itself is 1/M times larger): odefun's Taylor steps are then as long as the linear law's while
                # a2c² is small (near 1 + 3a2c² = 0 in the complex plane they shorten: a property of the law)
                kappa = ref * curvature(mu, ref, A)
                state = [phi, kappa, x, y, cos_phi, sin_phi]
                if variations:
                    # δκ = ref·δμ/D, D = ∂μ/∂c = ref(1 + 3a2c²)
                    stiff = 1 + 3 * A * (kappa / ref) ** 2
                    state += [e for d in dvar for e in (d[0], d[1] / stiff, d[2], d[3])]

                def rhs(s, u, Mf=Mf, dMf=dMf, Mc=Mc, ref=ref, inv=1 / ref):
                    # κ' = ref·c' and δκ' = ref·δc' of the module's equations; on a piece where M is constant
                    # (ref = M) the factors ref/M drop out
                    cs, sn = u[4], u[5]
                    c = u[1] * inv
                    c2 = c * c
                    stiff = 1 + A3 * c2
                    load = X * sn - Y * cs
                    if Mc is None:
                        M, dM = Mf(s), dMf(s)
                        per = ref / (M * stiff)                     # ref/D
                        rate = (load - dM * c * (1 + A * c2)) * per
                        damp = (6 * M * A * c * rate * inv + dM * stiff) * per * inv
                    else:
                        per = 1 / stiff
                        rate = load * per
                        damp = A6 * c * rate * per * inv
                    out = [c, rate, cs, sn, -sn * c, cs * c]
                    if variations:
                        k = X * cs + Y * sn
                        for d, force in enumerate((sn, -cs, 0)):
                            dphi, dkappa = u[6 + 4 * d], u[7 + 4 * d]
                            out += [dkappa * inv, (k * dphi + force) * per - damp * dkappa, -sn * dphi, cs * dphi]
                    return out
                end = mp.odefun(rhs, a, state, tol=tol)(b)
                M = Mf(b) if Mc is None else Mc
                phi, kappa, x, y, cos_phi, sin_phi = end[:6]
                c = kappa / ref
                mu = M * c * (1 + A * c * c)
                if variations:
                    # δμ = D·δc = M(1 + 3a2c²)·δκ/ref
                    scale = M * (1 + 3 * A * c * c) / ref
                    dvar = [[end[6 + 4 * d], scale * end[7 + 4 * d], end[8 + 4 * d], end[9 + 4 * d]]
                            for d in range(3)]
            jac = None
            if variations:
                # rows (α, β, θ, N) = (x, y, φ, μ); columns X, Y, c0
                jac = tuple(tuple(dvar[d][r] for d in range(3)) for r in (2, 3, 0, 1))
            return EndState(x, y, phi, mu, jac)
