"""Charbonnier 1908, the general formulas (n°8–9, rebuilt) and §IV n°18–20.

n°8–9 are not in the file; they are rebuilt by variation of constants from
θ'' + k²θ + εφ = 0, θ0 = −α cos kt, and confirmed by their uses in the
seed (n°21 4°–7°, n°32–34).  E_s and E_c of the phase are written E_s(π),
E_c(π/2) as the memoir does: the argument is kt.
"""
from __future__ import annotations

import mpmath as mp
import sympy as sp

from pendsym import perturbation as pt
from pendsym import verify, wallis
from pendsym.result import Evidence, KernelArg, KernelSpec, Reading, Source, Spec
from . import truth as tr
from .symbols import DEFS, alpha, dtheta, eps, k, m, n, t, theta, theta_i, omega_i, y

MEMOIR = "charbonnier1908"
ODD_M = ((m, 2 * n + 1),)    # the claim holds for odd m: compared on m = 2n + 1
EVEN_M = ((m, 2 * n + 2),)   # … for even m ≥ 2
DEF_ITEMS = tuple(DEFS.items())

# E_s, E_c as functions of time (for the derivation) and of the phase kt (the memoir's notation)
Es_t, Ec_t = sp.Function("E_s_t"), sp.Function("E_c_t")
E_s, E_c = sp.Function("E_s"), sp.Function("E_c")
phi_t = sp.Function("varphi")(t)
u = sp.Symbol("u", real=True)
varphi = sp.Function("varphi")


def src(para: str, page: int) -> Source:
    return Source(MEMOIR, para, page)


def to_phase(expr: sp.Expr) -> sp.Expr:
    """E_s_t(τ) → E_s(kτ): the memoir writes E_s(π) for the value at t = π/k."""
    return expr.replace(Es_t, lambda arg: E_s(sp.expand(k * arg))).replace(Ec_t, lambda arg: E_c(sp.expand(k * arg)))


# ---------------------------------------------------------------- n°8 (rebuilt)
def theta_general(_deps) -> sp.Expr:
    """θ(t) to first order from any (θ_i, ω_i): θ0 + (ε/k)(E_s cos kt − E_c sin kt) (n°8, rebuilt)."""
    th0 = pt.unperturbed(t, k, theta_i, omega_i)
    return th0 + pt.theta1(Es_t(t), Ec_t(t), eps, k, t)


def dtheta_general(deps) -> sp.Expr:
    """θ'(t): the derivative of n°8's θ with E_s' = φ sin kt, E_c' = φ cos kt (rebuilt n°8)."""
    th = deps[f"{MEMOIR}.n08.theta"].derived
    d = sp.diff(th, t).subs({sp.Derivative(Es_t(t), t): phi_t * sp.sin(k * t),
                             sp.Derivative(Ec_t(t), t): phi_t * sp.cos(k * t)})
    return sp.expand(sp.simplify(d))


def _at_rest(expr: sp.Expr) -> sp.Expr:
    return expr.subs({theta_i: -alpha, omega_i: 0})


def _parts(deps):
    th = _at_rest(deps[f"{MEMOIR}.n08.theta"].derived)
    dth = _at_rest(deps[f"{MEMOIR}.n08.dtheta"].derived)
    th0 = pt.unperturbed(t, k, -alpha)
    return th0, th - th0, dth - sp.diff(th0, t)


def dT_general(deps) -> sp.Expr:
    """ΔT: shift of the turning point t* = π/k, −θ1'(t*)/θ0''(t*) (n°9, used n°21 5°, n°32)."""
    th0, _, d1 = _parts(deps)
    return to_phase(pt.turning_shift(th0, d1, t, sp.pi / k))


def dalpha_general(deps) -> sp.Expr:
    """Δα: θ1 at the turning point π/k, where θ0 = +α (n°9, used n°33)."""
    _, th1, _ = _parts(deps)
    return to_phase(sp.simplify(th1.subs(t, sp.pi / k)))


def dThalf_general(deps) -> sp.Expr:
    """ΔT½: shift of the lowest point t* = π/(2k), −θ1(t*)/θ0'(t*) (n°9 3°, used n°21 7°, n°34)."""
    th0, th1, _ = _parts(deps)
    return to_phase(pt.crossing_shift(th0, th1, t, sp.pi / (2 * k)))


