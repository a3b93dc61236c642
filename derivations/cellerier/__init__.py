"""Ch. Cellérier, Mouvement simultané d'un pendule et de ses supports."""
from . import elastic_bar, equation, general, pressures, static_support

SPECS = (equation.specs() + general.specs() + pressures.specs() + static_support.specs()
         + elastic_bar.specs())
