"""The LaTeX report of one memoir: printed beside derived, status, evidence, plots.

Expressions are printed by :mod:`.mathtex` (SymPy's printer with the memoirs' names, broken
into lines that fit); text goes through :func:`.textex.tex_text`; Jinja lays out the document
(templates/report.tex.j2).  The counts of the opening paragraph are those of results.json:
definitions are listed apart and never counted as verified.
"""
from __future__ import annotations

import re
from typing import Sequence

import sympy as sp

from .figures import figure_tex
from .files import render
from .kernels import Kernel
from .mathtex import abbreviation_names, display, tex_expr
from .textex import key_math, literal_points, tex_code, tex_name, tex_number, tex_ocr, tex_text

__all__ = ["report", "tex_text", "tex_expr", "num", "discrepancy_columns"]

# Widths (em of the 10 pt font) of the lines of a formula: the text width less the label column
# (see \formulas in the template); the estimate errs by ~10 %, the template scales what is over.
FORMULA_EM = 38.0
PRINTED_RESIDUAL = re.compile(r"printed form: max residual ([-+0-9.eE]+|inf|nan)")


def num(x) -> str:
    """A number for a table cell (3 significant digits), "--" when absent."""
    if x is None:
        return "--"
    if isinstance(x, bool):
        return "yes" if x else "no"
    return f"{x:.3g}"


def num_tex(x) -> str:
    """A number as LaTeX text: 1e-29 as 1 × 10⁻²⁹ (math), "--" when absent."""
    if x is None:
        return "--"
    s = f"{x:.3g}"
    if s in ("inf", "-inf", "nan"):
        return {"inf": r"$\infty$", "-inf": r"$-\infty$", "nan": "NaN"}[s]
    return f"${tex_number(s)}$"


def order(x) -> str:
    """A fitted order (two decimals: 5.00 against 3.00), "--" when absent."""
    return "--" if x is None else f"{x:.2f}"


def discrepancy_columns(ev) -> tuple[str, str, str]:
    """(derived, printed, what): the two columns of the discrepancy table from a Result's
    evidence: the fitted orders where the check is an order check, else the largest residual of
    each form (the printed one as the check noted it)."""
    if ev is None:
        return "--", "--", "none"
    if ev.kind == "order" and ev.order is not None:
        return (f"order {order(ev.order)}", f"order {order(ev.printed_order)}" if ev.printed_order is not None
                else "--", "order")
    m = PRINTED_RESIDUAL.search(ev.note or "")
    printed = num_tex(float(m.group(1))) if m else "--"
    return num_tex(ev.max_residual), printed, "residual"


def _params(ev) -> list[dict]:
    """The evidence's parameters: a list of points as items, anything else inline."""
    out = []
    for key, value in ev.params:
        points = literal_points(str(value))
        math = key_math(key)
        label = f"${math}$" if math is not None else tex_text(key)
        if points is not None and len(points) > 1:
            out.append({"label": label, "value": "", "points": points})
        else:
            val = points[0] if points else tex_text(str(value))
            numeric = tex_number(str(value))
            out.append({"label": label, "value": f"${numeric}$" if numeric is not None else val, "points": []})
    return out


def _evidence(rec) -> dict | None:
    ev = rec.evidence
    if ev is None:
        return None
    r = rec.result
    return {
        "kind": ev.kind, "truth": tex_text(ev.truth), "max_residual": num_tex(ev.max_residual),
        "order": order(ev.order), "expected": num(ev.expected_order),
        "param": tex_name(ev.param) if ev.param else "",
        "printed_order": order(ev.printed_order), "printed_agrees": ev.printed_agrees,
        "confirm": num(ev.confirm_digits), "note": tex_text(ev.note), "passed": ev.passed,
        "params": _params(ev),
        "series": [(num(p), num(v)) for p, v in ev.series],
        "printed_series": [(num(p), num(v)) for p, v in ev.printed_series if v > 0],
        "plot": bool(ev.series) and all(v > 0 for _, v in ev.series),
        "values": [(num(p), num(tv), num(fv)) for p, tv, fv in ev.values]
        if r.spec.show_values and ev.values and all(tv > 0 and fv > 0 for _, tv, fv in ev.values) else [],
    }


