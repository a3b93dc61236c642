"""Cellérier, the support as an elastic bar, and the dynamic correction to y1 = KQ (from
« En substituant Q = Σ γ cos(ρt + ρ') … » to « Or, pour le terme principal de Q … »).

Bar AO of length c fixed at A (z = 0), loaded at O (z = c) by Q = Σ γ cos(ρt + ρ'):
v_tt = n² v_zz, v(0) = 0, v_z(c) = aQ.  The independent truth for the bar is
its modal expansion (eigenfunctions sin λ_k z, λ_k = (k + ½)π/c) summed by
mpmath nsum; for the pendulum, the lumped support (mass M on the spring K)
integrated with the pendulum (derivations.cellerier.truth).
"""
from __future__ import annotations

import mpmath as mp
import sympy as sp

from pendsym import checks, verify
from pendsym.result import KernelArg, KernelSpec, Reading, Spec
from . import truth
from .common import DPS, H_TRUTH, Geometric, printed, rid, src
from .symbols import K, M, T, a, c, g, gamma, l, n, rho, rho_p, t, x, z

amplitude = sp.Symbol("A")     # the amplitude of the particular solution, solved for
RHO_CN = Geometric("0.01", "0.1")


# ----------------------------------------------------------------- derivation
def bar_particular_derived(_deps) -> sp.Expr:
    """v' = A sin(ρz/n) cos(ρt + ρ'): satisfies the wave equation and v(0) = 0; A from v_z(c) = aγ cos."""
    v = amplitude * sp.sin(rho * z / n) * sp.cos(rho * t + rho_p)
    if sp.simplify(sp.diff(v, t, 2) - n**2 * sp.diff(v, z, 2)) != 0 or v.subs(z, 0) != 0:
        raise ValueError("the ansatz does not solve the wave equation")
    A = sp.solve(sp.Eq(sp.diff(v, z).subs(z, c), a * gamma * sp.cos(rho * t + rho_p)), amplitude)[0]
    return sp.simplify(v.subs(amplitude, A))


def static_limit_derived(deps) -> sp.Expr:
    """ρ → 0 (slow load): v' → a z γ cos(ρt + ρ') = a z Q."""
    v = deps[rid("bar_particular")].derived
    # ρ → 0 in the spatial factor only (ρt + ρ' is the load's phase, kept)
    spatial = sp.simplify(v / sp.cos(rho * t + rho_p))
    return sp.limit(spatial, rho, 0) * sp.cos(rho * t + rho_p)


def K_ac_derived(deps) -> sp.Expr:
    """K from y1 = KQ and, at z = c, y1 = acQ."""
    v = deps[rid("bar_static_limit")].derived.subs(z, c)
    return sp.solve(sp.Eq(K * gamma * sp.cos(rho * t + rho_p), v), K)[0]


def dynamic_correction_derived(deps) -> sp.Expr:
    """First term in x = ρc/n of v'(c)/(acQ) − 1 (the dynamic correction to y1 = KQ)."""
    v = deps[rid("bar_particular")].derived.subs(z, c)
    ratio = sp.simplify(v / (a * c * gamma * sp.cos(rho * t + rho_p)))
    series = sp.series(sp.simplify(ratio.subs(rho, x * n / c)) - 1, x, 0, 4).removeO()
    (power,), coefficient = sp.Poly(series, x).terms()[-1]
    return coefficient * x**power


def rho_cn_derived(_deps) -> sp.Expr:
    """ρc/n with ρ = √(g/l) and the swing time T = π√(l/g)."""
    g_of_T = sp.solve(sp.Eq(T, sp.pi * sp.sqrt(l / g)), g)[0]
    return sp.simplify((sp.sqrt(g / l) * c / n).subs(g, g_of_T))


def lumped_derived(_deps) -> sp.Expr:
    """Support of mass M on the spring K: M y1'' = Q − y1/K; for Q = γ cos ρt, y1/(KQ) − 1 to first order in K.

    With ρ = √(g/l) (the principal term of Q), the relative correction to δ is K M g/l.
    """
    Q = gamma * sp.cos(rho * t)
    y1 = K * (Q - M * sp.diff(K * Q, t, 2))        # y1 = K(Q − M y1'') iterated once from y1 = KQ
    return sp.simplify(y1 / (K * Q) - 1).subs(rho, sp.sqrt(g / l))


