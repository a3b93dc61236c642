"""Haag 1935, chapter IX, n°107–110: the rhombus hole for a small hole, series in k (not in the memoir).

The Bessel forms (343)–(346) cancel large terms as k → 0 (x_0, x_1 ~ 2ω/k): in double precision the derived G_2
loses about log10(1/k) digits (measured: relative error 3e-12 at k = 1e-4, 2e-8 at k = 1e-8).  These Results
are the first terms of the expansion in k (:mod:`.rhombus_series`), checked by the fitted order of their residual
against the shot blade.
"""
from __future__ import annotations

from pendsym.result import Spec

from ..common import rid, src
from . import rhombus_series as series, rhombus_truth as truth

NOTE = ("Not printed by Haag: a form for k → 0, where the Bessel form loses digits; the k⁰ term is the uniform "
        "inverted blade (313).")


def specs() -> tuple[Spec, ...]:
    where = src("n°107–110 (series in k)", None)
    return (
        *(Spec(rid(343, f"{name}_small_k"), f"{name} = (uniform) + c_1 k + O(k²), rhombus hole", where,
               {"v0": "v_0", "w0": "w_0", "wl": r"w_\lambda"}[name],
               lambda deps, name=name: series.end_series(name, 1),
               check=truth.uniform_limit(name, expected=2.0, lo="1e-4", hi="1e-2"), note=NOTE)
          for name in ("v0", "w0", "wl")),
        Spec(rid(346, "G2_small_k"), "G_2 = (uniform) + c_1 k + O(k²), rhombus hole", where, "G_2",
             lambda deps: series.G2_series(1), check=truth.uniform_limit("G2", expected=2.0, lo="1e-4", hi="1e-2"),
             note=NOTE, show_values=True),
    )
