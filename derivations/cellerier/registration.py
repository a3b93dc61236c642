"""The registration of the memoir (``MEMOIR``: its sections, headings, affinities), moved out of the package's
``__init__`` so that importing one section does not build them all (see ``__init__.__getattr__``)."""
from pendsym.memoir import Memoir, Section

from . import common, elastic_bar, equation, general, neglected_terms, practical, pressures, static_support

MEMOIR = Memoir(
    key=common.MEMOIR,
    title="Ch. Cellérier, Mouvement simultané d'un pendule et de ses supports",
    sections=(
        Section.of(equation, "The equation of motion of a pendulum on a moving support"),
        Section.of(general, "Perturbation at finite amplitude: δ and α1 (the earlier memoir, rebuilt)"),
        Section.of(pressures, "The pressures on the knife edge"),
        Section.of(static_support, "A support of static compliance K"),
        Section.of(neglected_terms, "The neglected terms: δ at finite amplitude and the change of amplitude"),
        Section.of(elastic_bar, "The support as an elastic bar"),
        Section.of(practical, "δ in practice: the test force and the worked example"),
    ),
    # Checks that integrate the same trajectories (lru-cached in derivations.cellerier.truth): each
    # group runs in one worker so that the second reuses the first's integrations.
    affinity=(
        ("cellerier.delta_general", "cellerier.alpha1_general", "cellerier.delta_support"),
        ("cellerier.delta_static_finite", "cellerier.alpha1_static"),
        ("cellerier.delta_static", "cellerier.y1dd", "cellerier.delta_static_integral"),
        ("cellerier.example_delta", "cellerier.delta_practical"),
        ("cellerier.equation", "cellerier.equation_l"),
    ),
    cost=3.0,
)
