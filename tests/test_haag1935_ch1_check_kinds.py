"""derivations/haag1935/check_kinds.py: the blade-quadrature adapter passes the right formula and rejects a
wrong one."""
import mpmath as mp
import pytest
import sympy as sp

from derivations.haag1935 import profiles
from derivations.haag1935.check_kinds import OnShotBlade
from derivations.haag1935.common import rid, src
from derivations.haag1935.symbols import M_of_s, lam, s, w
from pendsym.checks import Point
from pendsym.result import Result, Spec

x, y = sp.symbols("x y", real=True)


def result(derived, printed=None) -> Result:
    spec = Spec(rid(999, "test"), "a test form", src("n°0", None), "f", lambda deps: derived,
                printed=None if printed is None else (lambda: printed))
    return Result(spec, derived, printed)


@pytest.mark.slow
def test_on_shot_blade_integrates_and_differentiates_on_the_blade():
    """(19) ∫ w/M ds = 1 and w'(λ) = 1 (10) on the shot uniform blade; a wrong truth fails."""
    shot = profiles.shot_blade("uniform")
    with mp.workdps(40):
        length = profiles.as_mpf(shot.blade.length)

    def points(truth):
        return lambda level, dps: [(Point("λ", {"lambda": length}, truth, 1), shot, None, length)]
    form = sp.Integral(w(s) / M_of_s(s), (s, 0, lam)) * w(s).diff(s)      # 1 · 1
    ev = OnShotBlade("(19) times (10)", points(mp.mpf(1)))(result(form, form), "quick")
    assert ev.passed and ev.printed_agrees and ev.max_residual < 1e-30
    assert not OnShotBlade("(19) times (10)", points(mp.mpf("1.001")))(result(form), "quick").passed
