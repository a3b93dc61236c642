"""Cellérier, δ for a support of static compliance K (y1 = K Q): from « En substituant les valeurs
de μ' et de u … » to « d'où résulte, en remplaçant de même cos θ par 1 … δ = Kmgh/(2l²) ».

The heart of the verification: the rigid pendulum on a spring (derivations.cellerier.truth)
integrated at 30 digits; (T − T0)/T0 against δ = Kmgh/(2l²), order fitted in K.
"""
from __future__ import annotations

import mpmath as mp
import sympy as sp

from pendsym import checks, finite_amplitude, verify
from pendsym.result import KernelArg, KernelSpec, Reading, Spec
from . import truth
from .common import DPS, H_TRUTH, Geometric, printed, read_l_as_t, rid, series_leading, src
from .pressures import on_free
from .symbols import K, alpha, g, h, l, m, phi, theta, u, x1dd, y1dd

x1dd_of_phi, y1dd_of_phi = sp.Function("x1dd"), sp.Function("y1dd")   # x1'', y1'' along the swing (of φ)
X_TESTS = (sp.Lambda(phi, sp.cos(phi) / 3 + phi / 7), sp.Lambda(phi, sp.sin(3 * phi) - sp.Rational(1, 5)))
Y_TESTS = (sp.Lambda(phi, sp.cos(2 * phi) + phi**2 / 9), sp.Lambda(phi, sp.exp(-phi) / 2))
XY_INSTANCES = tuple(((x1dd_of_phi, x), (y1dd_of_phi, y)) for x, y in zip(X_TESTS, Y_TESTS))
KS = Geometric("5e-3", "4e-2")          # the compliance K of the checks


# ----------------------------------------------------------------- derivation
def theta_of_phi() -> tuple[tuple[sp.Symbol, sp.Expr], ...]:
    """θ as a function of φ and α (cos θ = cos α cos²φ + sin²φ, p. 2): the definition under which δ's printed
    and derived forms are compared.  Derived when the Specs are built, not when the module is imported."""
    return ((theta, finite_amplitude.free_angle()),)


def u_of_mu(mu: sp.Expr) -> sp.Expr:
    """u = μ'/(2 m g sin ½α), as the text defines it."""
    return mu / (2 * m * g * sp.sin(alpha / 2))


def mu_prime_with(deps, x1_accel, y1_accel) -> sp.Expr:
    """μ' with the given x1'', y1''."""
    return deps[rid("mu_prime")].derived.subs({x1dd: x1_accel, y1dd: y1_accel})


def delta_support_derived(deps) -> sp.Expr:
    """δ of the general formula with u = μ'/(2mg sin ½α), μ' = mh(sin θ x1'' − cos θ y1'')."""
    general = deps[rid("delta_general")].derived
    mu = mu_prime_with(deps, x1dd_of_phi(phi), y1dd_of_phi(phi))
    return sp.simplify(general.replace(u, sp.Lambda(phi, u_of_mu(mu))))


def Q_static_derived(deps) -> sp.Expr:
    """Q on the free swing: θ'' = −(g/l) sin θ, θ'² = (2g/l)(cos θ − cos α)."""
    return on_free(deps[rid("Q_reduced")].derived)


def Q_leading_derived(deps) -> sp.Expr:
    """(mgh/l)θ: first order of Q in θ and α together ('les termes suivants … de l'ordre α³ ou θ³')."""
    return series_leading(deps[rid("Q_static")].derived, {theta: theta, alpha: alpha}, 2)


def sin_theta_derived(_deps) -> sp.Expr:
    """sin θ from cos θ = cos α cos²φ + sin²φ."""
    return sp.expand_trig(sp.sin(finite_amplitude.free_angle()))


def radical_error_derived(deps) -> sp.Expr:
    """1 − radical at α = 2°, φ = 0 (its largest value): the relative error of 'radical → 1'."""
    sin_theta = deps[rid("sin_theta")].derived
    radical = sp.simplify(sin_theta / (2 * sp.sin(alpha / 2) * sp.cos(phi)))
    return sp.nsimplify(1) - radical.subs({phi: 0, alpha: 2 * sp.pi / 180})


def y1dd_derived(deps) -> sp.Expr:
    """y1'' = K Q'' with Q → (mgh/l)θ, θ'' = −(g/l) sin θ, the radical → 1."""
    coefficient = sp.simplify(deps[rid("Q_leading")].derived / theta)          # mgh/l
    sin_theta = deps[rid("sin_theta")].derived
    s = sp.Symbol("s", positive=True)
    sin_theta_leading = series_leading(sin_theta.subs(sp.sin(alpha / 2), s), {s: s}, 1).subs(s, sp.sin(alpha / 2))
    return K * coefficient * (-g / l) * sin_theta_leading


