"""Small oscillations of a rigid pendulum on an elastic blade, computed without v and w.

This is the independent truth for the small-oscillation theory of an elastic suspension.  It starts again from
the governing equations (2)–(6) of n°1, linearised (θ, φ, β, Y of the first
order, α = λ, X = 1, x = s):

    M φ' = N + (λ − s) Y − (β − y),    y' = φ,    y(0) = φ(0) = 0,      (2), (3)

and solves that boundary-value problem *directly* for a prescribed end
position (β = y(λ), θ = φ(λ)): the deflection is linear in the two unknown end
loads c = N − β and Y, so two initial-value integrations (c = 1, Y = 0) and
(c = 0, Y = 1) by mpmath's Taylor solver ``odefun``, segment by segment across
the jumps of M, and a 2×2 linear solve give the end loads (Y, N) as a linear
function of (β, θ): the 2×2 *stiffness* of the suspension.  The theory's functions
v, w and their two-point conditions (10) are never used.

The rigid pendulum (mass m, centre of gravity G with AG = a, radius of
gyration R about G) then obeys, by the theorem of the centre of gravity and
the theorem of the angular momentum about A (n°1, (5)–(6) linearised),

    m (β'' + a θ'') = −m g Y,
    m [a (β'' + a θ'') + R² θ''] = −m g (N + a θ),

i.e. the generalised eigenproblem  K q = n² 𝕄 q  for q = (β, θ) with the
symmetric mass matrix 𝕄 = m [[1, a], [a, a² + R²]] and K = m g [[∂Y/∂β, ∂Y/∂θ],
[∂N/∂β, ∂N/∂θ + a]], solved by mpmath ``eig``.  A mode's node on the rod
(the point that does not move, y = β + (a + z)θ = 0) gives its focus z.

Static equilibrium under a force Q perpendicular to the rod at B (AB = b),
n°18: Y = Q/(mg), N = Qb/(mg) − aθ, solved for (β, θ) with the stiffness.
"""
from __future__ import annotations

import functools
from dataclasses import dataclass, field

import mpmath as mp
import sympy as sp

from . import blade as linear_blade


def number(x) -> mp.mpf:
    """A SymPy number as an mpf at the working precision (a Rational exactly rounded once)."""
    x = sp.nsimplify(x) if not isinstance(x, sp.Basic) else x
    if isinstance(x, sp.Rational):
        return mp.mpf(int(x.p)) / int(x.q)
    return mp.mpf(str(sp.N(x, mp.mp.dps + 10)))


@dataclass(frozen=True)
class Suspension:
    """The directly solved blade: end-load stiffness and the deflection for any (β, θ).

    ``pieces`` holds (a, b, odefun solution of [y_c, φ_c, y_Y, φ_Y], M on the piece).
    ``stiffness`` is the 2×2 matrix S with (Y, N) = S·(β, θ).
    """

    blade: linear_blade.Blade
    dps: int
    wdps: int
    pieces: tuple
    stiffness: mp.matrix
    _ends: tuple            # (c, Y) per unit β and per unit θ
    # the four fundamental solutions already interpolated at s (quadratures reuse their nodes)
    _memo: dict = field(default_factory=dict, compare=False, hash=False, repr=False)

    def loads(self, beta, theta) -> tuple:
        """(c, Y, N) for the end position (β, θ)."""
        with mp.workdps(self.wdps):
            (cb, Yb), (ct, Yt) = self._ends
            beta, theta = mp.mpf(beta), mp.mpf(theta)
            c = cb * beta + ct * theta
            Y = Yb * beta + Yt * theta
            return c, Y, c + beta

    def _piece(self, s):
        for piece in self.pieces:
            if s <= piece[1]:
                return piece
        return self.pieces[-1]

    def deflection(self, s, beta, theta) -> tuple:
        """(y, φ, φ') at s for the end position (β, θ) (φ' = dφ/ds from (2))."""
        with mp.workdps(self.wdps):
            s = mp.mpf(s)
            c, Y, N = self.loads(beta, theta)
            _, _, sol, Mf = self._piece(s)
            if s not in self._memo:
                self._memo[s] = sol(s)
            yc, pc, yY, pY = self._memo[s]
            y = c * yc + Y * yY
            phi = c * pc + Y * pY
            lam = number(self.blade.length)
            return y, phi, (c + (lam - s) * Y + y) / Mf(s)

    def M_at(self, s):
        with mp.workdps(self.wdps):
            return self._piece(mp.mpf(s))[3](mp.mpf(s))

    def integrate(self, f) -> mp.mpf:
        """∫_0^λ f(s) ds by Gauss–Legendre quadrature, split at the jumps of M."""
        with mp.workdps(self.wdps):
            return linear_blade.integrate_pieces(self.pieces, f)


