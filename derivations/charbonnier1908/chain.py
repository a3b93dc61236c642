"""The chain every worked example of Charbonnier follows, as Specs.

model l(θ, θ', t) ──▶ perturbing term P (θ'' + k²θ + P = 0) ──▶ εφ along θ0 = −α cos kt
  ──▶ E_s, E_c ──▶ θ(t), θ'(t) ──▶ ΔT, Δα, ΔT½, Δθ'_m   (general formulas n°9)

An :class:`Example` carries the memoir's printed forms (data) and the model; the
functions below turn it into Specs whose derived forms are computed from the
model and the general formulas, and whose checks integrate the model.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import mpmath as mp
import sympy as sp

from pendsym import checks, pendulum, perturbation, verify
from pendsym.result import KernelSpec, Source, Spec
from . import truth
from .common import ALPHA, ALPHA_CHECK, DPS, K, K_CHECK, MEMOIR, TIME, Geometric, printed
from .symbols import DEFS, E_c, E_s, alpha, dtheta, eps, g, k, l0, t, theta

DELTA = sp.Symbol("delta", positive=True)   # bookkeeping scale of the amplitude
QUANTITIES = ("eom", "eps", "phi", "Es", "Ec", "theta", "dtheta", "dT", "dalpha", "dThalf", "dthetam")


@dataclass(frozen=True)
class Example:
    """One worked example: its model, its printed forms, and how to check it."""

    key: str                                  # "n21"
    name: str
    pages: dict                               # quantity → page ("default" for the others)
    law: str                                  # model name in truth.LAWS
    small: sp.Symbol                          # DELTA (amplitude) or a parameter such as a
    order: int                                # order of P in ``small``
    eps: sp.Expr                              # printed ε
    phi: sp.Expr                              # printed φ (of t, or of θ when phi_of_theta)
    printed: dict = field(default_factory=dict)   # quantity → printed expression (eom, Es, Ec, theta, …)
    readings: dict = field(default_factory=dict)  # quantity → tuple[Reading]
    params: tuple = ()                        # ((symbol, value string), …) for the checks
    extra_args: tuple = ()                    # KernelArgs of the model parameters
    check_range: tuple = ("0.005", "0.1")     # geometric range of the small parameter in checks
    check_param: sp.Symbol = alpha
    phi_of_theta: bool = False
    law_from: str | None = None               # id of a Result whose derived form is the length law
    key_of: dict = field(default_factory=dict)  # quantity → paragraph key where it is not ``key``
    notes: dict = field(default_factory=dict)
    defs: tuple = ()

    def id(self, quantity: str) -> str:
        return f"{MEMOIR}.{self.key_of.get(quantity, self.key)}.{quantity}"

    def src(self, quantity: str) -> Source:
        return Source(MEMOIR, f"n°{self.key_of.get(quantity, self.key)[1:]}",
                      self.pages.get(quantity, self.pages["default"]))

    @property
    def amplitude_problem(self) -> bool:
        return self.small == DELTA


# ----------------------------------------------------------------- derivation
def eom(ex: Example, deps) -> sp.Expr:
    """P from the example's law by the variable-length equation of n°2, to lowest order."""
    law, restoring, _ = truth.LAWS[ex.law]
    if ex.law_from:
        law = deps[ex.law_from].derived
    law = law.subs(g, k**2 * l0)
    P = pendulum.perturbing_term(law, theta, dtheta, t, k, l0, restoring)
    scale = {theta: DELTA * theta, dtheta: DELTA * dtheta} if ex.amplitude_problem else {}
    return sp.factor_terms(pendulum.lowest_order(P, ex.small, scale, ex.order))


def along_motion(P: sp.Expr) -> sp.Expr:
    """εφ(t): P along θ0 = −α cos kt."""
    return sp.simplify(perturbation.along(P, theta, dtheta, -alpha * sp.cos(k * t), t))


