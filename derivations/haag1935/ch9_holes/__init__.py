"""Haag 1935, chapter IX, n°104–111, eqs. (321)–(346): blades with a rectangular hole and a rhombus hole.

* the rhombus hole, n°107–110: :mod:`.rhombus_derivation` (SymPy, Bessel's equation), :mod:`.rhombus_printed`,
  :mod:`.rhombus_truth` (the blade shot, no Bessel function), :mod:`.rhombus_table_functions`,
  :mod:`.rhombus_table_ends`; :mod:`.rhombus_series`, :mod:`.rhombus_table_small`: the series in k for a small
  hole, where the Bessel forms lose digits;
* the rectangular hole, n°104–106: :mod:`.rectangle_derivation` (SymPy, trigonometric pieces),
  :mod:`.rectangle_printed`, :mod:`.rectangle_truth` (the blade shot), :mod:`.rectangle_table`;
* :mod:`.limits`: the blade without a hole, the limit of both;
* :mod:`.rhombus_table_kernels`, :mod:`.kernels`: v_0/λ, w_0/λ, w_λ/λ in u = ωλ, q = kλ with supplied kernel forms.

Findings (the truth is the blade shot by :mod:`pendsym.blade`, no Bessel function involved):

* Haag's Y_n is Neumann's (Jahnke–Emde), (π/2)Y_n(today) + (ln 2 − γ)J_n: the Wronskian 1/x he quotes and
  the end values (343) hold only under that scale (today's Y_n: 2/(πx), w_0 off by (π/2)²);
* (346) and the line before it are wrong: n°110 takes dz/dx = 1 at x_1 where w'(λ/2) = 1 gives kx_1/(2ω²); the
  derived G_2 = k/(8ω²D²D'²)(1/x_0² + 2x_1²D D' D_1 D'_1 − D² − D'²) + 1/k + λ/2 − (kx_1/4ω²)(D_1/D + D'_1/D')
  agrees with the truth (the printed terms ω²/k and ½(D_1/D + D'_1/D') are not lengths);
* the rectangular hole (321)–(333), including the long (333), agrees with the truth throughout.
"""
from __future__ import annotations

from types import ModuleType

from . import rectangle_table, rhombus_table_ends, rhombus_table_functions, rhombus_table_small
from . import rectangle_table_kernels, rhombus_table_kernels, rhombus_table_scene

SECTIONS: tuple[tuple[ModuleType, str], ...] = (
    (rectangle_table, "Chapter IX. The rectangular hole (321)–(333) and the stability remark of n°106"),
    (rhombus_table_functions, "Chapter IX. The rhombus hole: Bessel's equation and the constants (334)–(342)"),
    (rhombus_table_ends, "Chapter IX. The rhombus hole: end values, (345) and G_2 (343)–(346)"),
    (rhombus_table_small, "Chapter IX. The rhombus hole for a small hole: series in k (not in the memoir)"),
    (rhombus_table_scene, "Chapter IX. The rhombus hole in a gravity meter: β1, a1, n², G, C (not in the memoir)"),
    (rhombus_table_kernels, "Chapter IX. The rhombus hole's end values in u = ωλ, q = kλ, with their kernels"),
    (rectangle_table_kernels, "Chapter IX. G_2/λ of the concentric rectangular hole in u = ωλ, u_p = ω'p, ρ = p/λ (for a kernel)"),
)


def sections() -> tuple[tuple[ModuleType, str], ...]:
    return SECTIONS
