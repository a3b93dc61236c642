"""Charbonnier 1908 §VI, the pendulum whose length grows at a constant rate,
l = l0(1 + at) (n°27–35, pp. 233–238).  The small parameter is a.
"""
from __future__ import annotations

import mpmath as mp
import sympy as sp

from pendsym import checks, verify
from pendsym.result import KernelArg, KernelSpec, Reading, Spec
from pendsym.truth import turning_time
from . import chain, truth
from .chain import Example
from .common import ALPHA, ALPHA_CHECK, DPS, K, K_CHECK, L0, RATE, READ_RATE, Geometric, printed, rid, src
from .symbols import DEF_ITEMS, DEFS, T, a, alpha, cos_kt, dtheta, k, kt, l0, omega, sin_kt, t, theta

R = sp.Rational
RATES = Geometric("1e-4", "3e-3")          # the rate a of the checks

N27 = Example(
    key="n28", name="Length growing at a constant rate", law="growing", small=a, order=1,
    pages={"default": 234, "eom": 233, "theta": 235, "dtheta": 235, "dT": 236, "dalpha": 236,
           "dThalf": 236, "dthetam": 237},
    eps=a * alpha * k, phi=kt * cos_kt + 2 * sin_kt,
    printed={
        "eom": a * (2 * dtheta - k**2 * theta * t),
        "eps": a * alpha * k,
        "phi": kt * cos_kt + 2 * sin_kt,
        "Es": (kt / 2 * sin_kt**2 + 3 * kt / 4 - R(3, 4) * cos_kt * sin_kt) / k,
        "Ec": (kt**2 / 4 + R(3, 4) * sin_kt**2 + kt / 2 * sin_kt * cos_kt) / k,
        "theta": -alpha * cos_kt - R(1, 4) * a * alpha / k * (kt**2 * sin_kt - 3 * kt * cos_kt + 3 * sin_kt),
        "dtheta": k * alpha * sin_kt - a * alpha / 4 * (kt**2 * cos_kt - kt * sin_kt),
        "dT": a / 4 * T**2,
        "dalpha": -R(3, 4) * a * alpha * T,
        "dThalf": a / (4 * k**2) * ((sp.pi / 2) ** 2 + 3),
        "dthetam": -R(5, 8) * a * alpha * sp.pi,
    },
    readings={
        "eom": (Reading("θ'' + k²θ + a(2θ' − k²θt).", "… = 0 (the '= 0' is missing)"),),
        "eps": (Reading("ε = ααk", "ε = aαk"),),
        "theta": (Reading("(1/4)(αα/k)", "(1/4)(aα/k)"),),
        "dtheta": (READ_RATE, Reading("[(kt)² cos kt − kt sin kt]",
                                      "as printed. Differentiating the printed θ(t) of the same paragraph gives "
                                      "[(kt)² cos kt + 5kt sin kt]; a sign and a digit differ, so a misreading is "
                                      "possible but would need two faults", certain=False)),
        "dT": (Reading("ΔT = (α/4)T²", "(a/4)T²"),),
        "dalpha": (Reading("Δx = −(3/4)αxT", "Δα = −(3/4)aαT"),),
        "dThalf": (Reading("α/(4k²)", "a/(4k²)"),),
        "dthetam": (Reading("Δθ'_m = −(5/8)aαπ", "as printed"),),
    },
    key_of={"Es": "n29", "Ec": "n30", "theta": "n31", "dtheta": "n31", "dT": "n32", "dalpha": "n33",
            "dThalf": "n34", "dthetam": "n34"},
    params=(), extra_args=(RATE,),
    check_param=a, check_range=("1e-4", "3e-3"), law_from=rid(27, "l"),
)


# ----------------------------------------------------------------- derivation
def length_law(_deps) -> sp.Expr:
    """n°27: the cable unwinds at a constant, very small speed, l = l0(1 + at): the law of the
    model the truth integrates (truth.LAWS["growing"])."""
    return truth.LAWS["growing"][0]


def mean_length(deps) -> sp.Expr:
    """The length L of a simple pendulum whose swing lasts T + ΔT, to first order in a (n°32)."""
    L = sp.Symbol("L", positive=True)
    dT = deps[rid(32, "dT")].derived
    (solution,) = sp.solve(sp.Eq(sp.pi * sp.sqrt(L / (k**2 * l0)), sp.pi / k + dT), L)
    return sp.expand(sp.series(solution, a, 0, 2).removeO())


