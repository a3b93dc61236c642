"""Haag 1935, chapter III: the uniform blade, n°47–57, eqs. (156)–(183) and (30)–(37) for K, z, n².

The section keeps its jobs apart:

* :mod:`.derivation_functions`, :mod:`.derivation_pendulum`: the derivation (pure SymPy),
  from (9)–(10) of chapter I with a constant M = λ²/u² (156), step by step;
* :mod:`.rational`: the rational forms in th(u/2) that the memoir writes its results in;
* :mod:`.printed`: the formulas as printed, with their OCR readings;
* :mod:`.truth`, :mod:`.truth_modes`: the independent truth, the uniform blade solved by
  shooting (pendsym.blade), the quadrature of the definitions and the normal modes;
* :mod:`.kernels`: the kernels asked of the emitters;
* the Result tables, one per heading of the memoir, which join them.

:func:`sections` gives the tables with their titles, in the memoir's order; :func:`specs`
all their Specs.
"""
from __future__ import annotations

from types import ModuleType

from pendsym.result import Spec

from . import table_f_integrals, table_foci, table_functions, table_gamma_integrals, table_shape_fatigue
from . import table_stresses_inertia
from .kernels import KERNELS_READY

SECTIONS: tuple[tuple[ModuleType, str], ...] = (
    (table_functions, "Chapter III. The uniform blade: v, w and the functions U, U1, U2 (156)–(161)"),
    (table_gamma_integrals, "Chapter III. The integrals Γ_n (162)–(166)"),
    (table_f_integrals, "Chapter III. The integrals F_n and F (167)–(170)"),
    (table_foci, "Chapter III. Foci, K and the period of the uniform blade (n°50)"),
    (table_shape_fatigue, "Chapter III. Shape and fatigue of the uniform blade (171)–(179)"),
    (table_stresses_inertia, "Chapter III. Stresses of both vibrations, I_λ and J (180)–(183)"),
)


def sections() -> tuple[tuple[ModuleType, str], ...]:
    """The (module, title) pairs of chapter III, in the memoir's order; each module has ``specs()``."""
    return SECTIONS


def specs() -> tuple[Spec, ...]:
    """Every Spec of chapter III, in the memoir's order."""
    return tuple(spec for module, _title in SECTIONS for spec in module.specs())


__all__ = ["KERNELS_READY", "SECTIONS", "sections", "specs"]
