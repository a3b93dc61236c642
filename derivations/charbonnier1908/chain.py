"""The chain every worked example of Charbonnier follows, as Specs.

model l(θ, θ', t) ──▶ perturbing term P (θ'' + k²θ + P = 0) ──▶ εφ along θ0 = −α cos kt
  ──▶ E_s, E_c ──▶ θ(t), θ'(t) ──▶ ΔT, Δα, ΔT½, Δθ'_m   (general formulas n°9)

An :class:`Example` carries the memoir's printed forms and the model; the
functions below turn it into Specs whose derived forms are computed from the
model and the general formulas, and whose checks integrate the model.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable

import mpmath as mp
import sympy as sp

from pendsym import pendulum, perturbation as pt, verify
from pendsym.result import Evidence, KernelArg, KernelSpec, Reading, Source, Spec
from . import truth as tr
from .general import E_c, E_s, MEMOIR
from .symbols import DEFS, alpha, dtheta, k, l0, t, theta

DELTA = sp.Symbol("delta", positive=True)   # bookkeeping scale of the amplitude
PRINTED = Callable[[], sp.Expr]

ALPHA = KernelArg("alpha", 1e-3, 3.0, unit="rad")
K = KernelArg("k", 0.1, 10.0, unit="1/s")
TIME = KernelArg("t", 0.0, 10.0, log=False, unit="s")
THETA = KernelArg("theta", -1.0, 1.0, log=False, unit="rad")
THETADOT = KernelArg("thetadot", -10.0, 10.0, log=False, unit="rad/s")
L0 = KernelArg("l_0", 1e-3, 100.0, unit="m")
RATE = KernelArg("a", 1e-8, 1e-1, unit="1/s")


@dataclass(frozen=True)
class Example:
    """One worked example: its model, its printed forms, and how to check it."""

    key: str                                  # "n21"
    name: str
    pages: dict                               # item → page
    law: str                                  # model name in truth.LAWS
    small: sp.Symbol                          # DELTA (amplitude) or a parameter such as a
    order: int                                # order of P in ``small``
    eps: PRINTED                              # printed ε
    phi: PRINTED                              # printed φ (of t, or of θ when phi_of_theta)
    printed: dict = field(default_factory=dict)   # quantity → printed() (eom, Es, Ec, theta, …)
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

    def id(self, q: str) -> str:
        return f"{MEMOIR}.{self.key_of.get(q, self.key)}.{q}"

    def src(self, q: str, para: str = "") -> Source:
        return Source(MEMOIR, para or f"n°{self.key_of.get(q, self.key)[1:]}", self.pages.get(q, self.pages["default"]))

    @property
    def amplitude_problem(self) -> bool:
        return self.small == DELTA


# ----------------------------------------------------------------- derivations
def eom(ex: Example, deps) -> sp.Expr:
    """P from the example's law by the variable-length equation of n°2, to lowest order."""
    law, restoring, _ = tr.LAWS[ex.law]
    if ex.law_from:
        law = deps[ex.law_from].derived
    law = law.subs(sp.Symbol("g", positive=True), k**2 * l0)
    P = pendulum.perturbing_term(law, theta, dtheta, t, k, l0, restoring)
    scale = {theta: DELTA * theta, dtheta: DELTA * dtheta} if ex.amplitude_problem else {}
    return sp.factor_terms(pendulum.lowest_order(P, ex.small, scale, ex.order))


def along_motion(P: sp.Expr) -> sp.Expr:
    """εφ(t): P along θ0 = −α cos kt."""
    return sp.simplify(pt.along(P, theta, dtheta, -alpha * sp.cos(k * t), t))


def eps_derived(P: sp.Expr, ex: Example) -> sp.Expr:
    """ε = εφ / φ_printed; it must not depend on t (else φ's shape is wrong)."""
    ratio = sp.simplify((along_motion(P) if not ex.phi_of_theta else P) / ex.phi())
    return ratio


