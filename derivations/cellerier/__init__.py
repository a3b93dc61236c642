"""Ch. Cellérier, Mouvement simultané d'un pendule et de ses supports.

Sections, in the order of the text: the equation of motion on a moving knife edge
(equation.py), the general formulas of the earlier memoir (general.py), the pressures on the
knife edge (pressures.py), the static support y1 = KQ (static_support.py) and the terms its
leading substitutions neglect (neglected_terms.py), the support as an elastic bar
(elastic_bar.py), δ in practice and the worked example (practical.py).  Shared helpers:
common.py (ids, locators, readings, precision) and symbols.py; the truth models: truth.py.


The registration (``MEMOIR``) is in :mod:`.registration`, imported when first asked for.
"""
from pendsym.plugin import lazy_package

__getattr__ = lazy_package(__name__)
