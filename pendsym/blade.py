"""The elastic blade of a pendulum suspension, independent of any memoir.

A blade of length λ has the stiffness ratio M(s) = EI/(mg) on [0, λ].  The
functions of the small-oscillation theory of an elastic suspension (the blade memoir's eqs. (9)–(14))
are the solutions v, w of

    M v'' − v = 0,    v'(0) = v'(λ) = −1,   w'(0) = 0,  w'(λ) = 1,       (9)–(10)

with φ1 = 1 + v', φ2 = w' (11), the end values v0, vλ, w0, wλ, the
coefficients β1 = λ + vλ − v0, β2 = wλ − w0 (17), (22), and the integrals

    F_n(K)   = ∫ (Kφ1 + φ2)^n ds,         G_n(K) = ∫ (Kv + w)^n / M^{n−1} ds    (79)
    H_n(Y,θ) = ∫ (Yφ1 + θφ2)^n ds                                           (103)

all over [0, λ].  Here they are computed numerically by shooting: the two
fundamental solutions (y = 1, y' = 0) and (y = 0, y' = 1) are integrated by
mpmath's Taylor solver ``odefun`` segment by segment (M may jump, as over a
hole: y and y' are continuous there because y'' = y/M is integrable), the
two-point conditions (10) are solved from their end values, and the integrals
are done by mpmath ``quad`` on the dense solution.  M may be a constant, any
SymPy expression in s, a Piecewise with jumps, or negative (the inverted
blade, n°100–101).  When the boundary-value problem is singular (the inverted
blade at its buckling values) :class:`SingularBlade` is raised.

For constant M, :func:`closed_forms` returns the SymPy solution (dsolve).
"""
from __future__ import annotations

import functools
import types
from dataclasses import dataclass, field
from typing import Callable

import mpmath as mp
import sympy as sp

S = sp.Symbol("s", real=True)   # curvilinear abscissa, 0 ≤ s ≤ λ


class SingularBlade(ValueError):
    """The two-point problem (9)–(10) has no unique solution (y1'(λ) = 0)."""


@dataclass(frozen=True)
class Blade:
    """A blade: its length λ and its stiffness ratio M(s) = EI/(mg) (the blade memoir's eq. (1)).

    ``M`` is a number or a SymPy expression in ``var``; jumps are written with
    ``Piecewise`` and conditions comparing ``var`` with numbers.
    """

    length: sp.Expr
    M: sp.Expr
    var: sp.Symbol = S

    def __post_init__(self):
        length = sp.sympify(self.length)
        # an exact number stays as it is (nsimplify would round λ(1 + 1e-9) back to λ)
        object.__setattr__(self, "length", length if length.is_Rational else sp.nsimplify(length))
        object.__setattr__(self, "M", sp.sympify(self.M))
        if not (self.length.is_number and self.length > 0):
            raise ValueError(f"the length must be a positive number, got {self.length}")
        extra = self.M.free_symbols - {self.var}
        if extra:
            raise ValueError(f"M depends on {sorted(map(str, extra))}, not only on {self.var}")

    @property
    def constant(self) -> bool:
        return self.var not in self.M.free_symbols


# ---------------------------------------------------------------- segments
def breakpoints(blade: Blade) -> tuple[sp.Expr, ...]:
    """0, the abscissae where a Piecewise M may jump (inside (0, λ)), and λ."""
    pts = {sp.S.Zero, blade.length}
    for pw in blade.M.atoms(sp.Piecewise):
        for _, cond in pw.args:
            for rel in cond.atoms(sp.core.relational.Relational):
                for side in (rel.lhs, rel.rhs):
                    if side.is_number and 0 < side < blade.length:
                        pts.add(sp.nsimplify(side))
    return tuple(sorted(pts, key=float))


def _branch(expr: sp.Expr, var: sp.Symbol, at: sp.Expr) -> sp.Expr:
    """expr with every Piecewise replaced by its branch valid at var = at."""
    def pick(pw):
        for e, c in pw.args:
            if bool(c.subs(var, at)):
                return e
        raise ValueError(f"M is undefined at {var} = {at}")
    return expr.replace(lambda e: isinstance(e, sp.Piecewise), pick)


def segments(blade: Blade) -> tuple[tuple[sp.Expr, sp.Expr, sp.Expr], ...]:
    """(a, b, M on (a, b)) for the smooth pieces of M."""
    pts = breakpoints(blade)
    return tuple((a, b, _branch(blade.M, blade.var, (a + b) / 2)) for a, b in zip(pts, pts[1:]))


def growth(blade: Blade) -> mp.mpf:
    """∫ |M|^{−1/2} ds: the exponential growth (in nepers) of the solutions; sets guard digits."""
    total = mp.mpf(0)
    with mp.workdps(15):
        for a, b, e in segments(blade):
            f = sp.lambdify(blade.var, e, modules="mpmath")
            total += mp.quad(lambda x: 1 / mp.sqrt(abs(f(x))), [a, b])
    return total


