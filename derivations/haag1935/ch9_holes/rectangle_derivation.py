"""Haag 1935, chapter IX, n°104–106, eqs. (321)–(333): the blade with a rectangular hole, derived with SymPy.

The blade is inverted (n°104: “en supposant la lame renversée”, chapter VIII: g → −g) and M is taken in
absolute value, as in n°107: (9) reads M v'' + v = 0 with M = 1/ω² for s < s_0 and s > s_1 = s_0 + p and
M' = 1/ω'² across the hole.  The steps follow the memoir:

* (321), (322), (324): the general solution on each piece, by SymPy's ``dsolve``;
* (323), (325): the constants carried across s_0 and s_1 by the continuity of v and v';
* (326)–(329): B, A, D, v_0, v_λ from v'(0) = v'(λ) = −1; (330) the concentric hole;
* (331)–(332): w, from w'(0) = 0, w'(λ) = 1;
* (333): G_2 = ∫ w²/M ds over the three pieces, each integral by SymPy's ``integrate``.
"""
from __future__ import annotations

import functools
import types

import sympy as sp

from pendsym.blade import S as s

from ..symbols import lam, omega

omega_p = sp.Symbol("omega'", positive=True)     # ω' across the hole (n°104)
s0 = sp.Symbol("s_0", positive=True)             # upper side of the hole
p = sp.Symbol("p", positive=True)                # height of the hole, s_1 = s_0 + p
s1 = s0 + p
A, B = sp.symbols("A B", real=True)              # (321)
A1, B1 = sp.symbols("A' B'", real=True)          # (322)
A2, B2 = sp.symbols("A'' B''", real=True)        # (324)
f = sp.Function("f")


@functools.lru_cache(maxsize=None)
def piece(freq: sp.Symbol, origin: sp.Expr, constants: tuple) -> sp.Expr:
    """(321), (322), (324): the general solution of M f'' + f = 0, M = 1/freq², by ``dsolve``, written as
    C cos freq(s − origin) + C' sin freq(s − origin) (the constants renamed)."""
    t = sp.Symbol("t", real=True)                 # t = s − origin
    general = sp.dsolve(f(t).diff(t, 2) / freq**2 + f(t), f(t)).rhs
    C1, C2 = sorted(general.free_symbols - {t, freq}, key=lambda c: c.name)
    cos_part, sin_part = general.coeff(sp.cos(freq * t)), general.coeff(sp.sin(freq * t))
    renamed = general.subs({cos_part: constants[0], sin_part: constants[1]}) if {cos_part, sin_part} == {C1, C2} \
        else None
    if renamed is None:
        raise ValueError(f"unexpected general solution {general}")
    return renamed.subs(t, s - origin)


def pieces() -> tuple:
    """v on s < s_0 (321), s_0 < s < s_1 (322), s > s_1 (324)."""
    return (piece(omega, 0, (A, B)), piece(omega_p, s0, (A1, B1)), piece(omega, s1, (A2, B2)))


def joined(left: sp.Expr, right: sp.Expr, at: sp.Expr) -> list:
    """v and v' continuous at s = at (n°104)."""
    return [(left - right).subs(s, at), sp.diff(left - right, s).subs(s, at)]


@functools.lru_cache(maxsize=None)
def carried() -> types.MappingProxyType:
    """(323) A', B' from A, B; (325) A'', B'' from A, B (through A', B')."""
    first, middle, last = pieces()
    across_s0 = sp.solve(joined(first, middle, s0), [A1, B1], dict=True)[0]
    across_s1 = sp.solve(joined(middle, last, s1), [A2, B2], dict=True)[0]
    out = {A1: across_s0[A1], B1: across_s0[B1]}
    out.update({name: sp.expand(across_s1[name].subs(across_s0)) for name in (A2, B2)})
    return types.MappingProxyType({name: sp.expand(value) for name, value in out.items()})


def across_s1(name: str) -> sp.Expr:
    """After (324): A'' or B'' in terms of A', B' (v, v' continuous at s_1)."""
    _, middle, last = pieces()
    sol = sp.solve(joined(middle, last, s1), [A2, B2], dict=True)[0]
    return sp.expand(sol[{"A''": A2, "B''": B2}[name]])