# ----------------------------------------------------------------- printed
def bar_particular_printed() -> sp.Expr:
    return gamma * a * n / rho * sp.cos(rho * t + rho_p) * sp.sin(rho * z / n) / sp.cos(rho * c / n)


PRINTED = {
    "bar_static_limit": a * z * gamma * sp.cos(rho * t + rho_p),
    "K_ac": a * c,
    "rho_cn": sp.pi * c / (n * T),
}


# ----------------------------------------------------------------- checks: the bar's modal expansion
def modal_tip(xv, zf=1):
    """v(z, 0)/(a c γ) at z = zf·c from the modal sum, c = n = a = γ = 1, ρ = x, ρ' = 0."""
    zz = mp.mpf(zf)
    term = lambda k: 2 * mp.sin((k + mp.mpf(1) / 2) * mp.pi) * mp.sin((k + mp.mpf(1) / 2) * mp.pi * zz) / (
        ((k + mp.mpf(1) / 2) * mp.pi) ** 2 - xv**2)
    return mp.nsum(term, [0, mp.inf])


UNIT_BAR = {a: 1, c: 1, n: 1, gamma: 1, rho_p: 0}
MODAL_TEXT = "modal expansion of the forced bar at z = c (mpmath nsum)"


def particular_check(result, level):
    f = sp.lambdify((z, t, rho), result.derived.subs(UNIT_BAR), "mpmath")
    pairs = []
    with mp.workdps(DPS):
        for xv, zf in (("0.3", "1"), ("1.2", "0.6"), ("2.5", "0.35")):
            pairs.append((f"x={xv},z={zf}", f(mp.mpf(zf), 0, mp.mpf(xv)), modal_tip(mp.mpf(xv), zf)))
    return verify.value_check(truth_desc="modal expansion Σ 2 sin λ_k c sin λ_k z/(λ_k² − ρ²), λ_k = (k+½)π "
                              "(c = n = a = γ = 1), summed by mpmath nsum", pairs=pairs, tol=mp.mpf("1e-20"),
                              kind="value")


def static_limit_check(result, level):
    f = sp.lambdify(z, result.derived.subs({**UNIT_BAR, t: 0}), "mpmath")
    return verify.order_check(param="rho c/n", values=RHO_CN(level), truth=lambda xv, dps: modal_tip(xv),
                              derived=lambda xv: f(1), expected=2, band=0.2, truth_desc=MODAL_TEXT)


DYNAMIC_CHECK = checks.Order(
    param="rho c/n", values=RHO_CN, truth=lambda xv, dps: modal_tip(xv) - 1,
    at=lambda expr, xv: verify.value_at(expr, {"x": xv}), expected=4, band=0.2,
    truth_desc=MODAL_TEXT + ", v(c)/(acQ) − 1")


# ----------------------------------------------------------------- checks: the lumped support integrated
KS_LUMPED = Geometric("5e-3", "4e-2")
LUMPED_TEXT = (f"rigid pendulum (m = g = l = 1, h = {H_TRUTH}) on a spring K carrying a mass M = 1, and on a "
               "massless one; δ_M − δ_0 from two mpmath odefun swings, α = 0.003")


def lumped_difference(k, dps):
    """δ_M − δ_0 of the pendulum on a massive (M = 1) and on a massless spring K."""
    ks = mp.nstr(k, 40)
    return (truth.delta_measured("0.003", ks, "1", dps, h_val=H_TRUTH)
            - truth.delta_measured("0.003", ks, "0", dps, h_val=H_TRUTH))


def lumped_order_check(result, level):
    """The dynamic correction to δ is O(K²) (relative O(K))."""
    return verify.order_check(
        param="K", values=KS_LUMPED(level), truth=lumped_difference, derived=lambda k: 0, expected=2, band=0.3,
        truth_desc=LUMPED_TEXT, params=(("M", "1"), ("alpha", "0.003")),
        note=("the dynamic correction to δ is O(K²) (relative O(K)): it shrinks as the support stiffens; "
              "its O(K³) remainder is not resolved: the support vibration left by the O(K²) slow-manifold "
              "start is of the same order"))


