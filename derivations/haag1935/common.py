"""What every section of Haag 1935 shares: its key, ids, sources, the v, w reading, precision."""
from __future__ import annotations

from pendsym import checks
from pendsym.result import Reading, Source

MEMOIR = "haag1935"
DPS, CONFIRM_DPS, TOL = checks.DPS, checks.CONFIRM_DPS, checks.TOL

READ_VW = Reading("ν, ω (for v, w)", "v, w: the OCR renders Haag's functions v, w (and their end values) as ν, ω")


def rid(eq: int, name: str) -> str:
    """The id of a Result of equation (eq): haag1935.eqNNN.name."""
    return f"{MEMOIR}.eq{eq:03d}.{name}"


def src(para: str, eq: str | None) -> Source:
    """The source of a Result: paragraph n° and equation number."""
    return Source(MEMOIR, para, None, eq)