def blade_function(slope_top: sp.Expr, slope_bottom: sp.Expr) -> types.MappingProxyType:
    """A, B and the three pieces of the solution with f'(0) = slope_top, f'(λ) = slope_bottom (n°4)."""
    first, middle, last = pieces()
    c = carried()
    last_in_AB = last.subs({A2: c[A2], B2: c[B2]})
    sol = sp.solve([sp.diff(first, s).subs(s, 0) - slope_top, sp.diff(last_in_AB, s).subs(s, lam) - slope_bottom],
                   [A, B], dict=True)[0]
    return types.MappingProxyType({
        A: sol[A], B: sol[B],
        "pieces": (first.subs(sol), middle.subs({A1: c[A1], B1: c[B1]}).subs(sol), last_in_AB.subs(sol))})


@functools.lru_cache(maxsize=None)
def v_solution() -> types.MappingProxyType:
    """(326)–(327): v with v'(0) = v'(λ) = −1."""
    return blade_function(-1, -1)


@functools.lru_cache(maxsize=None)
def w_solution() -> types.MappingProxyType:
    """(331): w with w'(0) = 0, w'(λ) = 1."""
    return blade_function(0, 1)


def constant(which: str, name: str) -> sp.Expr:
    """(326)–(327) for v, (331) for w: A or B."""
    sol = v_solution() if which == "v" else w_solution()
    return sp.simplify(sol[{"A": A, "B": B}[name]])


def carried_constant(name: str) -> sp.Expr:
    """(323), (325): A', B', A'' or B'' in terms of A, B."""
    return carried()[{"A'": A1, "B'": B1, "A''": A2, "B''": B2}[name]]


def denominator() -> sp.Expr:
    """(328): D, the denominator of A solved in (327), scaled so that D = sin ωλ without a hole (p = 0)."""
    num, den = sp.fraction(sp.together(v_solution()[A]))
    scale = sp.simplify(den.subs(p, 0) / sp.sin(omega * lam))
    return sp.expand(den / scale)


def end_value(which: str, end: str) -> sp.Expr:
    """(329), (332): v_0, v_λ, w_0, w_λ."""
    sol = v_solution() if which == "v" else w_solution()
    first, _, last = sol["pieces"]
    return sp.factor(sp.together(first.subs(s, 0) if end == "0" else last.subs(s, lam)))


def concentric(expr: sp.Expr) -> sp.Expr:
    """(330): the concentric hole, λ − s_1 = s_0, i.e. λ = 2s_0 + p."""
    return expr.subs(lam, 2 * s0 + p)


def identity_16() -> sp.Expr:
    """(16): w_0 − v_λ − w_λ, which must vanish."""
    return end_value("w", "0") - end_value("v", "l") - end_value("w", "l")


# ---------------------------------------------------------------- n°105: G_2
@functools.lru_cache(maxsize=None)
def square_integral() -> sp.Expr:
    """∫_0^L (a cos kt + b sin kt)² dt by SymPy (the integral of each piece of (333))."""
    a, b, kk, L, t = sp.symbols("a b k L t", positive=True)
    return sp.simplify(sp.integrate(sp.expand((a * sp.cos(kk * t) + b * sp.sin(kk * t)) ** 2), (t, 0, L)))


def piece_integral(expr: sp.Expr, freq: sp.Symbol, origin: sp.Expr, length: sp.Expr) -> sp.Expr:
    """freq² ∫ expr² ds over (origin, origin + length), expr = a cos freq(s − origin) + b sin freq(s − origin)."""
    a_, b_, kk, L, t = sp.symbols("a b k L t", positive=True)
    shifted = sp.expand(expr.subs(s, origin + t))
    a_value, b_value = shifted.coeff(sp.cos(freq * t)), shifted.coeff(sp.sin(freq * t))
    if sp.simplify(shifted - a_value * sp.cos(freq * t) - b_value * sp.sin(freq * t)) != 0:
        raise ValueError("a piece is not a cos + b sin")
    return freq**2 * square_integral().subs({a_: a_value, b_: b_value, kk: freq, L: length})


def G2() -> sp.Expr:
    """n°105, (333): G_2 = ∫_0^λ w²/M ds, M = 1/ω² off the hole and 1/ω'² across it."""
    first, middle, last = w_solution()["pieces"]
    return (piece_integral(first, omega, 0, s0) + piece_integral(middle, omega_p, s0, p)
            + piece_integral(last, omega, s1, lam - s1))
