"""pendsym.scenes.program: a form's distinct nodes evaluated once each; the same number as SymPy's evaluation."""
import mpmath as mp
import pytest
import sympy as sp

from pendsym import codec
from pendsym.scenes import program

x, y, u = sp.symbols("x y u", positive=True)
s = sp.Symbol("s")


def _at(expr, values, dps=40):
    with mp.workdps(dps):
        return program.run(program.compile(expr), {k: mp.mpf(v) for k, v in values.items()})


@pytest.mark.parametrize("expr", [
    x**2 * sp.besselj(0, y) - sp.bessely(1, x * y) / 3 + sp.EulerGamma * sp.log(x),
    sp.tan(u) / u - 1 / sp.sin(u)**2 + sp.sqrt(x) + x**sp.Rational(-3, 2) + sp.Float("0.1234567890123456789012345", 25),
    sp.tanh(u / 2) * sp.sinh(u) + sp.exp(-x) * sp.pi + sp.cos(x) ** 3,
])
def test_a_form_is_sympys_number(expr):
    values = {"x": "0.71", "y": "2.3", "u": "1.3"}
    want = sp.N(expr.subs({sp.Symbol(k, positive=True): sp.Float(v, 50) for k, v in values.items()}), 40)
    got = _at(expr, values)
    with mp.workdps(50):
        assert abs(got - mp.mpf(str(want))) <= mp.mpf(10) ** -36 * abs(mp.mpf(str(want)))


def test_a_shared_subexpression_is_listed_once():
    inner = sp.besselj(0, x) * sp.bessely(1, y) - sp.besselj(1, x) * sp.bessely(0, y)
    expr = inner
    for n in range(40):                      # unfolded: 2^40 copies of inner
        expr = sp.Add(expr, expr * (n + 2), evaluate=False)
    prog = program.compile(expr)
    assert len(prog.code) < 6 * 40 + 20          # linear in the depth, not 2^40
    assert sum(op[0] == "fn" for op in prog.code) == 4


def test_piecewise_evaluates_only_its_chosen_branch():
    expr = sp.Piecewise((1 / u, u > 0), (sp.Integer(7), True))
    assert _at(expr, {"u": "0.5"}) == 2
    with pytest.raises(ZeroDivisionError):
        _at(1 / u, {"u": "0"})
    assert _at(sp.Piecewise((1 / (u - 1), u > 1), (sp.Integer(7), True)), {"u": "1"}) == 7


def test_an_integral_by_quadrature_with_outer_nodes_once():
    expr = sp.Integral(sp.besselj(0, s * x) * sp.besselj(1, y), (s, 0, 1))
    with mp.workdps(30):
        want = mp.quad(lambda t: mp.besselj(0, t * mp.mpf("0.7")), [0, 1]) * mp.besselj(1, mp.mpf("1.9"))
    got = _at(expr, {"x": "0.7", "y": "1.9"}, 30)
    assert abs(got - want) < mp.mpf(10) ** -27
    prog = program.compile(expr)
    bessel_y = [i for i, op in enumerate(prog.code) if op[:2] == ("fn", "besselj") and not prog.bound[i]]
    assert bessel_y                            # J1(y) is outside the integrand


def test_unsupported_nodes_are_refused():
    with pytest.raises(program.Unsupported):
        program.compile(sp.Function("f")(x))
    with pytest.raises(program.Unsupported):
        program.compile(sp.Integral(x * s, s))


def test_a_program_is_data_through_the_codec_and_a_foreign_name_is_refused():
    prog = program.compile(sp.besselj(0, x) + sp.pi * sp.Float("0.25", 30))
    back = codec.decode(codec.encode(prog))
    assert back == prog
    with mp.workdps(30):
        assert program.run(back, {"x": mp.mpf(1)}) == mp.besselj(0, 1) + mp.pi / 4
    bad = program.Program(("x",), (("in", 0), ("fn", "__import__", 0)), (False, False))
    with pytest.raises(program.Unsupported):
        program.run(bad, {"x": mp.mpf(1)})
    bad = program.Program((), (("const", "__class__"),), (False,))
    with pytest.raises(program.Unsupported):
        program.run(bad, {})


def test_an_endpoint_singularity_falls_back_to_tanh_sinh():
    """Gauss–Legendre is kept only when its error estimate is at the working precision: ∫₀¹ s^(−1/2) ds = 2."""
    got = _at(sp.Integral(1 / sp.sqrt(s * x), (s, 0, 1)), {"x": "1"}, 30)
    with mp.workdps(30):
        gauss = mp.quad(lambda t: 1 / mp.sqrt(t), [0, 1], method="gauss-legendre")
        assert abs(gauss - 2) > mp.mpf(10) ** -3                  # what Gauss–Legendre alone would give
        assert got == mp.quad(lambda t: 1 / mp.sqrt(t), [0, 1])   # tanh–sinh's
        assert abs(got - 2) < mp.mpf(10) ** -15
