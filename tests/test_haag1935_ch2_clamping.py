"""Haag 1935, chapter II, n°31–35: the derivation of (116)–(134), its printed forms and its truth."""
import mpmath as mp
import pytest
import sympy as sp

from pendsym import verify
from derivations.haag1935 import ch1_model
from derivations.haag1935.ch2_clamping import derivation, printed, table
from derivations.haag1935.ch2_common import J, h_127, h_132, i_clamp, i_prime, j_eq, theta1
from derivations.haag1935.symbols import (Fn, K, X, Y, a, a1, beta, n_squared, theta, theta_ddot, theta_dot, vl, w0,
                                          zp)


def test_116_as_printed():
    assert all(sp.expand(d - p) == 0 for d, p in zip(derivation.eq116(), printed.eq116()))


def test_first_order_is_even_but_second_order_is_not():
    """The odd part of the bracket vanishes with the first-order (116) — and not with the second-order
    parts, so the proof is not vacuous."""
    assert derivation.first_order_odd_part() == 0
    e1, e2, e3 = (derivation.coefficient(e.subs(derivation.ERRORS, simultaneous=True), derivation.delta, 2)
                  for e in derivation.eq116())
    br = derivation.bracket_of_104(e1, e2, e3).subs(X, 1)
    flip = {theta: -theta, theta_dot: -theta_dot, theta_ddot: -theta_ddot, Y: -Y}
    assert sp.simplify(br - br.subs(flip, simultaneous=True)) != 0


def test_equilibrium_117_118_and_the_statics():
    assert sp.simplify(derivation.eq117_j() - printed.eq117_j()) == 0
    assert sp.expand(derivation.eq117_h() - printed.eq117_h()) == 0
    assert sp.simplify(derivation.eq118() - printed.eq118()) == 0
    # (23) at (h, j) gives Y = −i
    Y_at = ch1_model.Y_of_end().subs({beta: derivation.eq117_h(), theta: j_eq})
    assert sp.simplify(Y_at + i_clamp) == 0


def test_122_and_121():
    assert sp.expand(derivation.eq122() - (K * theta1 - i_clamp)) == 0
    assert sp.expand(derivation.eq121() + (a + zp) * theta1) == 0


def test_133_as_printed_but_129_and_delta_f_are_not():
    """(133) is the derivation's; (129) misses a factor 2 on aKi'(i' + 2j), Δf the sign of its ai'(aj + h)
    term (the sum of the printed (129) and Δf is not (133))."""
    assert sp.expand(derivation.eq133() - printed.eq133()) == 0
    d129 = sp.expand(derivation.eq129() - printed.eq129())
    assert sp.expand(d129 + n_squared / (2 * K) * a * K * i_prime * (i_prime + 2 * j_eq) * theta1) == 0
    dDf = sp.expand(derivation.eq132_delta_f() - printed.delta_f())
    assert sp.expand(dDf + n_squared / (2 * K) * theta1 * 4 * K / zp * a * i_prime * (a * j_eq + h_127)) == 0
    assert sp.expand(printed.q1_from_parts() - printed.eq133()) != 0


def test_a_hinge_has_no_clamping_error():
    """A blade reduced to a hinge at the clamp (vλ = w0 = a1 = 0, h = h' = F2 = 0, z' = −a): the rigid pendulum's
    period does not depend on the tilt of the clamp or on G off the rod, so Q1 = 0 (the derivation's j = −i − i')."""
    hinge = {vl: 0, w0: 0, a1: 0}
    j = derivation.eq117_j().subs(hinge)
    assert sp.simplify(j + i_clamp + i_prime) == 0
    Q1 = derivation.eq133().subs({j_eq: j, h_127: 0, h_132: 0, Fn(2): 0, zp: -a})
    assert sp.simplify(Q1) == 0
    assert sp.simplify(printed.q1_from_parts().subs({j_eq: j, h_127: 0, h_132: 0, Fn(2): 0, zp: -a})) != 0


def test_in_h_rejects_a_moment_that_is_not_h():
    try:
        derivation.in_h(J(1, 0))
    except ValueError:
        return
    raise AssertionError("∫φ1 ds is not a function of h, h', F_n")


def test_table_ids_and_size():
    ids = [s.id for s in table.specs()]
    assert len(ids) == len(set(ids))
    assert {f"haag1935.eq{n:03d}" for n in range(116, 135)} <= {i.rsplit(".", 1)[0] for i in ids}


@pytest.mark.slow
def test_the_truth_judges_the_printed_sum_against_133():
    """Against the exact tilted blade, ΔT/T = Q1/Q falls off like i⁴ with the derived (= printed (133)) Q1,
    only like i² with Q1 from the printed (129) + Δf."""
    spec = next(s for s in table.specs() if s.id.endswith("eq133.sum"))
    check = spec.check
    values = check.values("quick")
    with mp.workdps(30):
        tr = [check.truth(p, 30) for p in values]
        good = [t - check.at(derivation.eq133(), p) for p, t in zip(values, tr)]
        bad = [t - check.at(printed.q1_from_parts(), p) for p, t in zip(values, tr)]
    assert abs(verify.fit_order(values, good) - 4) < 0.2
    assert abs(verify.fit_order(values, bad) - 2) < 0.2
