"""derivations.cellerier.general: δ and α1 of the earlier memoir."""
import sympy as sp

from derivations.cellerier import general
from derivations.cellerier.symbols import alpha, h, phi, u
from pendsym import pipeline, stages


def test_printed_and_derived_agree_on_test_functions():
    built = stages.results(["cellerier.delta_general", "cellerier.alpha1_general"])
    for rid in ("cellerier.delta_general", "cellerier.alpha1_general"):
        assert pipeline.compare(built[rid])[0] == "match", rid


def test_the_printed_delta_of_a_constant_u_vanishes():
    # ∫_0^π cos φ dφ = 0: a constant moment does not change the swing time at leading order
    assert general.delta_printed().replace(u, sp.Lambda(phi, 1)).doit() == 0
    assert sp.simplify(general.alpha1_printed().replace(u, sp.Lambda(phi, 1)).doit()
                       - 4 / h * sp.tan(alpha / 2)) == 0


def test_u_of_the_test_forcing_is_odd_at_small_amplitude():
    U = general.u_of_phi_timefree()
    assert U.free_symbols <= {alpha, phi}
