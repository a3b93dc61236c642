"""pendsym.bench_blade (``make bench``): the exact blade's periods per second at 30 digits.  The shape of its
output with a stand-in solver (quick), and one real solve at low precision (slow)."""
import json
from types import SimpleNamespace

import mpmath as mp
import pytest

from pendsym import bench_blade, nonlinear_blade


def test_amplitudes_are_random_distinct_and_in_range():
    thetas = bench_blade.amplitudes(20)
    assert len(set(thetas)) == 20
    assert all(bench_blade.AMPLITUDE_LO <= float(t) <= bench_blade.AMPLITUDE_HI for t in thetas)
    assert thetas == bench_blade.amplitudes(20)                 # seeded: the same draw on every run
    assert thetas != bench_blade.amplitudes(20, seed="other")


def test_output_shape(monkeypatch, tmp_path):
    """main writes nonlinear-blade.json with the timed rows, their min and median, periods per second, and the
    node check; every timed solve is a call of the uncached orbit on a new amplitude."""
    seen = []

    def fake_orbit(blade, a, R, g, theta0, nodes, dps):
        seen.append((theta0, nodes))
        return SimpleNamespace(period=mp.mpf(1) + mp.mpf(theta0) ** 2 / 16, nodes=nodes, residual=mp.mpf(10) ** -40)
    monkeypatch.setattr(nonlinear_blade, "orbit", fake_orbit)
    assert bench_blade.main(["--out", str(tmp_path), "--solves", "3"]) == 0
    out = json.loads((tmp_path / "nonlinear-blade.json").read_text())
    assert out["dps"] == 30 and out["solves"] == 3 and len(out["rows"]) == 3
    assert out["wall_s_min"] <= out["wall_s_median"] and out["cpu_s_min"] <= out["cpu_s_median"]
    assert out["periods_per_s_best"] == pytest.approx(1 / out["wall_s_min"])
    assert out["periods_per_s_median"] == pytest.approx(1 / out["wall_s_median"])
    thetas = [t for t, _ in seen]
    assert len(set(thetas[:4])) == 4                       # the warm-up and three timed solves: all new amplitudes
    assert seen[4] == (out["rows"][0]["theta0"], out["rows"][0]["nodes"] + 2)   # the node check
    for row in out["rows"]:
        assert set(row) == {"theta0", "nodes", "period", "residual", "cpu_s", "wall_s"}


@pytest.mark.slow
def test_one_real_solve():
    """One warm-up, one timed solve and the node check at 15 digits on the exact blade: the period is that of
    nonlinear_blade.period (the cached path) and two more nodes agree to the precision."""
    out = bench_blade.run(solves=1, dps=15)
    row = out["rows"][0]
    ref = nonlinear_blade.period(bench_blade.the_blade(), *bench_blade.PENDULUM, row["theta0"], 15, row["nodes"])
    assert abs(mp.mpf(row["period"]) - ref) < mp.mpf(10) ** -13 * ref
    assert out["nodes_check"]["relative_difference"] < 1e-13
    assert out["periods_per_s_best"] > 0
