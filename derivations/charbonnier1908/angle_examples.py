"""Charbonnier 1908 §IV, the worked examples n°21 (second term of the period),
n°22 (thread winding on a curve) and n°23 (the "cycloidal" pendulum).

Pages (pp. 223–229) are placed from the OCR's page marks ( 223 ), ( 225 ), ( 227 ).
"""
from __future__ import annotations

import mpmath as mp
import sympy as sp

from pendsym import verify, wallis
from pendsym.result import KernelArg, KernelSpec, Reading, Spec
from . import chain, truth
from .chain import DELTA, Example
from .common import BETA, K_CHECK, L0, THETA, Geometric, printed, rid, src
from .symbols import DEF_ITEMS, T, alpha, beta, cos_kt, dtheta, eps, k, kt, l0, m, omega, q, sin_kt, theta, theta_m, y

R = sp.Rational

# ----------------------------------------------------------------- n°21: the second term of the sine
N21 = Example(
    key="n21", name="Second term of the period", law="sine", small=DELTA, order=3,
    pages={"default": 224, "eom": 223, "Es": 224, "dT": 225, "dThalf": 225, "dthetam": 225},
    eps=-k**2 / 6, phi=theta**3, phi_of_theta=True,
    printed={
        "eom": -R(1, 6) * k**2 * theta**3,
        "Es": -alpha**3 / (4 * k) * (1 - cos_kt**4),
        "Ec": -alpha**3 / (4 * k) * (cos_kt * sin_kt * (cos_kt**2 + R(3, 2)) + R(3, 2) * kt),
        "theta": -alpha * cos_kt - R(1, 24) * alpha**3 / 2 * sin_kt * (3 * kt + sin_kt * cos_kt),
        "dtheta": k * alpha * sin_kt - R(1, 24) * k * alpha**3 * (R(3, 2) * kt * cos_kt + sin_kt * (2 + 3 * cos_kt**2)),
        "dT": alpha**2 * T / 16,
        "dalpha": sp.S.Zero,
        "dThalf": alpha**2 * T / 32,
        "dthetam": -alpha**2 * theta_m / 24,
    },
    readings={
        "eom": (Reading("−(1/1.2.3) k²θ³", "P = −k²θ³/6"),),
        "dtheta": (Reading("sin kt (2 + 3 cos² kt)", "as printed; the derived bracket is sin kt (1 + (3/2)cos² kt). "
                           "The memoir's own use at kt = π (−3π/2) and its Δθ'_m = −α²θ'_m/24 agree with the "
                           "derived form, so the printed bracket is a slip of the memoir or of the OCR (a lost "
                           "factor 1/2)", certain=False),),
        "dThalf": (Reading("ΔT_1 = α²T/32", "ΔT_½ (the subscript ½ read as 1)"),),
    },
    notes={"dthetam": "θ'_m = kα is the unperturbed speed at the lowest point."},
)


def J3_derived(_deps) -> sp.Expr:
    """J_3(y) = ∫_0^y cos⁴ from the recurrence of n°20 (n°21 3°)."""
    return wallis.J(3, y)


def J3_printed() -> sp.Expr:
    return sp.cos(y) * sp.sin(y) * (sp.cos(y) ** 2 + R(3, 2)) / 4 + R(3, 8) * y


def J3_check(result, level):
    f = verify.lambdify_mp(result.derived, (y,))
    pairs = [(f"y={v}", f(mp.mpf(v)), mp.quad(lambda u: mp.cos(u) ** 4, [0, mp.mpf(v)])) for v in ("0.5", "2", "5.5")]
    return verify.value_check(truth_desc="mpmath quad of ∫_0^y cos⁴ y dy", pairs=pairs, tol=mp.mpf("1e-28"))


def dT_from_monomial(deps) -> sp.Expr:
    """n°21 6°: the monomial formula of n°20 with m = 3, ε = −k²/6."""
    return sp.simplify(deps[rid(20, "dT")].derived.subs({m: 3, eps: -k**2 / 6}))


# ----------------------------------------------------------------- n°22: the thread winding on a curve
A1 = sp.Symbol("A_1", real=True)


def winding_length(_deps) -> sp.Expr:
    """l(θ) of the thread winding on ρ = βl0ω²(1 + A1ω + …), to second order in θ (n°22 1°).

    The tangent makes with the radius vector the angle I, tan I = ρ/(dρ/dω),
    the thread's direction is θ = I + ω, and l = l0 − ρ (chord for arc).
    """
    rho = beta * l0 * omega**2 * (1 + A1 * omega)
    I = sp.atan(rho / sp.diff(rho, omega))
    theta_of_omega = sp.series(I + omega, omega, 0, 3).removeO()     # θ(ω) to second order
    w = sp.Symbol("w")
    inverse = sp.solve(sp.Eq(theta, theta_of_omega.subs(omega, w)), w)
    omega_small = [r for r in inverse if sp.limit(r, theta, 0) == 0][0]
    length = (l0 - rho).subs(omega, omega_small)
    return sp.expand(sp.series(length, theta, 0, 3).removeO())


def winding_length_check(result, level):
    """Exact geometry: contact angle from θ = ω + atan(ρ/ρ'), wound length = arc length."""
    bv, a1v = mp.mpf("0.7"), mp.mpf("0.3")
    f = verify.lambdify_mp(result.derived, (theta, beta, l0, A1))

    def l_exact(th, dps):
        with mp.workdps(dps):
            rho = lambda w: bv * w**2 * (1 + a1v * w)
            drho = lambda w: bv * (2 * w + 3 * a1v * w**2)
            w = mp.findroot(lambda w: w + mp.atan(rho(w) / drho(w)) - th, 2 * th / 3)
            return 1 - mp.quad(lambda u: mp.sqrt(rho(u) ** 2 + drho(u) ** 2), [0, w])
    return verify.order_check(param="theta", values=Geometric("0.005", "0.1")(level), truth=l_exact,
                              derived=lambda th: f(th, bv, 1, a1v), expected=3, band=0.3,
                              params=(("beta", "0.7"), ("A_1", "0.3"), ("l_0", "1")),
                              truth_desc="exact wound arc length on ρ = βl0ω²(1 + A1ω), contact from "
                                         "θ = ω + atan(ρ/ρ') (mpmath findroot, quad)")


