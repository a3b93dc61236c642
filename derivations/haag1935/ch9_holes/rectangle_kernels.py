"""Haag 1935, chapter IX, n°105–106: the kernel of G_2/λ of the blade with a concentric rectangular hole (issue #14).

**Status: declared** (session 12) with :func:`compensated_form`: the half-blade form below (:func:`short_form`),
every operation after libm's sin and cos compensated (:mod:`.compensated`: two-sum, exact residuals by the helper
``quotient_low``).  :func:`short_form` alone held the contract on the derive sample (254 points: 2.31 scaled ulp,
Python and C) but not in the audit (``python -m pendsym.audit --only eq333_G2_concentric_u``, 20,000 points with
its adversarial search): :data:`AUDIT`.  What was left was rounding, not cancellation: ~25 operations on the path
of the value, the slope D squared (its own rounding and sin α's doubled), where κ = 1 (u near π/2) allows 4 ulp and
κ = 2 (u → 0, G_2 ∝ 1/u²) 8; the worst points were close to the uniform blade (u_p and ρ small).  Compensated,
those roundings go; what is left is libm's sin and cos (each within an ulp) carried to first order: 1.69 scaled ulp
in the audit (κ = 2.04 there; Python and C alike, none of 20,000 points over 4), C about 500 ns a call.

**Arguments.**  G_2 of (333) is a length and depends on ω, ω', λ, s_0, p; for the concentric hole of n°106's footnote
(λ − s_1 = s_0, i.e. s_0 = (λ − p)/2) G_2/λ is a function of three dimensionless numbers (:func:`concentric_scaled`,
an error if λ remains): u = ωλ (the blade's phase, as in chapters III and VIII), u_p = ω'p (the hole's phase) and
ρ = p/λ (the hole's share of the length).  These are the numbers the footnote's stability conditions are stated
in, ωλ < π/2 and ω'p < π/2, so its whole region is a box.  An off-centre hole needs a fourth argument and
s_0 + p ≤ λ, which a box cannot state: it is not declared.

**Domain.**  u ∈ [1e-6, π/2], u_p ∈ [1e-6, π/2] (π/2 the double below it), ρ ∈ [1e-6, 1 − 1e-6]: the footnote's
region up to its ends.  The box holds the hole proper (ω' ≥ ω, u_p ≥ ρu) and its mirror, a section stiffer than
the blade (u_p < ρu); both are blades of (9), and the form below is the same for both.  The hole vanishes on the
surface u_p = ρu (ω' = ω), inside the box, and as ρ → 0 or u_p → 0 at its faces; none is singular in these
arguments.  G_2/λ grows as 1/u² as u → 0 (ω → 0: the blade stiffens without bound), hence the lower end
1e-6 (the inverted uniform blade's kernels of chapter VIII start there too).  The odd part's determinant D_o
below stays positive on the closed box (see below), and the even one's is a sum of two positive terms, so G_2
has no pole in it.

**Why a supplied form.**  The derived (333) over the concentric hole is ~630 operations; in session 9 the engine's
best rewrite of it measured 22.9 scaled ulp in the audit (terms of the three integrals that cancel, and
(2ωs_0 − sin 2ωs_0)-like differences as ωs_0 → 0).  :func:`short_form` derives another arrangement by code:

* the blade is symmetric about its middle, so w = w_e + w_o (even and odd about s = λ/2), each with the slope ½ at
  the ends (w'(0) = 0, w'(λ) = 1), and the cross term of ∫w²/M vanishes: G_2 = 2∫_0^{λ/2}(w_e² + w_o²)/M over the
  half blade, hole x < p/2 then blade; each half solution is two pieces of (321)–(324) (``dsolve``), joined at the
  hole's edge;
* on the blade piece w = b cos ωt + c sin ωt, and ω²∫_0^{s_0} w² dt = ω(C b² + 2X bc + S c²) (C, X, S by
  ``integrate``), written as a sum of two squares, ω(C(b + cX/C)² + c²(SC − X²)/C), where SC − X² =
  (α² − sin²α)/4, α = ωs_0 (by ``simplify``): the plain sum cancels as α → 0 (c²S against 2Xbc), this one does
  not;
* x − sin x (at α ≤ π/4 in SC − X², and at u_p ≤ π/2 in the odd hole integral) is its Taylor polynomial
  x³ Σ (−x²)^j/(2j + 3)! in Horner form (``series``), whose terms alternate and decrease for x ≤ π/2, so the first
  term left out bounds the truncation: below 2⁻⁶⁰ of the value.

Two differences remain, neither a cancellation the inputs do not have: the odd part's determinant
D_o = ω' cos β cos α − ω sin β sin α, whose second term is at most 0.207 of its first on the box (at u = u_p = π/2,
ρ = ½, on a grid of 8·10⁶ points), so that it loses no digit, and the even part's
b + cX/C = K(cos β − r sin β X/C), r = ω'/ω, which is squared and added to the positive c²(SC − X²)/C: where it
vanishes the sum's relative error stays below ~√3 ulp.  Every sin and cos argument (α ≤ π/4, β ≤ π/4, 2α, u_p)
lies in [0, π/2], so no sign is lost.

The form's equality with the derived (333) is checked at three points to 40 digits whenever it is built
(:func:`checked_short_form`; an error otherwise).
"""
from __future__ import annotations

