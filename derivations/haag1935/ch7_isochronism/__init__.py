"""Haag 1935, chapter VII, n°92–93 and n°97, eqs. (281)–(284): the gravity pendulum's perturbations in general,
its isochronism error, the flexion-law correction and internal friction.

:mod:`.table` (the Results).
"""
from . import table


def sections():
    """(module, title) of the chapter VII Result tables."""
    return ((table, "Chapter VII. Perturbations of the gravity pendulum, isochronism error (281)–(284), n°92–93, 97"),)


__all__ = ["sections"]
