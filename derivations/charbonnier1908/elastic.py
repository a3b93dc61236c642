"""Charbonnier 1908 §V, the elastic thread (n°24–26, pp. 229–232).

The thread stretches statically: l = λ[1 + (m/e)(g cos θ + v²/l)], with
l0 = λ(1 + mg/e).  We write μ = mg/e, so that mg/(e + mg) = μ/(1 + μ).
"""
from __future__ import annotations

import mpmath as mp
import sympy as sp

from pendsym import pendulum, verify
from pendsym.result import KernelSpec, Reading, Spec
from . import chain, truth
from .chain import DELTA, Example
from .common import ALPHA, K, MU, READ_ALPHA_AS_X, THETA, THETADOT, TIME, Geometric, rid, src
from .symbols import DEF_ITEMS, DEFS, T, alpha, cos_kt, dtheta, e, g, k, kt, l0, mass, mu, sin_kt, t, theta

R = sp.Rational
NU = mass * g / (e + mass * g)   # the printed mg/(e + mg)

N24 = Example(
    key="n25", name="Elastic thread", law="elastic", small=DELTA, order=3,
    pages={"default": 232, "eom": 231, "eps": 231, "phi": 231},
    eps=R(1, 2) * mu / (1 + mu) * k**2 * alpha**3, phi=(15 * sin_kt**2 - 1) * cos_kt,
    printed={
        "eps": R(1, 2) * NU * k**2 * alpha**3,
        "phi": (15 * sin_kt**2 - 1) * cos_kt,
        "Es": R(15, 4) / k * sin_kt**4 - 1 / (2 * k) * sin_kt**2,
        "Ec": 1 / (4 * k) * (R(11, 2) * kt + cos_kt * sin_kt * (R(11, 2) - 15 * cos_kt**2)),
        "dT": R(11, 16) * NU * alpha**2 * T,
        "dalpha": sp.S.Zero,
    },
    readings={"eps": (READ_ALPHA_AS_X,)},
    params=((mu, "0.3"),), extra_args=(MU,),
    key_of={"Es": "n26", "Ec": "n26", "theta": "n26", "dtheta": "n26", "dT": "n26", "dalpha": "n26"},
    notes={"eom": "The memoir prints the equation only along the motion (n°25): see n25.eps and n25.phi.",
           "dT": "n°26 3°: always positive."},
)


# ----------------------------------------------------------------- derivation (n°24–25)
def ratio_derived(_deps) -> sp.Expr:
    """l/l0 to second order in the amplitude from the implicit law (n°24)."""
    law = truth.ELASTIC_L.subs(g, k**2 * l0) / l0
    return pendulum.lowest_order(law, DELTA, {theta: DELTA * theta, dtheta: DELTA * dtheta}, 2)


def ratio_along_derived(deps) -> sp.Expr:
    """l/l0 along θ0 = −α cos kt (n°24, last formula)."""
    ratio = deps[rid(24, "l_ratio")].derived
    return sp.simplify(ratio.subs({theta: -alpha * cos_kt, dtheta: alpha * k * sin_kt}, simultaneous=True))


def rate_derived(deps) -> sp.Expr:
    """(1/l0) dl/dt along the motion (n°25)."""
    return sp.simplify(sp.diff(deps[rid(24, "l_ratio_t")].derived, t))


# ----------------------------------------------------------------- printed
def ratio_printed() -> sp.Expr:
    # v = l0 θ' (n°24): the printed form in v is rewritten with θ'
    return 1 + mass / (e + mass * g) * ((l0 * dtheta) ** 2 / l0 - g * theta**2 / 2)


def ratio_along_printed() -> sp.Expr:
    return 1 + NU * alpha**2 * (sin_kt**2 - cos_kt**2 / 2)


def rate_printed() -> sp.Expr:
    return 3 * NU * k * alpha**2 * sin_kt * cos_kt


# ----------------------------------------------------------------- checks: the implicit law solved exactly
def ratio_check(mode: str):
    """The exact implicit law against the second-order forms, order 4 in the amplitude.

    mode "state": l/l0 at states (θ, θ'); "time": along θ0 = −α cos kt;
    "rate": (1/l0) dl/dt along θ0, by mpmath differentiation of the exact law.
    """
    def check(result, level):
        law = verify.lambdify_mp((truth.ELASTIC_L.subs(g, k**2 * l0) / l0), (theta, dtheta, k, l0, mu))
        f = verify.lambdify_mp(result.derived.subs(DEFS), (theta, dtheta, alpha, t, k, l0, mu))
        kv, mv = mp.mpf("1.3"), mp.mpf("0.3")
        along = lambda p, tt: law(-p * mp.cos(kv * tt), p * kv * mp.sin(kv * tt), kv, 1, mv)

        def largest_error(p, dps):
            if mode == "state":
                return max(abs(law(p * c1, p * c2 * kv, kv, 1, mv) - f(p * c1, p * c2 * kv, 0, 0, kv, 1, mv))
                           for c1, c2 in ((1, mp.mpf("0.5")), (mp.mpf("-0.3"), 1)))
            times = (mp.mpf("0.3"), mp.mpf("1.2"), mp.mpf("2.2"))
            if mode == "time":
                return max(abs(along(p, tt) - f(0, 0, p, tt, kv, 1, mv)) for tt in times)
            return max(abs(mp.diff(lambda u: along(p, u), tt) - f(0, 0, p, tt, kv, 1, mv)) for tt in times)
        return verify.order_check(param="amplitude", values=Geometric("0.005", "0.1")(level),
                                  truth=largest_error, derived=lambda p: 0, expected=4, band=0.3,
                                  truth_desc="the implicit law l = λ[1 + (m/e)(g cos θ + lθ'²)] solved exactly for l",
                                  params=(("k", "1.3"), ("mu", "0.3")))
    return check


# ----------------------------------------------------------------- the Result table
def specs() -> tuple[Spec, ...]:
    return (
        Spec(rid(24, "l_ratio"), "l/l0 to second order", src("n°24", 230), "l/l_0", ratio_derived,
             printed=ratio_printed, defs=DEF_ITEMS, check=ratio_check("state"),
             kernel=KernelSpec((THETA, THETADOT, K, MU), "l/l0 of the elastic thread"),
             readings=(Reading("v²/l0 with v = l0 dθ/dt", "θ'² l0"),)),
        Spec(rid(24, "l_ratio_t"), "l/l0 along the motion", src("n°24", 230), "l/l_0", ratio_along_derived,
             deps=(rid(24, "l_ratio"),), printed=ratio_along_printed, readings=(READ_ALPHA_AS_X,), defs=DEF_ITEMS,
             check=ratio_check("time"), kernel=KernelSpec((ALPHA, K, TIME, MU), "l/l0 along the motion")),
        Spec(rid(25, "rate"), "(1/l0) dl/dt along the motion", src("n°25", 231), r"\frac{1}{l_0}\frac{dl}{dt}",
             rate_derived, deps=(rid(24, "l_ratio_t"),), printed=rate_printed, readings=(READ_ALPHA_AS_X,),
             defs=DEF_ITEMS, check=ratio_check("rate"),
             kernel=KernelSpec((ALPHA, K, TIME, MU), "(1/l0) dl/dt along the motion")),
    ) + chain.specs(N24)
