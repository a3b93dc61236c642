"""Charbonnier 1908, Sur la théorie des perturbations du pendule (suite et fin), §IV–VI, n°18–35.

Sections: general formulas and monomials (n°8–9 rebuilt, n°18–20), the
examples on the angle (n°21–23), the elastic thread (n°24–26), the length
growing with time (n°27–35).
"""
from . import angle_examples, elastic, general, variable_length

SPECS = general.specs() + angle_examples.specs() + elastic.specs() + variable_length.specs()

TITLE = ("P. Charbonnier, Sur la théorie des perturbations du pendule (suite et fin), "
         "Nouvelles annales de mathématiques, 4e série, t. 8 (1908), p. 220–238, n°18–35")
SECTIONS = (
    ("8-9", "General formulas (n°8–9, not in the file, rebuilt)"),
    ("18-20", "§IV. The perturbing function depends on the angle: general formulas, monomials, J_m (n°18–20)"),
    ("21-21", "n°21. Second term of the period"),
    ("22-22", "n°22. Thread winding on a curve"),
    ("23-23", "n°23. The cycloidal pendulum"),
    ("24-26", "§V. Pendulum with an elastic thread (n°24–26)"),
    ("27-35", "§VI. Pendulum of variable length (n°27–35)"),
)