def dthetam_general(deps) -> sp.Expr:
    """Δθ'_m: θ1' at the lowest point (θ0'' = 0 there) (n°9 3°, used n°21 7°, n°34)."""
    _, _, d1 = _parts(deps)
    return to_phase(sp.simplify(d1.subs(t, sp.pi / (2 * k))))


# ---- checks of the general formulas: a generic φ(θ, θ', t), k = 1.7, against integration
K_TEST, ALPHA_TEST = "1.7", "0.4"
PHI_GENERIC = tr.PHIS["generic"]


def _E_quad(phi_expr, kv, th_i, om_i, upto, trig):
    th0 = pt.unperturbed(t, k, theta_i, omega_i)
    f = sp.lambdify((t, k, theta_i, omega_i), pt.along(phi_expr, theta, dtheta, th0, t), modules="mpmath")
    return mp.quad(lambda s: f(s, kv, th_i, om_i) * trig(kv * s), [0, upto])


def _general_event_check(result, level: str, quantity: str) -> Evidence:
    kv, al = mp.mpf(K_TEST), mp.mpf(ALPHA_TEST)
    eps_vals = verify.geometric("1e-4", "1e-2", verify.LEVELS[level])
    points = {"dT": (mp.pi, E_c), "dalpha": (mp.pi, E_s), "dThalf": (mp.pi / 2, E_c), "dthetam": (mp.pi / 2, E_s)}
    phase, fn = points[quantity]

    def formula(ev):
        E = _E_quad(PHI_GENERIC, kv, -al, 0, phase / kv, mp.sin if fn is E_s else mp.cos)
        expr = result.derived.replace(fn, lambda arg: sp.Symbol("E"))
        return verify.lambdify_mp(expr, (sp.Symbol("E"), eps, k, alpha))(E, ev, kv, al)

    def measured(ev, dps):
        sw = tr.oscillator("generic", mp.nstr(ev, 40), K_TEST, "-" + ALPHA_TEST, "0", dps)
        return {"dT": sw.T - mp.pi / kv, "dalpha": sw.amp - al,
                "dThalf": sw.t_low - mp.pi / (2 * kv), "dthetam": sw.v_low - kv * al}[quantity]

    return verify.order_check(
        param="epsilon", values=eps_vals, truth=measured, derived=formula, expected=2, band=0.3,
        truth_desc="θ'' + k²θ + εφ = 0 with φ = θ² + θθ'/2 + θ sin(1.3t) + 1/3, k = 1.7 (mpmath odefun); "
                   "E_s, E_c by mpmath quad along θ0",
        params=(("k", K_TEST), ("alpha", ALPHA_TEST)))


def _theta_general_check(result, level: str, which: int) -> Evidence:
    kv, thi, omi = mp.mpf(K_TEST), mp.mpf("0.3"), mp.mpf("0.5")
    times = [mp.mpf(s) for s in ("0.5", "1.3", "2.9")]
    eps_vals = verify.geometric("1e-4", "1e-2", verify.LEVELS[level])
    Es, Ec = sp.Symbol("Es"), sp.Symbol("Ec")
    expr = result.derived.subs({Es_t(t): Es, Ec_t(t): Ec, phi_t: sp.Symbol("PHI")})
    f = verify.lambdify_mp(expr, (Es, Ec, sp.Symbol("PHI"), eps, k, t, theta_i, omega_i))
    th0 = pt.unperturbed(t, k, theta_i, omega_i)
    phi_along = sp.lambdify((t, k, theta_i, omega_i), pt.along(PHI_GENERIC, theta, dtheta, th0, t), modules="mpmath")

    def formula_at(ev, s):
        es = _E_quad(PHI_GENERIC, kv, thi, omi, s, mp.sin)
        ec = _E_quad(PHI_GENERIC, kv, thi, omi, s, mp.cos)
        return f(es, ec, phi_along(s, kv, thi, omi), ev, kv, s, thi, omi)

    def worst(ev, dps, formula):
        traj = tr.oscillator("generic", mp.nstr(ev, 40), K_TEST, "0.3", "0.5", dps)
        return max(abs(traj(s)[which] - formula(ev, s)) for s in times)

    def measured(ev, dps):
        # the truth enters only through |θ_true − θ_formula|; order_check subtracts 0
        return worst(ev, dps, formula_at)

    return verify.order_check(
        param="epsilon", values=eps_vals, truth=measured, derived=lambda ev: 0, expected=2, band=0.3,
        truth_desc="θ'' + k²θ + εφ = 0 from θ(0) = 0.3, θ'(0) = 0.5, k = 1.7, generic φ (mpmath odefun); "
                   "largest |error| at t = 0.5, 1.3, 2.9",
        params=(("k", K_TEST), ("theta_i", "0.3"), ("omega_i", "0.5")))


