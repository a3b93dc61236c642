"""The reports' tables and counts say what results.json says: the discrepancy table shows orders
or residuals (never dashes), the opening paragraph counts definitions apart, every Result shows its
locator, and only a memoir with a swing correction speaks of a bench."""
import re

import pytest

from pendsym import pipeline, registry
from pendsym.emit.latex import discrepancy_columns, order
from pendsym.emit.textex import tex_text
from pendsym.result import Evidence


@pytest.fixture(scope="module")
def results(generated):
    return pipeline.load_results_json(generated / "results.json")


@pytest.fixture(scope="module")
def reports(generated):
    return {p.stem: p.read_text() for p in (generated / "tex").glob("*.tex")}


def _rows(tex: str) -> list[list[str]]:
    """The rows of the discrepancy table, as cells."""
    table = tex.split(r"\section*{Discrepancies}")[1].split(r"\endhead")[1].split(r"\bottomrule")[0]
    rows = [r.strip() for r in table.split("\\\\\n") if r.strip()]
    return [[c.strip() for c in re.split(r"\s&\s", r)] for r in rows]


def test_the_discrepancy_table_shows_orders_or_residuals(results, reports):
    for memoir, tex in reports.items():
        disc = [r for r in results.values() if r["memoir"] == memoir and r["status"] == "discrepancy"]
        rows = _rows(tex) if disc else []
        assert len(rows) == len(disc), memoir
        for rec in disc:
            cell = rec["id"].replace("_", r"\_") + "}"          # the whole id (eq346.G2 is not eq346.G2_x)
            (row,) = [row for row in rows if cell in row[0].replace(r".\allowbreak ", ".")]
            derived, printed = row[1], row[2]
            if rec["evidence"]["kind"] == "chain":    # judged through the Result it feeds (test_generated's list)
                continue
            for cell in (derived, printed):
                assert cell not in ("--", "–", "-", ""), (rec["id"], row)
            ev = rec["evidence"]
            if ev["kind"] == "order":
                assert derived == f"order {order(ev['order'])}" and printed == f"order {order(ev['printed_order'])}"
            else:
                assert re.search(r"\d", derived) and re.search(r"\d", printed), row


def test_the_caption_says_which(reports, results):
    for memoir, tex in reports.items():
        head = tex.split(r"\section*{Discrepancies}")[1].split(r"\begin{xltabular}")[0]
        kinds = {r["evidence"]["kind"] == "order" for r in results.values()
                 if r["memoir"] == memoir and r["status"] == "discrepancy"}
        if True in kinds:
            assert "fitted order" in head, memoir
        if False in kinds:
            assert "largest residual" in head, memoir


def test_discrepancy_columns_from_the_evidence():
    order_ev = Evidence(kind="order", passed=True, truth="t", order=5.0006, printed_order=2.99971)
    assert discrepancy_columns(order_ev) == ("order 5.00", "order 3.00", "order")
    value_ev = Evidence(kind="value", passed=True, truth="t", max_residual=1.61843e-39,
                        note="6 points; truth confirmed to 40.2 digits at 45 digits; printed form: max residual 0.304")
    assert discrepancy_columns(value_ev) == (r"$1.62\times 10^{-39}$", "$0.304$", "residual")
    assert discrepancy_columns(None)[:2] == ("--", "--")


def test_the_opening_counts_agree_with_results_json(results, reports):
    for memoir, tex in reports.items():
        recs = [r for r in results.values() if r["memoir"] == memoir]
        n, v = len(recs), sum(r["verified"] for r in recs)
        d = sum(r["status"] == "discrepancy" for r in recs)
        f = sum(r["definition"] for r in recs)
        m = re.search(r"\\textbf\{(\d+) results: (\d+) verified, (\d+)\s+discrepanc(?:y|ies), (\d+)\s+definitions?\.\}", tex)
        assert m, memoir
        assert tuple(map(int, m.groups())) == (n, v, d, f), memoir
        assert not any(r["verified"] for r in recs if r["definition"])
        claims = n - f
        assert f"asked of the\n{claims} claims" in tex or f"asked of the {claims} claims" in tex.replace("\n", " ")


def test_definitions_are_listed_apart(results, reports):
    for memoir, tex in reports.items():
        defs = [r for r in results.values() if r["memoir"] == memoir and r["definition"]]
        if not defs:
            continue
        listed = tex.split(r"\section*{Definitions}")[1].split(r"\end{xltabular}")[0]
        for r in defs:
            assert r["id"].replace("_", r"\_\allowbreak{}").replace(".", r".\allowbreak{}") in listed, r["id"]


def test_every_result_shows_its_locator(results, reports):
    for rec in results.values():
        assert tex_text(rec["ref"]) in reports[rec["memoir"]], rec["id"]
    incipits = [r["ref"] for r in results.values() if r["memoir"] == "cellerier"]
    assert incipits and all(ref.startswith("«") and ref.endswith("»") for ref in incipits)


def test_only_a_memoir_with_a_swing_correction_speaks_of_a_bench(reports):
    for memoir, tex in reports.items():
        benched = registry.memoir(memoir).swing_correction is not None
        assert ("Speed against error" in tex) == benched, memoir
        if not benched:
            assert "make bench" not in tex and "bench" not in tex.split(r"\begin{document}")[1], memoir


def test_the_kernel_table_states_the_bound_on_the_scaled_error(reports):
    for memoir, tex in reports.items():
        if r"\section{Generated kernels}" in tex:
            kernels = tex.split(r"\section{Generated kernels}")[1].split(r"\end{xltabular}")[0]
            assert "scaled (bound 4)" in kernels and "raw ulp" in kernels
            assert r"{\linewidth}" in kernels        # the table is as wide as the text, not wider
