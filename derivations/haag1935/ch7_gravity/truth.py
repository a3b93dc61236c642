"""Haag 1935, chapters VII–VIII: the independent truth of the gravity pendulum, direct and inverted.

The blade is solved directly for a prescribed end position (:mod:`pendsym.suspension`: the linearised
(2)–(3), no v, w), for M = EI/(mg) > 0 (direct suspension, g > 0) or M < 0 (inverted blade: g → −g in
every equation, n°100, so that M v'' − v = 0 reads |M| v'' + v = 0).  The rigid pendulum on it gives the
generalised eigenproblem K q = n² 𝕄 q (K = mg[[∂Y/∂β, ∂Y/∂θ], [∂N/∂β, ∂N/∂θ + a]], g < 0 for the inverted
blade), solved by mpmath ``eig``.  The critical distance a1 is where det K = 0 (K is linear in a), so that
a = a1 + ελ (256) or a = a1 − ελ (312) is placed on the truth itself, never on a formula.

The two modes are named by chapter VII's convention (n°83): the slow mode (n² → 0 with ε) has its node
at z' (the root near w0), the fast one at z.  K = −n²z'/g and K' = −n'²z/g (34).  The sensitivity
coefficient is G = 2 d log T/d log g = −d log n²/d log g at fixed EI, m, a, R, λ (61): g(1 + kh) and
M/(1 + kh), k = ±1, ±2, by the 5-point stencil (error O((Gh)⁴), h = 1e-10·ε·min(1, u²) rounded down to a
power of ten, 42 working digits or more).
Haag's v, w (the end values w0, β1 a formula takes) come from the shot blade of :mod:`pendsym.blade`.
"""
from __future__ import annotations

import functools

import mpmath as mp
import sympy as sp

from pendsym import blade, suspension
from .. import profiles

LAMBDA = sp.Rational(1, 10)           # 10 cm blade
R_VALUE = "0.05"                      # radius of gyration (m)
G_VALUE = "9.81"
H = sp.Rational(1, 10**10)            # relative step of the stencil in g
MODEL = ("pendsym.suspension: the blade (2)–(3) solved directly (no v, w) and the eigenproblem K q = n² 𝕄 q "
         "of the rigid pendulum on it, solved by mpmath eig; a1 where det K = 0; 30 digits, confirmed at 45")


def base_blade(key: str, sign: int) -> blade.Blade:
    """The blade ``key``: "u=<rational>" the uniform blade M = ±(λ/u)², λ = 1/10, or a chapter I profile
    of :mod:`..profiles` ("tapered", "bulged"); sign −1 turns M into −M (the inverted blade, g → −g)."""
    if key.startswith("u="):
        u = sp.Rational(key[2:])
        return blade.Blade(LAMBDA, sign * (LAMBDA / u) ** 2)
    base = profiles.profile(key)
    return blade.Blade(base.length, sign * base.M)


def scaled_blade(key: str, sign: int, k: int, step: sp.Rational = H) -> blade.Blade:
    """The blade at g(1 + k·step): M = EI/(mg) divided by 1 + k·step."""
    base = base_blade(key, sign)
    return blade.Blade(base.length, base.M / (1 + k * step))


@functools.lru_cache(maxsize=128)
def direct(key: str, sign: int, k: int = 0, dps: int = 30, step: sp.Rational = H) -> suspension.Suspension:
    return suspension.solve(scaled_blade(key, sign, k, step), dps)


def stencil_step(env: dict, eps) -> sp.Rational:
    """H times the power of ten below ε·min(1, u²): G ~ 1/(εu²) near a1, so that G·step stays ≤ H and the
    stencil's O((G·step)⁴) error stays negligible."""
    size = mp.mpf(eps) * min(1, env.get("u", 1) ** 2)
    return H * sp.Rational(10) ** int(mp.floor(mp.log10(size)))


@functools.lru_cache(maxsize=32)
def shot(key: str, sign: int, dps: int = 30) -> blade.BladeSolution:
    return blade.solve(base_blade(key, sign), dps)


def critical_distance(sus: suspension.Suspension) -> mp.mpf:
    """The a where det K(a) = 0: S00(S11 + a) − S01S10 = 0."""
    S = sus.stiffness
    with mp.workdps(sus.wdps):
        return S[0, 1] * S[1, 0] / S[0, 0] - S[1, 1]


def eigenmodes(sus: suspension.Suspension, a, R, g) -> list[tuple]:
    """[(n², node z)] of K q = n² 𝕄 q, by increasing n² (node: y = β + (a + z)θ = 0)."""
    with mp.workdps(sus.wdps):
        a, R, g = mp.mpf(a), mp.mpf(R), mp.mpf(g)
        ev, vecs = mp.eig(mp.inverse(suspension.mass_matrix(a, R)) * suspension.stiffness_matrix(sus, a, 1, g))
        out = [(mp.re(ev[i]), -mp.re(vecs[0, i] / vecs[1, i]) - a) for i in range(2)]
        return sorted(out, key=lambda pair: pair[0])


