"""Haag 1935's figures (chapters II, VII, VIII, IX): the data each one draws, checked against what is found
independently of the figure (roots by findroot, the chapter's other Results), so that a figure that draws
the wrong thing fails here.  Chapter II's own data: test_haag1935_ch2_figures.py."""
import dataclasses
import math

import mpmath as mp
import pytest

from pendsym import figure, stages, verify
from derivations.haag1935 import MEMOIR
from derivations.haag1935.ch7_gravity import figures as ch7
from derivations.haag1935.ch8_inverted import figures as ch8, truth as ch8_truth
from derivations.haag1935.ch9_holes import figures as ch9, rhombus_g2_kernel

pytestmark = pytest.mark.slow


@pytest.fixture(scope="module")
def plots():
    """The figures as make derive sampled them (read from the cache under the derive's keys; sampled here when no
    derive did), and the Results they cite."""
    cites = [i for f in MEMOIR.figures for i in f.cites]
    built = stages.results(ids=cites)
    return stages.figure_plots(MEMOIR.key), built


def test_the_figures_read_from_the_derive_are_what_sampling_gives(plots):
    """The cheapest figure (its form curves only, at a few points) sampled here equals the derive's plot at those
    points: a plot read from the cache is the sampling of these very Results."""
    fig, plot = plots[0]["haag1935.fig.sensitivity"]
    built = plots[1]
    forms = [c for c in fig.curves if c.source in ("derived", "printed")]
    assert forms
    cheap = dataclasses.replace(fig, curves=tuple(dataclasses.replace(c, points=c.points[::7]) for c in forms))
    again = figure.sample(cheap, built)
    whole = dict(zip((c.label for c in fig.curves), plot.series))
    for curve, points in zip(cheap.curves, again.series):
        assert points and set(points) <= set(whole[curve.label]), curve.label


def series(plots, fig_id, label):
    fig, plot = plots[0][fig_id]
    return dict(zip((c.label for c in fig.curves), plot.series))[label]


def test_the_memoir_registers_one_figure_per_chapter_each_after_a_result_of_it(plots):
    ids = {s.id for s in MEMOIR.specs}
    assert [f.id for f in MEMOIR.figures] == ["haag1935.fig.period_amplitude", "haag1935.fig.sensitivity",
                                              "haag1935.fig.windows", "haag1935.fig.rhombus_G2"]
    assert [f.place for f in MEMOIR.figures] == ["haag1935.eq112.Qp", "haag1935.eq264.G", "haag1935.eq309.weights",
                                                 "haag1935.eq346.G2"]
    assert all(f.place in ids for f in MEMOIR.figures)


# ----------------------------------------------------------------- VIII: the stability windows
def sign_changes(points):
    ys = [(x, y) for x, y in points if y is not None]
    return [(a[0], b[0]) for a, b in zip(ys, ys[1:]) if (a[1] > 0) != (b[1] > 0)]


def test_the_smaller_n2_changes_sign_exactly_at_the_window_ends_found_by_findroot(plots):
    smaller = series(plots, "haag1935.fig.windows", "smaller n²")
    brackets = sign_changes(smaller)
    assert len(brackets) == 3, brackets
    with mp.workdps(20):
        ratio = lambda u: float((2 * u / mp.pi) ** 2)      # noqa: E731  mg/P = (2u/π)²
        a = mp.mpf(ch8.A_FIGURE)
        ends = [ratio(ch8_truth.upper_end("3.11", a, 20)), ratio(ch8_truth.lower_end("8.99", 20)),
                ratio(ch8_truth.upper_end("9.41", a, 20))]
        # 2x1 from tan x = x alone (no blade): the lower end of the window n = 1
        x1 = mp.findroot(lambda t: mp.tan(t) - t, mp.mpf("4.49"))
        assert abs(ratio(2 * x1) - ends[1]) < 1e-6
    for (lo, hi), end in zip(brackets, ends):
        assert lo < end < hi
    # Haag's marks: the footnote of n°102 and (309); the upper ends approach them as a → −∞ (λ/|a| = 0.1 here)
    assert [m.x for m in plots[0]["haag1935.fig.windows"][0].marks] == [4, 32.7, 36]
    assert abs(ends[1] - 32.7) < 0.05 and 0 < 4 - ends[0] < 0.2 and 0 < 36 - ends[2] < 0.2


def test_both_n2_are_positive_inside_the_windows_and_not_outside(plots):
    smaller = dict(series(plots, "haag1935.fig.windows", "smaller n²"))
    larger = dict(series(plots, "haag1935.fig.windows", "larger n²"))
    for x, y in smaller.items():
        stable = x < 3.9 or 32.8 < x < 35.9
        unstable = 4 < x < 32.7 or x > 36
        assert y is not None and larger[x] >= y
        if stable:
            assert y > 0
        if unstable:
            assert y < 0


