"""Charbonnier 1908, Sur la théorie des perturbations du pendule (suite et fin), §IV–VI, n°18–35."""
from . import general

SPECS = general.specs()
