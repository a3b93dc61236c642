"""Haag 1935, chapter IV (the thread): the package, its Result table, its derivations and checks."""
import pytest
import sympy as sp

from derivations.haag1935 import MEMOIR, ch4_thread
from derivations.haag1935.ch4_thread import derivation, printed
from derivations.haag1935.symbols import K, a, lam, n, u, zp
from pendsym import checks, stages, verify

P = "haag1935"
IDS = tuple(spec.id for spec in ch4_thread.specs())
ENGINE_KINDS = (checks.Values, checks.Order, checks.Inequality, checks.Proof, checks.Chain, checks.Definition,
                checks.All)


def test_ids_are_unique_and_registered():
    assert len(IDS) == len(set(IDS)) == 32
    registered = {spec.id for sec in MEMOIR.sections for spec in sec.specs}
    assert set(IDS) <= registered
    headed = {i for heading in MEMOIR.report_headings() if heading.title.startswith("Chapter IV") for i in heading.ids}
    assert headed == set(IDS)


def test_every_check_is_a_declaration_of_the_engine():
    for spec in ch4_thread.specs():
        assert isinstance(spec.check, ENGINE_KINDS), spec.id
        parts = spec.check.checks if isinstance(spec.check, checks.All) else (spec.check,)
        assert all(isinstance(part, ENGINE_KINDS) for part in parts), spec.id


def test_chains_feed_results_of_the_table():
    for spec in ch4_thread.specs():
        if isinstance(spec.check, checks.Chain):
            assert set(spec.check.downstream) <= set(IDS), spec.id


def test_isochronism_from_the_direct_energies():
    """(186)–(187) → n°60's quartic energies → (194) → (195) → (196), without the pipeline."""
    class Built:
        def __init__(self, expr):
            self.derived = expr
    deps = {f"{P}.eq186.T": Built(derivation.kinetic({})), f"{P}.eq187.U": Built(derivation.force_function({}))}
    deps[f"{P}.eq194.T4"] = Built(derivation.kinetic_quartic(deps))
    deps[f"{P}.eq194.U4"] = Built(derivation.force_quartic(deps))
    deps[f"{P}.eq194.equation"] = Built(derivation.reduced_equation(deps))
    deps[f"{P}.eq195.acceleration"] = Built(derivation.perturbing_acceleration(deps))
    assert sp.simplify(derivation.isochronism(deps) - printed.isochronism()) == 0
    assert sp.simplify(deps[f"{P}.eq194.equation"].derived - printed.reduced_equation()) == 0
    # (195): the text's letter n² is the linear pulsation of (194); with it the forms agree, without it they do not
    acceleration = deps[f"{P}.eq195.acceleration"].derived
    with_n2 = printed.perturbing_acceleration().subs(dict(printed.LINEAR_N2))
    assert sp.simplify(acceleration - with_n2) == 0
    assert sp.simplify(acceleration - printed.perturbing_acceleration()) != 0


def test_the_heavy_thread_inertia_carries_K_cubed():
    derived = derivation.inertia_period({f"{P}.eq135.thread_acceleration":
                                         type("B", (), {"derived": derivation.inertia_acceleration({})})()})
    assert sp.simplify(derived - printed.inertia_period() * K) == 0


# ---------------------------------------------------------------- the built chapter (slow)
@pytest.fixture(scope="module")
def built():
    return stages.results(IDS)


@pytest.mark.slow
@pytest.mark.parametrize("rid", ["eq184.ends", "eq184.F", "eq185.I_J", "eq186.T", "eq188.T", "eq189.U",
                                 "eq190.motion", "eq191.combination", "eq193.K", "eq192.dT", "eq192.G",
                                 "eq193.end_stresses", "eq194.T4", "eq194.U4", "eq195.acceleration", "eq196.dT", "eq136.thread_dT",
                                 "eq184.along", "eq193.shape", "eq192.footnote", "eq197.Q", "eq192.from_58", "eq192.from_44"])
def test_printed_matches_derived(built, rid):
    r = built[f"{P}.{rid}"]
    assert verify.compare_forms(r.printed_value, r.derived_value, r.id)[0] == "match"


@pytest.mark.slow
@pytest.mark.parametrize("rid, fix", [
    ("eq184.Gn", lambda expr: expr.subs((u / lam) ** (n - 1), (u / lam) ** (n - 3))),
    ("eq135.thread_dT", lambda expr: expr * K)])
def test_discrepancies_the_truth_decides(built, rid, fix):
    """(184) prints (u/λ)^{n−1}, n°62 prints K²: the derived form passes its check and the printed one
    does not; the corrected reading equals the derived form."""
    r = built[f"{P}.{rid}"]
    assert verify.compare_forms(r.printed_value, r.derived_value, r.id)[0] == "discrepancy"
    ev = stages.assessed(r)[1]
    assert ev.passed and ev.printed_agrees is False
    assert verify.numeric_difference(fix(r.printed_value), r.derived_value, r.id) < 1e-40


@pytest.mark.slow
def test_all_checks_pass_quick(built):
    own = [built[i] for i in IDS if not isinstance(built[i].spec.check, checks.Chain)]
    failed = [r.id for r in own if not stages.assessed(r)[1].passed]
    assert failed == []


@pytest.mark.slow
def test_limits_have_the_fitted_order(built):
    ev = stages.assessed(built[f"{P}.eq185.I_J"])[1]
    assert ev.kind == "order" and abs(ev.order - 1) < 0.3


def test_thread_K_is_35_at_the_limit():
    expr = derivation.K_thread({f"{P}.eq184.ends": type("B", (), {"derived": sp.Tuple(0, 0, 0, 0, lam, 0, 1, 0, 1)})()})
    assert sp.simplify(expr + (a + zp) / lam) == 0
