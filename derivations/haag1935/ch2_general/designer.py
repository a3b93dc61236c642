"""Haag 1935, chapter II specialised to the uniform short blade: the designer's coefficients (issue #12's
emitters).

Chapter II's general formulas, (111)–(112) for the isochronism error, (133)–(134) for the clamping errors,
(135)–(136) for the blade's inertia and weight, take the uniform blade's forms of chapter III (F_2 (169),
F (170), I_λ (182), J (183)) and, for the short blade (λ ≪ a, K → 1, chapter VI, n°79–81), become closed
forms in u = λ/√M alone times a power of λ/a: (244), (249), (251), (253).  The coefficients below are those
Results' derived forms divided by their scale (nothing typed in):

* c_Q = (a/λ)(Q'/Q − 1), from (244): ΔT/T = (θ0²/16)(1 + (λ/a)c_Q) (the isochronism coefficient);
* c_ii, c_ij, c_jj, from (249): ΔT/T = (λ/a)(c_ii i² + c_ij ij + c_jj j²) (the clamping-error coefficients);
* c_I = (m/m')(a/λ)² ΔT/T, from (251) (the blade's inertia);
* c_J = (m/m')(a/λ) ΔT/T, from (253) (the blade's weight);
* c_D, from (149) with p + q = 1 (Le Rolland's law of n°23: the energy lost per period in proportion to the
  blade's largest energy of deformation, Δθ0 ∝ θ0): Δθ0 = −(π/2)i_{p,q+1}(a_pq + b_pq + a'_pq + b'_pq)n^qθ0
  (λ/a)c_D (the damping per period); the memoir does not specialise (149) to the short blade, so the step is
  made here as chapter VI makes (251), (253): g of (140), G_n of (163), Γ_2 of (166) at K = 1 (k = K(1 − K) of
  (165) vanishes), Q of (221) at its leading order in λ/a (:func:`damping_coefficient`).

The check of each coefficient is its own: the exact modes of the pendulum a = λ/ε on the uniform blade
u = 2 (:mod:`..ch6_short_blade.truth`: the eigenproblem of the directly solved blade, the blade's integrals
by quadrature on the shot blade) give chapter II's quantity, scaled as the coefficient; its residual
against the coefficient falls as λ/a (fitted order 1).
"""
from __future__ import annotations

import mpmath as mp
import sympy as sp

from pendsym import checks, verify

from ..common import rid
from ..symbols import u

ISOCHRONISM, CLAMPING, INERTIA, WEIGHT = rid(244, "dT"), rid(249, "dT"), rid(251, "dT"), rid(253, "dT")
DAMPING = rid(149, "amplitude")
DAMPING_DEPS = (DAMPING, rid(140, "g"), rid(163, "Gamma"), rid(166, "Gamma2"), rid(216, "K"), rid(221, "Q"))
BLADE = "uniform"        # the uniform blade u = 2 of chapter VI's truth


def _named(expr: sp.Expr) -> dict[str, sp.Symbol]:
    return {s.name: s for s in expr.free_symbols}


def _of_u(expr: sp.Expr, what: str) -> sp.Expr:
    """expr, which must be a function of u alone."""
    if expr.free_symbols - {u}:
        raise ValueError(f"{what} is not a function of u alone: {expr.free_symbols}")
    return expr


def isochronism_coefficient(deps) -> sp.Expr:
    """c_Q = (a/λ)(16(ΔT/T)/θ0² − 1) of (244) = (a/λ)(Q'/Q − 1) of (111), (112) for the short uniform blade."""
    dT = deps[ISOCHRONISM].derived
    n = _named(dT)
    c = sp.expand(n["a"] / n["lambda"] * (16 * dT / n["theta_0"] ** 2 - 1))
    return _of_u(c, "c_Q")


