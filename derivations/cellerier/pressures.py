"""Cellérier p. 4–5: the pressures P, Q on the knife edge, the forces F, F' and their maxima."""
from __future__ import annotations

from functools import lru_cache

import mpmath as mp
import sympy as sp

from pendsym import truth, verify
from pendsym.result import Evidence, KernelArg, KernelSpec, Reading, Spec
from .equation import MEMOIR, X1, Y1, _symbolize, pressures_exact, src, th, t
from .symbols import F, Fp, P, Q, alpha, g, h, l, m, theta, thetad, thetadd, x1dd, y1dd

MGH_L = m * g * h / l


def reduced(which: int) -> sp.Expr:
    """P or Q with the pivot's accelerations neglected (x1, y1 of the order of the disturbance, p. 4)."""
    return sp.expand(pressures_exact()[which].subs({x1dd: 0, y1dd: 0}))


@lru_cache(maxsize=None)
def components() -> tuple[sp.Expr, sp.Expr]:
    """(F, F') solving P = F cos θ − F' sin θ, Q = F sin θ + F' cos θ (the text's decomposition)."""
    sol = sp.solve([sp.Eq(reduced(0), F * sp.cos(theta) - Fp * sp.sin(theta)),
                    sp.Eq(reduced(1), F * sp.sin(theta) + Fp * sp.cos(theta))], [F, Fp], dict=True)[0]
    return sp.simplify(sol[F]), sp.simplify(sol[Fp])


@lru_cache(maxsize=None)
def free_motion() -> dict:
    """θ'' = −(g/l) sin θ and the energy integral θ'² = (2g/l)(cos θ − cos α) (rest at θ = α).

    The energy integral is derived: θ'θ'' = d(θ'²/2)/dt integrated from α to θ.
    """
    s = sp.Symbol("s", real=True)
    acc = -g / l * sp.sin(theta)
    sq = 2 * sp.integrate(acc.subs(theta, s), (s, alpha, theta))
    return {thetadd: acc, thetad**2: sp.simplify(sq)}


def on_free(expr: sp.Expr) -> sp.Expr:
    fm = free_motion()
    return sp.simplify(sp.expand(expr).subs(thetad**2, fm[thetad**2]).subs(thetadd, fm[thetadd]))


