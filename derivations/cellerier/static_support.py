"""Cellérier p. 4–7 and 10: δ for a support of static compliance K (y1 = K Q) and its practical form.

The heart of the verification: the rigid pendulum on a spring (derivations.cellerier.truth)
integrated at 30 digits; (T − T0)/T0 against δ = Kmgh/(2l²), order fitted in K.
"""
from __future__ import annotations

from functools import lru_cache

import mpmath as mp
import sympy as sp

from pendsym import finite_amplitude as fa
from pendsym import truth as ptruth
from pendsym import verify
from pendsym import pipeline
from pendsym.result import KernelArg, KernelSpec, Reading, Spec
from . import truth as tr
from .equation import MEMOIR, src
from .pressures import _free_traj, on_free, reduced
from .symbols import K, T, alpha, eps, g, h, l, m, p, phi, pp, theta, thetad, thetadd, u, x1dd, y1dd

Xf, Yf = sp.Function("x1dd"), sp.Function("y1dd")       # x1'', y1'' along the swing, as functions of φ
X_TESTS = (sp.Lambda(phi, sp.cos(phi) / 3 + phi / 7), sp.Lambda(phi, sp.sin(3 * phi) - sp.Rational(1, 5)))
Y_TESTS = (sp.Lambda(phi, sp.cos(2 * phi) + phi**2 / 9), sp.Lambda(phi, sp.exp(-phi) / 2))
XY_INSTANCES = tuple(((Xf, a), (Yf, b)) for a, b in zip(X_TESTS, Y_TESTS))
THETA_PHI = ((theta, fa.free_angle()),)
S_, C_, W_ = tr.S, tr.Cc, tr.W
H_TRUTH = "0.2"            # h/l of the model pendulum (m = g = l = 1, C = m h l)


def u_of_mu(mu: sp.Expr) -> sp.Expr:
    """u = μ'/(2 m g sin ½α) (p. 3)."""
    return mu / (2 * m * g * sp.sin(alpha / 2))


def _mu(deps, xdd, ydd) -> sp.Expr:
    return deps[f"{MEMOIR}.mu_prime"].derived.subs({x1dd: xdd, y1dd: ydd})


def delta_support_derived(deps) -> sp.Expr:
    """δ of the general formula with u = μ'/(2mg sin ½α), μ' = mh(sin θ x1'' − cos θ y1'') (p. 4)."""
    gen = deps[f"{MEMOIR}.delta_general"].derived
    mu = _mu(deps, Xf(phi), Yf(phi))
    return sp.simplify(gen.replace(u, sp.Lambda(phi, u_of_mu(mu))))


def delta_support_printed() -> sp.Expr:
    return sp.Integral((sp.sin(theta) * Xf(phi) - sp.cos(theta) * Yf(phi)) * sp.cos(phi) / sp.sin(alpha / 2),
                       (phi, 0, sp.pi)) / (2 * sp.pi * g)


def Q_static_derived(deps) -> sp.Expr:
    """Q on the free swing: θ'' = −(g/l) sin θ, θ'² = (2g/l)(cos θ − cos α) (p. 5)."""
    return on_free(deps[f"{MEMOIR}.Q_reduced"].derived)


def Q_static_printed() -> sp.Expr:
    return 2 * g * m * h / l * (sp.cos(theta) - sp.cos(alpha)) * sp.sin(theta) + m * g * h / l * sp.sin(theta) * sp.cos(theta)


def _series_leading(expr: sp.Expr, scale: dict, order: int) -> sp.Expr:
    lam = sp.Symbol("lambda", positive=True)
    ser = sp.series(expr.subs({k: lam * v for k, v in scale.items()}, simultaneous=True), lam, 0, order + 1).removeO()
    return sp.expand(ser.subs(lam, 1))


def Q_leading_derived(deps) -> sp.Expr:
    """(mgh/l)θ: first order of Q in θ and α together (p. 5, 'les termes suivants … de l'ordre α³ ou θ³')."""
    return _series_leading(deps[f"{MEMOIR}.Q_static"].derived, {theta: theta, alpha: alpha}, 2)


