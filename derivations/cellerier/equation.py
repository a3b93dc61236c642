"""Cellérier pp. 1–3: the equation of the pendulum on a moving knife edge, from rigid-body equations.

The body is described in axes O'X', O'Y' moving with the knife edge: an element
dm has body coordinates (ξ, η), rotated by θ.  The sums over the body need only
its moments Σdm = m, Σξ dm = m h, Ση dm = 0 (G on the axis ξ) and
Σ(ξ² + η²) dm = C; the derivation checks that nothing else appears.
The three equations of the text are Σx''dm = ΣX, Σy''dm = ΣY,
Σ(x y'' − y x'')dm = ΣR, with the forces of the text: the support's action
−(P + mg), −Q at O' and the weight mg at G'.
"""
from __future__ import annotations

from functools import lru_cache

import mpmath as mp
import sympy as sp

from pendsym import verify
from pendsym import pipeline
from pendsym.result import Reading, Source, Spec
from .symbols import C, P, Q, g, h, l, m, mu_p, theta, thetad, thetadd, x1dd, x1s, y1dd, y1s

MEMOIR = "cellerier"
t = sp.Symbol("t", real=True)
th, X1, Y1 = sp.Function("theta")(t), sp.Function("x_1")(t), sp.Function("y_1")(t)
xi, eta = sp.symbols("xi eta", real=True)
Ixx, Iyy, Ixy = sp.symbols("I_xixi I_etaeta I_xieta", real=True)


def src(quote: str) -> Source:
    return Source(MEMOIR, "Mouvement simultané d'un pendule et de ses supports", quote=quote)


def _symbolize(expr: sp.Expr) -> sp.Expr:
    """θ(t), its derivatives and those of x1, y1 → plain symbols (θ, θ', θ'', x1'', y1'')."""
    rep = {sp.diff(th, t, 2): thetadd, sp.diff(th, t): thetad, sp.diff(X1, t, 2): x1dd, sp.diff(Y1, t, 2): y1dd}
    return expr.subs(rep).subs({th: theta, X1: x1s, Y1: y1s})


def _body_sum(expr: sp.Expr) -> sp.Expr:
    """Σ expr dm for expr polynomial (degree ≤ 2) in the body coordinates ξ, η."""
    poly = sp.Poly(sp.expand(expr), xi, eta)
    moments = {(0, 0): m, (1, 0): m * h, (0, 1): 0, (2, 0): Ixx, (0, 2): Iyy, (1, 1): Ixy}
    out = 0
    for mon, coeff in poly.terms():
        if mon not in moments:
            raise ValueError(f"moment {mon} not available")
        out += coeff * moments[mon]
    # only the polar moment about the edge may remain: Σ(ξ² + η²)dm = C
    out = sp.expand(out.subs(Iyy, C - Ixx))
    if out.has(Ixx) or out.has(Ixy):
        raise ValueError("the sum depends on more than the polar moment")
    return out


@lru_cache(maxsize=None)
def rigid_body() -> dict[str, sp.Expr]:
    """The three equations of motion of the text, summed over the body (symbols for derivatives)."""
    xr = xi * sp.cos(th) - eta * sp.sin(th)             # x' (from O', OX vertical downwards)
    yr = xi * sp.sin(th) + eta * sp.cos(th)
    x, y = X1 + xr, Y1 + yr
    ddx, ddy = sp.diff(x, t, 2), sp.diff(y, t, 2)
    # forces of the text: −(P + mg), −Q at O' = (x1, y1); mg at G' = (x1 + h cos θ, y1 + h sin θ)
    forces = [((X1, Y1), (-(P + m * g), -Q)), ((X1 + h * sp.cos(th), Y1 + h * sp.sin(th)), (m * g, 0))]
    sum_X = sum(F[0] for _, F in forces)
    sum_Y = sum(F[1] for _, F in forces)
    sum_R = sum(pt[0] * F[1] - pt[1] * F[0] for pt, F in forces)
    lhs1, lhs2 = _body_sum(ddx), _body_sum(ddy)
    lhs3 = _body_sum(x * ddy - y * ddx)
    return {k: sp.expand(_symbolize(v)) for k, v in
            {"X": lhs1 - sum_X, "Y": lhs2 - sum_Y, "R": lhs3 - sum_R}.items()}


@lru_cache(maxsize=None)
def pressures_exact() -> tuple[sp.Expr, sp.Expr]:
    """(P, Q) from the first two equations: P = −m(x1 + h cos θ)'', Q = −m(y1 + h sin θ)'' (p. 3)."""
    eq = rigid_body()
    return sp.solve(eq["X"], P)[0], sp.solve(eq["Y"], Q)[0]


