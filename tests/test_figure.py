"""pendsym.figure and its report (pendsym.emit.figures): a figure declared by a memoir, sampled at
derive time (forms, kernels, truths, with their provenance), cached, and set after its Result."""
import math
import textwrap

import mpmath as mp
import pytest
import sympy as sp

from pendsym import derive, figure, keys, pipeline
from pendsym.emit import figures as figtex, latex
from pendsym.figure import Axis, Curve, Figure, Mark, Plot
from pendsym.result import Result, Source, Spec

x = sp.Symbol("x", positive=True)


def result(derived, printed=None, rid="m.q"):
    spec = Spec(id=rid, title=f"Result {rid[2:]}", source=Source("m", "n°1"), lhs="q", derive=lambda deps: derived,
                printed=(lambda: printed) if printed is not None else None)
    return Result(spec=spec, derived=derived, printed=printed)


def env(v):
    return {"x": v}


def square_figure(**kw):
    curves = kw.pop("curves", (
        Curve("derived", "derived", ("1", "2", "3"), result="m.q", env=env),
        Curve("printed", "printed", ("1", "2"), result="m.q", env=env, style="dashed"),
        Curve("truth", "truth", ("0.5", "4"), truth=lambda v, dps: v**2 + dps, describe="v² + dps", style="marks"),
    ))
    return Figure(id="m.fig.square", module=__name__, title="q against x", caption="Eq. (1).",
                  x=Axis("x"), y=Axis("q"), curves=curves, **kw)


# ----------------------------------------------------------------- records
def test_a_curve_says_where_its_points_come_from():
    with pytest.raises(ValueError, match="source"):
        Curve("c", "guess", ("1",), result="m.q", env=env)
    with pytest.raises(ValueError, match="truth"):
        Curve("c", "truth", ("1",), truth=lambda v, d: v)            # no description of the model
    with pytest.raises(ValueError, match="Result"):
        Curve("c", "derived", ("1",), env=env)
    with pytest.raises(ValueError, match="points"):
        Curve("c", "derived", (), result="m.q", env=env)
    assert "derived form of m.q" in Curve("c", "derived", ("1",), result="m.q", env=env).provenance()


def test_a_figure_is_placed_after_its_first_cited_result_unless_told():
    fig = square_figure()
    assert fig.cites == ("m.q",) and fig.place == "m.q" and fig.memoir == "m"
    assert square_figure(after="m.other").place == "m.other"


# ----------------------------------------------------------------- sampling
def test_sampling_evaluates_each_form_and_truth_at_its_points():
    plot = figure.sample(square_figure(dps=17), {"m.q": result(x**2, x**2 + 1)})
    derived, printed, truth = plot.series
    assert derived == ((1.0, 1.0), (2.0, 4.0), (3.0, 9.0))
    assert printed == ((1.0, 2.0), (2.0, 5.0))
    assert truth == ((0.5, 0.25 + 17), (4.0, 16.0 + 17))          # the truth runs at the figure's digits
    assert plot.notes == () and plot.seconds >= 0


def test_sampling_is_deterministic():
    fig, results = square_figure(), {"m.q": result(sp.sqrt(x) * sp.pi)}
    assert figure.sample(fig, results).series == figure.sample(fig, results).series


def test_a_kernel_curve_without_a_kernel_is_empty_and_said():
    fig = square_figure(curves=(Curve("kernel", "kernel", ("1", "2"), result="m.q", env=env),))
    plot = figure.sample(fig, {"m.q": result(x**2)})
    assert plot.series == ((),) and "no kernel of m.q is emitted" in plot.notes[0]
    drawn = figure.sample(fig, {"m.q": result(x**2)}, {"m.q": (lambda v: 3 * v, ["x"])})
    assert drawn.series == (((1.0, 3.0), (2.0, 6.0)),) and drawn.notes == ()


