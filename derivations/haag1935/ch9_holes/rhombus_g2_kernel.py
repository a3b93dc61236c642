"""Haag 1935, chapter IX, n°110: the rhombus blade's G_2 (346) in a form that keeps its digits as k → 0 (issue #14).

(346) is G_2 = (2ω²/k)(∫y²/x + ∫z²/x) with each integral written by the primitive (v² + v'²)/2 − vv'/x of n°110 as a
difference of values at x_1 and x_0: terms of order 1 whose difference is of order k, so that in double precision
(346) loses log10(1/k) digits on top of the rounding of the Bessel arguments (:mod:`.kernel_forms`).  Here the
same G_2 is derived, by code, as a sum of positive terms:

1. :func:`solution_from_middle`: every solution of (335) is v(x) = √(x x_0)/x_0 [v(x_0) N_01(x) − v'(x_0) N_11(x)],
   where N_ab(x) = (π√(x_0x)/2)(Y_a(x_0)J_b(x) − J_a(x_0)Y_b(x)) (today's Y: the Wronskian J_1Y_0 − Y_1J_0 = 2/(πx),
   checked by :func:`today_wronskian_residual`) are the cross products the helper ``bessel_cross`` evaluates;
   so v²/x = [v(x_0)N_01 − v'(x_0)N_11]²/x_0;
2. :func:`G2_in_cross`: y and z of n°110 start at the middle with y_0 = z_0, y'_0 = −z'_0 (derived in
   :func:`.rhombus_derivation.middle_values`), so the cross terms cancel in y² + z² and
   G_2 = (2ω²/k)·(2h/x_0)·(y_0² I_01 + y'_0² I_11), h = x_1 − x_0, I_ab = ∫_0^1 N_ab(x_0 + th)² dt;
   y_0 and y'_0 of n°110, rewritten from Haag's Y into today's, are k√(x_0x_1)/(4ω²N_00) and k√(x_0x_1)/(4ω²N_10)
   at x = x_1 (:func:`middle_in_cross`, by SymPy: no step typed in);
3. :func:`scaled_in_cross`: over λ in u = ωλ, q = kλ, with h = u/(1 + √(1 + q/2)) (:func:`.kernel_forms.end_gap`):
   G_2/λ = h√(2q + 4)/(4u)·(I_01/N_00² + I_11/N_10²): no subtraction anywhere;
4. :func:`supplied`: I_ab by Gauss–Legendre quadrature in t (:data:`NODES` nodes, computed here by mpmath): the
   integrand is analytic in x except at x = 0, which lies at t = −x_0/h ≤ −2 for q ≤ 2.5 (≤ −1.148 for q ≤ 5), so
   that the rule's error is below (5 + √24)^(−2n) ≈ 1e-23 for n = 12 (6e-20 at q = 5, measured); each N_ab by
   ``bessel_cross`` (Hankel's expansion or the Taylor series in the gap, in one or two steps: no Bessel function),
   from x_0 = 2u/q as a double-double and the gap th.

5. the sums and the assembly compensated (:mod:`.compensated`): the squares of the cross products, the weights
   and nodes as double-doubles, the two sums of twelve terms by two-sum, the quotients by N_a0² and the factor
   h√(2q + 4)/(4u) by exact residuals (``quotient_low``); what is left is the cross products' own error (~1 ulp
   each, 2 in N_a0²).

**The kernel** (:func:`kernel`, declared on eq346.G2_u_q).  Without step 5, make audit found 6.32 (Python), 6.55 (C)
ulp × max(1, κ) at u = 1.81433, q = 0.128159 (135 and 141 of 20,000 points over 4), of which ~4 ulp were the
roundings of the sums and the assembly; with it (session 12), make audit's machinery (``pendsym.audit.run.main
--only eq346_G2_u_q``, 20,000 points with its adversarial search, on the kernel as the emitter prints it) measured
3.47 ulp × max(1, κ) at worst, Python and C alike, at u = 1.58794, q = 0.0296435 (κ = 0.97; 4.57 ulp), no point
over 4; C about 37 µs a call (26 cross products, most by the double-double Taylor series; on a loaded machine).

**Domain**: u ∈ [0.05, π], q ∈ [1e-8, 5] (its own :data:`Q_ARG`; the kernels of (343) go to q = 1000).  Up to
q = 2.5 (the gap h = x_0/2) the singular point x = 0 of the integrand lies at t = −x_0/h ≤ −2 and the 12-node rule
errs below 1e-23; up to q = 5 at t ≤ −1.148, and :func:`quadrature_residual` measured 5.9e-20 (u = 0.05), 5.4e-20
(u = 1.5), 3.5e-20 (u = π) at q = 5 (3.4e-24 at q = 2.5).  Until session 12 every cross product above q = 2.5 came
from the library's Bessel functions (45 points of q ∈ [2.5, 5]: up to 10.8 scaled ulp, Python, 6.5, C); since
session 13 ``bessel_cross`` continues its Taylor series in steps there (:mod:`.kernels`, "Domain"), within an ulp
at every q, so q ∈ [2.5, 5] is declared.  Beyond q = 5 the blade stays stable and the cross products hold, but the
rule loses digits (2e-13 relative at q = 20, where x = 0 comes to t ≈ −0.43): more nodes (about 16 at q = 20, 30 at
q = 200, by the rate (|z| + √(z² − 1))^(−2n), z = −1 − 2x_0/h), or composite rules on the Taylor steps'
intervals [x_k, 1.5x_k] (each with x = 0 at t = −2), would carry the kernel further; not done.

:func:`integral_residual` checks step 1–3 against the derived (346) by mpmath (the integrals by ``mpmath.quad`` at 50
digits) and :func:`quadrature_residual` step 4; both are run by tests/test_haag1935_ch9_g2_kernel.py, not when the
Specs are built.
"""
from __future__ import annotations

