"""Haag 1935, chapter VII, n°96, eqs. (291)–(294), and chapter VIII, n°103, eqs. (319)–(320): the inertia and
weight of the blade of a gravity pendulum, direct and inverted.

:mod:`.derivation` (chapter II's (135)–(136) at a = a1 ± ελ, principal part in ε; (294) from chapter I's
temperature laws and (270); u → iu for chapter VIII), :mod:`.printed` (the text and its readings), :mod:`.truth`
(pendsym.massive_blade at a = a1 ± ελ placed on the truth, the slow root; warmed blades for (294)),
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