# ---------------------------------------------------------------- n°18
def Es_theta_derived(_deps) -> sp.Expr:
    """E_s as a quadrature in θ: sin kt dt = dθ/(kα) along θ = −α cos kt (n°18 1°, p. 221)."""
    tau = sp.Symbol("tau", nonnegative=True)
    I = sp.Integral(varphi(-alpha * sp.cos(k * tau)) * sp.sin(k * tau), (tau, 0, t))
    return I.transform(-alpha * sp.cos(k * tau), u)


def Es_theta_printed() -> sp.Expr:
    return sp.Integral(varphi(u), (u, -alpha, theta)) / (k * alpha)


def Ec_theta_derived(_deps) -> sp.Expr:
    """E_c by parts: cos kt dt = dθ'/(k²α), E_c = [θ'φ − ∫θ'φ'(θ)dθ]/(k²α) (n°18 2°, p. 221)."""
    tau = sp.Symbol("tau", nonnegative=True)
    th0 = -alpha * sp.cos(k * tau)
    w = sp.diff(th0, tau)                               # θ0'
    # ∫ φ(θ0) dθ0' = φ θ0' − ∫ θ0' dφ(θ0)  (integration by parts, in τ)
    boundary = (varphi(th0) * w).subs(tau, t) - (varphi(th0) * w).subs(tau, 0)
    rest = sp.Integral(w * sp.diff(varphi(th0), tau), (tau, 0, t))
    return (boundary - rest) / (k**2 * alpha)


def Ec_theta_printed() -> sp.Expr:
    # θ' as a function of θ along the motion: θ'² = k²(α² − θ²) for 0 ≤ kt ≤ π
    thp = k * sp.sqrt(alpha**2 - u**2)
    return (k * sp.sqrt(alpha**2 - theta**2) * varphi(theta)
            - sp.Integral(thp * sp.Derivative(varphi(u), u), (u, -alpha, theta))) / (k**2 * alpha)


THETA_OF_T = ((theta, -alpha * sp.cos(k * t)),)
PHI_TESTS = (sp.Lambda(u, u**2 + sp.exp(u / 3)), sp.Lambda(u, sp.cos(u) - u**3 / 5))
PHI_INSTANCES = tuple(((varphi, lam),) for lam in PHI_TESTS)


def _n18_check(result, level: str) -> Evidence:
    """Quadrature in time of the definition vs the θ-form, for two test functions φ."""
    pairs = []
    kv, al = mp.mpf("1.3"), mp.mpf("0.7")
    for lam in PHI_TESTS:
        f = sp.lambdify(u, lam(u), modules="mpmath")
        df = sp.lambdify(u, sp.diff(lam(u), u), modules="mpmath")
        for tv in (mp.mpf("0.4"), mp.mpf("1.9")):
            th = -al * mp.cos(kv * tv)
            if result.id.endswith("Es_theta"):
                truth = mp.quad(lambda s: f(-al * mp.cos(kv * s)) * mp.sin(kv * s), [0, tv])
                form = mp.quad(f, [-al, th]) / (kv * al)
            else:
                truth = mp.quad(lambda s: f(-al * mp.cos(kv * s)) * mp.cos(kv * s), [0, tv])
                thp = kv * al * mp.sin(kv * tv)
                # the θ-integral of θ'φ'(θ) runs over the branch θ' = k√(α²−θ²) ≥ 0 (kt ≤ π)
                form = (thp * f(th) - mp.quad(lambda s: kv * mp.sqrt(al**2 - s**2) * df(s), [-al, th])) / (kv**2 * al)
            pairs.append((f"t={tv}", form, truth))
    return verify.value_check(truth_desc="mpmath quad of the time integral of the definition (n°18), "
                              "φ = θ² + e^{θ/3} and cos θ − θ³/5, k = 1.3, α = 0.7",
                              pairs=pairs, tol=mp.mpf("1e-25"), params=(("k", "1.3"), ("alpha", "0.7")))