import functools

import mpmath as mp
import sympy as sp

from pendsym.emit.kernels.supplied import BesselCross, QuotientLow, RootQuotient, SuppliedKernelSpec
from pendsym.result import KernelArg

from ..symbols import lam, omega, u
from . import compensated as cm, kernel_forms, kernels, rhombus_derivation as derivation

q = kernel_forms.q
x, x0, x1, k = derivation.x, derivation.x0, derivation.x1, derivation.k
N01, N11, N00, N10 = sp.symbols("N_01 N_11 N_00 N_10", real=True)    # cross products (π√(x_0 x)/2)(Y_aJ_b − J_aY_b)
I01, I11 = sp.symbols("I_01 I_11", positive=True)                   # ∫_0^1 N_ab(x_0 + th)² dt
h = sp.Symbol("h", positive=True)                                   # x_1 − x_0
v_mid, v_mid_slope = sp.symbols("v_m v'_m", real=True)              # v(x_0), dv/dx(x_0)
NODES = 12                                                          # Gauss–Legendre nodes on [0, 1]
Q_ARG = KernelArg("q", 1e-8, 5.0, log=True)     # the 12-node rule within 5e-20 up to q = 5 (see Domain)

# today's J_n, Y_n at x_0 (a), at x (c) and at x_1 (b), as symbols
j0a, j1a, y0a, y1a = sp.symbols("j0a j1a y0a y1a", real=True)
j0c, j1c, y0c, y1c = sp.symbols("j0c j1c y0c y1c", real=True)
y0b, y1b = sp.symbols("y0b y1b", real=True)


def today_wronskian_residual(dps: int = 40) -> float:
    """max |J_1(x)Y_0(x) − Y_1(x)J_0(x) − 2/(πx)| over a few x by mpmath (today's Y_n; Haag's is (π/2)·that plus a
    multiple of J_n, :func:`.rhombus_derivation.neumann_Y`)."""
    with mp.workdps(dps):
        return float(max(abs(mp.besselj(1, t) * mp.bessely(0, t) - mp.bessely(1, t) * mp.besselj(0, t) - 2 / (mp.pi * t))
                         for t in (mp.mpf("0.3"), mp.mpf(7), mp.mpf(250))))