def phi_derived(P: sp.Expr, ex: Example) -> sp.Expr:
    """φ = εφ / ε_printed (the memoir's normalization of ε is a convention)."""
    return sp.simplify((P if ex.phi_of_theta else along_motion(P)) / ex.eps())


def phi_t(deps, ex: Example) -> sp.Expr:
    phi = deps[ex.id("phi")].derived
    return pt.along(phi, theta, dtheta, -alpha * sp.cos(k * t), t) if ex.phi_of_theta else phi


def Es_derived(deps, ex):
    return pt.E_s(phi_t(deps, ex), t, k)


def Ec_derived(deps, ex):
    return pt.E_c(phi_t(deps, ex), t, k)


def motion(deps, ex, which: int):
    th0 = -alpha * sp.cos(k * t)
    th, dth = pt.first_order(th0, deps[ex.id("Es")].derived, deps[ex.id("Ec")].derived, ex.eps(), k, t)
    return sp.simplify([th, dth][which])


def general(deps, ex, gen_id: str) -> sp.Expr:
    """A general formula of n°9 with this example's ε and E_s, E_c at the phase it names."""
    form = deps[f"{MEMOIR}.n09.{gen_id}"].derived
    Es, Ec = deps[ex.id("Es")].derived, deps[ex.id("Ec")].derived
    form = form.replace(E_s, lambda x: Es.subs(t, x / k)).replace(E_c, lambda x: Ec.subs(t, x / k))
    return sp.simplify(form.subs(sp.Symbol("epsilon", real=True), ex.eps()))


# ----------------------------------------------------------------- checks
def _pvals(ex: Example) -> dict:
    return {s.name: v for s, v in ex.params}


def _model_syms(ex: Example) -> tuple:
    """The model parameters, the checked small parameter last when it is not α."""
    return tuple(s for s, _ in ex.params) + (() if ex.check_param == alpha else (ex.check_param,))


def _numeric(expr, ex: Example):
    """mpmath evaluator of expr in (α, k, t, model parameters…)."""
    return verify.lambdify_mp(expr.subs(DEFS), (alpha, k, t) + _model_syms(ex))


K_CHECK = "1.3"


def _swing(ex: Example, p, dps):
    """The truth swing for the small-parameter value p."""
    vals = dict(_pvals(ex))
    al = "0.3"
    if ex.check_param == alpha:
        al = mp.nstr(p, 40)
    else:
        vals[ex.check_param.name] = mp.nstr(p, 40)
    return tr.swing(ex.law, al, K_CHECK, dps, **vals), mp.mpf(al)


def _formula_at(ex: Example, expr, p, tv=None):
    vals = dict(_pvals(ex))
    al = p if ex.check_param == alpha else mp.mpf("0.3")
    if ex.check_param != alpha:
        vals[ex.check_param.name] = p
    f = _numeric(expr, ex)
    return f(al, mp.mpf(K_CHECK), tv if tv is not None else 0, *(mp.mpf(vals[s.name]) for s in _model_syms(ex)))


def expected_order(ex: Example, q: str) -> int:
    """Order of the residual of quantity q in the checked small parameter."""
    if ex.check_param != alpha:
        return 2                      # first order in a: residual O(a²)
    base = {"dT": 2, "dThalf": 2, "dthetam": 3, "theta": 3, "dtheta": 3, "dalpha": 3}[q]
    return base + ex.order - 1        # next order in the amplitude


