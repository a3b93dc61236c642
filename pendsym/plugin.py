"""What a memoir package's ``__init__`` may delegate to the engine: lazy registration (PEP 562).

A memoir package that keeps its ``MEMOIR`` in a ``registration`` submodule writes one line,
``__getattr__ = lazy_package(__name__)``: importing one of its sections, or its scene effects,
then builds no other section, and ``MEMOIR`` is built when first asked for.
"""
from __future__ import annotations

import importlib
import importlib.util
from typing import Callable


def lazy_package(package: str, registration: str = "registration") -> Callable[[str], object]:
    """The module-level ``__getattr__`` of ``package``: a submodule by its name; any other name
    (``MEMOIR``, ``SECTIONS``…) from ``package.registration``, imported on first use."""
    def __getattr__(name: str):
        if name.startswith("__"):
            raise AttributeError(f"module {package!r} has no attribute {name!r}")
        if importlib.util.find_spec(f"{package}.{name}") is not None:
            return importlib.import_module(f"{package}.{name}")
        try:
            return getattr(importlib.import_module(f"{package}.{registration}"), name)
        except AttributeError:
            raise AttributeError(f"module {package!r} has no attribute {name!r}") from None
    return __getattr__
