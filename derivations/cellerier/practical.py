"""Cellérier, δ in practice: the support's compliance measured by a test force, and the worked
example (« De ce qui précède résulte que la valeur trouvée pour δ … » and « expression où
n'entrent que des rapports abstraits … », the end of the text)."""
from __future__ import annotations

import mpmath as mp
import sympy as sp

from pendsym import checks, verify
from pendsym.truth import integrate, turning_time
from pendsym.result import KernelArg, KernelSpec, Reading, Spec
from . import truth
from .common import Geometric, printed, proof_of, rid, src
from .symbols import K, T, eps, g, h, l, m, p, pp


# ----------------------------------------------------------------- derivation
def practical_derived(deps) -> sp.Expr:
    """K = ε/p from the test deflection (y1 = KQ with Q = p), p' = mg."""
    K_measured = sp.solve(sp.Eq(eps, K * p), K)[0]
    return sp.simplify(deps[rid("delta_static")].derived.subs(K, K_measured).subs(m, pp / g))


def example_derived(deps) -> sp.Expr:
    """p = p', l = 1 m, h = 2/3 m; ε in metres."""
    return deps[rid("delta_practical")].derived.subs({p: pp, l: 1, h: sp.Rational(2, 3)})


def g_error_derived(deps) -> sp.Expr:
    """|Δg/g| from g = π² l/T² when T → T(1 + δ), first order in δ: 2δ; with the example δ."""
    d = sp.Symbol("d", positive=True)
    g_of_T = sp.pi**2 * l / T**2
    relative = sp.series((g_of_T - g_of_T.subs(T, T * (1 + d))) / g_of_T, d, 0, 2).removeO()
    return sp.simplify(relative.subs(d, deps[rid("example_delta")].derived))


def eps_bound_derived(deps) -> sp.Expr:
    """ε (in mm) at which the relative error on g reaches 1/100000."""
    solution = sp.solve(sp.Eq(deps[rid("g_error")].derived, sp.Rational(1, 100000)), eps)
    return solution[0] * 1000


# ----------------------------------------------------------------- printed
PRINTED = {
    "delta_practical": eps / l * h / l * pp / p / 2,
    "example_delta": eps / 3,
    "g_error": 2 * eps / 3,
    "eps_bound": sp.Rational(15, 1000),
}


# ----------------------------------------------------------------- checks
EXAMPLE_CHECK = checks.Order(   # the worked example's own pendulum (l = 1, h = 2/3, p = p' = mg): ε = K p
    param="epsilon", values=Geometric("1e-2", "4e-2"),
    truth=lambda e, dps: truth.delta_measured("0.003", mp.nstr(e, 40), "0", dps, h_val="2/3"),
    at=lambda expr, e: verify.value_at(expr, {"epsilon": e}), expected=2, band=0.3,
    truth_desc=("rigid pendulum with l = 1, h = 2/3 (m = g = 1) on a massless spring deflected ε by p = p' = mg, "
                "slow-manifold start at α = 0.003, mpmath odefun; δ = T/T0 − 1"),
    params=(("h/l", "2/3"), ("alpha", "0.003")), note="ε in units of l; residual O(ε²)")


def g_error_check(result, level):
    """The free pendulum integrated with l and with l(1+δ)²: g inferred from T = π√(l/g) is off by ≈ 2δ."""
    # δ stands for ε/3 here: the derived form is (2/3)ε → 2δ
    f = sp.lambdify(eps, result.derived, "mpmath")

    def relative_error(e, dps):
        with mp.workdps(dps):
            d = e / 3                                           # the example's δ
            traj = integrate(lambda tt, y: [y[1], -mp.sin(y[0]) / (1 + d) ** 2], [mp.mpf("0.01"), 0], dps)
            T1 = turning_time(traj, mp.pi * (1 + d), width=mp.mpf("0.2"))
            T0 = 2 * mp.ellipk(mp.sin(mp.mpf("0.005")) ** 2)
            return 1 - (T0 / T1) ** 2                            # g_inferred/g − 1 with g ∝ 1/T²
    return verify.order_check(param="epsilon", values=Geometric("1e-4", "1e-2")(level), truth=relative_error,
                              derived=lambda e: f(e), expected=2, band=0.3,
                              truth_desc="swing time of θ'' = −sin θ/(1+δ)² (length stretched so T grows by 1+δ), "
                                         "α = 0.01, mpmath odefun; relative error of g ∝ 1/T²")


# ----------------------------------------------------------------- kernel declarations
PRACTICAL_KERNEL = KernelSpec((KernelArg("epsilon", 1e-8, 1e-3, unit="m"), KernelArg("l", 0.1, 5.0, unit="m"),
                               KernelArg("h", 0.01, 2.0, unit="m"), KernelArg("p'", 0.1, 1000.0, unit="N"),
                               KernelArg("p", 0.1, 1000.0, unit="N")),
                              doc="δ = ½ (ε/l)(h/l)(p'/p)")
G_ERROR_KERNEL = KernelSpec((KernelArg("epsilon", 1e-8, 1e-3, unit="m"),),
                            doc="relative error on g for the worked example (l = 1 m, h = 2/3 m, p = p')")


# ----------------------------------------------------------------- the Result table
def specs() -> tuple[Spec, ...]:
    return (
        Spec(rid("delta_practical"), "δ = ½ (ε/l)(h/l)(p'/p)",
             src("test_force", "on aura alors K = ε/p; … δ = ½ · ε/l · h/l · p'/p"), r"\delta", practical_derived,
             deps=(rid("delta_static"),), printed=printed(PRINTED["delta_practical"]), kernel=PRACTICAL_KERNEL,
             readings=(Reading("K = ı/p", "K = ε/p"),), check=checks.Chain((rid("example_delta"),))),
        Spec(rid("example_delta"), "δ = ε/3 for p = p', l = 1 m, h = 2/3 m",
             src("example", "en supposant … que la force p soit égale au poids même du pendule, … l = 1, h = 2/3, on "
                 "trouvera δ = (1/3)·ε"), r"\delta", example_derived, deps=(rid("delta_practical"),),
             printed=printed(PRINTED["example_delta"]), check=EXAMPLE_CHECK, note="ε in metres (l = 1 m)."),
        Spec(rid("g_error"), "Relative error on g: 2δ = (2/3)ε",
             src("example", "l'erreur relative qui résulterait de celle-là pour la valeur de g serait 3 c"),
             r"\Delta g/g", g_error_derived, deps=(rid("example_delta"),), printed=printed(PRINTED["g_error"]),
             readings=(Reading("3 c", "⅔ ε: the next line writes (2/3) ε < 1/100000", certain=False),),
             check=g_error_check, kernel=G_ERROR_KERNEL),
        Spec(rid("eps_bound"), "ε < 0.015 mm keeps the fourth decimal of g",
             src("example", "(2/3) ε < 1/100000, ε < 0mm,015"), r"\varepsilon_{max}\,[\mathrm{mm}]", eps_bound_derived,
             deps=(rid("g_error"),), printed=printed(PRINTED["eps_bound"]), check=proof_of(sp.Rational(3, 200)),
             readings=(Reading("0mm,015", "0.015 mm"),),
             note="The fourth decimal of g ≈ 9.8 m/s² is read as a relative error 1/100000, as the text writes."),
    )