def test_undefined_values_are_none():
    fig = square_figure(curves=(Curve("d", "derived", ("0", "1"), result="m.q", env=env),))
    plot = figure.sample(fig, {"m.q": result(1 / (x - 1))})
    assert plot.series[0][1] == (1.0, None)


def test_the_key_covers_points_digits_and_cited_results():
    roots = ("pendsym",)
    base = figure.figure_key(square_figure(), {"m.q": "a"}, {}, roots)
    assert base == figure.figure_key(square_figure(), {"m.q": "a"}, {}, roots)
    assert base != figure.figure_key(square_figure(), {"m.q": "b"}, {}, roots)
    assert base != figure.figure_key(square_figure(dps=16), {"m.q": "a"}, {}, roots)
    moved = square_figure(curves=(Curve("derived", "derived", ("1", "2.5"), result="m.q", env=env),))
    assert base != figure.figure_key(moved, {"m.q": "a"}, {}, roots)


# ----------------------------------------------------------------- the report
def plot_of(fig, *series, notes=()):
    return Plot(fig.id, tuple(series), tuple(notes), 0.0)


def test_a_log_axis_drops_values_that_are_not_positive_and_says_so():
    fig = Figure(id="m.fig.f", module=__name__, title="t", caption="C.", x=Axis("x", log=True),
                 y=Axis("y", log=True), curves=(Curve("d", "derived", ("1", "2", "3"), result="m.q", env=env),))
    tex = figtex.figure_tex(fig, plot_of(fig, ((1.0, 2.0), (2.0, -1.0), (3.0, 4.0))), 1)
    assert "(1,2) (2,nan) (3,4)" in tex
    assert "1 of its 3 values are not positive" in tex
    assert "xmode=log" in tex and "ymode=log" in tex


def test_a_linear_frame_holds_far_values_at_its_edge_and_breaks_a_jump_across_it():
    fig = Figure(id="m.fig.f", module=__name__, title="t", caption="C.", x=Axis("x"), y=Axis("y", lo=-10, hi=10),
                 curves=(Curve("d", "derived", ("1",), result="m.q", env=env),), marks=(Mark(2.5, "end"),))
    points = ((1.0, 5.0), (2.0, -1e6), (3.0, 1e6), (4.0, 5.0))
    tex = figtex.figure_tex(fig, plot_of(fig, points), 3)
    # edge ±(10 + 20/4): -1e6 → -15, then a break before +1e6 → 15
    assert "(1,5) (2,-15) (3,nan) (3,15) (4,5)" in tex
    assert "axis cs:2.5,1" in tex and "{end}" in tex
    assert r"\textbf{Figure 3.}" in tex and "ymin=-10" in tex and "ymax=10" in tex


def test_the_caption_gives_provenance_and_digits():
    fig = square_figure(dps=12, form_dps=35)
    plot = figure.sample(fig, {"m.q": result(x**2, x**2)})
    tex = figtex.figure_tex(fig, plot, 1)
    assert "derived form of" in tex and "printed form of" in tex and "v² + dps".replace("²", "$^{2}$") in tex
    assert "35 digits" in tex and "12 working digits" in tex


def test_the_report_sets_the_figure_after_its_result_and_numbers_figures_in_order():
    a, b = result(x, rid="m.a"), result(x**2, rid="m.b")
    records = [pipeline.Record(r, "derived-only", "none printed", None) for r in (a, b)]
    first = Figure(id="m.fig.1", module=__name__, title="First figure", caption="C.", x=Axis("x"), y=Axis("y"),
                   curves=(Curve("d", "derived", ("1",), result="m.b", env=env),))
    second = Figure(id="m.fig.2", module=__name__, title="Second figure", caption="C.", x=Axis("x"), y=Axis("y"),
                    curves=(Curve("d", "derived", ("1",), result="m.b", env=env),), after="m.a")
    plots = [(f, plot_of(f, ((1.0, 1.0),))) for f in (first, second)]
    tex = latex.report("m", "A memoir", records, [], None, [(("m.a", "m.b"), "Chapter")], figures=plots,
                       swing_correction=False)
    at_a, at_b = tex.index(r"\subsection*{Result a}"), tex.index(r"\subsection*{Result b}")
    assert at_a < tex.index("Second figure") < at_b < tex.index("First figure")
    assert tex.index(r"\textbf{Figure 1.} \textit{Second") < tex.index(r"\textbf{Figure 2.} \textit{First")