import functools
import math

import mpmath as mp
import sympy as sp

from pendsym.emit.kernels.plan import Grouped
from pendsym.emit.kernels.supplied import SuppliedKernelSpec
from pendsym.result import KernelArg

from ..symbols import lam, omega, u
from . import compensated, rectangle_derivation as rd

u_p = sp.Symbol("u_p", positive=True)        # u_p = ω'p, the hole's phase
rho = sp.Symbol("rho", positive=True)        # ρ = p/λ

HALF_PI = math.pi / 2                        # the double below π/2
U_ARG = KernelArg("u", 1e-6, HALF_PI, log=True)
UP_ARG = KernelArg("u_p", 1e-6, HALF_PI, log=True)
RHO_ARG = KernelArg("rho", 1e-6, 1 - 1e-6, log=True)
SERIES_TOLERANCE = sp.Rational(1, 2**60)
# the audit of the form as it stood at each step (worst scaled ulp, Python = C; points over 4 of 20,000; where)
AUDIT = (
    ("the plain half-blade form, left to cse", 5.39, 83, (1.5707963267948966, 0.1350652078039178, 0.07934248049565838)),
    ("its parts Grouped, cω and ωb shared by D", 6.33, 41,
     (1.5707963252241002, 0.0029873161605352477, 0.0005780150330459939)),
    ("ω(b + cX/C) as ωb + cω·X/C (short_form)", 4.40, 44,
     (0.03126596553082553, 3.5722303520047847e-06, 1.7013865218909938e-06)),
    ("short_form compensated (compensated_form, the kernel; session 12)", 1.69, 0,
     (0.2794498684478546, 0.781780565354073, 2.2845813098178616e-05)))


def concentric_scaled(g2: sp.Expr) -> sp.Expr:
    """(333) with s_0 = (λ − p)/2 (the concentric hole of n°106's footnote), over λ, in u = ωλ, u_p = ω'p, ρ = p/λ;
    an error if λ remains.  Each trigonometric argument is written as one product (sin(u(ρ − 1)/2) as
    −sin(u(1 − ρ)/2))."""
    g2 = g2.subs(rd.s0, (lam - rd.p) / 2)
    g2 = g2.subs({omega: u / lam, rd.omega_p: u_p / (rho * lam)}).subs(rd.p, rho * lam) / lam
    at = {u: sp.Rational(7, 5), u_p: sp.Rational(1, 2), rho: sp.Rational(3, 10)}
    values = [sp.N(g2.subs(at).subs(lam, length), 30) for length in (sp.Rational(1, 3), 7)]
    if abs(values[0] - values[1]) > 1e-25 * abs(values[1]):
        raise ValueError(f"G_2/λ depends on λ: {values}")
    return g2.subs(lam, 1).replace(lambda e: isinstance(e, (sp.sin, sp.cos)), lambda e: e.func(sp.factor(e.args[0])))


# ---------------------------------------------------------------- the half blade
x = sp.Symbol("x", real=True)                # distance from the middle of the blade
alpha = sp.Symbol("alpha", positive=True)    # α = ωs_0, the blade piece's phase
beta = sp.Symbol("beta", positive=True)      # β = ω'p/2, the half hole's phase
K = sp.Symbol("K", real=True)                # the amplitude on the hole


