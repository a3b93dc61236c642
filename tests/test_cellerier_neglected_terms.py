"""derivations.cellerier.neglected_terms: δ at finite amplitude, the change of amplitude α1."""
import sympy as sp

from derivations.cellerier import neglected_terms
from derivations.cellerier.symbols import K
from pendsym import stages


def test_the_support_forcing_is_first_order_in_K():
    forcing = neglected_terms.support_forcing()
    assert sp.simplify(forcing - K * sp.diff(forcing, K)) == 0 and forcing != 0


def test_alpha1_vanishes_at_first_order_for_every_amplitude():
    built = stages.results(["cellerier.alpha1_static", "cellerier.alpha1_leading"])
    assert built["cellerier.alpha1_static"].derived == 0
    assert built["cellerier.alpha1_leading"].derived == 0