def _item(rec) -> dict:
    r = rec.result
    spec = r.spec
    names = abbreviation_names()
    derived, derived_where = _formula(spec.lhs, r.derived, names)
    printed, printed_where = _formula(spec.lhs, r.printed, names) if r.printed is not None else ([], [])
    return {
        "id": r.id, "id_tex": tex_code(r.id), "title": tex_text(spec.title), "ref": tex_text(spec.source.ref()),
        "para": spec.source.para, "lhs": spec.lhs,
        "printed": printed, "printed_where": printed_where, "derived": derived, "derived_where": derived_where,
        "status": rec.status, "comparison": tex_text(rec.comparison), "verified": rec.verified,
        "definition": spec.definition,
        "readings": [(tex_ocr(x.shows), tex_text(x.read_as), x.certain) for x in spec.readings],
        "note": tex_text(spec.note),
        "ev": _evidence(rec),
    }


_CLAIM = re.compile(r"^(?P<left>[^:]+?)\s*(?P<rel>>|<|\\geq?|\\leq?)\s*0$")


def _formula(lhs: str, expr, names) -> tuple[list[str], list[str]]:
    """The lines of ``lhs = expr``; for a claim of sign (lhs "X > 0", expr the quantity X),
    ``X = expr > 0``, which reads as the claim."""
    m = _CLAIM.match(lhs)
    if not m or isinstance(expr, sp.Tuple):
        return display(lhs, expr, FORMULA_EM, names)
    left, rel = m.group("left"), m.group("rel")
    if re.sub(r"[{} ]", "", tex_expr(expr)) == re.sub(r"[{} ]", "", left):
        return [f"{left} {rel} 0"], []                   # the quantity is its own symbol: v_0 > 0
    lines, where = display(left, expr, FORMULA_EM - 2, names)
    lines[-1] += f" {rel} 0"
    return lines, where


def _counts(records: Sequence) -> dict:
    """The counts of the opening paragraph, as results.json has them."""
    defs = [rec for rec in records if rec.result.spec.definition]
    claims = [rec for rec in records if not rec.result.spec.definition]
    by = {s: sum(1 for rec in claims if rec.status == s) for s in ("match", "discrepancy", "derived-only")}
    return {
        "total": len(records), "verified": sum(1 for rec in records if rec.verified),
        "discrepancies": sum(1 for rec in records if rec.status == "discrepancy"),
        "definitions": len(defs), "claims": len(claims), "claims_by": by,
        "defs_with_text": sum(1 for rec in defs if rec.status == "match"),
        "defs_without_text": sum(1 for rec in defs if rec.status == "derived-only"),
        "unverified": [tex_code(rec.result.id) for rec in claims if not rec.verified],
    }


def _kernels(kernels: Sequence[Kernel]) -> list[dict]:
    def acc(a, field):
        return num_tex(getattr(a, field)) if a else "--"
    return [{"name": tex_code(k.name), "rule": tex_text(k.rule), "id": k.result_id,
             "pys": acc(k.py_accuracy, "max_scaled"), "py": acc(k.py_accuracy, "max_ulp"),
             "cs": acc(k.c_accuracy, "max_scaled"), "c": acc(k.c_accuracy, "max_ulp")} for k in kernels]