def _argmax_on_swing(expr: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """Maximum over 0 ≤ θ ≤ α of expr(θ) (≥ 0 there): critical points and ends, compared at α = 1/2."""
    cands = [sp.S.Zero, alpha] + [c for c in sp.solve(sp.diff(expr, theta), theta)
                                  if c.is_real is not False and c.free_symbols <= {alpha}]
    vals = [(sp.simplify(expr.subs(theta, c)), c) for c in cands]
    test = {alpha: sp.Rational(1, 2), m: 1, g: 1, h: 1, l: 1}
    inside = [(v, c) for v, c in vals if 0 <= float(c.subs(test)) <= 0.5]
    return max(inside, key=lambda vc: float(vc[0].subs(test)))


def F_max_derived(deps) -> sp.Expr:
    """Maximum of F on the free swing (at θ = 0, p. 5)."""
    return sp.simplify(_argmax_on_swing(on_free(deps[f"{MEMOIR}.F"].derived))[0])


def Fp_max_derived(deps) -> sp.Expr:
    """Maximum of F' on the free swing (at θ = α, p. 5)."""
    return sp.simplify(_argmax_on_swing(on_free(deps[f"{MEMOIR}.Fp"].derived))[0])


def leading(expr: sp.Expr) -> sp.Expr:
    """Leading term of expr in α."""
    lam = sp.Symbol("lambda", positive=True)
    ser = sp.series(expr.subs(alpha, lam * alpha), lam, 0, 6).removeO()
    return sp.expand(sp.Poly(ser, lam).terms()[-1][1] * 1)


# ---------------------------------------------------------------- truth: free pendulum integrated
@lru_cache(maxsize=None)
def _free_traj(alpha_val: str, dps: int):
    """θ'' = −sin θ (g = l = 1) from rest at θ = α: trajectory with state [θ, θ']."""
    with mp.workdps(dps):
        return truth.integrate(lambda tt, y: [y[1], -mp.sin(y[0])], [mp.mpf(alpha_val), 0], dps)


def _newton_PQ(tr_, s, hh=1, mm=1):
    """P, Q = −m d²(h cos θ)/dt², −m d²(h sin θ)/dt² by numerical differentiation of the solution."""
    # fixed step: the trajectory is evaluated at its own precision (an automatic step would round away)
    step = mp.mpf("1e-7")
    P_ = -mm * mp.diff(lambda x: hh * mp.cos(tr_(x)[0]), s, 2, h=step)
    Q_ = -mm * mp.diff(lambda x: hh * mp.sin(tr_(x)[0]), s, 2, h=step)
    return P_, Q_


def _F_check(result, level):
    """F (or F') against the projection of Newton's P, Q along O'G' (or across) on the integrated swing."""
    pairs, ppairs = [], []
    with mp.workdps(30):
        traj = _free_traj("0.8", 30)
        f = sp.lambdify((theta, thetad, thetadd, m, h), result.derived, "mpmath")
        fp = (sp.lambdify((theta, thetad, thetadd, m, h), result.printed_value, "mpmath")
              if result.printed is not None else None)
        for s in (mp.mpf("0.5"), mp.mpf("1.9")):
            th_, w_ = traj(s)
            P_, Q_ = _newton_PQ(traj, s)
            along = P_ * mp.cos(th_) + Q_ * mp.sin(th_)
            across = -P_ * mp.sin(th_) + Q_ * mp.cos(th_)
            want = along if result.id.endswith(".F") else across
            pairs.append((f"t={s}", f(th_, w_, -mp.sin(th_), 1, 1), want))
            if fp is not None:
                ppairs.append((f"t={s}", fp(th_, w_, -mp.sin(th_), 1, 1), want))
    ev = verify.value_check(truth_desc="θ'' = −sin θ, α = 0.8 (mpmath odefun); P, Q = −m(h cos θ)'', −m(h sin θ)'' "
                            "by numerical differentiation; F = projection on O'G', F' across", pairs=pairs,
                            tol=mp.mpf("1e-10"), kind="value", params=(("alpha", "0.8"),))
    if not ppairs:
        return ev
    pev = verify.value_check(truth_desc="", pairs=ppairs, tol=mp.mpf("1e-10"))
    return Evidence(**{**ev.__dict__, "printed_agrees": pev.passed,
                       "note": f"printed form: largest difference {pev.max_residual:.3g} from Newton's projection"})


def _max_on_traj(alpha_val: str, fn, dps: int):
    """Max over one swing of fn(θ, θ') on the integrated trajectory (sampled, then refined by findroot)."""
    with mp.workdps(dps):
        traj = _free_traj(alpha_val, dps)
        T = truth.turning_time(traj, mp.pi, width=mp.mpf(1))
        val = lambda s: fn(*traj(s))
        grid = [T * i / 64 for i in range(65)]
        best = max(grid, key=lambda s: abs(val(s)))
        if best in (grid[0], grid[-1]):
            return abs(val(best))
        d = lambda s: mp.diff(lambda x: abs(val(x)), s, h=mp.mpf(10) ** (-dps // 3))
        sm = mp.findroot(d, (best - T / 64, best + T / 64), solver="anderson")
        return abs(val(sm))


F_FN = lambda th_, w_: w_**2                       # F/(mh) on the free swing (g = l = 1)
FP_FN = lambda th_, w_: mp.sin(th_)                 # F'/(mh)
P_FN = lambda th_, w_: w_**2 * mp.cos(th_) - mp.sin(th_) ** 2          # P/(mh), θ'' = −sin θ
Q_FN = lambda th_, w_: w_**2 * mp.sin(th_) + mp.sin(th_) * mp.cos(th_)


def _max_value_check(fn, what):
    def check(result, level):
        f = sp.lambdify(alpha, result.derived.subs({m: 1, g: 1, h: 1, l: 1}), "mpmath")
        with mp.workdps(30):
            pairs = [(f"alpha={a}", f(mp.mpf(a)), _max_on_traj(a, fn, 30)) for a in ("0.3", "1.2")]
        return verify.value_check(truth_desc=f"max over one integrated swing of {what} (θ'' = −sin θ, mpmath odefun; "
                                  "max refined by findroot)", pairs=pairs, tol=mp.mpf("1e-20"), kind="value")
    return check


def _approx_order_check(fn, expected, what):
    def check(result, level):
        f = sp.lambdify(alpha, result.derived.subs({m: 1, g: 1, h: 1, l: 1}), "mpmath")
        return verify.order_check(param="alpha", values=verify.geometric("0.02", "0.2", verify.LEVELS[level]),
                                  truth=lambda a, dps: _max_on_traj(mp.nstr(a, 40), fn, dps),
                                  derived=lambda a: f(a), expected=expected, band=0.3,
                                  truth_desc=f"max over one integrated swing of {what} (mpmath odefun, g = l = m = h = 1)")
    return check


def ratio_derived(deps) -> sp.Expr:
    """Leading term of max|P|/max|Q|: P at θ = 0, Q at θ = α on the free swing (p. 5)."""
    Pf = on_free(reduced(0))
    Qf = on_free(reduced(1))
    return leading(sp.simplify(Pf.subs(theta, 0) / Qf.subs(theta, alpha)))


def _ratio_check(result, level):
    f = sp.lambdify(alpha, result.derived, "mpmath")
    return verify.order_check(
        param="alpha", values=verify.geometric("0.02", "0.2", verify.LEVELS[level]),
        truth=lambda a, dps: _max_on_traj(mp.nstr(a, 40), P_FN, dps) / _max_on_traj(mp.nstr(a, 40), Q_FN, dps),
        derived=lambda a: f(a), expected=3, band=0.3,
        truth_desc="max|P|/max|Q| over one integrated swing, P, Q from the state (θ'' = −sin θ, mpmath odefun)",
        note="the vertical pressure is O(α) times the horizontal one; residual O(α³)")


def specs() -> tuple[Spec, ...]:
    Pm = MEMOIR
    kern = KernelSpec((KernelArg("m", 0.01, 100.0), KernelArg("g", 9.0, 10.0, log=False), KernelArg("h", 0.01, 2.0),
                       KernelArg("l", 0.1, 5.0), KernelArg("alpha", 1e-3, 3.0)), doc="force, N", unit="N")
    return (
        Spec(f"{Pm}.P_reduced", "P with the pivot's motion neglected", src("P = −mh d²·(cos θ)/dt² (p. 4)"), "P",
             lambda d: reduced(0), printed=lambda: -m * h * _symbolize(sp.diff(sp.cos(th), t, 2)),
             check=lambda r, lv: _reduced_check(r, lv, 0)),
        Spec(f"{Pm}.Q_reduced", "Q with the pivot's motion neglected", src("Q = −mh d²·(sin θ)/dt² (p. 4)"), "Q",
             lambda d: reduced(1), printed=lambda: -m * h * _symbolize(sp.diff(sp.sin(th), t, 2)),
             check=lambda r, lv: _reduced_check(r, lv, 1)),
        Spec(f"{Pm}.F", "F, the component of the pressure along O'G' (centrifugal force)",
             src("P = F cos θ − F' sin θ, Q = F sin θ + F' cos θ, en posant F = −mh(dθ/dt)², F' = −mh d²θ/dt² … "
                 "la première est évidemment la force centrifuge (p. 4)"),
             "F", lambda d: components()[0], printed=lambda: -m * h * thetad**2, check=_F_check,
             readings=(Reading("F = −mh(dθ/dt)²", "as printed; a stray '−' (OCR or print) would give the derived "
                               "+mh θ'², the centrifugal force the text names", certain=False),),
             note="With the printed decomposition P = F cos θ − F' sin θ the component along O'G' is +mh θ'²."),
        Spec(f"{Pm}.Fp", "F', the component of the pressure across O'G'", src("F' = −mh d²θ/dt² (p. 4)"), "F'",
             lambda d: components()[1], printed=lambda: -m * h * thetadd, check=_F_check),
        Spec(f"{Pm}.F_max", "Maximum of F over a swing (at θ = 0)",
             src("la première devient maxima pour θ = 0 … ces valeurs maxima étant (mgh/l)·4 sin²(α/2) (p. 5)"),
             r"F_{max}", F_max_derived, deps=(f"{Pm}.F",), printed=lambda: MGH_L * 4 * sp.sin(alpha / 2) ** 2,
             check=_max_value_check(F_FN, "mh θ'²"), kernel=kern,
             note="Derived from the derived F (+mh θ'²); the printed sign of F would give a minimum."),
        Spec(f"{Pm}.Fp_max", "Maximum of F' over a swing (at θ = α)",
             src("la seconde pour θ = α, … (mgh/l) sin α (p. 5)"), r"F'_{max}", Fp_max_derived, deps=(f"{Pm}.Fp",),
             printed=lambda: MGH_L * sp.sin(alpha), check=_max_value_check(FP_FN, "mh|θ''|"), kernel=kern),
        Spec(f"{Pm}.F_max_approx", "F_max ≈ (mgh/l) α²", src("ou sensiblement (mgh/l)α², (mgh/l)α (p. 5)"),
             r"F_{max}", lambda d: leading(d[f"{Pm}.F_max"].derived), deps=(f"{Pm}.F_max",),
             printed=lambda: MGH_L * alpha**2, check=_approx_order_check(F_FN, 4, "mh θ'²")),
        Spec(f"{Pm}.Fp_max_approx", "F'_max ≈ (mgh/l) α", src("ou sensiblement (mgh/l)α², (mgh/l)α (p. 5)"),
             r"F'_{max}", lambda d: leading(d[f"{Pm}.Fp_max"].derived), deps=(f"{Pm}.Fp_max",),
             printed=lambda: MGH_L * alpha, check=_approx_order_check(FP_FN, 3, "mh|θ''|")),
        Spec(f"{Pm}.horizontal_dominates", "max vertical / max horizontal pressure ≈ α (horizontal dominates)",
             src("la seconde est donc beaucoup plus grande, et par suite la pression est plus énergique dans le "
                 "sens horizontal (p. 5)"), r"\max|P|/\max|Q|", ratio_derived,
             printed=lambda: alpha, check=_ratio_check,
             note="Printed: the ratio of the text's approximate maxima (mgh/l)α² : (mgh/l)α."),
    )


def _reduced_check(result, level, which):
    pairs = []
    with mp.workdps(30):
        traj = _free_traj("0.8", 30)
        f = sp.lambdify((theta, thetad, thetadd, m, h), result.derived, "mpmath")
        for s in (mp.mpf("0.5"), mp.mpf("1.9")):
            th_, w_ = traj(s)
            pairs.append((f"t={s}", f(th_, w_, -mp.sin(th_), 1, 1), _newton_PQ(traj, s)[which]))
    return verify.value_check(truth_desc="θ'' = −sin θ, α = 0.8 (mpmath odefun); −m(h cos θ)'', −m(h sin θ)'' by "
                              "numerical differentiation of the solution (step 1e-7)", pairs=pairs, tol=mp.mpf("1e-10"),
                              kind="value")