# ----------------------------------------------------------------- VII: G against u
def test_the_truth_of_G_is_the_derived_principal_part_less_one_to_relative_order_eps(plots):
    built = plots[1]
    derived = built["haag1935.eq263.G"].derived_value
    truth = series(plots, "haag1935.fig.sensitivity", "truth")
    assert len(truth) == 10
    for u, G in truth:
        with mp.workdps(30):
            principal = float(verify.value_at(derived, {"u": mp.mpf(u), "varepsilon": mp.mpf(ch7.EPS)}))
        # G = −1 + G2/Q (62): the principal part less one, the rest of relative order ε
        assert abs(G / (principal - 1) - 1) < 2 * float(ch7.EPS), (u, G, principal)
        assert abs(G / principal - 1) > abs(G / (principal - 1) - 1)


def test_the_u_small_form_meets_the_truth_at_small_u_only(plots):
    small = dict(series(plots, "haag1935.fig.sensitivity", "(264) derived, u small"))
    truth = dict(series(plots, "haag1935.fig.sensitivity", "truth"))
    nearest = lambda u: min(small, key=lambda x: abs(math.log(x / u)))     # noqa: E731
    assert abs(small[nearest(0.1)] / truth[0.1] - 1) < 0.01
    assert small[nearest(10.0)] / truth[10.0] < 0.25


# ----------------------------------------------------------------- IX: G2 of the rhombus hole
def test_the_derived_G2_meets_the_shot_blade_and_the_printed_one_does_not(plots):
    derived = dict(series(plots, "haag1935.fig.rhombus_G2", "(346) derived"))
    printed = dict(series(plots, "haag1935.fig.rhombus_G2", "(346) printed"))
    truth = series(plots, "haag1935.fig.rhombus_G2", "truth")
    assert truth[0][0] == 1e-8 and truth[-1][0] == 1e3
    built = plots[1]["haag1935.eq346.G2"]
    for k, G2 in truth:
        with mp.workdps(40):
            env = ch9.env(mp.mpf(k))
            assert abs(verify.value_at(built.derived_value, env) / G2 - 1) < 1e-8
    # as k → 0 the printed form grows like (ω² − 1)/k, ω² = 1/M0 = 2
    assert abs(printed[1e-8] * 1e-8 - 1) < 1e-3 and abs(derived[1e-8] / truth[0][1] - 1) < 1e-8
    # the uniform inverted blade at k → 0: G2 = ω²∫w² ds, w = −cos ωs/(ω sin ωλ) ((313): w0, wλ), by quadrature
    omega, lam = mp.sqrt(2), mp.mpf(ch9.LAMBDA)                 # the figure's λ (1 since session 11)
    uniform = omega**2 * mp.quad(lambda s: (mp.cos(omega * s) / (omega * mp.sin(omega * lam))) ** 2, [0, lam])
    assert abs(truth[0][1] / uniform - 1) < 1e-6


def test_the_blade_is_stable_at_every_k_drawn_and_the_kernel_meets_the_derived_form(plots):
    """β_1 < 0 at every k of the truth; the emitted kernel of G_2/λ (λ = 1) is drawn from k = 1e-8 to its domain's end
    q = 5 (rhombus_g2_kernel.Q_ARG; none beyond: it raises there) and agrees with the derived (346) at 40 digits within 1e-14 relative."""
    for k, _ in series(plots, "haag1935.fig.rhombus_G2", "truth"):
        assert ch9.beta1(mp.mpf(k), 15) < 0
    kernel = series(plots, "haag1935.fig.rhombus_G2", "stable kernel")
    derived = dict(series(plots, "haag1935.fig.rhombus_G2", "(346) derived"))
    drawn = [(k, y) for k, y in kernel if y is not None]
    end = rhombus_g2_kernel.Q_ARG.hi
    inside = [k for k, _ in kernel if k <= end]
    assert [k for k, _ in drawn] == inside and inside[0] == 1e-8 and inside[-1] > 3
    assert all(y is None for k, y in kernel if k > end)
    for k, y in drawn:
        assert abs(y / derived[k] - 1) < 1e-14, k


def test_no_result_key_covers_a_figure_module():
    """A figure's module is outside every section's imports: editing a figure re-checks no Result."""
    from pendsym import keys
    roots = ("pendsym", "derivations")
    for sec in MEMOIR.sections:
        assert not any(m.endswith(".figures") or m == "pendsym.figure" for m in keys.closure(sec.module, roots))
