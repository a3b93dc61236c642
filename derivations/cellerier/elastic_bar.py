"""Cellérier p. 7–9: the support as an elastic bar, and the dynamic correction to y1 = KQ.

Bar AO of length c fixed at A (z = 0), loaded at O (z = c) by Q = Σ γ cos(ρt + ρ'):
v_tt = n² v_zz, v(0) = 0, v_z(c) = aQ.  The independent truth for the bar is
its modal expansion (eigenfunctions sin λ_k z, λ_k = (k + ½)π/c) summed by
mpmath nsum; for the pendulum, the lumped support (mass M on the spring K)
integrated with the pendulum (derivations.cellerier.truth).
"""
from __future__ import annotations

import mpmath as mp
import sympy as sp

from pendsym import verify
from pendsym import pipeline
from pendsym.result import KernelArg, KernelSpec, Reading, Spec
from . import truth as tr
from .equation import MEMOIR, src
from .static_support import H_TRUTH
from .symbols import K, M, Q, T, a, c, g, gamma, h, l, m, n, rho, rho_p, t, x, z

A_ = sp.Symbol("A")


def bar_particular_derived(_deps) -> sp.Expr:
    """v' = A sin(ρz/n) cos(ρt + ρ'): satisfies the wave equation and v(0) = 0; A from v_z(c) = aγ cos (p. 8)."""
    v = A_ * sp.sin(rho * z / n) * sp.cos(rho * t + rho_p)
    if sp.simplify(sp.diff(v, t, 2) - n**2 * sp.diff(v, z, 2)) != 0 or v.subs(z, 0) != 0:
        raise ValueError("the ansatz does not solve the wave equation")
    Av = sp.solve(sp.Eq(sp.diff(v, z).subs(z, c), a * gamma * sp.cos(rho * t + rho_p)), A_)[0]
    return sp.simplify(v.subs(A_, Av))


def bar_particular_printed() -> sp.Expr:
    return gamma * a * n / rho * sp.cos(rho * t + rho_p) * sp.sin(rho * z / n) / sp.cos(rho * c / n)


def static_limit_derived(deps) -> sp.Expr:
    """ρ → 0 (slow load): v' → a z γ cos(ρt + ρ') = a z Q (p. 8)."""
    v = deps[f"{MEMOIR}.bar_particular"].derived
    # ρ → 0 in the spatial factor only (ρt + ρ' is the load's phase, kept)
    spatial = sp.simplify(v / sp.cos(rho * t + rho_p))
    return sp.limit(spatial, rho, 0) * sp.cos(rho * t + rho_p)


def static_limit_printed() -> sp.Expr:
    return a * z * gamma * sp.cos(rho * t + rho_p)


def K_ac_derived(deps) -> sp.Expr:
    """K from y1 = KQ and, at z = c, y1 = acQ (p. 8)."""
    v = deps[f"{MEMOIR}.bar_static_limit"].derived.subs(z, c)
    Qv = gamma * sp.cos(rho * t + rho_p)
    return sp.solve(sp.Eq(K * Qv, v), K)[0]


def dynamic_correction_derived(deps) -> sp.Expr:
    """First term in x = ρc/n of v'(c)/(acQ) − 1 (the dynamic correction to y1 = KQ) (p. 8–9)."""
    v = deps[f"{MEMOIR}.bar_particular"].derived.subs(z, c)
    ratio = sp.simplify(v / (a * c * gamma * sp.cos(rho * t + rho_p)))
    ratio_x = sp.simplify(ratio.subs(rho, x * n / c))
    ser = sp.series(ratio_x - 1, x, 0, 4).removeO()
    return sp.Poly(ser, x).terms()[-1][1] * x ** sp.Poly(ser, x).terms()[-1][0][0]


def rho_cn_derived(_deps) -> sp.Expr:
    """ρc/n with ρ = √(g/l) and the swing time T = π√(l/g) (p. 8)."""
    gsol = sp.solve(sp.Eq(T, sp.pi * sp.sqrt(l / g)), g)[0]
    return sp.simplify((sp.sqrt(g / l) * c / n).subs(g, gsol))