def order_check_of(ex: Example, q: str) -> Callable[[object, str], Evidence]:
    def measured(p, dps):
        sw, al = _swing(ex, p, dps)
        kv = mp.mpf(K_CHECK)
        return {"dT": sw.T - mp.pi / kv, "dalpha": sw.amp - al, "dThalf": sw.t_low - mp.pi / (2 * kv),
                "dthetam": sw.v_low - kv * al}[q]

    def check(result, level):
        vals = verify.geometric(*ex.check_range, verify.LEVELS[level])
        printed = result.printed_value
        return verify.order_check(
            param=ex.check_param.name, values=vals, truth=measured,
            derived=lambda p: _formula_at(ex, result.derived, p),
            printed=(lambda p: _formula_at(ex, printed, p)) if printed is not None else None,
            expected=expected_order(ex, q), band=0.35, truth_desc=tr.MODEL_TEXT[ex.law],
            params=(("k", K_CHECK),) + tuple((s.name, v) for s, v in ex.params)
            + ((("alpha", "0.3"),) if ex.check_param != alpha else ()))
    return check


def zero_check_of(ex: Example, q: str):
    """Δα = 0 of a reversible model: the integrated amplitude returns to α."""
    def check(result, level):
        pairs = []
        for p in verify.geometric(*ex.check_range, 3):
            sw, al = _swing(ex, p, 30)
            pairs.append((f"{ex.check_param.name}={mp.nstr(p, 4)}", _formula_at(ex, result.derived, p), sw.amp - al))
        return verify.value_check(truth_desc=tr.MODEL_TEXT[ex.law] + "; amplitude at the turning point",
                                  pairs=pairs, tol=mp.mpf("1e-24"), kind="value",
                                  params=(("k", K_CHECK),) + tuple((s.name, v) for s, v in ex.params))
    return check


def motion_check_of(ex: Example, which: int):
    """θ(t) or θ'(t) against the integrated model at sample times, order fitted."""
    times = (mp.mpf("0.45"), mp.mpf("1.1"), mp.mpf("2.0"))   # in units of T = π/k

    def check(result, level):
        kv = mp.mpf(K_CHECK)

        def err(p, dps, expr):
            sw, _ = _swing(ex, p, dps)
            return max(abs(sw.traj(s * mp.pi / kv)[which] - _formula_at(ex, expr, p, s * mp.pi / kv)) for s in times)
        vals = verify.geometric(*ex.check_range, verify.LEVELS[level])
        printed = result.printed_value
        ev = verify.order_check(
            param=ex.check_param.name, values=vals, truth=lambda p, dps: err(p, dps, result.derived),
            derived=lambda p: 0, expected=expected_order(ex, "theta"), band=0.35,
            truth_desc=tr.MODEL_TEXT[ex.law] + "; largest |error| at t = 0.45T, 1.1T, 2T",
            params=(("k", K_CHECK),) + tuple((s.name, v) for s, v in ex.params))
        if printed is None:
            return ev
        with mp.workdps(30):
            pser = tuple((verify.rounded(p), verify.rounded(err(p, 30, printed))) for p in vals)
        pslope = verify.fit_order([a for a, _ in pser], [b for _, b in pser])
        return Evidence(**{**ev.__dict__, "printed_series": pser, "printed_order": verify.rounded(pslope),
                           "printed_agrees": bool(pslope >= expected_order(ex, "theta") - 0.35)})
    return check


def forcing_of(result, ex: Example, q: str) -> sp.Expr:
    """The forcing to test: P(θ, θ', t) itself, or εφ along θ0 with one factor derived."""
    if q == "eom":
        return result.derived
    eps_, phi_ = (ex.eps(), result.derived) if q == "phi" else (result.derived, ex.phi())
    phi_ = pt.along(phi_, theta, dtheta, -alpha * sp.cos(k * t), t) if ex.phi_of_theta else phi_
    return eps_ * phi_


