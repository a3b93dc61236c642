"""The figure of chapter II (n°29): the period against the amplitude (derivations.haag1935.ch2_general.figures)."""
import mpmath as mp
import pytest

from derivations.haag1935 import ch2_general
from derivations.haag1935.ch2_general import figures, truth
from pendsym import figure, registry


def test_the_exact_blade_reuses_the_check_amplitudes():
    """The exact blade's abscissae are (111)'s order-check amplitudes, mapped back to the check's own numbers (so
    that the cached solves are found), and at most two more."""
    check = list(truth.amplitudes("full"))
    points = figures.truth_points()
    assert len(points) - len(check) <= 2
    with mp.workdps(figures.PERIOD.dps):         # as figure.sample reads the abscissae
        for theta0, p in zip(check, points):
            # the solve's cache key holds nstr(θ0, 40): the figure's must be the check's
            assert mp.nstr(figures._amplitude(mp.mpf(p)), 40) == mp.nstr(theta0, 40)
    assert figures._amplitude(mp.mpf("0.05")) == mp.mpf("0.05")


def test_the_figure_is_registered():
    from derivations.haag1935 import ch2_figures   # noqa: F401  (the registration line)
    assert figures.PERIOD in registry.memoir("haag1935").figures
    assert figures.PERIOD.place in {s.id for s in ch2_general.specs()}


@pytest.mark.slow
def test_the_formula_and_the_rigid_pendulum_curves():
    """The (111) curve is (Q'/Q)θ0²/16: a constant times θ0²; the rigid pendulum's is θ0²/16(1 + O(θ0²)); and the
    blade lowers the coefficient (Q'/Q < 1 on this case, as (111)'s check measures on the exact blade)."""
    cheap = figure.Figure(**{**figures.PERIOD.__dict__, "curves": figures.PERIOD.curves[:2]})
    plot = figure.sample(cheap, registry.build(list(cheap.cites)))
    formula, rigid = plot.series
    ratios = [y / (x * x / 16) for x, y in formula]
    assert max(ratios) - min(ratios) < 1e-12 * abs(ratios[0])
    assert 0 < ratios[0] < 1
    for x, y in rigid:
        assert abs(y / (x * x / 16) - 1) < x * x
