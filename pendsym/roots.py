"""Roots of a real quadratic, written so that neither one cancels.

For z² + p z + q = 0 with real roots, the textbook forms −p/2 ± √(p²/4 − q) lose
the root of smaller modulus when |p| is large: −p/2 and the square root nearly
cancel.  Vieta's product z₁z₂ = q gives that root without the cancellation.
Both roots are returned as Piecewise expressions on the sign of p, each branch
algebraically identical to the textbook form (the tests check it); the forms
follow the usual numerical practice (e.g. Press et al., Numerical Recipes §5.6).
"""
from __future__ import annotations

import sympy as sp


def quadratic_roots(poly: sp.Poly) -> tuple[sp.Expr, sp.Expr]:
    """(z₊, z₋) = −p/2 ± √(p²/4 − q) of the monic quadratic poly = z² + p z + q.

    Where p > 0, z₋ is taken as it stands and z₊ = q/z₋; elsewhere z₊ as it stands and
    z₋ = q/z₊.  The roots must be real (p²/4 − q ≥ 0) and q ≠ 0 for the Vieta form.
    """
    if poly.degree() != 2 or poly.LC() != 1:
        raise ValueError(f"quadratic_roots: a monic quadratic is required, got {poly.as_expr()}")
    _, p, q = poly.all_coeffs()
    root = sp.sqrt(p**2 / 4 - q)
    plus, minus = -p / 2 + root, -p / 2 - root
    return (sp.Piecewise((q / minus, p > 0), (plus, True)),
            sp.Piecewise((minus, p > 0), (q / plus, True)))
