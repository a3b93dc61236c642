"""Charbonnier 1908, the general formulas of n°8–9 (not in the file; rebuilt).

n°8–9 are rebuilt by variation of constants from θ'' + k²θ + εφ = 0,
θ0 = −α cos kt, and confirmed by their uses in the seed (n°21 4°–7°,
n°32–34).  E_s and E_c of the phase are written E_s(π), E_c(π/2) as the
memoir does: the argument is kt.
"""
from __future__ import annotations

import mpmath as mp
import sympy as sp

from pendsym import perturbation, verify
from pendsym.result import Reading, Spec
from . import truth
from .common import ALPHA_OSCILLATOR, EPSILONS, K_OSCILLATOR, rid, src
from .symbols import DEF_ITEMS, E_c, E_s, alpha, dtheta, eps, k, t, theta, theta_i, omega_i

# E_s, E_c as functions of time (for the derivation); E_s, E_c of the phase are the memoir's
Es_of_t, Ec_of_t = sp.Function("E_s_t"), sp.Function("E_c_t")
varphi_of_t = sp.Function("varphi")(t)


def to_phase(expr: sp.Expr) -> sp.Expr:
    """E_s_t(τ) → E_s(kτ): the memoir writes E_s(π) for the value at t = π/k."""
    return (expr.replace(Es_of_t, lambda arg: E_s(sp.expand(k * arg)))
            .replace(Ec_of_t, lambda arg: E_c(sp.expand(k * arg))))


# ----------------------------------------------------------------- derivation: n°8 (rebuilt)
def theta_general(_deps) -> sp.Expr:
    """θ(t) to first order from any (θ_i, ω_i): θ0 + (ε/k)(E_s cos kt − E_c sin kt) (n°8, rebuilt)."""
    theta0 = perturbation.unperturbed(t, k, theta_i, omega_i)
    return theta0 + perturbation.theta1(Es_of_t(t), Ec_of_t(t), eps, k, t)


def dtheta_general(deps) -> sp.Expr:
    """θ'(t): the derivative of n°8's θ with E_s' = φ sin kt, E_c' = φ cos kt (rebuilt n°8)."""
    th = deps[rid(8, "theta")].derived
    d = sp.diff(th, t).subs({sp.Derivative(Es_of_t(t), t): varphi_of_t * sp.sin(k * t),
                             sp.Derivative(Ec_of_t(t), t): varphi_of_t * sp.cos(k * t)})
    return sp.expand(sp.simplify(d))


# ----------------------------------------------------------------- derivation: n°9 (rebuilt)
def _at_rest(expr: sp.Expr) -> sp.Expr:
    return expr.subs({theta_i: -alpha, omega_i: 0})


def _parts(deps):
    """(θ0, θ1, θ1') of the start at rest at −α."""
    th = _at_rest(deps[rid(8, "theta")].derived)
    dth = _at_rest(deps[rid(8, "dtheta")].derived)
    theta0 = perturbation.unperturbed(t, k, -alpha)
    return theta0, th - theta0, dth - sp.diff(theta0, t)


def dT_general(deps) -> sp.Expr:
    """ΔT: shift of the turning point t* = π/k, −θ1'(t*)/θ0''(t*) (n°9, used n°21 5°, n°32)."""
    theta0, _, dtheta1 = _parts(deps)
    return to_phase(perturbation.turning_shift(theta0, dtheta1, t, sp.pi / k))


def dalpha_general(deps) -> sp.Expr:
    """Δα: θ1 at the turning point π/k, where θ0 = +α (n°9, used n°33)."""
    _, theta1, _ = _parts(deps)
    return to_phase(sp.simplify(theta1.subs(t, sp.pi / k)))


def dThalf_general(deps) -> sp.Expr:
    """ΔT½: shift of the lowest point t* = π/(2k), −θ1(t*)/θ0'(t*) (n°9 3°, used n°21 7°, n°34)."""
    theta0, theta1, _ = _parts(deps)
    return to_phase(perturbation.crossing_shift(theta0, theta1, t, sp.pi / (2 * k)))