def _cross(a: int, b: int, at: str) -> sp.Expr:
    """(π√(x_0 x)/2)(Y_a(x_0)J_b(x) − J_a(x_0)Y_b(x)) with the values as symbols, x at ``at`` ("c": x)."""
    ja, ya = (j0a, y0a) if a == 0 else (j1a, y1a)
    jc, yc = (j0c, y0c) if b == 0 else (j1c, y1c)
    return sp.pi * sp.sqrt(x0 * x) / 2 * (ya * jc - ja * yc)


@functools.lru_cache(maxsize=None)
def solution_from_middle() -> sp.Expr:
    """Step 1: v(x) = x[P J_1(x) + Q Y_1(x)] ((336), any basis) with P, Q solved from v(x_0), v'(x_0) (dv/dx =
    x[P J_0 + Q Y_0], n°107), the determinant J_1Y_0 − Y_1J_0 at x_0 replaced by 2/(πx_0); returned as
    √(x x_0)/x_0 [v(x_0) N_01 − v'(x_0) N_11] after SymPy shows the two equal (an error otherwise)."""
    P, Q = sp.symbols("P Q")
    sol = sp.solve([x0 * (P * j1a + Q * y1a) - v_mid, x0 * (P * j0a + Q * y0a) - v_mid_slope], [P, Q], dict=True)[0]
    v = x * (sol[P] * j1c + sol[Q] * y1c)
    candidate = sp.sqrt(x * x0) / x0 * (v_mid * N01 - v_mid_slope * N11)
    wronskian = {j1a: (2 / (sp.pi * x0) + y1a * j0a) / y0a}        # J_1Y_0 − Y_1J_0 = 2/(πx_0) at x_0
    diff = (v - candidate.subs({N01: _cross(0, 1, "c"), N11: _cross(1, 1, "c")})).subs(wronskian)
    if sp.simplify(sp.together(diff)) != 0:
        raise ValueError(f"v(x) is not √(x x_0)/x_0 [v(x_0)N_01 − v'(x_0)N_11]: {sp.simplify(diff)}")
    return candidate


def middle_in_cross() -> dict:
    """Step 2: y_0 and y'_0 of n°110 (:func:`.rhombus_derivation.middle_values`, Haag's Y_n) with Y_n = (π/2)Y_n(today)
    + (ln 2 − γ)J_n, each solved for through the one cross product at (x_0, x_1) it holds: N_00 for y_0, N_10 for y'_0."""
    w0, wl, y0, y0p, z0, z0p = derivation.half_symbols()
    d = derivation
    shift = d.NEUMANN_SHIFT
    today = {d.Y0a: sp.pi / 2 * y0a + shift * d.J0a, d.Y1a: sp.pi / 2 * y1a + shift * d.J1a,
             d.Y0b: sp.pi / 2 * y0b + shift * d.J0b, d.Y1b: sp.pi / 2 * y1b + shift * d.J1b}
    values = d.middle_values()
    root = sp.pi * sp.sqrt(x0 * x1) / 2
    out = {}
    for name, cross, defn, solve_for in ((y0, N00, root * (y0a * d.J0b - d.J0a * y0b), y0b),
                                         (y0p, N10, root * (y1a * d.J0b - d.J1a * y0b), y1a)):
        expr = sp.factor(sp.expand(values[name].xreplace(today)))
        expr = sp.simplify(expr.subs(solve_for, sp.solve(cross - defn, solve_for)[0]))
        if expr.free_symbols & {y0a, y1a, y0b, y1b, d.J0a, d.J1a, d.J0b, d.J1b}:
            raise ValueError(f"{name} is not a function of {cross} alone: {expr}")
        out[name] = expr
    if sp.simplify(values[z0] - values[y0]) != 0 or sp.simplify(values[z0p] + values[y0p]) != 0:
        raise ValueError("z_0 = y_0 and z'_0 = −y'_0 do not hold")
    return out