def sin_theta_derived(_deps) -> sp.Expr:
    """sin θ from cos θ = cos α cos²φ + sin²φ (p. 6)."""
    return sp.expand_trig(sp.sin(fa.free_angle()))


def sin_theta_printed() -> sp.Expr:
    return 2 * sp.sin(alpha / 2) * sp.cos(phi) * sp.sqrt(1 - sp.sin(alpha / 2) ** 2 * sp.cos(phi) ** 2)


def radical_error_derived(deps) -> sp.Expr:
    """1 − radical at α = 2°, φ = 0 (its largest value): the relative error of 'radical → 1' (p. 6)."""
    st = deps[f"{MEMOIR}.sin_theta"].derived
    radical = sp.simplify(st / (2 * sp.sin(alpha / 2) * sp.cos(phi)))
    return sp.nsimplify(1) - radical.subs({phi: 0, alpha: 2 * sp.pi / 180})


def y1dd_derived(deps) -> sp.Expr:
    """y1'' = K Q'' with Q → (mgh/l)θ, θ'' = −(g/l) sin θ, the radical → 1 (p. 6)."""
    Ql = deps[f"{MEMOIR}.Q_leading"].derived
    coeff = sp.simplify(Ql / theta)                          # mgh/l
    st = deps[f"{MEMOIR}.sin_theta"].derived
    s = sp.Symbol("s", positive=True)
    st_lead = _series_leading(st.subs(sp.sin(alpha / 2), s), {s: s}, 1).subs(s, sp.sin(alpha / 2))
    return K * coeff * (-g / l) * st_lead


def y1dd_printed() -> sp.Expr:
    return -2 * K * m * g**2 * h / l**2 * sp.sin(alpha / 2) * sp.cos(phi)


def delta_static_integral_derived(deps) -> sp.Expr:
    """δ of the general formula with x1'' = 0, y1'' of the previous result, cos θ → 1 (p. 6)."""
    mu = _mu(deps, 0, deps[f"{MEMOIR}.y1dd"].derived).subs(sp.cos(theta), 1)
    gen = deps[f"{MEMOIR}.delta_general"].derived
    return sp.simplify(gen.replace(u, sp.Lambda(phi, sp.simplify(u_of_mu(mu)))))


def delta_static_integral_printed() -> sp.Expr:
    return K * m * h * g / (sp.pi * l**2) * sp.Integral(sp.cos(phi) ** 2, (phi, 0, sp.pi))


def delta_static_derived(deps) -> sp.Expr:
    return sp.simplify(deps[f"{MEMOIR}.delta_static_integral"].derived.doit())


# ---------------------------------------------------------------- the static support's forcing (exact first order)
@lru_cache(maxsize=None)
def support_forcing() -> sp.Expr:
    """f = μ'/(mhl) = −cos θ y1''/l with y1'' = K d²Q/dt² along the free flow, Q = Q(θ, θ') (exact in α).

    In the symbols (sin θ, cos θ, θ') of the truth module: Q = mh(θ'² sin θ − θ'' cos θ) with
    θ'' = −(g/l) sin θ, differentiated twice along the free flow.
    """
    Qr = reduced(1).subs({theta: sp.Symbol("TH")})
    TH = sp.Symbol("TH")
    Qs = Qr.subs(thetadd, -g / l * sp.sin(TH)).subs(thetad, W_).subs({sp.sin(TH): S_, sp.cos(TH): C_})
    acc = -g / l * S_
    D = lambda e: tr._lie(e, acc)
    ydd = K * D(D(Qs))
    return sp.expand(-C_ * ydd / l)


def _forcing_numeric(hh: str):
    f = sp.lambdify((S_, C_, W_), support_forcing().subs({K: 1, m: 1, g: 1, l: 1, h: sp.Rational(hh)}), "mpmath")
    return lambda s, c, w, t: f(s, c, w)


@lru_cache(maxsize=None)
def first_order_support(alpha_val: str, hh: str = H_TRUTH) -> dict:
    """Exact first-order δ, α1 per unit K for the static support (pendsym.finite_amplitude)."""
    return fa.swing_first_order(_forcing_numeric(hh), alpha_val, 1, hh, dps=30)


