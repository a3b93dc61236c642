"""Charbonnier 1908 §IV, the perturbing function depends on the angle: n°18 (E_s, E_c as quadratures
in θ), n°19 (the monomial θ^m: E_s), n°20 (the monomial: E_c, the integrals J_m, ΔT), pp. 220–223.
"""
from __future__ import annotations

import mpmath as mp
import sympy as sp

from pendsym import checks, perturbation, verify, wallis
from pendsym.result import Reading, Spec
from . import truth
from .common import ALPHA_OSCILLATOR, EPSILONS, K_OSCILLATOR, READ_DALPHA, printed, rid, src
from .symbols import DEF_ITEMS, E_c, E_s, alpha, dtheta, eps, k, m, n, t, theta, varphi, y

ODD_M = ((m, 2 * n + 1),)    # the claim holds for odd m: compared on m = 2n + 1
u = sp.Symbol("u", real=True)                       # the angle as the variable of quadrature
THETA_OF_T = ((theta, -alpha * sp.cos(k * t)),)     # θ along the unperturbed motion
PHI_TESTS = (sp.Lambda(u, u**2 + sp.exp(u / 3)), sp.Lambda(u, sp.cos(u) - u**3 / 5))
PHI_INSTANCES = tuple(((varphi, lam),) for lam in PHI_TESTS)


# ----------------------------------------------------------------- derivation: n°18
def Es_theta_derived(_deps) -> sp.Expr:
    """E_s as a quadrature in θ: sin kt dt = dθ/(kα) along θ = −α cos kt (n°18 1°, p. 221)."""
    tau = sp.Symbol("tau", nonnegative=True)
    integral = sp.Integral(varphi(-alpha * sp.cos(k * tau)) * sp.sin(k * tau), (tau, 0, t))
    return integral.transform(-alpha * sp.cos(k * tau), u)


def Ec_theta_derived(_deps) -> sp.Expr:
    """E_c by parts: cos kt dt = dθ'/(k²α), E_c = [θ'φ − ∫θ'φ'(θ)dθ]/(k²α) (n°18 2°, p. 221)."""
    tau = sp.Symbol("tau", nonnegative=True)
    theta0 = -alpha * sp.cos(k * tau)
    speed = sp.diff(theta0, tau)                               # θ0'
    # ∫ φ(θ0) dθ0' = φ θ0' − ∫ θ0' dφ(θ0)  (integration by parts, in τ)
    boundary = (varphi(theta0) * speed).subs(tau, t) - (varphi(theta0) * speed).subs(tau, 0)
    rest = sp.Integral(speed * sp.diff(varphi(theta0), tau), (tau, 0, t))
    return (boundary - rest) / (k**2 * alpha)


# ----------------------------------------------------------------- derivation: n°19–20, the monomial θ^m
def Es_monomial(_deps) -> sp.Expr:
    """E_s for φ = θ^m along θ0 = −α cos kt, m symbolic (n°19, p. 221)."""
    return perturbation.E_s(perturbation.along(theta**m, theta, dtheta, -alpha * sp.cos(k * t), t), t, k)


def Ec_monomial(_deps) -> sp.Expr:
    """E_c for φ = θ^m, left as (−α)^m/k · J_m(kt) with J_m the integral of n°20."""
    x = sp.Symbol("x", real=True)
    integrand = perturbation.along(theta**m, theta, dtheta, -alpha * sp.cos(k * t), t).subs(t, x / k) * sp.cos(x)
    return sp.powsimp(sp.Integral(sp.powsimp(sp.expand_power_base(integrand, force=True), force=True),
                                  (x, 0, k * t)) / k, force=True)


def Es_pi_parity(deps, parity: int) -> sp.Expr:
    """E_s(π) with m = 2n + parity: the parity split of n°19 proved for every n."""
    es = deps[rid(19, "Es")].derived.subs(t, sp.pi / k)
    return sp.simplify(sp.powsimp(es.subs(m, 2 * n + parity), force=True))


def dalpha_monomial(deps) -> sp.Expr:
    """Δα = −(ε/k)E_s(π) with E_s(π) of even m (n°19, with n°9 2°)."""
    general = deps[rid(9, "dalpha")].derived
    es_pi = deps[rid(19, "Es_pi_even")].derived.subs(n, m / 2)
    return sp.simplify(general.subs(E_s(sp.pi), es_pi))


def recurrence_derived(_deps) -> sp.Expr:
    """(m+1)J_m − m J_{m−2} − sin y cos^m y, as the integral of a vanishing derivative (n°20)."""
    return wallis.recurrence_defect(m, y)