def integrate_pieces(pieces, f: Callable) -> mp.mpf:
    """∫ f(s) ds over the pieces (a, b, _, M on the piece) by Gauss–Legendre quadrature, split at
    the jumps of M and into sub-intervals of about 2 nepers of growth, at the working precision."""
    total = mp.mpf(0)
    for a, b, _, Mf in pieces:
        n = 1 + int(mp.quad(lambda x: 1 / mp.sqrt(abs(Mf(x))), [a, b], maxdegree=4) / 2)
        total += mp.quad(f, mp.linspace(a, b, n + 1), method="gauss-legendre")
    return total


# ---------------------------------------------------------------- the shooting solution
@dataclass(frozen=True)
class BladeSolution:
    """v, w of (9)–(10) on a blade, as dense high-precision functions of s.

    ``pieces`` holds (a, b, interpolant of [y1, y1', y2, y2'], M on the piece);
    v = Av·y1 − y2, w = Aw·y1 (v'(0) = −1, w'(0) = 0).
    """

    blade: Blade
    dps: int
    wdps: int
    pieces: tuple
    Av: mp.mpf
    Aw: mp.mpf
    # values of state(s) already computed: quadratures of F_n, G_n, H_n … at different n, K
    # reuse the same nodes, and each interpolation of the Taylor solution is costly
    _memo: dict = field(default_factory=dict, compare=False, hash=False, repr=False)

    def _piece(self, s):
        s = mp.mpf(s)
        for piece in self.pieces:
            if s <= piece[1]:
                return piece
        return self.pieces[-1]

    def state(self, s) -> tuple:
        """(v, v', w, w') at s (continuous across jumps of M)."""
        with mp.workdps(self.wdps):
            s = mp.mpf(s)
            if s not in self._memo:
                a, b, sol, _ = self._piece(s)
                y1, d1, y2, d2 = sol(s)
                self._memo[s] = (self.Av * y1 - y2, self.Av * d1 - d2, self.Aw * y1, self.Aw * d1)
            return self._memo[s]

    def M_at(self, s):
        with mp.workdps(self.wdps):
            return self._piece(s)[3](mp.mpf(s))

    # eq. (9)–(11)
    def v(self, s):
        return self.state(s)[0]

    def w(self, s):
        return self.state(s)[2]

    def phi1(self, s):
        """φ1 = 1 + v' (eq. 11)."""
        with mp.workdps(self.wdps):
            return 1 + self.state(s)[1]

    def phi2(self, s):
        """φ2 = w' (eq. 11)."""
        return self.state(s)[3]

    # end values and coefficients
    @property
    def v0(self):
        return self.v(0)

    @property
    def vl(self):
        return self.v(self.blade.length)

    @property
    def w0(self):
        return self.w(0)

    @property
    def wl(self):
        return self.w(self.blade.length)

    @property
    def beta1(self):
        """β1 = λ + vλ − v0 (eqs. 17, 22)."""
        with mp.workdps(self.wdps):
            return mp.mpf(self.blade.length) + self.vl - self.v0

    @property
    def beta2(self):
        """β2 = wλ − w0 (eq. 22)."""
        with mp.workdps(self.wdps):
            return self.wl - self.w0

    # integrals
    def integrate(self, f: Callable) -> mp.mpf:
        """∫_0^λ f(s) ds by mpmath quad, split at the jumps and into pieces of ~2 nepers."""
        with mp.workdps(self.wdps):
            return integrate_pieces(self.pieces, f)

    def F(self, n: int, K) -> mp.mpf:
        """F_n = ∫ (Kφ1 + φ2)^n ds (eq. 79)."""
        with mp.workdps(self.wdps):
            K = mp.mpf(K)
            return self.integrate(lambda s: (lambda st: (K * (1 + st[1]) + st[3]) ** n)(self.state(s)))

    def G(self, n: int, K) -> mp.mpf:
        """G_n = ∫ (Kv + w)^n / M^{n−1} ds (eq. 79)."""
        with mp.workdps(self.wdps):
            K = mp.mpf(K)
            return self.integrate(lambda s: (lambda st: (K * st[0] + st[2]) ** n / self.M_at(s) ** (n - 1))(self.state(s)))

    def H(self, n: int, Y, theta) -> mp.mpf:
        """H_n = ∫ (Yφ1 + θφ2)^n ds (eq. 103)."""
        with mp.workdps(self.wdps):
            Y, theta = mp.mpf(Y), mp.mpf(theta)
            return self.integrate(lambda s: (lambda st: (Y * (1 + st[1]) + theta * st[3]) ** n)(self.state(s)))

    def y(self, s, Y, theta):
        """Ordinate of the blade, y = Y(s + v − v0) + θ(w − w0) (eq. 77, x replaced by s)."""
        with mp.workdps(self.wdps):
            v, _, w, _ = self.state(s)
            return mp.mpf(Y) * (s + v - self.v0) + mp.mpf(theta) * (w - self.w0)

    def inertia(self, K) -> mp.mpf:
        """I_λ/m' = (1/λ)∫ y² ds for θ = 1, Y = K, uniform linear density m'/λ (n°36)."""
        with mp.workdps(self.wdps):
            lam = mp.mpf(self.blade.length)
            return self.integrate(lambda s: self.y(s, K, 1) ** 2) / lam

    def weight_integral(self, K) -> mp.mpf:
        """J = (1/λ)∫ (s − x) ds with s − x = ½∫_0^s (Kφ1 + φ2)² (θ = 1, uniform density, n°37);
        by Fubini J = (1/2λ)∫ (λ − s)(Kφ1 + φ2)² ds."""
        with mp.workdps(self.wdps):
            lam, K = mp.mpf(self.blade.length), mp.mpf(K)
            f = lambda s: (lambda st: (lam - s) * (K * (1 + st[1]) + st[3]) ** 2)(self.state(s))
            return self.integrate(f) / (2 * lam)


