"""Haag 1935, Théorie de la suspension élastique des pendules: the chapters rebuilt so far.

Each chapter is a tuple of sections (a section package's ``sections()`` or Section.of lines);
the report's headings group the Results of a chapter by equation number.


The registration (``MEMOIR``) is in :mod:`.registration`, imported when first asked for.
"""
import importlib
import importlib.util


def __getattr__(name: str):
    """A submodule by its name; any other name (``MEMOIR``, ``SECTIONS``, ``CHAPTER_n``…) from :mod:`.registration`, imported on first use
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
