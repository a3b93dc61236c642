"""The Wallis-type integrals J_m(y) = ∫_0^y cos^{m+1} y dy and their recurrence.

The recurrence of the monomials (the memoir's n°20): (m+1) J_m = sin y cos^m y + m J_{m−2},
J_{−1} = y, J_0 = sin y; and for odd m, J_m(π) = π·1·3·5…m / (2·4·6…(m+1)).
The proofs here hold for a symbolic m, not for sampled values.
"""
from __future__ import annotations

import sympy as sp


def J_integrand(m: sp.Expr, y: sp.Symbol) -> sp.Expr:
    """cos^{m+1} y, the integrand of J_m (n°20)."""
    return sp.cos(y) ** (m + 1)


def recurrence_defect(m: sp.Expr, y: sp.Symbol) -> sp.Expr:
    """d/dy[sin y cos^m y] − ((m+1) cos^{m+1} y − m cos^{m−1} y).

    It vanishes identically; integrating d/dy[sin y cos^m y] from 0 to y then
    gives (m+1)J_m − mJ_{m−2} = sin y cos^m y, the recurrence of n°20.
    """
    lhs = sp.diff(sp.sin(y) * sp.cos(y) ** m, y)
    rhs = (m + 1) * sp.cos(y) ** (m + 1) - m * sp.cos(y) ** (m - 1)
    return sp.simplify(sp.expand(lhs - rhs).subs(sp.sin(y) ** 2, 1 - sp.cos(y) ** 2))


def J(m: int, y: sp.Expr) -> sp.Expr:
    """J_m(y) for an integer m ≥ −1, by the recurrence of n°20 from J_{−1} = y, J_0 = sin y."""
    if m < -1:
        raise ValueError("J_m is defined here for m >= -1")
    if m == -1:
        return y
    if m == 0:
        return sp.sin(y)
    return sp.expand((sp.sin(y) * sp.cos(y) ** m + m * J(m - 2, y)) / (m + 1))


def J_pi_odd(m: sp.Expr) -> sp.Expr:
    """J_m(π) = π·(1·3·5…m)/(2·4·6…(m+1)) for odd m, as a Gamma ratio (n°20, p. 222).

    With m = 2n+1: 1·3…(2n+1) = (2n+1)!!, 2·4…(2n+2) = 2^{n+1}(n+1)!.
    """
    return sp.pi * sp.factorial2(m) / sp.factorial2(m + 1)


def J_pi_odd_gamma(n: sp.Symbol) -> sp.Expr:
    """J_{2n+1}(π) written with Gamma functions: √π Γ(n+3/2)/Γ(n+2)."""
    return sp.sqrt(sp.pi) * sp.gamma(n + sp.Rational(3, 2)) / sp.gamma(n + 2)


def parity_reflection(m: sp.Expr, y: sp.Symbol) -> sp.Expr:
    """cos^{m+1}(π − y) / cos^{m+1}(y) = (−1)^{m+1}: J_m(π) = (−1)^{m+1} J_m(π).

    Hence J_m(π) = 0 for even m (odd power of cos), the half of n°20's theorem.
    """
    return sp.powsimp(sp.powdenest(J_integrand(m, sp.pi - y) / J_integrand(m, y), force=True), force=True)
