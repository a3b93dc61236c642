"""Kernels: Python (math only) and C99 (libm only) functions for every closed form.

A Result whose Spec asks for a kernel is emitted from its derived form.  The package is
split by job:

- :mod:`.rules`     named rewrite rules, objects in tuples (whole-expression rewrites, the
  near-zero series, far forms of a leaf, skeleton forms);
- :mod:`.series`    the series of a leaf below a switch and its Taylor pieces between knots;
- :mod:`.leaves`    stable-form synthesis: skeleton, leaves, each leaf's piecewise form;
- :mod:`.sampling`  the seeded sample of a kernel's domain, hard points included;
- :mod:`.measure`   errors in ulp against 50-digit mpmath, condition numbers, the bound;
- :mod:`.choice`    the choice of form by measured accuracy, and the naive form;
- :mod:`.plan`      statements (SymPy's codegen AST) shared by the two languages;
- :mod:`.printing`  the C99 and Python printers, functions laid out by Jinja templates;
- :mod:`.sharing`   a large part several kernels of a file compute, emitted once;
- :mod:`.compile`   the printed code compiled, so what is measured is what is emitted;
- :mod:`.kernel`    the Kernel record and :func:`kernel_of`, which builds it once.

The accuracy contract is stated once, in docs/kernel-accuracy.md.
"""
from .choice import choose_form, naive_form
from .compile import c_accuracy, c_callable, compile_c, emitted_py
from .kernel import CONTRACT, Kernel, closed_form, kernel_name, kernel_of
from .leaves import hard_argument, leaf_form, split_hard, stable_forms, vertex_curve
from .measure import BOUND, Accuracy, Naive, measure, measure_naive, py_callable, references
from .plan import Grouped
from .printing import (Function, c_function, definition, identifier, kernel_function, printed, prototype,
                       py_function)
from .rules import FAR_FORMS, NEAR_ZERO, REWRITES, SKELETONS, exp_form
from .sampling import kernel_sample, sample_points, vertex_points
from .series import KNOTS, SWITCHES, laurent
from .sharing import SHARE_MIN, part_doc, share

__all__ = [
    "Accuracy", "BOUND", "CONTRACT", "FAR_FORMS", "Function", "Grouped", "KNOTS", "Kernel", "NEAR_ZERO", "Naive",
    "REWRITES", "SHARE_MIN", "SKELETONS", "SWITCHES", "c_accuracy", "c_callable", "c_function", "choose_form",
    "closed_form", "compile_c", "definition", "emitted_py", "exp_form", "hard_argument", "identifier",
    "kernel_function", "kernel_name", "kernel_of", "kernel_sample", "laurent", "leaf_form", "measure",
    "measure_naive", "naive_form", "part_doc", "printed", "prototype", "py_callable", "py_function", "references",
    "sample_points", "share", "split_hard", "stable_forms", "vertex_curve", "vertex_points",
]