def lumped_ratio_check(result, level):
    """The relative correction (δ_M − δ_0)/δ_0 against KMg/l, for K ≤ 0.02."""
    f = sp.lambdify(K, result.derived.subs({M: 1, g: 1, l: 1}), "mpmath")
    ks = KS_LUMPED(level)
    with mp.workdps(DPS):
        pairs = []
        for k in ks:
            if k <= mp.mpf("0.021"):
                d0 = truth.delta_measured("0.003", mp.nstr(k, 40), "0", DPS, h_val=H_TRUTH)
                pairs.append((f"K={mp.nstr(k, 4)}", f(k), lumped_difference(k, DPS) / d0))
    return verify.value_check(truth_desc=LUMPED_TEXT + "; relative correction (δ_M − δ_0)/δ_0 against KMg/l",
                              pairs=pairs, tol=mp.mpf("0.1") * mp.mpf("0.021"), kind="value",
                              note="relative correction KMg/l to within 10 % for K ≤ 0.02")


# ----------------------------------------------------------------- kernel declarations
DYNAMIC_KERNEL = KernelSpec((KernelArg("x", 1e-8, 0.5),), doc="relative dynamic correction, x = ρc/n")
LUMPED_KERNEL = KernelSpec((KernelArg("K", 1e-9, 1e-3), KernelArg("M", 0.1, 1000.0),
                            KernelArg("g", 9.0, 10.0, log=False), KernelArg("l", 0.1, 5.0)),
                           doc="relative dynamic correction K M g/l of a lumped support")


# ----------------------------------------------------------------- the Result table
def specs() -> tuple[Spec, ...]:
    return (
        Spec(rid("bar_particular"), "Forced longitudinal motion of the bar",
             src("bar_forced", "v' = Σ (γan/ρ) cos(ρt + ρ') sin(ρz/n)/cos(ρc/n)"), "v'", bar_particular_derived,
             printed=bar_particular_printed, check=particular_check,
             note="One term of the sum Σ; the resonance denominator cos(ρc/n) vanishes at ρ = (k+½)πn/c."),
        Spec(rid("bar_static_limit"), "Slow load: v' = azQ", src("slow_load", "v' = az Σ γ cos(ρt + ρ'') = zaQ"),
             "v'", static_limit_derived, deps=(rid("bar_particular"),), printed=printed(PRINTED["bar_static_limit"]),
             readings=(Reading("cos(ρt + ρ'')", "cos(ρt + ρ'): the same phase as in Q"),),
             check=static_limit_check),
        Spec(rid("K_ac"), "K = ac", src("slow_load", "y1 = acQ; … on peut en conclure que ac = K"), "K", K_ac_derived,
             deps=(rid("bar_static_limit"),), printed=printed(PRINTED["K_ac"]),
             check=checks.Proof("K = ac", holds=lambda expr: sp.simplify(expr - a * c) == 0, truth="symbolic")),
        Spec(rid("bar_dynamic_correction"), "First term of the dynamic correction: y1 = KQ(1 + (ρc/n)²/3 + …)",
             src("slow_load", "Si ρc/n … est très-petit … en substituant sin(ρz/n) = ρz/n, cos(ρc/n) = 1"),
             r"\frac{y_1}{KQ}-1", dynamic_correction_derived, deps=(rid("bar_particular"),), check=DYNAMIC_CHECK,
             kernel=DYNAMIC_KERNEL,
             note="Not printed: the text only says the correction vanishes with ρc/n; it is (ρc/n)²/3."),
        Spec(rid("rho_cn"), "ρc/n = πc/(nT)", src("principal_rho", "ρ = π/T, ρc/n = πc/(nT)"), r"\rho c/n",
             rho_cn_derived, printed=printed(PRINTED["rho_cn"]), definition=True, check=checks.Definition(),
             readings=(Reading("βc/n", "ρc/n"),)),
        Spec(rid("lumped_dynamic"), "Dynamic correction for a support of mass M (not in the memoir)",
             src("static_deviation", "on peut seulement conjecturer qu'il en est à peu près ainsi quand Q varie "
                 "très-lentement"), r"\delta_M/\delta_0-1", lumped_derived,
             check=checks.All((lumped_order_check, lumped_ratio_check)), kernel=LUMPED_KERNEL,
             note="Lumped analogue of the bar's (ρc/n)²/3: relative correction KMρ² with ρ² = g/l."),
    )
