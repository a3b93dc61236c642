"""Haag 1935, chapter III (the uniform blade): the package, its sections, its Result tables and their checks."""
import pytest
import sympy as sp

from derivations.haag1935 import MEMOIR, ch3_uniform
from derivations.haag1935.ch3_uniform import printed
from derivations.haag1935.symbols import DEFS, U1
from pendsym import checks, stages, verify

P = "haag1935"
IDS = tuple(spec.id for spec in ch3_uniform.specs())
ENGINE_KINDS = (checks.Values, checks.Order, checks.Inequality, checks.Proof, checks.Chain, checks.Definition,
                checks.All)


def equation(result_id: str) -> int:
    return int(result_id.split(".")[1][2:])


# ---------------------------------------------------------------- fast: the package and its tables
def test_specs_are_the_sections_in_order():
    from_sections = tuple(spec.id for module, _title in ch3_uniform.sections() for spec in module.specs())
    assert from_sections == IDS
    assert len(IDS) == len(set(IDS)) == 67
    assert ch3_uniform.KERNELS_READY is True


@pytest.mark.parametrize("index, equations", [
    (0, range(156, 162)), (1, range(162, 167)), (2, range(167, 171)), (3, (30, 34, 35, 36)),
    (4, range(171, 180)), (5, range(180, 184))])
def test_each_table_holds_its_heading(index, equations):
    module, title = ch3_uniform.sections()[index]
    assert title.startswith("Chapter III.")
    assert {equation(spec.id) for spec in module.specs()} <= set(equations)


def test_the_memoir_has_the_sections_and_headings_of_chapter_three():
    modules = {sec.module for sec in MEMOIR.sections}
    assert {module.__name__ for module, _title in ch3_uniform.sections()} <= modules
    headed = {i for heading in MEMOIR.report_headings() if heading.title.startswith("Chapter III") for i in heading.ids}
    assert headed == set(IDS)


def test_every_check_is_a_declaration_of_the_engine():
    for spec in ch3_uniform.specs():
        if spec.definition:
            assert spec.check is None, spec.id
            continue
        assert isinstance(spec.check, ENGINE_KINDS), spec.id
        parts = spec.check.checks if isinstance(spec.check, checks.All) else (spec.check,)
        assert all(isinstance(part, ENGINE_KINDS) for part in parts), spec.id


def test_value_checks_confirm_their_truth():
    """Every check against the numerical blade recomputes its truth at a second precision."""
    for spec in ch3_uniform.specs():
        if isinstance(spec.check, checks.Values) and spec.check.kind == "quadrature":
            assert spec.check.confirm is not None, spec.id


# ---------------------------------------------------------------- the built chapter (slow: ~40 s build)
@pytest.fixture(scope="module")
def built():
    return stages.results(IDS)


@pytest.mark.slow
@pytest.mark.parametrize("rid", ["eq159.v0", "eq159.w0", "eq159.beta1", "eq166.Gamma2", "eq166.Gamma3",
                                 "eq166.Gamma4", "eq168.F1", "eq169.F2", "eq182.I", "eq183.J", "eq174.c",
                                 "eq165.k", "eq161.square"])
def test_printed_matches_derived(built, rid):
    r = built[f"{P}.{rid}"]
    assert verify.compare_forms(r.printed_value, r.derived_value, r.id)[0] == "match"


@pytest.mark.slow
@pytest.mark.parametrize("rid", ["eq166.Gamma5", "eq170.F"])
def test_exponent_slips_are_discrepancies_the_blade_decides(built, rid):
    """Γ_5 and F print U_1^3 where the derivation (and the numerical blade) give U_1^4."""
    r = built[f"{P}.{rid}"]
    assert verify.compare_forms(r.printed_value, r.derived_value, r.id)[0] == "discrepancy"
    ev = stages.assessed(r)[1]
    assert ev.passed                         # the derived form agrees with the blade
    assert ev.printed_agrees is False        # … and the printed one does not
    assert ev.confirm_digits >= checks.MIN_DIGITS


@pytest.mark.slow
def test_corrected_exponent_agrees(built):
    """Reading 4U_1^4 for 4U_1^3 in Γ_5 removes the discrepancy (the OCR hypothesis)."""
    r = built[f"{P}.eq166.Gamma5"]
    fixed = printed.Gamma5().subs(4 * U1**3, 4 * U1**4).subs(dict(DEFS), simultaneous=True)
    assert verify.numeric_difference(fixed, r.derived_value, r.id) < 1e-40
    assert verify.numeric_difference(r.printed_value, r.derived_value, r.id) > 1e-3


@pytest.mark.slow
def test_all_checks_pass_quick(built):
    own = [r for r in built.values() if r.id in IDS and r.spec.check and not isinstance(r.spec.check, checks.Chain)]
    failed = [r.id for r in own if not stages.assessed(r)[1].passed]
    assert failed == []


@pytest.mark.slow
def test_launch_stresses_side_with_K_prime(built):
    """(180) prints K where the parasitic term needs K'; (181) prints K' and agrees."""
    ev180 = stages.assessed(built[f"{P}.eq180.T0"])[1]
    ev181 = stages.assessed(built[f"{P}.eq181.T0"])[1]
    assert ev180.passed and ev181.passed
    assert ev180.printed_agrees is False
    assert ev181.printed_agrees is True


@pytest.mark.slow
def test_leading_terms_have_the_fitted_order_two(built):
    r = built[f"{P}.eq166.Gamma_top"]
    ev = stages.assessed(r)[1]
    assert ev.passed and ev.kind == "order" and abs(ev.order - 2) < 0.3
    assert sp.simplify(r.derived_value[0] - r.printed_value[0]) == 0