N22 = Example(
    key="n22", name="Thread winding on a curve", law="winding", small=DELTA, order=3,
    pages={"default": 227, "eom": 226, "dT": 228},
    eps=R(4, 9) * beta * k**2 * alpha**3, phi=cos_kt * (4 * sin_kt**2 - cos_kt**2),
    printed={
        "eom": R(4, 9) * beta * theta * (k**2 * theta**2 - 4 * dtheta**2),
        "Es": 1 / k * (2 - R(5, 4) * sin_kt**2) * sin_kt**2,
        "Ec": 1 / k * (R(1, 8) * kt + cos_kt * sin_kt * (R(1, 8) - R(5, 4) * cos_kt**2)),
        "dT": beta * alpha**2 * T / 18,
        "dalpha": sp.S.Zero,
    },
    readings={
        "Es": (Reading("E_s = (1/k)(2 − (5/4) sin² kt) sin² kt",
                       "as printed. The integrand cos kt (4 − 5cos² kt) sin kt integrates to "
                       "((5/4) sin² kt − 1/2) sin² kt/k; both vanish at kt = π and agree at kt = π/2, so "
                       "the conclusions of n°22 stand. A misreading seems unlikely (two numbers differ).",
                       certain=False),),
        "dT": (Reading("ΔT = (1/2.3.3) βα²T", "βα²T/18"),),
    },
    params=((beta, "0.7"),), extra_args=(BETA,), law_from=rid(22, "l"),
)

# ----------------------------------------------------------------- n°23: the "cycloidal" pendulum
N23 = Example(
    key="n23", name="Pendulum on a curve l = l0(1 + qθ²)", law="curve_q", small=DELTA, order=3,
    pages={"default": 228},
    eps=-q * k**2 * alpha**3, phi=cos_kt * (4 * sin_kt**2 - cos_kt**2),
    printed={"dT": -q / 8 * alpha**2 * T},
    readings={"dT": (Reading("ΔT = −(g/8)α²T", "−(q/8)α²T: the OCR reads q as g"),)},
    params=((q, "0.4"),), extra_args=(KernelArg("q", -10.0, 10.0, log=False),),
    notes={"eps": "n°23 gives no ε; ε = −qk²α³ is n°22's with −4β/9 replaced by q, as the memoir says."},
)


def isochronous_q(deps) -> sp.Expr:
    """q that cancels the α² term: ΔT(n°21) + ΔT(n°23, linear model) = 0 (n°23)."""
    total = deps[rid(21, "dT")].derived + deps[rid(23, "dT")].derived
    (solution,) = sp.solve(sp.Eq(total, 0), q)
    return solution


def isochronous_check(result, level):
    """With q = 1/2 and the full sin θ, the swing time differs from π/k by O(α⁴) only."""
    kv = mp.mpf(K_CHECK)
    qv = mp.nstr(mp.mpf(sp.N(result.derived, 40)), 40)

    def relative_change(p, dps):
        return (truth.swing("cycloidal_sine", mp.nstr(p, 40), K_CHECK, dps, q=qv).T - mp.pi / kv) / (mp.pi / kv)
    return verify.order_check(
        param="alpha", values=Geometric("0.02", "0.3")(level), derived=lambda p: 0, expected=4, band=0.3,
        truth=relative_change, truth_desc=truth.MODEL_TEXT["cycloidal_sine"] + "; (T − π/k)/(π/k)",
        params=(("k", K_CHECK), ("q", qv)), note="order 4, not 2: the α² term is cancelled")


# ----------------------------------------------------------------- the Result table
def specs() -> tuple[Spec, ...]:
    return (
        chain.specs(N21)
        + (Spec(rid(21, "J3"), "J_3 = ∫_0^y cos⁴ y dy by the recurrence", src("n°21 3°", 224), "J_3(y)",
                J3_derived, printed=J3_printed, check=J3_check,
                kernel=KernelSpec((KernelArg("y", 0.0, 20.0, log=False),), "J_3(y)")),
           Spec(rid(21, "dT_from_monomial"), "n°20's monomial ΔT with m = 3, ε = −k²/6", src("n°21 6°", 225),
                r"\Delta T", dT_from_monomial, deps=(rid(20, "dT"),), printed=printed(alpha**2 * T / 16),
                check=chain.order_check_of(N21, "dT"), defs=DEF_ITEMS))
        + (Spec(rid(22, "l"), "Length of the free thread, l(θ)", src("n°22 1°", 226), "l",
                winding_length, printed=printed(l0 * (1 - R(4, 9) * beta * theta**2)),
                check=winding_length_check,
                kernel=KernelSpec((THETA, BETA, L0), "l(θ) of the winding thread"),
                note="Independent of A1 to this order, as the memoir's formula implies."),)
        + chain.specs(N22)
        + chain.specs(N23)
        + (Spec(rid(23, "q"), "q making the swings isochronous to O(α⁴)", src("n°23", 229), "q",
                isochronous_q, deps=(rid(21, "dT"), rid(23, "dT")), printed=printed(R(1, 2)),
                readings=(Reading("g = 1/2", "q = 1/2"),), check=isochronous_check),)
    )
