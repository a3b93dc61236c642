"""Ch. Cellérier, Mouvement simultané d'un pendule et de ses supports.

Sections, in the order of the text: the equation of motion on a moving knife edge
(equation.py), the general formulas of the earlier memoir (general.py), the pressures on the
knife edge (pressures.py), the static support y1 = KQ (static_support.py) and the terms its
leading substitutions neglect (neglected_terms.py), the support as an elastic bar
(elastic_bar.py), δ in practice and the worked example (practical.py).  Shared helpers:
common.py (ids, locators, readings, precision) and symbols.py; the truth models: truth.py.


The registration (``MEMOIR``) is in :mod:`.registration`, imported when first asked for.
"""
import importlib
import importlib.util


def __getattr__(name: str):
    """A submodule by its name; any other name (``MEMOIR``…) from :mod:`.registration`, imported on first use
    (PEP 562): importing one section, or the memoir's scene effects, does not import and build every section."""
    if name.startswith("__"):
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    if importlib.util.find_spec(f"{__name__}.{name}") is not None:
        return importlib.import_module(f"{__name__}.{name}")
    registration = importlib.import_module(f"{__name__}.registration")
    try:
        return getattr(registration, name)
    except AttributeError:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}") from None
