"""The spine: build → compare → verify → emit.  Each stage is a plain function."""
from __future__ import annotations

import json
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Sequence

import mpmath as mp
import sympy as sp

from . import checks, verify
from .result import Evidence, Result


@dataclass(frozen=True)
class Record:
    """A Result with its assessment: the printed/derived comparison and the evidence."""

    result: Result
    status: str          # match | discrepancy | derived-only
    comparison: str
    evidence: Evidence | None

    @property
    def verified(self) -> bool:
        """An independent check passed (a definition is not a claim: it is never "verified")."""
        return not self.result.spec.definition and self.evidence is not None and self.evidence.passed


def compare(result: Result) -> tuple[str, str]:
    """Stage 2: printed ≡ derived?"""
    if result.printed is None:
        return "derived-only", "the memoir prints no formula for it"
    if result.spec.printed_decimals is not None:
        return verify.compare_decimal(result.printed_value, result.derived_value, result.spec.printed_decimals)
    return verify.compare_forms(result.printed_value, result.derived_value, result.id, result.spec.instances)


def check(result: Result, level: str = "full") -> Evidence | None:
    """Stage 3: the independent check, at 40 working digits unless it scopes its own (a Chain's
    evidence is filled by :func:`fill_chains`).  Callers cache it under the Result's key."""
    if result.spec.check is None or isinstance(result.spec.check, checks.Chain):
        return None
    with mp.workdps(40):
        return checks.run(result.spec.check, result, level)


def assessed(r: Result, level: str = "full") -> tuple[tuple[str, str], Evidence | None]:
    """(comparison, evidence) of one Result: stages 2 and 3."""
    return compare(r), check(r, level)


def fill_chains(records: Sequence[Record]) -> list[Record]:
    """Stage 3b: the evidence of each Chain step, from the evidence of the Results it feeds
    (which must be among the records: a step is assessed with what it feeds)."""
    evidence = {rec.result.id: rec.evidence for rec in records}
    out = []
    for rec in records:
        chk = rec.result.spec.check
        if isinstance(chk, checks.Chain):
            missing = [d for d in chk.downstream if d not in evidence]
            if missing:
                raise ValueError(f"{rec.result.id} is verified through {', '.join(missing)}, not assessed with it")
            rec = Record(rec.result, rec.status, rec.comparison, checks.chained(chk, evidence))
        out.append(rec)
    return out


# ----------------------------------------------------------------- results.json
def _evidence_json(ev: Evidence | None) -> dict | None:
    if ev is None:
        return None
    d = asdict(ev)
    d["params"] = dict(ev.params)
    d["series"] = [list(x) for x in ev.series]
    d["printed_series"] = [list(x) for x in ev.printed_series]
    d["values"] = [list(x) for x in ev.values]
    d["band"] = list(ev.band) if ev.band else None
    return d


def record_json(rec: Record, kernels: Sequence[str] = ()) -> dict:
    r, spec = rec.result, rec.result.spec
    return {
        "id": r.id,
        "memoir": spec.memoir,
        "title": spec.title,
        "ref": spec.source.ref(),
        "para": spec.source.para,
        "page": spec.source.page,
        "status": rec.status,
        "comparison": rec.comparison,
        "verified": rec.verified,
        "definition": spec.definition,
        "printed": None if r.printed is None else sp.sstr(r.printed),
        "derived": sp.sstr(r.derived),
        "readings": [{"shows": x.shows, "read_as": x.read_as, "certain": x.certain} for x in spec.readings],
        "symbols": [{"name": s.name, "assumptions": sorted(k for k, v in s.assumptions0.items() if v)}
                    for s in r.symbols()],
        "deps": list(spec.deps),
        "evidence": _evidence_json(rec.evidence),
        "kernels": list(kernels),
        "note": spec.note,
    }


def results_json(records: Sequence[Record], kernels: dict[str, list[str]]) -> str:
    body = [record_json(rec, kernels.get(rec.result.id, ())) for rec in records]
    return json.dumps({"results": body}, indent=1, ensure_ascii=False, sort_keys=False) + "\n"


def load_results_json(path: Path) -> dict[str, dict]:
    data = json.loads(Path(path).read_text(encoding="utf-8"))
    return {r["id"]: r for r in data["results"]}