def delta_static_finite_derived(deps) -> sp.Expr:
    """δ exact in α, first order in K: finite_amplitude.delta_exact with u of the static support."""
    f_sym = support_forcing()
    Uq = sp.Symbol("U")
    w0 = sp.sqrt(g / l)
    th = fa.free_angle()
    along = f_sym.subs({S_: sp.expand_trig(sp.sin(th)), C_: sp.expand_trig(sp.cos(th)),
                        W_: fa.free_speed(alpha, phi, w0)})
    uexpr = sp.solve(sp.Eq(fa.forcing_of_u(Uq).subs(fa.w0, w0), along), Uq)[0]
    lam = sp.Lambda(phi, uexpr)
    return fa.delta_exact().replace(u, lam).subs(fa.w0, w0)


def alpha1_leading_derived(deps) -> sp.Expr:
    """α1 with the same leading substitutions as δ: ∝ ∫ cos φ sin φ dφ = 0 (p. 7)."""
    mu = _mu(deps, 0, deps[f"{MEMOIR}.y1dd"].derived).subs(sp.cos(theta), 1)
    gen = deps[f"{MEMOIR}.alpha1_general"].derived
    return sp.simplify(gen.replace(u, sp.Lambda(phi, u_of_mu(mu))).doit())


def alpha1_static_derived(_deps) -> sp.Expr:
    """α1 at first order in K, exact in α: the integrand is odd about φ = π/2, so α1 = 0.

    u(π − φ) = −u(φ) because Q is odd in θ, even in θ', and θ(π − φ) = −θ(φ),
    θ'(π − φ) = θ'(φ); the weight sin φ/√(1 − κ² cos²φ) is even.  Checked by SymPy.
    """
    f_sym = support_forcing()
    th = fa.free_angle()
    along = f_sym.subs({S_: sp.expand_trig(sp.sin(th)), C_: sp.expand_trig(sp.cos(th)),
                        W_: fa.free_speed(alpha, phi, sp.sqrt(g / l))})
    dens = fa.first_order_densities()["dalpha"].subs(fa.kappa, sp.sin(alpha / 2))
    Uq = sp.Symbol("U")
    uexpr = sp.solve(sp.Eq(fa.forcing_of_u(Uq).subs(fa.w0, sp.sqrt(g / l)), along), Uq)[0]
    integrand = dens.replace(u, sp.Lambda(phi, uexpr))
    odd = sp.simplify(sp.expand_trig(integrand.subs(phi, sp.pi - phi) + integrand))
    if odd != 0:
        raise ValueError("the α1 integrand is not odd about π/2")
    return sp.S.Zero


def practical_derived(deps) -> sp.Expr:
    """K = ε/p from the test deflection (y1 = KQ with Q = p), p' = mg (p. 10)."""
    Kv = sp.solve(sp.Eq(eps, K * p), K)[0]
    return sp.simplify(deps[f"{MEMOIR}.delta_static"].derived.subs(K, Kv).subs(m, pp / g))


def example_derived(deps) -> sp.Expr:
    """p = p', l = 1 m, h = 2/3 m (p. 10); ε in metres."""
    return deps[f"{MEMOIR}.delta_practical"].derived.subs({p: pp, l: 1, h: sp.Rational(2, 3)})


def g_error_derived(deps) -> sp.Expr:
    """|Δg/g| from g = π² l/T² when T → T(1 + δ), first order in δ: 2δ; with the example δ (p. 10)."""
    d = sp.Symbol("d", positive=True)
    gT = sp.pi**2 * l / T**2
    rel = sp.series((gT - gT.subs(T, T * (1 + d))) / gT, d, 0, 2).removeO()
    return sp.simplify(rel.subs(d, deps[f"{MEMOIR}.example_delta"].derived))


def eps_bound_derived(deps) -> sp.Expr:
    """ε (in mm) at which the relative error on g reaches 1/100000 (p. 10)."""
    sol = sp.solve(sp.Eq(deps[f"{MEMOIR}.g_error"].derived, sp.Rational(1, 100000)), eps)
    return sol[0] * 1000