@functools.lru_cache(maxsize=None)
def G2_in_cross() -> sp.Expr:
    """Step 2: G_2 = (1/M ds/dx)·x·(∫y²/x + ∫z²/x) (n°110, :func:`.rhombus_derivation.jacobian_in_x`), each v²/x
    by step 1, the cross term of y² + z² cancelled by expansion, ∫_{x_0}^{x_1} N_ab² dx = h·I_ab; then y_0, y'_0 in
    N_00, N_10."""
    w0, wl, y0, y0p, z0, z0p = derivation.half_symbols()
    v = solution_from_middle()
    integrand = sum(((v**2 / x).subs({v_mid: mid, v_mid_slope: slope}) for mid, slope in ((y0, y0p), (y0, -y0p))),
                    sp.Integer(0))
    integrand = sp.expand(integrand)
    if integrand.coeff(N01 * N11) != 0:
        raise ValueError(f"the cross term of y² + z² does not cancel: {integrand}")
    integral = h * (integrand.coeff(N01**2) * I01 + integrand.coeff(N11**2) * I11)
    factor = sp.simplify(derivation.jacobian_in_x() * x)
    if factor.has(x):
        raise ValueError(f"(1/M)(ds/dx)·x depends on x: {factor}")
    return sp.factor(factor * integral).subs(middle_in_cross())


@functools.lru_cache(maxsize=None)
def scaled_in_cross() -> sp.Expr:
    """Step 3: G_2/λ in u = ωλ, q = kλ, with x_0, x_1 of (334) and h = x_1 − x_0 = :func:`.kernel_forms.end_gap`
    (the gap is a function of u, q only); an error if λ remains."""
    ends = derivation.x_ends()
    expr = G2_in_cross().subs(ends).subs({omega: u / lam, k: q / lam}) / lam
    expr = sp.simplify(expr)
    if expr.has(lam):
        raise ValueError(f"G_2/λ depends on λ: {expr}")
    return expr.subs(h, kernel_forms.end_gap())


def cross_value(a: int, b: int, u_, q_) -> mp.mpf:
    """N_ab at (x_0, x_1) of (334) by mpmath (today's J, Y), at the working precision."""
    X0 = 2 * u_ / q_
    X1 = X0 * mp.sqrt(1 + q_ / 2)
    return cross_at(a, b, X0, X1)


def cross_at(a: int, b: int, X0, X) -> mp.mpf:
    return mp.pi * mp.sqrt(X0 * X) / 2 * (mp.bessely(a, X0) * mp.besselj(b, X) - mp.besselj(a, X0) * mp.bessely(b, X))


def _integrals(u_, q_) -> dict:
    """I_01, I_11 by mpmath quad over t ∈ [0, 1], at the working precision."""
    X0 = 2 * u_ / q_
    gap = X0 * (mp.sqrt(1 + q_ / 2) - 1)
    return {I01: mp.quad(lambda t: cross_at(0, 1, X0, X0 + t * gap) ** 2, [0, 1]),
            I11: mp.quad(lambda t: cross_at(1, 1, X0, X0 + t * gap) ** 2, [0, 1])}


def integral_residual(points=((1.7, 0.1), (0.3, 2.5), (3.1, 1e-4), (1, 1e-8)), dps: int = 50) -> float:
    """max relative difference between step 3 (I_ab by mpmath quad, N_ab by mpmath) and the derived (346) over λ
    (:func:`.kernel_forms.scaled`, the Bessel form at ``dps`` digits) at the points (u, q)."""
    form = scaled_in_cross()
    worst = 0.0
    with mp.workdps(dps):
        for u_, q_ in points:
            U, Q = mp.mpf(u_), mp.mpf(q_)
            env = {u: U, q: Q, N00: cross_value(0, 0, U, Q), N10: cross_value(1, 0, U, Q), **_integrals(U, Q)}
            value = sp.lambdify(list(env), form, "mpmath")(*env.values())
            ref = kernel_forms.reference("G2", u_, q_, dps + 20)
            worst = max(worst, float(abs(value / ref - 1)))
    return worst


