"""A user's own perturbation problem: parsed safely, solved to order n, verified by integration.

The public names are :func:`solve`, :func:`load`, :class:`Problem` and :class:`ProblemError`;
``docs/solve.md`` documents the problem format.
"""
from .api import Solution, solve
from .averaging import NotAveraged
from .frequency import NotApplicable
from .parse import FormulaError
from .problem import Problem, ProblemError, from_dict, load
from .variation import NotPerSwing

# a problem pendsym cannot take: reported in one line (exit 2 from the command)
REFUSALS = (ProblemError, FormulaError, NotAveraged, NotApplicable, NotPerSwing)

__all__ = ["solve", "Solution", "load", "from_dict", "Problem", "ProblemError", "REFUSALS"]
