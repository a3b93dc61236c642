"""Haag 1935, chapter I, n°1–9, eqs. (1)–(41): equations, properties of v and w, foci, periods, existence.

Derivations: (4)–(6) from the kinematics of the centre of gravity G of the rigid
pendulum, (7) by differentiating (2) with (3), (8) by linearising (7); (12)–(14)
from the definitions (9)–(11); (15)–(16), (21)–(37) by the step functions of
:mod:`.ch1_model`; the inequalities of n°3 and n°9 as the quantities that the
memoir claims positive.

Independent truth: :mod:`pendsym.suspension` (the linearised blade (2)–(3)
solved directly for a prescribed end position, its end loads, and the
eigenproblem K q = n² 𝕄 q of the pendulum, which knows nothing of v, w),
mpmath quad of definitions, and, for the properties of v, w themselves (n°3,
n°4), the shot v, w of :mod:`pendsym.blade`.  All on the four blades of
:mod:`.profiles` (uniform, hole, tapered, bulged) and both pendulums, at 30
digits, with the truth confirmed by a 45-digit solve of the ``hole`` blade.
"""
from __future__ import annotations

import dataclasses
import functools

import mpmath as mp
import sympy as sp

from pendsym import blade as B
from pendsym import pipeline, verify
from pendsym import suspension as SU
from pendsym.result import Evidence, Reading, Source, Spec
from . import ch1_model as C
from . import profiles as P
from .ch1_model import N, X, alpha, bdd, beta, eps, n2, tdd, thd, v, w
# the steps of n°5–8, each cached in ch1_model (computed once per process)
from .ch1_model import K_of_z, K_of_zp, foci_quadratic, focal_conditions, motion, n2_of_focus, product_shifted, vieta
from .symbols import K, R, Y, a, beta1, beta2, g, lam, s, theta, v0, vl, w0, wl, z, zp

MEMOIR = "haag1935"


READ_VW = Reading("ν, ω", "v, w: the OCR renders Haag's functions v, w (and their end values) as ν, ω")

# ---------------------------------------------------------------- symbols of this module
m = sp.Symbol("m", positive=True)                 # mass of the pendulum (1)
EI = sp.Symbol("EI", positive=True)               # E·I (1)
add = sp.Symbol("alpha''", real=True)             # α''
Mf = C.Mf                                         # M(s) (1)
x_, y_, phi_ = sp.Function("x"), sp.Function("y"), sp.Function("varphi")
phi1, phi2 = sp.symbols("varphi_1 varphi_2", real=True)   # values of φ1, φ2 at s (11)
v_s, w_s, M_s = sp.symbols("v_s w_s M_s", real=True)      # v(s), w(s), M(s) at a point
M1, M2, mu = sp.symbols("M_1 M_2 mu", positive=True)      # min, max of M and μ = M2/M1 (n°3)
t = sp.Symbol("t", real=True)
# test functions under which forms holding arbitrary functions of s are compared (verify.compare_forms)
INSTANCES = tuple(tuple((f, sp.Lambda(s, e)) for f, e in zip((phi_, x_, y_, C.Mf, v, w), exprs)) for exprs in (
    (sp.sin(s) / 3 + s**2, 1 + s / 2, s**3 - s, 2 + sp.cos(s), sp.exp(s / 3) - 1, s**2 + 3),
    (s / 5 - s**3, sp.cos(s), sp.sin(2 * s), 1 + s**2, 2 - s, sp.exp(-s))))

DPS, CONFIRM_DPS = 30, 45
CONFIRM_PROFILE = "hole"
TOL = mp.mpf("1e-25")
PROFILES = {"quick": ("uniform", "tapered"), "full": P.PROFILE_NAMES}
PENDS = {"quick": ("clock",), "full": ("clock", "compact")}
POSITIONS = (("1", "0"), ("0", "1"), ("0.3", "-0.7"))    # (β/λ, θ) end positions for the load checks


def rid(eq: int, name: str) -> str:
    return f"{MEMOIR}.eq{eq:03d}.{name}"


def src(para: str, eq: str | None) -> Source:
    return Source(MEMOIR, para, None, eq)


# ================================================================ n°1: (1)–(6)
def bending_moment() -> sp.Expr:
    """Right side of (2): N + (α − x)Y − (β − y)X, with x, y functions of s."""
    return N + (alpha - x_(s)) * Y - (beta - y_(s)) * X


def G_coordinates():
    """x_G = α + a cos θ, y_G = β + a sin θ (AT passes through G, AG = a; n°1)."""
    al, be, th = (sp.Function(n)(t) for n in ("alpha", "beta", "theta"))
    return al, be, th, al + a * sp.cos(th), be + a * sp.sin(th)


def _dot_symbols(expr, al, be, th):
    """α(t), β(t), θ(t) and their derivatives → the symbols α, β, θ, α'', β'', θ', θ''."""
    rep = {al.diff(t, 2): add, be.diff(t, 2): bdd, th.diff(t, 2): tdd, th.diff(t): thd}
    expr = expr.subs(rep)
    return expr.subs({al: alpha, be: beta, th: theta})


def centre_of_gravity(axis: int) -> sp.Expr:
    """m x_G'' − (forces on Ox): (4) for axis 0, m y_G'' − (forces on Oy): (5) for axis 1.

    Forces on the pendulum: the weight mg along Ox (vertical, downwards), the reaction (−mgX, −mgY) at A.
    """
    al, be, th, xG, yG = G_coordinates()
    force = (m * g - m * g * X, -m * g * Y)[axis]
    return sp.expand(_dot_symbols(m * (xG, yG)[axis].diff(t, 2) - force, al, be, th))


def angular_momentum() -> sp.Expr:
    """(R²/g)θ'' − (moment about G of −mgN and of (−mgX, −mgY) at A)/(mg): (6)."""
    r = (-a * sp.cos(theta), -a * sp.sin(theta))          # A − G
    F = (-m * g * X, -m * g * Y)
    moment = -m * g * N + r[0] * F[1] - r[1] * F[0]
    return sp.expand(R**2 / g * tdd - moment / (m * g))


# ================================================================ n°2: (7)–(14)
def differentiated_bending() -> sp.Expr:
    """d/ds of the right side of (2) with (3) x' = cos φ, y' = sin φ: the right side of (7)."""
    d = bending_moment().diff(s)
    return sp.expand(d.subs({x_(s).diff(s): sp.cos(phi_(s)), y_(s).diff(s): sp.sin(phi_(s))}))


def linearised_bending() -> sp.Expr:
    """(7) to the first order: φ, Y of order ε, X = 1 + O(ε²) (n°2): the right side of (8)."""
    rhs = differentiated_bending().subs({phi_(s): eps * phi_(s), Y: eps * Y, X: 1 + eps**2 * X})
    return sp.expand(sp.series(rhs, eps, 0, 2).removeO().coeff(eps))


BC10 = {v(s).diff(s).subs(s, 0): -1, v(s).diff(s).subs(s, lam): -1,
        w(s).diff(s).subs(s, 0): 0, w(s).diff(s).subs(s, lam): 1}          # (10)


def phi_of_s() -> sp.Expr:
    """φ = Yφ1 + θφ2 (13) with φ1 = 1 + v', φ2 = w' (11)."""
    return Y * (1 + v(s).diff(s)) + theta * w(s).diff(s)


def reduce9(expr: sp.Expr) -> sp.Expr:
    """Replace v'', w'' by v/M, w/M (9)."""
    return expr.subs({v(s).diff(s, 2): v(s) / Mf(s), w(s).diff(s, 2): w(s) / Mf(s)})


def phi_prime() -> sp.Expr:
    """φ' from (13), (11) and (9): (14)."""
    return sp.factor(reduce9(phi_of_s().diff(s)))


def eq8_residual() -> sp.Expr:
    """d/ds(Mφ') − (φ − Y) for φ of (13): identically 0 by (9), (11), whatever Y and θ."""
    lhs = reduce9((Mf(s) * phi_prime()).diff(s))
    rhs = linearised_bending().subs(phi_(s), phi_of_s())
    return sp.simplify(lhs - rhs)


def phi_ends() -> sp.Tuple:
    """(φ_0, φ_λ) of (13) with (10)."""
    f = phi_of_s()
    return sp.Tuple(*(f.subs(s, e).subs(BC10) for e in (0, lam)))


