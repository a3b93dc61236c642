"""``make bench``: how fast each example scene answers (issue: ≤ 1 s after ``make derive``, ≤ 10 s cold).

Every ``scenes/*.toml`` (and every id-list scene, ``derivations/*/scenes/*.toml``) is answered by ``pendsym scene
FILE`` in a fresh process, three ways:

* **cold**: an empty cache (a temporary ``PENDSYM_CACHE``): the closure of the kept effects is derived;
* **warm**: the cache a derive filled (``PENDSYM_CACHE`` as set, or the default), the scene's answer itself not
  remembered yet (``pendsym.scenes.bench --first``: the budget solved and printed without its answer's memo);
* **repeated**: the same command again, its answer read back from the cache.

Each is repeated (cold ``--cold`` times, the others ``--repeat`` times) and reported as the min and the median of
the CPU seconds of the child process (user + system, imports included) and of its wall time, with the load
averages when measured (the machine is shared: wall time is noisy, CPU time less so).  Written to
``OUT/scenes.json`` and ``OUT/scenes.txt``; never written by ``make derive`` (timings are not reproducible).
"""
from __future__ import annotations

import argparse
import json
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from ..io import write_atomic

WARM_LIMIT, COLD_LIMIT = 1.0, 10.0       # seconds (the figures)


def _run(cmd: list[str], env: dict) -> tuple[float, float]:
    """(CPU seconds of the child, wall seconds) of one command; it must succeed."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    done = subprocess.run(cmd, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if done.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} failed ({done.returncode}): {done.stderr.strip()[:300]}")
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime), wall


def _stats(samples: list[tuple[float, float]]) -> dict:
    cpu, wall = [s[0] for s in samples], [s[1] for s in samples]
    return {"n": len(samples), "cpu_min": min(cpu), "cpu_median": statistics.median(cpu),
            "wall_min": min(wall), "wall_median": statistics.median(wall)}


def first_answer(path: str) -> int:
    """The answer of a scene without the memo of answers (the Results' cache is used): what a user sees the first
    time a scene is asked after ``make derive``."""
    from . import from_data, solved, text
    from .. import scene
    data = scene.parse(path)
    where = f"scene {scene.printable(path)}"
    if not scene.is_hardware(data):                 # a list of Result ids: their values (no memo of answers)
        sc = scene.load(path, data)
        rows, built = scene.evaluate(sc)
        print(sc.name, built, *(f"{rid} {value}" for rid, _, value in rows))
        return 0
    sc = from_data(data, where)
    print(text(solved(sc, where), scene.printable(sc.name or Path(path).stem)))
    return 0


def measure(files: list[Path], repeat: int, cold: int) -> list[dict]:
    python = sys.executable
    env = dict(os.environ, PYTHONHASHSEED="0")
    rows = []
    for f in files:
        scene_cmd = [python, "-m", "pendsym.cli", "scene", str(f)]
        first_cmd = [python, "-m", "pendsym.scenes.bench", "--first", str(f)]
        cold_samples = []
        for _ in range(cold):
            with tempfile.TemporaryDirectory(prefix="pendsym-cold-") as empty:
                cold_samples.append(_run(scene_cmd, dict(env, PENDSYM_CACHE=empty)))
        warm = [_run(first_cmd, env) for _ in range(repeat)]
        _run(scene_cmd, env)                                  # remembers the answer
        repeated = [_run(scene_cmd, env) for _ in range(repeat)]
        row = {"scene": f.name, "cold": _stats(cold_samples) if cold_samples else None, "warm": _stats(warm),
               "repeated": _stats(repeated), "load": list(os.getloadavg())}
        rows.append(row)
        print(line(row), flush=True)
    return rows


def line(row: dict) -> str:
    def part(name):
        s = row[name]
        return "—" if s is None else f"{s['cpu_min']:6.2f} / {s['cpu_median']:6.2f}"
    return f"{row['scene']:<40} {part('cold'):>17} {part('warm'):>17} {part('repeated'):>17}"


HEADER = (f"{'scene (CPU s, min / median)':<40} {'cold':>17} {'warm':>17} {'repeated':>17}")


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="pendsym-scenes-bench")
    p.add_argument("--out", default="generated/bench")
    p.add_argument("--scenes", default="scenes", help="the directory of the example scenes")
    p.add_argument("--id-lists", default="derivations/*/scenes/*.toml", help="the id-list scenes (a glob)")
    p.add_argument("--repeat", type=int, default=3)
    p.add_argument("--cold", type=int, default=1, help="cold runs per scene (each derives its closure)")
    p.add_argument("--only", default=None, help="one scene file name")
    p.add_argument("--first", metavar="FILE", help=argparse.SUPPRESS)
    args = p.parse_args(argv)
    if args.first:
        return first_answer(args.first)
    files = sorted(Path(args.scenes).glob("*.toml")) + sorted(Path().glob(args.id_lists))
    if args.only:
        files = [f for f in files if f.name == args.only]
    print(HEADER)
    rows = measure(files, args.repeat, args.cold)
    out = Path(args.out)
    write_atomic(out / "scenes.json", json.dumps(rows, indent=1) + "\n")
    write_atomic(out / "scenes.txt", "\n".join([HEADER, *map(line, rows)]) + "\n")
    slow = [r["scene"] for r in rows if r["warm"]["cpu_median"] > WARM_LIMIT
            or (r["cold"] and r["cold"]["cpu_median"] > COLD_LIMIT)]
    print(f"beyond {WARM_LIMIT:g} s warm or {COLD_LIMIT:g} s cold (CPU, median): {', '.join(slow) or 'none'}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