@functools.lru_cache(maxsize=64)
def solve(blade: Blade, dps: int = 30) -> BladeSolution:
    """Shoot the two fundamental solutions through the segments and solve (10).

    Guard digits cover the growth e^{∫|M|^{-1/2}} of the solutions, whose
    combination v decays where y1, y2 grow.  Raises SingularBlade when
    y1'(λ) = 0 to the working precision (e.g. the inverted uniform blade at
    λ/√(−M) = jπ).
    """
    for a, b, expr in segments(blade):
        Mf = sp.lambdify(blade.var, expr, modules="mpmath")
        if any(mp.mpf(Mf(x)) == 0 for x in mp.linspace(mp.mpf(a), mp.mpf(b), 7)):
            raise ValueError(f"M vanishes on [{a}, {b}]")
    g = growth(blade)
    wdps = dps + 12 + int(g / mp.log(10))
    with mp.workdps(wdps):
        tol = mp.mpf(10) ** (-wdps)
        state = [mp.mpf(1), mp.mpf(0), mp.mpf(0), mp.mpf(1)]
        pieces = []
        for a, b, expr in segments(blade):
            Mf = sp.lambdify(blade.var, expr, modules="mpmath")
            rhs = (lambda Mf: lambda x, y: [y[1], y[0] / Mf(x), y[3], y[2] / Mf(x)])(Mf)
            sol = mp.odefun(rhs, mp.mpf(a), state, tol=tol)
            state = sol(mp.mpf(b))
            pieces.append((mp.mpf(a), mp.mpf(b), sol, Mf))
        y1, d1, y2, d2 = state
        scale = max(abs(y1), abs(d1) * mp.mpf(blade.length), abs(y2) / mp.mpf(blade.length), abs(d2), 1)
        if abs(d1) * mp.mpf(blade.length) <= scale * mp.mpf(10) ** (-(dps + 5)):
            raise SingularBlade(f"y1'(λ) = {mp.nstr(d1, 5)}: the problem (9)–(10) is singular "
                                "(buckling value of the blade)")
        Av = (d2 - 1) / d1        # v'(λ) = Av·y1'(λ) − y2'(λ) = −1
        Aw = 1 / d1               # w'(λ) = Aw·y1'(λ) = 1
    return BladeSolution(blade, dps, wdps, tuple(pieces), Av, Aw)


# ---------------------------------------------------------------- closed forms (constant M)
@functools.lru_cache(maxsize=8)
def closed_forms(M: sp.Expr, lam: sp.Expr, s: sp.Symbol = S) -> dict:
    """v, w, φ1, φ2 and their end values for constant M, solved by SymPy dsolve from (9)–(10).

    M, lam may be symbols (their sign assumptions pick exponentials or
    trigonometric functions) or numbers.
    """
    f = sp.Function("f")
    ode = M * f(s).diff(s, 2) - f(s)
    d = lambda at: f(s).diff(s).subs(s, at)
    v = sp.dsolve(ode, f(s), ics={d(0): -1, d(lam): -1}).rhs
    w = sp.dsolve(ode, f(s), ics={d(0): 0, d(lam): 1}).rhs
    out = {"v": v, "w": w, "phi1": 1 + sp.diff(v, s), "phi2": sp.diff(w, s),
           "v0": v.subs(s, 0), "vl": v.subs(s, lam), "w0": w.subs(s, 0), "wl": w.subs(s, lam)}
    out["beta1"] = lam + out["vl"] - out["v0"]
    out["beta2"] = out["wl"] - out["w0"]
    return types.MappingProxyType(out)


def blade_closed_forms(blade: Blade):
    """The SymPy closed forms of (9)–(10) for a blade of constant M (None when M varies)."""
    if not blade.constant:
        return None
    return closed_forms(blade.M, blade.length, blade.var)
