"""Haag 1935, chapter II, n°36–43, eqs. (135)–(150): the blade's inertia and weight, Le Rolland's moment law,
internal friction.

:mod:`.derivation` (SymPy, from (104)–(105) of n°28), :mod:`.printed` (the text and its readings), :mod:`.truth`
(the pendulum on a blade with mass, :mod:`pendsym.massive_blade`; the stiffer linear blade; the exact blade with
the law M(c + a2c³), :mod:`pendsym.bending_law`; the reduced damped equation), :mod:`.table_mass` (n°36–37) and
:mod:`.table_law` (n°38–43; (145) and n°43 derived in :mod:`.derivation_experiment`).
"""
from . import table_law, table_mass

# (141) is checked at q = 2 on the exact blade's orbits at (111)'s amplitudes: one worker with (111)
LAW_RESULTS = (table_law.YOUNG,)


def sections():
    """(module, title) of the two Result tables."""
    return ((table_mass, "Chapter II. The blade's inertia and weight (135)–(136)"),
            (table_law, "Chapter II. Le Rolland's moment law, internal friction (137)–(150)"))


__all__ = ["LAW_RESULTS", "sections", "table_law", "table_mass"]