def delta_static_integral_derived(deps) -> sp.Expr:
    """δ of the general formula with x1'' = 0, y1'' of the previous result, cos θ → 1."""
    mu = mu_prime_with(deps, 0, deps[rid("y1dd")].derived).subs(sp.cos(theta), 1)
    general = deps[rid("delta_general")].derived
    return sp.simplify(general.replace(u, sp.Lambda(phi, sp.simplify(u_of_mu(mu)))))


def delta_static_derived(deps) -> sp.Expr:
    return sp.simplify(deps[rid("delta_static_integral")].derived.doit())


# ----------------------------------------------------------------- printed
def delta_support_printed() -> sp.Expr:
    integrand = (sp.sin(theta) * x1dd_of_phi(phi) - sp.cos(theta) * y1dd_of_phi(phi)) * sp.cos(phi) / sp.sin(alpha / 2)
    return sp.Integral(integrand, (phi, 0, sp.pi)) / (2 * sp.pi * g)


def Q_static_printed() -> sp.Expr:
    return (2 * g * m * h / l * (sp.cos(theta) - sp.cos(alpha)) * sp.sin(theta)
            + m * g * h / l * sp.sin(theta) * sp.cos(theta))


def sin_theta_printed() -> sp.Expr:
    return 2 * sp.sin(alpha / 2) * sp.cos(phi) * sp.sqrt(1 - sp.sin(alpha / 2) ** 2 * sp.cos(phi) ** 2)


PRINTED = {
    "Q_leading": m * g * h / l * theta,
    "y1dd": -2 * K * m * g**2 * h / l**2 * sp.sin(alpha / 2) * sp.cos(phi),
    "delta_static_integral": K * m * h * g / (sp.pi * l**2) * sp.Integral(sp.cos(phi) ** 2, (phi, 0, sp.pi)),
    "delta_static": K * m * g * h / (2 * l**2),
}


# ----------------------------------------------------------------- checks
def static_truth_text(alpha_val: str) -> str:
    return (f"rigid pendulum (m = g = l = 1, h = {H_TRUTH}, C = mhl) on a massless spring of compliance K, "
            f"Euler–Lagrange equations by SymPy, slow-manifold start at rest at α = {alpha_val}, "
            "mpmath odefun; δ = T/T0 − 1 with T0 = 2K(sin²½α)/ω0")


DELTA_STATIC_CHECK = checks.Order(   # printed = derived: both fitted
    param="K", values=KS, truth=lambda k, dps: truth.delta_measured("0.003", mp.nstr(k, 40), "0", dps, h_val=H_TRUTH),
    at=lambda expr, k: verify.value_at(expr, {"K": k, "m": 1, "g": 1, "l": 1, "h": H_TRUTH}),
    expected=2, band=0.3, truth_desc=static_truth_text("0.003"), params=(("alpha", "0.003"), ("h/l", H_TRUTH)),
    note="small amplitude: residual O(K²) (α² K negligible)")


def Q_static_check(result, level):
    f = sp.lambdify((theta, alpha), result.derived.subs({m: 1, g: 1, h: 1, l: 1}), "mpmath")
    pairs = []
    with mp.workdps(DPS):
        traj = truth.free_swing_trajectory("0.8", DPS)
        for s in (mp.mpf("0.5"), mp.mpf("1.9")):
            Q_newton = -mp.diff(lambda x: mp.sin(traj(x)[0]), s, 2, h=mp.mpf("1e-7"))
            pairs.append((f"t={s}", f(traj(s)[0], mp.mpf("0.8")), Q_newton))
    return verify.value_check(truth_desc="θ'' = −sin θ, α = 0.8 (mpmath odefun); Q = −m(h sin θ)'' by numerical "
                              "differentiation (step 1e-7)", pairs=pairs, tol=mp.mpf("1e-10"), kind="value")


def is_first_degree(expr: sp.Expr) -> bool:
    """Q's series to degree 2 in (θ, α) scaled together is homogeneous of degree 1: no degree-2 term."""
    lam = sp.Symbol("lambda", positive=True)
    return sp.expand(expr.subs({theta: lam * theta, alpha: lam * alpha}, simultaneous=True) - lam * expr) == 0


def sin_theta_check(result, level):
    f = sp.lambdify((alpha, phi), result.derived, "mpmath")
    pairs = []
    with mp.workdps(DPS):
        for a, ph in (("0.4", "0.3"), ("1.9", "2.2"), ("1.0", "1.4")):
            A, PH = mp.mpf(a), mp.mpf(ph)
            target = mp.cos(A) * mp.cos(PH) ** 2 + mp.sin(PH) ** 2
            th = mp.findroot(lambda x: mp.cos(x) - target, A * mp.cos(PH))
            th = abs(th) * (1 if mp.cos(PH) > 0 else -1)
            pairs.append((f"alpha={a},phi={ph}", f(A, PH), mp.sin(th)))
    return verify.value_check(truth_desc="θ from cos θ = cos α cos²φ + sin²φ by mpmath findroot, sign of cos φ",
                              pairs=pairs, tol=mp.mpf("1e-25"), kind="value")


