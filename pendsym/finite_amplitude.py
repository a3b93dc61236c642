"""First-order perturbation of the pendulum at finite amplitude (osculating α, φ).

The perturbed equation is  θ'' = −ω0² sin θ + f,  f small (any function of θ,
θ', t).  Following the support-sway memoir (Mém. Soc. Phys. Genève t. XVIII, § 4, quoted in
his memoir on the supports), the free motion of amplitude α is written with the
angle φ of

    cos θ = cos α cos²φ + sin²φ,   i.e.  sin(θ/2) = sin(α/2) cos φ,

φ running from 0 (θ = α) to π (θ = −α) over one swing.  Variation of the
constants keeps these relations for θ and θ' with α, φ variable (osculating
elements); the rates α', φ' follow from a 2×2 linear system solved by SymPy.

The memoir's letters: u = μ'/(2 m g sin ½α) with f = μ'/(m h l), so
f = 2 ω0² sin(α/2) u / h.  One swing (φ from 0 to π) gives, to first order in f:

    α_end − α = −(2/h) tan(α/2) ∫_0^π u sin φ / D dφ,        D = √(1 − κ² cos²φ)
    T − T0(α) = (1/(ω0 h)) ∫_0^π u cos φ / D² dφ  +  (1/ω0) ∫_0^π ∂_α(1/D) Δα(φ) dφ

with κ = sin(α/2), T0(α) = ∫_0^π dφ/(ω0 D) = 2K(κ²)/ω0 and Δα(φ) the change
of α from 0 to φ.  The memoir's printed forms are these with the weights of the
free motion (D, T0) at κ → 0: exact to first order in f and to relative
O(sin²½α).  The modulus of the free motion is kept as a separate symbol κ so
that this limit is a substitution, not a retyping.

All functions are pure and return SymPy objects; :func:`swing_first_order`
evaluates the exact first-order formulas with mpmath for a given forcing.
"""
from __future__ import annotations

from functools import lru_cache
from typing import Callable

import mpmath as mp
import sympy as sp

alpha = sp.Symbol("alpha", positive=True)      # osculating amplitude
phi = sp.Symbol("phi", nonnegative=True)       # the memoir's angle φ
psi = sp.Symbol("psi", nonnegative=True)       # dummy angle
w0 = sp.Symbol("omega_0", positive=True)       # √(g/l)
h = sp.Symbol("h", positive=True)              # distance pivot–centre of gravity
f = sp.Symbol("f", real=True)                  # perturbing angular acceleration μ'/(m h l)
kappa = sp.Symbol("kappa", positive=True)      # modulus sin(α/2) of the free motion (weights only)
u = sp.Function("u")                           # the memoir's u(φ) along the free motion


def free_angle(a=alpha, p=phi) -> sp.Expr:
    """θ(α, φ) from cos θ = cos α cos²φ + sin²φ, branch θ = α at φ = 0 (memoir, p. 2)."""
    th = sp.Symbol("theta", real=True)
    # 1 − cos θ = (1 − cos α) cos²φ  ⇔  sin²(θ/2) = sin²(α/2) cos²φ
    rel = sp.Eq(1 - sp.cos(th), (1 - sp.cos(a)) * sp.cos(p) ** 2)
    half = sp.Symbol("s", real=True)
    s2 = sp.solve(rel.subs(sp.cos(th), 1 - 2 * half**2), half)
    # the branch positive at φ = 0 (θ = α > 0), checked at a sample amplitude
    s_pos = [s for s in s2 if s.subs({p: 0, a: sp.Rational(1, 2)}).evalf() > 0]
    if len(s_pos) != 1:
        raise ValueError("no branch θ = α at φ = 0")
    # √(2 − 2cos α)/2 = sin(α/2) for 0 < α < π: same square, same sign
    half_form = sp.sin(a / 2) * sp.cos(p)
    if sp.simplify(sp.expand_trig(s_pos[0] ** 2 - half_form**2).rewrite(sp.cos)) != 0:
        raise ValueError("unexpected half-angle form")
    return 2 * sp.asin(half_form)


def free_speed(a=alpha, p=phi, w=w0) -> sp.Expr:
    """θ' along the free swing: energy θ'² = 2ω0²(cos θ − cos α), θ' ≤ 0 for 0 ≤ φ ≤ π."""
    th = free_angle(a, p)
    sq = sp.simplify(sp.expand_trig(2 * w**2 * (sp.cos(th) - sp.cos(a))))
    # sq = 4ω0² sin²(α/2) sin²φ: the root with the sign of −sin φ (θ decreasing)
    cand = -2 * w * sp.sin(a / 2) * sp.sin(p)
    if sp.simplify(cand**2 - sq) != 0:
        raise ValueError("unexpected form of the energy integral")
    return cand