# ----------------------------------------------------------------- end to end: a memoir declares a figure
TOY_WITH_FIGURE = '''
from pendsym.memoir import Memoir, Section
from toy_memoirs.toy import period
from . import figures

MEMOIR = Memoir(key="toy", title="A toy memoir with a figure", sections=(Section.of(period, "The period"),),
                figures=(figures.PERIOD,))
'''
TOY_FIGURE = '''
import mpmath as mp
from pendsym.figure import Axis, Curve, Figure
from toy_memoirs.toy import period


def env(al):
    return {"k": mp.mpf(period.K_CHECK), "alpha": al}


PERIOD = Figure(id="toy.fig.period", module=__name__, title="The period against the amplitude",
                caption="The period (2) against alpha.", x=Axis(r"\\alpha"), y=Axis("T"),
                curves=(Curve("(2) derived", "derived", ("0.1", "0.5", "1"), result="toy.T", env=env),
                        Curve("integrated", "truth", ("0.1", "1"), truth=period.swing_period,
                              describe="the pendulum integrated by mpmath odefun", style="marks")),
                dps=15)
'''


@pytest.fixture()
def toy_with_figure(monkeypatch, tmp_path):
    pkg = tmp_path / "figtoys" / "figtoy"
    pkg.mkdir(parents=True)
    (tmp_path / "figtoys" / "__init__.py").write_text("")
    (pkg / "__init__.py").write_text(textwrap.dedent(TOY_WITH_FIGURE))
    (pkg / "figures.py").write_text(textwrap.dedent(TOY_FIGURE))
    monkeypatch.syspath_prepend(str(tmp_path))
    monkeypatch.setenv("PENDSYM_MEMOIR_PACKAGES", "figtoys")
    monkeypatch.setenv("PENDSYM_CACHE", str(tmp_path / "cache"))
    return tmp_path


def test_a_memoir_figure_is_sampled_cached_and_drawn(toy_with_figure):
    lines = []
    outcome = derive.derive_all(toy_with_figure / "out", level="quick", log=lines.append)
    assert outcome.failed == ()
    assert any(line.startswith("sampled 1 figures (1 anew)") and "toy.fig.period" in line for line in lines)
    tex = (toy_with_figure / "out" / "tex" / "toy.tex").read_text()
    assert tex.index(r"\subsection*{Period to second order") < tex.index("The period against the amplitude")
    # the truth's points: the integrated period, T(α) = 4K(sin(α/2))/k (an independent closed form)
    for al in (0.1, 1.0):
        exact = 4 * float(mp.ellipk(math.sin(al / 2) ** 2)) / float(period_k())
        assert f"({al:.7g},{exact:.7g})" in tex
    again = []
    derive.derive_all(toy_with_figure / "out2", level="quick", log=again.append)
    assert any(line.startswith("sampled 1 figures (0 anew)") for line in again)


def period_k():
    from toy_memoirs.toy import period
    return mp.mpf(period.K_CHECK)


def test_no_memoir_is_named_in_the_engine(root):
    for path in [root / "pendsym" / "figure.py", root / "pendsym" / "emit" / "figures.py"]:
        text = path.read_text().lower()
        assert not any(name in text for name in ("haag", "charbonnier", "cellerier"))
    assert keys.SPINE and "pendsym.figure" not in {m for s in keys.SPINE for m in keys.closure(s, ("pendsym",))}