def lumped_derived(_deps) -> sp.Expr:
    """Support of mass M on the spring K: M y1'' = Q − y1/K; for Q = γ cos ρt, y1/(KQ) − 1 to first order in K.

    With ρ = √(g/l) (the principal term of Q), the relative correction to δ is K M g/l.
    """
    Qt = gamma * sp.cos(rho * t)
    # iterate y1 = K(Q − M y1'') once from y1 = KQ
    y1 = K * (Qt - M * sp.diff(K * Qt, t, 2))
    corr = sp.simplify(y1 / (K * Qt) - 1)
    return corr.subs(rho, sp.sqrt(g / l))


# ---------------------------------------------------------------- checks
def modal_tip(xv, zf=1):
    """v(z, 0)/(a c γ) at z = zf·c from the modal sum, c = n = a = γ = 1, ρ = x, ρ' = 0."""
    zz = mp.mpf(zf)
    term = lambda k: 2 * mp.sin((k + mp.mpf(1) / 2) * mp.pi) * mp.sin((k + mp.mpf(1) / 2) * mp.pi * zz) / (
        ((k + mp.mpf(1) / 2) * mp.pi) ** 2 - xv**2)
    return mp.nsum(term, [0, mp.inf])


def _particular_check(result, level):
    f = sp.lambdify((z, t, rho), result.derived.subs({a: 1, c: 1, n: 1, gamma: 1, rho_p: 0}), "mpmath")
    pairs = []
    with mp.workdps(30):
        for xv, zf in (("0.3", "1"), ("1.2", "0.6"), ("2.5", "0.35")):
            pairs.append((f"x={xv},z={zf}", f(mp.mpf(zf), 0, mp.mpf(xv)), modal_tip(mp.mpf(xv), zf)))
    return verify.value_check(truth_desc="modal expansion Σ 2 sin λ_k c sin λ_k z/(λ_k² − ρ²), λ_k = (k+½)π "
                              "(c = n = a = γ = 1), summed by mpmath nsum", pairs=pairs, tol=mp.mpf("1e-20"),
                              kind="value")


def _static_limit_check(result, level):
    f = sp.lambdify(z, result.derived.subs({a: 1, c: 1, n: 1, gamma: 1, rho_p: 0, t: 0}), "mpmath")
    return verify.order_check(param="rho c/n", values=verify.geometric("0.01", "0.1", verify.LEVELS[level]),
                              truth=lambda xv, dps: modal_tip(xv), derived=lambda xv: f(1), expected=2, band=0.2,
                              truth_desc="modal expansion of the forced bar at z = c (mpmath nsum)")


def _dynamic_check(result, level):
    f = sp.lambdify(x, result.derived, "mpmath")
    return verify.order_check(param="rho c/n", values=verify.geometric("0.01", "0.1", verify.LEVELS[level]),
                              truth=lambda xv, dps: modal_tip(xv) - 1, derived=lambda xv: f(xv), expected=4, band=0.2,
                              truth_desc="modal expansion of the forced bar at z = c (mpmath nsum), v(c)/(acQ) − 1")


def _lumped_check(result, level):
    """δ_M − δ_0 of the pendulum on a massive spring: its order in K, and its ratio to δ_0·KMg/l."""
    Ks = verify.geometric("5e-3", "4e-2", verify.LEVELS[level])
    f = sp.lambdify(K, result.derived.subs({M: 1, g: 1, l: 1}), "mpmath")

    def truth_diff(k, dps):
        ks = mp.nstr(k, 40)
        return (tr.delta_measured("0.003", ks, "1", dps, h_val=H_TRUTH)
                - tr.delta_measured("0.003", ks, "0", dps, h_val=H_TRUTH))
    desc = (f"rigid pendulum (m = g = l = 1, h = {H_TRUTH}) on a spring K carrying a mass M = 1, and on a "
            "massless one; δ_M − δ_0 from two mpmath odefun swings, α = 0.003")
    order = verify.order_check(
        param="K", values=Ks, truth=truth_diff, derived=lambda k: 0, expected=2, band=0.3,
        truth_desc=desc, params=(("M", "1"), ("alpha", "0.003")),
        note=("the dynamic correction to δ is O(K²) (relative O(K)): it shrinks as the support stiffens; "
              "its O(K³) remainder is not resolved: the support vibration left by the O(K²) slow-manifold "
              "start is of the same order"))
    with mp.workdps(30):
        pairs = []
        for k in Ks:
            if k <= mp.mpf("0.021"):
                d0 = tr.delta_measured("0.003", mp.nstr(k, 40), "0", 30, h_val=H_TRUTH)
                pairs.append((f"K={mp.nstr(k, 4)}", f(k), truth_diff(k, 30) / d0))
    ratio = verify.value_check(truth_desc=desc + "; relative correction (δ_M − δ_0)/δ_0 against KMg/l",
                               pairs=pairs, tol=mp.mpf("0.1") * mp.mpf("0.021"), kind="value",
                               note="relative correction KMg/l to within 10 % for K ≤ 0.02")
    return verify.combine(order, ratio)