# ---------------------------------------------------------------- n°19–20: monomials
def Es_monomial(_deps) -> sp.Expr:
    """E_s for φ = θ^m along θ0 = −α cos kt, m symbolic (n°19, p. 221)."""
    return pt.E_s(pt.along(theta**m, theta, dtheta, -alpha * sp.cos(k * t), t), t, k)


def Ec_monomial(_deps) -> sp.Expr:
    """E_c for φ = θ^m, left as (−α)^m/k · J_m(kt) with J_m the integral of n°20."""
    x = sp.Symbol("x", real=True)
    integrand = pt.along(theta**m, theta, dtheta, -alpha * sp.cos(k * t), t).subs(t, x / k) * sp.cos(x)
    return sp.powsimp(sp.Integral(sp.powsimp(sp.expand_power_base(integrand, force=True), force=True),
                                  (x, 0, k * t)) / k, force=True)


def Es_pi_parity(deps, parity: int) -> sp.Expr:
    """E_s(π) with m = 2n + parity: the parity split of n°19 proved for every n."""
    es = deps[f"{MEMOIR}.n19.Es"].derived.subs(t, sp.pi / k)
    return sp.simplify(sp.powsimp(es.subs(m, 2 * n + parity), force=True))


def dalpha_monomial(deps) -> sp.Expr:
    """Δα = −(ε/k)E_s(π) with E_s(π) of even m (n°19, with n°9 2°)."""
    gen = deps[f"{MEMOIR}.n09.dalpha"].derived
    es_pi = deps[f"{MEMOIR}.n19.Es_pi_even"].derived.subs(n, (m) / 2)
    return sp.simplify(gen.subs(E_s(sp.pi), es_pi))


def recurrence_derived(_deps) -> sp.Expr:
    """(m+1)J_m − m J_{m−2} − sin y cos^m y, as the integral of a vanishing derivative (n°20)."""
    return wallis.recurrence_defect(m, y)


def J_pi_induction(_deps) -> sp.Expr:
    """J_{2n+1}(π)/J_{2n−1}(π) − (2n+1)/(2n+2) for the closed form; zero proves the induction step."""
    C = wallis.J_pi_odd
    ratio = sp.expand_func((C(2 * n + 1) / C(2 * n - 1)).rewrite(sp.gamma))
    return sp.simplify(sp.gammasimp(ratio) - (2 * n + 1) / (2 * n + 2))


def J_pi_closed(_deps) -> sp.Expr:
    """J_m(π) for odd m: the recurrence at y = π gives J_m = m/(m+1) J_{m−2}, J_{−1} = π (n°20)."""
    return wallis.J_pi_odd(m)


def J_even_zero(_deps) -> sp.Expr:
    """cos^{m+1}(π−y)/cos^{m+1}(y) for even m = 2n: −1, so J_m(π) = −J_m(π) = 0 (n°20)."""
    return sp.simplify(wallis.parity_reflection(2 * n, y))


def Ec_pi_monomial(deps) -> sp.Expr:
    """E_c(π) = (−α)^m/k · J_m(π), m odd (n°20, p. 223)."""
    return (-alpha) ** m / k * deps[f"{MEMOIR}.n20.J_pi"].derived


def dT_monomial(deps) -> sp.Expr:
    """ΔT = ε E_c(π)/(k²α) with the E_c(π) of odd m (n°20 with n°9)."""
    gen = deps[f"{MEMOIR}.n09.dT"].derived
    ec = deps[f"{MEMOIR}.n20.Ec_pi"].derived
    return sp.simplify(sp.powsimp(gen.subs(E_c(sp.pi), ec), force=True).subs((-1) ** m, -1))


