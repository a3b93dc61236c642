"""A toy memoir with two Results, to show that a memoir is a plug-in (no edit to pendsym/)."""
from pendsym.memoir import Memoir, Section

from . import period

MEMOIR = Memoir(key="toy", title="A toy memoir: the period of the simple pendulum", sections=(
    Section.of(period, "The period, small and finite amplitude"),
))
