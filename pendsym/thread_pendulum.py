"""A rigid body hung from an inextensible thread: the exact double pendulum, at high precision.

The thread OA (length λ, angle ψ from the downward vertical) is hinged at the fixed point O
and carries at A a rigid body whose centre of gravity G lies on the line AG (length a,
angle θ), with radius of gyration R about G and mass m.  The thread may be given a mass
m' spread uniformly along it, as a straight rigid rod hinged at both ends (moment of
inertia m'λ²/3 about O, centre of gravity at λ/2).  Nothing here is linearised:

* :func:`kinetic_energy` and :func:`potential_energy` from the Cartesian positions of G
  and A (the velocities by mpmath ``diff`` of the positions along the motion);
* :func:`accelerations`, the exact Lagrange equations of the two angles;
* :func:`linear_modes`, the small oscillations: the generalised eigenproblem
  V q = n² 𝕋 q of the Hessians at rest (det(V − n²𝕋) = 0 solved as a polynomial in n²,
  so that R = 0, where 𝕋 is singular, keeps its one finite mode);
* :func:`motion`, the exact equations integrated by mpmath ``odefun`` (Taylor series);
* :func:`principal_period`, the period of the principal nonlinear oscillation of amplitude
  θ0: the periodic orbit through the rest point (θ0, ψ0), found by shooting on ψ0 until
  θ and ψ vanish together a quarter period later (the orbit is symmetric).

Lengths in any unit, g in the same unit per s²; mass ratios only (m = 1).
"""
from __future__ import annotations

from dataclasses import dataclass

import mpmath as mp


@dataclass(frozen=True)
class Pendulum:
    """Thread length λ, AG = a, radius of gyration R, gravity g and the thread's mass ratio m'/m:
    ``thread_mass`` in the kinetic energy, ``thread_weight`` in the weight (the same when None;
    a perturbation study may switch one of them off)."""

    lam: object
    a: object
    R: object
    g: object
    thread_mass: object = 0
    thread_weight: object = None

    def numbers(self) -> tuple:
        """(λ, a, R, g, m'/m in the inertia) as mpf at the working precision."""
        return tuple(mp.mpf(x) for x in (self.lam, self.a, self.R, self.g, self.thread_mass))

    def weight_ratio(self) -> mp.mpf:
        """m'/m in the weight."""
        return mp.mpf(self.thread_mass if self.thread_weight is None else self.thread_weight)


# ---------------------------------------------------------------- energies from the positions
def positions(p: Pendulum, theta, psi) -> tuple:
    """(x_A, y_A, x_G, y_G), y upward from O."""
    lam, a, _R, _g, _mu = p.numbers()
    xA, yA = lam * mp.sin(psi), -lam * mp.cos(psi)
    return xA, yA, xA + a * mp.sin(theta), yA - a * mp.cos(theta)


def kinetic_energy(p: Pendulum, theta, psi, dtheta, dpsi) -> mp.mpf:
    """T = ½m|v_G|² + ½mR²θ'² (+ ½(m'λ²/3)ψ'² for the thread), m = 1; v_G by differentiating the
    Cartesian position along the motion θ + θ't, ψ + ψ't at t = 0."""
    _lam, _a, R, _g, mu = p.numbers()
    vx = mp.diff(lambda t: positions(p, theta + dtheta * t, psi + dpsi * t)[2], 0)
    vy = mp.diff(lambda t: positions(p, theta + dtheta * t, psi + dpsi * t)[3], 0)
    lam = mp.mpf(p.lam)
    return (vx**2 + vy**2 + R**2 * dtheta**2) / 2 + mu * lam**2 * dpsi**2 / 6


def potential_energy(p: Pendulum, theta, psi) -> mp.mpf:
    """V = m g y_G + m' g y_(middle of the thread), m = 1 (zero at O)."""
    g = p.numbers()[3]
    _xA, yA, _xG, yG = positions(p, theta, psi)
    return g * yG + p.weight_ratio() * g * yA / 2


# ---------------------------------------------------------------- exact equations of motion
def mass_matrix(p: Pendulum, theta, psi) -> mp.matrix:
    """𝕋(q) of T = ½ q'ᵀ𝕋 q', q = (θ, ψ)."""
    lam, a, R, _g, mu = p.numbers()
    c = a * lam * mp.cos(theta - psi)
    return mp.matrix([[R**2 + a**2, c], [c, lam**2 * (1 + mu / 3)]])