def clamping_coefficient(deps, monomial: str) -> sp.Expr:
    """The coefficient of i², ij or j² (monomial "ii", "ij", "jj") in (a/λ)ΔT/T of (249), (134) for the short
    uniform blade."""
    dT = deps[CLAMPING].derived
    n = _named(dT)
    i, j = n["i"], n["j"]
    poly = sp.Poly(sp.expand(n["a"] / n["lambda"] * dT), i, j)
    if poly.total_degree() != 2 or any(sum(m) != 2 for m in poly.monoms()):
        raise ValueError("(249) is not a quadratic form in i, j")
    powers = {"ii": (2, 0), "ij": (1, 1), "jj": (0, 2)}[monomial]
    return _of_u(sp.expand(poly.coeff_monomial(powers)), f"c_{monomial}")


def inertia_coefficient(deps) -> sp.Expr:
    """c_I = (m/m')(a/λ)²ΔT/T of (251), (135) for the short uniform blade."""
    dT = deps[INERTIA].derived
    n = _named(dT)
    return _of_u(sp.expand(n["m"] / n["m'"] * (n["a"] / n["lambda"]) ** 2 * dT), "c_I")


def weight_coefficient(deps) -> sp.Expr:
    """c_J = (m/m')(a/λ)ΔT/T of (253), (136) for the short uniform blade."""
    dT = deps[WEIGHT].derived
    n = _named(dT)
    return _of_u(sp.expand(n["m"] / n["m'"] * n["a"] / n["lambda"] * dT), "c_J")


def damping_coefficient(deps) -> sp.Expr:
    """c_D = −(2/π)(a/λ)Δθ0/(i_{p,q+1}βn^qθ0), β = a_pq + b_pq + a'_pq + b'_pq, of (149) at p + q = 1 for the short
    uniform blade: g_1(β) = βG_2 (140), G_2 = λΓ_2 (163), Γ_2 (166) at K = 1 (k = K(1 − K) (165), K of (216) at its
    leading order), Q of (221) at its leading order in λ/a (a); the leading term of the product taken as in (251):
    G_2 (exactly O(λ)) at the leading K, times the leading rest."""
    from ..ch6_short_blade.expansion import leading
    from ..symbols import Gn, K, Q, R, k, lam
    dth = deps[DAMPING].derived
    n = _named(dth)
    p, q, theta0 = n["p"], n["q"], n["theta_0"]
    dth = dth.subs(q, 1 - p)
    g_named = _named(deps[rid(140, "g")].derived)
    g_1 = deps[rid(140, "g")].derived.subs({g_named["q"]: 1, g_named["x"]: 1})         # g_1(1) = G(2)
    gs = [e for e in dth.atoms(sp.Function) if e.func.__name__ == "g"]
    if len(gs) != 1 or gs[0].args != (1, 1) or g_1 != Gn(2):
        raise ValueError(f"(149) at p + q = 1 does not hold g_1(1) = G_2: {gs}, {g_1}")
    Gamma = sp.Symbol("Gamma_2")
    n_sym = _named(deps[rid(163, "Gamma")].derived)["n"]
    G_2 = sp.solve(sp.Eq(deps[rid(163, "Gamma")].derived.subs(n_sym, 2), Gamma), Gn(2))[0]      # λΓ_2
    K_short = leading(deps[rid(216, "K")].derived.subs(R, 0))
    Gamma_2 = deps[rid(166, "Gamma2")].derived.subs(k, K * (1 - K)).subs(K, K_short)
    rest = sp.cancel(dth / gs[0])
    if rest.has(gs[0]):
        raise ValueError("(149) is not proportional to g")
    rest = leading(rest.subs(Q, deps[rid(221, "Q")].derived))
    short = rest * G_2.subs(Gamma, Gamma_2)
    beta = n["a_pq"] + n["b_pq"] + n["a'_pq"] + n["b'_pq"]
    i_pq = [e for e in dth.atoms(sp.Function) if e.func.__name__ == "i"]
    if len(set(i_pq)) != 1:
        raise ValueError(f"(149) at p + q = 1 holds several i_mn: {i_pq}")
    a = _named(rest)["a"]
    scale = -sp.pi / 2 * i_pq[0] * beta * n["n"] ** (1 - p) * theta0 * lam / a
    return _of_u(sp.expand(sp.cancel(short / scale)), "c_D")


# ---------------------------------------------------------------- the checks
def _u_value():
    from ..ch6_short_blade.truth import UNIFORM_U
    value = UNIFORM_U[BLADE]
    return mp.mpf(value.p) / value.q


