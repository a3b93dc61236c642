"""Haag 1935, chapter VI: the short blade (λ/a small), n°68–81, eqs. (212)–(254).

The section keeps its jobs apart:

* :mod:`.expansion`: the bookkeeping of the series in λ/a (every length of the blade O(λ), M O(λ²));
* :mod:`.derivation`: the derivation (pure SymPy), series in λ/a of the derived results of
  chapter I (any M(s)) and chapter III (the uniform blade), step by step;
* :mod:`.printed`: the formulas as printed, with their OCR readings;
* :mod:`.truth`, :mod:`.truth_dynamics`: the independent truth, the exact eigenproblem of the
  pendulum on the directly solved blade as a = λ/ε grows (and its temperature derivatives, static
  offset, blow and curvature), judged by the fitted order of the residual in ε;
* :mod:`.kernels`: the kernel of Δl (220);
* the Result tables, one per group of paragraphs, which join them.

n°74 and n°78–79 ((233)–(234), (241)–(245)) are in :mod:`.derivation_perturbations`,
:mod:`.printed_perturbations`, :mod:`.truth_perturbations` and :mod:`.table_blow_isochronism`.

n°80–81 ((246)–(254): the clamping errors, the inertia and weight of the blade, chapter II's (117), (133),
(135), (136) specialised) are in :mod:`.derivation_errors`, :mod:`.printed_errors`, :mod:`.truth_errors` and
:mod:`.table_errors`.
"""
from __future__ import annotations

from types import ModuleType

from pendsym.result import Spec

from . import table_blow_isochronism, table_errors, table_foci_period, table_vibration_flexion

SECTIONS: tuple[tuple[ModuleType, str], ...] = (
    (table_foci_period, "Chapter VI. The short blade: foci, period, Δl, Q, temperature (212)–(223)"),
    (table_vibration_flexion, "Chapter VI. The short blade: parasitic vibration, suppleness, centre of flexion "
                              "(224)–(240)"),
    (table_blow_isochronism, "Chapter VI. The short blade: fatigue after a blow, isochronism (233)–(245)"),
    (table_errors, "Chapter VI. The short blade: clamping errors, the blade's inertia and weight (246)–(254)"),
)


def sections() -> tuple[tuple[ModuleType, str], ...]:
    """The (module, title) pairs of chapter VI, in the memoir's order; each module has ``specs()``."""
    return SECTIONS


def specs() -> tuple[Spec, ...]:
    return tuple(spec for module, _title in SECTIONS for spec in module.specs())


__all__ = ["SECTIONS", "sections", "specs"]
