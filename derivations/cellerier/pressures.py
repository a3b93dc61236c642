"""Cellérier, the pressures P, Q on the knife edge, the forces F, F' and their maxima (from
« Ces valeurs des pressions P et Q ne sont point très-petites … » to « la seconde est donc beaucoup
plus grande … »)."""
from __future__ import annotations

from functools import lru_cache

import mpmath as mp
import sympy as sp

from pendsym import checks, verify
from pendsym.result import KernelArg, KernelSpec, Reading, Spec
from pendsym.truth import turning_time
from . import truth
from .common import DPS, Geometric, printed, rid, src
from .equation import pressures_exact, symbolize, theta_t
from .symbols import F, Fp, alpha, g, h, l, m, t, theta, thetad, thetadd, x1dd, y1dd

MGH_L = m * g * h / l


# ----------------------------------------------------------------- derivation
def reduced(which: int) -> sp.Expr:
    """P (0) or Q (1) with the pivot's accelerations neglected (x1, y1 of the order of the disturbance)."""
    return sp.expand(pressures_exact()[which].subs({x1dd: 0, y1dd: 0}))


@lru_cache(maxsize=None)
def components() -> tuple[sp.Expr, sp.Expr]:
    """(F, F') solving P = F cos θ − F' sin θ, Q = F sin θ + F' cos θ (the text's decomposition)."""
    solution = sp.solve([sp.Eq(reduced(0), F * sp.cos(theta) - Fp * sp.sin(theta)),
                         sp.Eq(reduced(1), F * sp.sin(theta) + Fp * sp.cos(theta))], [F, Fp], dict=True)[0]
    return sp.simplify(solution[F]), sp.simplify(solution[Fp])


@lru_cache(maxsize=None)
def free_motion() -> dict:
    """θ'' = −(g/l) sin θ and the energy integral θ'² = (2g/l)(cos θ − cos α) (rest at θ = α).

    The energy integral is derived: θ'θ'' = d(θ'²/2)/dt integrated from α to θ.
    """
    s = sp.Symbol("s", real=True)
    acceleration = -g / l * sp.sin(theta)
    square = 2 * sp.integrate(acceleration.subs(theta, s), (s, alpha, theta))
    return {thetadd: acceleration, thetad**2: sp.simplify(square)}


def on_free(expr: sp.Expr) -> sp.Expr:
    """expr along the free swing: θ'' and θ'² replaced by the free motion's."""
    fm = free_motion()
    return sp.simplify(sp.expand(expr).subs(thetad**2, fm[thetad**2]).subs(thetadd, fm[thetadd]))