def phi_end_values() -> sp.Tuple:
    """(φ10, φ1λ, φ20, φ2λ) from (11) with (10): (12)."""
    p1, p2 = 1 + v(s).diff(s), w(s).diff(s)
    return sp.Tuple(*(f.subs(s, e).subs(BC10) for f in (p1, p2) for e in (0, lam)))


# ================================================================ n°3
def ratio_integral() -> sp.Expr:
    """∫_0^λ w0/w² ds = −[v/w]_0^λ, since d/ds(v/w) = −w0/w² by (15)."""
    wr = v(s) * w(s).diff(s) - w(s) * v(s).diff(s)         # = w0 by (15)
    if sp.expand(sp.diff(v(s) / w(s), s) * w(s) ** 2 + wr) != 0:
        raise ValueError("d/ds(v/w) is not −(vw' − wv')/w²")
    return C.ends(v(0) / w(0) - v(lam) / w(lam))


def unit_integral() -> sp.Expr:
    """∫ w/M ds = ∫ w'' ds = w'_λ − w'_0 = 1 by (9), (10)."""
    return (w(s).diff(s).subs(s, lam) - w(s).diff(s).subs(s, 0)).subs(BC10)


# ================================================================ n°4: symmetric blade
def symmetric_vl() -> sp.Expr:
    """v odd in s − λ/2 (n°4): v(λ − σ) = −v(σ) at σ = 0 gives vλ = −v0."""
    sigma = sp.Symbol("sigma")
    return C.ends((-v(sigma)).subs(sigma, 0))


def symmetric_beta1() -> sp.Expr:
    return sp.expand(C.beta1_def().subs(vl, symmetric_vl()))


def symmetric_wl() -> sp.Expr:
    """(16) vλ + wλ = w0 with vλ = −v0."""
    return sp.solve(sp.Eq(C.wronskian_at_lambda().subs(vl, symmetric_vl()), w0), wl)[0]


# ================================================================ n°7–9
def sum_relation() -> sp.Expr:
    """(a − vλ)(z + z') + … of (32): (a − vλ) times (z + z' − Vieta sum of (30))."""
    return sp.expand(sp.cancel((a - vl) * (z + zp - vieta()[1])))


def K_product() -> sp.Expr:
    """KK' with K of (35) and K' by exchanging z and z'; the product of (33) substituted: (37)."""
    k35 = K_of_zp()
    kk = sp.factor(k35 * k35.subs(zp, z))
    assert sp.expand(kk * beta1**2 - (a + z - vl) * (a + zp - vl)) == 0
    return sp.cancel(product_shifted() / beta1**2)


def critical_distance() -> sp.Expr:
    """a where the right side of (33) vanishes (K, K' change sign): (41)."""
    return sp.solve(product_shifted(), a)[0]


# ================================================================ numerical truth
def _mp(x) -> mp.mpf:
    return SU.number(sp.nsimplify(x))


@functools.lru_cache(maxsize=64)
def M_range(name: str) -> tuple:
    """(M1, M2) = min and max of M on [0, λ]: ends of each smooth piece and its critical points."""
    cands = []
    for lo, hi, e in B.segments(P.profile(name)):
        xs = [lo, hi] + [r for r in sp.solve(sp.diff(e, s), s) if r.is_real and lo < r < hi]
        cands += [e.subs(s, x) for x in xs]
    return min(cands), max(cands)


def shot_env(name: str, dps: int = DPS) -> dict:
    """v0, vλ, w0, wλ, β1, β2, λ of the shot blade (pendsym.blade), by symbol name."""
    sol = P.blade_solution(name, dps)
    M1v, M2v = M_range(name)
    return {"v_0": sol.v0, "v_lambda": sol.vl, "w_0": sol.w0, "w_lambda": sol.wl, "beta_1": sol.beta1,
            "beta_2": sol.beta2, "lambda": _mp(sol.blade.length),
            "M_1": _mp(M1v), "M_2": _mp(M2v), "mu": _mp(M2v / M1v)}


def pendulum(pend: str) -> tuple:
    return tuple(mp.mpf(x) for x in P.PENDULUMS[pend])


def mode_env(name: str, pend: str, dps: int = DPS) -> dict:
    """a, R, g and, from suspension.modes (no v, w): the foci z (lower, node of the parasitic mode),
    z' (upper, node of the principal mode), n² (principal) and n'² (parasitic)."""
    av, Rv, gv = pendulum(pend)
    principal, parasitic = SU.modes(P.suspension(name, dps), av, Rv, gv)
    return {"a": av, "R": Rv, "g": gv, "z": parasitic.z, "z'": principal.z,
            "n^2": principal.n2, "n'^2": parasitic.n2}


def evaluate(expr: sp.Expr, env: dict) -> mp.mpf:
    """expr at the point env (symbol name → value), at the precision in force."""
    return mp.mpf(verify.value_at(expr, env))


def _abs_terms(expr: sp.Expr, env: dict) -> mp.mpf:
    """Σ|terms| of the expanded expr at env: the scale of a quantity that should vanish."""
    terms = sp.Add.make_args(sp.expand(expr))
    return sum((abs(evaluate(tm, env)) for tm in terms), mp.mpf(0))


def _digits(env30: dict, env45: dict, t30, t45) -> float:
    """Agreement of the truth (and of every shared nonzero value of the environment) at two precisions."""
    ds = [verify.truth_digits(t30, t45)] if t30 != 0 else []
    ds += [verify.truth_digits(env30[k], env45[k]) for k in env30 if k in env45 and env30[k] != 0]
    return min(ds) if ds else 45.0


def confirmation() -> float:
    """Digits to which the truth (shot v, w, the suspension's modes at the clock pendulum) of the hole blade
    agrees between 30 and 45 digits."""
    e30 = env_shot(CONFIRM_PROFILE, "clock", DPS)
    with mp.workdps(CONFIRM_DPS + 10):
        e45 = env_shot(CONFIRM_PROFILE, "clock", CONFIRM_DPS)
    return _digits(e30, e45, 0, 0)


def confirmed(check):
    """Add the 45-digit confirmation to a check's Evidence: it fails below 28 digits."""
    def run(result, level):
        ev = check(result, level)
        d = confirmation()
        return Evidence(**{**ev.__dict__, "passed": bool(ev.passed and d >= 28), "confirm_digits": verify.rounded(d),
                           "note": ev.note + f" | truth confirmed to {d:.1f} digits at {CONFIRM_DPS}"})
    return run


def _resid(f, t, scale) -> mp.mpf:
    return abs(mp.mpf(f) - mp.mpf(t)) / max(abs(mp.mpf(t)), mp.mpf(scale))


def numeric_check(desc: str, rows, pend: bool = True, names=None, extra=None):
    """Compare the derived (and the printed) form with the truth on the profiles (and pendulums).

    ``rows(name, pend, dps)`` yields (label, env, truth, scale): the formula is evaluated at env,
    its residual |formula − truth| / max(|truth|, scale) must stay below 1e-25.  The first row of
    the ``hole`` blade is recomputed at 45 digits: the check fails unless it agrees to 28 digits.
    ``extra(result, level)`` may return a further Evidence to combine.
    """
    def check(result, level):
        pends = PENDS[level] if pend else (None,)
        worst, pworst, labels = mp.mpf(0), mp.mpf(0), []
        for name in names or PROFILES[level]:
            for pe in pends:
                for label, env, truth, scale in rows(name, pe, DPS):
                    worst = max(worst, _resid(evaluate(result.derived_value, env), truth, scale))
                    if result.printed is not None:
                        pworst = max(pworst, _resid(evaluate(result.printed_value, env), truth, scale))
                    labels.append(f"{name}/{pe}" if pe else name)
        l30, e30, t30, _ = next(iter(rows(CONFIRM_PROFILE, pends[0], DPS)))
        with mp.workdps(CONFIRM_DPS + 10):
            l45, e45, t45, _ = next(iter(rows(CONFIRM_PROFILE, pends[0], CONFIRM_DPS)))
        digits = _digits(e30, e45, t30, t45)
        note = (f"{len(labels)} points on {', '.join(sorted(set(labels)))}; truth confirmed to {digits:.1f} digits "
                f"by a {CONFIRM_DPS}-digit solve of the {CONFIRM_PROFILE} blade")
        if result.printed is not None:
            note += f"; printed form: max residual {float(pworst):.3g}"
        ev = Evidence(kind="value", passed=bool(worst < TOL and digits >= 28), truth=desc,
                      max_residual=verify.rounded(worst),
                      printed_agrees=None if result.printed is None else bool(pworst < TOL),
                      confirm_digits=verify.rounded(digits), note=note)
        if extra is not None:
            ev = verify.combine(ev, extra(result, level), truth_desc=ev.truth)
            ev = Evidence(**{**ev.__dict__, "printed_agrees": None if result.printed is None else bool(pworst < TOL),
                             "confirm_digits": verify.rounded(digits), "max_residual": verify.rounded(worst)})
        return ev
    return check