@lru_cache(maxsize=None)
def theta_ddot() -> sp.Expr:
    """θ'' from the moment equation with P, Q of the first two (the x1, y1 terms cancel)."""
    eq = rigid_body()
    Pv, Qv = pressures_exact()
    moment = sp.expand(eq["R"].subs({P: Pv, Q: Qv}))
    if moment.has(x1s) or moment.has(y1s):
        raise ValueError("the pivot position does not cancel")
    return sp.simplify(sp.solve(moment, thetadd)[0])


def mu_prime_derived(_deps) -> sp.Expr:
    """μ' = C θ'' + m g h sin θ: the part of the moment due to the pivot's motion (p. 2)."""
    return sp.expand(C * theta_ddot() + m * g * h * sp.sin(theta))


def mu_prime_printed() -> sp.Expr:
    return m * h * (sp.sin(theta) * x1dd - sp.cos(theta) * y1dd)


def equation_derived(deps) -> sp.Expr:
    """C θ'' = −m g h sin θ + μ', the right side as derived, μ' kept as the symbol (p. 3)."""
    mu = deps[f"{MEMOIR}.mu_prime"].derived
    rhs = sp.expand(C * theta_ddot())
    return sp.expand(rhs - mu) + mu_p


def equation_printed() -> sp.Expr:
    return -m * g * h * sp.sin(theta) + mu_p


def equation_l_derived(deps) -> sp.Expr:
    """θ'' = −(g/l) sin θ + μ'/(m h l): the C-form divided by C, with C = m h l (p. 3)."""
    return sp.expand(deps[f"{MEMOIR}.equation"].derived / C).subs(C, m * h * l)


def equation_l_printed() -> sp.Expr:
    return -g / l * sp.sin(theta) + mu_p / (m * h * l)


MU_DEF = ((mu_p, mu_prime_printed()),)


# ---------------------------------------------------------------- checks (discrete bodies)
BODY = ((mp.mpf("0.7"), mp.mpf("0.9"), mp.mpf("0.1")), (mp.mpf("0.5"), mp.mpf("0.2"), mp.mpf("-0.35")),
        (mp.mpf("1.1"), mp.mpf("-0.15"), mp.mpf("0.22")))        # (mass, ξ, η) of three point masses
TH_T = lambda s: mp.mpf("0.3") * mp.sin(mp.mpf("1.1") * s) + mp.mpf("0.2")
X1_T = lambda s: mp.mpf("0.01") * mp.cos(2 * s)
Y1_T = lambda s: mp.mpf("0.02") * mp.sin(mp.mpf("1.7") * s) + mp.mpf("0.005") * s**2


def _particles(s):
    out = []
    for mi, a, b in BODY:
        fx = lambda s, a=a, b=b: X1_T(s) + a * mp.cos(TH_T(s)) - b * mp.sin(TH_T(s))
        fy = lambda s, a=a, b=b: Y1_T(s) + a * mp.sin(TH_T(s)) + b * mp.cos(TH_T(s))
        out.append((mi, fx(s), fy(s), mp.diff(fx, s, 2), mp.diff(fy, s, 2)))
    return out


def _body_constants():
    mt = sum(b[0] for b in BODY)
    xg = sum(b[0] * b[1] for b in BODY) / mt
    yg = sum(b[0] * b[2] for b in BODY) / mt
    # align ξ with O'G: the body angle of G is β, θ measured to O'G means θ_G = θ_body + β
    beta = mp.atan2(yg, xg)
    hh = mp.sqrt(xg**2 + yg**2)
    CC = sum(b[0] * (b[1] ** 2 + b[2] ** 2) for b in BODY)
    return mt, hh, CC, beta


