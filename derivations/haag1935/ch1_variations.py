"""Haag 1935, chapter I, n°10–15, eqs. (42)–(63): small variations of the period, temperature, g.

Derivations.  (42)–(44) are total differentials of n² = −Kg/z' (34) with K from
(35) or (36) and zz' = −R² (31) (:mod:`.ch1_model`), taken symbol by symbol
(da, dR, dλ, dv0, dvλ, dwλ, dz, dz', dβ1, dK); (49)–(52) solve the two-point
problem satisfied by u = ∂v/∂λ; (54)–(57) are the variation of constants with
the Wronskian w0 (15); (58) substitutes (51), (52), (56), (57) into (44);
(60)–(63) specialise (58).

Independent truth.  Logarithmic derivatives of the principal period
T = 2π/√n² of the directly solved suspension (pendsym.suspension.modes, no v, w)
and derivatives of the shot end values v0, vλ, w0, wλ (pendsym.blade), both by
the 5-point central stencil [8(f(h) − f(−h)) − (f(2h) − f(−2h))]/(12h) (error
O(h⁴)) on blades of length λ(1 + kH) with the same M(s), or of stiffness
M(s)(1 + kHε(s)), k = ±1, ±2, H = 10⁻⁷ (λ) or 10⁻⁸ (ε), solved at 30 digits (42 working digits).
The first profile is recomputed at 45 digits with step 2H: agreement bounds both
the truncation (16 times larger at 2H) and the rounding of the 30-digit value.  Variations of a, R, g at a
fixed blade need no new solve.
"""
from __future__ import annotations

import functools

import mpmath as mp
import sympy as sp

from pendsym import blade as B
from pendsym import suspension as SU
from pendsym import pipeline, verify
from pendsym.result import Evidence, Reading, Source, Spec
from . import ch1_model as CM
from . import profiles as PR
from .symbols import K, R, a, a1, beta1, g, lam, s, v0, vl, w0, wl, z, zp

MEMOIR = "haag1935"
v, w, Mf = CM.v, CM.w, CM.Mf
epsf = sp.Function("epsilon")                   # ε(s) of n°12
Ml = sp.Symbol("M_lambda", positive=True)       # M at s = λ
Q = sp.Symbol("Q", positive=True)               # (45)
G2 = sp.Symbol("G_2", positive=True)            # ∫(Kv + w)²/M ds (79)
Gs = sp.Symbol("G", real=True)                  # coefficient of sensitivity (62)
Pl = sp.Symbol("P_lambda", positive=True)       # P at s = λ (59)
Wmg = sp.Symbol("W/(mg)", positive=True)        # strain energy for θ = 1 radian, over mg (63)
# differentials; ζ = dz'/z', ρ = dR/R, γ = dg/g are written as log-differentials
da, dlam, dv0, dvl, dw0, dwl, dz, dzp, db1, dK, dR = sp.symbols(
    "da dlambda dv_0 dv_lambda dw_0 dw_lambda dz dz' dbeta_1 dK dR", real=True)
zeta = sp.Symbol("dz'/z'", real=True)
rho = sp.Symbol("dR/R", real=True)
gam = sp.Symbol("dg/g", real=True)
epsc = sp.Symbol("epsilon", real=True)          # a constant ε
al, alp, bet = sp.symbols("alpha alpha' beta_t", real=True)   # dilatation of blade, pendulum; thermo-elastic

DIFF = {a: da, R: dR, lam: dlam, v0: dv0, vl: dvl, w0: dw0, wl: dwl, z: dz, zp: dzp, beta1: db1, K: dK}
READ_VW = Reading("ν, ω (for v, w)", "v, w: the OCR renders Haag's v, w as ν, ω")




def rid(eq: int, name: str) -> str:
    return f"{MEMOIR}.eq{eq:03d}.{name}"


def src(para: str, eq: str | None) -> Source:
    return Source(MEMOIR, para, None, eq)


def total_diff(expr: sp.Expr) -> sp.Expr:
    """Σ ∂expr/∂x dx over Haag's variables (g constant)."""
    return sum(sp.diff(expr, x) * dx for x, dx in DIFF.items())


def dlogT_of_n2(n2expr: sp.Expr) -> sp.Expr:
    """dT/T = −½ d(n²)/n² for T = 2π/n."""
    return -total_diff(n2expr) / (2 * n2expr)


def n2_K() -> sp.Expr:
    """n² as −Kg/z': n2_of_focus divided by K_of_zp·(−g/z') must be 1 (checked), so n² = K·(−g/z')."""
    ratio = sp.simplify(CM.n2_of_focus() / (CM.K_of_zp() * (-g / zp)))
    if ratio != 1:
        raise ValueError("(34) does not follow from (28), (31)")
    return -K * g / zp


def zp_of_K() -> sp.Expr:
    """z' from (35): z' = vλ − a − Kβ1."""
    return sp.solve(sp.Eq(K, CM.K_of_zp()), zp)[0]


def z_of_K() -> sp.Expr:
    """z from (36): z = (a + wλ)/K − a + vλ."""
    return sp.solve(sp.Eq(K, CM.K_of_z()), z)[0]


def d_beta1() -> sp.Expr:
    """dβ1 = dλ + dvλ − dv0 from β1 = λ + vλ − v0 (22)."""
    return total_diff(CM.beta1_def())


# ================================================================ n°10: (42)–(45)
def eq42(_deps) -> sp.Expr:
    """dT/T from (34) with dK from (35) (implicit differentiation), z' eliminated by (35)."""
    dKv = total_diff(CM.K_of_zp())
    expr = dlogT_of_n2(n2_K()).subs(dK, dKv).subs(dzp, zp * zeta)
    return sp.factor(sp.cancel(expr.subs(zp, zp_of_K())))


def eq43(_deps) -> sp.Expr:
    """dT/T from (34) with dK from (36) and dz from d(zz') = d(−R²) (31); z eliminated by (36)."""
    prod, _ = CM.vieta()
    dz_sol = sp.solve(sp.Eq(total_diff(z * zp), total_diff(prod)), dz)[0]
    dKv = total_diff(CM.K_of_z())
    expr = dlogT_of_n2(n2_K()).subs(dK, dKv).subs(dz, dz_sol)
    expr = expr.subs({dzp: zp * zeta, dR: R * rho}).subs(zp, -R**2 / z)
    return sp.factor(sp.cancel(expr.subs(z, z_of_K())))


def eq44(deps) -> sp.Expr:
    """Eliminate dz'/z' between (42) and (43); dβ1 by (22)."""
    X = sp.Symbol("X")
    sol = sp.solve([sp.Eq(X, deps[rid(42, "dT")].derived), sp.Eq(X, deps[rid(43, "dT")].derived)], [X, zeta],
                   dict=True)[0]
    return sp.factor(sp.cancel(sol[X].subs(db1, d_beta1())))


def eq45(_deps) -> sp.Expr:
    """a − a1 + K²β1 with a1 = −wλ (41), a + wλ = K(a + z − vλ) (36), Kβ1 = −(a + z' − vλ) (35)."""
    expr = a + wl + K**2 * beta1
    expr = expr.subs(wl, sp.solve(sp.Eq(K, CM.K_of_z()), wl)[0]).subs(beta1, sp.solve(sp.Eq(K, CM.K_of_zp()), beta1)[0])
    return sp.factor(sp.expand(expr))