def radical_check(result, level):
    with mp.workdps(DPS):
        a = 2 * mp.pi / 180
        worst = max(1 - mp.sqrt(1 - mp.sin(a / 2) ** 2 * mp.cos(mp.pi * i / 200) ** 2) for i in range(201))
        return verify.value_check(truth_desc="largest 1 − √(1 − sin²1° cos²φ) over 201 points of [0, π]",
                                  pairs=[("alpha=2deg", sp.N(result.derived, 40), worst)], tol=mp.mpf("1e-25"),
                                  kind="value")


# ----------------------------------------------------------------- kernel declarations
DELTA_KERNEL = KernelSpec((KernelArg("K", 1e-9, 1e-3), KernelArg("m", 0.01, 100.0),
                           KernelArg("g", 9.0, 10.0, log=False), KernelArg("h", 0.01, 2.0), KernelArg("l", 0.1, 5.0)),
                          doc="relative lengthening of the swing on a support of static compliance K (m/N)")


# ----------------------------------------------------------------- the Result table
def specs() -> tuple[Spec, ...]:
    return (
        Spec(rid("delta_support"), "δ for the motion of the knife edge",
             src("substitution", "δ = 1/(2πg) ∫_0^π [sin θ d²x1/dt² − cos θ d²y1/dt²] cos φ/sin ½α dφ"), r"\delta",
             delta_support_derived, deps=(rid("delta_general"), rid("mu_prime")), printed=delta_support_printed,
             defs=theta_of_phi(), instances=XY_INSTANCES, check=checks.Chain((rid("delta_general"), rid("mu_prime"))),
             note="x1'', y1'' along the swing are arbitrary functions of φ (compared on test functions). "
                  "Verified through its two ingredients; no integration with a prescribed support motion yet."),
        Spec(rid("Q_static"), "Q on the free swing",
             src("static_deviation", "La valeur exacte de Q est: Q = (2gmh/l)(cos θ − cos α) sin θ + (mgh/l) sin θ cos θ"),
             "Q", Q_static_derived, deps=(rid("Q_reduced"),), printed=Q_static_printed, check=Q_static_check),
        Spec(rid("Q_leading"), "Q = (mgh/l)θ + O(α³)", src("static_deviation", "= (mgh/l)(θ + etc.)"), "Q",
             Q_leading_derived, deps=(rid("Q_static"),), printed=printed(PRINTED["Q_leading"]),
             check=checks.Proof("the series of Q in (θ, α) scaled together has no term of degree 2",
                                holds=is_first_degree, truth="SymPy series")),
        Spec(rid("sin_theta"), "sin θ in terms of φ", src("sin_theta", "sin θ = 2 sin ½α cos φ √(1 − sin²½α cos²φ)"),
             r"\sin\theta", sin_theta_derived, printed=sin_theta_printed, check=sin_theta_check),
        Spec(rid("radical_error"), "Relative error of √(1 − sin²½α cos²φ) → 1 for α ≤ 2°",
             src("radical", "en supposant que α ne dépasse pas 2°, le radical précédent peut être remplacé par "
                 "l'unité, l'erreur relative ne dépassant pas 1 … (the bound is cut off in the file)"),
             r"1-\sqrt{1-\sin^2 1^\circ}", radical_error_derived, deps=(rid("sin_theta"),),
             check=radical_check, note="≈ 1.52e-4 ≈ 1/6566; the printed bound is lost in the OCR after '1'."),
        Spec(rid("y1dd"), "y1'' to the leading order", src("radical", "d²y1/dt² = −(2Kmg²h/t²) sin ½α cos φ"),
             r"y_1''", y1dd_derived, deps=(rid("Q_leading"), rid("sin_theta")), printed=printed(PRINTED["y1dd"]),
             readings=(read_l_as_t("t²", "l²"), Reading("g_1 = KQ", "y1 = KQ")),
             check=checks.Chain((rid("delta_static"),)),
             note="y1 = KQ (the horizontal deflection; the text's x1 is vertical and neglected)."),
        Spec(rid("delta_static_integral"), "δ as an integral for the static support",
             src("cos_theta_one", "δ = (Kmhg/(πl²)) ∫_0^π cos²φ dφ"), r"\delta", delta_static_integral_derived,
             deps=(rid("delta_general"), rid("mu_prime"), rid("y1dd")),
             printed=printed(PRINTED["delta_static_integral"]), check=checks.Chain((rid("delta_static"),)),
             note="cos θ → 1 as the text does ('en remplaçant de même cos θ par 1')."),
        Spec(rid("delta_static"), "δ = Kmgh/(2l²)", src("cos_theta_one", "δ = … = Kmgh/(2l²)"), r"\delta",
             delta_static_derived, deps=(rid("delta_static_integral"),), printed=printed(PRINTED["delta_static"]),
             check=DELTA_STATIC_CHECK, kernel=DELTA_KERNEL, show_values=True),
    )
