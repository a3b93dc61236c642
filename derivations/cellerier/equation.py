"""Cellérier, the equation of the pendulum on a moving knife edge, from the rigid-body equations
(from « Admettons ensuite que le couteau se déplace … » to « En posant l = C/(mh) … »).

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

from pendsym import checks, verify
from pendsym.result import Reading, Spec
from .common import DPS, read_l_as_t, rid, src
from .symbols import C, P, Q, g, h, l, m, mu_p, t, theta, thetad, thetadd, x1dd, x1s, y1dd, y1s

theta_t, x1_t, y1_t = sp.Function("theta")(t), sp.Function("x_1")(t), sp.Function("y_1")(t)
xi, eta = sp.symbols("xi eta", real=True)
I_xixi, I_etaeta, I_xieta = sp.symbols("I_xixi I_etaeta I_xieta", real=True)


def symbolize(expr: sp.Expr) -> sp.Expr:
    """θ(t), its derivatives and those of x1, y1 → plain symbols (θ, θ', θ'', x1'', y1'')."""
    rep = {sp.diff(theta_t, t, 2): thetadd, sp.diff(theta_t, t): thetad,
           sp.diff(x1_t, t, 2): x1dd, sp.diff(y1_t, t, 2): y1dd}
    return expr.subs(rep).subs({theta_t: theta, x1_t: x1s, y1_t: y1s})


# ----------------------------------------------------------------- derivation
def body_sum(expr: sp.Expr) -> sp.Expr:
    """Σ expr dm for expr polynomial (degree ≤ 2) in the body coordinates ξ, η."""
    poly = sp.Poly(sp.expand(expr), xi, eta)
    moments = {(0, 0): m, (1, 0): m * h, (0, 1): 0, (2, 0): I_xixi, (0, 2): I_etaeta, (1, 1): I_xieta}
    out = 0
    for mon, coeff in poly.terms():
        if mon not in moments:
            raise ValueError(f"moment {mon} not available")
        out += coeff * moments[mon]
    # only the polar moment about the edge may remain: Σ(ξ² + η²)dm = C
    out = sp.expand(out.subs(I_etaeta, C - I_xixi))
    if out.has(I_xixi) or out.has(I_xieta):
        raise ValueError("the sum depends on more than the polar moment")
    return out


@lru_cache(maxsize=None)
def rigid_body() -> dict[str, sp.Expr]:
    """The three equations of motion of the text, summed over the body (symbols for derivatives)."""
    x_rel = xi * sp.cos(theta_t) - eta * sp.sin(theta_t)             # x' (from O', OX vertical downwards)
    y_rel = xi * sp.sin(theta_t) + eta * sp.cos(theta_t)
    x, y = x1_t + x_rel, y1_t + y_rel
    ddx, ddy = sp.diff(x, t, 2), sp.diff(y, t, 2)
    # forces of the text: −(P + mg), −Q at O' = (x1, y1); mg at G' = (x1 + h cos θ, y1 + h sin θ)
    forces = [((x1_t, y1_t), (-(P + m * g), -Q)),
              ((x1_t + h * sp.cos(theta_t), y1_t + h * sp.sin(theta_t)), (m * g, 0))]
    sum_X = sum(F[0] for _, F in forces)
    sum_Y = sum(F[1] for _, F in forces)
    sum_R = sum(at[0] * F[1] - at[1] * F[0] for at, F in forces)
    equations = {"X": body_sum(ddx) - sum_X, "Y": body_sum(ddy) - sum_Y, "R": body_sum(x * ddy - y * ddx) - sum_R}
    return {name: sp.expand(symbolize(e)) for name, e in equations.items()}


@lru_cache(maxsize=None)
def pressures_exact() -> tuple[sp.Expr, sp.Expr]:
    """(P, Q) from the first two equations: P = −m(x1 + h cos θ)'', Q = −m(y1 + h sin θ)''."""
    eq = rigid_body()
    return sp.solve(eq["X"], P)[0], sp.solve(eq["Y"], Q)[0]


@lru_cache(maxsize=None)
def theta_ddot() -> sp.Expr:
    """θ'' from the moment equation with P, Q of the first two (the x1, y1 terms cancel)."""
    eq = rigid_body()
    P_value, Q_value = pressures_exact()
    moment = sp.expand(eq["R"].subs({P: P_value, Q: Q_value}))
    if moment.has(x1s) or moment.has(y1s):
        raise ValueError("the pivot position does not cancel")
    return sp.simplify(sp.solve(moment, thetadd)[0])


def mu_prime_derived(_deps) -> sp.Expr:
    """μ' = C θ'' + m g h sin θ: the part of the moment due to the pivot's motion."""
    return sp.expand(C * theta_ddot() + m * g * h * sp.sin(theta))


def equation_derived(deps) -> sp.Expr:
    """C θ'' = −m g h sin θ + μ', the right side as derived, μ' kept as the symbol."""
    mu = deps[rid("mu_prime")].derived
    return sp.expand(sp.expand(C * theta_ddot()) - mu) + mu_p


def equation_l_derived(deps) -> sp.Expr:
    """θ'' = −(g/l) sin θ + μ'/(m h l): the C-form divided by C, with C = m h l."""
    return sp.expand(deps[rid("equation")].derived / C).subs(C, m * h * l)


# ----------------------------------------------------------------- printed
def P_exact_printed() -> sp.Expr:
    return -m * symbolize(sp.diff(x1_t + h * sp.cos(theta_t), t, 2))


def Q_exact_printed() -> sp.Expr:
    return -m * symbolize(sp.diff(y1_t + h * sp.sin(theta_t), t, 2))


def mu_prime_printed() -> sp.Expr:
    return m * h * (sp.sin(theta) * x1dd - sp.cos(theta) * y1dd)


def equation_printed() -> sp.Expr:
    return -m * g * h * sp.sin(theta) + mu_p


def equation_l_printed() -> sp.Expr:
    return -g / l * sp.sin(theta) + mu_p / (m * h * l)


MU_DEF = ((mu_p, mu_prime_printed()),)   # μ' as the text defines it, applied before comparing


# ----------------------------------------------------------------- checks: Newton for a discrete body
BODY = ((mp.mpf("0.7"), mp.mpf("0.9"), mp.mpf("0.1")), (mp.mpf("0.5"), mp.mpf("0.2"), mp.mpf("-0.35")),
        (mp.mpf("1.1"), mp.mpf("-0.15"), mp.mpf("0.22")))        # (mass, ξ, η) of three point masses


def test_motion(s):
    """(θ, x1, y1) at time s: the test motions the body is moved along."""
    return (mp.mpf("0.3") * mp.sin(mp.mpf("1.1") * s) + mp.mpf("0.2"), mp.mpf("0.01") * mp.cos(2 * s),
            mp.mpf("0.02") * mp.sin(mp.mpf("1.7") * s) + mp.mpf("0.005") * s**2)


def particles(s):
    """(m_i, x_i, y_i, x_i'', y_i'') of the three point masses at time s."""
    out = []
    for mi, a, b in BODY:
        fx = lambda s, a=a, b=b: test_motion(s)[1] + a * mp.cos(test_motion(s)[0]) - b * mp.sin(test_motion(s)[0])
        fy = lambda s, a=a, b=b: test_motion(s)[2] + a * mp.sin(test_motion(s)[0]) + b * mp.cos(test_motion(s)[0])
        out.append((mi, fx(s), fy(s), mp.diff(fx, s, 2), mp.diff(fy, s, 2)))
    return out


def body_constants():
    """(m, h, C, β) of the three point masses; β is the body angle of G (θ = θ_body + β)."""
    mt = sum(b[0] for b in BODY)
    xg = sum(b[0] * b[1] for b in BODY) / mt
    yg = sum(b[0] * b[2] for b in BODY) / mt
    return mt, mp.sqrt(xg**2 + yg**2), sum(b[0] * (b[1] ** 2 + b[2] ** 2) for b in BODY), mp.atan2(yg, xg)


def newton_check(what: str):
    """P, Q, μ' or the equation against Newton's sums for three point masses (numerical derivatives)."""
    def check(result, level):
        pairs = []
        with mp.workdps(DPS):
            mt, hh, CC, beta = body_constants()
            gv = mp.mpf("9.8")
            for s in (mp.mpf("0.4"), mp.mpf("1.7")):
                parts = particles(s)
                P_sum = -sum(p[0] * p[3] for p in parts)            # Σ x'' dm = −P
                Q_sum = -sum(p[0] * p[4] for p in parts)
                moment = sum(p[0] * (p[1] * p[4] - p[2] * p[3]) for p in parts)
                angle = lambda x: test_motion(x)[0]
                x1, y1 = lambda x: test_motion(x)[1], lambda x: test_motion(x)[2]
                values = {theta: angle(s) + beta, thetad: mp.diff(angle, s), thetadd: mp.diff(angle, s, 2),
                          x1dd: mp.diff(x1, s, 2), y1dd: mp.diff(y1, s, 2), m: mt, h: hh, C: CC, g: gv,
                          x1s: x1(s), y1s: y1(s)}
                at = lambda e: sp.lambdify(tuple(values), e, "mpmath")(*values.values())
                if what == "P":
                    pairs.append((f"P t={s}", at(result.derived), P_sum))
                elif what == "Q":
                    pairs.append((f"Q t={s}", at(result.derived), Q_sum))
                else:
                    # the moment equation with the support's moment removed: Σ(xy''−yx'')dm − y1 P + x1 Q
                    # = C θ'' − μ' (the weight's moment −mgh sin θ on both sides)
                    newton = moment - (y1(s) * P_sum - x1(s) * Q_sum)
                    rhs = result.derived_value + m * g * h * sp.sin(theta) if what == "equation" else result.derived
                    pairs.append((f"t={s}", at(C * thetadd - rhs), newton))
        return verify.value_check(
            truth_desc="three point masses (m_i, ξ_i, η_i) moved rigidly along θ(t), x1(t), y1(t) (test motions); "
                       "Σ m_i(x y'' − y x''), Σ m_i x'', Σ m_i y'' by mpmath numerical differentiation",
            pairs=pairs, tol=mp.mpf("1e-20"), kind="value")
    return check


# ----------------------------------------------------------------- the Result table
def specs() -> tuple[Spec, ...]:
    return (
        Spec(rid("P_exact"), "Vertical pressure P from the first equation of motion",
             src("pressures", "P = −m d²·(x1 + h cos θ)/dt²"), "P", lambda d: pressures_exact()[0],
             printed=P_exact_printed, check=newton_check("P"), note="Derived from Σ x''dm = ΣX = −P with Σξ dm = mh."),
        Spec(rid("Q_exact"), "Horizontal pressure Q from the second equation of motion",
             src("pressures", "Q = −m d²·(y1 + h sin θ)/dt²"), "Q", lambda d: pressures_exact()[1],
             printed=Q_exact_printed, check=newton_check("Q")),
        Spec(rid("mu_prime"), "μ', the moment due to the motion of the knife edge",
             src("relative_axes", "en posant: μ' = mh[sin θ d²x1/dt² − cos θ d²y1/dt²]"), r"\mu'", mu_prime_derived,
             printed=mu_prime_printed, check=newton_check("mu"),
             readings=(Reading("d²x^4/dt², d²y^4/dt²", "d²x1/dt², d²y1/dt²"),),
             note="Derived as Cθ'' + mgh sin θ from the moment equation after eliminating P, Q."),
        Spec(rid("equation"), "C θ'' = −mgh sin θ + μ'",
             src("inertia", "Σ[(x − x1) d²y/dt² − (y − y1) d²x/dt²] dm = −mgh sin θ … C d²θ/dt² = −mgh sin θ + μ'"),
             r"C\theta''", equation_derived, deps=(rid("mu_prime"),), printed=equation_printed, defs=MU_DEF,
             check=newton_check("equation"),
             note="The x1, y1 terms of P, Q cancel in the moment equation (the text's 'multipliant … par y1, −x1')."),
        Spec(rid("equation_l"), "θ'' = −(g/l) sin θ + μ'/(mhl), l = C/(mh)",
             src("length_l", "En posant l = C/(mh), on pourra l'écrire: d²θ/dt² = −(g/t) sin θ + μ'/(mht)"),
             r"\theta''", equation_l_derived, deps=(rid("equation"),), printed=equation_l_printed, defs=MU_DEF,
             check=checks.Chain((rid("equation"),)), readings=(read_l_as_t("g/t, μ'/(mht)", "g/l, μ'/(mhl)"),)),
    )
