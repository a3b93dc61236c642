"""The registration of the memoir (``MEMOIR``: its sections, headings, affinities), moved out of the package's
``__init__`` so that importing one section does not build them all (see ``__init__.__getattr__``)."""
from pendsym.memoir import Memoir, Section, headings_by

from . import ch1_blade, ch1_launch, ch1_motion, ch1_shape, ch1_variations, ch2_general, ch3_uniform
from . import ch2_clamping, ch2_dissymmetry, ch2_perturbations
from .ch2_general import table_designer
from . import ch4_thread, ch5_point, ch6_short_blade, ch7_gravity, ch8_inverted, ch9_holes
from . import ch7_clamping, ch7_dissymmetry, ch7_isochronism, ch7_mass
from .ch2_general import figures as ch2_figures
from .ch7_gravity import figures as ch7_figures
from .ch8_inverted import figures as ch8_figures
from .ch9_holes import figures as ch9_figures
from .memoir_order import equation


def _of(package) -> tuple[Section, ...]:
    """The sections of a chapter package (its ``sections()``: (module, title) pairs)."""
    return tuple(Section.of(module, title) for module, title in package.sections())


def _inverted(package) -> tuple[Section, ...]:
    """The chapter VIII sections of a chapter VII package (its ``inverted_sections()``)."""
    return tuple(Section.of(module, title) for module, title in package.inverted_sections())


CHAPTER_1 = (
    Section.of(ch1_blade, "Chapter I. The equations of the blade and the functions v, w (1)–(20)"),
    Section.of(ch1_motion, "Chapter I. End loads, equations of motion, foci, periods, existence (21)–(41)"),
    # its checks differentiate the same varied blades (the stencils of ch1_variations.truth)
    Section.of(ch1_variations, "Chapter I. Small variations of the periods, temperature, g (42)–(63)", shared=True),
    Section.of(ch1_launch, "Chapter I. Principal oscillation and launching (64)–(76)"),
    Section.of(ch1_shape, "Chapter I. Shape, fatigue, suppleness, centre of flexion, fork (77)–(87)"),
)
CHAPTER_2 = (
    Section.of(ch2_general, "Chapter II. General theory of perturbations and the isochronism error (88)–(115)"),
    Section.of(ch2_clamping, "Chapter II. Clamping errors and their interaction with the isochronism error (116)–(134)"),
    # the checks of (135)–(136) share the blades with mass and their quadratures
    Section.of(ch2_perturbations.table_mass, "Chapter II. The blade's inertia and weight (135)–(136)", shared=True),
    Section.of(ch2_perturbations.table_law, "Chapter II. Le Rolland's moment law, internal friction (137)–(150)"),
    Section.of(ch2_dissymmetry, "Chapter II. The dissymmetric blade, the symmetric clock, friction with clamping "
                                "errors (151)–(155)"),
    # derived-only coefficients of the short uniform blade, with kernels; their checks share chapter VI's modes
    Section.of(table_designer, "Chapter II. The designer's coefficients of the short uniform blade", shared=True),
)
CHAPTER_3 = _of(ch3_uniform)
CHAPTER_4 = (Section.of(ch4_thread, "Chapter IV. The thread as the limit u → ∞ of the uniform blade (184)–(197)"),)
CHAPTER_5 = (Section.of(ch5_point, "Chapter V. Point pendulum, point mass, equal periods, beats (198)–(211)"),)
CHAPTER_6 = _of(ch6_short_blade)
CHAPTER_7 = ((Section.of(ch7_gravity, "Chapter VII. The gravity pendulum with direct suspension (255)–(285)"),)
             + _of(ch7_isochronism) + _of(ch7_clamping) + _of(ch7_mass) + _of(ch7_dissymmetry))
CHAPTER_8 = ((Section.of(ch8_inverted, "Chapter VIII. The inverted blade (302)–(317)"),)
             + _inverted(ch7_clamping) + _inverted(ch7_mass))
CHAPTER_9 = _of(ch9_holes)
SECTIONS = CHAPTER_1 + CHAPTER_2 + CHAPTER_3 + CHAPTER_4 + CHAPTER_5 + CHAPTER_6 + CHAPTER_7 + CHAPTER_8 + CHAPTER_9


def _eqs(lo: int, hi: int, chapter: tuple[Section, ...]):
    """Takes a Spec of the chapter whose equation number lies in [lo, hi]."""
    ids = {s.id for sec in chapter for s in sec.specs}
    return lambda spec: spec.id in ids and lo <= equation(spec) <= hi


