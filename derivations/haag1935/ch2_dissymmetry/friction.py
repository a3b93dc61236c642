"""Haag 1935, chapter II, n°46: internal friction together with clamping errors, derived on the reduced equation.

Haag states without formulas ("on constate") that the period is symmetric about the vertical (the same for
the equilibria j and −j) in two cases: the difference between the incoming and the outgoing friction is the
same on the right and on the left (b − a = b' − a'), or the friction does not depend on the curvature (p = 0).
Here n°41's friction term is taken about the tilted equilibrium as (146) writes it, in θ = j + θ1 (the
curvature in proportion to θ, the reading of n°44 where the side is the sign of θ): the force on θ1 is
(n²/Q)·C·|θ|^p|θ1'|^q against the motion, C = b (right, going back), a' (left, out), b' (left, back),
a (right, out), the sides parted at θ1 = −j, i.e. φ = φ_j with θ0 cos φ_j = −j along θ1 = θ0 cos φ.
ΔT/T is the first harmonic (114) (derived, :func:`..ch2_general.derivation.eq114_relative`); its part odd in
j is what makes T differ between the two equilibria.
"""
from __future__ import annotations

import functools

import sympy as sp

from ..ch2_common import j_eq, theta0
from ..ch2_general import derivation as general
from ..symbols import Q, n_squared

phi = sp.Symbol("phi", real=True)
phi_j = sp.Symbol("phi_j", positive=True)          # θ0 cos φ_j = −j: where θ = j + θ1 changes sign
n_freq = sp.Symbol("n", positive=True)
a_r, b_r, a_l, b_l = sp.symbols("a_pq b_pq a'_pq b'_pq", real=True)   # as in (144)–(145), right and left


@functools.lru_cache(maxsize=16)
def period(p: int, q: int) -> sp.Expr:
    """ΔT/T of the friction term of degrees (p, q) about the equilibrium j, by (114) over the four arcs."""
    Th = theta0 * sp.cos(phi) + j_eq                   # θ = j + θ1
    rate = n_freq * theta0 * sp.sin(phi)              # −θ1' (> 0 on (0, π))
    arcs = ((0, phi_j, b_r * Th**p * rate**q),                       # right, going back: force > 0
            (phi_j, sp.pi, a_l * (-Th) ** p * rate**q),               # left, going out
            (sp.pi, 2 * sp.pi - phi_j, -b_l * (-Th) ** p * (-rate) ** q),   # left, going back
            (2 * sp.pi - phi_j, 2 * sp.pi, -a_r * Th**p * (-rate) ** q))    # right, going out
    C = sum(sp.integrate(sp.expand(n_freq**2 / Q * F * sp.cos(phi)), (phi, lo, hi)) for lo, hi, F in arcs)
    C = sp.expand(sp.expand_trig(C)).subs(sp.cos(phi_j), -j_eq / theta0)
    C = C.subs(sp.sin(phi_j), sp.sqrt(1 - j_eq**2 / theta0**2)).subs(phi_j, sp.pi / 2 + sp.asin(j_eq / theta0))   # acos(−j/θ0)
    rel = general.eq114_relative().subs(sp.Symbol("C"), C)
    return sp.simplify(rel.subs(n_squared, n_freq**2))


def odd_part(p: int, q: int) -> sp.Expr:
    """n°46: [ΔT/T(j) − ΔT/T(−j)]/2 of the term (p, q)."""
    d = period(p, q)
    return sp.factor(sp.simplify((d - d.subs(j_eq, -j_eq)) / 2))


DEGREES = ((1, 0), (1, 1), (2, 0), (2, 1), (1, 2))


def case_equal_differences() -> sp.Tuple:
    """n°46, first case: b − a = b' − a' (b' = b − a + a'): the odd parts for the degrees of DEGREES, all 0."""
    return sp.Tuple(*(sp.simplify(odd_part(p, q).subs(b_l, b_r - a_r + a_l)) for p, q in DEGREES))


def case_no_curvature() -> sp.Tuple:
    """n°46, second case: p = 0 (a friction independent of the curvature): the odd parts for q = 0 … 3, all 0."""
    return sp.Tuple(*(odd_part(0, q) for q in range(4)))


def odd_p1q1() -> sp.Expr:
    """n°46: the odd part at p = q = 1, ∝ (b − a) − (b' − a'): neither case, T not symmetric."""
    return odd_part(1, 1)
