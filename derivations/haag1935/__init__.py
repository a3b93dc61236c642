"""Haag 1935, Théorie de la suspension élastique des pendules: chapter I (any M(s), eqs. (1)–(87))
and chapter III, the uniform blade (eqs. (156)–(183))."""
from pendsym.memoir import Memoir, Section, headings_by

from . import ch1_blade, ch1_launch, ch1_motion, ch1_shape, ch1_variations, ch3_uniform
from . import ch7_gravity, ch8_inverted

CHAPTER_1 = (
    Section.of(ch1_blade, "Chapter I. The equations of the blade and the functions v, w (1)–(20)"),
    Section.of(ch1_motion, "Chapter I. End loads, equations of motion, foci, periods, existence (21)–(41)"),
    Section.of(ch1_variations, "Chapter I. Small variations of the periods, temperature, g (42)–(63)"),
    Section.of(ch1_launch, "Chapter I. Principal oscillation and launching (64)–(76)"),
    Section.of(ch1_shape, "Chapter I. Shape, fatigue, suppleness, centre of flexion, fork (77)–(87)"),
)
SECTIONS = CHAPTER_1 + tuple(Section.of(module, title) for module, title in ch3_uniform.sections())
CHAPTER_7 = (Section.of(ch7_gravity, "Chapter VII. The gravity pendulum with direct suspension (255)–(285)"),
             Section.of(ch8_inverted, "Chapter VIII. The inverted blade (307)–(317)"))
SECTIONS = SECTIONS + CHAPTER_7
_CH1 = {sec.module for sec in CHAPTER_1}
_CH3 = {sec.module for sec in SECTIONS[len(CHAPTER_1):len(SECTIONS) - len(CHAPTER_7)]}
_CH7 = {sec.module for sec in CHAPTER_7}


def _eqs(lo: int, hi: int, modules: set):
    """Takes a Spec of the given section modules whose equation number lies in [lo, hi]."""
    ids = {s.id for sec in SECTIONS if sec.module in modules for s in sec.specs}
    return lambda spec: spec.id in ids and lo <= int(spec.id.split(".")[1][2:]) <= hi


MEMOIR = Memoir(
    key="haag1935",
    title=("J. Haag, Théorie de la suspension élastique des pendules (1935), chapter I: first approximation "
           "for any M(s), eqs. (1)–(87); chapter III: the uniform blade, eqs. (156)–(183)"),
    sections=SECTIONS,
    headings=headings_by(tuple(s for sec in SECTIONS for s in sec.specs), (
        ("Chapter I. The equations and the functions v, w for any M(s) (1)–(20)", _eqs(1, 20, _CH1)),
        ("Chapter I. End loads, equations of motion, foci, periods, existence (21)–(41)", _eqs(21, 41, _CH1)),
        ("Chapter I. Small variations of the periods, temperature, g (42)–(63)", _eqs(42, 63, _CH1)),
        ("Chapter I. Principal oscillation, launching, shape, fatigue, suppleness, fork (64)–(87)",
         _eqs(64, 87, _CH1)),
        ("Chapter III. The uniform blade: v, w and the functions U, U1, U2 (156)–(161)", _eqs(156, 161, _CH3)),
        ("Chapter III. The integrals Γ_n (162)–(166)", _eqs(162, 166, _CH3)),
        ("Chapter III. The integrals F_n and F (167)–(170)", _eqs(167, 170, _CH3)),
        ("Chapter III. Foci, K and the period of the uniform blade (n°50)", _eqs(30, 37, _CH3)),
        ("Chapter III. Shape, fatigue, I_λ and J (171)–(183)", _eqs(171, 183, _CH3)),
        ("Chapter VII. The gravity pendulum with direct suspension (255)–(285), n°82–93",
         lambda spec: spec.id in {s.id for s in CHAPTER_7[0].specs}),
        ("Chapter VIII. The inverted blade (307)–(317), n°100–103",
         lambda spec: spec.id in {s.id for s in CHAPTER_7[1].specs}),
    )),
    cost=2.0,
    # whether the uniform blade's kernels are emitted is decided where they are declared
    kernels=ch3_uniform.KERNELS_READY,
)