def eps_derived(P: sp.Expr, ex: Example) -> sp.Expr:
    """ε = εφ / φ_printed; it must not depend on t (else φ's shape is wrong)."""
    return sp.simplify((along_motion(P) if not ex.phi_of_theta else P) / ex.phi)


def phi_derived(P: sp.Expr, ex: Example) -> sp.Expr:
    """φ = εφ / ε_printed (the memoir's normalization of ε is a convention)."""
    return sp.simplify((P if ex.phi_of_theta else along_motion(P)) / ex.eps)


def phi_of_time(phi: sp.Expr, ex: Example) -> sp.Expr:
    """φ(t): φ itself, or φ(θ, θ') along θ0 = −α cos kt."""
    return perturbation.along(phi, theta, dtheta, -alpha * sp.cos(k * t), t) if ex.phi_of_theta else phi


def Es_derived(deps, ex: Example) -> sp.Expr:
    return perturbation.E_s(phi_of_time(deps[ex.id("phi")].derived, ex), t, k)


def Ec_derived(deps, ex: Example) -> sp.Expr:
    return perturbation.E_c(phi_of_time(deps[ex.id("phi")].derived, ex), t, k)


def motion(deps, ex: Example, which: int) -> sp.Expr:
    """θ(t) (which = 0) or θ'(t) (1) to first order by the general formulas of n°8."""
    theta0 = -alpha * sp.cos(k * t)
    th, dth = perturbation.first_order(theta0, deps[ex.id("Es")].derived, deps[ex.id("Ec")].derived,
                                       ex.eps, k, t)
    return sp.simplify([th, dth][which])


def general(deps, ex: Example, quantity: str) -> sp.Expr:
    """A general formula of n°9 with this example's ε and E_s, E_c at the phase it names."""
    form = deps[f"{MEMOIR}.n09.{quantity}"].derived
    Es, Ec = deps[ex.id("Es")].derived, deps[ex.id("Ec")].derived
    form = form.replace(E_s, lambda x: Es.subs(t, x / k)).replace(E_c, lambda x: Ec.subs(t, x / k))
    return sp.simplify(form.subs(eps, ex.eps))


# ----------------------------------------------------------------- the truth: one swing of the model
def model_values(ex: Example) -> dict:
    return {s.name: v for s, v in ex.params}


def model_symbols(ex: Example) -> tuple:
    """The model parameters, the checked small parameter last when it is not α."""
    return tuple(s for s, _ in ex.params) + (() if ex.check_param == alpha else (ex.check_param,))


def check_params(ex: Example) -> tuple:
    """The fixed parameters of an example's integrations, as an Evidence lists them."""
    return (("k", K_CHECK),) + tuple((s.name, v) for s, v in ex.params)


def numeric(expr, ex: Example):
    """mpmath evaluator of expr in (α, k, t, model parameters…)."""
    return verify.lambdify_mp(expr.subs(DEFS), (alpha, k, t) + model_symbols(ex))


def swing_at(ex: Example, p, dps):
    """The truth swing for the small-parameter value p, and its amplitude α."""
    values = dict(model_values(ex))
    amplitude = ALPHA_CHECK
    if ex.check_param == alpha:
        amplitude = mp.nstr(p, 40)
    else:
        values[ex.check_param.name] = mp.nstr(p, 40)
    return truth.swing(ex.law, amplitude, K_CHECK, dps, **values), mp.mpf(amplitude)


def formula_at(ex: Example, expr, p, time=None):
    """expr at the small-parameter value p (and at t = time)."""
    values = dict(model_values(ex))
    amplitude = p if ex.check_param == alpha else mp.mpf(ALPHA_CHECK)
    if ex.check_param != alpha:
        values[ex.check_param.name] = p
    f = numeric(expr, ex)
    return f(amplitude, mp.mpf(K_CHECK), time if time is not None else 0,
             *(mp.mpf(values[s.name]) for s in model_symbols(ex)))