def specs() -> tuple[Spec, ...]:
    Pm = MEMOIR
    return (
        Spec(f"{Pm}.bar_particular", "Forced longitudinal motion of the bar",
             src("v' = Σ (γan/ρ) cos(ρt + ρ') sin(ρz/n)/cos(ρc/n) (p. 8)"), "v'", bar_particular_derived,
             printed=bar_particular_printed, check=_particular_check,
             note="One term of the sum Σ; the resonance denominator cos(ρc/n) vanishes at ρ = (k+½)πn/c."),
        Spec(f"{Pm}.bar_static_limit", "Slow load: v' = azQ", src("v' = az Σ γ cos(ρt + ρ'') = zaQ (p. 8)"), "v'",
             static_limit_derived, deps=(f"{Pm}.bar_particular",), printed=static_limit_printed,
             readings=(Reading("cos(ρt + ρ'')", "cos(ρt + ρ'): the same phase as in Q"),),
             check=_static_limit_check),
        Spec(f"{Pm}.K_ac", "K = ac", src("y1 = acQ; … on peut en conclure que ac = K (p. 8)"), "K", K_ac_derived,
             deps=(f"{Pm}.bar_static_limit",), printed=lambda: a * c,
             check=lambda r, lv: verify.proof(statement="K = ac", holds=sp.simplify(r.derived - a * c) == 0,
                                              truth_desc="symbolic")),
        Spec(f"{Pm}.bar_dynamic_correction", "First term of the dynamic correction: y1 = KQ(1 + (ρc/n)²/3 + …)",
             src("Si ρc/n … est très-petit … en substituant sin(ρz/n) = ρz/n, cos(ρc/n) = 1 (p. 8)"),
             r"\frac{y_1}{KQ}-1", dynamic_correction_derived, deps=(f"{Pm}.bar_particular",), check=_dynamic_check,
             kernel=KernelSpec((KernelArg("x", 1e-8, 0.5),), doc="relative dynamic correction, x = ρc/n"),
             note="Not printed: the text only says the correction vanishes with ρc/n; it is (ρc/n)²/3."),
        Spec(f"{Pm}.rho_cn", "ρc/n = πc/(nT)", src("ρ = π/T, ρc/n = πc/(nT) (p. 8)"), r"\rho c/n", rho_cn_derived,
             printed=lambda: sp.pi * c / (n * T), definition=True, check=pipeline.definition_check,
             readings=(Reading("βc/n", "ρc/n"),)),
        Spec(f"{Pm}.lumped_dynamic", "Dynamic correction for a support of mass M (not in the memoir)",
             src("on peut seulement conjecturer qu'il en est à peu près ainsi quand Q varie très-lentement (p. 6)"),
             r"\delta_M/\delta_0-1", lumped_derived, check=_lumped_check,
             kernel=KernelSpec((KernelArg("K", 1e-9, 1e-3), KernelArg("M", 0.1, 1000.0), KernelArg("g", 9.0, 10.0, log=False),
                                KernelArg("l", 0.1, 5.0)), doc="relative dynamic correction K M g/l of a lumped support"),
             note="Lumped analogue of the bar's (ρc/n)²/3: relative correction KMρ² with ρ² = g/l."),
    )
