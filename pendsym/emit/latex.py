"""The LaTeX report of one memoir: printed beside derived, status, evidence, plots.

Expressions are printed by ``sympy.latex``; text goes through :func:`tex_text`;
Jinja lays out the document (templates/report.tex.j2).
"""
from __future__ import annotations

import re
from typing import Sequence

import sympy as sp

from .files import render
from .kernels import Kernel

GREEK = {
    "α": r"\alpha", "β": r"\beta", "γ": r"\gamma", "δ": r"\delta", "ε": r"\varepsilon", "θ": r"\theta",
    "κ": r"\kappa", "λ": r"\lambda", "μ": r"\mu", "ν": r"\nu", "π": r"\pi", "ρ": r"\rho", "σ": r"\sigma",
    "τ": r"\tau", "φ": r"\varphi", "ω": r"\omega", "Γ": r"\Gamma", "Δ": r"\Delta", "Σ": r"\Sigma",
    "²": "^2", "³": "^3", "⁴": "^4", "½": r"\tfrac12", "≡": r"\equiv", "≤": r"\le", "≥": r"\ge",
    "≠": r"\ne", "→": r"\to", "∫": r"\int ", "√": r"\surd ", "·": r"\cdot ", "×": r"\times ", "−": "-",
    "…": r"\ldots ", "′": "'", "∞": r"\infty ", "≈": r"\approx ", "±": r"\pm ", "ℓ": r"\ell ",
    "⁻": "^-", "¹": "^1", "₀": "_0", "₁": "_1", "₂": "_2", "∂": r"\partial ",
}
SPECIAL = {"\\": r"\textbackslash{}", "&": r"\&", "%": r"\%", "$": r"\$", "#": r"\#", "_": r"\_",
           "{": r"\{", "}": r"\}", "~": r"\textasciitilde{}", "^": r"\textasciicircum{}"}


def tex_text(s: str) -> str:
    """Escape text for LaTeX; Greek letters and math signs become inline math."""
    out = []
    for ch in s:
        if ch in SPECIAL:
            out.append(SPECIAL[ch])
        elif ch in GREEK:
            out.append(f"${GREEK[ch]}$")
        elif ord(ch) < 128 or ch in "éèêàâçùûôîïëüÉÈ°«»’–—":
            out.append(ch)
        else:
            out.append("?")
    return re.sub(r"\$\$", "", "".join(out))


def tex_expr(e: sp.Basic | None) -> str:
    if e is None:
        return ""
    return sp.latex(e, ln_notation=False)


def num(x) -> str:
    if x is None:
        return "--"
    if isinstance(x, bool):
        return "yes" if x else "no"
    return f"{x:.3g}"


def report(memoir: str, title: str, records: Sequence, kernels: Sequence[Kernel], bench: str | None,
           sections: Sequence[tuple[str, str]], withheld: Sequence = ()) -> str:
    """The report's LaTeX text.  sections: (paragraph range such as "18-20" or a tuple of ids, heading)."""
    items = []
    for rec in records:
        r = rec.result
        ev = rec.evidence
        items.append({
            "id": r.id, "title": tex_text(r.spec.title), "ref": tex_text(r.spec.source.ref()),
            "para": r.spec.source.para, "lhs": r.spec.lhs,
            "printed": tex_expr(r.printed), "derived": tex_expr(r.derived), "status": rec.status,
            "comparison": tex_text(rec.comparison), "verified": rec.verified,
            "readings": [(tex_text(x.shows), tex_text(x.read_as), x.certain) for x in r.spec.readings],
            "note": tex_text(r.spec.note),
            "ev": None if ev is None else {
                "kind": ev.kind, "truth": tex_text(ev.truth), "max_residual": num(ev.max_residual),
                "order": num(ev.order), "expected": num(ev.expected_order), "param": tex_text(ev.param or ""),
                "printed_order": num(ev.printed_order), "printed_agrees": ev.printed_agrees,
                "confirm": num(ev.confirm_digits), "note": tex_text(ev.note), "passed": ev.passed,
                "params": ", ".join(f"{tex_text(k)} = {v}" for k, v in ev.params),
                "series": [(num(p), num(v)) for p, v in ev.series],
                "printed_series": [(num(p), num(v)) for p, v in ev.printed_series if v > 0],
                "plot": bool(ev.series) and all(v > 0 for _, v in ev.series),
                "values": [(num(p), num(tv), num(fv)) for p, tv, fv in ev.values]
                if r.spec.show_values and ev.values and all(tv > 0 and fv > 0 for _, tv, fv in ev.values) else [],
            },
        })
    groups, placed = [], set()
    for selector, heading in sections:
        members = [it for it in items if _selected(it, selector) and it["id"] not in placed]
        placed |= {it["id"] for it in members}
        groups.append({"heading": tex_text(heading), "items": members})
    rest = [it for it in items if it["id"] not in placed]
    if rest:
        groups.append({"heading": "Other results", "items": rest})
    disc = [it for it in items if it["status"] == "discrepancy"]
    ks = [{"name": tex_text(k.name), "rule": tex_text(k.rule), "id": k.result_id,
           "py": num(k.py_accuracy.max_ulp) if k.py_accuracy else "--",
           "pys": num(k.py_accuracy.max_scaled) if k.py_accuracy else "--",
           "c": num(k.c_accuracy.max_ulp) if k.c_accuracy else "--",
           "cs": num(k.c_accuracy.max_scaled) if k.c_accuracy else "--"} for k in kernels]
    naive = [{"name": tex_text(k.name), "form": k.naive.form, "naive": num(k.naive.accuracy.max_scaled),
              "stable": num(max(a.max_scaled for a in (k.py_accuracy, k.c_accuracy) if a)),
              "fails": tex_text(_short(k.naive.fails))} for k in kernels if k.naive and k.py_accuracy]
    held = [{"name": tex_text(k.name), "rule": tex_text(k.rule), "id": k.result_id,
             "pys": num(k.py_accuracy.max_scaled) if k.py_accuracy else "--",
             "cs": num(k.c_accuracy.max_scaled) if k.c_accuracy else "--",
             "naive": num(k.naive.accuracy.max_scaled) if k.naive else "--"} for k in withheld]
    counts = {s: sum(1 for it in items if it["status"] == s) for s in ("match", "discrepancy", "derived-only")}
    return render("report.tex.j2", memoir=memoir, title=tex_text(title), groups=groups, discrepancies=disc,
                  kernels=ks, naive=naive, withheld=held, bench=bench, counts=counts, total=len(items),
                  verified=sum(1 for it in items if it["verified"]))


def _short(fails: str, runs: int = 4) -> str:
    """The first few failing ranges of a naive form (the list can be long)."""
    parts = fails.split("; ")
    return "; ".join(parts[:runs]) + (f"; … ({len(parts) - runs} more)" if len(parts) > runs else "")


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
