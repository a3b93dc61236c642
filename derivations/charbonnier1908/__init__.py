"""Charbonnier 1908, Sur la théorie des perturbations du pendule (suite et fin), §IV–VI, n°18–35.

Sections: the general formulas (n°8–9, rebuilt), the perturbing function of the angle and its
monomials (n°18–20), the examples on the angle (n°21–23), the elastic thread (n°24–26), the
length growing with time (n°27–35).  Shared helpers: common.py (ids, sources, readings,
precision, kernel arguments) and symbols.py; the models of the truth: truth.py; the chain every
worked example follows: chain.py.


The registration (``MEMOIR``) is in :mod:`.registration`, imported when first asked for.
"""
from pendsym.plugin import lazy_package

__getattr__ = lazy_package(__name__)
