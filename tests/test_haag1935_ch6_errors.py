"""Haag 1935, chapter VI, n°80–81: the clamping errors (246)–(250) and the blade's inertia and weight (251)–(254):
derivation steps, printed forms and the truth of derivation_errors / truth_errors."""
import mpmath as mp
import sympy as sp

from derivations.haag1935.ch2_clamping import printed as ch2_printed
from derivations.haag1935.ch2_common import J, h_127, h_132, i_clamp, i_prime, j_eq
from derivations.haag1935.ch6_short_blade import derivation_errors as derivation
from derivations.haag1935.ch6_short_blade import printed_errors as printed
from derivations.haag1935.ch6_short_blade import truth, truth_errors
from derivations.haag1935.symbols import DEFS, K, a1, lam, u, wl


class Built:
    def __init__(self, expr):
        self.derived = expr


def test_246_from_the_printed_117():
    """(117) as printed, a1 = −w_λ: j + i + i' at its leading order in λ/a is (246)."""
    deps = {"haag1935.eq117.j": Built(ch2_printed.eq117_j()), "haag1935.eq041.a1": Built(-wl)}
    assert sp.simplify(derivation.sum_246(deps) - printed.sum_246()) == 0


def test_the_thin_limits_of_the_printed_249_251_253_are_the_printed_250_252_254():
    for eq, thin, wide, narrow in ((249, derivation.dT_250, printed.dT_249, printed.dT_250),
                                   (251, derivation.inertia_252, printed.inertia_251, printed.inertia_252),
                                   (253, derivation.weight_254, printed.weight_253, printed.weight_254)):
        deps = {f"haag1935.eq{eq}.dT": Built(wide().subs(dict(DEFS)))}
        assert sp.simplify(thin(deps) - narrow()) == 0, eq


def test_the_weight_dominates_the_inertia_for_a_short_blade():
    """Haag's closing remark of n°81: |(254)| ≫ (252) when λ/a is small (here λ/a = 1/20, u = 6)."""
    values = {u: 6, lam: 1, sp.Symbol("a", positive=True): 20}
    inertia, weight = (sp.N(f().subs(values)) for f in (printed.inertia_252, printed.weight_254))
    assert inertia > 0 > weight and abs(weight) > 10 * inertia


def test_the_moments_are_read_off_the_polynomials_in_K():
    A, B, C = sp.symbols("A B C")
    deps = {"haag1935.eq169.F2": Built(A * K**2 + 2 * B * K + C)}
    table, solved = derivation.moments(deps)
    assert table == {J(2, 0): A, J(1, 1): B, J(0, 2): C}
    hp = sp.expand(ch2_printed.eq132().subs(K, 1).subs(solved))
    assert not hp.atoms(J) and hp.has(*derivation.C)


def test_h_and_h_prime_by_quadrature_agree_with_chapter_two_in_moments():
    """The truth's h = ∫φψ ds and h' = ∫(24Kψ²φ − 24iψφ² − 12ψ²φ²) ds against (127), (132) as printed with the
    moments J(p, q) = ∫φ1^pφ2^q ds by quadrature (the uniform blade, K = 0.9, i = 1, j = −0.4)."""
    dps = 20
    with mp.workdps(dps):
        sol = truth.shot("uniform", dps)
        env = {"a": mp.mpf(10), "v_lambda": sol.vl, "w_lambda": sol.wl, "K": mp.mpf("0.9")}
        got = truth_errors.clamping_inputs(env, "uniform", dps)
        moments = {J(p, q): sp.Float(sol.integrate(lambda s, p=p, q=q: (lambda st: (1 + st[1]) ** p * st[3] ** q)(
            sol.state(s))), dps) for p in range(5) for q in range(5) if 2 <= p + q <= 4}
        values = {K: sp.Float("0.9", dps), i_clamp: 1, j_eq: sp.Float(got["j"], dps)}
        for formula, key in ((ch2_printed.eq127(), "h"), (ch2_printed.eq132(), "h'")):
            expected = sp.N(formula.subs(moments).subs(values), dps)
            assert abs(mp.mpf(expected) - got[key]) < mp.mpf("1e-15") * (1 + abs(got[key])), key


def test_248_approaches_the_exact_133_as_the_blade_shortens():
    """(248) at the modes of a = 1000λ against (133) at the same modes: relative difference O(λ/a)."""
    env = truth.state("tapered", truth.FIXED, "1e-3", 20)
    env.update(truth_errors.clamping_inputs(env, "tapered", 20))
    formula = printed.Q1_248().subs({h_127: env["h"], h_132: env["h'"], i_clamp: env["i"]})
    formula = formula.subs({sp.Function("F")(2): env["F_2"], sp.Symbol("v_0", real=True): env["v_0"],
                            lam: env["lambda"]})
    exact = truth_errors.exact_Q1(env)
    assert not sp.sympify(formula).free_symbols
    assert abs(mp.mpf(sp.N(formula, 20)) / exact - 1) < mp.mpf("5e-3")


def test_i_prime_drops_out_of_248():
    assert not printed.Q1_248().has(i_prime) and not printed.dT_249().has(i_prime)
    assert not printed.sum_246().has(a1)


def test_253_against_the_blade_with_mass_at_a_thousand_lengths():
    """The period change of the blade's weight from pendsym.massive_blade (m'/m = 10⁻⁸, a = 1000λ) against
    the printed (253): relative difference O(λ/a)."""
    env = {"lambda": mp.mpf("0.1"), "a": mp.mpf(100), "dps": 20}
    with mp.workdps(20):
        value = truth_errors.massive_change("uniform", False)(env)
    formula = printed.weight_253().subs(dict(DEFS)).subs({u: 2, lam: sp.Rational(1, 10),
                                                         sp.Symbol("a", positive=True): 100,
                                                         sp.Symbol("m'", positive=True): sp.Rational(1, 10**8),
                                                         sp.Symbol("m", positive=True): 1})
    assert value < 0 and abs(value / mp.mpf(sp.N(formula, 20)) - 1) < mp.mpf("5e-3")