def theorem_derived(deps) -> sp.Expr:
    """(E_s(π)·J_m(π) for m = 2n, the same for m = 2n+1): both zero, so amplitude and
    duration never change together (n°19–20)."""
    Jsym = sp.Symbol("J")
    refl = deps[f"{MEMOIR}.n20.J_even"].derived
    # even m: the reflection gives J_m(π) = refl·J_m(π), whose only solution is 0 when refl ≠ 1
    J_even = sp.solve(sp.Eq(Jsym, refl * Jsym), Jsym)
    if J_even != [0]:
        raise ValueError("the reflection does not force J_m(pi) = 0")
    odd_J = wallis.J_pi_odd(2 * n + 1)
    return sp.Tuple(deps[f"{MEMOIR}.n19.Es_pi_even"].derived * J_even[0],
                    sp.simplify(deps[f"{MEMOIR}.n19.Es_pi_odd"].derived * odd_J))


def _proof_check(expected):
    def check(result, level):
        holds = sp.simplify(result.derived - expected) == 0
        return verify.proof(statement=f"SymPy reduces the derived form to {sp.sstr(expected)} for symbolic m (n)",
                            holds=holds, truth_desc="symbolic proof for general m")
    return check


def _quad_J_check(result, level):
    pairs = []
    for mv in range(1, 10):
        tv = mp.quad(lambda s: mp.cos(s) ** (mv + 1), [0, mp.pi])
        if mv % 2:
            pairs.append((f"m={mv}", sp.N(result.derived.subs(m, mv), 40), tv))
    return verify.value_check(truth_desc="mpmath quad of ∫_0^π cos^{m+1} y dy, m = 1, 3, …, 9",
                              pairs=pairs, tol=mp.mpf("1e-28"))


def _recurrence_check(result, level):
    proven = sp.simplify(result.derived) == 0
    pairs = []
    for mv in range(1, 8):
        for yv in (mp.mpf("0.7"), mp.mpf("2.3")):
            J = lambda j: mp.quad(lambda s: mp.cos(s) ** (j + 1), [0, yv])
            pairs.append((f"m={mv}", (mv + 1) * J(mv), mp.sin(yv) * mp.cos(yv) ** mv + mv * J(mv - 2)))
    ev = verify.value_check(truth_desc="mpmath quad of J_m and J_{m−2}, m = 1…7, y = 0.7, 2.3",
                            pairs=pairs, tol=mp.mpf("1e-28"))
    return verify.combine(verify.proof(statement="d/dy[sin y cos^m y] = (m+1)cos^{m+1} − m cos^{m−1} for symbolic m",
                                       holds=proven, truth_desc="symbolic proof"), ev)


def _monomial_order_check(quantity: str, ms: tuple[int, ...]):
    def check(result, level):
        kv, al = mp.mpf(K_TEST), mp.mpf(ALPHA_TEST)
        eps_vals = verify.geometric("1e-4", "1e-2", verify.LEVELS[level])
        evs = []
        for mv in ms:
            form = verify.lambdify_mp(result.derived.subs(m, mv), (eps, k, alpha))

            def measured(ev, dps, mv=mv):
                sw = tr.oscillator(f"theta^{mv}", mp.nstr(ev, 40), K_TEST, "-" + ALPHA_TEST, "0", dps)
                return sw.T - mp.pi / kv if quantity == "dT" else sw.amp - al
            evs.append(verify.order_check(
                param="epsilon", values=eps_vals, truth=measured, derived=lambda ev: form(ev, kv, al),
                expected=2, band=0.3, params=(("m", str(mv)), ("k", K_TEST), ("alpha", ALPHA_TEST)),
                truth_desc=f"θ'' + k²θ + εθ^{mv} = 0 (mpmath odefun)"))
        return verify.combine(*evs, truth_desc=f"θ'' + k²θ + εθ^m = 0, m = {ms}, integrated by mpmath odefun")
    return check