@functools.lru_cache(maxsize=32)
def solve(blade: linear_blade.Blade, dps: int = 30) -> Suspension:
    """Integrate the linearised blade (2)–(3) for the two unit end loads and build the stiffness.

    Raises :class:`pendsym.blade.SingularBlade` when the end position does not
    determine the loads (the inverted blade at a buckling value).
    """
    g = linear_blade.growth(blade)
    wdps = dps + 12 + int(g / mp.log(10))
    with mp.workdps(wdps):
        lam = number(blade.length)
        tol = mp.mpf(10) ** (-wdps)
        state = [mp.mpf(0)] * 4
        pieces = []
        for a, b, expr in linear_blade.segments(blade):
            Mf = sp.lambdify(blade.var, expr, modules="mpmath")

            def rhs(x, y, Mf=Mf):
                m = Mf(x)
                return [y[1], (1 + y[0]) / m, y[3], ((lam - x) + y[2]) / m]
            sol = mp.odefun(rhs, mp.mpf(a), state, tol=tol)
            state = sol(mp.mpf(b))
            pieces.append((mp.mpf(a), mp.mpf(b), sol, Mf))
        yc, pc, yY, pY = state
        # y(λ) = c·yc + Y·yY = β,  φ(λ) = c·pc + Y·pY = θ
        det = yc * pY - yY * pc
        # det against the square of the largest entry (in units of λ); det/scale is ~e^{−growth}
        # on a regular blade, which the guard digits of wdps cover
        scale = max(abs(yc), abs(yY) / lam, lam * abs(pc), abs(pY)) ** 2
        if abs(det) <= scale * mp.mpf(10) ** (-(wdps - 5)):
            raise linear_blade.SingularBlade("the end position does not determine the loads (buckling value of the blade)")
        per_beta = ((pY / det), (-pc / det))           # (c, Y) for β = 1, θ = 0
        per_theta = ((-yY / det), (yc / det))          # (c, Y) for β = 0, θ = 1
        # N = c + β
        S = mp.matrix([[per_beta[1], per_theta[1]], [per_beta[0] + 1, per_theta[0]]])
    return Suspension(blade, dps, wdps, tuple(pieces), S, (per_beta, per_theta))


@dataclass(frozen=True)
class Mode:
    """One normal mode: n², the end position (β, θ) normalised to θ = 1, and its node z (GF)."""

    n2: mp.mpf
    beta: mp.mpf
    theta: mp.mpf
    z: mp.mpf


def stiffness_matrix(sus: Suspension, a, m=1, g=1) -> mp.matrix:
    """K = m g [[∂Y/∂β, ∂Y/∂θ], [∂N/∂β, ∂N/∂θ + a]] on q = (β, θ) (moments about A)."""
    S = sus.stiffness
    a = mp.mpf(a)
    return mp.mpf(m) * mp.mpf(g) * mp.matrix([[S[0, 0], S[0, 1]], [S[1, 0], S[1, 1] + a]])


def mass_matrix(a, R, m=1) -> mp.matrix:
    """𝕄 = m [[1, a], [a, a² + R²]]: kinetic energy ½ m[(β' + aθ')² + R²θ'²] of the rigid pendulum."""
    a, R = mp.mpf(a), mp.mpf(R)
    return mp.mpf(m) * mp.matrix([[1, a], [a, a * a + R * R]])


def modes(sus: Suspension, a, R, g) -> tuple[Mode, Mode]:
    """The two normal modes of K q = n² 𝕄 q (mpmath eig), principal (node above G, z < 0) first.

    The theory calls the node above G the upper focus F' (z' < 0): it stays fixed in the
    principal oscillation (n°16); the other mode, with F fixed, is the parasitic vibration.
    """
    with mp.workdps(sus.wdps):
        Kq = stiffness_matrix(sus, a, 1, g)
        Mq = mass_matrix(a, R)
        ev, vecs = mp.eig(mp.inverse(Mq) * Kq)
        out = []
        for i in range(2):
            be, th = vecs[0, i], vecs[1, i]
            if abs(mp.im(ev[i])) > abs(ev[i]) * mp.mpf(10) ** (-sus.dps):
                raise ValueError("complex eigenvalue: the pendulum has no real small oscillation")
            be, th = mp.re(be / th), mp.mpf(1)
            out.append(Mode(mp.re(ev[i]), be, th, -be - mp.mpf(a)))
        out.sort(key=lambda md: md.z)
        return out[0], out[1]


def static_offset(sus: Suspension, a, b, q) -> tuple:
    """(β0, θ0) at equilibrium under the force Q = q·mg perpendicular to the rod at AB = b (n°18).

    Projection on Oy: −mgY + Q = 0; moments about A: −mgN − mgaθ + Qb = 0.
    """
    with mp.workdps(sus.wdps):
        a, b, q = mp.mpf(a), mp.mpf(b), mp.mpf(q)
        S = sus.stiffness
        A = mp.matrix([[S[0, 0], S[0, 1]], [S[1, 0], S[1, 1] + a]])
        sol = mp.lu_solve(A, mp.matrix([q, q * b]))
        return sol[0], sol[1]


def energy(sus: Suspension, beta, theta) -> mp.mpf:
    """W/(mg) = ½∫ M φ'² ds, the strain energy of the blade at the end position (β, θ) (n°23)."""
    with mp.workdps(sus.wdps):
        return sus.integrate(lambda s: sus.M_at(s) * sus.deflection(s, beta, theta)[2] ** 2) / 2
