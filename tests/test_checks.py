"""pendsym.checks, the one check engine: each kind passes the right formula and rejects a wrong one."""
import mpmath as mp
import pytest
import sympy as sp

from pendsym import checks, verify
from pendsym.checks import Point
from pendsym.result import Evidence, Result, Source, Spec

x, y, eps = sp.symbols("x y epsilon", positive=True)


def result(derived, printed=None) -> Result:
    spec = Spec("toy.test", "a test form", Source("toy", "n°0"), "f", lambda deps: derived,
                printed=None if printed is None else (lambda: printed))
    return Result(spec, derived, printed)


def fixed(*points):
    return lambda level, dps: list(points)


def test_values_compares_derived_and_printed_and_confirms():
    check = checks.Values("x²", fixed(Point("p", {"x": mp.mpf(3)}, 9)), confirm=lambda dps: {"t": mp.mpf(9)})
    ev = checks.run(check, result(x**2, x * x), "quick")
    assert ev.passed and ev.printed_agrees and ev.max_residual == 0 and ev.confirm_digits >= checks.MIN_DIGITS
    ev = checks.run(check, result(x**2, x**2 + 1e-20), "quick")
    assert ev.passed and ev.printed_agrees is False
    assert not checks.run(check, result(x**2 + 1e-20), "quick").passed


def test_an_unstable_truth_fails_the_confirmation():
    check = checks.Values("x", fixed(Point("p", {"x": mp.mpf(3)}, 3)),
                          confirm=lambda dps: {"t": mp.mpf(3) + mp.mpf(10) ** -20 * dps})
    assert not checks.run(check, result(x), "quick").passed


def test_values_of_a_tuple_form_compare_each_component():
    form = sp.Tuple(x, 2 * x)
    right = checks.Values("x, 2x", fixed(Point("a", {"x": mp.mpf(3)}, 3, 1, component=0),
                                         Point("b", {"x": mp.mpf(3)}, 6, 1, component=1)))
    wrong = checks.Values("x, 2x", fixed(Point("b", {"x": mp.mpf(3)}, 7, 1, component=1)))
    assert checks.run(right, result(form, form), "quick").passed
    assert not checks.run(wrong, result(form), "quick").passed


def test_a_vanishing_form_is_measured_against_its_terms():
    point = Point("p", {"x": mp.mpf(5), "y": mp.mpf(5)}, 0, denom="terms")
    ev = checks.run(checks.Values("x = y", fixed(point)), result(x**2 - y**2, (x - y) * (x + y)), "quick")
    assert ev.passed and ev.printed_agrees
    off = Point("p", {"x": mp.mpf(5), "y": mp.mpf("5.001")}, 0, denom="terms")
    assert not checks.run(checks.Values("x = y", fixed(off)), result(x**2 - y**2), "quick").passed
    assert checks.terms_scale(x - y, {"x": mp.mpf(2), "y": mp.mpf(3)}) == 5


def test_a_counterexample_must_miss_its_truth():
    def at(truth):
        return checks.Values("x ≠ truth", fixed(Point("p", {"x": mp.mpf(2)}, truth, abs(truth))), fails_by="1e-4")
    assert checks.run(at(mp.mpf(3)), result(x), "quick").passed
    assert not checks.run(at(mp.mpf(2)), result(x), "quick").passed


def test_definition_compares_exactly_also_componentwise():
    assert checks.run(checks.Definition(), result(2 * x, x + x), "quick").passed
    assert not checks.run(checks.Definition(), result(2 * x, 3 * x), "quick").passed
    assert checks.run(checks.Definition(), result(sp.Tuple(x, 2 * x), sp.Tuple(x, x + x)), "quick").passed
    assert not checks.run(checks.Definition(), result(sp.Tuple(x, 2 * x), sp.Tuple(x, 3 * x)), "quick").passed


def test_proof_and_inequality():
    assert checks.run(checks.Proof("x − x = 0"), result(x - x), "quick").passed
    assert not checks.run(checks.Proof("x = 0"), result(x), "quick").passed
    positive = checks.Inequality("x² − y > 0", fixed(("p", {"x": mp.mpf(2), "y": mp.mpf(1)})))
    assert checks.run(positive, result(x**2 - y), "quick").passed
    negative = checks.Inequality("x² − y > 0", fixed(("p", {"x": mp.mpf(1), "y": mp.mpf(2)})))
    assert not checks.run(negative, result(x**2 - y), "quick").passed


def test_order_fits_the_residual_slope():
    truth = lambda p, dps: mp.sin(p)                                   # the model
    check = checks.Order(param="epsilon", values=checks.Geometric("1e-3", "1e-2"), truth=truth,
                         at=lambda form, p: verify.value_at(form, {"epsilon": p}), expected=3, truth_desc="sin ε")
    ev = checks.run(check, result(eps, eps - eps**3 / 6), "quick")
    assert ev.passed and abs(ev.order - 3) < 0.1 and abs(ev.printed_order - 5) < 0.2
    assert not checks.run(check, result(eps + eps**2), "quick").passed   # residual of order 2


def test_all_and_chain():
    good = checks.Proof("0 = 0")
    bad = checks.Proof("x = 0")
    assert checks.run(checks.All((good, good)), result(x - x), "quick").passed
    assert not checks.run(checks.All((good, bad)), result(x), "quick").passed
    chain = checks.Chain(("toy.a", "toy.b"))
    assert checks.run(chain, result(x), "quick") is None          # filled later by the pipeline
    ok = Evidence(kind="value", passed=True, truth="model", max_residual=1e-30)
    assert checks.chained(chain, {"toy.a": ok, "toy.b": ok}).passed
    assert not checks.chained(chain, {"toy.a": ok, "toy.b": Evidence(kind="value", passed=False, truth="m")}).passed
    assert not checks.chained(chain, {}).passed


def test_geometric_levels():
    assert len(checks.Geometric("1e-3", "1e-1")("quick")) == verify.LEVELS["quick"]
    with pytest.raises(KeyError):
        checks.Geometric("1e-3", "1e-1")("extreme")