def coefficient_order(scaled, what: str, inputs) -> checks.Order:
    """The fitted order in ε = λ/a of scaled(env) − c(u) at the exact modes of the pendulum a = λ/ε, R = 0.08 m,
    on the uniform blade u = 2: the coefficient is the limit of the scaled quantity, so the residual is O(λ/a)."""
    from ..ch6_short_blade.truth import EPSILONS, FIXED, FAMILY_TEXT, MODES, state

    def environment(epsilon, dps):
        env = state(BLADE, FIXED, epsilon, dps)
        return {**env, **inputs(env, BLADE, dps)}

    def truth(epsilon, dps):
        with mp.workdps(dps + 10):
            return scaled(environment(epsilon, dps))

    def at(expr, epsilon):
        return sp.N(expr.subs(u, sp.Float(mp.nstr(_u_value(), 40), 40)), checks.DPS + 10)

    return checks.Order(param="lambda/a", values=EPSILONS[FIXED], truth=truth, at=at, expected=1, band=0.3,
                        truth_desc=f"{what}; {MODES}; blade {BLADE} (u = 2), {FAMILY_TEXT[FIXED]}",
                        params=(("blade", BLADE), ("family", FAMILY_TEXT[FIXED])))


def isochronism_check() -> checks.Order:
    from ..ch6_short_blade.truth_perturbations import EXACT_112, exact_ratio, isochronism_inputs

    def scaled(env):
        return env["a"] / env["lambda"] * (exact_ratio(env) - 1)
    return coefficient_order(scaled, "(a/λ)(Q'/Q − 1) with " + EXACT_112, isochronism_inputs)


def inertia_check() -> checks.Order:
    from ..ch6_short_blade.truth_errors import exact_inertia, mass_inputs

    def scaled(env):
        return (env["a"] / env["lambda"]) ** 2 * exact_inertia(env)
    return coefficient_order(scaled, "(a/λ)²(m/m')ΔT/T, (135) ΔT/T = −I_λ/(2mz'(z − z')), I_λ = m'(1/λ)∫y² ds by "
                             "quadrature at the mode's K", mass_inputs)


def weight_check() -> checks.Order:
    from ..ch6_short_blade.truth_errors import exact_weight, mass_inputs

    def scaled(env):
        return env["a"] / env["lambda"] * exact_weight(env)
    return coefficient_order(scaled, "(a/λ)(m/m')ΔT/T, (136) ΔT/T = −Jm'/(Qm), Q = K(z − z'), J = (1/2λ)∫(λ − s)"
                             "(Kφ1 + φ2)² ds by quadrature at the mode's K", mass_inputs)


def damping_inputs(env, name, dps):
    """G_2 = ∫(Kv + w)²/M ds (79) by quadrature on the shot blade at the mode's K."""
    from ..ch6_short_blade.truth import shot
    with mp.workdps(dps + 10):
        return {"G_2": shot(name, dps).G(2, env["K"])}


def damping_check() -> checks.Order:
    """(a/λ)g_1(1)/Q of (149) at p + q = 1, g_1(1) = G_2 (140), at the exact modes: −(2/π)(a/λ)Δθ0/(i βn^qθ0)."""
    def scaled(env):
        return env["a"] / env["lambda"] * env["G_2"] / (env["K"] * (env["z"] - env["z'"]))
    return coefficient_order(scaled, "(a/λ)G_2/Q, (149) at p + q = 1 with g_1(1) = G_2 (140), G_2 (79) by quadrature "
                             "on the shot blade at the mode's K, Q = K(z − z') (45)", damping_inputs)


# the clamping errors (i, j) at which the quadratic form (a/λ)ΔT/T is read: i' follows from j of (117)
POLARISATION = {"ii": ((1, 0),), "jj": ((0, 1),), "ij": ((1, 1), (1, 0), (0, 1))}


