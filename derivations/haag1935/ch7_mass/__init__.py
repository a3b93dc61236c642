"""Haag 1935, chapter VII, n°96, eqs. (291)–(294), and chapter VIII, n°103, eqs. (319)–(320): the inertia and
weight of the blade of a gravity pendulum, direct and inverted.

:mod:`.table` (chapter VII's Results), :mod:`.table_inverted` (chapter VIII's).
"""
from . import table, table_inverted


def sections():
    """(module, title) of the chapter VII Result tables."""
    return ((table, "Chapter VII. The blade's inertia and weight in the gravity pendulum (291)–(294), n°96"),)


def inverted_sections():
    """(module, title) of the chapter VIII Result tables."""
    return ((table_inverted, "Chapter VIII. The inverted blade's inertia and weight (319)–(320), n°103"),)


__all__ = ["inverted_sections", "sections"]
