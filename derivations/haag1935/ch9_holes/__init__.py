"""Haag 1935, chapter IX, n°104–111, eqs. (321)–(346): blades with a rectangular hole and a rhombus hole.

* the rhombus hole, n°107–110: :mod:`.rhombus_derivation` (SymPy, Bessel's equation), :mod:`.rhombus_printed`,
  :mod:`.rhombus_truth` (the blade shot, no Bessel function), :mod:`.rhombus_table_functions`,
  :mod:`.rhombus_table_ends`; :mod:`.rhombus_series`, :mod:`.rhombus_table_small`: the series in k for a small
  hole, where the Bessel forms lose digits;
* the rectangular hole, n°104–106: :mod:`.rectangle_derivation` (SymPy, trigonometric pieces),
  :mod:`.rectangle_printed`, :mod:`.rectangle_truth` (the blade shot), :mod:`.rectangle_table`;
* :mod:`.limits`: the blade without a hole, the limit of both.
"""
from __future__ import annotations

from types import ModuleType

from . import rectangle_table, rhombus_table_ends, rhombus_table_functions, rhombus_table_small

SECTIONS: tuple[tuple[ModuleType, str], ...] = (
    (rectangle_table, "Chapter IX. The rectangular hole (321)–(333) and the stability remark of n°106"),
    (rhombus_table_functions, "Chapter IX. The rhombus hole: Bessel's equation and the constants (334)–(342)"),
    (rhombus_table_ends, "Chapter IX. The rhombus hole: end values, (345) and G_2 (343)–(346)"),
    (rhombus_table_small, "Chapter IX. The rhombus hole for a small hole: series in k (not in the memoir)"),
)


def sections() -> tuple[tuple[ModuleType, str], ...]:
    return SECTIONS