def numbers(sus_key: str, sign: int, dps: int = 30) -> dict:
    """λ, R, g (g < 0 for the inverted blade), the shot end values and β1, and the direct a1, by symbol name."""
    sol = shot(sus_key, sign, dps)
    sus = direct(sus_key, sign, 0, dps)
    out = {"lambda": suspension.number(sol.blade.length), "R": mp.mpf(R_VALUE), "g": sign * mp.mpf(G_VALUE),
           "v_0": sol.v0, "v_lambda": sol.vl, "w_0": sol.w0, "w_lambda": sol.wl, "beta_1": sol.beta1,
           "a_1": critical_distance(sus)}
    if sus_key.startswith("u="):
        out["u"] = suspension.number(sp.Rational(sus_key[2:]))
    out["M_lambda"] = sol.M_at(sol.blade.length)
    out.update({name: suspension.number(value) for name, value in TEMPERATURE.items()})
    return out


def state(key: str, sign: int, eps, dps: int = 30) -> dict:
    """:func:`numbers` and, at a = a1 + sign·ελ, the slow mode (n², node z') and the fast one (n'², z),
    K = −n²z'/g, K' = −n'²z/g, and ε (``varepsilon``)."""
    env = numbers(key, sign, dps)
    sus = direct(key, sign, 0, dps)
    with mp.workdps(sus.wdps):
        eps = mp.mpf(eps)
        a = env["a_1"] + sign * eps * env["lambda"]
        (n2, zp), (n2p, z) = eigenmodes(sus, a, env["R"], env["g"])
        env.update({"a": a, "varepsilon": eps, "n^2": n2, "z'": zp, "n'^2": n2p, "z": z,
                    "K": -n2 * zp / env["g"], "K'": -n2p * z / env["g"]})
    return env


def sensitivity(key: str, sign: int, eps, dps: int = 30) -> mp.mpf:
    """G = −d log n²/d log g of the slow mode, at fixed EI, m, a, R, λ (61): stencil over g(1 + kh),
    h = :func:`stencil_step`."""
    env = numbers(key, sign, dps)
    sus = direct(key, sign, 0, dps)
    with mp.workdps(sus.wdps):
        a = env["a_1"] + sign * mp.mpf(eps) * env["lambda"]
        step = stencil_step(env, eps)
        h = suspension.number(step)

        def log_n2(k):
            return mp.log(eigenmodes(direct(key, sign, k, dps, step), a, env["R"], env["g"] * (1 + k * h))[0][0])
        return -(8 * (log_n2(1) - log_n2(-1)) - (log_n2(2) - log_n2(-2))) / (12 * h)


# ---------------------------------------------------------------- temperature (n°87, n°103)
# per degree: dλ/λ = α, da/a = dR/R = α', dE/E = β, dI/I = 4α (n°14); a steel blade and a brass rod
ALPHA, ALPHA_ROD, BETA_T = sp.Rational(11, 10**6), sp.Rational(19, 10**6), sp.Rational(-24, 10**5)
TEMPERATURE = {"alpha": ALPHA, "alpha'": ALPHA_ROD, "beta_t": BETA_T}
H_DEGREE = sp.Rational(1, 10**6)     # step of the temperature stencil, in degrees


@functools.lru_cache(maxsize=64)
def warmed(key: str, sign: int, k: int, dps: int = 30) -> suspension.Suspension:
    """The uniform blade ``key`` after kH degrees: λ(1 + αkH), M(1 + (β + 4α)kH) (M = EI/(mg), (1))."""
    base = base_blade(key, sign)
    step = k * H_DEGREE
    return suspension.solve(blade.Blade(base.length * (1 + ALPHA * step), base.M * (1 + (BETA_T + 4 * ALPHA) * step)),
                            dps)


def temperature(key: str, sign: int, eps, dps: int = 30) -> mp.mpf:
    """d log T per degree of the slow mode (n°14): a, R grow by α', the blade as :func:`warmed`, g fixed;
    the pendulum placed at a = a1 ± ελ before the warming.  5-point stencil in the temperature."""
    env = numbers(key, sign, dps)
    with mp.workdps(direct(key, sign, 0, dps).wdps):
        a = env["a_1"] + sign * mp.mpf(eps) * env["lambda"]
        h, rod = suspension.number(H_DEGREE), suspension.number(ALPHA_ROD)

        def log_T(k):
            grown = 1 + rod * k * h
            return -mp.log(eigenmodes(warmed(key, sign, k, dps), a * grown, env["R"] * grown, env["g"])[0][0]) / 2
        return (8 * (log_T(1) - log_T(-1)) - (log_T(2) - log_T(-2))) / (12 * h)


def g_correction(key: str, sign: int, eps, dps: int = 30) -> mp.mpf:
    """The correction dg/g = −(2/G) dT/T of a 1° warming (n°87), both from the truth."""
    return -2 * temperature(key, sign, eps, dps) / sensitivity(key, sign, eps, dps)