def J_pi_induction(_deps) -> sp.Expr:
    """J_{2n+1}(π)/J_{2n−1}(π) − (2n+1)/(2n+2) for the closed form; zero proves the induction step."""
    ratio = sp.expand_func((wallis.J_pi_odd(2 * n + 1) / wallis.J_pi_odd(2 * n - 1)).rewrite(sp.gamma))
    return sp.simplify(sp.gammasimp(ratio) - (2 * n + 1) / (2 * n + 2))


def J_pi_closed(_deps) -> sp.Expr:
    """J_m(π) for odd m: the recurrence at y = π gives J_m = m/(m+1) J_{m−2}, J_{−1} = π (n°20)."""
    return wallis.J_pi_odd(m)


def J_even_zero(_deps) -> sp.Expr:
    """cos^{m+1}(π−y)/cos^{m+1}(y) for even m = 2n: −1, so J_m(π) = −J_m(π) = 0 (n°20)."""
    return sp.simplify(wallis.parity_reflection(2 * n, y))


def Ec_pi_monomial(deps) -> sp.Expr:
    """E_c(π) = (−α)^m/k · J_m(π), m odd (n°20, p. 223)."""
    return (-alpha) ** m / k * deps[rid(20, "J_pi")].derived


def dT_monomial(deps) -> sp.Expr:
    """ΔT = ε E_c(π)/(k²α) with the E_c(π) of odd m (n°20 with n°9)."""
    general = deps[rid(9, "dT")].derived
    ec = deps[rid(20, "Ec_pi")].derived
    return sp.simplify(sp.powsimp(general.subs(E_c(sp.pi), ec), force=True).subs((-1) ** m, -1))


def theorem_derived(deps) -> sp.Expr:
    """(E_s(π)·J_m(π) for m = 2n, the same for m = 2n+1): both zero, so amplitude and
    duration never change together (n°19–20)."""
    J = sp.Symbol("J")
    reflection = deps[rid(20, "J_even")].derived
    # even m: the reflection gives J_m(π) = reflection·J_m(π), whose only solution is 0 when it is ≠ 1
    J_even = sp.solve(sp.Eq(J, reflection * J), J)
    if J_even != [0]:
        raise ValueError("the reflection does not force J_m(pi) = 0")
    return sp.Tuple(deps[rid(19, "Es_pi_even")].derived * J_even[0],
                    sp.simplify(deps[rid(19, "Es_pi_odd")].derived * wallis.J_pi_odd(2 * n + 1)))


# ----------------------------------------------------------------- printed
def Es_theta_printed() -> sp.Expr:
    return sp.Integral(varphi(u), (u, -alpha, theta)) / (k * alpha)


def Ec_theta_printed() -> sp.Expr:
    # θ' as a function of θ along the motion: θ'² = k²(α² − θ²) for 0 ≤ kt ≤ π
    speed = k * sp.sqrt(alpha**2 - u**2)
    return (k * sp.sqrt(alpha**2 - theta**2) * varphi(theta)
            - sp.Integral(speed * sp.Derivative(varphi(u), u), (u, -alpha, theta))) / (k**2 * alpha)


def J_pi_printed(m_) -> sp.Expr:
    """π (1·3·5…m)/(2·4·6…(m+1))."""
    return sp.pi * sp.factorial2(m_) / sp.factorial2(m_ + 1)


PRINTED = {
    "Es": (-alpha) ** m / k / (m + 1) * (1 - sp.cos(k * t) ** (m + 1)),
    "Es_pi_even": alpha ** (2 * n) / k * 2 / (2 * n + 1),
    "dalpha": -2 * eps / (m + 1) * alpha**m / k**2,
    "Ec": (-alpha) ** m / k * sp.Integral(sp.cos(y) ** (m + 1), (y, 0, k * t)),
    "J_pi": J_pi_printed(m),
    "Ec_pi": -alpha**m / k * J_pi_printed(m),
    "dT": -eps * alpha ** (m - 1) / k**3 * J_pi_printed(m),
}


