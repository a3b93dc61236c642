"""Haag 1935, chapter VII, n°86, 88–90: (269), (274)–(277), (279): derivation steps and the launch truth of
derivation_launch / checks_launch."""
import mpmath as mp
import pytest
import sympy as sp

from derivations.haag1935.ch7_gravity import checks_launch, derivation_launch as derivation, printed_launch as printed
from derivations.haag1935.ch7_gravity.symbols import a_r, l_syn
from derivations.haag1935.symbols import g, lam, u


class Built:
    def __init__(self, expr):
        self.derived = expr


WL = Built(lam / (u * sp.tanh(u)))     # (159)


def test_269_is_the_small_u_limit_of_268():
    period = g / l_syn + g * lam / (3 * a_r * l_syn) + sp.Symbol("C", positive=True)
    deps = {"haag1935.eq268.period": Built(period), "haag1935.eq159.wl": WL}
    assert sp.simplify(derivation.g_difference_269(deps) - printed.g_difference_269()) == 0


def test_269_refuses_a_period_not_linear_in_g():
    deps = {"haag1935.eq268.period": Built(g**2 / l_syn), "haag1935.eq159.wl": WL}
    with pytest.raises(ValueError):
        derivation.g_difference_269(deps)


def test_the_blow_excites_the_parasitic_vibration_far_more_than_the_static_release():
    """n°88: the ratio of (276) to (275), R√(ελβ1)/(R² + z'²), is very small: launch by a blow is to be avoided."""
    env = checks_launch.launch_env("u=2", "1e-4", 20)
    static = checks_launch.LAUNCH_QUANTITY["ratio"](env, "u=2", 20)
    blow = checks_launch.blow_ratio(env, "u=2", 20)
    with mp.workdps(20):
        assert abs(blow / static) < mp.mpf("0.05")
        assert abs(static) > 100          # the principal oscillation dominates after a static release