# ---------------------------------------------------------------- checks
def _static_order_check(alpha_val: str, formula, note: str, printed=None, lo="5e-3", hi="4e-2"):
    def run(level):
        return verify.order_check(
            param="K", values=verify.geometric(lo, hi, verify.LEVELS[level]),
            truth=lambda k, dps: tr.delta_measured(alpha_val, mp.nstr(k, 40), "0", dps, h_val=H_TRUTH),
            derived=formula, printed=printed, expected=2, band=0.3,
            truth_desc=(f"rigid pendulum (m = g = l = 1, h = {H_TRUTH}, C = mhl) on a massless spring of compliance K, "
                        f"Euler–Lagrange equations by SymPy, slow-manifold start at rest at α = {alpha_val}, "
                        "mpmath odefun; δ = T/T0 − 1 with T0 = 2K(sin²½α)/ω0"),
            params=(("alpha", alpha_val), ("h/l", H_TRUTH)), note=note)
    return run


def _delta_static_check(result, level):
    f = sp.lambdify(K, result.derived.subs({m: 1, g: 1, l: 1, h: sp.Rational(H_TRUTH)}), "mpmath")
    return _static_order_check("0.003", lambda k: f(k), "small amplitude: residual O(K²) (α² K negligible)",
                               printed=lambda k: f(k))(level)


def _delta_finite_check(result, level):
    c1 = first_order_support("1.0")["delta"]
    return _static_order_check("1.0", lambda k: k * c1,
                               "α = 1 rad: exact first-order δ (finite_amplitude) has residual O(K²); "
                               "Kmgh/(2l²) alone is off by a relative O(α²)")(level)


def _alpha1_static_check(result, level):
    return verify.order_check(
        param="K", values=verify.geometric("5e-3", "4e-2", verify.LEVELS[level]),
        truth=lambda k, dps: tr.amplitude_change("1.0", mp.nstr(k, 40), "0", dps, h_val=H_TRUTH),
        derived=lambda k: 0, expected=3, band=0.4,
        truth_desc="the same pendulum on a spring, α = 1 rad: |θ(T)| − α over one swing (mpmath odefun)",
        params=(("alpha", "1.0"),),
        note=("No O(K) (nor O(K²)) change of amplitude: the quasi-static motion is reversible; the O(K³) "
              "left is the support vibration excited by the truncated (O(K²)) slow-manifold start."))


def _example_check(result, level):
    """The worked example's own pendulum (l = 1, h = 2/3, p = p' = mg): ε = K p, κ = K m g/l = ε/l."""
    f = sp.lambdify(eps, result.derived, "mpmath")
    return verify.order_check(
        param="epsilon", values=verify.geometric("1e-2", "4e-2", verify.LEVELS[level]),
        truth=lambda e, dps: tr.delta_measured("0.003", mp.nstr(e, 40), "0", dps, h_val="2/3"),
        derived=lambda e: f(e), printed=lambda e: e / 3, expected=2, band=0.3,
        truth_desc=("rigid pendulum with l = 1, h = 2/3 (m = g = 1) on a massless spring deflected ε by p = p' = mg, "
                    "slow-manifold start at α = 0.003, mpmath odefun; δ = T/T0 − 1"),
        params=(("h/l", "2/3"), ("alpha", "0.003")), note="ε in units of l; residual O(ε²)")


def _sin_theta_check(result, level):
    f = sp.lambdify((alpha, phi), result.derived, "mpmath")
    pairs = []
    with mp.workdps(30):
        for a, ph in (("0.4", "0.3"), ("1.9", "2.2"), ("1.0", "1.4")):
            A, PH = mp.mpf(a), mp.mpf(ph)
            target = mp.cos(A) * mp.cos(PH) ** 2 + mp.sin(PH) ** 2
            guess = A * mp.cos(PH)
            thv = mp.findroot(lambda x: mp.cos(x) - target, guess)
            thv = abs(thv) * (1 if mp.cos(PH) > 0 else -1)
            pairs.append((f"alpha={a},phi={ph}", f(A, PH), mp.sin(thv)))
    return verify.value_check(truth_desc="θ from cos θ = cos α cos²φ + sin²φ by mpmath findroot, sign of cos φ",
                              pairs=pairs, tol=mp.mpf("1e-25"), kind="value")


