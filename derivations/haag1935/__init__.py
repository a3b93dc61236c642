"""Haag 1935, Théorie de la suspension élastique des pendules: chapter I (any M(s), eqs. (1)–(87))
and chapter III, the uniform blade (eqs. (156)–(183))."""
from . import ch1_launch, ch1_motion, ch1_variations, ch3_uniform

SPECS = ch1_motion.specs() + ch1_variations.specs() + ch1_launch.specs() + ch3_uniform.specs()

TITLE = ("J. Haag, Théorie de la suspension élastique des pendules (1935), chapter I: first approximation "
         "for any M(s), eqs. (1)–(87); chapter III: the uniform blade, eqs. (156)–(183)")


def _eqs(lo: int, hi: int, chapter=None) -> tuple[str, ...]:
    mods = chapter or (ch1_motion, ch1_variations, ch1_launch, ch3_uniform)
    ids = [s.id for m in mods for s in m.specs()]
    return tuple(i for i in ids if lo <= int(i.split(".")[1][2:]) <= hi)


_CH3 = (ch3_uniform,)
_CH1 = (ch1_motion, ch1_variations, ch1_launch)

SECTIONS = tuple(sec for sec in (
    (_eqs(1, 20, _CH1), "Chapter I. The equations and the functions v, w for any M(s) (1)–(20)"),
    (_eqs(21, 41, _CH1), "Chapter I. End loads, equations of motion, foci, periods, existence (21)–(41)"),
    (_eqs(42, 63, _CH1), "Chapter I. Small variations of the periods, temperature, g (42)–(63)"),
    (_eqs(64, 87, _CH1), "Chapter I. Principal oscillation, launching, shape, fatigue, suppleness, fork (64)–(87)"),
    (_eqs(156, 161, _CH3), "Chapter III. The uniform blade: v, w and the functions U, U1, U2 (156)–(161)"),
    (_eqs(162, 166, _CH3), "Chapter III. The integrals Γ_n (162)–(166)"),
    (_eqs(167, 170, _CH3), "Chapter III. The integrals F_n and F (167)–(170)"),
    (_eqs(30, 37, _CH3), "Chapter III. Foci, K and the period of the uniform blade (n°50)"),
    (_eqs(171, 183, _CH3), "Chapter III. Shape, fatigue, I_λ and J (171)–(183)"),
) if sec[0])

# Whether the uniform blade's kernels are emitted is decided where they are declared.
KERNELS_READY = ch3_uniform.KERNELS_READY