HEADINGS = (
    ("Chapter I. The equations and the functions v, w for any M(s) (1)–(20)", _eqs(1, 20, CHAPTER_1)),
    ("Chapter I. End loads, equations of motion, foci, periods, existence (21)–(41)", _eqs(21, 41, CHAPTER_1)),
    ("Chapter I. Small variations of the periods, temperature, g (42)–(63)", _eqs(42, 63, CHAPTER_1)),
    ("Chapter I. Principal oscillation, launching, shape, fatigue, suppleness, fork (64)–(87)",
     _eqs(64, 87, CHAPTER_1)),
    ("Chapter II. General theory of perturbations: f, ΔX, ΔY, ΔN (88)–(105)", _eqs(88, 105, CHAPTER_2)),
    ("Chapter II. The isochronism error and the classical formula (106)–(115)", _eqs(106, 115, CHAPTER_2)),
    ("Chapter II. Clamping errors (116)–(134)", _eqs(116, 134, CHAPTER_2)),
    ("Chapter II. The blade's inertia and weight, Le Rolland's moment law, internal friction (135)–(150)",
     _eqs(135, 150, CHAPTER_2)),
    ("Chapter II. The dissymmetric blade, the symmetric clock, friction with clamping errors (151)–(155)",
     _eqs(151, 155, CHAPTER_2)),
    ("Chapter III. The uniform blade: v, w and the functions U, U1, U2 (156)–(161)", _eqs(156, 161, CHAPTER_3)),
    ("Chapter III. The integrals Γ_n (162)–(166)", _eqs(162, 166, CHAPTER_3)),
    ("Chapter III. The integrals F_n and F (167)–(170)", _eqs(167, 170, CHAPTER_3)),
    ("Chapter III. Foci, K and the period of the uniform blade (n°50)", _eqs(30, 37, CHAPTER_3)),
    ("Chapter III. Shape, fatigue, I_λ and J (171)–(183)", _eqs(171, 183, CHAPTER_3)),
    ("Chapter IV. The thread: limits u → ∞ and the direct study (184)–(197)", _eqs(0, 999, CHAPTER_4)),
    ("Chapter V. Point pendulum, point mass, equal periods, beats (198)–(211)", _eqs(0, 999, CHAPTER_5)),
    ("Chapter VI. The short blade: foci, period, Δl, Q, temperature (212)–(223)", _eqs(212, 223, CHAPTER_6)),
    ("Chapter VI. The short blade: parasitic vibration, suppleness, centre of flexion (224)–(240)",
     _eqs(224, 240, CHAPTER_6)),
    ("Chapter VI. The short blade: perturbations, isochronism, clamping errors, inertia and weight (241)–(254)",
     _eqs(241, 254, CHAPTER_6)),
    ("Chapter VII. The gravity pendulum with direct suspension (255)–(280), n°82–91", _eqs(0, 280, CHAPTER_7)),
    ("Chapter VII. The gravity pendulum's perturbations (281)–(301), n°92–99", _eqs(281, 999, CHAPTER_7)),
    ("Chapter VIII. The inverted blade (302)–(320), n°100–103", _eqs(0, 999, CHAPTER_8)),
    ("Chapter IX. The rectangular hole (321)–(333)", _eqs(321, 333, CHAPTER_9)),
    ("Chapter IX. The rhombus hole (334)–(346)", _eqs(334, 346, CHAPTER_9)),
)

MEMOIR = Memoir(
    key="haag1935",
    title=("J. Haag, Théorie de la suspension élastique des pendules (1935): chapter I, first approximation "
           "for any M(s), eqs. (1)–(87); chapter II, n°26–46, the second approximation: the isochronism and "
           "clamping errors, the blade's inertia and weight, internal friction, the dissymmetric blade, "
           "eqs. (88)–(155); chapter III, the uniform blade, eqs. (156)–(183); chapters IV–V, "
           "the thread, the point pendulum and beats, eqs. (184)–(211); chapter VI, the short blade, "
           "eqs. (212)–(254); chapters VII–VIII, the gravity pendulum direct and inverted, eqs. (255)–(320); "
           "chapter IX, blades with a hole, eqs. (321)–(346)"),
    sections=SECTIONS,
    headings=headings_by(tuple(s for sec in SECTIONS for s in sec.specs), HEADINGS),
    # (111), (112), n°25's claims on (64), (85) and (141) at q = 2 are checked on the same nonlinear orbits
    affinity=(ch2_general.PERIOD_RESULTS + ch1_shape.ORBIT_RESULTS + ch2_perturbations.LAW_RESULTS,
              ch2_clamping.TILT_RESULTS),
    cost=2.0,
    # whether the uniform blade's kernels are emitted is decided where they are declared
    kernels=ch3_uniform.KERNELS_READY,
    figures=ch2_figures.FIGURES + ch7_figures.FIGURES + ch8_figures.FIGURES + ch9_figures.FIGURES,
)