# ================================================================ n°11: (46)–(52)
SLOPES = {(v, 0): -1, (v, lam): -1, (w, 0): 0, (w, lam): 1}     # v', w' at s = 0 and s = λ (10)


def end_slope_of_u(end_value) -> sp.Expr:
    """(∂u/∂s)_λ for u = ∂y/∂λ, y = v or w (48): y'(λ; λ) is the constant of (10) for every λ, so
    d/dλ y'_λ = (∂y'/∂s + ∂u/∂s)_λ = 0 with ∂y'/∂s = y'' = y/M (9)."""
    up_l = sp.Symbol("u'_lambda")
    return sp.solve(sp.Eq(end_value / Ml + up_l, 0), up_l)[0]


def _u_of_bc(end_value) -> sp.Expr:
    """u = c1 v + c2 w solving (9), with u'_0 = 0 (47) and u'_λ of (48)."""
    c1, c2 = sp.symbols("c_1 c_2")
    eqs = [sp.Eq(c1 * SLOPES[(v, 0)] + c2 * SLOPES[(w, 0)], 0),
           sp.Eq(c1 * SLOPES[(v, lam)] + c2 * SLOPES[(w, lam)], end_slope_of_u(end_value))]
    cs = sp.solve(eqs, [c1, c2], dict=True)[0]
    return cs[c1] * v(s) + cs[c2] * w(s)


def at_end(expr: sp.Expr, where) -> sp.Expr:
    """expr at s = 0 or λ with the slopes of (10), the end values v0 … wλ and M(λ) = Mλ."""
    slopes = {v(s).diff(s): SLOPES[(v, where)], w(s).diff(s): SLOPES[(w, where)]}
    return CM.ends(expr.subs(slopes).subs(s, where)).subs(Mf(lam), Ml)


def eq46(deps):
    """∂u/∂s = ∂v'/∂λ (46), u = ∂v/∂λ: the s-derivative of (49)."""
    return sp.diff(deps[rid(49, "dv_dlam")].derived, s)


def eq47(deps):
    """(46) at s = 0: w'_0 = 0 (10) makes it vanish."""
    return at_end(deps[rid(46, "du_ds")].derived, 0)


def eq48(_deps):
    """(∂u/∂s)_λ from d/dλ v'_λ = 0 (10) and v'' = v/M (9)."""
    return end_slope_of_u(vl)


def eq49(_deps):
    """∂v/∂λ: u with v'_λ = −1 constant, v''_λ = vλ/Mλ."""
    return _u_of_bc(vl)


def eq50(_deps):
    """∂w/∂λ: same with w'_λ = 1, w''_λ = wλ/Mλ."""
    return _u_of_bc(wl)


def _at0(dep):
    def derive(deps):
        return CM.ends(deps[dep].derived.subs(s, 0))
    return derive


def _atl(dep, slope):
    def derive(deps):
        """(∂y/∂s + ∂y/∂λ) at s = λ, ∂y/∂s = y'_λ by (10)."""
        return CM.ends(slope + deps[dep].derived.subs(s, lam))
    return derive


def eq52_identity(deps):
    """d/dλ of (16) w0 − vλ − wλ = 0 with (51), (52), reduced by (16)."""
    expr = deps[rid(51, "dw0")].derived - deps[rid(52, "dvl")].derived - deps[rid(52, "dwl")].derived
    return sp.factor(sp.expand(expr).subs(w0, CM.wronskian_at_lambda()))


# ================================================================ n°12: (53)–(57)
t = sp.Symbol("t", real=True)
xf = sp.Function("x")                      # the increment of v (n°12)


def eq53(_deps):
    """M x'' − x for (9) with M → M(1 + ε), v → v + x, to the first order in ε and x."""
    eta = sp.Symbol("eta")
    full = Mf(s) * (1 + eta * epsf(s)) * (v(s) + eta * xf(s)).diff(s, 2) - (v(s) + eta * xf(s))
    first = sp.diff(full, eta).subs(eta, 0)
    return sp.expand((Mf(s) * xf(s).diff(s, 2) - xf(s)) - first)


def eq55(which):
    def derive(_deps):
        """A (or B) = ∫_0^s A' (B') with A', B' of the variation of constants for (53) (:func:`_AB`)."""
        prime = _AB(v)[0 if which == "A" else 1]
        return sp.Integral(prime.subs(s, t), (t, 0, s))
    return derive


def _homogeneous_part(Al, Bl):
    """C of x = Av + (B + C)w: x'(λ) = A_λ v'_λ + (B_λ + C) w'_λ = 0 (A'v + B'w = 0), x'_0 = 0."""
    C = sp.Symbol("C")
    return sp.solve(sp.Eq(Al * SLOPES[(v, lam)] + (Bl + C) * SLOPES[(w, lam)], 0), C)[0]


def eq54(deps):
    """x = A v + (B + C) w (54) with A, B of (55) and C from x'(λ) = 0."""
    A_, B_ = deps[rid(55, "A")].derived, deps[rid(55, "B")].derived
    Al, Bl = A_.subs(s, lam), B_.subs(s, lam)
    return A_ * v(s) + (B_ + _homogeneous_part(Al, Bl)) * w(s)


def _AB(fn):
    """(A', B') for x'' − x/M = −εy'' (53), x = Av + Bw with A'v + B'w = 0, the Wronskian
    vw' − wv' replaced by its value w0 (15)."""
    Ap, Bp, W = sp.symbols("A' B' W")
    f = -epsf(s) * fn(s).diff(s, 2)
    sol = sp.solve([Ap * v(s) + Bp * w(s), Ap * v(s).diff(s) + Bp * w(s).diff(s) - f], [Ap, Bp], dict=True)[0]
    wr = sp.expand(v(s) * w(s).diff(s) - w(s) * v(s).diff(s))
    out = []
    for x in (Ap, Bp):
        num, den = sp.fraction(sp.together(sol[x]))
        den = sp.expand(den)
        if sp.expand(den - wr) == 0:
            den = w0
        elif sp.expand(den + wr) == 0:
            den = -w0
        else:
            raise ValueError(f"denominator is not the Wronskian: {den}")
        out.append(num / den)
    return tuple(out)


def _x_ends(fn):
    """(x0, xλ) for x = Av + (B + Aλ − Bλ)w (54): A(0) = B(0) = 0, v'(λ) = −1, w'(λ) = 1, w'(0) = 0 (10)."""
    Ap, Bp = _AB(fn)
    Al = sp.Integral(Ap, (s, 0, lam))
    Bl = sp.Integral(Bp, (s, 0, lam))
    C = _homogeneous_part(Al, Bl)
    x0 = C * w0
    xl = Al * vl + (Bl + C) * wl
    return x0, xl


