"""The Results (to be built)."""
from __future__ import annotations

from pendsym.result import Spec


def specs() -> tuple[Spec, ...]:
    return ()
