"""Haag 1935, chapter IX: the blade without a hole, the limit both holes must reach (the inverted uniform blade
of n°101–103, (313), derived here by SymPy's ``dsolve`` of (9)–(10) with M = −1/ω², not copied from (313))."""
from __future__ import annotations

import sympy as sp

from pendsym import blade

from ..symbols import lam, omega


def uniform(name: str) -> sp.Expr:
    """v_0, v_λ, w_0, w_λ of the inverted uniform blade, or G_2 = ∫_0^λ w²ω² ds (|M| = 1/ω²)."""
    forms = blade.closed_forms(-1 / omega**2, lam)
    if name == "G2":
        return sp.simplify(sp.integrate(sp.expand_trig(forms["w"] ** 2 * omega**2), (blade.S, 0, lam)))
    return sp.simplify(forms[{"v0": "v0", "vl": "vl", "w0": "w0", "wl": "wl"}[name]])