def _merge(expr: sp.Expr) -> sp.Expr:
    """Σ c_i ∫f_i ds → ∫Σ c_i f_i ds (c_i free of s), y'' = y/M (9), w0 = vλ + wλ (16) outside, integrand factored."""
    expr = sp.expand(expr)
    body, rest = sp.S.Zero, sp.S.Zero
    for term in sp.Add.make_args(expr):
        ints = [f for f in sp.Mul.make_args(term) if isinstance(f, sp.Integral)]
        if ints:
            coeff = term / ints[0]
            body += coeff * ints[0].function
        else:
            rest += term
    body = body.subs({v(s).diff(s, 2): v(s) / Mf(s), w(s).diff(s, 2): w(s) / Mf(s)})
    out = sp.factor(sp.expand(body))
    return rest + (sp.Integral(out, (s, 0, lam)) if out != 0 else 0)


def eq56(fn):
    def derive(_deps):
        """d(fn)_0 = x_0 of (54)."""
        return _merge(_x_ends(fn)[0])
    return derive


def eq57(fn):
    def derive(_deps):
        """d(fn)_λ = x_λ of (54) with vλ + wλ = w0 (16)."""
        return _merge(sp.expand(_x_ends(fn)[1]).subs(wl, w0 - vl))
    return derive


def eq57_identity(deps):
    """d(w0 − vλ − wλ) with (56), (57): the integrands cancel."""
    expr = deps[rid(56, "dw0")].derived - deps[rid(57, "dvl")].derived - deps[rid(57, "dwl")].derived
    return _merge(expr)


# ================================================================ n°13–15: (58)–(63)
def eq58(deps):
    """(44) with dv0, dvλ, dw0, dwλ = (51), (52) dλ + (56), (57); w0 = vλ + wλ (16); z by (36) kept symbolic."""
    d = lambda eq, name: deps[rid(eq, name)].derived
    sub = {dv0: d(51, "dv0") * dlam + d(56, "dv0"), dvl: d(52, "dvl") * dlam + d(57, "dvl"),
           dwl: d(52, "dwl") * dlam + d(57, "dwl")}
    expr = d(44, "dT").subs(sub)
    num, den = sp.fraction(sp.factor(sp.together(expr)))
    num = _merge(sp.expand(num).subs(w0, CM.wronskian_at_lambda()))
    return num / den


def eq60(deps):
    """(58) with da = α'a, dR/R = α', dλ = αλ, ε = β + 4α constant: ∫εP = (β + 4α)G2 (79)."""
    expr = deps[rid(58, "dT")].derived.subs({da: alp * a, rho: alp, dlam: al * lam, epsf(s): bet + 4 * al})
    return _integral_to(expr, G2)


def _integral_to(expr, sym):
    """Replace ∫c(Kv + w)²/M ds (c free of s) by c·sym (79)."""
    def rep(I):
        body = I.function
        ratio = sp.factor(body / ((K * v(s) + w(s)) ** 2 / Mf(s)))
        if ratio.has(s):
            raise ValueError(f"integrand is not ∝ (Kv + w)²/M: {body}")
        return ratio * sym
    return expr.replace(lambda e: isinstance(e, sp.Integral), rep)


def eq61(deps):
    """(58) with ε = −dg/g (M = EI/(mg)), da = dR = dλ = 0, plus −½dg/g from the factor g of (34)."""
    expr = deps[rid(58, "dT")].derived.subs({da: 0, rho: 0, dlam: 0, epsf(s): -gam})
    g_part = -sp.diff(n2_K(), g) * g * gam / (2 * n2_K())
    return sp.factor(sp.cancel(_integral_to(expr, G2) + g_part))


def eq62(deps):
    """G = 2(dT/T)/(dg/g) from (61)."""
    return sp.factor(sp.cancel(2 * deps[rid(61, "dT")].derived / gam))


def eq63(deps):
    """G2 = 2W/(mg) for θ = 1: W/(mg) = ½∫Mφ'² with φ' = (Kv + w)/M (66) in the principal oscillation."""
    phi_p = (K * v(s) + w(s)) / Mf(s)
    energy = sp.Integral(sp.factor(Mf(s) * phi_p**2 / 2), (s, 0, lam))
    # ∫(Kv + w)²/M = 2·(W/mg): the integrand of the energy is ½(Kv + w)²/M
    ratio = sp.simplify(energy.function / ((K * v(s) + w(s)) ** 2 / Mf(s)))
    return deps[rid(62, "G")].derived.subs(G2, Wmg / ratio)


# ================================================================ the independent truth
PROFILES = {"quick": ("uniform", "hole"), "full": ("uniform", "hole", "tapered")}
STEPS = (-2, -1, 1, 2)
DPS, CONFIRM_DPS = 30, 45
# step H (relative for λ); the 45-digit confirmation takes 2H, so that agreement bounds both the rounding
# and the O(H⁴) truncation of the 30-digit value (pendsym.blade.Blade rounds a length through a float by
# nsimplify, which loses or garbles most other steps: the λ family keeps H at 45 digits, which
# confirms its rounding only)
STEP = {DPS: sp.Rational(1, 10**8), CONFIRM_DPS: sp.Rational(2, 10**8)}
LAM_STEP = sp.Rational(1, 10**7)
TOL = mp.mpf("1e-25")
TEMP = {"alpha": "1.1e-5", "alpha'": "0.9e-5", "beta_t": "-2.4e-4"}   # steel blade, brass-like rod, per degree
EPS_KINDS = {"lin": lambda L: 1 + s / L, "one": lambda L: sp.Integer(1)}
TRUTH = ("principal period T = 2π/√n² of the directly solved suspension (pendsym.suspension.modes, no v, w) "
         "and shot end values (pendsym.blade), differentiated by the 5-point central stencil on blades "
         "λ(1 + kH) or M(s)(1 + kHε(s)), k = ±1, ±2, H = 1e-7 for λ (relative), 1e-8 for ε, at 30 digits")


def stencil(f, h):
    """[8(f(1) − f(−1)) − (f(2) − f(−2))]/(12h): the derivative to O(h⁴) from f at k = ±1, ±2."""
    return (8 * (f(1) - f(-1)) - (f(2) - f(-2))) / (12 * h)


def _blade(name: str, kind: str, k: int, dps: int) -> B.Blade:
    b = PR.profile(name)
    H = k * (LAM_STEP if kind == "lam" else STEP[dps])
    if kind == "lam":
        return B.Blade(b.length * (1 + H), b.M)
    if kind == "base":
        return b
    return B.Blade(b.length, b.M * (1 + H * EPS_KINDS[kind](b.length)))


@functools.lru_cache(maxsize=128)
def shot(name: str, kind: str = "base", k: int = 0, dps: int = DPS) -> B.BladeSolution:
    return B.solve(_blade(name, kind, k, dps), dps)


@functools.lru_cache(maxsize=128)
def direct(name: str, kind: str = "base", k: int = 0, dps: int = DPS) -> SU.Suspension:
    return SU.solve(_blade(name, kind, k, dps), dps)


def _step(name: str, kind: str, dps: int):
    H = SU.number(LAM_STEP if kind == "lam" else STEP[dps])
    return H * SU.number(PR.profile(name).length) if kind == "lam" else H