def forcing_check_of(ex: Example, q: str):
    """P (or εφ along θ0) against the exact acceleration of the model, order fitted.

    The exact θ'' comes from :func:`pendsym.pendulum.exact_rhs` applied to the
    example's length law; θ''_exact + k²θ + P must vanish to one order beyond P.
    States are (θ, θ') = amplitude × (c1, c2 k) for P, and the unperturbed
    motion for εφ(t).
    """
    along = q != "eom"

    def check(result, level):
        kv = mp.mpf(K_CHECK)
        forcing = forcing_of(result, ex, q).subs(DEFS)
        f = verify.lambdify_mp(forcing, (theta, dtheta, alpha, k, t) + _model_syms(ex))

        def resid(p, dps):
            vals = dict(_pvals(ex))
            amp = p if ex.check_param == alpha else mp.mpf("0.3")
            if ex.check_param != alpha:
                vals[ex.check_param.name] = p
            rhs = tr.rhs(ex.law, kv, vals)
            pv = [mp.mpf(vals[s.name]) for s in _model_syms(ex)]
            worst = mp.mpf(0)
            for tv, (c1, c2) in zip((mp.mpf("0.3"), mp.mpf("0.8"), mp.mpf("1.7")),
                                    ((1, mp.mpf("0.7")), (mp.mpf("-0.6"), mp.mpf("1.1")), (mp.mpf("0.9"), -1))):
                if along:
                    th, dth = -amp * mp.cos(kv * tv), amp * kv * mp.sin(kv * tv)
                else:
                    th, dth = c1 * amp, c2 * amp * kv
                acc = rhs(tv, [th, dth])[1]
                worst = max(worst, abs(acc + kv**2 * th + f(th, dth, amp, kv, tv, *pv)))
            return worst
        vals = verify.geometric(*ex.check_range, verify.LEVELS[level])
        return verify.order_check(
            param=ex.check_param.name, values=vals, truth=resid, derived=lambda p: 0,
            expected=ex.order + (2 if ex.amplitude_problem else 1), band=0.35,
            truth_desc=tr.MODEL_TEXT[ex.law].replace(", mpmath odefun", "") + ": exact θ'' of the model",
            params=(("k", K_CHECK),) + tuple((s.name, v) for s, v in ex.params))
    return check


def quad_check_of(ex: Example, trig):
    """E_s or E_c against mpmath quad of its definition with the derived φ; the printed form too."""
    def check(result, level):
        kv, al = mp.mpf(K_CHECK), mp.mpf("0.3")
        f = _numeric(result.derived, ex)
        fp = _numeric(result.printed_value, ex) if result.printed is not None else None
        ph = _numeric(_phi_along_of(result), ex)
        pv = [mp.mpf(v) for _, v in ex.params] + ([] if ex.check_param == alpha else [mp.mpf(ex.check_range[1])])
        pairs, ppairs = [], []
        for s in (mp.mpf("0.4"), mp.mpf("1.3"), mp.mpf("2.6")):
            truth = mp.quad(lambda x: ph(al, kv, x, *pv) * trig(kv * x), [0, s])
            pairs.append((f"t={s}", f(al, kv, s, *pv), truth))
            if fp is not None:
                ppairs.append((f"t={s}", fp(al, kv, s, *pv), truth))
        tol = mp.mpf("1e-27")
        ev = verify.value_check(truth_desc="mpmath quad of the definition ∫_0^t φ " + verify.trig_name(trig) + " kτ dτ",
                                pairs=pairs, tol=tol,
                                params=(("k", K_CHECK), ("alpha", "0.3")) + tuple((s.name, v) for s, v in ex.params))
        if not ppairs:
            return ev
        pev = verify.value_check(truth_desc="", pairs=ppairs, tol=tol)
        return Evidence(**{**ev.__dict__, "printed_agrees": pev.passed,
                           "note": f"printed form: largest difference {pev.max_residual:.3g} from the quadrature"})
    return check


def _phi_along_of(result) -> sp.Expr:
    """φ(t) along θ0 for the E_s/E_c Result (from its dependency)."""
    (dep,) = [d for i, d in result.deps.items() if i.endswith(".phi")]
    phi = dep.derived
    if phi.has(theta) or phi.has(dtheta):
        phi = pt.along(phi, theta, dtheta, -alpha * sp.cos(k * t), t)
    return phi