def inequality_check(desc: str, env_fn, pend: bool = False):
    """The derived (and printed) quantity, claimed positive by the memoir, on every profile (and pendulum).

    Each margin must exceed 1e-20 of Σ|terms| (resolved at 30 digits); the margins are reported.
    """
    def check(result, level):
        pends = PENDS["full"] if pend else (None,)
        margins, ok = [], True
        for name in P.PROFILE_NAMES:
            for pe in pends:
                env = env_fn(name, pe, DPS)
                mval = evaluate(result.derived_value, env)
                scale = _abs_terms(result.derived_value, env)
                ok &= bool(mval > scale * mp.mpf("1e-20"))
                if result.printed is not None:
                    ok &= bool(evaluate(result.printed_value, env) > scale * mp.mpf("1e-20"))
                margins.append((f"{name}/{pe}" if pe else name, mval, mval / scale if scale else mval))
        lo = min(mg_[2] for mg_ in margins)
        note = "margins (value; value/Σ|terms|): " + "; ".join(
            f"{lb}: {mp.nstr(mv, 6)} ({mp.nstr(rel, 3)})" for lb, mv, rel in margins)
        return Evidence(kind="inequality", passed=bool(ok), truth=desc, max_residual=verify.rounded(lo),
                        printed_agrees=None if result.printed is None else bool(ok), note=note)
    return confirmed(check)


# ---------------------------------------------------------------- rows of the numeric checks
SHOT = "shot v, w of pendsym.blade (odefun shooting, 30 digits)"
SUS = ("pendsym.suspension: the linearised blade (2)–(3) solved directly for the end position (β, θ), "
       "no v, w (30 digits)")
EIG = ("pendsym.suspension.modes: the eigenproblem K q = n² 𝕄 q of the pendulum on the directly solved "
       "blade, no v, w (30 digits)")


def env_shot(name, pe, dps):
    env = shot_env(name, dps)
    if pe:
        env.update(mode_env(name, pe, dps))
    return env


def rows_loads(quantity):
    """Rows for (21)–(24): at several end positions, the end loads of the suspension as truth."""
    def rows(name, pe, dps):
        sus = P.suspension(name, dps)
        env0 = shot_env(name, dps)
        for bq, tq in POSITIONS:
            be, th = mp.mpf(bq) * env0["lambda"], mp.mpf(tq)
            c, Yv, Nv = sus.loads(be, th)
            env = dict(env0, beta=be, theta=th, Y=Yv, N=Nv)
            truth = {"beta": be, "Y": Yv, "N": Nv, "beta1": 1 / sus.stiffness[0, 0],
                     "beta2": -sus.stiffness[0, 1] / sus.stiffness[0, 0]}[quantity]
            yield (f"β={bq}λ,θ={tq}", env, truth, env0["lambda"] if quantity == "beta" else mp.mpf(0))
    return rows


def rows_deflection(which, fracs=("0", "0.37", "0.81", "1")):
    """Rows for (13), (14): φ or φ' along the blade from the suspension (which = 1 or 2)."""
    def rows(name, pe, dps):
        sus, sol = P.suspension(name, dps), P.blade_solution(name, dps)
        env0 = shot_env(name, dps)
        be, th = mp.mpf("0.3") * env0["lambda"], mp.mpf("-0.7")
        _, Yv, _ = sus.loads(be, th)
        for frac in fracs:
            sv = mp.mpf(frac) * env0["lambda"]
            vv, dv, wv, dw = sol.state(sv)
            env = dict(env0, Y=Yv, theta=th, varphi_1=1 + dv, varphi_2=dw, v_s=vv, w_s=wv, M_s=sol.M_at(sv))
            truth = sus.deflection(sv, be, th)[which]
            yield (f"s={frac}λ", env, truth, abs(th) * (1 if which == 1 else 1 / env0["lambda"]))
    return rows


def rows_modes(quantity):
    """Rows for (25)–(41): the foci and n² of suspension.modes, per pendulum."""
    def rows(name, pe, dps):
        env = env_shot(name, pe, dps)
        yield (pe, env, quantity(env), mp.mpf(0))
    return rows


def zero_check(desc, swap=False):
    """The derived/printed residual at each focus with the suspension's n²: must vanish.

    For (28), (29): the root z goes with the n² of the mode whose node is the other root
    (the canonical variable y_F vanishes in the other mode); swap=True adds the other pair.
    """
    def check(result, level):
        worst, pworst, n = mp.mpf(0), mp.mpf(0), 0
        for name in PROFILES[level]:
            for pe in PENDS[level]:
                env = env_shot(name, pe, DPS)
                pairs = [env]
                if swap:
                    pairs.append(dict(env, z=env["z'"], **{"z'": env["z"], "n^2": env["n'^2"]}))
                for e in pairs:
                    for form, acc in ((result.derived_value, "d"), (result.printed_value, "p")):
                        if form is None:
                            continue
                        r = abs(evaluate(form, e)) / _abs_terms(form, e)
                        if acc == "d":
                            worst = max(worst, r)
                        else:
                            pworst = max(pworst, r)
                    n += 1
        digits = confirmation()
        return Evidence(kind="value", passed=bool(worst < TOL and digits >= 28), truth=desc,
                        max_residual=verify.rounded(worst),
                        printed_agrees=None if result.printed is None else bool(pworst < TOL),
                        confirm_digits=verify.rounded(digits),
                        note=f"{n} (profile, pendulum, focus) cases, residual relative to Σ|terms|; "
                             f"printed: {float(pworst):.3g}; truth confirmed to {digits:.1f} digits at {CONFIRM_DPS}")
    return check


# ---------------------------------------------------------------- specific checks
def _is_zero(expr) -> bool:
    """Every component of expr (a scalar, Tuple or Matrix) simplifies to 0."""
    parts = list(expr) if isinstance(expr, (sp.Tuple, sp.MatrixBase, tuple, list)) else [expr]
    return all(sp.simplify(x) == 0 for x in parts)


def _proof(statement, expr_fn):
    def check(result, level):
        return verify.proof(statement=statement, holds=_is_zero(expr_fn(result)), truth_desc="symbolic proof")
    return check


def phi_numeric(fracs, statement: str):
    """Symbolic proof (the derived form vanishes) and φ = Yφ1 + θφ2 of the shot blade against the suspension's φ(s)
    at s = frac·λ (end position (0.3λ, −0.7), Y the suspension's end load)."""
    def check(result, level):
        worst, n = mp.mpf(0), 0
        for name in PROFILES[level]:
            for label, env, truth, scale in rows_deflection(1, fracs)(name, None, DPS):
                worst = max(worst, _resid(evaluate(Y * phi1 + theta * phi2, env), truth, scale))
                n += 1
        num = Evidence(kind="value", passed=bool(worst < TOL), truth=SUS, max_residual=verify.rounded(worst),
                       note=f"Yφ1 + θφ2 (shot) against the suspension's φ at {n} points (s/λ ∈ {fracs})")
        prf = verify.proof(statement=statement, holds=_is_zero(result.derived - result.printed) if not
                           isinstance(result.derived, sp.Tuple) else _is_zero(
                               [d_ - p_ for d_, p_ in zip(result.derived, result.printed)]),
                           truth_desc="symbolic proof")
        return verify.combine(num, prf, truth_desc=SUS + " + symbolic proof")
    return check


def tuple_definition_check(result, level) -> Evidence:
    """A definition holding several components: each equal to the text, exactly."""
    same = result.printed is not None and len(result.printed) == len(result.derived) and \
        _is_zero([p_ - d_ for p_, d_ in zip(result.printed_value, result.derived_value)])
    return Evidence(kind="definition", passed=bool(same), truth="a definition, compared exactly with the text")