def accelerations(p: Pendulum, theta, psi, dtheta, dpsi) -> tuple:
    """(θ'', ψ'') of the exact Lagrange equations.

    d/dt ∂T/∂q' − ∂T/∂q = −∂V/∂q with T of :func:`mass_matrix`:
    (R² + a²)θ'' + aλ cos(θ − ψ)ψ'' + aλ sin(θ − ψ)ψ'² + g a sin θ = 0,
    λ²(1 + μ/3)ψ'' + aλ cos(θ − ψ)θ'' − aλ sin(θ − ψ)θ'² + gλ(1 + μ_w/2) sin ψ = 0
    (μ = m'/m in the inertia, μ_w in the weight).
    """
    lam, a, _R, g, _mu = p.numbers()
    s = a * lam * mp.sin(theta - psi)
    rhs = mp.matrix([-s * dpsi**2 - g * a * mp.sin(theta),
                     s * dtheta**2 - g * lam * (1 + p.weight_ratio() / 2) * mp.sin(psi)])
    acc = mp.lu_solve(mass_matrix(p, theta, psi), rhs)
    return acc[0], acc[1]


# ---------------------------------------------------------------- small oscillations
@dataclass(frozen=True)
class Mode:
    """A normal mode: n², the ratio ψ/θ, and the node z of the rod measured from G (n°7 convention:
    the point at a + z from A along the rod stays still, λψ + (a + z)θ = 0)."""

    n2: mp.mpf
    ratio: mp.mpf
    z: mp.mpf


def rest_matrices(p: Pendulum) -> tuple:
    """(𝕋, V): the mass matrix and the Hessian of V at rest."""
    lam, a, _R, g, _mu = p.numbers()
    return mass_matrix(p, 0, 0), mp.matrix([[g * a, 0], [0, g * lam * (1 + p.weight_ratio() / 2)]])


def squared_pulsations(p: Pendulum) -> list:
    """The roots n² of det(V − n²𝕋) = 0, sorted (one root when R = 0)."""
    T0, V0 = rest_matrices(p)
    # det(V − x T) = det T · x² − (V00 T11 + V11 T00 − 2 V01 T01)·x + det V
    coeffs = [T0[0, 0] * T0[1, 1] - T0[0, 1] ** 2, -(V0[0, 0] * T0[1, 1] + V0[1, 1] * T0[0, 0]),
              V0[0, 0] * V0[1, 1]]
    scale = max(abs(c) for c in coeffs)
    if abs(coeffs[0]) <= scale * mp.mpf(10) ** (-mp.mp.dps + 3):
        roots = [-coeffs[2] / coeffs[1]]
    else:
        roots = sorted(mp.re(r) for r in mp.polyroots(coeffs, maxsteps=200, extraprec=2 * mp.mp.prec))
    return roots


def linear_modes(p: Pendulum) -> tuple:
    """The modes of V q = n² 𝕋 q at rest, sorted by n² (one mode when R = 0)."""
    lam, a = p.numbers()[:2]
    T0, V0 = rest_matrices(p)
    out = []
    for x in squared_pulsations(p):
        # first row: (V00 − x T00) θ − x T01 ψ = 0
        ratio = (V0[0, 0] - x * T0[0, 0]) / (x * T0[0, 1])
        out.append(Mode(x, ratio, -lam * ratio - a))
    return tuple(out)


def principal_mode(p: Pendulum) -> Mode:
    """The mode whose node is above G (z' < 0, n°9): the principal oscillation."""
    return next(md for md in linear_modes(p) if md.z < 0)


# ---------------------------------------------------------------- integration
def motion(p: Pendulum, state0, tol=None):
    """The exact motion from state0 = (θ, ψ, θ', ψ') at t = 0: mpmath odefun, a function of t."""
    def rhs(_t, y):
        th2, ps2 = accelerations(p, y[0], y[1], y[2], y[3])
        return [y[2], y[3], th2, ps2]
    return mp.odefun(rhs, 0, [mp.mpf(x) for x in state0], tol=tol)


def quarter_residual(p: Pendulum, theta0, psi0, t_guess) -> tuple:
    """From rest at (θ0, ψ0): the first time t1 after which θ vanishes, and ψ(t1)."""
    sol = motion(p, (theta0, psi0, 0, 0))
    t1 = mp.findroot(lambda t: sol(t)[0], t_guess)
    return t1, sol(t1)[1]


def principal_period(p: Pendulum, theta0) -> mp.mpf:
    """The period of the principal nonlinear oscillation with θ between ±θ0 (a periodic orbit).

    Shooting on ψ0 (secant, from the linear mode's ratio) until ψ vanishes when θ does: by the
    symmetry (θ, ψ, t) → (−θ, −ψ, −t) the orbit is then periodic, of period 4 t1.
    """
    theta0 = mp.mpf(theta0)
    mode = principal_mode(p)
    t_guess = [mp.pi / (2 * mp.sqrt(mode.n2))]

    def residual(psi0):
        t1, psi_at = quarter_residual(p, theta0, psi0, t_guess[0])
        t_guess[0] = t1
        return psi_at

    start = mode.ratio * theta0
    psi0 = mp.findroot(residual, (start, start * (1 + theta0**2 / 10)), solver="secant")
    t1, _ = quarter_residual(p, theta0, psi0, t_guess[0])
    return 4 * t1
