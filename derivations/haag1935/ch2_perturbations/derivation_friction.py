"""Haag 1935, chapter II, n°40–42, eqs. (144)–(149): internal friction, derived.

n°41: one term −Ma_pq c^p c'^q of the outgoing friction (144) gives f by (104)–(105) as for the moment law of
n°38 ((146)); the other quadrants of the phase follow from Haag's replacements (a → −b, a → −a', a → b' with
the signs of θ, θ'); ΔT/T (147) is the first harmonic (114) and Δθ0 (149) the work of f over a period, each
quadrant moved to (0, π/2), cos^m sin^n → (π/2)i_mn.
"""
from __future__ import annotations

import sympy as sp

from ..ch2_common import theta0
from ..ch2_general import derivation as general
from ..symbols import K, M_of_s, Q, n_squared, s, theta, z, zp
from .derivation import _single_integral, c_curv, eq139, f_of_moment, g_fn, i_fn, phi, q, slope_rate

p_f = sp.Symbol("p", integer=True, nonnegative=True)      # degree in c of a friction term (144)
a_f, b_f, ap_f, bp_f = sp.symbols("a_pq b_pq a'_pq b'_pq", real=True)   # the coefficients of (144), (145)
c_rate = sp.Symbol("c'", real=True)                        # c' = dc/dt (144)
theta_dot = sp.Symbol("theta'", real=True)
n_freq = sp.Symbol("n", positive=True)


def friction_moment() -> sp.Expr:
    """n°41: ε of the outgoing friction (144), one term: the moment diminished by M a_pq c^p c'^q."""
    return -M_of_s(s) * a_f * c_curv**p_f * c_rate**q


def eq146() -> sp.Expr:
    """(146): f by (104)–(105) for θ, θ' > 0, c = θ(Kv + w)/M, c' = θ'(Kv + w)/M ((9), (13)): the integral is
    g_{p+q}(a_pq) of (139) (a_pq constant along the blade taken inside g)."""
    eps = friction_moment().subs({c_curv: theta * slope_rate(s), c_rate: theta_dot * slope_rate(s)})
    f = f_of_moment(lambda x: eps.subs(s, x))
    k, integral = _single_integral(f)
    body = sp.powsimp(sp.expand_power_base(sp.powsimp(integral.function, force=True), force=True),
                      force=True, combine="exp")
    consts = sp.Mul(*[x for x in sp.Mul.make_args(body) if not x.has(s)])
    rest = sp.Mul(*[x for x in sp.Mul.make_args(body) if x.has(s)])
    target = eq139().function.subs(q, p_f + q).subs(sp.Symbol("x"), 1)
    if sp.simplify(sp.powsimp(rest / target, force=True)) != 1:
        raise ValueError(f"the integrand is not that of g_(p+q): {rest}")
    coeff = consts / a_f
    return sp.powsimp(k * coeff * g_fn(p_f + q, a_f), force=True)


def friction_quadrants() -> tuple:
    """n°41: f in the four quadrants of the phase φ (θ = θ0 cos φ, θ' = −nθ0 sin φ), by Haag's replacements
    in (146): θ > 0, θ' < 0: a → −b, θ' → −θ'; θ < 0, θ' < 0: a → −a', θ → −θ, θ' → −θ'; θ < 0, θ' > 0:
    a → b', θ → −θ; θ > 0, θ' > 0: (146) itself.  Returns ((φ_lo, φ_hi, f), …); g is linear in its argument."""
    f = eq146()
    g_of = lambda coef: f.xreplace({g_fn(p_f + q, a_f): coef * g_fn(p_f + q, 1)})
    rules = ((0, sp.pi / 2, {a_f: -b_f}, {theta_dot: -theta_dot}),
             (sp.pi / 2, sp.pi, {a_f: -ap_f}, {theta: -theta, theta_dot: -theta_dot}),
             (sp.pi, 3 * sp.pi / 2, {a_f: bp_f}, {theta: -theta}),
             (3 * sp.pi / 2, 2 * sp.pi, {}, {}))
    out = []
    for lo, hi, coef, signs in rules:
        expr = g_of(a_f.xreplace(coef)).xreplace(signs)
        out.append((lo, hi, expr))
    return tuple(out)


