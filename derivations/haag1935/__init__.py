"""Haag 1935, Théorie de la suspension élastique des pendules: chapter III, the uniform blade (eqs. (156)–(183))."""
from . import ch3_uniform

SPECS = ch3_uniform.specs()

TITLE = "J. Haag, Théorie de la suspension élastique des pendules (1935), chapter III: the uniform blade, eqs. (156)–(183)"


def _eqs(lo: int, hi: int) -> tuple[str, ...]:
    return tuple(s.id for s in SPECS if lo <= int(s.id.split(".")[1][2:]) <= hi)


SECTIONS = (
    (_eqs(156, 161), "The uniform blade: v, w and the functions U, U1, U2 (156)–(161)"),
    (_eqs(162, 166), "The integrals Γ_n (162)–(166)"),
    (_eqs(167, 170), "The integrals F_n and F (167)–(170)"),
    (_eqs(30, 37), "Foci, K and the period of the uniform blade (n°50)"),
    (_eqs(171, 183), "Shape, fatigue, I_λ and J (171)–(183)"),
)

# Whether the uniform blade's kernels are emitted is decided where they are declared.
KERNELS_READY = ch3_uniform.KERNELS_READY
