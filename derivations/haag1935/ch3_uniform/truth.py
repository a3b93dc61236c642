"""Haag 1935, chapter III: the independent truth, the uniform blade solved numerically.

The blade λ = 13/10 with M = (λ/u)² is solved by shooting (:mod:`pendsym.blade`:
mpmath odefun, then mpmath quad of the definitions (79), (77), n°36–37) at
``DPS`` digits; nothing here reads a closed form of chapter III.  A check is a
:class:`pendsym.checks.Values` declaration: :class:`OnBlade` supplies its points
(the truth at each point of a grid of u, K and s) and its confirmation (the
truth at the first point recomputed from a shooting at the precision asked,
``CONFIRM_DPS`` by the engine).  The normal modes and the launches of n°50–54
are in :mod:`.truth_modes`.
"""
from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Callable, Mapping

import mpmath as mp
import sympy as sp

from pendsym import blade, checks, verify

from ..common import DPS, TOL
from ..symbols import Fn, Gam, Gn, k, n, x0, xl

LAMBDA_VALUE = sp.Rational(13, 10)
U_VALUES = {"quick": ("7/10", "43/10"), "full": ("7/10", "43/10", "13")}
K_VALUES = {"quick": ("0.83",), "full": ("0.83", "-0.4")}
BLADE = "uniform blade M = (λ/u)² solved by shooting (mpmath odefun) and mpmath quad of the definitions"
WHERE = "λ = 13/10; u = 7/10, 43/10 and, at full level, 13"

Environment = Mapping[str, object]
Quantity = Callable[[blade.BladeSolution, Environment], object]


@functools.lru_cache(maxsize=16)
def blade_solution(u_exact: str, dps: int = DPS) -> blade.BladeSolution:
    """The uniform blade λ = 13/10, M = (λ/u)², solved by shooting at dps digits."""
    u_value = sp.Rational(u_exact)
    return blade.solve(blade.Blade(LAMBDA_VALUE, (LAMBDA_VALUE / u_value) ** 2), dps)


def grid(level: str, along: bool = False, with_K: bool = True, extra: Mapping | None = None) -> list[dict]:
    """The environments of a check: u (and the exact "u_exact" that picks the blade), λ, K and k = K(1 − K)
    (K = 0 when ``with_K`` is false), s = 0.2λ and 0.65λ when ``along`` the blade (else s = 0), and ``extra``."""
    out = []
    for u_exact in U_VALUES[level]:
        for K_text in (K_VALUES[level] if with_K else ("0",)):
            K_value = sp.Float(K_text, 60)
            base = {"u_exact": u_exact, "u": str(sp.N(sp.Rational(u_exact), 60)), "lambda": str(sp.N(LAMBDA_VALUE, 60)),
                    "K": K_text, "k": str(sp.N(K_value * (1 - K_value), 60))}
            for fraction in (("0.2", "0.65") if along else ("0",)):
                env = dict(base, s=str(sp.N(sp.Rational(fraction) * LAMBDA_VALUE, 60)))
                out.append(dict(env, **(extra or {})))
    return out


def label(env: Environment) -> str:
    return ", ".join(f"{name}={env[name]}" for name in ("u_exact", "K", "s", "n") if name in env)


def as_mpf(value: sp.Rational) -> mp.mpf:
    """An exact rational as an mpf at the working precision."""
    return mp.mpf(value.p) / value.q


def formula_input(value) -> sp.Float:
    """A truth value handed to a formula (F_{n−1}, x_0 …): its decimal form at the working precision."""
    return sp.Float(str(value), 45)


