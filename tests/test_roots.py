"""pendsym.roots: the quadratic's roots without cancellation."""
import math

import mpmath as mp
import pytest
import sympy as sp

from pendsym.roots import quadratic_roots

z, p, q = sp.symbols("z p q", real=True)


def test_each_branch_is_the_textbook_root():
    plus, minus = quadratic_roots(sp.Poly(z**2 + p * z + q, z))
    root = sp.sqrt(p**2 / 4 - q)
    for pw, textbook in ((plus, -p / 2 + root), (minus, -p / 2 - root)):
        for branch, _cond in pw.args:
            assert sp.simplify(sp.radsimp(branch - textbook)) == 0


@pytest.mark.parametrize("pv", [1e8, -1e8, 3.0, -3.0])
def test_small_root_keeps_its_digits_where_the_textbook_form_cancels(pv):
    qv = -1.0
    forms = quadratic_roots(sp.Poly(z**2 + p * z + q, z))
    plus, minus = (sp.lambdify([p, q], f, modules="math")(pv, qv) for f in forms)
    with mp.workdps(50):
        d = mp.sqrt(mp.mpf(pv) ** 2 / 4 - qv)
        true = (-mp.mpf(pv) / 2 + d, -mp.mpf(pv) / 2 - d)
    for got, tv in zip((plus, minus), true):
        assert abs(got - tv) <= 2 * math.ulp(float(tv))
    if abs(pv) > 1e4:       # the textbook form really loses the small root there
        naive = (-pv / 2 + math.sqrt(pv * pv / 4 - qv), -pv / 2 - math.sqrt(pv * pv / 4 - qv))
        small = min(range(2), key=lambda i: abs(true[i]))
        assert abs(naive[small] - float(true[small])) > 1e6 * math.ulp(float(true[small]))


def test_only_monic_quadratics():
    with pytest.raises(ValueError):
        quadratic_roots(sp.Poly(2 * z**2 + p * z + q, z))
    with pytest.raises(ValueError):
        quadratic_roots(sp.Poly(z**3 + q, z))