def modes_at(sus, av, Rv, gv):
    """(log T, z', z, K, principal mode) of the suspension (K = −n²z'/g (34) read on the truth)."""
    pr, pa = SU.modes(sus, av, Rv, gv)
    return -mp.log(pr.n2) / 2, pr.z, pa.z, -pr.n2 * pr.z / gv, pr


def pend(pname):
    """(a, R, g) of the pendulum, exact to 60 digits."""
    with mp.workdps(60):
        return tuple(mp.mpf(x) for x in PR.PENDULUMS[pname])


@functools.lru_cache(maxsize=256)
def partials(name: str, pname: str, kind: str, dps: int = DPS) -> dict:
    """d/dp of log T, log|z'|, z along kind ∈ a, R, g (fixed blade), lam, lin, one (new blades)."""
    av, Rv, gv = pend(pname)
    with mp.workdps(dps + 12):
        if kind in ("a", "R", "g"):
            sus = direct(name, dps=dps)
            x0 = {"a": av, "R": Rv, "g": gv}[kind]
            h = x0 * mp.mpf("1e-9")
            def f(k, i):
                args = {"a": av, "R": Rv, "g": gv}
                args[kind] = x0 + k * h
                m = modes_at(sus, args["a"], args["R"], args["g"])
                return (m[0], mp.log(-m[1]), m[2])[i]
        else:
            h = _step(name, kind, dps)
            def f(k, i):
                m = modes_at(direct(name, kind, k, dps), av, Rv, gv)
                return (m[0], mp.log(-m[1]), m[2])[i]
        return {key: stencil(lambda k: f(k, i), h) for i, key in enumerate(("logT", "logzp", "z"))}


@functools.lru_cache(maxsize=64)
def blade_partials(name: str, kind: str, dps: int = DPS, at: tuple = ()) -> dict:
    """d/dp of v0, vλ, w0, wλ, β1 and of v(s), w(s) at the fractions ``at`` of λ (fixed s)."""
    with mp.workdps(dps + 12):
        L = SU.number(PR.profile(name).length)
        h = _step(name, kind, dps)
        get = {"v0": lambda sol: sol.v0, "vl": lambda sol: sol.vl, "w0": lambda sol: sol.w0,
               "wl": lambda sol: sol.wl, "beta1": lambda sol: sol.beta1}
        for fr in at:
            get[f"v@{fr}"] = lambda sol, fr=fr: sol.v(L * mp.mpf(fr))
            get[f"w@{fr}"] = lambda sol, fr=fr: sol.w(L * mp.mpf(fr))
            get[f"v'@{fr}"] = lambda sol, fr=fr: sol.state(L * mp.mpf(fr))[1]
        return {key: stencil(lambda k: fn(shot(name, kind, k, dps)), h) for key, fn in get.items()}


def base_values(name: str, pname: str, dps: int = DPS) -> dict:
    """Haag's quantities at the unperturbed point: shot v0 … β1, Mλ and the truth's z, z', K."""
    sol = shot(name, dps=dps)
    av, Rv, gv = pend(pname)
    _, zp_, z_, Kv, pr = modes_at(direct(name, dps=dps), av, Rv, gv)
    L = SU.number(PR.profile(name).length)
    return {"a": av, "R": Rv, "g": gv, "lambda": L, "v_0": sol.v0, "v_lambda": sol.vl, "w_0": sol.w0,
            "w_lambda": sol.wl, "beta_1": sol.beta1, "M_lambda": sol.M_at(L), "K": Kv, "z": z_, "z'": zp_}


ZERO_D = ("da", "dlambda", "dv_0", "dv_lambda", "dw_0", "dw_lambda", "dbeta_1", "dR/R", "dz'/z'", "dg/g")


def direction_values(name: str, pname: str, kind: str, dps: int = DPS) -> dict:
    """The differentials along one direction (per unit of its parameter) and the truth d log T."""
    base = base_values(name, pname, dps)
    d = dict.fromkeys(ZERO_D, mp.mpf(0))
    pt = partials(name, pname, kind, dps)
    d["dz'/z'"] = pt["logzp"]
    d["truth"] = pt["logT"]
    if kind == "a":
        d["da"] = mp.mpf(1)
    elif kind == "R":
        d["dR/R"] = 1 / base["R"]
    elif kind in ("lam", "lin", "one"):
        bp = blade_partials(name, kind, dps)
        d.update({"dv_0": bp["v0"], "dv_lambda": bp["vl"], "dw_0": bp["w0"], "dw_lambda": bp["wl"],
                  "dbeta_1": bp["beta1"]})
        if kind == "lam":
            d["dlambda"] = mp.mpf(1)
    return {**base, **d}


def evaluate(expr: sp.Expr, vals: dict, sol=None, eps=None, at=None) -> mp.mpf:
    """expr at vals (symbol name → mpf); each ∫_0^λ f(v, w, M, ε) ds, or ∫_0^s with s = ``at``, by
    quadrature on the shot ``sol`` (v'' = v/M (9)); v(s), w(s) outside the integrals are the
    shot's at s = ``at``."""
    V_, W_, M_, E_ = sp.symbols("V_ W_ M_ E_")

    def integral(I):
        (var, lo, hi), = I.limits
        body = I.function.subs({v(var).diff(var, 2): v(var) / Mf(var), w(var).diff(var, 2): w(var) / Mf(var)})
        body = body.subs({v(var): V_, w(var): W_, Mf(var): M_, epsf(var): E_})
        syms = sorted(body.free_symbols - {V_, W_, M_, E_, var}, key=lambda x: x.name)
        fb = verify.lambdify_mp(body, (V_, W_, M_, E_, var, *syms))
        others = [vals[x.name] for x in syms]
        ef = eps or (lambda x: 0)
        f = lambda x: (lambda st: fb(st[0], st[2], sol.M_at(x), ef(x), x, *others))(sol.state(x))
        if lo == 0 and hi == lam:
            return sol.integrate(f)
        if lo == 0 and hi == s and at is not None:
            with mp.workdps(sol.wdps):
                return B.integrate_pieces([(pa, min(pb, at), q, Mq) for pa, pb, q, Mq in sol.pieces if pa < at], f)
        raise ValueError(f"evaluate: integral over {I.limits} not supported")
    ints = list(expr.atoms(sp.Integral))
    names = [sp.Symbol(f"_I{i}") for i in range(len(ints))]
    expr = expr.xreplace(dict(zip(ints, names)))
    extra = {n.name: integral(I) for n, I in zip(names, ints)}
    if at is not None:
        st = sol.state(at)
        expr = expr.subs({v(s): sp.Symbol("_V"), w(s): sp.Symbol("_W")})
        extra.update({"_V": st[0], "_W": st[2]})
    allv = {**vals, **extra}
    syms = sorted(expr.free_symbols, key=lambda x: x.name)
    return mp.mpf(verify.lambdify_mp(expr, syms)(*[allv[x.name] for x in syms]))


def _rel_pairs(pairs):
    """(label, formula/scale, truth/scale) so that value_check's tolerance is relative."""
    out = []
    for lab, f, t in pairs:
        sc = max(abs(t), mp.mpf("1e-40"))
        out.append((lab, f / sc, t / sc))
    return out