# ----------------------------------------------------------------- the Specs
def kernel(ex: Example, doc: str, with_time: bool = False) -> KernelSpec:
    args = (ALPHA, K) + ((TIME,) if with_time else ()) + tuple(ex.extra_args)
    return KernelSpec(args=args, doc=doc)


def specs(ex: Example) -> tuple[Spec, ...]:
    pr, rd = ex.printed, ex.readings
    defs = tuple(DEFS.items()) + tuple(ex.defs)

    def S(q, title, lhs, derive, deps=(), check=None, kern=None, para=""):
        return Spec(ex.id(q), title, ex.src(q, para), lhs, derive, deps=deps, printed=pr.get(q),
                    readings=tuple(rd.get(q, ())), check=check, kernel=kern, defs=defs, note=ex.notes.get(q, ""))

    gen = lambda g: (f"{MEMOIR}.n09.{g}", ex.id("Es"), ex.id("Ec"))
    out = [
        S("eom", "Perturbing term P of θ'' + k²θ + P = 0", "P(\\theta, \\theta', t)",
          lambda d: eom(ex, d), deps=(ex.law_from,) if ex.law_from else (), check=forcing_check_of(ex, "eom")),
        S("eps", "ε (the memoir's normalization)", r"\varepsilon",
          lambda d: eps_derived(d[ex.id("eom")].derived, ex), deps=(ex.id("eom"),),
          check=forcing_check_of(ex, "eps")),
        S("phi", "φ", r"\varphi", lambda d: phi_derived(d[ex.id("eom")].derived, ex), deps=(ex.id("eom"),),
          check=forcing_check_of(ex, "phi")),
        S("Es", "E_s(t)", r"E_s", lambda d: Es_derived(d, ex), deps=(ex.id("phi"),),
          check=quad_check_of(ex, mp.sin), kern=kernel(ex, "E_s(t)", True)),
        S("Ec", "E_c(t)", r"E_c", lambda d: Ec_derived(d, ex), deps=(ex.id("phi"),),
          check=quad_check_of(ex, mp.cos), kern=kernel(ex, "E_c(t)", True)),
        S("theta", "θ(t) to first order", r"\theta(t)", lambda d: motion(d, ex, 0), deps=(ex.id("Es"), ex.id("Ec")),
          check=motion_check_of(ex, 0), kern=kernel(ex, "θ(t), first order", True)),
        S("dtheta", "θ'(t) to first order", r"\theta'(t)", lambda d: motion(d, ex, 1),
          deps=(ex.id("Es"), ex.id("Ec")), check=motion_check_of(ex, 1), kern=kernel(ex, "θ'(t), first order", True)),
        S("dT", "Change of the swing time", r"\Delta T", lambda d: general(d, ex, "dT"), deps=gen("dT"),
          check=order_check_of(ex, "dT"), kern=kernel(ex, "ΔT, first order")),
    ]
    dalpha_zero = ex.check_param == alpha
    out.append(S("dalpha", "Change of the amplitude", r"\Delta\alpha", lambda d: general(d, ex, "dalpha"),
                 deps=gen("dalpha"), check=(zero_check_of(ex, "dalpha") if dalpha_zero else order_check_of(ex, "dalpha")),
                 kern=None if dalpha_zero else kernel(ex, "Δα, first order")))
    if "dThalf" in pr:
        out.append(S("dThalf", "Change of the time to the lowest point", r"\Delta T_{1/2}",
                     lambda d: general(d, ex, "dThalf"), deps=gen("dThalf"), check=order_check_of(ex, "dThalf"),
                     kern=kernel(ex, "ΔT½, first order")))
        out.append(S("dthetam", "Change of the speed at the lowest point", r"\Delta\theta'_m",
                     lambda d: general(d, ex, "dthetam"), deps=gen("dthetam"), check=order_check_of(ex, "dthetam"),
                     kern=kernel(ex, "Δθ'_m, first order")))
    return tuple(out)
