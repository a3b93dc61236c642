"""The series and Taylor pieces of a leaf, shortened and evaluated by Estrin's scheme (issue #11, point 4).

A piece keeps only the terms its interval needs (`needed_terms`), and a long polynomial is evaluated
with a Horner head and an Estrin tail (`EstrinTail`).  References here are the leaves' own functions
at 50 digits (mpmath), not the forms under test.
"""
import math

import mpmath as mp
import pytest
import sympy as sp

from pendsym.emit.kernels import series as sr
from pendsym.emit.kernels.leaves import _in_double
from pendsym.emit.kernels.plan import body
from pendsym.emit.kernels.printing import KernelC

u = sp.Symbol("u", positive=True)
LEAF = 1 - 2 * sp.tanh(u / 2) / u          # β1/λ of (159): cancels like u²/12 as u → 0


def _ulp_err(got: float, true) -> float:
    return float(abs(mp.mpf(got) - true)) / math.ulp(float(true))


def _depth(text: str) -> int:
    """The deepest nesting of parentheses in printed code (a Horner chain nests one level per term)."""
    most = level = 0
    for ch in text:
        level += (ch == "(") - (ch == ")")
        most = max(most, level)
    return most


@pytest.mark.slow
def test_a_series_below_a_small_switch_needs_few_terms_and_keeps_its_accuracy():
    m, cs = sr.SERIES.coefficients(LEAF, u)
    short, n = sr.SERIES.below(m, cs, u, 0.125)
    _, n_long = sr.SERIES.below(m, cs, u, 1.5)
    assert n <= 20 < n_long              # (0.125/π)² per term in u²: ~8 terms; 1.5 needs most of the 65
    f = _in_double(short, u)
    with mp.workdps(50):
        for v in (1e-6, 1e-3, 0.05, 0.1, math.nextafter(0.125, 0)):
            true = 1 - 2 * mp.tanh(mp.mpf(v) / 2) / mp.mpf(v)
            assert _ulp_err(f(v), true) <= 1.5, v


def test_estrin_tail_is_the_polynomial():
    cs = [sp.Float(1) / (j + 1) ** 2 for j in range(30)]
    w = sp.Symbol("w")
    for scheme in (sr.ESTRIN, sr.HORNER, sr.EstrinTail(head=0, longer=0)):
        f = sp.lambdify([w], scheme(cs, w).replace(lambda e: e.func.__name__ == "Grouped", lambda e: e.args[0]))
        for v in (0.0, 0.3, -0.7):
            exact = sum(float(c) * v**j for j, c in enumerate(cs))
            assert abs(f(v) - exact) <= 1e-14 * sum(abs(float(c) * v**j) for j, c in enumerate(cs))


@pytest.mark.slow
def test_a_long_taylor_piece_has_no_long_dependency_chain_and_holds_its_accuracy():
    ref = sp.lambdify([u], LEAF, modules="mpmath")
    form, dbl = sr.TAYLOR(ref, 2, 0.25, 3.0, u)
    assert _depth(KernelC().doprint(body(form))) <= 20
    c0, cs = sr.taylor_coeffs(ref, 2, 0.25, 3.0)
    assert _depth(KernelC().doprint(body(sr.taylor_expr(c0, cs, 2, u)))) >= 45      # Horner: one level a term
    with mp.workdps(50):
        for i in range(1, 40):
            v = 0.25 + 2.75 * i / 40
            true = 1 - 2 * mp.tanh(mp.mpf(v) / 2) / mp.mpf(v)
            assert _ulp_err(dbl(v), true) <= 1.5, v


def test_needed_terms_drops_only_what_is_below_the_tolerance():
    cs = [1.0 / 2**j for j in range(100)]           # Σ (y/2)^j on [0, 1]: the tail from j is ~2^(1−j), the value ~2
    assert sr.needed_terms(cs, 1.0) == 64           # 2^-63 ≤ 2^-64·2: the terms from 64 on are dropped, 63 is not
    assert sr.needed_terms(cs, 0.5) < 64


def test_a_test_on_leaves_becomes_a_select_and_each_leaf_is_printed_once():
    from pendsym.emit.kernels.leaves import conditions_as_selects
    from pendsym.emit.kernels.plan import Grouped, Select
    K = sp.Symbol("K")
    leaf = sp.Symbol("leaf_0")
    skel = sp.Piecewise((1 / (K - leaf), leaf * K > 0), (K + leaf, True))
    sel = conditions_as_selects(skel, {leaf: LEAF})
    assert isinstance(sel, Select) and sel.args[0] == leaf * K
    piece = sp.Piecewise((u**2 / 12, u < sp.Rational(1, 8)), (LEAF, True))
    form = sel.xreplace({leaf: Grouped(piece)})
    text = KernelC().doprint(body(form))
    assert text.count("tanh(") == 1          # as a Piecewise condition it was folded: once in the test, once per branch
    f = _in_double(form.subs(K, 2), u)
    with mp.workdps(50):
        for v in (0.01, 3.0):
            x = mp.mpf(v)
            leaf_v = x**2 / 12 if v < 0.125 else 1 - 2 * mp.tanh(x / 2) / x      # the piece's own value
            assert _ulp_err(f(v), 1 / (2 - leaf_v)) <= 4, v                       # 2·leaf > 0: the first branch


def test_an_exponential_shared_by_far_forms_is_called_once():
    from pendsym.emit.kernels.plan import Grouped, shared_exponentials
    E = Grouped(sp.exp(-u / 2))
    K = sp.Symbol("K")
    form = (sp.Piecewise((u, u < 1), (E**2 / u, True)) * K
            + sp.Piecewise((u**3, u < sp.Rational(1, 2)), (Grouped(E**2) ** 5 - 1, True)))
    assert shared_exponentials(form) == [E]
    text = KernelC().doprint(body(form))
    assert text.count("exp(") == 1 and "pow(" not in text
    assert text.index("exp(") < text.index("if (")