def _finish(desc, pairs, ppairs, confirm, level, note=""):
    ev = verify.value_check(truth_desc=desc, pairs=_rel_pairs(pairs), tol=TOL,
                            params=(("profiles", ",".join(PROFILES[level])),),
                            note=f"truth confirmed to {confirm:.1f} digits at 45 digits with step 2H (H for λ) (uniform)" + note)
    if ppairs:
        pv = verify.value_check(truth_desc="", pairs=_rel_pairs(ppairs), tol=TOL)
        ev = Evidence(**{**ev.__dict__, "printed_agrees": pv.passed,
                         "note": ev.note + f"; printed form: max relative residual {pv.max_residual:.3g}"})
    if confirm < 28:
        ev = Evidence(**{**ev.__dict__, "passed": False})
    return ev


def _confirm(fn):
    """Digits of agreement of fn(dps) between 30 digits (step H) and 45 digits (step 2H)."""
    lo = fn(DPS)
    with mp.workdps(60):
        hi = fn(CONFIRM_DPS)
    return verify.truth_digits(lo, hi)


def period_check(kinds=("a", "R", "lam")):
    """dT/T of the formula against the truth's d log T along each direction, profiles × pendulums."""
    def check(result, level):
        pairs, ppairs = [], []
        for name in PROFILES[level]:
            for pname in PR.PENDULUMS:
                for kind in kinds:
                    vals = direction_values(name, pname, kind)
                    with mp.workdps(40):
                        lab = f"{name}/{pname}/d{kind}"
                        pairs.append((lab, evaluate(result.derived_value, vals), vals["truth"]))
                        if result.printed is not None:
                            ppairs.append((lab, evaluate(result.printed_value, vals), vals["truth"]))
        conf = _confirm(lambda dps: partials("uniform", "clock", "lam", dps)["logT"])
        return _finish(f"d log T along {', '.join(kinds)}: " + TRUTH, pairs, ppairs, conf, level)
    return check


def combo_values(name, pname, combo, dps=DPS):
    """Differentials and truth of a linear combination {kind: coefficient} of directions (d log T is linear)."""
    out = None
    for kind, c in combo.items():
        dv = direction_values(name, pname, kind, dps)
        if out is None:
            out = {k: (c * x if k in ZERO_D or k == "truth" else x) for k, x in dv.items()}
        else:
            for k in list(ZERO_D) + ["truth"]:
                out[k] += c * dv[k]
    return out


COMBOS = ({"a": 1, "R": mp.mpf("0.5"), "lam": mp.mpf("0.3"), "lin": 1},
          {"lam": 1, "one": mp.mpf("-0.7")})


def eps_fun(name, kind, coeff=1):
    L = SU.number(PR.profile(name).length)
    return (lambda x: coeff * (1 + x / L)) if kind == "lin" else (lambda x: coeff * mp.mpf(1))


def _eps_of_combo(name, combo):
    fs = [eps_fun(name, k, c) for k, c in combo.items() if k in EPS_KINDS]
    return lambda x: sum((f(x) for f in fs), mp.mpf(0))


def check58(result, level):
    pairs, ppairs = [], []
    for name in PROFILES[level]:
        sol = shot(name)
        for pname in PR.PENDULUMS:
            for i, combo in enumerate(COMBOS):
                vals = combo_values(name, pname, combo)
                ef = _eps_of_combo(name, combo)
                with mp.workdps(40):
                    lab = f"{name}/{pname}/combo{i}"
                    pairs.append((lab, evaluate(result.derived_value, vals, sol, ef), vals["truth"]))
                    ppairs.append((lab, evaluate(result.printed_value, vals, sol, ef), vals["truth"]))
    conf = _confirm(lambda dps: partials("uniform", "clock", "lin", dps)["logT"])
    return _finish("d log T along da, dR, dλ, εM combined (" + "; ".join(map(str, COMBOS)) + "): " + TRUTH,
                   pairs, ppairs, conf, level)


def check60(result, level):
    pairs, ppairs = [], []
    T_ = {k: mp.mpf(x) for k, x in TEMP.items()}
    for name in PROFILES[level]:
        sol = shot(name)
        for pname in PR.PENDULUMS:
            av, Rv, _ = pend(pname)
            L = SU.number(PR.profile(name).length)
            combo = {"a": T_["alpha'"] * av, "R": T_["alpha'"] * Rv, "lam": T_["alpha"] * L,
                     "one": T_["beta_t"] + 4 * T_["alpha"]}
            vals = combo_values(name, pname, combo)
            vals.update(T_)
            with mp.workdps(40):
                vals["G_2"] = sol.G(2, vals["K"])
                lab = f"{name}/{pname}"
                pairs.append((lab, evaluate(result.derived_value, vals, sol), vals["truth"]))
                ppairs.append((lab, evaluate(result.printed_value, vals, sol), vals["truth"]))
    conf = _confirm(lambda dps: partials("uniform", "clock", "one", dps)["logT"])
    return _finish(f"d log T per degree, {TEMP}: α'(a∂_a + R∂_R) + αλ∂_λ + (β + 4α)∂_ε of " + TRUTH,
                   pairs, ppairs, conf, level,
                   note="; M(s) kept as a function of s when λ grows (Haag's dλ of n°11), G2 by quadrature")


def g_truth(name, pname, dps=DPS):
    """d log T/d log g: g∂_g at fixed blade minus ∂_ε with ε = 1 (M = EI/(mg) ∝ 1/g)."""
    gv = pend(pname)[2]
    return gv * partials(name, pname, "g", dps)["logT"] - partials(name, pname, "one", dps)["logT"]


def g_check(which):
    def check(result, level):
        pairs, ppairs = [], []
        for name in PROFILES[level]:
            sol = shot(name)
            for pname in PR.PENDULUMS:
                vals = base_values(name, pname)
                truth = g_truth(name, pname)
                with mp.workdps(40):
                    vals["dg/g"] = mp.mpf(1)
                    vals["G_2"] = sol.G(2, vals["K"])
                    if which == "G":
                        truth = 2 * truth
                        pr = modes_at(direct(name), *pend(pname))[4]
                        vals["W/(mg)"] = SU.energy(direct(name), pr.beta, 1)
                        vals["Q"] = vals["K"] * (vals["z"] - vals["z'"])
                    lab = f"{name}/{pname}"
                    pairs.append((lab, evaluate(result.derived_value, vals, sol), truth))
                    if result.printed is not None:
                        ppairs.append((lab, evaluate(result.printed_value, vals, sol), truth))
        conf = _confirm(lambda dps: g_truth("uniform", "clock", dps))
        what = "2 d log T/d log g" if which == "G" else "d log T/d log g"
        extra = "; W = suspension.energy of the principal mode (θ = 1), Q = K(z − z') of the truth" if which == "G" else ""
        return _finish(f"{what}: g∂_g log T at fixed blade − ∂_ε log T (ε = 1, M ∝ 1/g), " + TRUTH,
                       pairs, ppairs, conf, level, note=extra)
    return check


