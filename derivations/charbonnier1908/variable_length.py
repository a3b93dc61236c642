"""Charbonnier 1908 §VI, the pendulum whose length grows at a constant rate,
l = l0(1 + at) (n°27–35, pp. 233–238).  The small parameter is a.
"""
from __future__ import annotations

import mpmath as mp
import sympy as sp

from pendsym import verify
from pendsym.result import KernelArg, KernelSpec, Reading, Source, Spec
from . import chain, truth as tr
from .chain import Example
from .general import MEMOIR
from .symbols import DEFS, T, a, alpha, k, l, l0, omega, t, theta, dtheta

c, s = sp.cos(k * t), sp.sin(k * t)
x = k * t
R = sp.Rational
OCR_A = Reading("α (or x) where the rate a stands", "a: the OCR confuses a, α and x", certain=True)

N27 = Example(
    key="n28", name="Length growing at a constant rate", law="growing", small=a, order=1,
    pages={"default": 234, "eom": 233, "theta": 235, "dtheta": 235, "dT": 236, "dalpha": 236,
           "dThalf": 236, "dthetam": 237},
    eps=lambda: a * alpha * k, phi=lambda: x * c + 2 * s,
    printed={
        "eom": lambda: a * (2 * dtheta - k**2 * theta * t),
        "eps": lambda: a * alpha * k,
        "phi": lambda: x * c + 2 * s,
        "Es": lambda: (x / 2 * s**2 + 3 * x / 4 - R(3, 4) * c * s) / k,
        "Ec": lambda: (x**2 / 4 + R(3, 4) * s**2 + x / 2 * s * c) / k,
        "theta": lambda: -alpha * c - R(1, 4) * a * alpha / k * (x**2 * s - 3 * x * c + 3 * s),
        "dtheta": lambda: k * alpha * s - a * alpha / 4 * (x**2 * c - x * s),
        "dT": lambda: a / 4 * T**2,
        "dalpha": lambda: -R(3, 4) * a * alpha * T,
        "dThalf": lambda: a / (4 * k**2) * ((sp.pi / 2) ** 2 + 3),
        "dthetam": lambda: -R(5, 8) * a * alpha * sp.pi,
    },
    readings={
        "eom": (Reading("θ'' + k²θ + a(2θ' − k²θt).", "… = 0 (the '= 0' is missing)"),),
        "eps": (Reading("ε = ααk", "ε = aαk"),),
        "theta": (Reading("(1/4)(αα/k)", "(1/4)(aα/k)"),),
        "dtheta": (OCR_A, Reading("[(kt)² cos kt − kt sin kt]",
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
    params=(), extra_args=(chain.RATE,),
    check_param=a, check_range=("1e-4", "3e-3"),
)


def mean_length(deps) -> sp.Expr:
    """The length L of a simple pendulum whose swing lasts T + ΔT, to first order in a (n°32)."""
    L = sp.Symbol("L", positive=True)
    dT = deps[f"{MEMOIR}.n32.dT"].derived
    (sol,) = sp.solve(sp.Eq(sp.pi * sp.sqrt(L / (k**2 * l0)), sp.pi / k + dT), L)
    return sp.expand(sp.series(sol, a, 0, 2).removeO())


def mean_length_check(result, level):
    """L against the mean of the lengths at the two ends of the swing, from the integrated T."""
    kv = mp.mpf(chain.K_CHECK)

    def truth(p, dps):
        Tt = tr.swing("growing", "0.3", chain.K_CHECK, dps, a=mp.nstr(p, 40)).T
        return (Tt * kv / mp.pi) ** 2          # L/l0 of the pendulum with the same swing time
    f = verify.lambdify_mp(result.derived.subs(DEFS) / l0, (a, k))
    return verify.order_check(param="a", values=verify.geometric("1e-4", "3e-3", verify.LEVELS[level]),
                              truth=truth, derived=lambda p: f(p, kv), expected=2, band=0.3,
                              truth_desc=tr.MODEL_TEXT["growing"] + "; L = l0 (kT/π)²",
                              params=(("k", chain.K_CHECK), ("alpha", "0.3")))


def tangent_at_E(deps) -> sp.Expr:
    """n°35 2°: the slope ψ of the trajectory at the lowest point E, to first order in a.

    The bob moves with l' = a l0 along the thread and l θ' across it, so
    tan ψ = l'/(l θ'); with θ' = kα + Δθ'_m there, ψ = a/(kα) + O(a²) > 0:
    not horizontal, as the memoir says.
    """
    dthm = deps[f"{MEMOIR}.n34.dthetam"].derived
    psi = sp.atan(a * l0 / (l0 * (1 + a * sp.pi / (2 * k)) * (k * alpha + dthm)))
    return sp.simplify(sp.series(psi, a, 0, 2).removeO())


def tangent_check(result, level):
    kv = mp.mpf(chain.K_CHECK)
    f = verify.lambdify_mp(result.derived, (a, alpha, k))

    def measured(p, dps):
        sw = tr.swing("growing", "0.3", chain.K_CHECK, dps, a=mp.nstr(p, 40))
        return mp.atan(p / ((1 + p * sw.t_low) * sw.v_low))
    return verify.order_check(
        param="a", values=verify.geometric("1e-4", "3e-3", verify.LEVELS[level]), truth=measured,
        derived=lambda p: f(p, mp.mpf("0.3"), kv), expected=2, band=0.3,
        truth_desc=tr.MODEL_TEXT["growing"] + "; ψ = atan(l'/(lθ')) at the lowest point",
        params=(("k", chain.K_CHECK), ("alpha", "0.3")))


def angle_at_C(deps) -> sp.Expr:
    """The angle at C, after two swings: α + 2Δα to first order (n°35 5°)."""
    return sp.expand(alpha + 2 * deps[f"{MEMOIR}.n33.dalpha"].derived)


def length_at_C(_deps) -> sp.Expr:
    """l at C, t = 2T (n°35 6°)."""
    return (l0 * (1 + a * t)).subs(t, 2 * sp.pi / k)


def curve_of_C(deps) -> sp.Expr:
    """The locus of C: dω/ω = (2Δα/α) per 2aT l0 of length, integrated (n°35).

    Returns l(ω) with l = l0 at ω = α.
    """
    lam = sp.Symbol("L", positive=True)
    w = sp.Function("w")
    per_two = sp.simplify(2 * deps[f"{MEMOIR}.n33.dalpha"].derived / alpha)        # dω/ω over two swings
    dl = sp.simplify(deps[f"{MEMOIR}.n35.l_C"].derived - l0)                        # dl over two swings
    ode = sp.Eq(w(lam).diff(lam), per_two / dl * w(lam))
    sol = sp.dsolve(ode, w(lam), ics={w(l0): alpha}).rhs
    (l_of_w,) = sp.solve(sp.Eq(omega, sol), lam)
    expanded = sp.expand(sp.expand_log(l_of_w, force=True))
    # l0 + c·l0·(log α − log ω)  →  l0 + c·l0·log(α/ω), the memoir's way of writing it
    c = sp.simplify(expanded.coeff(sp.log(alpha)) / l0)
    if sp.simplify(expanded - (l0 + c * l0 * (sp.log(alpha) - sp.log(omega)))) != 0:
        return expanded
    return l0 + c * l0 * sp.log(alpha / omega)


def _C_points(p, dps, n_pairs: int):
    """(l, ω) at the left turning points after 2, 4, … swings of the integrated model."""
    kv = mp.mpf(chain.K_CHECK)
    sw = tr.swing("growing", "0.3", chain.K_CHECK, dps, a=mp.nstr(p, 40))
    out, tt = [], mp.mpf(0)
    with mp.workdps(dps):
        for j in range(1, 2 * n_pairs + 1):
            tt = tr.truth.turning_time(sw.traj, tt + mp.pi / kv * (1 + p * tt / 2), width=mp.pi / (4 * kv))
            if j % 2 == 0:
                out.append((1 + p * tt, abs(sw.traj(tt)[0])))
    return out


def C_check(kind: str):
    def check(result, level):
        kv = mp.mpf(chain.K_CHECK)
        printed = result.printed_value

        def measured(p, dps):
            lC, wC = _C_points(p, dps, 1)[0]
            return wC if kind == "angle" else lC
        f = verify.lambdify_mp(result.derived.subs(DEFS), (a, alpha, k, l0))
        pf = verify.lambdify_mp(printed, (a, alpha, k, l0))
        return verify.order_check(
            param="a", values=verify.geometric("1e-4", "3e-3", verify.LEVELS[level]), truth=measured,
            derived=lambda p: f(p, mp.mpf("0.3"), kv, 1), printed=lambda p: pf(p, mp.mpf("0.3"), kv, 1),
            expected=2, band=0.3, truth_desc=tr.MODEL_TEXT["growing"] + "; the second turning point C",
            params=(("k", chain.K_CHECK), ("alpha", "0.3")))
    return check


def curve_check(result, level):
    """At the first point C of the integrated model, l_C against l(ω_C) of the curve (order 2 in a)."""
    f = verify.lambdify_mp(result.derived, (omega, alpha, l0))
    pf = verify.lambdify_mp(result.printed_value, (omega, alpha, l0))
    al = mp.mpf("0.3")
    return verify.order_check(
        param="a", values=verify.geometric("1e-4", "3e-3", verify.LEVELS[level]),
        truth=lambda p, dps: _C_points(p, dps, 1)[0][0],
        derived=lambda p: f(_C_points(p, 30, 1)[0][1], al, 1),
        printed=lambda p: pf(_C_points(p, 30, 1)[0][1], al, 1),
        expected=2, band=0.3, truth_desc=tr.MODEL_TEXT["growing"] + "; (l_C, ω_C) at the second turning point",
        params=(("k", chain.K_CHECK), ("alpha", "0.3")))


def specs() -> tuple[Spec, ...]:
    P = MEMOIR
    defs = tuple(DEFS.items())
    return chain.specs(N27) + (
        Spec(f"{P}.n32.mean_length", "T + ΔT is the swing of a pendulum of the mean length",
             Source(P, "n°32", 236), "L", mean_length, deps=(f"{P}.n32.dT",),
             printed=lambda: l0 * (1 + a * T / 2), check=mean_length_check, defs=defs,
             kernel=KernelSpec((chain.RATE, chain.K, chain.L0), "length of the pendulum with the same swing"),
             readings=(Reading("l = l0(1 + αT/2)", "l0(1 + aT/2)"),)),
        Spec(f"{P}.n35.tangent_E", "Slope of the trajectory at the lowest point E", Source(P, "n°35 2°", 237),
             r"\psi_E", tangent_at_E, deps=(f"{P}.n34.dthetam",), check=tangent_check, defs=defs,
             note="The memoir states only that the tangent is inclined, not horizontal; ψ_E > 0 confirms it.",
             kernel=KernelSpec((chain.RATE, chain.ALPHA, chain.K), "slope at E")),
        Spec(f"{P}.n35.omega_C", "Angle at C after two swings", Source(P, "n°35 5°", 237), r"\omega_C",
             angle_at_C, deps=(f"{P}.n33.dalpha",), printed=lambda: alpha * (1 - R(3, 2) * a * T),
             check=C_check("angle"), defs=defs,
             kernel=KernelSpec((chain.RATE, chain.ALPHA, chain.K), "angle at C")),
        Spec(f"{P}.n35.l_C", "Length at C", Source(P, "n°35 6°", 238), "l_C", length_at_C,
             printed=lambda: l0 * (1 + 2 * a * T), check=C_check("length"), defs=defs,
             kernel=KernelSpec((chain.RATE, chain.K, chain.L0), "length at C")),
        Spec(f"{P}.n35.curve", "The curve, locus of the points C", Source(P, "n°35 6°", 238), "l(\\omega)",
             curve_of_C, deps=(f"{P}.n33.dalpha", f"{P}.n35.l_C"),
             printed=lambda: l0 + R(2, 3) * l0 * sp.log(alpha / omega), check=curve_check, defs=defs,
             kernel=KernelSpec((KernelArg("omega", 1e-3, 3.0, unit="rad"), chain.ALPHA, chain.L0), "l(ω) on the curve of C"),
             readings=(Reading("dω/ω = −(3/2) dl/l0", "as printed. From the memoir's own dl = 2al0T and "
                               "dω = −(3/2)aωT the ratio is −3/4, so its curve should read "
                               "l = l0 + (4/3)l0 Log(α/ω); the slip is in the memoir, not the OCR (the "
                               "factor 2/3 repeats it)", certain=True),)),
    )
