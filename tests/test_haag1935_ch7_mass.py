"""Haag 1935, chapter VII n°96 and chapter VIII n°103: the blade's inertia and weight in the gravity pendulum
(291)–(294), (319)–(320): the derivation, its printed forms and its truth (the blade with mass)."""
import mpmath as mp
import pytest
import sympy as sp

from pendsym import checks, massive_blade, stages, suspension
from derivations.haag1935.ch7_gravity import truth as gravity
from derivations.haag1935.ch7_gravity.symbols import eps
from derivations.haag1935.ch7_mass import derivation, table, table_inverted, truth
from derivations.haag1935.common import rid
from derivations.haag1935.symbols import lam, u

IDS = [spec.id for spec in table.specs() + table_inverted.specs()]


@pytest.fixture(scope="module")
def built():
    return stages.results(IDS)


class Derived:
    def __init__(self, derived):
        self.derived = derived


def test_principal_part_keeps_the_lowest_powers():
    x = sp.Symbol("x", positive=True)
    assert derivation.principal_part((3 + eps) / (2 * eps + eps**2 * x)) == sp.Rational(3, 2) / eps
    assert sp.simplify(derivation.principal_part((x + eps) / (1 + x * eps)) - x) == 0


def test_minus2_refuses_a_ratio_that_is_not_a_number():
    deps = {rid(294, "depsilon"): Derived(lam / eps), rid(270, "dT"): Derived(u / eps)}
    with pytest.raises(ValueError):
        derivation.depsilon_minus2(deps)


def test_294_follows_the_power_of_epsilon_in_292():
    """With ΔT/T ∝ 1/ε² instead of 1/ε the factor would be 1 + 2·2 = 5: the 3 is not typed in."""
    deps = {rid(292, "weight"): Derived(-sp.Symbol("J") / eps**2),
            rid(294, "minus2"): Derived(-2 * derivation.dT_T)}
    assert sp.simplify(derivation.period_294(deps) - 5 * derivation.DT_T * derivation.dT_T) == 0


@pytest.mark.slow
@pytest.mark.parametrize("rid_", IDS)
def test_derived_forms_equal_the_printed_ones(built, rid_):
    result = built[rid_]
    difference = result.derived_value - result.printed_value
    with mp.workdps(50):
        values = {sym: sp.Rational(13 + 7 * k, 10) for k, sym in enumerate(sorted(difference.free_symbols,
                                                                                    key=lambda s: s.name))}
        values.update({sym: sp.Rational(7, 10) for sym in difference.free_symbols if sym.name == "u"})
        assert abs(sp.N(difference.subs(values), 40)) < 1e-30


@pytest.mark.slow
def test_dT_per_degree_is_minus_half_depsilon(built):
    """n°96: dε/ε = −2dT/T, the number found by comparing with (270)."""
    assert built[rid(294, "minus2")].derived == -2 * derivation.dT_T
    assert sp.simplify(built[rid(294, "dT")].derived - 3 * derivation.DT_T * derivation.dT_T) == 0


def test_slowest_root_is_the_slow_mode_near_the_critical_distance():
    """massive_blade's ``slowest``: on the massless blade near a1 the root is the smaller n² of the two modes of
    pendsym.suspension (direct and inverted, g < 0), the default the principal (node above G) one."""
    for key, sign in (("u=2", 1), ("u=1", -1)):
        bl = gravity.base_blade(key, sign)
        a = truth.placed(key, sign, "1e-3", 30)
        g = sign * sp.Rational(gravity.G_VALUE)
        with mp.workdps(40):
            pair = suspension.modes(suspension.solve(bl, 30), suspension.number(a), mp.mpf("0.05"),
                                    suspension.number(g))
            slow = min(md.n2 for md in pair)
            n2 = massive_blade.principal_n2(massive_blade.MassiveBlade(bl, 0), a, sp.Rational(1, 20), g, 30, True)
            assert abs(n2 - slow) < mp.mpf(10) ** -25 * slow
            assert max(md.n2 for md in pair) > 10 * slow


def test_weight_against_the_blade_with_mass_and_a_wrong_sign_fails():
    """At ε = 10⁻³ on the uniform blade u = 2, (293) is right to about 10⁻³ relative, its opposite is not."""
    with mp.workdps(30):
        true = truth.period_change("u=2", 1, "0.001", "weight", 30)
        env = truth.blade_numbers("u=2", 1, 30)
        uu, e = env["u"], mp.mpf("0.001")
        formula = -env["m'"] / (8 * e) * (1 / uu**2 - 1 / mp.sinh(uu) ** 2)
        assert abs(true - formula) < mp.mpf("0.002") * abs(true)
        assert abs(true + formula) > abs(true)


def test_inverted_weight_delays():
    """(320): the weight of the inverted blade delays (1/u² < 1/sin²u), the truth agrees."""
    with mp.workdps(30):
        assert truth.period_change("u=1", -1, "0.001", "weight", 30) > 0


@pytest.mark.slow
@pytest.mark.parametrize("rid_", IDS)
def test_checks_pass(built, rid_):
    (comparison, _), evidence = stages.assessed(built[rid_])
    if isinstance(built[rid_].spec.check, checks.Chain):
        assert evidence is None
    else:
        assert evidence.passed, evidence
