"""Haag 1935, chapter VII, n°98–99, eqs. (295)–(301): the dissymmetric blade of a gravity pendulum with an
unbalance j; the extremes of the period and how to measure ε.

:mod:`.table` (the Results).
"""
from . import table


def sections():
    """(module, title) of the chapter VII Result tables."""
    return ((table, "Chapter VII. The dissymmetric blade of the gravity pendulum (295)–(301), n°98–99"),)


__all__ = ["sections"]