def _quarter(expr_of_phi: sp.Expr, lo) -> sp.Expr:
    """∫_lo^{lo+π/2} expr dφ moved to (0, π/2) by φ = lo + u (cos, sin shifted by SymPy), the powers of
    −cos, −sin of the moved quadrant made positive, then cos^m sin^n → (π/2)i_mn (i_mn = (2/π)∫cos^m sin^n)."""
    u = sp.Symbol("u", positive=True)
    moved = sp.powsimp(sp.expand_power_base(expr_of_phi.subs(phi, lo + u), force=True), force=True)
    moved = sp.powdenest(moved, force=True)
    coeff, cs, sn = sp.S.One, sp.S.Zero, sp.S.Zero
    for fac in sp.Mul.make_args(sp.expand_power_base(moved, force=True)):
        base, ex = fac.as_base_exp()
        if base in (sp.cos(u), -sp.cos(u)):
            cs += ex
            coeff *= (-1) ** ex if base == -sp.cos(u) else 1
        elif base in (sp.sin(u), -sp.sin(u)):
            sn += ex
            coeff *= (-1) ** ex if base == -sp.sin(u) else 1
        elif fac.has(u):
            raise ValueError(f"{fac} in a quadrant")
        else:
            coeff *= fac
    return sp.powsimp(coeff, force=True) * sp.pi / 2 * i_fn(sp.expand(cs), sp.expand(sn))


def _along(f: sp.Expr) -> sp.Expr:
    """f along θ = θ0 cos φ, θ' = −nθ0 sin φ (φ = nt)."""
    return f.subs({theta: theta0 * sp.cos(phi), theta_dot: -n_freq * theta0 * sp.sin(phi)}, simultaneous=True)


def i_symmetric() -> sp.Expr:
    """n°41: i_mn = i_nm: cos^m φ sin^n φ at φ = π/2 − u is cos^n u sin^m u (SymPy's shift); returns the
    difference of the integrands, 0."""
    m_, n_ = sp.symbols("m n", integer=True, nonnegative=True)
    u = sp.Symbol("u", positive=True)
    return sp.simplify((sp.cos(phi) ** m_ * sp.sin(phi) ** n_).subs(phi, sp.pi / 2 - u) - sp.cos(u) ** n_ * sp.sin(u) ** m_)


def _ordered(expr: sp.Expr, first: sp.Expr) -> sp.Expr:
    """i(m, n) written with ``first`` as its first index when the other order occurs (i_mn = i_nm,
    :func:`i_symmetric`)."""
    if i_symmetric() != 0:
        raise ValueError("i_mn is not symmetric")
    return expr.replace(lambda e: isinstance(e, sp.Function) and e.func == i_fn and len(e.args) == 2
                        and e.args[1] == first, lambda e: i_fn(e.args[1], e.args[0]))


def eq147() -> sp.Expr:
    """(147): ΔT/T by (114) (the perturbation of θ'' is f/(z − z')), the four quadrants moved to (0, π/2);
    n² of (114) is n_freq² here; Q = K(z − z') (45)."""
    C = sum(_quarter(_along(f) / (z - zp) * sp.cos(phi), lo) for lo, hi, f in friction_quadrants())
    rel = general.eq114_relative().subs(sp.Symbol("C"), C).subs(n_squared, n_freq**2)
    rel = sp.simplify(rel.subs(n_squared, n_freq**2))
    return _ordered(sp.factor(sp.simplify(sp.powsimp(rel.subs(z, Q / K + zp), force=True))), p_f + 1)


def eq149() -> sp.Expr:
    """(149): Δθ0 by the first line of n°42 (:func:`first_line_149`) with ∫f dθ over a period, dθ = −θ0 sin φ dφ,
    the quadrants moved to (0, π/2); Q = K(z − z')."""
    total = sum(_quarter(_along(f) * (-theta0 * sp.sin(phi)), lo) for lo, hi, f in friction_quadrants())
    total = total.subs(n_squared, n_freq**2)
    out = first_line_149().subs(sp.Symbol("I_f"), total).subs(z, Q / K + zp)
    return _ordered(sp.factor(sp.simplify(sp.powsimp(out, force=True))), p_f)


def first_line_149() -> sp.Expr:
    """n°42: the first line, Δθ0 = (1/(n²(z − z')θ0))∫f dθ, from the energy of y'' + n²y = f, y = (z − z')θ:
    Δ(½y'² + ½n²y²) = ∫f dy over a period, and ½n²y0² changes by n²y0Δy0 (I_f stands for ∫f dθ)."""
    y0, dy0, F = sp.symbols("y_0 Delta_y_0 F")          # F = ∫f dy
    sol = sp.solve(sp.Eq(n_freq**2 * y0 * dy0, F), dy0)[0]
    return sp.simplify(sol.subs({y0: (z - zp) * theta0, F: (z - zp) * sp.Symbol("I_f")}) / (z - zp))