def expected_order(ex: Example, quantity: str) -> int:
    """Order of the residual of a quantity in the checked small parameter."""
    if ex.check_param != alpha:
        return 2                      # first order in a: residual O(a²)
    base = {"dT": 2, "dThalf": 2, "dthetam": 3, "theta": 3, "dtheta": 3, "dalpha": 3}[quantity]
    return base + ex.order - 1        # next order in the amplitude


# ----------------------------------------------------------------- checks
def order_check_of(ex: Example, quantity: str) -> checks.Order:
    """ΔT, Δα, ΔT½ or Δθ'_m of the printed and derived forms against one integrated swing."""
    def measured(p, dps):
        kv = mp.mpf(K_CHECK)
        sw, amplitude = swing_at(ex, p, dps)
        return {"dT": sw.T - mp.pi / kv, "dalpha": sw.amp - amplitude, "dThalf": sw.t_low - mp.pi / (2 * kv),
                "dthetam": sw.v_low - kv * amplitude}[quantity]

    return checks.Order(
        param=ex.check_param.name, values=Geometric(*ex.check_range), truth=measured,
        at=lambda expr, p: formula_at(ex, expr, p), expected=expected_order(ex, quantity), band=0.35,
        truth_desc=truth.MODEL_TEXT[ex.law],
        params=check_params(ex) + ((("alpha", ALPHA_CHECK),) if ex.check_param != alpha else ()))


def zero_check_of(ex: Example):
    """Δα = 0 of a reversible model: the integrated amplitude returns to α."""
    def check(result, level):
        pairs = []
        for p in verify.geometric(*ex.check_range, 3):
            sw, amplitude = swing_at(ex, p, DPS)
            pairs.append((f"{ex.check_param.name}={mp.nstr(p, 4)}", formula_at(ex, result.derived, p),
                          sw.amp - amplitude))
        return verify.value_check(truth_desc=truth.MODEL_TEXT[ex.law] + "; amplitude at the turning point",
                                  pairs=pairs, tol=mp.mpf("1e-24"), kind="value", params=check_params(ex))
    return check


def motion_check_of(ex: Example, which: int):
    """θ(t) or θ'(t) against the integrated model at t = 0.45T, 1.1T, 2T: the largest error, order fitted.

    The measured quantity is the error of the derived form itself (so its formula is 0); the
    printed form enters as the difference of the two errors, so that order_check fits the
    printed form's own largest error exactly as it fits the derived one's.
    """
    times = (mp.mpf("0.45"), mp.mpf("1.1"), mp.mpf("2.0"))   # in units of T = π/k

    def check(result, level):
        kv = mp.mpf(K_CHECK)

        def largest_error(expr):
            def error(p, dps):
                sw, _ = swing_at(ex, p, dps)
                return max(abs(sw.traj(s * mp.pi / kv)[which] - formula_at(ex, expr, p, s * mp.pi / kv))
                           for s in times)
            return error
        derived_error = largest_error(result.derived)
        printed_error = None if result.printed is None else largest_error(result.printed_value)
        return verify.order_check(
            param=ex.check_param.name, values=Geometric(*ex.check_range)(level), truth=derived_error,
            derived=lambda p: 0,
            printed=None if printed_error is None else (lambda p: derived_error(p, DPS) - printed_error(p, DPS)),
            expected=expected_order(ex, "theta"), band=0.35,
            truth_desc=truth.MODEL_TEXT[ex.law] + "; largest |error| at t = 0.45T, 1.1T, 2T", params=check_params(ex))
    return check


def forcing_of(result, ex: Example, quantity: str) -> sp.Expr:
    """The forcing to test: P(θ, θ', t) itself, or εφ along θ0 with one factor derived."""
    if quantity == "eom":
        return result.derived
    eps_, phi_ = (ex.eps, result.derived) if quantity == "phi" else (result.derived, ex.phi)
    return eps_ * phi_of_time(phi_, ex)