@dataclass(frozen=True)
class OnBlade:
    """A quantity of the numerical blade at the points of a grid: the truth of a Values check.

    ``inputs(solution, env)`` adds to the environment what the formula takes from the blade
    (the lower F_n of a recurrence, the shot x_0 …); ``point`` builds each :class:`checks.Point`.
    """

    quantity: Quantity
    environments: Callable[[str], list]
    inputs: Callable[[blade.BladeSolution, Environment], Mapping] | None = None
    point: Callable[..., checks.Point] = checks.Point

    def points(self, level: str, dps: int) -> list[checks.Point]:
        out = []
        for env in self.environments(level):
            solution = blade_solution(env["u_exact"], dps)
            truth = self.quantity(solution, env)
            if self.inputs is not None:
                env = {**env, **self.inputs(solution, env)}
            out.append(self.point(label(env), env, truth))
        return out

    def confirm(self, dps: int) -> dict:
        """The truth at the first point of the grid (the same at both levels), shot at dps digits."""
        env = self.environments("full")[0]
        return {f"truth at {label(env)}": self.quantity(blade_solution(env["u_exact"], dps), env)}


def on_blade(description: str, quantity: Quantity, *, along: bool = False, with_K: bool = True,
             extra: Mapping | None = None, environments: Callable[[str], list] | None = None,
             inputs=None, point=checks.Point) -> checks.Values:
    """The Values check of a formula against ``quantity`` of the numerical blade."""
    if environments is None:
        environments = functools.partial(grid, along=along, with_K=with_K, extra=extra)
    truth = OnBlade(quantity, environments, inputs, point)
    return checks.Values(truth=f"{description}; the {BLADE} ({WHERE})", points=truth.points,
                         confirm=truth.confirm, tol=TOL, kind="quadrature", params=(("lambda", str(LAMBDA_VALUE)),))


# ================================================================ n°47: v, w, φ1, φ2 and their ends
def function_along(name: str) -> Quantity:
    """v, w, φ1 or φ2 of the shot blade at s."""
    return lambda solution, env: getattr(solution, name)(mp.mpf(env["s"]))


def end_value(name: str) -> Quantity:
    """v_0, v_λ, w_0, w_λ, β1 or β2 of the shot blade."""
    return lambda solution, env: getattr(solution, name)


def state_at(solution, env) -> tuple:
    """(v, v', w, w') of the shot blade at s."""
    return solution.state(mp.mpf(env["s"]))


# ================================================================ n°48: G_n, Γ_n
def first_integral_G(solution, env):
    """M x'² − x² for x = Kv + w, with the shot v, w."""
    v, dv, w, dw = state_at(solution, env)
    K_value, M_value = mp.mpf(env["K"]), (mp.mpf(env["lambda"]) / mp.mpf(env["u"])) ** 2
    x, x_prime = K_value * v + w, K_value * dv + dw
    return M_value * x_prime**2 - x**2


def Gamma_on_blade(solution, env, m: int):
    """Γ_m = G_m/(λ(u/λ)^{m−2}) (163) with G_m by quadrature of (79)."""
    K_value, lam_value, u_value = mp.mpf(env["K"]), mp.mpf(env["lambda"]), mp.mpf(env["u"])
    return solution.G(m, K_value) / (lam_value * (u_value / lam_value) ** (m - 2))


def Gamma_of(m: int) -> Quantity:
    return lambda solution, env: Gamma_on_blade(solution, env, m)


def with_index(indices: tuple[int, ...], keep: int | None = None):
    """The environments of a recurrence: the grid, each point with n in ``indices`` (the first ``keep``
    of them at quick level)."""
    def environments(level):
        out = [dict(env, n=m) for env in grid(level) for m in indices]
        return out[:keep] if level == "quick" and keep else out
    return environments


def n_times_G(solution, env):
    return env["n"] * solution.G(env["n"], mp.mpf(env["K"]))


def G_recurrence_inputs(solution, env) -> dict:
    """G_{n−2} by quadrature, and x_0, x_λ of the shot blade."""
    m, K_value = env["n"], mp.mpf(env["K"])
    return {Gn(n - 2): formula_input(solution.G(m - 2, K_value)),
            x0.name: formula_input(K_value * solution.v0 + solution.w0),
            xl.name: formula_input(K_value * solution.vl + solution.wl)}