@functools.lru_cache(maxsize=None)
def half_solution(parity: str) -> tuple[sp.Expr, sp.Expr, sp.Expr, sp.Expr]:
    """The even or odd part of w about the middle: K cos ω'x or K sin ω'x on the hole (n°104's (322) by ``dsolve``),
    b cos ω(x − p/2) + c sin ω(x − p/2) beyond it ((324)), v, v' continuous at x = p/2; with p = 2β/ω',
    λ = p + 2α/ω.  Returns (D, b/K, c/K, ω'²∫_0^{p/2} (w/K)² dx): the slope at x = λ/2 is K·D, so K = 1/(2D)."""
    hole = rd.piece(rd.omega_p, 0, (rd.A1, rd.B1)).subs(rd.s, x)
    hole = hole.subs({rd.A1: K, rd.B1: 0} if parity == "even" else {rd.A1: 0, rd.B1: K})
    blade_piece = rd.piece(omega, rd.p / 2, (rd.A2, rd.B2)).subs(rd.s, x)
    edge = rd.p / 2
    joined = sp.solve([(hole - blade_piece).subs(x, edge), sp.diff(hole - blade_piece, x).subs(x, edge)],
                      [rd.A2, rd.B2], dict=True)[0]
    lengths = {lam: 2 * beta / rd.omega_p + 2 * alpha / omega}
    slope = sp.diff(blade_piece.subs(joined), x).subs(x, lam / 2).subs(lengths).subs(rd.p, 2 * beta / rd.omega_p)
    D = sp.expand(sp.simplify(slope / K))
    b, c = (sp.simplify(joined[name].subs(rd.p, 2 * beta / rd.omega_p) / K) for name in (rd.A2, rd.B2))
    unit = sp.integrate(sp.expand_trig(rd.omega_p**2 * (hole / K) ** 2), (x, 0, rd.p / 2)).subs(rd.p, 2 * beta / rd.omega_p)
    if D.has(K) or b.has(K) or c.has(K) or sp.simplify(sp.solve(K * D - sp.Rational(1, 2), K)[0] - 1 / (2 * D)) != 0:
        raise ValueError(f"the {parity} half solution is not linear in its amplitude")
    return D, b, c, sp.factor(sp.simplify(unit))


@functools.lru_cache(maxsize=None)
def gram() -> tuple[sp.Expr, sp.Expr, sp.Expr, sp.Expr]:
    """C, X, S = ω∫_0^{s_0} (cos², cos·sin, sin²)(ωt) dt in α = ωs_0 (``integrate``), and SC − X² simplified."""
    t = sp.Symbol("t", positive=True)
    C, X, S = (omega * sp.integrate(f.subs(t, omega * t), (t, 0, alpha / omega))
               for f in (sp.cos(t) ** 2, sp.cos(t) * sp.sin(t), sp.sin(t) ** 2))
    C, X, S = (sp.simplify(sp.expand_trig(e)) for e in (C, X, S))
    det = sp.simplify(sp.expand_trig(S * C - X**2))
    if sp.simplify(det - (alpha**2 - sp.sin(alpha) ** 2) / 4) != 0:
        raise ValueError(f"SC − X² = {det} is not (α² − sin²α)/4")
    return C, X, S, (alpha**2 - sp.sin(alpha) ** 2) / 4


@functools.lru_cache(maxsize=None)
def x_minus_sin_series() -> sp.Lambda:
    """x − sin x as x³ times its Taylor polynomial in x² (Horner form, ``series``), to the first order whose term
    left out is below :data:`SERIES_TOLERANCE` of x³/6 at x = π/2 (the terms alternate and decrease there)."""
    z, y = sp.symbols("z y", positive=True)
    full = sp.expand(sp.series(z - sp.sin(z), z, 0, 33).removeO() / z**3)     # up to z^30 in the quotient
    left_out = next(m for m in range(2, 31, 2)          # the first power of z (in the quotient by z³) left out
                    if sp.N(6 * abs(full.coeff(z, m)) * (sp.pi / 2) ** m) < SERIES_TOLERANCE)
    coeffs = [full.coeff(z, m) for m in range(0, left_out, 2)]
    horner = sp.Integer(0)
    for c in reversed(coeffs):
        horner = c + y * horner
    return sp.Lambda(z, z**3 * horner.subs(y, z**2))