def check45(result, level):
    pairs = []
    for name in PROFILES[level]:
        for pname in PR.PENDULUMS:
            vals = base_values(name, pname)
            with mp.workdps(40):
                pairs.append((f"{name}/{pname}", evaluate(result.derived_value, vals),
                              vals["a"] + vals["w_lambda"] + vals["K"] ** 2 * vals["beta_1"]))
    return verify.value_check(truth_desc="a − a1 + K²β1 with the shot wλ, β1 and K = −n²z'/g of the truth; "
                              "K(z − z') with z, z' the nodes of the two modes of pendsym.suspension",
                              pairs=_rel_pairs(pairs), tol=TOL)


FRACS = ("0.3", "0.8")


def lam_check(key, fn_name=None):
    """∂/∂λ of a shot quantity (fixed s for v(s), w(s)) against the formula with the base shot values."""
    def check(result, level):
        pairs, ppairs = [], []
        for name in PROFILES[level]:
            sol = shot(name)
            bp = blade_partials(name, "lam", DPS, FRACS if fn_name else ())
            vals = base_values(name, "clock")
            L = vals["lambda"]
            for fr in (FRACS if fn_name else ("",)):
                with mp.workdps(40):
                    vv = dict(vals)
                    expr_d, expr_p = result.derived_value, result.printed_value
                    if fn_name:
                        st = sol.state(L * mp.mpf(fr))
                        VS, WS = sp.symbols("V_s W_s")
                        vv.update({"V_s": st[0], "W_s": st[2]})
                        rep = {v(s): VS, w(s): WS}
                        expr_d = expr_d.subs(rep)
                        expr_p = expr_p.subs(rep) if expr_p is not None else None
                        truth = bp[f"{fn_name}@{fr}"]
                    else:
                        truth = bp[key]
                    lab = f"{name} {fr}"
                    pairs.append((lab, evaluate(expr_d, vv), truth))
                    if expr_p is not None:
                        ppairs.append((lab, evaluate(expr_p, vv), truth))
        k0 = f"{fn_name}@{FRACS[0]}" if fn_name else key
        conf = _confirm(lambda dps: blade_partials("uniform", "lam", dps, FRACS if fn_name else ())[k0])
        return _finish("5-point stencil in λ of the shot " + (f"{fn_name}(s), s = 0.3λ, 0.8λ fixed" if fn_name else key)
                       + " on blades λ(1 + kH) with the same M(s) (pendsym.blade, 30 digits)", pairs, ppairs, conf, level)
    return check


def check46(result, level):
    """∂v'/∂λ at s = 0.3λ, 0.8λ (the λ-stencil of the shot v'(s), s fixed) against the derived
    ∂u/∂s with the shot w'(s) and the base end values."""
    pairs = []
    for name in PROFILES[level]:
        sol = shot(name)
        bp = blade_partials(name, "lam", DPS, FRACS)
        vals = base_values(name, "clock")
        for fr in FRACS:
            st = sol.state(vals["lambda"] * mp.mpf(fr))
            WP = sp.Symbol("WP_s")
            with mp.workdps(40):
                pairs.append((f"{name} {fr}", evaluate(result.derived_value.subs(w(s).diff(s), WP),
                                                       {**vals, "WP_s": st[3]}), bp[f"v'@{fr}"]))
    conf = _confirm(lambda dps: blade_partials("uniform", "lam", dps, FRACS)[f"v'@{FRACS[0]}"])
    return _finish("5-point stencil in λ of the shot v'(s), s = 0.3λ, 0.8λ fixed, on blades λ(1 + kH) with "
                   "the same M(s) (pendsym.blade, 30 digits)", pairs, [], conf, level)


def forward_stencil(f, h):
    """[−25f(0) + 48f(1) − 36f(2) + 16f(3) − 3f(4)]/(12h): the derivative to O(h⁴) from one side."""
    return (-25 * f(0) + 48 * f(1) - 36 * f(2) + 16 * f(3) - 3 * f(4)) / (12 * h)


def end_partial(name: str, dps: int = DPS) -> mp.mpf:
    """∂v'/∂λ at s = λ0, the end of the base blade: v'(λ0) on blades λ0(1 + kH), k = 0 … 4 (all
    of them reach s = λ0), by the one-sided stencil."""
    with mp.workdps(dps + 12):
        L = SU.number(PR.profile(name).length)
        return forward_stencil(lambda k: shot(name, "lam", k, dps).state(L)[1], _step(name, "lam", dps))


def check48(result, level):
    pairs, ppairs = [], []
    for name in PROFILES[level]:
        truth = end_partial(name)
        vals = base_values(name, "clock")
        with mp.workdps(40):
            pairs.append((name, evaluate(result.derived_value, vals), truth))
            ppairs.append((name, evaluate(result.printed_value, vals), truth))
    conf = _confirm(lambda dps: end_partial("uniform", dps))
    return _finish("one-sided 5-point stencil in λ of the shot v'(λ0) (s = λ0 fixed) on blades λ0(1 + kH), "
                   "k = 0 … 4 (pendsym.blade, 30 digits)", pairs, ppairs, conf, level)


def check54(result, level):
    """x(s) = ∂v/∂h at s = 0.3λ, 0.8λ: the h-stencil of the shot v(s) on blades M(1 + hε), against
    (54) with A, B of (55) by quadrature on the unperturbed shot."""
    pairs, ppairs = [], []
    for name in PROFILES[level]:
        sol = shot(name)
        vals = base_values(name, "clock")
        for kind in ("lin", "one"):
            if kind == "one" and name == "tapered":
                continue
            bp = blade_partials(name, kind, DPS, FRACS)
            for fr in FRACS:
                s0 = vals["lambda"] * mp.mpf(fr)
                with mp.workdps(40):
                    ef, lab = eps_fun(name, kind), f"{name}/ε={kind} {fr}"
                    pairs.append((lab, evaluate(result.derived_value, vals, sol, ef, at=s0), bp[f"v@{fr}"]))
                    ppairs.append((lab, evaluate(result.printed_value, vals, sol, ef, at=s0), bp[f"v@{fr}"]))
    conf = _confirm(lambda dps: blade_partials("uniform", "lin", dps, FRACS)[f"v@{FRACS[0]}"])
    return _finish("5-point stencil in h of the shot v(s), s = 0.3λ, 0.8λ fixed, on blades M(s)(1 + hε(s)), "
                   "ε = 1 + s/λ and ε = 1 (pendsym.blade); A, B by Gauss–Legendre quadrature on the shot",
                   pairs, ppairs, conf, level)


def eps_check(key):
    """d(key) for M → M(1 + hε), ε = 1 + s/λ and ε = 1, against the integral by quadrature on the shot blade."""
    def check(result, level):
        pairs = []
        for name in PROFILES[level]:
            sol = shot(name)
            for kind in ("lin", "one"):
                if kind == "one" and name == "tapered":
                    continue
                truth = blade_partials(name, kind)[key]
                vals = base_values(name, "clock")
                with mp.workdps(40):
                    pairs.append((f"{name}/ε={kind}", evaluate(result.derived_value, vals, sol, eps_fun(name, kind)), truth))
        conf = _confirm(lambda dps: blade_partials("uniform", "lin", dps)[key])
        return _finish(f"5-point stencil in h of the shot {key} on blades M(s)(1 + hε(s)) (pendsym.blade), "
                       "the integral by Gauss–Legendre quadrature on the unperturbed shot v, w", pairs, [], conf, level)
    return check