def _theorem_check(result, level):
    """The truth side of n°20: for m = 2 only α changes, for m = 3 only T (to first order)."""
    kv, al = mp.mpf(K_TEST), mp.mpf(ALPHA_TEST)
    eps_vals = verify.geometric("1e-4", "1e-2", verify.LEVELS[level])
    zero = lambda ev: 0
    dT2 = verify.order_check(param="epsilon", values=eps_vals, expected=2, band=0.3, derived=zero,
                             truth=lambda ev, dps: tr.oscillator("theta^2", mp.nstr(ev, 40), K_TEST, "-0.4", "0", dps).T - mp.pi / kv,
                             truth_desc="m = 2: ΔT is O(ε²)")
    da3 = verify.order_check(param="epsilon", values=eps_vals, expected=2, band=0.3, derived=zero,
                             truth=lambda ev, dps: tr.oscillator("theta^4", mp.nstr(ev, 40), K_TEST, "-0.4", "0", dps).T - mp.pi / kv,
                             truth_desc="m = 4: ΔT is O(ε²)")
    proof = verify.proof(statement="E_s(π)·J_m(π) = 0 for m = 2n and m = 2n+1, n symbolic",
                         holds=all(sp.simplify(x) == 0 for x in result.derived), truth_desc="symbolic proof")
    return verify.combine(proof, dT2, da3)