def tangent_at_E(deps) -> sp.Expr:
    """n°35 2°: the slope ψ of the trajectory at the lowest point E, to first order in a.

    The bob moves with l' = a l0 along the thread and l θ' across it, so
    tan ψ = l'/(l θ'); with θ' = kα + Δθ'_m there, ψ = a/(kα) + O(a²) > 0:
    not horizontal, as the memoir says.
    """
    dthetam = deps[rid(34, "dthetam")].derived
    psi = sp.atan(a * l0 / (l0 * (1 + a * sp.pi / (2 * k)) * (k * alpha + dthetam)))
    return sp.simplify(sp.series(psi, a, 0, 2).removeO())


def angle_at_C(deps) -> sp.Expr:
    """The angle at C, after two swings: α + 2Δα to first order (n°35 5°)."""
    return sp.expand(alpha + 2 * deps[rid(33, "dalpha")].derived)


def length_at_C(deps) -> sp.Expr:
    """l at C, t = 2T (n°35 6°), from the law of n°27."""
    return deps[rid(27, "l")].derived.subs(t, 2 * sp.pi / k)


def curve_of_C(deps) -> sp.Expr:
    """The locus of C: dω/ω = (2Δα/α) per 2aT l0 of length, integrated (n°35).

    Returns l(ω) with l = l0 at ω = α.
    """
    length = sp.Symbol("L", positive=True)
    w = sp.Function("w")
    per_two = sp.simplify(2 * deps[rid(33, "dalpha")].derived / alpha)      # dω/ω over two swings
    dl = sp.simplify(deps[rid(35, "l_C")].derived - l0)                       # dl over two swings
    ode = sp.Eq(w(length).diff(length), per_two / dl * w(length))
    solution = sp.dsolve(ode, w(length), ics={w(l0): alpha}).rhs
    (l_of_omega,) = sp.solve(sp.Eq(omega, solution), length)
    expanded = sp.expand(sp.expand_log(l_of_omega, force=True))
    # l0 + c·l0·(log α − log ω)  →  l0 + c·l0·log(α/ω), the memoir's way of writing it
    c = sp.simplify(expanded.coeff(sp.log(alpha)) / l0)
    if sp.simplify(expanded - (l0 + c * l0 * (sp.log(alpha) - sp.log(omega)))) != 0:
        return expanded
    return l0 + c * l0 * sp.log(alpha / omega)


# ----------------------------------------------------------------- printed (n°27, n°32, n°35)
PRINTED = {
    "l": l0 * (1 + a * t),
    "mean_length": l0 * (1 + a * T / 2),
    "omega_C": alpha * (1 - R(3, 2) * a * T),
    "l_C": l0 * (1 + 2 * a * T),
    "curve": l0 + R(2, 3) * l0 * sp.log(alpha / omega),
}


# ----------------------------------------------------------------- checks: the growing pendulum integrated
GROWING = truth.MODEL_TEXT["growing"]
FIXED = (("k", K_CHECK), ("alpha", ALPHA_CHECK))


def growing_swing(p, dps) -> truth.Swing:
    """One swing of the growing pendulum at the rate p, from rest at −α."""
    return truth.swing("growing", ALPHA_CHECK, K_CHECK, dps, a=mp.nstr(p, 40))


def mean_length_check(result, level):
    """L against the mean of the lengths at the two ends of the swing, from the integrated T."""
    kv = mp.mpf(K_CHECK)

    def same_swing_length(p, dps):
        return (growing_swing(p, dps).T * kv / mp.pi) ** 2      # L/l0 of the pendulum with the same swing time
    f = verify.lambdify_mp(result.derived.subs(DEFS) / l0, (a, k))
    return verify.order_check(param="a", values=RATES(level), truth=same_swing_length,
                              derived=lambda p: f(p, kv), expected=2, band=0.3,
                              truth_desc=GROWING + "; L = l0 (kT/π)²", params=FIXED)


def slope_at_lowest_point(p, dps):
    sw = growing_swing(p, dps)
    return mp.atan(p / ((1 + p * sw.t_low) * sw.v_low))


def C_points(p, dps, n_pairs: int):
    """(l, ω) at the left turning points after 2, 4, … swings of the integrated model."""
    kv = mp.mpf(K_CHECK)
    sw = growing_swing(p, dps)
    out, tt = [], mp.mpf(0)
    with mp.workdps(dps):
        for j in range(1, 2 * n_pairs + 1):
            tt = turning_time(sw.traj, tt + mp.pi / kv * (1 + p * tt / 2), width=mp.pi / (4 * kv))
            if j % 2 == 0:
                out.append((1 + p * tt, abs(sw.traj(tt)[0])))
    return out


