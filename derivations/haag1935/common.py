"""What every section of Haag 1935 shares: its key, ids, sources, the v, w reading, precision."""
from __future__ import annotations

from typing import Callable, Mapping

import sympy as sp

from pendsym import checks
from pendsym.result import Reading, Result, Source

MEMOIR = "haag1935"
DPS, CONFIRM_DPS, TOL = checks.DPS, checks.CONFIRM_DPS, checks.TOL

READ_VW = Reading("ν, ω (for v, w)", "v, w: the OCR renders Haag's functions v, w (and their end values) as ν, ω")


def rid(eq: int, name: str) -> str:
    """The id of a Result of equation (eq): haag1935.eqNNN.name."""
    return f"{MEMOIR}.eq{eq:03d}.{name}"


def src(para: int | str, eq: str | None) -> Source:
    """The source of a Result: Haag's paragraph (n°para, for a number) and equation number."""
    return Source(MEMOIR, f"n°{para}" if isinstance(para, int) else para, None, eq)


def step(derivation: Callable[[], sp.Basic]) -> Callable[[Mapping[str, Result]], sp.Basic]:
    """A Spec's ``derive`` for a derivation step that needs no other Result."""
    return lambda deps: derivation()