def proof_zero(statement):
    def check(result, level):
        return verify.proof(statement=statement, holds=sp.simplify(result.derived) == 0, truth_desc="symbolic proof")
    return check


# ================================================================ the Specs
def _defs():
    """Haag's definitions used by the printed forms: Q (45), a1 = −wλ (41), z by (36), Pλ (59)."""
    return ((Q, a + wl + K**2 * beta1), (a1, -wl), (z, z_of_K()), (Pl, (K * vl + wl) ** 2 / Ml))


INSTANCES = (((v, sp.Lambda(s, 1 + s**2 / 3)), (w, sp.Lambda(s, 2 - s)), (Mf, sp.Lambda(s, 1 + s / 2)),
              (epsf, sp.Lambda(s, s + sp.Rational(1, 3)))),
             ((v, sp.Lambda(s, sp.exp(-s))), (w, sp.Lambda(s, sp.cosh(s))), (Mf, sp.Lambda(s, 2 + s**2)),
              (epsf, sp.Lambda(s, 1 - s / 3))))
P_int = lambda: sp.Integral(epsf(s) * (K * v(s) + w(s)) ** 2 / Mf(s), (s, 0, lam))


def specs() -> tuple[Spec, ...]:
    n10, n11, n12, n13, n14, n15 = "n°10", "n°11", "n°12", "n°13", "n°14", "n°15"
    D = _defs()
    r = rid
    lam_fn = lambda fn: lam_check(None, fn)
    sub51 = Reading("dv0/dλ = −v0 w0/Mλ, dw0/dλ = −w0 w0/Mλ",
                    "printed as shown; (49) at s = 0 gives −vλw0/Mλ and −wλw0/Mλ: the λ subscript of the first "
                    "factor may have been lost by the OCR", certain=False)
    return (
        Spec(r(42, "dT"), "dT/T with dK from (35)", src(n10, "42"), r"\frac{dT}{T}", eq42,
             printed=lambda: (-zeta * (a - vl) / (K * beta1) + (da - dvl + K * db1) / (K * beta1)) / 2,
             check=period_check(),
             note="Printed as 2dT/T = …; dz'/z' and dR/R are log-differentials. The derived form eliminates z' by (35)."),
        Spec(r(43, "dT"), "dT/T with dK from (36) and dz from (31)", src(n10, "43"), r"\frac{dT}{T}", eq43,
             printed=lambda: (zeta * K * (a - vl) / (a - a1)
                              + (-da - dvl + K * (da - dvl) + 2 * K * z * rho) / (a - a1)) / 2,
             defs=D,
             readings=(Reading("−da − dv_λ + K(da − dv_λ)", "transcribed as shown; the derivation gives −da − dw_λ "
                               "for the first pair, and (44), which Haag draws from (43), carries −dw_λ: "
                               "OCR (ω read as v) or misprint", certain=False),),
             check=period_check(),
             note="The derived form eliminates z by (36) (the printed one is compared with z = (a + wλ)/K − a + vλ)."),
        Spec(r(44, "dT"), "dT/T: dz'/z' eliminated", src(n10, "44"), r"\frac{dT}{T}", eq44,
             deps=(r(42, "dT"), r(43, "dT")),
             printed=lambda: (2 * K * z * rho + (2 * K - 1) * da + K**2 * (dlam - dv0) + K * (K - 2) * dvl - dwl) / (2 * Q),
             defs=D, readings=(READ_VW, Reading("dω_λ", "dw_λ")), check=period_check()),
        Spec(r(45, "Q"), "Q = a − a1 + K²β1 = K(z − z')", src(n10, "45"), "Q", eq45, printed=lambda: K * (z - zp),
             check=check45, note="Q is defined by a − a1 + K²β1; the derived form uses (35), (36), (41)."),
        Spec(r(49, "dv_dlam"), "∂v/∂λ", src(n11, "49"), r"\frac{\partial v}{\partial\lambda}", eq49,
             printed=lambda: -vl / Ml * w(s), check=lam_fn("v"),
             note="(46)–(48): u = ∂v/∂λ solves (9) with u'_0 = 0, u'_λ = −vλ/Mλ; M(s) given, λ varies."),
        Spec(r(46, "du_ds"), "∂u/∂s = ∂v'/∂λ, u = ∂v/∂λ", src(n11, "46"), r"\frac{\partial u}{\partial s}", eq46,
             deps=(r(49, "dv_dlam"),), check=check46,
             note="(46) states ∂u/∂s = ∂v'/∂λ; the derived ∂u/∂s (the s-derivative of (49)) is checked against "
                  "the λ-derivative of the shot v'(s), which is (46) itself in numbers."),
        Spec(r(47, "du_ds_0"), "(∂u/∂s)_0 = dv'_0/dλ = 0", src(n11, "47"),
             r"\left(\frac{\partial u}{\partial s}\right)_0", eq47, deps=(r(46, "du_ds"),), printed=lambda: sp.S.Zero,
             check=proof_zero("(46) at s = 0 with w'_0 = 0 (10) is 0: v'_0 = −1 for every λ")),
        Spec(r(48, "du_ds_l"), "(∂u/∂s)_λ = −vλ/Mλ", src(n11, "48"),
             r"\left(\frac{\partial u}{\partial s}\right)_\lambda", eq48, printed=lambda: -vl / Ml, check=check48,
             note="From d/dλ v'_λ = 0 (10) and v'' = v/M (9), as in the memoir."),
        Spec(r(50, "dw_dlam"), "∂w/∂λ", src(n11, "50"), r"\frac{\partial w}{\partial\lambda}", eq50,
             printed=lambda: -wl / Ml * w(s), check=lam_fn("w"), readings=(READ_VW,)),
        Spec(r(51, "dv0"), "dv0/dλ", src(n11, "51"), r"\frac{dv_0}{d\lambda}", _at0(r(49, "dv_dlam")),
             deps=(r(49, "dv_dlam"),), printed=lambda: -v0 * w0 / Ml, readings=(sub51,), check=lam_check("v0")),
        Spec(r(51, "dw0"), "dw0/dλ", src(n11, "51"), r"\frac{dw_0}{d\lambda}", _at0(r(50, "dw_dlam")),
             deps=(r(50, "dw_dlam"),), printed=lambda: -w0 * w0 / Ml, readings=(sub51, READ_VW), check=lam_check("w0")),
        Spec(r(52, "dvl"), "dvλ/dλ", src(n11, "52"), r"\frac{dv_\lambda}{d\lambda}", _atl(r(49, "dv_dlam"), -1),
             deps=(r(49, "dv_dlam"),), printed=lambda: -1 - vl * wl / Ml, check=lam_check("vl")),
        Spec(r(52, "dwl"), "dwλ/dλ", src(n11, "52"), r"\frac{dw_\lambda}{d\lambda}", _atl(r(50, "dw_dlam"), 1),
             deps=(r(50, "dw_dlam"),), printed=lambda: 1 - wl**2 / Ml, check=lam_check("wl")),
        Spec(r(52, "wronskian"), "d/dλ of (16) holds identically", src(n11, None),
             r"\frac{d}{d\lambda}(w_0 - v_\lambda - w_\lambda)", eq52_identity,
             deps=(r(51, "dw0"), r(52, "dvl"), r(52, "dwl")),
             check=proof_zero("dw0/dλ − dvλ/dλ − dwλ/dλ with the derived (51), (52) and w0 = vλ + wλ (16) is 0"),
             note="Holds with the derived dw0/dλ = −wλw0/Mλ; with the printed −w0²/Mλ it would need w0 = wλ."),
        Spec(r(53, "x_ode"), "Mx'' − x = −εMv'' for the increment x of v", src(n12, "53"), "Mx'' - x", eq53,
             printed=lambda: -epsf(s) * Mf(s) * v(s).diff(s, 2), instances=INSTANCES, check=pipeline.through(r(54, "x")),
             note="(9) with M → M(1 + ε), v → v + x to the first order; x'_0 = x'_λ = 0 by (10)."),
        Spec(r(55, "A"), "A = (1/w0)∫_0^s εwv'' ds", src(n12, "55"), "A", eq55("A"),
             printed=lambda: sp.Integral(epsf(t) * w(t) * v(t).diff(t, 2), (t, 0, s)) / w0, instances=INSTANCES,
             readings=(READ_VW,), check=pipeline.through(r(54, "x")),
             note="Variation of constants for (53) with the Wronskian w0 (15)."),
        Spec(r(55, "B"), "B = −(1/w0)∫_0^s εvv'' ds", src(n12, "55"), "B", eq55("B"),
             printed=lambda: -sp.Integral(epsf(t) * v(t) * v(t).diff(t, 2), (t, 0, s)) / w0, instances=INSTANCES,
             readings=(READ_VW,), check=pipeline.through(r(54, "x"))),
        Spec(r(54, "x"), "x = Av + (B + Aλ − Bλ)w", src(n12, "54"), "x", eq54, deps=(r(55, "A"), r(55, "B")),
             printed=lambda: (sp.Integral(epsf(t) * w(t) * v(t).diff(t, 2), (t, 0, s)) / w0 * v(s)
                              + (-sp.Integral(epsf(t) * v(t) * v(t).diff(t, 2), (t, 0, s)) / w0
                                 + sp.Integral(epsf(t) * w(t) * v(t).diff(t, 2), (t, 0, lam)) / w0
                                 + sp.Integral(epsf(t) * v(t) * v(t).diff(t, 2), (t, 0, lam)) / w0) * w(s)),
             instances=INSTANCES, readings=(READ_VW,), check=check54,
             note="A_λ, B_λ are A, B at s = λ; the printed form is (54) with (55) written out."),
        Spec(r(56, "dv0"), "dv0 for M → M(1 + ε)", src(n12, "56"), "dv_0", eq56(v),
             printed=lambda: sp.Integral(epsf(s) / Mf(s) * (v(s) + w(s)) * v(s), (s, 0, lam)),
             instances=INSTANCES, readings=(READ_VW,), check=eps_check("v0"),
             note="(53)–(55) by variation of constants with the Wronskian w0 (15)."),
        Spec(r(56, "dw0"), "dw0 for M → M(1 + ε)", src(n12, "56"), "dw_0", eq56(w),
             printed=lambda: sp.Integral(epsf(s) / Mf(s) * (v(s) + w(s)) * w(s), (s, 0, lam)),
             instances=INSTANCES, readings=(READ_VW,), check=eps_check("w0")),
        Spec(r(57, "dvl"), "dvλ for M → M(1 + ε)", src(n12, "57"), r"dv_\lambda", eq57(v),
             printed=lambda: sp.Integral(epsf(s) / Mf(s) * w(s) * v(s), (s, 0, lam)),
             instances=INSTANCES, readings=(READ_VW,), check=eps_check("vl")),
        Spec(r(57, "dwl"), "dwλ for M → M(1 + ε)", src(n12, "57"), r"dw_\lambda", eq57(w),
             printed=lambda: sp.Integral(epsf(s) / Mf(s) * w(s) ** 2, (s, 0, lam)),
             instances=INSTANCES, readings=(READ_VW,), check=eps_check("wl")),
        Spec(r(57, "wronskian"), "the differential of (16) holds identically", src(n12, None),
             r"dw_0 - dv_\lambda - dw_\lambda", eq57_identity, deps=(r(56, "dw0"), r(57, "dvl"), r(57, "dwl")),
             check=proof_zero("dw0 − dvλ − dwλ with the derived (56), (57): the integrands cancel")),
        Spec(r(59, "P"), "P = (Kv + w)²/M", src(n13, "59"), "P", lambda d: (K * v(s) + w(s)) ** 2 / Mf(s),
             definition=True, readings=(READ_VW,)),
        Spec(r(58, "dT"), "dT/T for da, dR, dλ and M → M(1 + ε)", src(n13, "58"), r"\frac{dT}{T}", eq58,
             deps=(r(44, "dT"), r(51, "dv0"), r(52, "dvl"), r(52, "dwl"), r(56, "dv0"), r(57, "dvl"), r(57, "dwl")),
             printed=lambda: (2 * K * z * rho + (2 * K - 1) * (da + dlam) + Pl * dlam - P_int()) / (2 * Q),
             defs=D, instances=INSTANCES, check=check58,
             note="Derived with the derived (51) (−vλw0/Mλ); the printed (51) would not give (58)."),
        Spec(r(60, "dT"), "dT/T per degree of temperature", src(n14, "60"), r"\frac{dT}{T}", eq60, deps=(r(58, "dT"),),
             printed=lambda: (2 * K * z * alp + (2 * K - 1) * (alp * a + al * lam) + al * lam * Pl
                              - (bet + 4 * al) * G2) / (2 * Q),
             defs=D, check=check60,
             readings=(Reading("β (thermo-elastic coefficient)", "β_t, not the ordinate β of A"),),
             note="da/a = dR/R = α', dλ/λ = α, ε = β + 4α constant (dE/E = β, dI/I = 4α); G2 of (79)."),
        Spec(r(61, "dT"), "dT/T for a variation of g", src(n15, "61"), r"\frac{dT}{T}", eq61, deps=(r(58, "dT"),),
             printed=lambda: gam * Gs / 2, defs=D + ((Gs, -1 + G2 / (a + wl + K**2 * beta1)),), check=g_check("T"),
             note="ε = −dg/g (M = EI/(mg)) and −½dg/g from the factor g of (34)."),
        Spec(r(62, "G"), "coefficient of sensitivity G", src(n15, "62"), "G", eq62, deps=(r(61, "dT"),),
             printed=lambda: -1 + G2 / Q, defs=D, check=g_check("G")),
        Spec(r(63, "G"), "G = −1 + 2W/(mgQ)", src(n15, "63"), "G", eq63, deps=(r(62, "G"),),
             printed=lambda: -1 + 2 * Wmg / Q, defs=D, check=g_check("G"),
             note="W/(mg) = ½∫Mφ'² ds with φ' = (Kv + w)/M (66), θ = 1; checked with pendsym.suspension.energy "
                  "of the principal mode, not with G2."),
    )
