"""Haag 1935, chapter VII, n°94–95, eqs. (286)–(290), and chapter VIII, n°103, eq. (318): the gravity pendulum's
clamping errors, direct and inverted.

Chapter II's derived (117)–(133) near the critical distance (a = a1 + ελ, ε → 0), in the two regimes of n°95:
the pendulum not regulated (j ~ 1/ε: (286), and n°94's tilt ∝ G) and regulated (i, i', j of one order: (287)–(289));
(290) from (117); (318) from (289) by u → iu, ε → −ε.  :mod:`.derivation` (the steps), :mod:`.printed` (the
formulas as printed, with their readings), :mod:`.truth` (the slow mode of the exact tilted blade),
:mod:`.table` (chapter VII's Results), :mod:`.table_inverted` (chapter VIII's).
"""
from . import table, table_inverted


def sections():
    """(module, title) of the chapter VII Result tables."""
    return ((table, "Chapter VII. Clamping errors of the gravity pendulum (286)–(290), n°94–95"),)


def inverted_sections():
    """(module, title) of the chapter VIII Result tables."""
    return ((table_inverted, "Chapter VIII. Clamping errors of the inverted blade (318), n°103"),)


__all__ = ["inverted_sections", "sections"]
