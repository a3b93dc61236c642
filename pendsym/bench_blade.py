"""``make bench``: the speed of the exact large-deflection blade (:mod:`pendsym.nonlinear_blade`): periods per
second at 30 digits.

One period is one collocation solve of the periodic orbit (:func:`pendsym.nonlinear_blade.orbit`, not the
cached :func:`~pendsym.nonlinear_blade.period`: the cache would time a file read).  The case is the uniform
blade λ = 0.1 m, u = λ/√M = 2, under a short pendulum a = 0.12 m, R = 0.05 m, g = 9.81 m/s²; the amplitudes
θ0 are random and do not repeat (seeded, log-uniform in [AMPLITUDE_LO, AMPLITUDE_HI]), so no solve repeats
another's work through mpmath's or the engine's in-process caches.  The first solve is a warm-up (it builds
the collocation operators and the linear blade, which later solves share) and is reported apart.  The figures
are the least and the median of the per-solve times (CPU and wall) over the timed solves; the accuracy of each
period is the collocation's own residual (the orbit is solved to 30 digits, ``nonlinear_blade`` raises
otherwise) and the distance to a second solve with two more nodes on the first timed amplitude.
"""
from __future__ import annotations

import argparse
import json
import os
import random
import statistics
import time
from pathlib import Path

import mpmath as mp
import sympy as sp

from . import blade, nonlinear_blade
from .io import write_atomic

DPS = 30
LAMBDA, U = sp.Rational(1, 10), sp.Integer(2)
PENDULUM = ("0.12", "0.05", "9.81")          # a, R, g
AMPLITUDE_LO, AMPLITUDE_HI = 0.002, 0.05     # θ0 (rad)
SOLVES = 5                                    # timed solves (after one warm-up)
SEED = "nonlinear-blade-bench"


def the_blade() -> blade.Blade:
    return blade.Blade(LAMBDA, (LAMBDA / U) ** 2)


def amplitudes(n: int, seed: str = SEED) -> list[str]:
    """n distinct amplitudes, log-uniform in [AMPLITUDE_LO, AMPLITUDE_HI], as decimal strings (12 digits)."""
    rng = random.Random(seed)
    out: list[str] = []
    while len(out) < n:
        x = f"{AMPLITUDE_LO * (AMPLITUDE_HI / AMPLITUDE_LO) ** rng.random():.12g}"
        if x not in out:
            out.append(x)
    return out


def solve_timed(theta0: str, dps: int = DPS, nodes: int | None = None) -> dict:
    """One uncached collocation solve: its period, nodes, residual and CPU and wall seconds."""
    bl, (a, R, g) = the_blade(), PENDULUM
    nodes = nonlinear_blade.nodes_for(theta0, dps) if nodes is None else nodes
    c0, w0 = time.process_time(), time.perf_counter()
    o = nonlinear_blade.orbit(bl, a, R, g, theta0, nodes, dps)
    cpu, wall = time.process_time() - c0, time.perf_counter() - w0
    return {"theta0": theta0, "nodes": o.nodes, "period": mp.nstr(o.period, dps),
            "residual": float(o.residual), "cpu_s": cpu, "wall_s": wall}


def run(solves: int = SOLVES, dps: int = DPS) -> dict:
    """The warm-up solve, the timed solves and the summary (min and median; periods per second)."""
    thetas = amplitudes(solves + 1)
    warm = solve_timed(thetas[0], dps)
    rows = [solve_timed(t, dps) for t in thetas[1:]]
    first = rows[0]
    with mp.workdps(dps + 10):
        check = solve_timed(first["theta0"], dps, first["nodes"] + 2)
        agree = abs(mp.mpf(check["period"]) - mp.mpf(first["period"])) / mp.mpf(first["period"])
    cpu, wall = [r["cpu_s"] for r in rows], [r["wall_s"] for r in rows]
    return {"case": f"uniform blade λ = {LAMBDA} m, u = {U}; a, R, g = {', '.join(PENDULUM)}",
            "dps": dps, "solves": len(rows), "load": " ".join(f"{v:.2f}" for v in os.getloadavg()),
            "warmup": warm, "rows": rows,
            "cpu_s_min": min(cpu), "cpu_s_median": statistics.median(cpu),
            "wall_s_min": min(wall), "wall_s_median": statistics.median(wall),
            "periods_per_s_best": 1 / min(wall), "periods_per_s_median": 1 / statistics.median(wall),
            "periods_per_cpu_s_best": 1 / min(cpu), "periods_per_cpu_s_median": 1 / statistics.median(cpu),
            "nodes_check": {"theta0": first["theta0"], "nodes": check["nodes"],
                            "relative_difference": float(agree)}}


def summary(result: dict) -> str:
    return (f"nonlinear blade, {result['dps']} digits ({result['case']}): "
            f"{result['periods_per_s_best']:.3g} periods/s best, {result['periods_per_s_median']:.3g} median, per CPU "
            f"second {result['periods_per_cpu_s_best']:.3g} best, {result['periods_per_cpu_s_median']:.3g} median "
            f"(wall per period: min {result['wall_s_min']:.2f} s, median {result['wall_s_median']:.2f} s; CPU: min "
            f"{result['cpu_s_min']:.2f} s, median {result['cpu_s_median']:.2f} s; {result['solves']} random "
            f"amplitudes in [{AMPLITUDE_LO}, {AMPLITUDE_HI}] rad after a warm-up of {result['warmup']['wall_s']:.2f} s; "
            f"load {result['load']}); two more nodes change the period by "
            f"{result['nodes_check']['relative_difference']:.1e}")


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="pendsym-bench-blade", description=__doc__.splitlines()[0])
    p.add_argument("--out", default="generated/bench")
    p.add_argument("--solves", type=int, default=SOLVES)
    args = p.parse_args(argv)
    result = run(args.solves)
    write_atomic(Path(args.out) / "nonlinear-blade.json", json.dumps(result, indent=1) + "\n")
    print(summary(result))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