def clamping_at(env, name: str, dps: int, i, j):
    """(a/λ)ΔT/T = (a/λ)Q1/Q (133)–(134) at the exact modes for the clamping errors i, j, with i' from (117)
    (j = −[(a − v_λ)i + ai']/(a − a1), a1 = −w_λ (41)) and h (127), h' (132), F_2 (79) by quadrature."""
    from ..ch6_short_blade.truth import shot
    from ..ch6_short_blade.truth_errors import exact_dT
    i, j = mp.mpf(i), mp.mpf(j)
    a = env["a"]
    ip = -(j * (a + env["w_lambda"]) + (a - env["v_lambda"]) * i) / a
    sol, K = shot(name, dps), env["K"]

    def moments(s):
        v, dv, w, dw = sol.state(s)
        return K * (1 + dv) + dw, -i * (1 + dv) + j * dw
    h = sol.integrate(lambda s: (lambda p: p[0] * p[1])(moments(s)))
    hp = sol.integrate(lambda s: (lambda p: 24 * K * p[1] ** 2 * p[0] - 24 * i * p[1] * p[0] ** 2
                                  - 12 * p[1] ** 2 * p[0] ** 2)(moments(s)))
    return a / env["lambda"] * exact_dT({**env, "i": i, "i'": ip, "j": j, "h": h, "h'": hp,
                                         "F_2": sol.F(2, K)})


def clamping_check(monomial: str) -> checks.Order:
    points = POLARISATION[monomial]
    signs = (1,) + (-1,) * (len(points) - 1)
    reading = " − ".join(f"P{p}" for p in points)

    def inputs(env, name, dps):
        with mp.workdps(dps + 10):
            return {"scaled": sum(sign * clamping_at(env, name, dps, *p) for sign, p in zip(signs, points))}
    return coefficient_order(lambda env: env["scaled"],
                             f"{reading}, P(i, j) = (a/λ)Q1/Q (134), Q1 of (133) at the exact modes with i' from j "
                             "of (117), h (127), h' (132), F_2 (79) by quadrature on the shot blade at the mode's K",
                             inputs)


# ---------------------------------------------------------------- the gravity pendulum (chapters VII–VIII)
GRAVITY_WEIGHT, INVERTED_WEIGHT = rid(293, "weight"), rid(320, "weight")


def gravity_weight_coefficient(deps, inverted: bool = False) -> sp.Expr:
    """c = ε(m/m')ΔT/T of (293) (direct) or (320) (inverted): (136) for the gravity pendulum near its critical
    distance, a = a1 ± ελ, ΔT/T = (m'/(mε))c."""
    dT = deps[INVERTED_WEIGHT if inverted else GRAVITY_WEIGHT].derived
    n = _named(dT)
    return _of_u(sp.simplify(n["varepsilon"] * n["m"] / n["m'"] * dT), "c of (293)/(320)")


def gravity_weight_check(inverted: bool = False) -> checks.Order:
    """ε(ΔT/T)/(m'/m) of the exact blade with mass (pendsym.massive_blade) at a = a1 ± ελ, u = 2 (direct) or u = 1
    (inverted), against c: residual O(ε) (chapter VII's truth, :func:`..ch7_mass.truth.mass_order`)."""
    from ..ch7_mass import truth as mass
    key, sign = ("u=1", -1) if inverted else ("u=2", 1)
    ratio = mp.mpf(mass.MASS_RATIO.p) / mass.MASS_RATIO.q

    def truth(p, dps):
        with mp.workdps(dps + 10):
            return mass.period_change(key, sign, mp.nstr(mp.mpf(p), 20), "weight", dps) * mp.mpf(p) / ratio

    def at(expr, p):
        return verify.value_at(expr, mass.blade_numbers(key, sign, checks.DPS))
    return checks.Order(param="varepsilon", values=mass.eps_values, truth=truth, at=at, expected=1,
                        truth_desc=mass.MODEL.format(what="its weight in the tension (no inertia)",
                                                     sign="−" if inverted else "+")
                        + f"; ε(ΔT/T)/(m'/m); blade {key}, {'inverted (M < 0, g < 0)' if inverted else 'direct'}",
                        params=(("blade", key), ("m'/m", "1e-20"), ("R", mass.gravity.R_VALUE),
                                ("g", str(sign * float(mass.gravity.G_VALUE)))))