def _eq8_rows(name, pe, dps):
    """∫_0^λ (φ − Y) ds against [Mφ']_0^λ on the suspension: (8) integrated over the blade."""
    sus = P.suspension(name, dps)
    lamv = _mp(sus.blade.length)
    for bq, tq in POSITIONS:
        be, th = mp.mpf(bq) * lamv, mp.mpf(tq)
        _, Yv, _ = sus.loads(be, th)
        lhs = sus.integrate(lambda x: sus.deflection(x, be, th)[1] - Yv)
        ends = [sus.M_at(x) * sus.deflection(x, be, th)[2] for x in (0, lamv)]
        yield (f"β={bq}λ,θ={tq}", {"Y": Yv, "theta": th, "x": lhs}, ends[1] - ends[0], lamv * abs(Yv) + abs(th) * lamv)


def eq8_check(result, level):
    """(8) integrated: ∫(φ − Y) ds = [Mφ']: quad of the suspension's φ against its end moments."""
    worst, n = mp.mpf(0), 0
    for name in PROFILES[level]:
        for lb, env, truth, scale in _eq8_rows(name, None, DPS):
            worst = max(worst, abs(env["x"] - truth) / scale)
            n += 1
    ok = sp.simplify(result.derived - (sp.Function("varphi")(s) - Y)) == 0
    return Evidence(kind="quadrature", passed=bool(worst < TOL and ok), truth=SUS + "; mpmath quad of φ − Y",
                    max_residual=verify.rounded(worst), printed_agrees=ok,
                    note=f"{n} end positions; the right side of (8) is φ − Y: {ok}")


def _shot_state_rows(fn, fracs=("0.3", "0.7", "1")):
    def rows(name, pe, dps):
        sol = P.blade_solution(name, dps)
        env = shot_env(name, dps)
        for f in fracs:
            st = sol.state(mp.mpf(f) * env["lambda"])
            yield (f"s={f}λ", env, fn(st), mp.mpf(0))
    return rows


def _quad_rows(integrand):
    def rows(name, pe, dps):
        sol = P.blade_solution(name, dps)
        env = shot_env(name, dps)
        yield ("quad", env, sol.integrate(lambda x: integrand(sol, x, env)), mp.mpf(0))
    return rows


def ends12_check(result, level):
    pairs = []
    for name in PROFILES[level]:
        sol = P.blade_solution(name, DPS)
        lamv = _mp(sol.blade.length)
        shot = (sol.phi1(0), sol.phi1(lamv), sol.phi2(0), sol.phi2(lamv))
        pairs += [(f"{name}[{i}]", mp.mpf(str(sp.N(result.derived[i], 40))), shot[i]) for i in range(4)]
    worst = max(abs(mp.mpf(f) - t) for _, f, t in pairs)
    return Evidence(kind="value", passed=bool(worst < TOL), truth=SHOT + ": φ1 = 1 + v', φ2 = w' at 0 and λ",
                    max_residual=verify.rounded(worst), printed_agrees=None)


def symmetric_check(key):
    """(20) on the symmetric blades (must hold) and on the tapered one (must fail, by > 1e-4 relative)."""
    def check(result, level):
        res = {}
        for name in P.PROFILE_NAMES:
            env = shot_env(name, DPS)
            res[name] = _resid(evaluate(result.derived_value, env), env[key], 0)
            res[name + "/printed"] = _resid(evaluate(result.printed_value, env), env[key], 0)
        sym = max(res[n_] for n_ in P.SYMMETRIC)
        psym = max(res[n_ + "/printed"] for n_ in P.SYMMETRIC)
        fails = min(res[n_] for n_ in P.UNSYMMETRIC)
        passed = sym < TOL and fails > mp.mpf("1e-4")
        note = "; ".join(f"{k}: {mp.nstr(v_, 3)}" for k, v_ in res.items() if "/" not in k)
        return Evidence(kind="value", passed=bool(passed), truth=SHOT + f" ({key} of the shot blade)",
                        max_residual=verify.rounded(sym), printed_agrees=bool(psym < TOL),
                        note=f"relative residual per blade: {note} (symmetric blades: {', '.join(P.SYMMETRIC)}; "
                             f"the unsymmetric tapered blade must fail)")
    return confirmed(check)


def _eig_n2(A) -> list:
    ev = mp.eig(A)[0]
    return sorted(mp.re(x) for x in ev)


B12 = ((beta1, lam + vl - v0), (beta2, -vl))      # (17), (22): applied to both forms where the text mixes them


def printed25() -> sp.Expr:
    """(25) as printed: g(β2θ − β)/β1."""
    return g * (beta2 * theta - beta) / beta1


def printed26() -> sp.Expr:
    """(26) as printed: g[β(a − vλ) − θ(a(λ − v0) + vλ² + β1wλ)]/β1."""
    return g * (beta * (a - vl) - theta * (a * (lam - v0) + vl**2 + beta1 * wl)) / beta1


def acceleration_matrix(r25, r26, env) -> mp.matrix:
    """−A of q'' = A q, q = (β, θ), from the right sides of (25) (β'' + aθ'') and (26) (R²θ'')."""
    cols = []
    for q in ((1, 0), (0, 1)):
        e = dict(env, beta=mp.mpf(q[0]), theta=mp.mpf(q[1]))
        tdd_ = evaluate(r26, e) / env["R"] ** 2
        cols.append((evaluate(r25, e) - env["a"] * tdd_, tdd_))
    return mp.matrix([[-cols[0][0], -cols[1][0]], [-cols[0][1], -cols[1][1]]])


def motion_check(which):
    """(25) or (26) against the suspension's equations, plus the eigenvalues of the system (25)–(26)."""
    def rows(name, pe, dps):
        sus = P.suspension(name, dps)
        env0 = env_shot(name, pe, dps)
        for bq, tq in POSITIONS:
            be, th = mp.mpf(bq) * env0["lambda"], mp.mpf(tq)
            _, Yv, Nv = sus.loads(be, th)
            av, gv = env0["a"], env0["g"]
            truth = -gv * Yv if which == 25 else gv * (av * Yv - Nv - av * th)
            yield (f"β={bq}λ,θ={tq}", dict(env0, beta=be, theta=th), truth, mp.mpf(0))

    def eigen(result, level):
        pairs = {"derived": motion(), "printed": tuple(sp.sympify(f()).subs(dict(B12)) for f in (printed25, printed26))}
        worst = {k: mp.mpf(0) for k in pairs}
        for name in PROFILES[level]:
            for pe in PENDS[level]:
                env = env_shot(name, pe, DPS)
                want = sorted((env["n^2"], env["n'^2"]))
                for key, (r25, r26) in pairs.items():
                    got = _eig_n2(acceleration_matrix(r25, r26, env))
                    worst[key] = max(worst[key], *(abs(x - y) / y for x, y in zip(got, want)))
        return Evidence(kind="value", passed=bool(worst["derived"] < TOL), truth=EIG,
                        max_residual=verify.rounded(worst["derived"]),
                        note=f"eigenvalues n² of the system (25)–(26) with shot coefficients against suspension.modes: "
                             f"max relative residual {float(worst['derived']):.3g} (derived system), "
                             f"{float(worst['printed']):.3g} (printed system)")
    return numeric_check(SUS + "; the linearised (5), (6) with its end loads", rows, extra=eigen)


def newton_check(result, level):
    """(5), (6) of this module linearised, with the suspension's end loads: 𝕄 q'' + K q = 0, its n² against
    suspension.modes (the eigenproblem)."""
    e5, e6 = (C.linearized(e) for e in (centre_of_gravity(1) / m, angular_momentum()))
    coeffs = [[e.coeff(x) for x in (bdd, tdd, Y, N, theta)] for e in (e5, e6)]
    worst = mp.mpf(0)
    for name in PROFILES[level]:
        S = P.suspension(name, DPS).stiffness
        for pe in PENDS[level]:
            env = mode_env(name, pe, DPS)
            c = [[evaluate(x, env) for x in row] for row in coeffs]
            Mm = mp.matrix([[c[i][0], c[i][1]] for i in range(2)])
            Km = mp.matrix([[c[i][2] * S[0, j] + c[i][3] * S[1, j] + c[i][4] * j for j in range(2)] for i in range(2)])
            got = _eig_n2(mp.inverse(Mm) * Km)
            want = sorted((env["n^2"], env["n'^2"]))
            worst = max(worst, *(abs(x - y) / y for x, y in zip(got, want)))
    return Evidence(kind="value", passed=bool(worst < TOL), truth=EIG + "; stiffness of the suspension",
                    max_residual=verify.rounded(worst),
                    note="the first-order parts of the derived (5), (6), with (Y, N) from the suspension's stiffness: "
                         "the n² of 𝕄q'' + Kq = 0 against suspension.modes")


