"""Haag 1935, chapter IX, n°104–106: the rectangular hole (ch9_holes.rectangle_*)."""
import mpmath as mp
import pytest
import sympy as sp

from derivations.haag1935.ch9_holes import limits, rectangle_derivation as derivation, rectangle_printed as printed
from derivations.haag1935.ch9_holes import rectangle_table, rectangle_truth as truth
from derivations.haag1935.symbols import omega
from pendsym import verify

ASYMMETRIC = ("4/5", "1", "3/2", "1/5", "1/2")


@pytest.fixture(scope="module")
def shot():
    return truth.shot(ASYMMETRIC, 30)


def value(expr, env, defs=()):
    with mp.workdps(40):
        return verify.value_at(sp.sympify(expr).subs(dict(defs)), env)


def test_pieces_solve_the_inverted_blade():
    s = derivation.s
    first, middle, last = derivation.pieces()
    assert sp.simplify(first.diff(s, 2) / omega**2 + first) == 0
    assert sp.simplify(middle.diff(s, 2) / derivation.omega_p**2 + middle) == 0
    assert sp.simplify(last.diff(s, 2) / omega**2 + last) == 0


def test_D_is_sin_omega_lambda_without_hole():
    lam = sp.Symbol("lambda", positive=True)
    assert sp.simplify(derivation.denominator().subs(derivation.p, 0) - sp.sin(omega * lam)) == 0


def test_ends_and_G2_against_the_shot_blade(shot):
    env = truth.environment(ASYMMETRIC)
    assert abs(value(derivation.end_value("v", "0"), env) - shot.v0) < mp.mpf("1e-25")
    assert abs(value(derivation.end_value("v", "l"), env) - shot.vl) < mp.mpf("1e-25")
    assert abs(value(derivation.end_value("w", "l"), env) - shot.wl) < mp.mpf("1e-25")
    G2 = truth.G2(shot)
    assert abs(value(derivation.G2(), env) - G2) < mp.mpf("1e-25")
    assert abs(value(printed.G2_333(), env, printed.definition()) - G2) < mp.mpf("1e-25")


def test_a_wrong_sign_in_333_is_caught(shot):
    """The check can fail: (333) with the sign of its last term flipped misses the truth."""
    env = truth.environment(ASYMMETRIC)
    wrong = printed.G2_333()
    D = printed.D
    term = sp.sin(derivation.omega_p * derivation.p) ** 2 / (2 * D**2)
    assert abs(value(wrong + term, env, printed.definition()) - truth.G2(shot)) > mp.mpf("1e-3")


def test_no_hole_gives_the_uniform_blade():
    for name in ("v0", "w0", "wl"):
        form = derivation.end_value(name[0], name[1:])
        assert verify.exactly_equal(form.subs(derivation.p, 0), limits.uniform(name))


def test_stability_grid_is_inside_the_bounds():
    points = list(truth.stability_points("quick", 30))
    assert points
    for _, env in points:
        assert env["omega"] * env["lambda"] < sp.pi / 2 and env["omega'"] * env["p"] < sp.pi / 2
        assert env["lambda"] - env["s_0"] - env["p"] == env["s_0"]


def test_narrow_hole_makes_a1_negative():
    """The footnote's bounds do not give a_1 = −w_λ > 0: ωλ = 0.3, ω'p = 1, p = 0.3λ."""
    env = {"omega": sp.Rational(3, 10), "omega'": sp.Rational(10, 3), "lambda": 1, "s_0": sp.Rational(7, 20),
           "p": sp.Rational(3, 10)}
    assert value(derivation.end_value("w", "l"), env) > 0


def test_table_ids_unique_and_checked():
    specs = rectangle_table.specs()
    ids = [s.id for s in specs]
    assert len(ids) == len(set(ids)) and all(s.check is not None for s in specs)
