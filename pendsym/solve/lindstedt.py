"""Lindstedt–Poincaré expansion of an autonomous oscillator to any order.

The equation, in the stretched time τ = ωt with ω = k + ω1 μ + ω2 μ² + …, is

    ω² x_ττ + k² x + g(x, ω x_τ; μ) = 0,      x(0) = a,  ω x_τ(0) = b,

with g = Σ_{p≥1} μ^p g_p(x, v) polynomial in x and v.  Each x_n(τ) is a trigonometric
polynomial, held as a Laurent polynomial in z = e^{iτ} (a dict m → coefficient), so products
are convolutions and x'' + x = c z^m is solved by c z^m/(1 − m²).  At order n the resonant
coefficient (of z^{±1}) must vanish: its z¹ part fixes ω_n; the z⁻¹ part must then vanish as
well, otherwise the secular term is not an artefact of the frequency and the method refuses
(:class:`NotAFrequency`).  The initial values are kept exactly at every order (the velocity
condition is on ω x_τ, so ω's own corrections enter it).
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

Laurent = dict   # m -> SymPy coefficient of z**m


class NotAFrequency(ValueError):
    """The resonant term at some order is not removable by a frequency correction."""


@dataclass(frozen=True)
class Lindstedt:
    """The expansion: ω's coefficients ω_0 = k, ω_1, …, ω_n and x_0 … x_n as Laurent dicts."""

    omegas: tuple
    xs: tuple
    mu: sp.Symbol

    def frequency(self) -> sp.Expr:
        """ω = Σ ω_j μ^j."""
        return sum((w * self.mu**j for j, w in enumerate(self.omegas)), sp.S.Zero)

    def motion(self, tau: sp.Expr) -> sp.Expr:
        """x(τ) = Σ μ^j x_j(τ), written with cos mτ and sin mτ."""
        return sum((self.mu**j * trig(xj, tau) for j, xj in enumerate(self.xs)), sp.S.Zero)


def _clean(c: sp.Expr) -> sp.Expr:
    return sp.expand(c)


def add(p: Laurent, q: Laurent, scale=1) -> Laurent:
    out = dict(p)
    for m, c in q.items():
        out[m] = _clean(out.get(m, 0) + scale * c)
    return {m: c for m, c in out.items() if c != 0}


def mul(p: Laurent, q: Laurent) -> Laurent:
    out: dict = {}
    for m1, c1 in p.items():
        for m2, c2 in q.items():
            out[m1 + m2] = out.get(m1 + m2, 0) + c1 * c2
    return {m: c for m, c in ((m, _clean(c)) for m, c in out.items()) if c != 0}


def scale(p: Laurent, s) -> Laurent:
    return {m: c for m, c in ((m, _clean(s * c)) for m, c in p.items()) if c != 0}


def d_tau(p: Laurent) -> Laurent:
    return {m: _clean(sp.I * m * c) for m, c in p.items() if m != 0}


def at_zero(p: Laurent) -> sp.Expr:
    return _clean(sum(p.values(), sp.S.Zero))


def trig(p: Laurent, tau: sp.Expr) -> sp.Expr:
    """A real Laurent polynomial in e^{iτ} as Σ (A_m cos mτ + B_m sin mτ)."""
    out = sp.S.Zero
    for m in sorted({abs(m) for m in p}):
        cp, cm = p.get(m, 0), p.get(-m, 0)
        if m == 0:
            out += sp.expand(cp)
            continue
        out += sp.expand(cp + cm) * sp.cos(m * tau) + sp.expand(sp.I * (cp - cm)) * sp.sin(m * tau)
    return out


# truncated series in μ whose coefficients are Laurent polynomials
def _series_mul(s: list, t: list, n: int) -> list:
    out = [dict() for _ in range(n + 1)]
    for i, si in enumerate(s):
        if not si:
            continue
        for j in range(0, n + 1 - i):
            if j < len(t) and t[j]:
                out[i + j] = add(out[i + j], mul(si, t[j]))
    return out


def _series_scalar(s: list, w: list, n: int) -> list:
    """A series of Laurent polynomials times a series of scalars w (w[j] the μ^j coefficient)."""
    out = [dict() for _ in range(n + 1)]
    for i, si in enumerate(s):
        for j in range(0, n + 1 - i):
            if j < len(w) and w[j] != 0:
                out[i + j] = add(out[i + j], scale(si, w[j]))
    return out