def critical_check(result, level):
    """(41): a1 = −wλ is where an n² of the eigenproblem vanishes; above it both n² > 0, below it one n² < 0."""
    worst, notes, ok = mp.mpf(0), [], True
    for name in PROFILES[level]:
        sus = P.suspension(name, DPS)
        env = shot_env(name, DPS)
        with mp.workdps(sus.wdps):
            S = sus.stiffness
            a_sus = S[0, 1] * S[1, 0] / S[0, 0] - S[1, 1]        # det K(a) = 0: K linear in a
            a1v = evaluate(result.derived_value, env)
            worst = max(worst, abs(a1v - a_sus) / abs(a_sus))
            for pe in PENDS[level]:
                _, Rv, gv = pendulum(pe)
                n2s = {}
                for tag, av in (("a1", a1v), ("a1+1cm", a1v + mp.mpf("0.01")), ("a1-1cm", a1v - mp.mpf("0.01")),
                                ("a=-0.1", mp.mpf("-0.1"))):
                    n2s[tag] = _eig_n2(mp.inverse(SU.mass_matrix(av, Rv)) * SU.stiffness_matrix(sus, av, 1, gv))
                scale = gv / env["beta_1"]
                zero = min(abs(x) for x in n2s["a1"]) / scale
                ok &= bool(zero < TOL and n2s["a1"][1] > 0)
                ok &= bool(min(n2s["a1+1cm"]) > 0)
                ok &= bool(n2s["a1-1cm"][0] < 0 < n2s["a1-1cm"][1] and n2s["a=-0.1"][0] < 0 < n2s["a=-0.1"][1])
                notes.append(f"{name}/{pe}: |n²|/(g/β1) at a1 = {mp.nstr(zero, 3)}, n² at a1−1cm = "
                             f"{mp.nstr(n2s['a1-1cm'][0], 5)}, at a1+1cm = {mp.nstr(n2s['a1+1cm'][0], 5)}")
    return Evidence(kind="value", passed=bool(ok and worst < TOL), truth=EIG + "; the a where det K = 0",
                    max_residual=verify.rounded(worst), printed_agrees=None if result.printed is None else True,
                    note="; ".join(notes))


def unstable_check(result, level):
    """n°9: for a < a1, (38) holds and (39) fails: the foci of the eigenproblem at a = a1 − 1 cm."""
    ok, notes = True, []
    for name in PROFILES[level]:
        sus = P.suspension(name, DPS)
        env = shot_env(name, DPS)
        for pe in PENDS[level]:
            _, Rv, gv = pendulum(pe)
            av = -env["w_lambda"] - mp.mpf("0.01")
            md = SU.modes(sus, av, Rv, gv)
            zs = sorted(x.z for x in md)
            m38 = av + zs[0] - env["v_lambda"]
            m39 = av + zs[1] - env["v_lambda"]
            ok &= bool(m38 < 0 and m39 < 0)
            notes.append(f"{name}/{pe}: a + z' − vλ = {mp.nstr(m38, 5)}, a + z − vλ = {mp.nstr(m39, 5)}")
    return Evidence(kind="inequality", passed=bool(ok), truth=EIG + " at a = a1 − 1 cm", note="; ".join(notes))


# ================================================================ the Results
def _printed(expr):
    return lambda: expr


def _at_precision(check):
    """Run a check at 40 working digits whoever calls it (the pipeline does the same)."""
    def run(result, level):
        with mp.workdps(40):
            return check(result, level)
    return run


def specs() -> tuple[Spec, ...]:
    return tuple(dataclasses.replace(s_, check=_at_precision(s_.check)) if s_.check else s_ for s_ in _specs())