# ---------------------------------------------------------------- step 4: the supplied form
@functools.lru_cache(maxsize=None)
def gauss_legendre(n: int = NODES, dps: int = 40) -> tuple[tuple[mp.mpf, mp.mpf], ...]:
    """(node, weight) of the n-point Gauss–Legendre rule on [0, 1]: the roots of P_n by mpmath findroot from numpy's
    double nodes (``leggauss``), the weights 1/((1 − ξ²)P_n'(ξ)²) (half of the [−1, 1] weights); an error if a root
    is found twice or the weights do not sum to 1."""
    from numpy.polynomial.legendre import leggauss
    out = []
    with mp.workdps(dps):
        for start in leggauss(n)[0]:
            xi = mp.findroot(lambda t: mp.legendre(n, t), mp.mpf(float(start)))
            slope = n * (xi * mp.legendre(n, xi) - mp.legendre(n - 1, xi)) / (xi**2 - 1)
            out.append(((1 + xi) / 2, 1 / ((1 - xi**2) * slope**2)))
        if len({mp.nstr(t, 20) for t, w in out}) != n or abs(sum(w for t, w in out) - 1) > mp.mpf(10) ** (5 - dps):
            raise ValueError("the Gauss–Legendre rule lost a node")
    return tuple(sorted(out))


def quadrature_residual(u_, q_, n: int = NODES, dps: int = 40) -> float:
    """max relative error of the n-point rule on I_01, I_11 at (u, q) (mpmath, against mpmath quad)."""
    with mp.workdps(dps):
        U, Q = mp.mpf(u_), mp.mpf(q_)
        X0 = 2 * U / Q
        gap = X0 * (mp.sqrt(1 + Q / 2) - 1)
        exact = _integrals(U, Q)
        rule = gauss_legendre(n, dps)
        return float(max(abs(sum(w * cross_at(a, 1, X0, X0 + t * gap) ** 2 for t, w in rule) / exact[sym] - 1)
                         for a, sym in ((0, I01), (1, I11))))


def factor_parts() -> tuple[sp.Expr, sp.Expr]:
    """c(q) = h√(2q + 4)/(4u) of :func:`scaled_in_cross` (form = c·(I_01/N_00² + I_11/N_10²)) as (the gap h, the rest
    √(2q + 4)/(4u)): read off the derived form, an error if it is not so."""
    form = scaled_in_cross()
    factor = sp.factor(sp.diff(form, I01) * N00**2)
    if sp.simplify(form - factor * (I01 / N00**2 + I11 / N10**2)) != 0 or factor.free_symbols - {u, q}:
        raise ValueError(f"G_2/λ is not a function of u, q times I_01/N_00² + I_11/N_10²: {form}")
    gap = kernel_forms.end_gap()
    if sp.simplify(gap - u / (1 + sp.sqrt(1 + q / 2))) != 0:
        raise ValueError(f"the gap {gap} is not u/(1 + √(1 + q/2))")
    rest = sp.simplify(factor / gap)
    if sp.simplify(rest - sp.sqrt(2 * q + 4) / (4 * u)) != 0:
        raise ValueError(f"c(q)/h is not √(2q + 4)/(4u): {rest}")
    return gap, rest