def split_polynomial(g: sp.Expr, x: sp.Symbol, v: sp.Symbol, mu: sp.Symbol, n: int) -> list:
    """[g_1, …, g_n] with g = Σ μ^p g_p(x, v) + O(μ^{n+1}), each as {(i, j): coeff of x^i v^j}.

    Raises ValueError when a g_p is not a polynomial in x and v, or g has a μ⁰ term.
    """
    ser = sp.expand(sp.series(g, mu, 0, n + 1).removeO()) if g.has(mu) else sp.expand(g)
    parts = []
    if sp.expand(ser.subs(mu, 0)) != 0:
        raise ValueError("the perturbation does not vanish with the small parameter")
    for p in range(1, n + 1):
        gp = sp.expand(ser.coeff(mu, p))
        if gp.has(mu):
            raise ValueError("the perturbation is not a power series in the small parameter")
        try:
            poly = sp.Poly(gp, x, v)
        except sp.PolynomialError:
            raise ValueError("the perturbation is not a polynomial in the variable and its velocity") from None
        if not all(c.is_number or not c.has(x, v) for c in poly.coeffs()) or gp.has(sp.Abs, sp.sign):
            raise ValueError("the perturbation is not a polynomial in the variable and its velocity")
        parts.append(dict(poly.terms()))
    return parts


def _powers(s: list, top: int, n: int) -> list:
    out = [[{0: sp.S.One}] + [dict() for _ in range(n)]]
    for _ in range(top):
        out.append(_series_mul(out[-1], s, n))
    return out


def expand(g_parts: list, k: sp.Expr, a: sp.Expr, b: sp.Expr, mu: sp.Symbol, n: int) -> Lindstedt:
    """ω to order μⁿ and x_0 … x_n for ω² x_ττ + k² x + Σ μ^p g_p(x, ω x_τ) = 0, x(0)=a, ωx_τ(0)=b."""
    h = (a - sp.I * b / k) / 2
    xs: list = [{1: _clean(h), -1: _clean(sp.conjugate(h))}]
    xs[0] = {m: c for m, c in xs[0].items() if c != 0}
    if not xs[0]:
        raise ValueError("the unperturbed motion is at rest (zero initial values)")
    omegas = [k]
    top_x = max((i for gp in g_parts for (i, j) in gp), default=0)
    top_v = max((j for gp in g_parts for (i, j) in gp), default=0)
    for order in range(1, n + 1):
        X = xs + [dict() for _ in range(n + 1 - len(xs))]
        W = omegas + [sp.S.Zero] * (n + 1 - len(omegas))
        Xt = [d_tau(xj) for xj in X]
        V = _series_scalar(Xt, W, order)                                     # ω x_τ
        W2 = [_clean(sum(W[i] * W[order_j - i] for i in range(order_j + 1))) for order_j in range(order + 1)]
        Xtt = [d_tau(xj) for xj in Xt]
        lhs = _series_scalar(Xtt, W2, order)
        lhs = [add(lhs[j], scale(X[j], k**2)) if j < len(X) else lhs[j] for j in range(order + 1)]
        Xp, Vp = _powers(X[:order + 1], top_x, order), _powers(V, top_v, order)
        for p, gp in enumerate(g_parts, start=1):
            if p > order:
                break
            for (i, j), c in gp.items():
                term = _series_mul(Xp[i], Vp[j], order - p)
                lhs[order] = add(lhs[order], scale(term[order - p], c))
        R = lhs[order]
        # k²(x_n'' + x_n) + 2kω_n x_0'' + R = 0 ; x_0'' has z¹ coefficient −h
        omega_n = sp.factor(sp.cancel(R.get(1, 0) / (2 * k * h)))
        rest = sp.cancel(R.get(-1, 0) - 2 * k * omega_n * sp.conjugate(h))
        if sp.simplify(rest) != 0:
            raise NotAFrequency(f"at order {order} the resonant term is not removable by a frequency "
                                f"correction (secular growth or decay of the amplitude)")
        xn = {m: _clean(-c / (k**2 * (1 - m**2))) for m, c in R.items() if abs(m) != 1}
        C = -at_zero(xn)
        Dv = -sum((omegas[j] * at_zero(d_tau(xs[order - j])) for j in range(1, order)), sp.S.Zero)
        Dv = (Dv - omega_n * at_zero(d_tau(xs[0]))) / k - at_zero(d_tau(xn))
        D = _clean(Dv)
        xn = add(xn, {1: (C - sp.I * D) / 2, -1: (C + sp.I * D) / 2})
        xs.append(xn)
        omegas.append(omega_n)
    return Lindstedt(tuple(omegas), tuple(xs), mu)