def specs() -> tuple[Spec, ...]:
    P = f"{MEMOIR}"
    eventdeps = (f"{P}.n08.theta", f"{P}.n08.dtheta")
    return (
        Spec(f"{P}.n08.theta", "θ(t) to first order, any k, any φ(θ, θ', t), any initial state",
             src("n°8 (not in the file; rebuilt), confirmed by n°21 4°", 220), r"\theta(t)",
             theta_general, check=lambda r, lv: _theta_general_check(r, lv, 0), defs=DEF_ITEMS,
             note="Rebuilt by variation of constants; θ_i, ω_i are the initial angle and speed."),
        Spec(f"{P}.n08.dtheta", "θ'(t) to first order", src("n°8 (rebuilt)", 220), r"\theta'(t)",
             dtheta_general, deps=(f"{P}.n08.theta",), check=lambda r, lv: _theta_general_check(r, lv, 1),
             defs=DEF_ITEMS),
        Spec(f"{P}.n09.dT", "Change of the swing time (general formula)", src("n°9, stated in n°32", 235),
             r"\Delta T", dT_general, deps=eventdeps,
             printed=lambda: eps / (k**2 * alpha) * E_c(sp.pi),
             check=lambda r, lv: _general_event_check(r, lv, "dT"), defs=DEF_ITEMS),
        Spec(f"{P}.n09.dalpha", "Change of the amplitude (general formula)", src("n°9, stated in n°33", 236),
             r"\Delta\alpha", dalpha_general, deps=eventdeps,
             printed=lambda: -eps / k * E_s(sp.pi),
             readings=(Reading("Δx = − ε/k E_s(π)", "Δα: the OCR reads α as x"),),
             check=lambda r, lv: _general_event_check(r, lv, "dalpha"), defs=DEF_ITEMS),
        Spec(f"{P}.n09.dThalf", "Change of the time to the lowest point (general formula)",
             src("n°9 3°, stated in n°21 7° and n°34", 225), r"\Delta T_{1/2}", dThalf_general, deps=eventdeps,
             printed=lambda: eps / (k**2 * alpha) * E_c(sp.pi / 2),
             check=lambda r, lv: _general_event_check(r, lv, "dThalf"), defs=DEF_ITEMS),
        Spec(f"{P}.n09.dthetam", "Change of the speed at the lowest point (general formula)",
             src("n°9 3°, stated in n°21 7° and n°34", 225), r"\Delta\theta'_m", dthetam_general, deps=eventdeps,
             printed=lambda: -eps * E_s(sp.pi / 2),
             readings=(Reading("Δv'_m = −ε E_s(π/2) (n°34)", "Δθ'_m, as in n°21 7°", certain=False),),
             check=lambda r, lv: _general_event_check(r, lv, "dthetam"), defs=DEF_ITEMS),
        Spec(f"{P}.n18.Es_theta", "E_s as a quadrature in θ, for φ = φ(θ)", src("n°18 1°", 221), r"E_s",
             Es_theta_derived, printed=Es_theta_printed, check=_n18_check,
             readings=(Reading("upper limit 0 in ∫_{−α}^0 φ(θ)dθ", "θ: E_s(π) = (1/kα)∫_{−α}^{α}φ, as the "
                               "following remark on odd φ needs", certain=False),),
             defs=DEF_ITEMS + THETA_OF_T, instances=PHI_INSTANCES),
        Spec(f"{P}.n18.Ec_theta", "E_c by parts, for φ = φ(θ)", src("n°18 2°", 221), r"E_c",
             Ec_theta_derived, printed=Ec_theta_printed, check=_n18_check,
             readings=(Reading("∫_{−α}^0 θ'φ'(θ)dθ", "upper limit θ (as in 1°)", certain=False),
                       Reading("θ' in the bracket", "θ' = k√(α²−θ²), the branch 0 ≤ kt ≤ π"),),
             defs=DEF_ITEMS + THETA_OF_T, instances=PHI_INSTANCES),
        Spec(f"{P}.n19.Es", "E_s for φ = θ^m", src("n°19", 221), r"E_s", Es_monomial,
             printed=lambda: (-alpha) ** m / k / (m + 1) * (1 - sp.cos(k * t) ** (m + 1)),
             check=_monomial_quad(mp.sin), defs=DEF_ITEMS),
        Spec(f"{P}.n19.Es_pi_even", "E_s(π) for even m = 2n", src("n°19", 222), r"E_s(\pi)",
             lambda d: Es_pi_parity(d, 0), deps=(f"{P}.n19.Es",),
             printed=lambda: alpha ** (2 * n) / k * 2 / (2 * n + 1), check=_quad_at_pi(mp.sin, (2, 4, 6)),
             defs=DEF_ITEMS),
        Spec(f"{P}.n19.Es_pi_odd", "E_s(π) = 0 for odd m = 2n+1", src("n°19", 222), r"E_s(\pi)",
             lambda d: Es_pi_parity(d, 1), deps=(f"{P}.n19.Es",), printed=lambda: sp.S.Zero,
             check=_proof_check(0), defs=DEF_ITEMS),
        Spec(f"{P}.n19.dalpha", "Change of amplitude for θ^m, m even", src("n°19 (n°9, 2°)", 222),
             r"\Delta\alpha", dalpha_monomial, deps=(f"{P}.n09.dalpha", f"{P}.n19.Es_pi_even"),
             printed=lambda: -2 * eps / (m + 1) * alpha**m / k**2,
             readings=(Reading("Δx", "Δα"),), check=_monomial_order_check("dalpha", (2, 4)),
             kernel=None, defs=DEF_ITEMS),
        Spec(f"{P}.n20.Ec", "E_c for φ = θ^m", src("n°20", 222), r"E_c", Ec_monomial,
             printed=lambda: (-alpha) ** m / k * sp.Integral(sp.cos(y) ** (m + 1), (y, 0, k * t)),
             readings=(Reading("∫_0^{kt} cos^{m+1} kt dkt", "∫_0^{kt} cos^{m+1} y dy"),),
             check=_monomial_quad(mp.cos), defs=DEF_ITEMS),
        Spec(f"{P}.n20.recurrence", "(m+1)J_m = sin y cos^m y + m J_{m−2}", src("n°20", 222),
             r"(m+1)J_m - mJ_{m-2} - \sin y\cos^m y", recurrence_derived, printed=lambda: sp.S.Zero,
             check=_recurrence_check),
        Spec(f"{P}.n20.J_even", "J_m(π) = 0 for even m", src("n°20", 222),
             r"\cos^{m+1}(\pi-y)/\cos^{m+1}y\ (m=2n)", J_even_zero, printed=lambda: sp.S.NegativeOne,
             check=_proof_check(-1), note="The reflection y → π − y maps J_m(π) to (−1)^{m+1}J_m(π)."),
        Spec(f"{P}.n20.J_pi_step", "Induction step of the closed form of J_m(π)", src("n°20", 222),
             r"\frac{J_{2n+1}(\pi)}{J_{2n-1}(\pi)} - \frac{2n+1}{2n+2}", J_pi_induction,
             printed=lambda: sp.S.Zero, check=_proof_check(0),
             note="With J_{−1}(π) = π the closed form follows by induction for every odd m."),
        Spec(f"{P}.n20.J_pi", "J_m(π) for odd m", src("n°20", 222), r"J_m(\pi)", J_pi_closed,
             deps=(f"{P}.n20.J_pi_step", f"{P}.n20.recurrence"),
             printed=lambda: sp.pi * sp.factorial2(m) / sp.factorial2(m + 1), check=_quad_J_check, defs=ODD_M,
             readings=(Reading("π (1.3.5…m)/(2.4.6…(m+1))", "π m!!/(m+1)!!"),)),
        Spec(f"{P}.n20.theorem", "For θ^m, the amplitude or the duration changes, never both",
             src("n°19–20", 222), r"\left(E_s(\pi)J_m(\pi)\right)_{m=2n,\ 2n+1}", theorem_derived,
             deps=(f"{P}.n19.Es_pi_even", f"{P}.n19.Es_pi_odd", f"{P}.n20.J_even"),
             printed=lambda: sp.Tuple(0, 0), check=_theorem_check),
        Spec(f"{P}.n20.Ec_pi", "E_c(π) for θ^m, m odd", src("n°20", 223), r"E_c(\pi)", Ec_pi_monomial,
             deps=(f"{P}.n20.J_pi",),
             printed=lambda: -alpha**m / k * sp.pi * sp.factorial2(m) / sp.factorial2(m + 1),
             check=_quad_at_pi(mp.cos, (1, 3, 5)), defs=DEF_ITEMS + ODD_M,
             note="(−α)^m = −α^m for odd m: the derived form keeps (−α)^m; compared for odd m."),
        Spec(f"{P}.n20.dT", "Change of the swing time for θ^m, m odd", src("n°20", 223), r"\Delta T",
             dT_monomial, deps=(f"{P}.n09.dT", f"{P}.n20.Ec_pi"),
             printed=lambda: -eps * alpha ** (m - 1) / k**3 * sp.pi * sp.factorial2(m) / sp.factorial2(m + 1),
             check=_monomial_order_check("dT", (1, 3, 5)), defs=DEF_ITEMS + ODD_M),
    )