def _Q_static_check(result, level):
    f = sp.lambdify((theta, alpha), result.derived.subs({m: 1, g: 1, h: 1, l: 1}), "mpmath")
    pairs = []
    with mp.workdps(30):
        traj = _free_traj("0.8", 30)
        for s in (mp.mpf("0.5"), mp.mpf("1.9")):
            Qn = -mp.diff(lambda x: mp.sin(traj(x)[0]), s, 2, h=mp.mpf("1e-7"))
            pairs.append((f"t={s}", f(traj(s)[0], mp.mpf("0.8")), Qn))
    return verify.value_check(truth_desc="θ'' = −sin θ, α = 0.8 (mpmath odefun); Q = −m(h sin θ)'' by numerical "
                              "differentiation (step 1e-7)", pairs=pairs, tol=mp.mpf("1e-10"), kind="value")


def _radical_check(result, level):
    with mp.workdps(30):
        a = 2 * mp.pi / 180
        worst = max(1 - mp.sqrt(1 - mp.sin(a / 2) ** 2 * mp.cos(mp.pi * i / 200) ** 2) for i in range(201))
        return verify.value_check(truth_desc="largest 1 − √(1 − sin²1° cos²φ) over 201 points of [0, π]",
                                  pairs=[("alpha=2deg", sp.N(result.derived, 40), worst)], tol=mp.mpf("1e-25"),
                                  kind="value")


def _proof(expected):
    def check(result, level):
        return verify.proof(statement=f"SymPy reduces the derived form to {sp.sstr(expected)}",
                            holds=sp.simplify(result.derived - expected) == 0, truth_desc="symbolic")
    return check


def _g_error_check(result, level):
    """The free pendulum integrated with l and with l(1+δ)²: g inferred from T = π√(l/g) is off by ≈ 2δ."""
    # δ stands for ε/3 here: the derived form is (2/3)ε → 2δ
    f = sp.lambdify(eps, result.derived, "mpmath")

    def truth_rel(e, dps):
        with mp.workdps(dps):
            d = e / 3                                           # the example's δ
            traj = ptruth.integrate(lambda tt, y: [y[1], -mp.sin(y[0]) / (1 + d) ** 2], [mp.mpf("0.01"), 0], dps)
            T1 = ptruth.turning_time(traj, mp.pi * (1 + d), width=mp.mpf("0.2"))
            T0 = 2 * mp.ellipk(mp.sin(mp.mpf("0.005")) ** 2)
            return 1 - (T0 / T1) ** 2                            # g_inferred/g − 1 with g ∝ 1/T²
    return verify.order_check(param="epsilon", values=verify.geometric("1e-4", "1e-2", verify.LEVELS[level]),
                              truth=truth_rel, derived=lambda e: f(e), expected=2, band=0.3,
                              truth_desc="swing time of θ'' = −sin θ/(1+δ)² (length stretched so T grows by 1+δ), "
                                         "α = 0.01, mpmath odefun; relative error of g ∝ 1/T²")