@functools.lru_cache(maxsize=None)
def supplied() -> sp.Expr:
    """The form of G_2/λ in u, q: c·(S_0/N_00² + S_1/N_10²), S_a = Σ w_i N_a1(x_0 + t_i h)² over :func:`gauss_legendre`
    (I_ab = S_a), every N by ``bessel_cross`` from x_0 = 2u/q as a double-double and the node's gap t_i·h as a
    double-double (t_i, h and their product each with its low part), c = h·√(2q + 4)/(4u) (:func:`factor_parts`).
    Every operation after the cross products is compensated (:mod:`.compensated`: the squares, the weights as
    double-doubles, the two sums of twelve terms, the quotients, c): what is left is the cross products' own error.
    Measured (session 11) without the compensation: 2.77 scaled ulp on the derive's sample but 6.32 (Python), 6.55 (C)
    by make audit at u = 1.81433, q = 0.128159, of which ~4 ulp the roundings of the sums and the assembly."""
    X0 = 2 * u / q
    low = QuotientLow(2 * u, q, X0)
    x0_s, x1_s = kernel_forms.arguments()
    if sp.simplify(x0_s - X0) != 0 or sp.simplify(x1_s - u * sp.sqrt(2 * q + 4) / q) != 0:
        raise ValueError(f"(334) in u, q is not x_0 = 2u/q, x_1 = (u/q)√(2q + 4): {x0_s}, {x1_s}")
    factor_parts()                                      # c = h·√(2q + 4)/(4u), checked
    gap = cm.Pair(RootQuotient(u, q / 2, 0), RootQuotient(u, q / 2, 1))    # h = u/(1 + √(1 + q/2))
    c = cm.div(cm.mul(gap, cm.root(cm.add(cm.exact(2 * q), cm.exact(sp.Integer(4))))), cm.exact(4 * u))
    rule = [(cm.constant(t), cm.constant(w)) for t, w in gauss_legendre()]
    parts = []
    for a in (0, 1):
        end = cm.exact(BesselCross(a, 0, X0, low, gap.hi, gap.lo))                    # N_00, N_10
        terms = []
        for t, w in rule:
            at = cm.mul(t, gap)
            terms.append(cm.mul(w, cm.square(cm.exact(BesselCross(a, 1, X0, low, at.hi, at.lo)))))
        parts.append(cm.div(cm.total(terms), cm.square(end)))
    return cm.mul(c, cm.add(*parts)).value()


NOTES = ("G_2/λ = h√(2q + 4)/(4u)·(I_01/N_00² + I_11/N_10²), h = x_1 − x_0 = u/(1 + √(1 + q/2)), derived from (346) "
         "(module rhombus_g2_kernel): N_ab = (π√(x_0x)/2)(Y_a(x_0)J_b(x) − J_a(x_0)Y_b(x)) and I_ab = ∫_0^1 N_ab(x_0 + th)² dt, "
         "a sum of positive terms where (346) subtracts terms of order 1/k.",
         f"I_ab by the {NODES}-point Gauss–Legendre rule in t; each N_ab by the helper bessel_cross ({kernels.NOTES[0]})",
         "Every operation after the cross products is compensated (two-sum, exact residuals by quotient_low): the "
         "squares, the weighted sums, the quotients and the factor h√(2q + 4)/(4u) add well under an ulp to the cross "
         "products' own error.",
         "Domain: u ∈ [0.05, π] (the inverted blade exists up to u = π as q → 0, further as q grows); q ∈ [1e-8, 5]: "
         "up to q = 5 the integrand's singular point x = 0 lies at t ≤ −1.14 and the 12-point rule errs below 6e-20 "
         "(mpmath); every cross product is Hankel's expansion or the Taylor series in the gap (one or two steps). The "
         "blade is stable beyond, and the cross products hold there too (the kernels of (343) are declared to q = 1000), "
         "but the 12-point rule loses digits as x = 0 nears t = 0 (2e-13 relative at q = 20): q > 5 is not declared.")


def kernel() -> SuppliedKernelSpec:
    """The KernelSpec of G_2/λ (u on the box of :mod:`.kernels`, q ∈ [1e-8, 5]: :data:`Q_ARG`), declared on eq346.G2_u_q."""
    return SuppliedKernelSpec(args=(kernels.U_ARG, Q_ARG), form=supplied(),
                              rule="supplied: positive quadrature of cross products by bessel_cross", notes=NOTES,
                              doc="G_2/λ of the inverted rhombus blade (346), G_2 = ∫ w²/M ds, in u = ωλ and q = kλ "
                                  "(M = M_0(1 + k|s|), M at the ends M_0(1 + q/2)).")


def double_value(u_: float, q_: float) -> float:
    """The supplied form evaluated by its emitted Python (helpers included; for the tests and the figure)."""
    return _emitted()(u_, q_)


@functools.lru_cache(maxsize=None)
def _emitted():
    from pendsym.emit.kernels import emitted_py
    return emitted_py("G2_u_q", (kernels.U_ARG, Q_ARG), supplied())