def forcing_check_of(ex: Example, quantity: str):
    """P (or εφ along θ0) against the exact acceleration of the model, order fitted.

    The exact θ'' comes from :func:`pendsym.pendulum.exact_rhs` applied to the
    example's length law; θ''_exact + k²θ + P must vanish to one order beyond P.
    States are (θ, θ') = amplitude × (c1, c2 k) for P, and the unperturbed
    motion for εφ(t).
    """
    along = quantity != "eom"
    states = (("0.3", ("1", "0.7")), ("0.8", ("-0.6", "1.1")), ("1.7", ("0.9", "-1")))   # t, (c1, c2)

    def check(result, level):
        kv = mp.mpf(K_CHECK)
        forcing = forcing_of(result, ex, quantity).subs(DEFS)
        f = verify.lambdify_mp(forcing, (theta, dtheta, alpha, k, t) + model_symbols(ex))

        def residual(p, dps):
            values = dict(model_values(ex))
            amplitude = p if ex.check_param == alpha else mp.mpf(ALPHA_CHECK)
            if ex.check_param != alpha:
                values[ex.check_param.name] = p
            rhs = truth.rhs(ex.law, kv, values)
            pv = [mp.mpf(values[s.name]) for s in model_symbols(ex)]
            worst = mp.mpf(0)
            for tv, (c1, c2) in ((mp.mpf(tv), (mp.mpf(c1), mp.mpf(c2))) for tv, (c1, c2) in states):
                if along:
                    th, dth = -amplitude * mp.cos(kv * tv), amplitude * kv * mp.sin(kv * tv)
                else:
                    th, dth = c1 * amplitude, c2 * amplitude * kv
                acc = rhs(tv, [th, dth])[1]
                worst = max(worst, abs(acc + kv**2 * th + f(th, dth, amplitude, kv, tv, *pv)))
            return worst
        return verify.order_check(
            param=ex.check_param.name, values=Geometric(*ex.check_range)(level), truth=residual,
            derived=lambda p: 0, expected=ex.order + (2 if ex.amplitude_problem else 1), band=0.35,
            truth_desc=truth.MODEL_TEXT[ex.law].replace(", mpmath odefun", "") + ": exact θ'' of the model",
            params=check_params(ex))
    return check


def phi_along_of(result) -> sp.Expr:
    """φ(t) along θ0 for the E_s/E_c Result (from its dependency)."""
    (dep,) = [d for i, d in result.deps.items() if i.endswith(".phi")]
    phi = dep.derived
    if phi.has(theta) or phi.has(dtheta):
        phi = perturbation.along(phi, theta, dtheta, -alpha * sp.cos(k * t), t)
    return phi


def quad_check_of(ex: Example, trig):
    """E_s or E_c (printed and derived) against mpmath quad of its definition with the derived φ."""
    def check(result, level):
        phi = numeric(phi_along_of(result), ex)
        env = {"alpha": ALPHA_CHECK, "k": K_CHECK, **model_values(ex)}
        if ex.check_param != alpha:
            env[ex.check_param.name] = ex.check_range[1]

        def points(level, dps):
            kv, al = mp.mpf(K_CHECK), mp.mpf(ALPHA_CHECK)
            pv = [mp.mpf(env[s.name]) for s in model_symbols(ex)]
            for s in (mp.mpf("0.4"), mp.mpf("1.3"), mp.mpf("2.6")):
                exact = mp.quad(lambda x: phi(al, kv, x, *pv) * trig(kv * x), [0, s])
                yield checks.Point(f"t={s}", {**env, "t": s}, exact)
        return checks.run(checks.Values(
            truth="mpmath quad of the definition ∫_0^t φ " + verify.trig_name(trig) + " kτ dτ", points=points,
            tol=mp.mpf("1e-27"), kind="quadrature",
            params=(("k", K_CHECK), ("alpha", ALPHA_CHECK)) + tuple((s.name, v) for s, v in ex.params)), result, level)
    return check