def specs() -> tuple[Spec, ...]:
    Pm = MEMOIR
    kern = KernelSpec((KernelArg("K", 1e-9, 1e-3), KernelArg("m", 0.01, 100.0), KernelArg("g", 9.0, 10.0, log=False),
                       KernelArg("h", 0.01, 2.0), KernelArg("l", 0.1, 5.0)),
                      doc="relative lengthening of the swing on a support of static compliance K (m/N)")
    kern_pr = KernelSpec((KernelArg("epsilon", 1e-8, 1e-3, unit="m"), KernelArg("l", 0.1, 5.0, unit="m"),
                          KernelArg("h", 0.01, 2.0, unit="m"), KernelArg("p'", 0.1, 1000.0, unit="N"),
                          KernelArg("p", 0.1, 1000.0, unit="N")),
                         doc="δ = ½ (ε/l)(h/l)(p'/p)")
    return (
        Spec(f"{Pm}.delta_support", "δ for the motion of the knife edge",
             src("δ = 1/(2πg) ∫_0^π [sin θ d²x1/dt² − cos θ d²y1/dt²] cos φ/sin ½α dφ (p. 4)"), r"\delta",
             delta_support_derived, deps=(f"{Pm}.delta_general", f"{Pm}.mu_prime"), printed=delta_support_printed,
             defs=THETA_PHI, instances=XY_INSTANCES, check=pipeline.through(f"{Pm}.delta_general", f"{Pm}.mu_prime"),
             note="x1'', y1'' along the swing are arbitrary functions of φ (compared on test functions). "
                  "Verified through its two ingredients; no integration with a prescribed support motion yet."),
        Spec(f"{Pm}.Q_static", "Q on the free swing", src("La valeur exacte de Q est: Q = (2gmh/l)(cos θ − cos α) "
                                                          "sin θ + (mgh/l) sin θ cos θ (p. 5)"),
             "Q", Q_static_derived, deps=(f"{Pm}.Q_reduced",), printed=Q_static_printed, check=_Q_static_check),
        Spec(f"{Pm}.Q_leading", "Q = (mgh/l)θ + O(α³)", src("= (mgh/l)(θ + etc.) (p. 5)"), "Q", Q_leading_derived,
             deps=(f"{Pm}.Q_static",), printed=lambda: m * g * h / l * theta,
             check=lambda r, lv: verify.proof(
                 statement="the series of Q in (θ, α) scaled together has no term of degree 2",
                 holds=_series_leading(r.deps[f"{Pm}.Q_static"].derived, {theta: theta, alpha: alpha}, 2)
                 == _series_leading(r.deps[f"{Pm}.Q_static"].derived, {theta: theta, alpha: alpha}, 1),
                 truth_desc="SymPy series")),
        Spec(f"{Pm}.sin_theta", "sin θ in terms of φ", src("sin θ = 2 sin ½α cos φ √(1 − sin²½α cos²φ) (p. 6)"),
             r"\sin\theta", sin_theta_derived, printed=sin_theta_printed, check=_sin_theta_check),
        Spec(f"{Pm}.radical_error", "Relative error of √(1 − sin²½α cos²φ) → 1 for α ≤ 2°",
             src("en supposant que α ne dépasse pas 2°, le radical précédent peut être remplacé par l'unité, "
                 "l'erreur relative ne dépassant pas 1 … (p. 6; the bound is cut off in the file)"),
             r"1-\sqrt{1-\sin^2 1^\circ}", radical_error_derived, deps=(f"{Pm}.sin_theta",),
             check=_radical_check, note="≈ 1.52e-4 ≈ 1/6566; the printed bound is lost in the OCR after '1'."),
        Spec(f"{Pm}.y1dd", "y1'' to the leading order", src("d²y1/dt² = −(2Kmg²h/t²) sin ½α cos φ (p. 6)"),
             r"y_1''", y1dd_derived, deps=(f"{Pm}.Q_leading", f"{Pm}.sin_theta"), printed=y1dd_printed,
             readings=(Reading("t²", "l²: OCR reads l as t"), Reading("g_1 = KQ", "y1 = KQ")),
             check=pipeline.through(f"{Pm}.delta_static"),
             note="y1 = KQ (the horizontal deflection; the text's x1 is vertical and neglected)."),
        Spec(f"{Pm}.delta_static_integral", "δ as an integral for the static support",
             src("δ = (Kmhg/(πl²)) ∫_0^π cos²φ dφ (p. 6)"), r"\delta", delta_static_integral_derived,
             deps=(f"{Pm}.delta_general", f"{Pm}.mu_prime", f"{Pm}.y1dd"), printed=delta_static_integral_printed,
             check=pipeline.through(f"{Pm}.delta_static"),
             note="cos θ → 1 as the text does ('en remplaçant de même cos θ par 1')."),
        Spec(f"{Pm}.delta_static", "δ = Kmgh/(2l²)", src("δ = … = Kmgh/(2l²) (p. 6)"), r"\delta",
             delta_static_derived, deps=(f"{Pm}.delta_static_integral",), printed=lambda: K * m * g * h / (2 * l**2),
             check=_delta_static_check, kernel=kern, show_values=True),
        Spec(f"{Pm}.delta_static_finite", "δ at finite amplitude, first order in K (not in the memoir)",
             src("les termes négligés … sont de l'ordre de θ² (p. 7)"), r"\delta", delta_static_finite_derived,
             check=_delta_finite_check,
             note="pendsym.finite_amplitude.delta_exact with u of the static support; equals Kmgh/(2l²)(1 + O(α²))."),
        Spec(f"{Pm}.alpha1_leading", "The leading term of α1 vanishes",
             src("l'intégrale serait remplacée par ∫_0^π cos φ sin φ dφ ou 0 (p. 7)"), r"\alpha_1",
             alpha1_leading_derived, deps=(f"{Pm}.alpha1_general", f"{Pm}.mu_prime", f"{Pm}.y1dd"),
             printed=lambda: sp.S.Zero, check=_proof(0)),
        Spec(f"{Pm}.alpha1_static", "α1 at first order in K, exact in α (the surviving terms)",
             src("les termes négligés subsisteraient seuls, et l'expression contient de plus tang ½α comme facteur "
                 "(p. 7)"), r"\alpha_1", alpha1_static_derived, check=_alpha1_static_check,
             note=("The text expects surviving terms of relative order θ² (α1 = O(Kα³)); in fact the whole "
                   "first-order integrand is odd about φ = π/2, so α1 = 0 at O(K) for every α; the "
                   "integrated model shows no change below O(K³).")),
        Spec(f"{Pm}.delta_practical", "δ = ½ (ε/l)(h/l)(p'/p)",
             src("on aura alors K = ε/p; … δ = ½ · ε/l · h/l · p'/p (p. 10)"), r"\delta", practical_derived,
             deps=(f"{Pm}.delta_static",), printed=lambda: eps / l * h / l * pp / p / 2, kernel=kern_pr,
             readings=(Reading("K = ı/p", "K = ε/p"),), check=pipeline.through(f"{Pm}.example_delta")),
        Spec(f"{Pm}.example_delta", "δ = ε/3 for p = p', l = 1 m, h = 2/3 m",
             src("en supposant … que la force p soit égale au poids même du pendule, … l = 1, h = 2/3, on trouvera "
                 "δ = (1/3)·ε (p. 10)"), r"\delta", example_derived, deps=(f"{Pm}.delta_practical",),
             printed=lambda: eps / 3, check=_example_check, note="ε in metres (l = 1 m)."),
        Spec(f"{Pm}.g_error", "Relative error on g: 2δ = (2/3)ε",
             src("l'erreur relative qui résulterait de celle-là pour la valeur de g serait 3 c (p. 10)"),
             r"\Delta g/g", g_error_derived, deps=(f"{Pm}.example_delta",), printed=lambda: 2 * eps / 3,
             readings=(Reading("3 c", "⅔ ε: the next line writes (2/3) ε < 1/100000", certain=False),),
             check=_g_error_check,
             kernel=KernelSpec((KernelArg("epsilon", 1e-8, 1e-3, unit="m"),),
                               doc="relative error on g for the worked example (l = 1 m, h = 2/3 m, p = p')")),
        Spec(f"{Pm}.eps_bound", "ε < 0.015 mm keeps the fourth decimal of g",
             src("(2/3) ε < 1/100000, ε < 0mm,015 (p. 10)"), r"\varepsilon_{max}\,[\mathrm{mm}]", eps_bound_derived,
             deps=(f"{Pm}.g_error",), printed=lambda: sp.Rational(15, 1000), check=_proof(sp.Rational(3, 200)),
             readings=(Reading("0mm,015", "0.015 mm"),),
             note="The fourth decimal of g ≈ 9.8 m/s² is read as a relative error 1/100000, as the text writes."),
    )
