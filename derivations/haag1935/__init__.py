"""Haag 1935, Théorie de la suspension élastique des pendules: chapter III, the uniform blade (eqs. (156)–(183))."""
from . import ch3_uniform

SPECS = ch3_uniform.specs()