def _specs() -> list[Spec]:
    n1, n2_, n3, n4, n5, n6, n7, n8, n9 = (f"n°{i}" for i in range(1, 10))   # n2_: n2 is n²
    W16 = ((w0, vl + wl),)
    ineq = lambda desc: inequality_check(SHOT + "; " + desc, lambda name, pe, dps: shot_env(name, dps))
    ineq_modes = lambda desc: inequality_check(EIG + "; " + desc, env_shot, pend=True)
    zero = zero_check
    out = [
        # ---------------------------------------------------------------- n°1
        Spec(rid(1, "M"), "M = EI/(mg)", src(n1, "1"), "M", lambda d: EI / (m * g), printed=_printed(EI / (m * g)),
             definition=True, check=pipeline.definition_check),
        Spec(rid(2, "bending"), "M dφ/ds = N + (α − x)Y − (β − y)X (plane bending)", src(n1, "2"),
             r"M\varphi' - [N + (\alpha - x)Y - (\beta - y)X]",
             lambda d: Mf(s) * phi_(s).diff(s) - bending_moment(),
             printed=lambda: Mf(s) * phi_(s).diff(s) - (N + (alpha - x_(s)) * Y - (beta - y_(s)) * X),
             definition=True, instances=INSTANCES, check=pipeline.definition_check, note="Governing equation (bending law)."),
        Spec(rid(3, "dx"), "dx/ds = cos φ", src(n1, "3"), "x'", lambda d: sp.cos(phi_(s)),
             printed=lambda: sp.cos(phi_(s)), definition=True, instances=INSTANCES, check=pipeline.definition_check),
        Spec(rid(3, "dy"), "dy/ds = sin φ", src(n1, "3"), "y'", lambda d: sp.sin(phi_(s)),
             printed=lambda: sp.sin(phi_(s)), definition=True, instances=INSTANCES, check=pipeline.definition_check),
        Spec(rid(4, "gx"), "theorem of the centre of gravity, along Ox", src(n1, "4"),
             r"m\alpha'' - ma\theta'^2\cos\theta - ma\theta''\sin\theta - mg(1 - X)",
             lambda d: centre_of_gravity(0),
             printed=lambda: m * add - m * a * thd**2 * sp.cos(theta) - m * a * tdd * sp.sin(theta) - m * g * (1 - X),
             readings=(Reading("mαθ'^2 cos θ − mαθ'' sin θ", "m a θ'² cos θ − m a θ'' sin θ (a = AG, not α)"),),
             check=_proof("(4) ≡ m x_G'' − mg(1 − X) with x_G = α + a cos θ",
                          lambda r: r.derived - r.printed),
             note="Derived by differentiating x_G = α + a cos θ twice in t."),
        Spec(rid(5, "gy"), "theorem of the centre of gravity, along Oy", src(n1, "5"),
             r"m\beta'' - ma\theta'^2\sin\theta + ma\theta''\cos\theta + mgY",
             lambda d: centre_of_gravity(1),
             printed=lambda: m * bdd - m * a * thd**2 * sp.sin(theta) + m * a * tdd * sp.cos(theta) + m * g * Y,
             readings=(Reading("mαθ'^2 sin θ + mαθ'' cos θ", "m a θ'² sin θ + m a θ'' cos θ (a, not α)"),),
             check=confirmed(newton_check),
             note="Derived from y_G = β + a sin θ; checked with (6) against the eigenproblem of the suspension."),
        Spec(rid(6, "moment"), "theorem of the angular momentum about G", src(n1, "6"),
             r"\frac{R^2}{g}\theta'' + N - a(Y\cos\theta - X\sin\theta)",
             lambda d: angular_momentum(),
             printed=lambda: R**2 / g * tdd - (-N + a * (Y * sp.cos(theta) - X * sp.sin(theta))),
             check=confirmed(newton_check),
             note="Derived: moment about G of the couple −mgN and of (−mgX, −mgY) applied at A − G = −a(cos θ, sin θ)."),
        # ---------------------------------------------------------------- n°2
        Spec(rid(7, "dbending"), "d/ds(Mφ') = X sin φ − Y cos φ", src(n2_, "7"), r"\frac{d}{ds}(M\varphi')",
             lambda d: differentiated_bending(), printed=lambda: X * sp.sin(phi_(s)) - Y * sp.cos(phi_(s)),
             instances=INSTANCES, check=_proof("d/ds of the right side of (2), with (3), minus the printed right side of (7)",
                          lambda r: r.derived - r.printed)),
        Spec(rid(8, "linear"), "d/ds(Mφ') = φ − Y (small oscillations)", src(n2_, "8"), r"\frac{d}{ds}(M\varphi')",
             lambda d: linearised_bending(), printed=lambda: phi_(s) - Y, instances=INSTANCES, check=confirmed(eq8_check),
             note="First-order part of (7) with φ, Y = O(ε), X = 1 + O(ε²)."),
        Spec(rid(9, "v"), "M v'' − v = 0", src(n2_, "9"), "Mv'' - v", lambda d: Mf(s) * v(s).diff(s, 2) - v(s),
             printed=lambda: Mf(s) * v(s).diff(s, 2) - v(s), definition=True, instances=INSTANCES, check=pipeline.definition_check),
        Spec(rid(10, "bc"), "v'_0 = v'_λ = −1, w'_0 = 0, w'_λ = 1", src(n2_, "10"), r"(v'_0, v'_\lambda, w'_0, w'_\lambda)",
             lambda d: sp.Tuple(*BC10.values()), printed=lambda: sp.Tuple(-1, -1, 0, 1), definition=True,
             check=tuple_definition_check),
        Spec(rid(11, "phi12"), "φ1 = 1 + v', φ2 = w'", src(n2_, "11"), r"(\varphi_1, \varphi_2)",
             lambda d: sp.Tuple(1 + v(s).diff(s), w(s).diff(s)), printed=lambda: sp.Tuple(1 + v(s).diff(s), w(s).diff(s)),
             definition=True, check=tuple_definition_check),
        Spec(rid(12, "ends"), "φ10 = φ1λ = 0, φ20 = 0, φ2λ = 1", src(n2_, "12"),
             r"(\varphi_{10}, \varphi_{1\lambda}, \varphi_{20}, \varphi_{2\lambda})", lambda d: phi_end_values(),
             printed=lambda: sp.Tuple(0, 0, 0, 1), check=confirmed(ends12_check),
             note="Checked on the shot φ1, φ2 (a check of the shooting against (10)–(11))."),
        Spec(rid(13, "phi"), "φ = Yφ1 + θφ2", src(n2_, "13"), r"\varphi", lambda d: Y * phi1 + theta * phi2,
             printed=lambda: Y * phi1 + theta * phi2,
             check=numeric_check(SUS + ": its φ(s) for the end position (0.3λ, −0.7) and its end load Y",
                                 rows_deflection(1), pend=False),
             note="Y·φ1(s) + θ·φ2(s) with the shot φ1, φ2 against the directly solved φ(s), at s = 0, 0.37λ, 0.81λ, λ "
                  "(so also φ_0 = 0, φ_λ = θ)."),
        Spec(rid(13, "satisfies8"), "φ = Yφ1 + θφ2 satisfies (8) for all Y, θ", src(n2_, "13"),
             r"\frac{d}{ds}(M\varphi') - (\varphi - Y)", lambda d: eq8_residual(), printed=_printed(sp.S.Zero),
             check=confirmed(phi_numeric(("0.37", "0.81"),
                                         "d/ds(Mφ') − (φ − Y) = 0 for φ = Y(1 + v') + θw' with Mv'' = v, Mw'' = w")),
             note="'On vérifie aisément que cette fonction satisfait à l'équation (8)': symbolic proof, and the shot φ "
                  "against the directly solved blade at interior points."),
        Spec(rid(13, "phi_ends"), "φ_0 = 0, φ_λ = θ", src(n2_, "13"), r"(\varphi_0, \varphi_\lambda)",
             lambda d: phi_ends(), printed=_printed(sp.Tuple(0, theta)),
             check=confirmed(phi_numeric(("0", "1"), "φ(0) = 0 and φ(λ) = θ from (10), (11), (13)")),
             note="Numerically: Yφ1 + θφ2 of the shot blade at s = 0, λ against the suspension's φ."),
        Spec(rid(14, "phip"), "φ' = (Yv + θw)/M", src(n2_, "14"), r"\varphi'",
             lambda d: phi_prime().subs({v(s): v_s, w(s): w_s, Mf(s): M_s}),
             printed=lambda: (Y * v_s + theta * w_s) / M_s, readings=(READ_VW,),
             check=numeric_check(SUS + ": its φ'(s) for the end position (0.3λ, −0.7)", rows_deflection(2), pend=False),
             note="v_s, w_s, M_s stand for v(s), w(s), M(s)."),
        # ---------------------------------------------------------------- n°3
        Spec(rid(15, "wronskian"), "v w' − w v' = w0", src(n3, "15"), r"vw' - wv'",
             lambda d: C.wronskian_constant(), printed=_printed(w0), readings=(READ_VW,),
             check=numeric_check(SHOT + ": v w' − w v' at s = 0.3λ, 0.7λ, λ", _shot_state_rows(
                 lambda st: st[0] * st[3] - st[2] * st[1]), pend=False,
                 extra=_proof("d/ds(vw' − wv') = 0 by (9)", lambda r: C.wronskian_derivative())),
             note="Derived: d/ds(vw' − wv') = vw'' − wv'' = 0 by (9) (ch1_model), the constant at s = 0 by (10)."),
        Spec(rid(16, "w0"), "vλ + wλ = w0", src(n3, "16"), "w_0", lambda d: C.wronskian_at_lambda(),
             printed=_printed(vl + wl), readings=(READ_VW,),
             check=numeric_check(SHOT + ": w(0)", lambda name, pe, dps: iter(
                 [("w0", shot_env(name, dps), shot_env(name, dps)["w_0"], mp.mpf(0))]), pend=False)),
        Spec(rid(17, "v0_pos"), "v0 > 0", src(n3, "17"), "v_0 > 0", lambda d: C.ends(v(0)), printed=_printed(v0),
             readings=(READ_VW,), check=ineq("v0")),
        Spec(rid(17, "w0_pos"), "w0 > 0", src(n3, "17"), "w_0 > 0", lambda d: C.ends(w(0)), printed=_printed(w0),
             readings=(READ_VW,), check=ineq("w0")),
        Spec(rid(17, "wl_gt_w0"), "wλ > w0", src(n3, "17"), r"w_\lambda - w_0 > 0", lambda d: C.ends(w(lam) - w(0)),
             printed=_printed(wl - w0), readings=(READ_VW,), check=ineq("wλ − w0")),
        Spec(rid(17, "beta1_pos"), "β1 = λ + vλ − v0 > 0", src(n3, "17"), r"\beta_1 > 0", lambda d: C.beta1_def(),
             printed=_printed(lam + vl - v0), readings=(READ_VW,), check=ineq("β1")),
        Spec(rid(17, "vl_neg"), "vλ < 0", src(n3, "17"), r"-v_\lambda > 0", lambda d: -C.ends(v(lam)),
             printed=_printed(-vl), readings=(READ_VW,), check=ineq("−vλ")),
        Spec(rid(17, "beta1_lt"), "β1 < λ", src(n3, "17"), r"\lambda - \beta_1 > 0",
             lambda d: sp.expand(lam - C.beta1_def()), printed=_printed(lam - (lam + vl - v0)), check=ineq("λ − β1")),
        Spec(rid(17, "v0_lt"), "v0 < λ", src(n3, "17"), r"\lambda - v_0 > 0", lambda d: lam - C.ends(v(0)),
             printed=_printed(lam - v0), readings=(READ_VW,), check=ineq("λ − v0")),
        Spec(rid(17, "vl_gt"), "−vλ < λ", src(n3, "17"), r"\lambda + v_\lambda > 0", lambda d: lam + C.ends(v(lam)),
             printed=_printed(lam + vl), readings=(READ_VW,), check=ineq("λ + vλ")),
        Spec(rid(18, "integral"), "v0/w0 − vλ/wλ = ∫ w0/w² ds", src(n3, "18"), r"\int_0^\lambda w_0/w^2\,ds",
             lambda d: ratio_integral(), printed=_printed(v0 / w0 - vl / wl), readings=(READ_VW,),
             check=numeric_check(SHOT + "; mpmath quad of w0/w²", _quad_rows(
                 lambda sol, x, env: env["w_0"] / sol.w(x) ** 2), pend=False),
             note="The equality before (18): derived from (15), d/ds(v/w) = −w0/w²."),
        Spec(rid(18, "step0"), "v0/w0 − vλ/wλ > λw0/wλ²", src(n3, "18"),
             r"\frac{v_0}{w_0} - \frac{v_\lambda}{w_\lambda} - \frac{\lambda w_0}{w_\lambda^2} > 0",
             lambda d: ratio_integral() - lam * w0 / wl**2, printed=_printed(v0 / w0 - vl / wl - lam * w0 / wl**2),
             readings=(READ_VW,), check=ineq("v0/w0 − vλ/wλ − λw0/wλ²")),
        Spec(rid(18, "first"), "β1wλ + vλ² < −λvλ(1 + w0/wλ)", src(n3, "18"),
             r"-\lambda v_\lambda(1 + w_0/w_\lambda) - (\beta_1 w_\lambda + v_\lambda^2) > 0",
             lambda d: sp.expand((ratio_integral() - lam * w0 / wl**2) * w0 * wl).subs(v0, lam + vl - beta1),
             printed=_printed(-lam * vl * (1 + w0 / wl) - (beta1 * wl + vl**2)), defs=W16, readings=(READ_VW,),
             check=ineq("the first inequality of (18)"),
             note="Derived: the inequality before (18) times w0wλ, with (16) (w0 = vλ + wλ, applied to both forms) "
                  "and β1 of (17)."),
        Spec(rid(18, "second"), "−λvλ(1 + w0/wλ) < −2λvλ", src(n3, "18"),
             r"-2\lambda v_\lambda + \lambda v_\lambda(1 + w_0/w_\lambda) > 0",
             lambda d: sp.factor(-2 * lam * vl + lam * vl * (1 + w0 / wl)),
             printed=_printed(-2 * lam * vl - (-lam * vl * (1 + w0 / wl))), readings=(READ_VW,),
             check=ineq("the second inequality of (18)")),
        Spec(rid(18, "third"), "−2λvλ < 2λ²", src(n3, "18"), r"2\lambda^2 + 2\lambda v_\lambda > 0",
             lambda d: sp.factor(2 * lam**2 + 2 * lam * vl), printed=_printed(2 * lam**2 - (-2 * lam * vl)),
             readings=(READ_VW,), check=ineq("the third inequality of (18)")),
        Spec(rid(19, "unit"), "∫ w/M ds = 1", src(n3, "19"), r"\int_0^\lambda w/M\,ds", lambda d: unit_integral(),
             printed=_printed(sp.S.One), readings=(READ_VW,),
             check=numeric_check(SHOT + "; mpmath quad of w/M", _quad_rows(lambda sol, x, env: sol.w(x) / sol.M_at(x)),
                                 pend=False)),
        Spec(rid(19, "M1"), "M1 < λwλ", src(n3, "19"), r"\lambda w_\lambda - M_1 > 0", lambda d: lam * wl - M1,
             printed=_printed(lam * wl - M1), readings=(READ_VW,), check=ineq("λwλ − min M")),
        Spec(rid(19, "M2"), "M2 > λw0", src(n3, "19"), r"M_2 - \lambda w_0 > 0", lambda d: M2 - lam * w0,
             printed=_printed(M2 - lam * w0), readings=(READ_VW,), check=ineq("max M − λw0")),
        Spec(rid(19, "lower"), "λw0/μ < M (at the minimum M1 of M)", src(n3, "19"), r"M_1 - \lambda w_0/\mu > 0",
             lambda d: sp.expand((M2 - lam * w0) / mu), printed=_printed(M1 - lam * w0 / mu), defs=((M2, mu * M1),),
             readings=(READ_VW,), check=ineq("min M − λw0/μ")),
        Spec(rid(19, "upper"), "M < λμwλ (at the maximum M2 of M)", src(n3, "19"), r"\lambda\mu w_\lambda - M_2 > 0",
             lambda d: sp.expand(mu * (lam * wl - M1)), printed=_printed(lam * mu * wl - M2), defs=((M2, mu * M1),),
             readings=(READ_VW,), check=ineq("λμwλ − max M")),
        # ---------------------------------------------------------------- n°4
        Spec(rid(20, "vl"), "vλ = −v0 (symmetric blade)", src(n4, "20"), r"v_\lambda", lambda d: symmetric_vl(),
             printed=_printed(-v0), readings=(READ_VW,), check=symmetric_check("v_lambda")),
        Spec(rid(20, "beta1"), "β1 = λ − 2v0 (symmetric blade)", src(n4, "20"), r"\beta_1",
             lambda d: symmetric_beta1(), printed=_printed(lam - 2 * v0), readings=(READ_VW,),
             check=symmetric_check("beta_1")),
        Spec(rid(20, "wl"), "wλ = w0 + v0 (symmetric blade)", src(n4, "20"), r"w_\lambda", lambda d: symmetric_wl(),
             printed=_printed(w0 + v0), readings=(READ_VW,), check=symmetric_check("w_lambda")),
        # ---------------------------------------------------------------- n°5
        Spec(rid(21, "beta"), "β = ∫φ ds = Yβ1 + θβ2", src(n5, "21"), r"\beta", lambda d: C.beta_integral(),
             printed=_printed(Y * beta1 + theta * beta2), defs=((beta1, lam + vl - v0), (beta2, wl - w0)),
             check=numeric_check(SUS + ": β for its end load Y", rows_loads("beta"), pend=False)),
        Spec(rid(22, "beta1"), "β1 = λ + vλ − v0", src(n5, "22"), r"\beta_1", lambda d: C.beta1_def(),
             printed=_printed(lam + vl - v0), readings=(READ_VW,),
             check=numeric_check(SUS + ": β1 = 1/(∂Y/∂β)", rows_loads("beta1"), pend=False)),
        Spec(rid(22, "beta2"), "β2 = wλ − w0", src(n5, "22"), r"\beta_2", lambda d: C.beta_integral().coeff(theta),
             printed=_printed(wl - w0), readings=(READ_VW,),
             check=numeric_check(SUS + ": β2 = −(∂Y/∂θ)/(∂Y/∂β)", rows_loads("beta2"), pend=False)),
        Spec(rid(22, "beta2_vl"), "β2 = −vλ", src(n5, "22"), r"\beta_2", lambda d: C.beta2_def(),
             printed=_printed(-vl), readings=(READ_VW,),
             check=numeric_check(SUS + ": β2 = −(∂Y/∂θ)/(∂Y/∂β)", rows_loads("beta2"), pend=False)),
        Spec(rid(23, "Y"), "Y = (β + θvλ)/β1", src(n5, "23"), "Y", lambda d: C.Y_of_end(),
             printed=_printed((beta + theta * vl) / beta1), readings=(READ_VW,),
             check=numeric_check(SUS + ": its end load Y", rows_loads("Y"), pend=False)),
        Spec(rid(24, "N_Y"), "N = M_λφ'_λ = Yvλ + θwλ", src(n5, "24"), "N",
             lambda d: C.ends((Mf(lam) * phi_prime().subs(s, lam))), printed=_printed(Y * vl + theta * wl),
             readings=(READ_VW,), check=numeric_check(SUS + ": its end couple N", rows_loads("N"), pend=False)),
        Spec(rid(24, "N"), "N = (βvλ + θ(vλ² + β1wλ))/β1", src(n5, "24"), "N", lambda d: C.N_of_end(),
             printed=_printed((beta * vl + theta * (vl**2 + beta1 * wl)) / beta1), readings=(READ_VW,),
             check=numeric_check(SUS + ": its end couple N", rows_loads("N"), pend=False)),
        # ---------------------------------------------------------------- n°6
        Spec(rid(25, "motion"), "β'' + aθ'' = g(β2θ − β)/β1", src(n6, "25"), r"\beta'' + a\theta''",
             lambda d: motion()[0], printed=printed25, defs=B12,
             check=motion_check(25)),
        Spec(rid(26, "motion"), "R²θ'' = g[β(a − vλ) − θ(a(λ − v0) + vλ² + β1wλ)]/β1", src(n6, "26"), r"R^2\theta''",
             lambda d: motion()[1],
             printed=printed26, defs=B12, readings=(READ_VW,), check=motion_check(26),
             note="β1 = λ + vλ − v0 (17) applied to both forms for the comparison."),
        # ---------------------------------------------------------------- n°7
        Spec(rid(27, "y"), "y = β + (a + z)θ", src(n7, "27"), "y", lambda d: beta + (a + z) * theta,
             printed=_printed(beta + (a + z) * theta), definition=True, check=pipeline.definition_check),
        Spec(rid(28, "focal"), "(n²/g)β1 = 1 − (z/R²)(a − vλ)", src(n7, "28"),
             r"\frac{n^2}{g}\beta_1 - 1 + \frac{z}{R^2}(a - v_\lambda)", lambda d: focal_conditions()[0],
             printed=_printed(n2 / g * beta1 - (1 - z / R**2 * (a - vl))),
             check=zero(EIG + ": each focus z with the n² of the mode whose node is the other focus",
                        swap=True)),
        Spec(rid(29, "focal"), "(n²/g)(a + z)β1 = −β2 + (z/R²)[a(λ − v0) + vλ² + β1wλ]", src(n7, "29"),
             r"\frac{n^2}{g}(a + z)\beta_1 + \beta_2 - \frac{z}{R^2}[\dots]",
             lambda d: sp.expand(-focal_conditions()[1]),
             printed=_printed(n2 / g * (a + z) * beta1 - (-beta2 + z / R**2 * (a * (lam - v0) + vl**2 + beta1 * wl))),
             defs=B12, readings=(Reading("b_1 w_λ (in the line before (28))", "β1 wλ"),),
             check=zero(EIG + ": each focus z with the n² of the mode whose node is the other focus",
                        swap=True),
             note="Derived as the negative of ch1_model.focal_conditions()[1] (the same condition = 0)."),
        Spec(rid(30, "quadratic"), "z² + z(a² + aλ − R² − a(v0 + vλ) + vλ² + β1wλ)/(a − vλ) − R² = 0",
             src(n7, "30"), r"z^2 + z\frac{\dots}{a - v_\lambda} - R^2", lambda d: foci_quadratic().as_expr(),
             printed=_printed(z**2 + z * (a**2 + a * lam - R**2 - a * (v0 + vl) + vl**2 + beta1 * wl) / (a - vl) - R**2),
             defs=((beta1, lam + vl - v0),), readings=(READ_VW,),
             check=zero(EIG + ": both foci (nodes of the modes) are roots", swap=True),
             note="Monic quadratic in z: coefficients compared with (17) applied."),
        Spec(rid(31, "product"), "zz' = −R²", src(n7, "31"), "zz'", lambda d: vieta()[0], printed=_printed(-R**2),
             check=numeric_check(EIG + ": product of the nodes of the two modes",
                                 rows_modes(lambda e: e["z"] * e["z'"]))),
        Spec(rid(32, "sum"), "(a − vλ)(z + z') + a² + aλ − R² − a(v0 + vλ) + vλ² + β1wλ = 0", src(n7, "32"),
             r"(a - v_\lambda)(z + z') + \dots", lambda d: sum_relation(),
             printed=_printed((a - vl) * (z + zp) + a**2 + a * lam - R**2 - a * (v0 + vl) + vl**2 + beta1 * wl),
             defs=((beta1, lam + vl - v0),), readings=(READ_VW,),
             check=zero(EIG + ": z, z' = nodes of the two modes")),
        Spec(rid(33, "shifted"), "(a + z − vλ)(a + z' − vλ) = −β1(a + wλ)", src(n7, "33"),
             r"(a + z - v_\lambda)(a + z' - v_\lambda)", lambda d: product_shifted(),
             printed=_printed(-beta1 * (a + wl)), readings=(READ_VW,),
             check=numeric_check(EIG + ": (a + z − vλ)(a + z' − vλ) with the nodes of the two modes",
                                 rows_modes(lambda e: (e["a"] + e["z"] - e["v_lambda"]) * (e["a"] + e["z'"] - e["v_lambda"])))),
        # ---------------------------------------------------------------- n°8
        Spec(rid(34, "n2"), "n² = −Kg/z'", src(n8, "34"), "n^2", lambda d: n2_of_focus(),
             printed=_printed(-K * g / zp), defs=((K, -(a + zp - vl) / beta1),),
             check=numeric_check(EIG + ": n² of the principal mode (node z' = F')", rows_modes(lambda e: e["n^2"])),
             note="K of (35) applied to the printed form."),
        Spec(rid(35, "K"), "K = −(a + z' − vλ)/β1", src(n8, "35"), "K", lambda d: K_of_zp(),
             printed=_printed(-(a + zp - vl) / beta1), readings=(READ_VW,),
             check=numeric_check(EIG + ": K = −n²z'/g of the principal mode", rows_modes(lambda e: -e["n^2"] * e["z'"] / e["g"]))),
        Spec(rid(36, "K"), "K = (a + wλ)/(a + z − vλ)", src(n8, "36"), "K", lambda d: K_of_z(),
             printed=_printed((a + wl) / (a + z - vl)), readings=(READ_VW,),
             check=numeric_check(EIG + ": K = −n²z'/g of the principal mode", rows_modes(lambda e: -e["n^2"] * e["z'"] / e["g"]))),
        Spec(rid(37, "KKp"), "KK' = −(a + wλ)/β1", src(n8, "37"), "KK'", lambda d: K_product(),
             printed=_printed(-(a + wl) / beta1), readings=(READ_VW,),
             check=numeric_check(EIG + ": K = −n²z'/g, K' = −n'²z/g of the two modes",
                                 rows_modes(lambda e: e["n^2"] * e["z'"] * e["n'^2"] * e["z"] / e["g"] ** 2))),
        # ---------------------------------------------------------------- n°9
        Spec(rid(38, "upper"), "a + z' − vλ < 0", src(n9, "38"), r"-(a + z' - v_\lambda) > 0",
             lambda d: sp.expand(K_of_zp() * beta1), printed=_printed(-(a + zp - vl)), readings=(READ_VW,),
             check=ineq_modes("−(a + z' − vλ) with the node z' of the principal mode"),
             note="Derived as β1K (35): K > 0 with β1 > 0."),
        Spec(rid(39, "lower"), "a + z − vλ > 0", src(n9, "39"), r"a + z - v_\lambda > 0",
             lambda d: sp.expand(-K_of_zp().subs(zp, z) * beta1), printed=_printed(a + z - vl), readings=(READ_VW,),
             check=ineq_modes("a + z − vλ with the node z of the parasitic mode"),
             note="Derived as −β1K' (K' of (35) with z' → z): K' < 0."),
        Spec(rid(40, "a_wl"), "a + wλ > 0", src(n9, "40"), r"a + w_\lambda > 0",
             lambda d: sp.cancel(-product_shifted() / beta1), printed=_printed(a + wl), readings=(READ_VW,),
             check=ineq_modes("a + wλ"), note="Derived from (33): −(38)·(39)/β1."),
        Spec(rid(41, "a1"), "a1 = −wλ (critical distance)", src(n9, "41"), "a_1", lambda d: critical_distance(),
             printed=_printed(-wl), readings=(READ_VW,), check=confirmed(critical_check),
             note="Truth: the a at which det K(a) = 0 for the suspension's stiffness (an n² crosses 0); n² signs "
                  "at a1 ± 1 cm and at a = −0.1 m."),
        Spec(rid(41, "unstable"), "for a < a1, (38) holds and (39) fails", src(n9, "41"),
             r"a < a_1:\ a + z' - v_\lambda < 0,\ a + z - v_\lambda < 0", lambda d: product_shifted(),
             check=confirmed(unstable_check), note="The derived form is (33); for a < a1 both factors are negative."),
        Spec(rid(41, "below_vl"), "−wλ < vλ", src(n9, "41"), r"v_\lambda + w_\lambda > 0",
             lambda d: C.wronskian_at_lambda(), printed=_printed(vl - (-wl)), readings=(READ_VW,),
             check=ineq("vλ + wλ (= w0 by (16))")),
    ]
    return tuple(out)