def _discrete_check(result, level, what: str):
    """Newton for three point masses, accelerations by mpmath numerical differentiation."""
    pairs = []
    with mp.workdps(30):
        mt, hh, CC, beta = _body_constants()
        gv = mp.mpf("9.8")
        for s in (mp.mpf("0.4"), mp.mpf("1.7")):
            parts = _particles(s)
            Psum = -sum(p[0] * p[3] for p in parts)            # Σ x'' dm = −P
            Qsum = -sum(p[0] * p[4] for p in parts)
            lhs3 = sum(p[0] * (p[1] * p[4] - p[2] * p[3]) for p in parts)
            thG = TH_T(s) + beta                               # angle of O'G with the vertical
            vals = {theta: thG, thetad: mp.diff(TH_T, s), thetadd: mp.diff(TH_T, s, 2),
                    x1dd: mp.diff(X1_T, s, 2), y1dd: mp.diff(Y1_T, s, 2), m: mt, h: hh, C: CC, g: gv,
                    x1s: X1_T(s), y1s: Y1_T(s)}
            ev = lambda e: sp.lambdify(tuple(vals), e, "mpmath")(*vals.values())
            if what == "P":
                pairs.append((f"P t={s}", ev(result.derived), Psum))
            elif what == "Q":
                pairs.append((f"Q t={s}", ev(result.derived), Qsum))
            else:
                # the moment equation ΣR with the weight's moment removed: Σ(xy''−yx'')dm − y1 P + x1 Q
                # equals −mgh sin θ + (μ' − Cθ'' ... ) — compare C θ'' − μ' with the Newton sum
                newton = lhs3 - (Y1_T(s) * Psum - X1_T(s) * Qsum)
                if what == "equation":   # the derived right side, weight removed: μ' part only
                    rhs = result.derived_value + m * g * h * sp.sin(theta)
                    pairs.append((f"t={s}", ev(C * thetadd - rhs), newton))
                else:
                    pairs.append((f"t={s}", ev(C * thetadd - result.derived), newton))
    return verify.value_check(
        truth_desc="three point masses (m_i, ξ_i, η_i) moved rigidly along θ(t), x1(t), y1(t) (test motions); "
                   "Σ m_i(x y'' − y x''), Σ m_i x'', Σ m_i y'' by mpmath numerical differentiation",
        pairs=pairs, tol=mp.mpf("1e-20"), kind="value")


def _mu_check(result, level):
    return _discrete_check(result, level, "mu")


def specs() -> tuple[Spec, ...]:
    P_ = MEMOIR
    q_eq = "Σ[(x − x1) d²y/dt² − (y − y1) d²x/dt²] dm = −mgh sin θ … C d²θ/dt² = −mgh sin θ + μ'"
    return (
        Spec(f"{P_}.P_exact", "Vertical pressure P from the first equation of motion",
             src("P = −m d²·(x1 + h cos θ)/dt²  (p. 3, 'reprenons les deux premières équations')"), "P",
             lambda d: pressures_exact()[0],
             printed=lambda: -m * _symbolize(sp.diff(X1 + h * sp.cos(th), t, 2)),
             check=lambda r, lv: _discrete_check(r, lv, "P"),
             note="Derived from Σ x''dm = ΣX = −P with Σξ dm = mh."),
        Spec(f"{P_}.Q_exact", "Horizontal pressure Q from the second equation of motion",
             src("Q = −m d²·(y1 + h sin θ)/dt²  (p. 3)"), "Q", lambda d: pressures_exact()[1],
             printed=lambda: -m * _symbolize(sp.diff(Y1 + h * sp.sin(th), t, 2)),
             check=lambda r, lv: _discrete_check(r, lv, "Q")),
        Spec(f"{P_}.mu_prime", "μ', the moment due to the motion of the knife edge",
             src("μ' = mh[sin θ d²x1/dt² − cos θ d²y1/dt²]  (p. 2)"), r"\mu'", mu_prime_derived,
             printed=mu_prime_printed, check=_mu_check,
             readings=(Reading("d²x^4/dt², d²y^4/dt²", "d²x1/dt², d²y1/dt²"),),
             note="Derived as Cθ'' + mgh sin θ from the moment equation after eliminating P, Q."),
        Spec(f"{P_}.equation", "C θ'' = −mgh sin θ + μ'", src(q_eq), r"C\theta''", equation_derived,
             deps=(f"{P_}.mu_prime",), printed=equation_printed, defs=MU_DEF,
             check=lambda r, lv: _discrete_check(r, lv, "equation"),
             note="The x1, y1 terms of P, Q cancel in the moment equation (the text's 'multipliant … par y1, −x1')."),
        Spec(f"{P_}.equation_l", "θ'' = −(g/l) sin θ + μ'/(mhl), l = C/(mh)",
             src("En posant l = C/(mh), on pourra l'écrire: d²θ/dt² = −(g/t) sin θ + μ'/(mht)  (p. 3)"),
             r"\theta''", equation_l_derived, deps=(f"{P_}.equation",), printed=equation_l_printed, defs=MU_DEF,
             check=pipeline.through(f"{P_}.equation"),
             readings=(Reading("g/t, μ'/(mht)", "g/l, μ'/(mhl): OCR reads l as t"),)),
    )