# ----------------------------------------------------------------- checks
def n18_check(result, level):
    """Quadrature in time of the definition vs the θ-form, for two test functions φ."""
    pairs = []
    kv, al = mp.mpf("1.3"), mp.mpf("0.7")
    for lam in PHI_TESTS:
        f = sp.lambdify(u, lam(u), modules="mpmath")
        df = sp.lambdify(u, sp.diff(lam(u), u), modules="mpmath")
        for tv in (mp.mpf("0.4"), mp.mpf("1.9")):
            th = -al * mp.cos(kv * tv)
            if result.id.endswith("Es_theta"):
                exact = mp.quad(lambda s: f(-al * mp.cos(kv * s)) * mp.sin(kv * s), [0, tv])
                form = mp.quad(f, [-al, th]) / (kv * al)
            else:
                exact = mp.quad(lambda s: f(-al * mp.cos(kv * s)) * mp.cos(kv * s), [0, tv])
                speed = kv * al * mp.sin(kv * tv)
                # the θ-integral of θ'φ'(θ) runs over the branch θ' = k√(α²−θ²) ≥ 0 (kt ≤ π)
                form = (speed * f(th) - mp.quad(lambda s: kv * mp.sqrt(al**2 - s**2) * df(s), [-al, th])) / (kv**2 * al)
            pairs.append((f"t={tv}", form, exact))
    return verify.value_check(truth_desc="mpmath quad of the time integral of the definition (n°18), "
                              "φ = θ² + e^{θ/3} and cos θ − θ³/5, k = 1.3, α = 0.7",
                              pairs=pairs, tol=mp.mpf("1e-25"), params=(("k", "1.3"), ("alpha", "0.7")))


def monomial_quad_check(trig):
    """E_s(t) or E_c(t) of θ^m against mpmath quad of its definition, m = 1, 2, 3, 6."""
    def check(result, level):
        kv, al = mp.mpf("1.3"), mp.mpf("0.7")
        pairs = []
        for mv in (1, 2, 3, 6):
            for tv in (mp.mpf("0.6"), mp.mpf("2.2")):
                exact = mp.quad(lambda s: (-al * mp.cos(kv * s)) ** mv * trig(kv * s), [0, tv])
                at = {k: sp.Float("1.3", 40), alpha: sp.Float("0.7", 40), t: sp.Float(str(tv), 40)}
                pairs.append((f"m={mv},t={tv}", sp.N(result.derived.subs(m, mv).subs(at).doit(), 40), exact))
        return verify.value_check(truth_desc=f"mpmath quad of ∫_0^t θ0^m {verify.trig_name(trig)} kτ dτ, m = 1, 2, 3, 6",
                                  pairs=pairs, tol=mp.mpf("1e-28"), params=(("k", "1.3"), ("alpha", "0.7")))
    return check