# ----------------------------------------------------------------- kernel declarations
def kernel(ex: Example, doc: str, with_time: bool = False) -> KernelSpec:
    return KernelSpec(args=(ALPHA, K) + ((TIME,) if with_time else ()) + tuple(ex.extra_args), doc=doc)


# ----------------------------------------------------------------- the Specs of an example
def specs(ex: Example) -> tuple[Spec, ...]:
    defs = tuple(DEFS.items()) + tuple(ex.defs)

    def make(quantity, title, lhs, derive, deps=(), check=None, kern=None):
        form = ex.printed.get(quantity)
        return Spec(ex.id(quantity), title, ex.src(quantity), lhs, derive, deps=deps,
                    printed=None if form is None else printed(form), readings=tuple(ex.readings.get(quantity, ())),
                    check=check, kernel=kern, defs=defs, note=ex.notes.get(quantity, ""))

    def through_n09(quantity):
        return f"{MEMOIR}.n09.{quantity}", ex.id("Es"), ex.id("Ec")

    out = [
        make("eom", "Perturbing term P of θ'' + k²θ + P = 0", "P(\\theta, \\theta', t)",
             lambda d: eom(ex, d), deps=(ex.law_from,) if ex.law_from else (), check=forcing_check_of(ex, "eom")),
        make("eps", "ε (the memoir's normalization)", r"\varepsilon",
             lambda d: eps_derived(d[ex.id("eom")].derived, ex), deps=(ex.id("eom"),),
             check=forcing_check_of(ex, "eps")),
        make("phi", "φ", r"\varphi", lambda d: phi_derived(d[ex.id("eom")].derived, ex), deps=(ex.id("eom"),),
             check=forcing_check_of(ex, "phi")),
        make("Es", "E_s(t)", r"E_s", lambda d: Es_derived(d, ex), deps=(ex.id("phi"),),
             check=quad_check_of(ex, mp.sin), kern=kernel(ex, "E_s(t)", True)),
        make("Ec", "E_c(t)", r"E_c", lambda d: Ec_derived(d, ex), deps=(ex.id("phi"),),
             check=quad_check_of(ex, mp.cos), kern=kernel(ex, "E_c(t)", True)),
        make("theta", "θ(t) to first order", r"\theta(t)", lambda d: motion(d, ex, 0),
             deps=(ex.id("Es"), ex.id("Ec")), check=motion_check_of(ex, 0), kern=kernel(ex, "θ(t), first order", True)),
        make("dtheta", "θ'(t) to first order", r"\theta'(t)", lambda d: motion(d, ex, 1),
             deps=(ex.id("Es"), ex.id("Ec")), check=motion_check_of(ex, 1),
             kern=kernel(ex, "θ'(t), first order", True)),
        make("dT", "Change of the swing time", r"\Delta T", lambda d: general(d, ex, "dT"), deps=through_n09("dT"),
             check=order_check_of(ex, "dT"), kern=kernel(ex, "ΔT, first order")),
    ]
    amplitude_kept = ex.check_param == alpha        # a reversible model: Δα = 0 exactly
    out.append(make("dalpha", "Change of the amplitude", r"\Delta\alpha", lambda d: general(d, ex, "dalpha"),
                    deps=through_n09("dalpha"),
                    check=zero_check_of(ex) if amplitude_kept else order_check_of(ex, "dalpha"),
                    kern=None if amplitude_kept else kernel(ex, "Δα, first order")))
    if "dThalf" in ex.printed:
        out.append(make("dThalf", "Change of the time to the lowest point", r"\Delta T_{1/2}",
                        lambda d: general(d, ex, "dThalf"), deps=through_n09("dThalf"),
                        check=order_check_of(ex, "dThalf"), kern=kernel(ex, "ΔT½, first order")))
        out.append(make("dthetam", "Change of the speed at the lowest point", r"\Delta\theta'_m",
                        lambda d: general(d, ex, "dthetam"), deps=through_n09("dthetam"),
                        check=order_check_of(ex, "dthetam"), kern=kernel(ex, "Δθ'_m, first order")))
    return tuple(out)