def _monomial_quad(trig):
    """E_s(t) or E_c(t) of θ^m against mpmath quad of its definition, m = 1, 2, 3, 6."""
    def check(result, level):
        kv, al = mp.mpf("1.3"), mp.mpf("0.7")
        pairs = []
        for mv in (1, 2, 3, 6):
            for tv in (mp.mpf("0.6"), mp.mpf("2.2")):
                truth = mp.quad(lambda s: (-al * mp.cos(kv * s)) ** mv * trig(kv * s), [0, tv])
                at = {k: sp.Float("1.3", 40), alpha: sp.Float("0.7", 40), t: sp.Float(str(tv), 40)}
                val = sp.N(result.derived.subs(m, mv).subs(at).doit(), 40)
                pairs.append((f"m={mv},t={tv}", val, truth))
        return verify.value_check(truth_desc=f"mpmath quad of ∫_0^t θ0^m {verify.trig_name(trig)} kτ dτ, m = 1, 2, 3, 6",
                                  pairs=pairs, tol=mp.mpf("1e-28"), params=(("k", "1.3"), ("alpha", "0.7")))
    return check


def _quad_at_pi(trig, ms):
    """E_s(π) or E_c(π) of θ^m against mpmath quad of the definition over one swing."""
    def check(result, level):
        kv, al = mp.mpf("1.3"), mp.mpf("0.7")
        pairs = []
        for mv in ms:
            truth = mp.quad(lambda s: (-al * mp.cos(kv * s)) ** mv * trig(kv * s), [0, mp.pi / kv])
            sub = {n: sp.Integer(mv) // 2} if n in result.derived.free_symbols else {m: mv}
            val = sp.N(result.derived.subs(sub).subs({k: sp.Float("1.3", 40), alpha: sp.Float("0.7", 40)}), 40)
            pairs.append((f"m={mv}", val, truth))
        return verify.value_check(truth_desc=f"mpmath quad over 0 ≤ kt ≤ π of θ0^m {verify.trig_name(trig)} kt, m = {ms}",
                                  pairs=pairs, tol=mp.mpf("1e-28"), params=(("k", "1.3"), ("alpha", "0.7")))
    return check