def argmax_on_swing(expr: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """Maximum over 0 ≤ θ ≤ α of expr(θ) (≥ 0 there): critical points and ends, compared at α = 1/2."""
    candidates = [sp.S.Zero, alpha] + [c for c in sp.solve(sp.diff(expr, theta), theta)
                                       if c.is_real is not False and c.free_symbols <= {alpha}]
    values = [(sp.simplify(expr.subs(theta, c)), c) for c in candidates]
    test = {alpha: sp.Rational(1, 2), m: 1, g: 1, h: 1, l: 1}
    inside = [(v, c) for v, c in values if 0 <= float(c.subs(test)) <= 0.5]
    return max(inside, key=lambda vc: float(vc[0].subs(test)))


def F_max_derived(deps) -> sp.Expr:
    """Maximum of F on the free swing (at θ = 0)."""
    return sp.simplify(argmax_on_swing(on_free(deps[rid("F")].derived))[0])


def Fp_max_derived(deps) -> sp.Expr:
    """Maximum of F' on the free swing (at θ = α)."""
    return sp.simplify(argmax_on_swing(on_free(deps[rid("Fp")].derived))[0])


def leading(expr: sp.Expr) -> sp.Expr:
    """Leading term of expr in α."""
    lam = sp.Symbol("lambda", positive=True)
    ser = sp.series(expr.subs(alpha, lam * alpha), lam, 0, 6).removeO()
    return sp.expand(sp.Poly(ser, lam).terms()[-1][1] * 1)


def ratio_derived(deps) -> sp.Expr:
    """Leading term of max|P|/max|Q|: P at θ = 0, Q at θ = α on the free swing."""
    return leading(sp.simplify(on_free(reduced(0)).subs(theta, 0) / on_free(reduced(1)).subs(theta, alpha)))


# ----------------------------------------------------------------- printed
def P_reduced_printed() -> sp.Expr:
    return -m * h * symbolize(sp.diff(sp.cos(theta_t), t, 2))


def Q_reduced_printed() -> sp.Expr:
    return -m * h * symbolize(sp.diff(sp.sin(theta_t), t, 2))


PRINTED = {
    "F": -m * h * thetad**2,
    "Fp": -m * h * thetadd,
    "F_max": MGH_L * 4 * sp.sin(alpha / 2) ** 2,
    "Fp_max": MGH_L * sp.sin(alpha),
    "F_max_approx": MGH_L * alpha**2,
    "Fp_max_approx": MGH_L * alpha,
    "horizontal_dominates": alpha,     # the ratio of the text's approximate maxima (mgh/l)α² : (mgh/l)α
}


# ----------------------------------------------------------------- checks: the free swing integrated, Newton's P, Q
FREE_TEXT = "θ'' = −sin θ, α = 0.8 (mpmath odefun)"


def reduced_check(which: int):
    """P or Q against −m(h cos θ)'', −m(h sin θ)'' of the integrated swing."""
    def check(result, level):
        pairs = []
        with mp.workdps(DPS):
            traj = truth.free_swing_trajectory("0.8", DPS)
            f = sp.lambdify((theta, thetad, thetadd, m, h), result.derived, "mpmath")
            for s in (mp.mpf("0.5"), mp.mpf("1.9")):
                th, w = traj(s)
                pairs.append((f"t={s}", f(th, w, -mp.sin(th), 1, 1), truth.newton_pressures(traj, s)[which]))
        return verify.value_check(truth_desc=FREE_TEXT + "; −m(h cos θ)'', −m(h sin θ)'' by numerical "
                                  "differentiation of the solution (step 1e-7)", pairs=pairs, tol=mp.mpf("1e-10"),
                                  kind="value")
    return check


def projection_points(along: bool):
    """Points of the F (along O'G') or F' (across) check: Newton's P, Q projected, on the integrated swing."""
    def points(level, dps):
        with mp.workdps(DPS):
            traj = truth.free_swing_trajectory("0.8", DPS)
            for s in (mp.mpf("0.5"), mp.mpf("1.9")):
                th, w = traj(s)
                P, Q = truth.newton_pressures(traj, s)
                projection = P * mp.cos(th) + Q * mp.sin(th) if along else -P * mp.sin(th) + Q * mp.cos(th)
                yield checks.Point(f"t={s}", {"theta": th, "thetadot": w, "thetaddot": -mp.sin(th), "m": 1, "h": 1},
                                   projection)
    return points


def projection_check(along: bool) -> checks.Values:
    return checks.Values(
        truth=FREE_TEXT + "; P, Q = −m(h cos θ)'', −m(h sin θ)'' by numerical differentiation; "
                          "F = projection on O'G', F' across",
        points=projection_points(along), tol=mp.mpf("1e-10"), params=(("alpha", "0.8"),), work_dps=DPS)


def max_on_trajectory(alpha_val: str, fn, dps: int):
    """Max over one swing of fn(θ, θ') on the integrated trajectory (sampled, then refined by findroot)."""
    with mp.workdps(dps):
        traj = truth.free_swing_trajectory(alpha_val, dps)
        T = turning_time(traj, mp.pi, width=mp.mpf(1))
        value = lambda s: fn(*traj(s))
        grid = [T * i / 64 for i in range(65)]
        best = max(grid, key=lambda s: abs(value(s)))
        if best in (grid[0], grid[-1]):
            return abs(value(best))
        slope = lambda s: mp.diff(lambda x: abs(value(x)), s, h=mp.mpf(10) ** (-dps // 3))
        top = mp.findroot(slope, (best - T / 64, best + T / 64), solver="anderson")
        return abs(value(top))


def F_on_swing(th, w):           # F/(mh) on the free swing (g = l = 1)
    return w**2


def Fp_on_swing(th, w):          # F'/(mh)
    return mp.sin(th)


def P_on_swing(th, w):           # P/(mh), θ'' = −sin θ
    return w**2 * mp.cos(th) - mp.sin(th) ** 2


def Q_on_swing(th, w):           # Q/(mh)
    return w**2 * mp.sin(th) + mp.sin(th) * mp.cos(th)


def max_value_check(fn, what: str):
    def check(result, level):
        f = sp.lambdify(alpha, result.derived.subs({m: 1, g: 1, h: 1, l: 1}), "mpmath")
        with mp.workdps(DPS):
            pairs = [(f"alpha={a}", f(mp.mpf(a)), max_on_trajectory(a, fn, DPS)) for a in ("0.3", "1.2")]
        return verify.value_check(truth_desc=f"max over one integrated swing of {what} (θ'' = −sin θ, mpmath odefun; "
                                  "max refined by findroot)", pairs=pairs, tol=mp.mpf("1e-20"), kind="value")
    return check


AMPLITUDES = Geometric("0.02", "0.2")


def approx_order_check(fn, expected: int, what: str):
    def check(result, level):
        f = sp.lambdify(alpha, result.derived.subs({m: 1, g: 1, h: 1, l: 1}), "mpmath")
        return verify.order_check(param="alpha", values=AMPLITUDES(level),
                                  truth=lambda a, dps: max_on_trajectory(mp.nstr(a, 40), fn, dps),
                                  derived=lambda a: f(a), expected=expected, band=0.3,
                                  truth_desc=f"max over one integrated swing of {what} (mpmath odefun, g = l = m = h = 1)")
    return check


def ratio_check(result, level):
    f = sp.lambdify(alpha, result.derived, "mpmath")

    def ratio_of_maxima(a, dps):
        return max_on_trajectory(mp.nstr(a, 40), P_on_swing, dps) / max_on_trajectory(mp.nstr(a, 40), Q_on_swing, dps)
    return verify.order_check(
        param="alpha", values=AMPLITUDES(level), truth=ratio_of_maxima, derived=lambda a: f(a), expected=3, band=0.3,
        truth_desc="max|P|/max|Q| over one integrated swing, P, Q from the state (θ'' = −sin θ, mpmath odefun)",
        note="the vertical pressure is O(α) times the horizontal one; residual O(α³)")


# ----------------------------------------------------------------- kernel declarations
FORCE_KERNEL = KernelSpec((KernelArg("m", 0.01, 100.0), KernelArg("g", 9.0, 10.0, log=False),
                           KernelArg("h", 0.01, 2.0), KernelArg("l", 0.1, 5.0), KernelArg("alpha", 1e-3, 3.0)),
                          doc="force, N", unit="N")


# ----------------------------------------------------------------- the Result table
def specs() -> tuple[Spec, ...]:
    return (
        Spec(rid("P_reduced"), "P with the pivot's motion neglected", src("pivot_neglected", "P = −mh d²·(cos θ)/dt²"),
             "P", lambda d: reduced(0), printed=P_reduced_printed, check=reduced_check(0)),
        Spec(rid("Q_reduced"), "Q with the pivot's motion neglected", src("pivot_neglected", "Q = −mh d²·(sin θ)/dt²"),
             "Q", lambda d: reduced(1), printed=Q_reduced_printed, check=reduced_check(1)),
        Spec(rid("F"), "F, the component of the pressure along O'G' (centrifugal force)",
             src("pivot_neglected", "P = F cos θ − F' sin θ, Q = F sin θ + F' cos θ, en posant F = −mh(dθ/dt)², "
                 "F' = −mh d²θ/dt² … la première est évidemment la force centrifuge"),
             "F", lambda d: components()[0], printed=printed(PRINTED["F"]), check=projection_check(along=True),
             readings=(Reading("F = −mh(dθ/dt)²", "as printed; a stray '−' (OCR or print) would give the derived "
                               "+mh θ'², the centrifugal force the text names", certain=False),),
             note="With the printed decomposition P = F cos θ − F' sin θ the component along O'G' is +mh θ'²."),
        Spec(rid("Fp"), "F', the component of the pressure across O'G'", src("pivot_neglected", "F' = −mh d²θ/dt²"),
             "F'", lambda d: components()[1], printed=printed(PRINTED["Fp"]), check=projection_check(along=False)),
        Spec(rid("F_max"), "Maximum of F over a swing (at θ = 0)",
             src("two_forces", "la première devient maxima pour θ = 0 … ces valeurs maxima étant (mgh/l)·4 sin²(α/2)"),
             r"F_{max}", F_max_derived, deps=(rid("F"),), printed=printed(PRINTED["F_max"]),
             check=max_value_check(F_on_swing, "mh θ'²"), kernel=FORCE_KERNEL,
             note="Derived from the derived F (+mh θ'²); the printed sign of F would give a minimum."),
        Spec(rid("Fp_max"), "Maximum of F' over a swing (at θ = α)",
             src("two_forces", "la seconde pour θ = α, … (mgh/l) sin α"), r"F'_{max}", Fp_max_derived,
             deps=(rid("Fp"),), printed=printed(PRINTED["Fp_max"]), check=max_value_check(Fp_on_swing, "mh|θ''|"),
             kernel=FORCE_KERNEL),
        Spec(rid("F_max_approx"), "F_max ≈ (mgh/l) α²", src("two_forces", "ou sensiblement (mgh/l)α², (mgh/l)α"),
             r"F_{max}", lambda d: leading(d[rid("F_max")].derived), deps=(rid("F_max"),),
             printed=printed(PRINTED["F_max_approx"]), check=approx_order_check(F_on_swing, 4, "mh θ'²")),
        Spec(rid("Fp_max_approx"), "F'_max ≈ (mgh/l) α", src("two_forces", "ou sensiblement (mgh/l)α², (mgh/l)α"),
             r"F'_{max}", lambda d: leading(d[rid("Fp_max")].derived), deps=(rid("Fp_max"),),
             printed=printed(PRINTED["Fp_max_approx"]), check=approx_order_check(Fp_on_swing, 3, "mh|θ''|")),
        Spec(rid("horizontal_dominates"), "max vertical / max horizontal pressure ≈ α (horizontal dominates)",
             src("horizontal", "la seconde est donc beaucoup plus grande, et par suite la pression est plus "
                 "énergique dans le sens horizontal"), r"\max|P|/\max|Q|", ratio_derived,
             printed=printed(PRINTED["horizontal_dominates"]), check=ratio_check,
             note="Printed: the ratio of the text's approximate maxima (mgh/l)α² : (mgh/l)α."),
    )