def _pieces_as_written(with_series: bool) -> sp.Expr:
    """G_2/λ = 2 Σ K²(hole + ω(C(b + cX/C)² + c²(SC − X²)/C)) over the even and odd half solutions (K = 1/(2D)),
    α − sin α and u_p − sin u_p exact or by :func:`x_minus_sin_series`, with ω = u, ω' = u_p/ρ, α = u(1 − ρ)/2,
    β = u_p/2 (λ = 1).  The parts are :class:`~pendsym.emit.kernels.plan.Grouped` (each evaluated as one unit, in
    the order written): ω' = u_p/ρ, α (u/2 − uρ/2 for ρ < ½, one rounding), 2C = α + sin α cos α
    (``expand_trig``), X/C = sin²α/(2C), 4(SC − X²)/(2C), cω and ωb (each rounded once and shared by the slope D
    and the numerator, so that their rounding moves both alike), D and b + cX/C; left to ``cse`` the emitter
    rounded ω' as u_p·(1/ρ) and D, b + cX/C as products of five or six factors (5.39 scaled ulp in the audit)."""
    C, X, _, det = gram()
    z = sp.Symbol("z", positive=True)
    xms = x_minus_sin_series() if with_series else sp.Lambda(z, z - sp.sin(z))
    # α = u(1 − ρ)/2: for ρ < ½, 1 − ρ is rounded, and u/2 − uρ/2 rounds once (its second term is the smaller)
    A = Grouped(sp.Piecewise((u / 2 - u * rho / 2, rho < sp.Rational(1, 2)), (u * (1 - rho) / 2, True)))
    W, B = Grouped(u_p / rho), u_p / 2
    two_C = sp.expand_trig(2 * C)
    if sp.simplify(two_C - (alpha + sp.sin(alpha) * sp.cos(alpha))) != 0:
        raise ValueError(f"2C = {two_C} is not α + sin α cos α")
    two_C = Grouped(two_C.subs(alpha, A))
    ratio = Grouped(sp.simplify(2 * X).subs(alpha, A) / two_C)                       # X/C
    q = Grouped((xms(alpha) * (alpha + sp.sin(alpha))).subs(alpha, A) / two_C)        # 4(SC − X²)/(2C) = 2(SC − X²)/C
    if sp.simplify(4 * det - (alpha - sp.sin(alpha)) * (alpha + sp.sin(alpha))) != 0:
        raise ValueError("4(SC − X²) is not (α − sin α)(α + sin α)")
    env = {omega: u, rd.omega_p: W, alpha: A, beta: B}
    total = sp.Integer(0)
    for parity in ("even", "odd"):
        D, b, c, unit = half_solution(parity)
        c_w = sp.simplify(c * omega)                                    # cω = −ω' sin β or ω' cos β
        if c_w.has(omega) or b.has(omega) or b.has(rd.omega_p):
            raise ValueError(f"the {parity} blade piece is not b(β), c = ω'/ω × a function of β: {b}, {c}")
        if sp.simplify(D - (-omega * b * sp.sin(alpha) + c_w * sp.cos(alpha))) != 0:
            raise ValueError(f"the {parity} slope per unit amplitude {D} is not −ωb sin α + cω cos α")
        P, Q = Grouped(c_w.subs(env)), Grouped(u * b.subs(env))      # cω and ωb, each rounded once, shared
        scaled_square = Grouped(Q + P * ratio)                         # ω(b + cX/C)/K, sharing cω and ωb with D
        unit = sp.factor(unit.subs(beta, B)).subs(u_p - sp.sin(u_p), xms(u_p))
        if with_series and parity == "odd" and unit.has(sp.sin(u_p)):
            raise ValueError(f"the odd hole integral {unit} does not hold u_p − sin u_p")
        blade_part = (two_C * scaled_square**2 + P**2 * q) / (2 * u)   # ω(C(b + cX/C)² + c²(SC − X²)/C)
        slope = Grouped(-Q * sp.sin(A) + P * sp.cos(A))                # D = −ωb sin α + cω cos α
        total += 2 * (unit.subs(env) + blade_part) / (2 * slope) ** 2
    return total