def n_times_Gamma(solution, env):
    return env["n"] * Gamma_on_blade(solution, env, env["n"])


def Gamma_recurrence_inputs(solution, env) -> dict:
    """Γ_{n−2} by quadrature."""
    return {Gam(n - 2): formula_input(Gamma_on_blade(solution, env, env["n"] - 2))}


def Gamma_integral_environments(level: str) -> list[dict]:
    """The first two points of the grid, with n = 2, 3, 5."""
    return [dict(env, n=m) for env in grid(level)[:2] for m in (2, 3, 5)]


def Gamma_of_n(solution, env):
    return Gamma_on_blade(solution, env, env["n"])


def power_sum_points(level: str, dps: int) -> list[checks.Point]:
    """S_p − S_{p−1} + kS_{p−2} from the direct powers S_p = K^p + (1 − K)^p,
    relative to S_{p−1} − kS_{p−2}."""
    out = []
    for K_text in ("0.3", "-1.7", "2.9"):
        K_value = mp.mpf(K_text)
        k_value = K_value * (1 - K_value)
        S = lambda q: K_value**q + (1 - K_value) ** q
        for q in (2, 5, 9):
            right = S(q - 1) - k_value * S(q - 2)
            out.append(checks.Point(f"K={K_text}, p={q}", {"K": K_value, "p": q}, S(q) - right,
                                    max(abs(right), mp.mpf(1))))
    return out


def leading_coefficients_from_roots(derived: sp.Tuple) -> bool:
    """The leading coefficients of S_{2q}, S_{2q+1} (q = 1…6) in (−k), from the explicit roots
    K = (1 ± √(1 − 4k))/2 of t² − t + k = 0 expanded by SymPy, equal the derived ones."""
    root = sp.sqrt(1 - 4 * k)
    ok = True
    for q in range(1, 7):
        for j, m in ((0, 2 * q), (1, 2 * q + 1)):
            poly = sp.Poly(sp.expand(((1 + root) / 2) ** m + ((1 - root) / 2) ** m), k)
            ok &= poly.degree() == q and sp.simplify(poly.LC() / (-1) ** q - derived[2 * (q - 1) + j]) == 0
    return bool(ok)


LEADING_U = "43/10"


def Gamma_over_k_power(q: int, m: int):
    """Γ_{2q+1}(K)/k^q from the shot blade at u = 4.3, as a function of ε = 1/K."""
    def truth(epsilon, dps):
        K_value = 1 / epsilon
        k_value = K_value * (1 - K_value)
        env = {"K": K_value, "lambda": as_mpf(LAMBDA_VALUE), "u": as_mpf(sp.Rational(LEADING_U))}
        return Gamma_on_blade(blade_solution(LEADING_U, dps), env, m) / k_value**q
    return truth


def leading_coefficient_at(index: int):
    """The component ``index`` of (lc_k Γ_3, lc_k Γ_5) at u = 4.3 (it does not depend on 1/K)."""
    return lambda expr, _epsilon: verify.value_at(expr[index], {"u": str(sp.N(sp.Rational(LEADING_U), 50))})


def leading_order(q: int, m: int, index: int) -> checks.Order:
    """Γ_{2q+1}/k^q → its leading coefficient as 1/K → 0: the rest is O(1/k) = O(K^{−2})."""
    return checks.Order(param="1/K", values=lambda level: verify.geometric("1e-3", "1e-2", verify.LEVELS[level]),
                        truth=Gamma_over_k_power(q, m), at=leading_coefficient_at(index), expected=2, band=0.3,
                        truth_desc=f"Γ_{m}/k^{q} from G_{m} by quadrature on the {BLADE}, u = 4.3",
                        params=(("u", "4.3"), ("n", str(m))))