def dthetam_general(deps) -> sp.Expr:
    """Δθ'_m: θ1' at the lowest point (θ0'' = 0 there) (n°9 3°, used n°21 7°, n°34)."""
    _, _, dtheta1 = _parts(deps)
    return to_phase(sp.simplify(dtheta1.subs(t, sp.pi / (2 * k))))


# ----------------------------------------------------------------- printed (as stated in n°21, n°32–34)
def dT_printed() -> sp.Expr:
    return eps / (k**2 * alpha) * E_c(sp.pi)


def dalpha_printed() -> sp.Expr:
    return -eps / k * E_s(sp.pi)


def dThalf_printed() -> sp.Expr:
    return eps / (k**2 * alpha) * E_c(sp.pi / 2)


def dthetam_printed() -> sp.Expr:
    return -eps * E_s(sp.pi / 2)


# ----------------------------------------------------------------- checks: a generic φ(θ, θ', t), k = 1.7
PHI_GENERIC = truth.PHIS["generic"]
GENERIC_TEXT = "θ'' + k²θ + εφ = 0 with φ = θ² + θθ'/2 + θ sin(1.3t) + 1/3, k = 1.7 (mpmath odefun)"


def E_quad(phi_expr, k_val, theta_start, omega_start, upto, trig):
    """E_s or E_c (trig = sin or cos) of φ along θ0 from (θ_i, ω_i), by mpmath quad."""
    theta0 = perturbation.unperturbed(t, k, theta_i, omega_i)
    f = sp.lambdify((t, k, theta_i, omega_i), perturbation.along(phi_expr, theta, dtheta, theta0, t),
                    modules="mpmath")
    return mp.quad(lambda s: f(s, k_val, theta_start, omega_start) * trig(k_val * s), [0, upto])


EVENTS = {"dT": (mp.pi, E_c), "dalpha": (mp.pi, E_s), "dThalf": (mp.pi / 2, E_c), "dthetam": (mp.pi / 2, E_s)}


def event_check(quantity: str):
    """A general formula of n°9 against the integrated oscillator: residual O(ε²)."""
    def check(result, level):
        kv, al = mp.mpf(K_OSCILLATOR), mp.mpf(ALPHA_OSCILLATOR)
        phase, fn = EVENTS[quantity]
        E = sp.Symbol("E")
        form = verify.lambdify_mp(result.derived.replace(fn, lambda arg: E), (E, eps, k, alpha))

        def formula(ev):
            return form(E_quad(PHI_GENERIC, kv, -al, 0, phase / kv, mp.sin if fn is E_s else mp.cos), ev, kv, al)

        def measured(ev, dps):
            sw = truth.oscillator("generic", mp.nstr(ev, 40), K_OSCILLATOR, "-" + ALPHA_OSCILLATOR, "0", dps)
            return {"dT": sw.T - mp.pi / kv, "dalpha": sw.amp - al,
                    "dThalf": sw.t_low - mp.pi / (2 * kv), "dthetam": sw.v_low - kv * al}[quantity]

        return verify.order_check(
            param="epsilon", values=EPSILONS(level), truth=measured, derived=formula, expected=2, band=0.3,
            truth_desc=GENERIC_TEXT + "; E_s, E_c by mpmath quad along θ0",
            params=(("k", K_OSCILLATOR), ("alpha", ALPHA_OSCILLATOR)))
    return check


