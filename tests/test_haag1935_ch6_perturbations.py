"""Haag 1935, chapter VI, n°74 and n°79: the blow's fatigue (233)–(234) and the isochronism error (242)–(245):
derivation steps, printed forms and the truth of derivation_perturbations / truth_perturbations."""
import mpmath as mp
import sympy as sp

from derivations.haag1935.ch6_short_blade import derivation_perturbations as derivation
from derivations.haag1935.ch6_short_blade import printed_perturbations as printed
from derivations.haag1935.ch6_short_blade import truth, truth_perturbations
from derivations.haag1935.symbols import DEFS, lam, u


class Built:
    def __init__(self, expr):
        self.derived = expr


def test_exponentially_small_terms_are_dropped_and_powers_of_one_over_u_kept():
    expr = (sp.tanh(u / 2) + 1 / sp.sinh(u)) / u + 1 / sp.tanh(u) ** 2
    assert sp.simplify(derivation.exponentially_small_dropped(expr) - (1 / u + 1)) == 0


def test_the_thin_limit_of_the_printed_244_is_the_printed_245():
    deps = {"haag1935.eq244.dT": Built(printed.dT_244().subs(dict(DEFS)))}
    assert sp.simplify(derivation.dT_245(deps) - printed.dT_245()) == 0


def test_244_tends_to_the_simple_pendulum_as_u_grows():
    """Haag's check of (244): for u = ∞ the bracket vanishes (ΔT/T = θ0²/16)."""
    bracket = sp.limit(printed.dT_244().subs(dict(DEFS)) - derivation.theta_0**2 / 16, u, sp.oo)
    assert bracket == 0


def test_F_of_the_shot_uniform_blade_against_243():
    with mp.workdps(30):
        for point in truth_perturbations.F_points("quick", 30):
            formula = printed.F_243().subs(dict(DEFS)).subs(u, sp.Float(point.env["u"], 30))
            assert abs(point.truth - mp.mpf(sp.N(formula, 30))) < mp.mpf("1e-20"), point.label


def test_the_blow_stresses_at_both_clamps_agree_to_the_first_order():
    """"la plus grande fatigue a lieu simultanément aux deux encastrements": |T'_0|/|T'_λ| → 1 as λ/a → 0."""
    gaps = []
    for epsilon in ("1e-2", "1e-3"):
        env = truth.state("uniform", truth.RATIO, epsilon, 20)
        env = {**env, **truth_perturbations.blow_inputs(env, "uniform", 20)}
        at_O = truth_perturbations.blow_stress("uniform", "T0")(env)
        at_A = truth_perturbations.blow_stress("uniform", "Tl")(env)
        gaps.append(abs(at_O / at_A - 1))
    assert gaps[1] < gaps[0] / 5


def test_the_exact_isochronism_ratio_tends_to_one():
    env = truth.state("uniform", truth.FIXED, "1e-3", 20)
    env = {**env, **truth_perturbations.isochronism_inputs(env, "uniform", 20)}
    assert abs(truth_perturbations.exact_ratio(env) - 1) < 1e-2


def test_241_is_the_rigid_axis_limit_of_104():
    from derivations.haag1935.ch2_common import J, eps1, eps2, eps3, eps_lambda
    from derivations.haag1935.symbols import K, Y, a, beta1, theta, vl, wl, zp
    E1, E2 = sp.symbols("E_1 E_2")
    bracket = (E1 * K + E2 + K * Y * eps1 * J(2, 0) + K * eps1 * theta * J(1, 1) + Y * eps1 * J(1, 1)
               + a * eps1 * theta + eps1 * theta * J(0, 2) + eps2 * zp - eps3 - eps_lambda)
    deps = {"haag1935.eq216.K": Built(1 + (vl + wl) / a), "haag1935.eq215.zp": Built(-a + vl - beta1)}
    deps["haag1935.eq104.f"] = Built(bracket)
    assert sp.simplify(derivation.f_241(deps) - printed.f_241()) == 0
    deps["haag1935.eq104.f"] = Built(bracket - eps2 * zp)
    assert sp.simplify(derivation.f_241(deps) - printed.f_241()) != 0


def test_le_rollands_isochronism_fails_the_thin_check_that_245_passes():
    """The footnote of n°79: Le Rolland's −(θ0²/16)(λ/a)(1 − 2U/u) does not tend to the simple pendulum of length
    a + λ; the check of (245) refuses it (its residual does not vanish as u → ∞) and accepts (245)."""
    from derivations.haag1935.ch6_short_blade import table_blow_isochronism
    from derivations.haag1935.symbols import U, a
    from pendsym import checks
    from pendsym.result import Result
    spec = next(s for s in table_blow_isochronism.specs() if s.id == "haag1935.eq245.dT")
    theta_0 = derivation.theta_0
    le_rolland = (theta_0**2 / 16 - theta_0**2 / 16 * lam / a * (1 - 2 * U / u)).subs(dict(DEFS))
    assert not checks.run(spec.check, Result(spec, le_rolland), "quick").passed
    assert checks.run(spec.check, Result(spec, printed.dT_245()), "quick").passed
