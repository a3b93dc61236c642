"""Ch. Cellérier, Mouvement simultané d'un pendule et de ses supports."""
from . import elastic_bar, equation, general, pressures, static_support

SPECS = (equation.specs() + general.specs() + pressures.specs() + static_support.specs()
         + elastic_bar.specs())

TITLE = "Ch. Cellérier, Mouvement simultané d'un pendule et de ses supports"
SECTIONS = (
    (tuple(s.id for s in equation.specs()), "The equation of motion of a pendulum on a moving support"),
    (tuple(s.id for s in general.specs()), "Perturbation at finite amplitude: δ and α1 (the earlier memoir, rebuilt)"),
    (tuple(s.id for s in pressures.specs()), "The pressures on the knife edge"),
    (tuple(s.id for s in static_support.specs()), "A support of static compliance K"),
    (tuple(s.id for s in elastic_bar.specs()), "The support as an elastic bar"),
)


# Checks that integrate the same trajectories (lru-cached in derivations.cellerier.truth): the
# pipeline runs each group in one worker so that the second reuses the first's integrations.
# A step checked "through" the Results it feeds (pipeline.through) goes after them.
AFFINITY = (
    ("cellerier.delta_general", "cellerier.alpha1_general", "cellerier.delta_support"),
    ("cellerier.delta_static_finite", "cellerier.alpha1_static"),
    ("cellerier.delta_static", "cellerier.y1dd", "cellerier.delta_static_integral"),
    ("cellerier.example_delta", "cellerier.delta_practical"),
    ("cellerier.equation", "cellerier.equation_l"),
)