def at_rate(expr, p, **values):
    """expr at a = p, α = 0.3, k = 1.3, l0 = 1 (and the other values given)."""
    return verify.value_at(expr, {"a": p, "alpha": ALPHA_CHECK, "k": K_CHECK, "l_0": 1, **values})


TANGENT_CHECK = checks.Order(
    param="a", values=RATES, truth=slope_at_lowest_point, at=at_rate, expected=2, band=0.3,
    truth_desc=GROWING + "; ψ = atan(l'/(lθ')) at the lowest point", params=FIXED)
C_ANGLE_CHECK = checks.Order(
    param="a", values=RATES, truth=lambda p, dps: C_points(p, dps, 1)[0][1], at=at_rate, expected=2, band=0.3,
    truth_desc=GROWING + "; the second turning point C", params=FIXED)
C_LENGTH_CHECK = checks.Order(
    param="a", values=RATES, truth=lambda p, dps: C_points(p, dps, 1)[0][0], at=at_rate, expected=2, band=0.3,
    truth_desc=GROWING + "; the second turning point C", params=FIXED)
CURVE_CHECK = checks.Order(   # at the first point C of the model, l_C against l(ω_C) of the curve
    param="a", values=RATES, truth=lambda p, dps: C_points(p, dps, 1)[0][0],
    at=lambda expr, p: at_rate(expr, p, omega=C_points(p, DPS, 1)[0][1]), expected=2, band=0.3,
    truth_desc=GROWING + "; (l_C, ω_C) at the second turning point", params=FIXED)


# ----------------------------------------------------------------- the Result table
def specs() -> tuple[Spec, ...]:
    return (
        Spec(rid(27, "l"), "Length of the cable unwound at constant speed (the statement of the problem)", src("n°27", 233),
             "l", length_law, printed=printed(PRINTED["l"]), definition=True, check=checks.Definition(),
             note=("Énoncé du problème: a bucket going down a well swings while the cable unwinds at a constant, "
                   "very small speed; a is that speed relative to l0. The law of the model every check of n°28–35 "
                   "integrates.")),
    ) + chain.specs(N27) + (
        Spec(rid(32, "mean_length"), "T + ΔT is the swing of a pendulum of the mean length", src("n°32", 236), "L",
             mean_length, deps=(rid(32, "dT"),), printed=printed(PRINTED["mean_length"]), check=mean_length_check,
             defs=DEF_ITEMS, kernel=KernelSpec((RATE, K, L0), "length of the pendulum with the same swing"),
             readings=(Reading("l = l0(1 + αT/2)", "l0(1 + aT/2)"),)),
        Spec(rid(35, "tangent_E"), "Slope of the trajectory at the lowest point E", src("n°35 2°", 237),
             r"\psi_E", tangent_at_E, deps=(rid(34, "dthetam"),), check=TANGENT_CHECK, defs=DEF_ITEMS,
             note="The memoir states only that the tangent is inclined, not horizontal; ψ_E > 0 confirms it.",
             kernel=KernelSpec((RATE, ALPHA, K), "slope at E")),
        Spec(rid(35, "omega_C"), "Angle at C after two swings", src("n°35 5°", 237), r"\omega_C", angle_at_C,
             deps=(rid(33, "dalpha"),), printed=printed(PRINTED["omega_C"]), check=C_ANGLE_CHECK, defs=DEF_ITEMS,
             kernel=KernelSpec((RATE, ALPHA, K), "angle at C")),
        Spec(rid(35, "l_C"), "Length at C", src("n°35 6°", 238), "l_C", length_at_C, deps=(rid(27, "l"),),
             printed=printed(PRINTED["l_C"]), check=C_LENGTH_CHECK, defs=DEF_ITEMS,
             kernel=KernelSpec((RATE, K, L0), "length at C")),
        Spec(rid(35, "curve"), "The curve, locus of the points C", src("n°35 6°", 238), "l(\\omega)",
             curve_of_C, deps=(rid(33, "dalpha"), rid(35, "l_C")), printed=printed(PRINTED["curve"]),
             check=CURVE_CHECK, defs=DEF_ITEMS,
             kernel=KernelSpec((KernelArg("omega", 1e-3, 3.0, unit="rad"), ALPHA, L0), "l(ω) on the curve of C"),
             readings=(Reading("dω/ω = −(3/2) dl/l0", "as printed. From the memoir's own dl = 2al0T and "
                               "dω = −(3/2)aωT the ratio is −3/4, so its curve should read "
                               "l = l0 + (4/3)l0 Log(α/ω); the slip is in the memoir, not the OCR (the "
                               "factor 2/3 repeats it)", certain=True),)),
    )
