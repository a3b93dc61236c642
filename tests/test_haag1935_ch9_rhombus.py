"""Haag 1935, chapter IX, n°107–110: the rhombus hole (ch9_holes.rhombus_*)."""
import mpmath as mp
import pytest
import sympy as sp

from derivations.haag1935.ch9_holes import rhombus_derivation as derivation, rhombus_printed as printed
from derivations.haag1935.ch9_holes import rhombus_table_ends, rhombus_table_functions, rhombus_truth as truth
from pendsym import verify

CASE = ("1/2", "3/5", "6/5")


@pytest.fixture(scope="module")
def shot():
    return truth.shot(*CASE, 30)


def value(expr, env, defs=()):
    with mp.workdps(40):
        return verify.value_at(sp.sympify(expr).subs(dict(defs)), env)


def test_bessel_equation_from_9():
    V, x = derivation.V, derivation.x
    assert sp.simplify(derivation.bessel_equation() - (V(x).diff(x, 2) - V(x).diff(x) / x + V(x))) == 0
    assert sp.simplify(derivation.transformed_equation(-1) - derivation.bessel_equation()) == 0


def test_general_solution_spans_neumann_basis():
    sol = derivation.general_solution()
    assert sol.has(derivation.A) and sol.has(derivation.B)
    x = derivation.x
    assert sp.simplify(sol.diff(x, 2) - sol.diff(x) / x + sol) == 0


def test_wronskian_fixes_the_convention():
    """Neumann's Y gives 1/x (Haag's footnote); today's Y gives 2/(πx)."""
    env = {"x": "2.7"}
    with mp.workdps(40):
        x = mp.mpf("2.7")
        assert abs(value(derivation.wronskian(), env) - 1 / x) < mp.mpf("1e-35")
        assert abs(value(derivation.wronskian(second=sp.bessely), env) - 2 / (mp.pi * x)) < mp.mpf("1e-35")


def test_ends_against_the_shot_blade(shot):
    env = truth.environment(*CASE)
    assert abs(value(derivation.v_end(), env) - shot.v0) < mp.mpf("1e-25")
    assert abs(value(derivation.w_end("0"), env) - shot.w0) < mp.mpf("1e-25")
    assert abs(value(derivation.w_end("l"), env) - shot.wl) < mp.mpf("1e-25")
    # the printed w_0 under today's Y is off by the factor (π/2)²: the convention matters
    today = printed.w0_end().subs(dict(printed.DEFS)).subs(derivation.NEUMANN_SHIFT, 0).replace(
        lambda e: e.func == sp.bessely, lambda e: 2 / sp.pi * e)
    with mp.workdps(40):
        assert abs(value(today, env) / shot.w0 - (mp.pi / 2) ** 2) < mp.mpf("1e-20")


def test_G2_derived_matches_and_346_does_not(shot):
    env = truth.environment(*CASE)
    G2 = truth.G2(shot)
    assert abs(value(derivation.G2_final(), env) - G2) < mp.mpf("1e-25")
    assert abs(value(printed.G2_346(), env, printed.DEFS) / G2 - 1) > 0.5


def test_corrected_346_agrees_with_the_truth(shot):
    """(346) with 2x_1², 1/k + λ/2 for ω²/k and kx_1/(4ω²) for ½: the form the derivation gives."""
    D, Dp, D1, D1p = derivation.D_symbols()
    k, om, x0, x1, lam = derivation.k, derivation.omega, derivation.x0, derivation.x1, sp.Symbol("lambda", positive=True)
    corrected = (k / (8 * om**2 * D**2 * Dp**2) * (1 / x0**2 + 2 * x1**2 * D * Dp * D1 * D1p - D**2 - Dp**2)
                 + 1 / k + lam / 2 - k * x1 / (4 * om**2) * (D1 / D + D1p / Dp))
    env = truth.environment(*CASE)
    assert abs(value(corrected, env, printed.DEFS) - truth.G2(shot)) < mp.mpf("1e-25")


def test_346_is_haags_own_line_only_with_x1():
    """Haag's intermediate G_2 with (343) and (345) gives (346) with 2x_1², not the 2x_0² of the text."""
    env = truth.environment(*CASE)
    w0, wl = derivation.half_symbols()[:2]
    line = printed.G2_intermediate().subs({w0: printed.w0_end(), wl: printed.wl_end()})
    with_x1 = printed.G2_346().subs(derivation.x0**2 * sp.Symbol("D", real=True), sp.Symbol("X")).subs(
        sp.Symbol("X"), derivation.x1**2 * sp.Symbol("D", real=True))
    assert abs(value(line - with_x1, env, printed.DEFS)) < mp.mpf("1e-25")
    assert abs(value(line - printed.G2_346(), env, printed.DEFS)) > mp.mpf("1e-3")


def test_G2_is_a_length_and_346_is_not():
    """Scaling every length by c (λ → cλ, k → k/c, ω → ω/c; x_0, x_1 fixed) scales G_2 by c."""
    env = truth.environment(*CASE)
    with mp.workdps(60):
        scaled = dict(env, omega=env["omega"] / 3, k=env["k"] / 3, **{"lambda": env["lambda"] * 3})
    derived = derivation.G2_final()
    assert abs(value(derived, scaled) / value(derived, env) - 3) < mp.mpf("1e-25")
    form = printed.G2_346().subs(dict(printed.DEFS))
    assert abs(value(form, scaled) / value(form, env) - 3) > 0.1


def test_primitive_of_v2_over_x():
    val, der = sp.symbols("v v'", real=True)
    x = derivation.x
    F = derivation.integral_identity()
    assert sp.simplify(F - printed.integral_identity()) == 0
    dF = sp.diff(F, val) * der + sp.diff(F, der) * (der / x - val) + sp.diff(F, x)
    assert sp.simplify(dF - val**2 / x) == 0


def test_middle_condition_sign():
    """dw/ds continuous at s = 0 gives −(A'J_0 + B'Y_0), not the printed −A'J_0 + B'Y_0."""
    diff = sp.simplify(derivation.middle_slope() - printed.middle_slope())
    assert diff != 0 and sp.simplify(diff + 2 * derivation.B1 * derivation.Y(0, derivation.x0)) == 0


def test_tables_have_ids_and_checks():
    specs = rhombus_table_functions.specs() + rhombus_table_ends.specs()
    ids = [s.id for s in specs]
    assert len(ids) == len(set(ids)) and all(i.startswith("haag1935.eq3") for i in ids)
    assert all(s.check is not None for s in specs)