@lru_cache(maxsize=None)
def rates() -> tuple[sp.Expr, sp.Expr]:
    """(α', φ') of the osculating elements under θ'' = −ω0² sin θ + f (variation of constants).

    Conditions: θ = Θ(α, φ) and θ' = W(α, φ) hold along the perturbed motion,
    where Θ, W are the free-motion relations; differentiating gives
    Θ_α α' + Θ_φ φ' = W and W_α α' + W_φ φ' = −ω0² sin Θ + f.
    """
    ad, pd = sp.symbols("alphadot phidot")
    Th, W = free_angle(), free_speed()
    e1 = sp.diff(Th, alpha) * ad + sp.diff(Th, phi) * pd - W
    e2 = sp.diff(W, alpha) * ad + sp.diff(W, phi) * pd - (-w0**2 * sp.sin(Th) + f)
    sol = sp.solve([e1, e2], [ad, pd], dict=True)
    if len(sol) != 1:
        raise ValueError("variation of constants: singular system")
    return sp.simplify(sol[0][ad]), sp.simplify(sol[0][pd])


def D(k=kappa, p=phi) -> sp.Expr:
    """√(1 − κ² cos²φ): φ' = ω0 D on the free motion (memoir, p. 6: dφ = √(g/l)√(1 − sin²½α cos²φ) dt)."""
    return sp.sqrt(1 - k**2 * sp.cos(p) ** 2)


@lru_cache(maxsize=None)
def free_phase_rate() -> sp.Expr:
    """φ' of the free motion, from :func:`rates` with f = 0, written with κ = sin(α/2)."""
    pd0 = rates()[1].subs(f, 0)
    target = w0 * D(sp.sin(alpha / 2))
    if sp.simplify(sp.expand_trig(pd0**2 - target**2)) != 0:
        raise ValueError("free phase rate is not ω0 D")
    return w0 * D()


def forcing_of_u(uu: sp.Expr) -> sp.Expr:
    """f = μ'/(m h l) with u = μ'/(2 m g sin ½α) and g/l = ω0²: f = 2ω0² sin(α/2) u/h."""
    m_, g_, l_ = sp.symbols("m g l", positive=True)
    mu = 2 * m_ * g_ * sp.sin(alpha / 2) * uu
    return sp.simplify((mu / (m_ * h * l_)).subs(g_, w0**2 * l_))


@lru_cache(maxsize=None)
def first_order_densities() -> dict[str, sp.Expr]:
    """Per unit φ, to first order in u: dα/dφ and the extra dt/dφ, free weights with κ.

    dα/dφ = α'/φ' ≈ α'_1/(ω0 D);  dt/dφ = 1/φ' ≈ 1/(ω0 D) − φ'_1/(ω0 D)².
    """
    ad, pd = rates()
    fu = forcing_of_u(u(phi))
    ad1 = sp.simplify(ad.subs(f, fu))
    pd1 = sp.simplify((pd - pd.subs(f, 0)).subs(f, fu))
    free = free_phase_rate()
    return {"dalpha": sp.simplify(ad1 / free), "dt_direct": sp.simplify(-pd1 / free**2),
            "dt_free": 1 / free}


def T0(k=kappa) -> sp.Expr:
    """Free swing time ∫_0^π dφ/(ω0 D) (= 2K(κ²)/ω0); evaluated when κ = 0."""
    expr = sp.Integral(first_order_densities()["dt_free"].subs(kappa, k), (phi, 0, sp.pi))
    return expr.doit() if k == 0 else expr


def dalpha_swing(k=kappa) -> sp.Expr:
    """α_end − α over one swing, first order in u (free weight D taken at modulus k)."""
    return sp.Integral(first_order_densities()["dalpha"].subs(kappa, k), (phi, 0, sp.pi))


def alpha1(k=kappa) -> sp.Expr:
    """The memoir's α1: the decrease of the amplitude over one swing, −(α_end − α)."""
    return -dalpha_swing(k)


def delta_direct(k=kappa) -> sp.Expr:
    """Relative change of the swing time from the phase rate alone: ΔT_direct/T0."""
    num = sp.Integral(first_order_densities()["dt_direct"].subs(kappa, k), (phi, 0, sp.pi))
    return num / T0(k)


def delta_iso() -> sp.Expr:
    """Isochronism term: the free swing time depends on α, which changes along the swing.

    (1/T0) ∫_0^π ∂_α[1/(ω0 D(sin(α/2)))] Δα(φ) dφ with Δα(φ) = ∫_0^φ dα/dφ.  It vanishes
    with κ (its weight is ∂_α D ∝ κ).
    """
    dens = first_order_densities()
    w_alpha = sp.diff(dens["dt_free"].subs(kappa, sp.sin(alpha / 2)), alpha)
    d_alpha_upto = sp.Integral(dens["dalpha"].subs(kappa, sp.sin(alpha / 2)).subs(phi, psi).replace(u, lambda a: u(a)),
                               (psi, 0, phi))
    return sp.Integral(w_alpha * d_alpha_upto, (phi, 0, sp.pi)) / T0(sp.sin(alpha / 2))