def motion_check(which: int):
    """θ(t) (which = 0) or θ'(t) (1) from θ(0) = 0.3, θ'(0) = 0.5 against the integrated oscillator."""
    def check(result, level):
        kv, thi, omi = mp.mpf(K_OSCILLATOR), mp.mpf("0.3"), mp.mpf("0.5")
        times = [mp.mpf(s) for s in ("0.5", "1.3", "2.9")]
        Es, Ec, phi = sp.symbols("Es Ec PHI")
        expr = result.derived.subs({Es_of_t(t): Es, Ec_of_t(t): Ec, varphi_of_t: phi})
        f = verify.lambdify_mp(expr, (Es, Ec, phi, eps, k, t, theta_i, omega_i))
        theta0 = perturbation.unperturbed(t, k, theta_i, omega_i)
        phi_along = sp.lambdify((t, k, theta_i, omega_i), perturbation.along(PHI_GENERIC, theta, dtheta, theta0, t),
                                modules="mpmath")

        def formula_at(ev, s):
            es = E_quad(PHI_GENERIC, kv, thi, omi, s, mp.sin)
            ec = E_quad(PHI_GENERIC, kv, thi, omi, s, mp.cos)
            return f(es, ec, phi_along(s, kv, thi, omi), ev, kv, s, thi, omi)

        def largest_error(ev, dps):
            # the truth enters only through |θ_true − θ_formula|; order_check subtracts 0
            traj = truth.oscillator("generic", mp.nstr(ev, 40), K_OSCILLATOR, "0.3", "0.5", dps)
            return max(abs(traj(s)[which] - formula_at(ev, s)) for s in times)

        return verify.order_check(
            param="epsilon", values=EPSILONS(level), truth=largest_error, derived=lambda ev: 0, expected=2,
            band=0.3, truth_desc="θ'' + k²θ + εφ = 0 from θ(0) = 0.3, θ'(0) = 0.5, k = 1.7, generic φ "
                                 "(mpmath odefun); largest |error| at t = 0.5, 1.3, 2.9",
            params=(("k", K_OSCILLATOR), ("theta_i", "0.3"), ("omega_i", "0.5")))
    return check


# ----------------------------------------------------------------- the Result table
def specs() -> tuple[Spec, ...]:
    events = (rid(8, "theta"), rid(8, "dtheta"))
    return (
        Spec(rid(8, "theta"), "θ(t) to first order, any k, any φ(θ, θ', t), any initial state",
             src("n°8 (not in the file; rebuilt), confirmed by n°21 4°", 220), r"\theta(t)",
             theta_general, check=motion_check(0), defs=DEF_ITEMS,
             note="Rebuilt by variation of constants; θ_i, ω_i are the initial angle and speed."),
        Spec(rid(8, "dtheta"), "θ'(t) to first order", src("n°8 (rebuilt)", 220), r"\theta'(t)",
             dtheta_general, deps=(rid(8, "theta"),), check=motion_check(1), defs=DEF_ITEMS),
        Spec(rid(9, "dT"), "Change of the swing time (general formula)", src("n°9, stated in n°32", 235),
             r"\Delta T", dT_general, deps=events, printed=dT_printed, check=event_check("dT"), defs=DEF_ITEMS),
        Spec(rid(9, "dalpha"), "Change of the amplitude (general formula)", src("n°9, stated in n°33", 236),
             r"\Delta\alpha", dalpha_general, deps=events, printed=dalpha_printed,
             readings=(Reading("Δx = − ε/k E_s(π)", "Δα: the OCR reads α as x"),),
             check=event_check("dalpha"), defs=DEF_ITEMS),
        Spec(rid(9, "dThalf"), "Change of the time to the lowest point (general formula)",
             src("n°9 3°, stated in n°21 7° and n°34", 225), r"\Delta T_{1/2}", dThalf_general, deps=events,
             printed=dThalf_printed, check=event_check("dThalf"), defs=DEF_ITEMS),
        Spec(rid(9, "dthetam"), "Change of the speed at the lowest point (general formula)",
             src("n°9 3°, stated in n°21 7° and n°34", 225), r"\Delta\theta'_m", dthetam_general, deps=events,
             printed=dthetam_printed,
             readings=(Reading("Δv'_m = −ε E_s(π/2) (n°34)", "Δθ'_m, as in n°21 7°", certain=False),),
             check=event_check("dthetam"), defs=DEF_ITEMS),
    )