def report(memoir: str, title: str, records: Sequence, kernels: Sequence[Kernel], bench: str | None,
           sections: Sequence[tuple[str, str]], withheld: Sequence = (), swing_correction: bool | None = None,
           figures: Sequence = ()) -> str:
    """The report's LaTeX text.  sections: (paragraph range such as "18-20" or a tuple of ids, heading).
    ``swing_correction``: whether the memoir has a speed-against-error bench (``make bench``);
    by default, whether its Memoir declares a swing correction.  ``figures``: (Figure, Plot) pairs, each
    set after the Result it names (:attr:`pendsym.figure.Figure.place`)."""
    if swing_correction is None:
        swing_correction = _has_swing_correction(memoir)
    items = [_item(rec) for rec in records]
    for it in items:
        it["figures"] = [(f, p) for f, p in figures if f.place == it["id"]]
    groups, placed = [], set()
    for selector, heading in sections:
        members = [it for it in items if _selected(it, selector) and it["id"] not in placed]
        placed |= {it["id"] for it in members}
        groups.append({"heading": tex_text(heading), "items": members})
    rest = [it for it in items if it["id"] not in placed]
    if rest:
        groups.append({"heading": "Other results", "items": rest})
    number = 0
    for g in groups:                       # figures numbered in the order they appear
        for it in g["items"]:
            texts = []
            for fig, plot in it["figures"]:
                number += 1
                texts.append(figure_tex(fig, plot, number))
            it["figures"] = texts
    disc = []
    for rec, it in zip(records, items):
        if rec.status == "discrepancy":
            derived, printed, what = discrepancy_columns(rec.evidence)
            disc.append({**it, "col_derived": derived, "col_printed": printed, "what": what,
                         "id_table": rec.result.id.replace("_", r"\_").replace(".", r".\allowbreak ")})
    definitions = [it for it in items if it["definition"]]
    naive = [{"name": tex_code(k.name), "form": k.naive.form, "naive": num_tex(k.naive.accuracy.max_scaled),
              "stable": num_tex(max(a.max_scaled for a in (k.py_accuracy, k.c_accuracy) if a)),
              "fails": _short(k.naive.fails)} for k in kernels if k.naive and k.py_accuracy]
    held = [{"name": tex_code(k.name), "rule": tex_text(k.rule), "id": k.result_id,
             "pys": num_tex(k.py_accuracy.max_scaled) if k.py_accuracy else "--",
             "cs": num_tex(k.c_accuracy.max_scaled) if k.c_accuracy else "--",
             "naive": num_tex(k.naive.accuracy.max_scaled) if k.naive else "--"} for k in withheld]
    return render("report.tex.j2", memoir=memoir, title=tex_text(title), groups=groups, discrepancies=disc,
                  disc_kinds=sorted({d["what"] for d in disc}), definitions=definitions,
                  kernels=_kernels(kernels), naive=naive, withheld=held, bench=bench,
                  swing_correction=swing_correction, counts=_counts(records))


def _has_swing_correction(memoir: str) -> bool:
    from .. import registry   # the emitter needs the Memoir only for this flag
    try:
        return registry.memoir(memoir).swing_correction is not None
    except KeyError:
        return False


def _short(fails: str, runs: int = 4) -> str:
    """The first few failing ranges of a naive form (the list can be long), as LaTeX:
    "u in [1e-06, 0.749]; u = 0.898" → u ∈ [10⁻⁶, 0.749]; u = 0.898."""
    parts = fails.split("; ")
    shown = [_run(p) for p in parts[:runs]]
    more = f"; \\ldots{{}} ({len(parts) - runs} more)" if len(parts) > runs else ""
    return "; ".join(shown) + more


def _run(part: str) -> str:
    m = re.fullmatch(r"(\w+) in \[([^,\]]+), ([^\]]+)\]", part)
    if m:
        lo, hi = tex_number(m.group(2)), tex_number(m.group(3))
        if lo is not None and hi is not None:
            return f"${tex_name(m.group(1))} \\in [{lo}, {hi}]$"
    m = re.fullmatch(r"(\w+) = (\S+)", part)
    if m and tex_number(m.group(2)) is not None:
        return f"${tex_name(m.group(1))} = {tex_number(m.group(2))}$"
    return tex_text(part)


def _selected(item: dict, selector) -> bool:
    """A section takes a paragraph range such as "18-20", or a tuple of result ids."""
    if isinstance(selector, str):
        return _para_key(item["para"]) in _range(selector)
    return item["id"] in selector


def _para_key(para: str) -> int:
    m = re.search(r"(\d+)", para)
    return int(m.group(1)) if m else -1


def _range(prefix: str) -> range:
    lo, _, hi = prefix.partition("-")
    return range(int(lo), int(hi or lo) + 1)