def quad_at_pi_check(trig, ms):
    """E_s(π) or E_c(π) of θ^m against mpmath quad of the definition over one swing."""
    def check(result, level):
        kv, al = mp.mpf("1.3"), mp.mpf("0.7")
        pairs = []
        for mv in ms:
            exact = mp.quad(lambda s: (-al * mp.cos(kv * s)) ** mv * trig(kv * s), [0, mp.pi / kv])
            sub = {n: sp.Integer(mv) // 2} if n in result.derived.free_symbols else {m: mv}
            val = sp.N(result.derived.subs(sub).subs({k: sp.Float("1.3", 40), alpha: sp.Float("0.7", 40)}), 40)
            pairs.append((f"m={mv}", val, exact))
        return verify.value_check(truth_desc=f"mpmath quad over 0 ≤ kt ≤ π of θ0^m {verify.trig_name(trig)} kt, m = {ms}",
                                  pairs=pairs, tol=mp.mpf("1e-28"), params=(("k", "1.3"), ("alpha", "0.7")))
    return check


def J_pi_quad_check(result, level):
    """J_m(π) against mpmath quad of ∫_0^π cos^{m+1}, odd m ≤ 9."""
    pairs = []
    for mv in range(1, 10, 2):
        exact = mp.quad(lambda s: mp.cos(s) ** (mv + 1), [0, mp.pi])
        pairs.append((f"m={mv}", sp.N(result.derived.subs(m, mv), 40), exact))
    return verify.value_check(truth_desc="mpmath quad of ∫_0^π cos^{m+1} y dy, m = 1, 3, …, 9",
                              pairs=pairs, tol=mp.mpf("1e-28"))


def recurrence_quad_check(result, level):
    """(m+1)J_m = sin y cos^m y + m J_{m−2} with every J by mpmath quad, m = 1…7."""
    pairs = []
    for mv in range(1, 8):
        for yv in (mp.mpf("0.7"), mp.mpf("2.3")):
            J = lambda j: mp.quad(lambda s: mp.cos(s) ** (j + 1), [0, yv])
            pairs.append((f"m={mv}", (mv + 1) * J(mv), mp.sin(yv) * mp.cos(yv) ** mv + mv * J(mv - 2)))
    return verify.value_check(truth_desc="mpmath quad of J_m and J_{m−2}, m = 1…7, y = 0.7, 2.3",
                              pairs=pairs, tol=mp.mpf("1e-28"))


RECURRENCE_CHECK = checks.All((
    checks.Proof("d/dy[sin y cos^m y] = (m+1)cos^{m+1} − m cos^{m−1} for symbolic m", truth="symbolic proof"),
    recurrence_quad_check))


def proof_of(expected) -> checks.Proof:
    """SymPy reduces the derived form to ``expected`` for a symbolic m (or n)."""
    return checks.Proof(f"SymPy reduces the derived form to {sp.sstr(expected)} for symbolic m (n)",
                        holds=lambda expr: sp.simplify(expr - expected) == 0, truth="symbolic proof for general m")


def monomial_order(quantity: str, mv: int):
    """ΔT or Δα of θ'' + k²θ + εθ^m = 0 for one m against the formula: residual O(ε²)."""
    def check(result, level):
        kv, al = mp.mpf(K_OSCILLATOR), mp.mpf(ALPHA_OSCILLATOR)
        form = verify.lambdify_mp(result.derived.subs(m, mv), (eps, k, alpha))

        def measured(ev, dps):
            sw = truth.oscillator(f"theta^{mv}", mp.nstr(ev, 40), K_OSCILLATOR, "-" + ALPHA_OSCILLATOR, "0", dps)
            return sw.T - mp.pi / kv if quantity == "dT" else sw.amp - al
        return verify.order_check(
            param="epsilon", values=EPSILONS(level), truth=measured, derived=lambda ev: form(ev, kv, al),
            expected=2, band=0.3, params=(("m", str(mv)), ("k", K_OSCILLATOR), ("alpha", ALPHA_OSCILLATOR)),
            truth_desc=f"θ'' + k²θ + εθ^{mv} = 0 (mpmath odefun)")
    return check


def monomial_order_check(quantity: str, ms: tuple[int, ...]) -> checks.All:
    return checks.All(tuple(monomial_order(quantity, mv) for mv in ms),
                      truth=f"θ'' + k²θ + εθ^m = 0, m = {ms}, integrated by mpmath odefun")


def unchanged_swing_time(mv: int):
    """The truth side of n°20: for θ^{mv}, m even, the swing time changes by O(ε²) only."""
    def check(result, level):
        kv = mp.mpf(K_OSCILLATOR)
        return verify.order_check(
            param="epsilon", values=EPSILONS(level), expected=2, band=0.3, derived=lambda ev: 0,
            truth=lambda ev, dps: truth.oscillator(f"theta^{mv}", mp.nstr(ev, 40), K_OSCILLATOR, "-0.4", "0", dps).T - mp.pi / kv,
            truth_desc=f"m = {mv}: ΔT is O(ε²)")
    return check


THEOREM_CHECK = checks.All((
    checks.Proof("E_s(π)·J_m(π) = 0 for m = 2n and m = 2n+1, n symbolic",
                 holds=lambda pair: all(sp.simplify(x) == 0 for x in pair), truth="symbolic proof"),
    unchanged_swing_time(2), unchanged_swing_time(4)))


# ----------------------------------------------------------------- the Result table
def specs() -> tuple[Spec, ...]:
    return (
        Spec(rid(18, "Es_theta"), "E_s as a quadrature in θ, for φ = φ(θ)", src("n°18 1°", 221), r"E_s",
             Es_theta_derived, printed=Es_theta_printed, check=n18_check,
             readings=(Reading("upper limit 0 in ∫_{−α}^0 φ(θ)dθ", "θ: E_s(π) = (1/kα)∫_{−α}^{α}φ, as the "
                               "following remark on odd φ needs", certain=False),),
             defs=DEF_ITEMS + THETA_OF_T, instances=PHI_INSTANCES),
        Spec(rid(18, "Ec_theta"), "E_c by parts, for φ = φ(θ)", src("n°18 2°", 221), r"E_c",
             Ec_theta_derived, printed=Ec_theta_printed, check=n18_check,
             readings=(Reading("∫_{−α}^0 θ'φ'(θ)dθ", "upper limit θ (as in 1°)", certain=False),
                       Reading("θ' in the bracket", "θ' = k√(α²−θ²), the branch 0 ≤ kt ≤ π"),),
             defs=DEF_ITEMS + THETA_OF_T, instances=PHI_INSTANCES),
        Spec(rid(19, "Es"), "E_s for φ = θ^m", src("n°19", 221), r"E_s", Es_monomial, printed=printed(PRINTED["Es"]),
             check=monomial_quad_check(mp.sin), defs=DEF_ITEMS),
        Spec(rid(19, "Es_pi_even"), "E_s(π) for even m = 2n", src("n°19", 222), r"E_s(\pi)",
             lambda d: Es_pi_parity(d, 0), deps=(rid(19, "Es"),), printed=printed(PRINTED["Es_pi_even"]),
             check=quad_at_pi_check(mp.sin, (2, 4, 6)), defs=DEF_ITEMS),
        Spec(rid(19, "Es_pi_odd"), "E_s(π) = 0 for odd m = 2n+1", src("n°19", 222), r"E_s(\pi)",
             lambda d: Es_pi_parity(d, 1), deps=(rid(19, "Es"),), printed=printed(sp.S.Zero),
             check=proof_of(0), defs=DEF_ITEMS),
        Spec(rid(19, "dalpha"), "Change of amplitude for θ^m, m even", src("n°19 (n°9, 2°)", 222),
             r"\Delta\alpha", dalpha_monomial, deps=(rid(9, "dalpha"), rid(19, "Es_pi_even")),
             printed=printed(PRINTED["dalpha"]), readings=(READ_DALPHA,),
             check=monomial_order_check("dalpha", (2, 4)), defs=DEF_ITEMS),
        Spec(rid(20, "Ec"), "E_c for φ = θ^m", src("n°20", 222), r"E_c", Ec_monomial, printed=printed(PRINTED["Ec"]),
             readings=(Reading("∫_0^{kt} cos^{m+1} kt dkt", "∫_0^{kt} cos^{m+1} y dy"),),
             check=monomial_quad_check(mp.cos), defs=DEF_ITEMS),
        Spec(rid(20, "recurrence"), "(m+1)J_m = sin y cos^m y + m J_{m−2}", src("n°20", 222),
             r"(m+1)J_m - mJ_{m-2} - \sin y\cos^m y", recurrence_derived, printed=printed(sp.S.Zero),
             check=RECURRENCE_CHECK),
        Spec(rid(20, "J_even"), "J_m(π) = 0 for even m", src("n°20", 222),
             r"\cos^{m+1}(\pi-y)/\cos^{m+1}y\ (m=2n)", J_even_zero, printed=printed(sp.S.NegativeOne),
             check=proof_of(-1), note="The reflection y → π − y maps J_m(π) to (−1)^{m+1}J_m(π)."),
        Spec(rid(20, "J_pi_step"), "Induction step of the closed form of J_m(π)", src("n°20", 222),
             r"\frac{J_{2n+1}(\pi)}{J_{2n-1}(\pi)} - \frac{2n+1}{2n+2}", J_pi_induction,
             printed=printed(sp.S.Zero), check=proof_of(0),
             note="With J_{−1}(π) = π the closed form follows by induction for every odd m."),
        Spec(rid(20, "J_pi"), "J_m(π) for odd m", src("n°20", 222), r"J_m(\pi)", J_pi_closed,
             deps=(rid(20, "J_pi_step"), rid(20, "recurrence")), printed=printed(PRINTED["J_pi"]),
             check=J_pi_quad_check, defs=ODD_M,
             readings=(Reading("π (1.3.5…m)/(2.4.6…(m+1))", "π m!!/(m+1)!!"),)),
        Spec(rid(20, "theorem"), "For θ^m, the amplitude or the duration changes, never both",
             src("n°19–20", 222), r"\left(E_s(\pi)J_m(\pi)\right)_{m=2n,\ 2n+1}", theorem_derived,
             deps=(rid(19, "Es_pi_even"), rid(19, "Es_pi_odd"), rid(20, "J_even")),
             printed=printed(sp.Tuple(0, 0)), check=THEOREM_CHECK),
        Spec(rid(20, "Ec_pi"), "E_c(π) for θ^m, m odd", src("n°20", 223), r"E_c(\pi)", Ec_pi_monomial,
             deps=(rid(20, "J_pi"),), printed=printed(PRINTED["Ec_pi"]),
             check=quad_at_pi_check(mp.cos, (1, 3, 5)), defs=DEF_ITEMS + ODD_M,
             note="(−α)^m = −α^m for odd m: the derived form keeps (−α)^m; compared for odd m."),
        Spec(rid(20, "dT"), "Change of the swing time for θ^m, m odd", src("n°20", 223), r"\Delta T",
             dT_monomial, deps=(rid(9, "dT"), rid(20, "Ec_pi")), printed=printed(PRINTED["dT"]),
             check=monomial_order_check("dT", (1, 3, 5)), defs=DEF_ITEMS + ODD_M),
    )
