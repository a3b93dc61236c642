"""derivations.cellerier.elastic_bar: the support as an elastic bar, the lumped support."""
import mpmath as mp
import sympy as sp

from derivations.cellerier import elastic_bar
from derivations.cellerier.symbols import K, M, a, c, g, l, x
from pendsym import stages


def test_the_forced_bar_and_its_slow_limit():
    built = stages.results(["cellerier.K_ac", "cellerier.bar_dynamic_correction"])
    particular = built["cellerier.bar_particular"].derived
    assert sp.simplify(particular - elastic_bar.bar_particular_printed()) == 0
    assert built["cellerier.K_ac"].derived == a * c
    assert built["cellerier.bar_dynamic_correction"].derived == x**2 / 3


def test_the_modal_sum_at_a_slow_load():
    with mp.workdps(20):
        xv = mp.mpf("0.01")
        assert abs(elastic_bar.modal_tip(xv) - (1 + xv**2 / 3)) < mp.mpf("1e-8")


def test_the_lumped_correction():
    assert sp.simplify(elastic_bar.lumped_derived({}) - K * M * g / l) == 0
