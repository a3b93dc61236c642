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
