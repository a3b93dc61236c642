"""Ch. Cellérier, Mouvement simultané d'un pendule et de ses supports."""
from . import equation, general, pressures

SPECS = equation.specs() + general.specs() + pressures.specs()
