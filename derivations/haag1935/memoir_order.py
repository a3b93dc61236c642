"""Results of a chapter kept in several tables, merged back into the memoir's order."""
from __future__ import annotations

from typing import Iterable

from pendsym.result import Spec


def equation(spec: Spec) -> int:
    """The equation number of an id ``haag1935.eqNNN.name``."""
    return int(spec.id.split(".")[1][2:])


def merged(main: Iterable[Spec], *inserted: Iterable[Spec]) -> tuple[Spec, ...]:
    """``main``'s Results with each of ``inserted``'s placed before the first Result with a larger equation
    number (at the end when there is none)."""
    out = list(main)
    for specs in inserted:
        for spec in specs:
            place = next((i for i, other in enumerate(out) if equation(other) > equation(spec)), len(out))
            out.insert(place, spec)
    return tuple(out)