@functools.lru_cache(maxsize=None)
def short_form() -> sp.Expr:
    """The supplied form of G_2/λ (module docstring), α − sin α and u_p − sin u_p by their Taylor polynomials."""
    return _pieces_as_written(True)


@functools.lru_cache(maxsize=None)
def compensated_form() -> sp.Expr:
    """The kernel's form: :func:`short_form` with every sum, product, quotient and square compensated
    (:func:`.compensated.convert`: the same operations in the same arrangement, each with its exact rounding error
    carried in a low part; sin and cos of (α, β) by libm at the high part, corrected to first order for the low).
    Measured (session 12) against the test's reference (∫w²/|M| ds by mpmath, tests/test_haag1935_ch9_rectangle_kernels.py)
    at its 19 points, the plain form's audit worst points and 100 random points of the box: 0.91 scaled ulp at
    worst (Python = C), where :func:`short_form` measured 4.40; make audit's worst point of this form: 1.69
    (:data:`AUDIT`).  Its one Piecewise (α's two arrangements) becomes a Select of both (:func:`.compensated._choice`),
    both safe on the whole box."""
    return compensated.convert(short_form(), {}).value()


def ungrouped(expr: sp.Expr) -> sp.Expr:
    """expr with each :class:`Grouped` part replaced by its value (Grouped orders the kernel's operations only)."""
    return expr.replace(Grouped, lambda arg: arg).replace(sp.Piecewise, lambda *pieces: pieces[-1][0])


def checked_short_form(derived: sp.Expr) -> sp.Expr:
    """:func:`short_form` after checking that its exact version (no series) equals ``derived`` (the Result's
    G_2/λ from (333)) at three points of the box to 40 digits, and the series version to 1e-15."""
    exact, form = (ungrouped(e) for e in (_pieces_as_written(False), short_form()))
    for at in ((sp.Rational(7, 5), sp.Rational(1, 2), sp.Rational(3, 10)), (sp.Rational(1, 100), 1, sp.Rational(9, 10)),
               (sp.Rational(3, 2), sp.Rational(3, 2), sp.Rational(1, 20))):
        env = dict(zip((u, u_p, rho), at))
        with mp.workdps(50):
            want = sp.N(derived.subs(env), 50)
            if abs(sp.N(exact.subs(env), 50) - want) > 1e-40 * abs(want):
                raise ValueError(f"the half-blade form differs from (333) at {at}")
            if abs(sp.N(form.subs(env), 50) - want) > 1e-15 * abs(want):
                raise ValueError(f"the series form differs from (333) at {at}")
    return form


NOTES = ("G_2 = 2∫_0^{λ/2}(w_e² + w_o²)/M over the half blade (w even and odd about the middle, slope ½ at each end), "
         "each blade piece ω∫(b cos + c sin)² written as C(b + cX/C)² + c²(α² − sin²α)/(4C), α = u(1 − ρ)/2; "
         "x − sin x (x = α ≤ π/4 and x = u_p ≤ π/2) by its Taylor polynomial in Horner form.",
         "Every operation after libm's sin and cos is compensated (two-sum, exact residuals by quotient_low): the "
         "value is as if computed in twice the precision from sin and cos.",
         "Domain: u, u_p ∈ [1e-6, π/2], ρ ∈ [1e-6, 1 − 1e-6]: the stable region of n°106's footnote (ωλ < π/2, "
         "ω'p < π/2) as a box; G_2/λ ~ 1/u² as u → 0.")


def kernel() -> SuppliedKernelSpec:
    """The KernelSpec of G_2/λ in (u, u_p, ρ), :func:`compensated_form`.  Its form is not compared with the derived
    (333) here (that needs the Result, built later): the kernel stage measures it against the derived form on its
    sample, and :func:`checked_short_form` is a test."""
    return SuppliedKernelSpec(
        args=(U_ARG, UP_ARG, RHO_ARG), form=compensated_form(), rule="supplied: half blade, sums of squares, compensated",
        notes=NOTES,
        doc="G_2/λ of the inverted blade with a concentric rectangular hole (333), in u = ωλ, u_p = ω'p, ρ = p/λ "
            "(n°106 footnote: stable for u < π/2, u_p < π/2); G_2/λ ~ 1/u² as u → 0.")
