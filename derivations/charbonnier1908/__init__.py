"""Charbonnier 1908, Sur la théorie des perturbations du pendule (suite et fin), §IV–VI, n°18–35.

Sections: the general formulas (n°8–9, rebuilt), the perturbing function of the angle and its
monomials (n°18–20), the examples on the angle (n°21–23), the elastic thread (n°24–26), the
length growing with time (n°27–35).  Shared helpers: common.py (ids, sources, readings,
precision, kernel arguments) and symbols.py; the models of the truth: truth.py; the chain every
worked example follows: chain.py.


The registration (``MEMOIR``) is in :mod:`.registration`, imported when first asked for.
"""
import importlib
import importlib.util


def __getattr__(name: str):
    """A submodule by its name; any other name (``MEMOIR``, ``SECTIONS``…) from :mod:`.registration`, imported on first use
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