# ================================================================ n°49: F_n, F
def first_integral_F(solution, env):
    """M x'² − x² + 2Kx for x = Kφ1 + φ2, with φ1' = v'' = v/M, φ2' = w/M of the shot blade."""
    v, dv, w, dw = state_at(solution, env)
    K_value, M_value = mp.mpf(env["K"]), (mp.mpf(env["lambda"]) / mp.mpf(env["u"])) ** 2
    x = K_value * (1 + dv) + dw
    x_prime = (K_value * v + w) / M_value
    return M_value * x_prime**2 - x**2 + 2 * K_value * x


def F_of(which) -> Quantity:
    """F_0, F_m/λ, or F/λ = (4KF_3 − F_4)/λ (110) by quadrature of (79)."""
    def quantity(solution, env):
        K_value, lam_value = mp.mpf(env["K"]), mp.mpf(env["lambda"])
        if which == "F":
            return (4 * K_value * solution.F(3, K_value) - solution.F(4, K_value)) / lam_value
        if which == 0:
            return solution.F(0, K_value)
        return solution.F(which, K_value) / lam_value
    return quantity


def n_times_F(solution, env):
    return env["n"] * solution.F(env["n"], mp.mpf(env["K"]))


def F_recurrence_inputs(solution, env) -> dict:
    m, K_value = env["n"], mp.mpf(env["K"])
    return {Fn(n - 1): formula_input(solution.F(m - 1, K_value)), Fn(n - 2): formula_input(solution.F(m - 2, K_value))}


def four_F(solution, env):
    K_value = mp.mpf(env["K"])
    return 4 * (4 * K_value * solution.F(3, K_value) - solution.F(4, K_value))


def F1_F2_inputs(solution, env) -> dict:
    K_value = mp.mpf(env["K"])
    return {Fn(1): formula_input(solution.F(1, K_value)), Fn(2): formula_input(solution.F(2, K_value))}


# ================================================================ n°50–53: shape and fatigue
def foci_combination(solution, env):
    """v_λ² + β1 w_λ of the shot blade."""
    return solution.vl**2 + solution.beta1 * solution.wl


def omega_y(solution, env):
    """ω y of (77) at s, with Y, θ of the environment."""
    return mp.mpf(env["u"]) / mp.mpf(env["lambda"]) * solution.y(mp.mpf(env["s"]), env["Y"], env["theta"])


STATIC = {"a": "0.9", "b": "0.35"}


def theta_static(solution, env):
    """θ/Y of the static deviation (67) on the shot blade: (b − v_λ)/(a + w_λ)."""
    return (mp.mpf(env["b"]) - solution.vl) / (mp.mpf(env["a"]) + solution.wl)


THETA_OVER_Y = {"c": lambda solution, env: mp.mpf(env["theta"]),
                "principal": lambda solution, env: 1 / mp.mpf(env["K"]),
                "static": theta_static}


def shape_of_c(omega_s, c) -> mp.mpf:
    """ωs − sh ωs + c(ch ωs − 1): the shape (171) that c determines (c enters only there)."""
    return omega_s - mp.sinh(omega_s) + mp.mpf(c) * (mp.cosh(omega_s) - 1)


def shape_point(label_text, env, truth) -> checks.Point:
    """A point where c is measured through the shape (171), against ω y of (77) with Y = 1."""
    omega_s = mp.mpf(env["u"]) / mp.mpf(env["lambda"]) * mp.mpf(env["s"])
    return checks.Point(label_text, env, truth, through=functools.partial(shape_of_c, omega_s))


def c_on_blade(which: str) -> checks.Values:
    """c of (172)–(174) through (171), against ω y of (77) with Y = 1 and θ of the case."""
    def quantity(solution, env):
        omega = mp.mpf(env["u"]) / mp.mpf(env["lambda"])
        return omega * solution.y(mp.mpf(env["s"]), 1, THETA_OVER_Y[which](solution, env))
    return on_blade("ω y of (77) with Y = 1, against (171) with this c,", quantity, along=True,
                    extra={"Y": "1", "theta": "0.37", **STATIC}, point=shape_point)


