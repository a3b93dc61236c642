"""The registration of the memoir (``MEMOIR``: its sections, headings, affinities), moved out of the package's
``__init__`` so that importing one section does not build them all (see ``__init__.__getattr__``)."""
import re

from pendsym.memoir import Memoir, Section, headings_by

from . import angle, angle_examples, common, elastic, general, variable_length

SECTIONS = (
    Section.of(general, "General formulas (n°8–9, rebuilt)"),
    Section.of(angle, "The perturbing function depends on the angle: general formulas, monomials, J_m (n°18–20)"),
    Section.of(angle_examples, "The worked examples on the angle (n°21–23)"),
    Section.of(elastic, "Pendulum with an elastic thread (n°24–26)"),
    Section.of(variable_length, "Pendulum of variable length (n°27–35)"),
)


def paragraphs(lo: int, hi: int):
    """Takes a Spec whose paragraph n° lies in [lo, hi]."""
    def takes(spec) -> bool:
        m = re.search(r"(\d+)", spec.source.para)
        return m is not None and lo <= int(m.group(1)) <= hi
    return takes


MEMOIR = Memoir(
    key=common.MEMOIR,
    title=("P. Charbonnier, Sur la théorie des perturbations du pendule (suite et fin), "
           "Nouvelles annales de mathématiques, 4e série, t. 8 (1908), p. 220–238, n°18–35"),
    sections=SECTIONS,
    headings=headings_by(tuple(s for sec in SECTIONS for s in sec.specs), (
        ("General formulas (n°8–9, not in the file, rebuilt)", paragraphs(8, 9)),
        ("IV. The perturbing function depends on the angle: general formulas, monomials, J_m (n°18–20)",
         paragraphs(18, 20)),
        ("n°21. Second term of the period", paragraphs(21, 21)),
        ("n°22. Thread winding on a curve", paragraphs(22, 22)),
        ("n°23. The cycloidal pendulum", paragraphs(23, 23)),
        ("V. Pendulum with an elastic thread (n°24–26)", paragraphs(24, 26)),
        ("VI. Pendulum of variable length (n°27–35)", paragraphs(27, 35)),
    )),
    cost=1.0,
    swing_correction="n21_dT",   # ΔT of n°21 (T α²/16): make bench sets T + ΔT beside the exact swing time
)