def delta_exact() -> sp.Expr:
    """δ = T/T0(α) − 1 to first order in u, exact in α (α the amplitude at the start of the swing)."""
    return delta_direct(sp.sin(alpha / 2)) + delta_iso()


def delta_leading() -> sp.Expr:
    """δ with the free weights at κ = 0 (the isochronism term vanishes there): the memoir's form."""
    return sp.simplify(delta_direct(sp.S.Zero))


def alpha1_exact() -> sp.Expr:
    return alpha1(sp.sin(alpha / 2))


def alpha1_leading() -> sp.Expr:
    return alpha1(sp.S.Zero)


# ---------------------------------------------------------------- numerical evaluation
CPHI, SPHI, U = sp.symbols("C_phi S_phi U", real=True)
SA, CA = sp.symbols("S_a C_a", positive=True)   # sin(α/2), cos(α/2), computed once per swing


def _trig_free(expr: sp.Expr) -> sp.Expr:
    """cos φ, sin φ → states; functions of α/2 → constants (cheap at odefun's working precision)."""
    out = expr.subs({sp.cos(phi): CPHI, sp.sin(phi): SPHI})
    out = out.subs({sp.tan(alpha / 2): SA / CA, sp.sin(alpha / 2): SA, sp.cos(alpha / 2): CA})
    if alpha in out.free_symbols or phi in out.free_symbols:
        raise ValueError(f"not reduced to the evaluator's variables: {out}")
    return out


@lru_cache(maxsize=None)
def _numeric_weights():
    dens = first_order_densities()
    k_ = sp.sin(alpha / 2)
    args = (CPHI, SPHI, SA, CA, w0, h, U)
    da = sp.lambdify(args, _trig_free(dens["dalpha"].subs(kappa, k_).subs(u(phi), U)), "mpmath")
    dt = sp.lambdify(args, _trig_free(dens["dt_direct"].subs(kappa, k_).subs(u(phi), U)), "mpmath")
    tf = sp.lambdify(args, _trig_free(dens["dt_free"].subs(kappa, k_)), "mpmath")
    dtf_da = sp.lambdify(args, _trig_free(sp.diff(dens["dt_free"].subs(kappa, k_), alpha)), "mpmath")
    # the free state (sin θ, cos θ, θ') from sin(θ/2) = sin(α/2) cos φ
    th = free_angle()
    sin_th = _trig_free(sp.expand_trig(sp.sin(th)))
    cos_th = _trig_free(sp.expand_trig(sp.cos(th)))
    state = sp.lambdify((CPHI, SPHI, SA, CA, w0), (sin_th, cos_th, _trig_free(free_speed())), "mpmath")
    uf = sp.lambdify((SA, CA, w0, h, f), _trig_free(sp.solve(sp.Eq(forcing_of_u(U), f), U)[0]), "mpmath")
    return da, dt, tf, dtf_da, state, uf


def swing_first_order(forcing: Callable, alpha_val, w0_val=1, h_val=1, dps: int = 30) -> dict:
    """Exact first-order swing quantities for a forcing f(sin θ, cos θ, θ', t) (at unit size).

    Integrates in φ from 0 to π, with mpmath odefun, the system
    (cos φ, sin φ)' = (−sin φ, cos φ), t' = dt/dφ, Δα' = dα/dφ, ΔT_direct',
    ΔT_iso' = ∂_α(dt_free/dφ)·Δα, with u evaluated from f along the free motion.
    Returns a dict with ``dalpha`` (α_end − α), ``alpha1`` (= −dalpha),
    ``delta`` (T/T0 − 1), ``delta_direct``, ``delta_iso`` and ``T0``.  The h
    used in u cancels.
    """
    da, dt, tf, dtf_da, state, uf = _numeric_weights()
    with mp.workdps(dps):
        a, w, hh = mp.mpf(alpha_val), mp.mpf(w0_val), mp.mpf(h_val)
        sa, ca = mp.sin(a / 2), mp.cos(a / 2)

        def rhs(p, y):
            c, s, tt, dal, tdir, tiso = y
            st, ct, wt = state(c, s, sa, ca, w)
            U_ = uf(sa, ca, w, hh, forcing(st, ct, wt, tt))
            return [-s, c, tf(c, s, sa, ca, w, hh, 0), da(c, s, sa, ca, w, hh, U_), dt(c, s, sa, ca, w, hh, U_),
                    dtf_da(c, s, sa, ca, w, hh, 0) * dal]

        sol = mp.odefun(rhs, 0, [mp.mpf(1)] + [mp.mpf(0)] * 5, tol=mp.mpf(10) ** (-dps - 3))
        _, _, T0v, dal, tdir, tiso = sol(mp.pi)
        return {"T0": T0v, "dalpha": dal, "alpha1": -dal, "delta": (tdir + tiso) / T0v,
                "delta_direct": tdir / T0v, "delta_iso": tiso / T0v}