FATIGUE = {"E": "2.1", "e": "0.3", "Y": "0.8", "theta": "0.37"}


def bending_stress_of(kind: str) -> Quantity:
    """T' of (78) = (mg e/2I)(Yv + θw) with the shot v, w (I = e³h/12, mg by (156)); Γ = T'/(√(3ET)Y)
    for kind "Gamma"; Y = Kθ for kind "principal"."""
    def quantity(solution, env):
        v, _, w, _ = state_at(solution, env)
        E_value, e_value = mp.mpf(env["E"]), mp.mpf(env["e"])
        u_value, lam_value = mp.mpf(env["u"]), mp.mpf(env["lambda"])
        Y_value = mp.mpf(env["Y"]) if kind != "principal" else mp.mpf(env["K"]) * mp.mpf(env["theta"])
        stress = E_value * e_value * u_value**2 / (2 * lam_value**2) * (Y_value * v + mp.mpf(env["theta"]) * w)
        if kind == "Gamma":
            return stress * 2 * lam_value / (E_value * e_value * u_value * Y_value)
        return stress
    return quantity


def stress_bracket_at(where: int, kind: str) -> Quantity:
    """Γ_0, Γ_λ (177): ω(v + θw/Y) with θ/Y = 0.37/0.8; C_0, C_λ (179): ω(Kv + w); at the end ``where``."""
    def quantity(solution, env):
        u_value, lam_value = mp.mpf(env["u"]), mp.mpf(env["lambda"])
        v, w = (solution.v0, solution.w0) if where == 0 else (solution.vl, solution.wl)
        if kind == "Gamma":
            return u_value / lam_value * (v + mp.mpf("0.37") / mp.mpf("0.8") * w)
        return u_value / lam_value * (mp.mpf(env["K"]) * v + w)
    return quantity


def static_ends(sign: int) -> Quantity:
    """Γ_0 ∓ Γ_λ: ω(v + θw/Y) at both ends, θ/Y of the static deviation (67)."""
    def quantity(solution, env):
        omega = mp.mpf(env["u"]) / mp.mpf(env["lambda"])
        ratio = theta_static(solution, env)
        Gamma_0 = omega * (solution.v0 + ratio * solution.w0)
        Gamma_lambda = omega * (solution.vl + ratio * solution.wl)
        return Gamma_0 - Gamma_lambda if sign < 0 else Gamma_0 + Gamma_lambda
    return quantity


# ================================================================ n°56–57: I_λ, J
def inertia(solution, env):
    """(1/λ)∫ y² ds, y of (77) with Y = K, θ = 1, by quadrature."""
    return solution.inertia(mp.mpf(env["K"]))


def inertia_auxiliary(solution, env):
    """∫ (Ks − x_0)(Kv + w)/M ds by quadrature."""
    K_value = mp.mpf(env["K"])
    x_at_0 = K_value * solution.v0 + solution.w0
    with mp.workdps(solution.wdps):
        return solution.integrate(lambda x: (K_value * x - x_at_0) * (K_value * solution.v(x) + solution.w(x))
                                  / solution.M_at(x))


def half_integral_of_x_prime_squared(solution, env):
    """½∫_0^s (Kφ1 + φ2)² by Gauss–Legendre quadrature."""
    K_value, s_value = mp.mpf(env["K"]), mp.mpf(env["s"])
    with mp.workdps(solution.wdps):
        integrand = lambda x: (lambda state: (K_value * (1 + state[1]) + state[3]) ** 2)(solution.state(x))
        return mp.quad(integrand, [0, s_value / 2, s_value], method="gauss-legendre") / 2


def weight_integral(solution, env):
    """J = (1/2λ)∫(λ − s)(Kφ1 + φ2)² ds by quadrature."""
    return solution.weight_integral(mp.mpf(env["K"]))
