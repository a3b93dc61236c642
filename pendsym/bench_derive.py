"""``make bench-derive``: how long derive takes cold, with nothing changed, and after one section changed;
and the cold derive of the original 314 Results alone (issue #9, point 9: ≤ 90 s on 2 cores).

It works on a copy of the repository's files (tracked and untracked, not ignored) in a
temporary directory, with a cache of its own, so the working tree and its cache are not
touched.  Each derive is a separate process (``python -m pendsym.cli derive``) run with
the copy first on PYTHONPATH.  Writes ``generated/bench/derive.json``.

The original 314 (``bench_original_ids.txt``: the ids of ``generated/results.json`` at commit
103f171 — Charbonnier n°18–35, Cellérier, Haag chapters I and III) are derived by
:func:`derive_subset`, in a process of their own with an empty cache: the stages of a derive
(build, compare and check, kernel forms, C measure) over those Results, their dependencies and
the Results their chained checks feed; the figures, the emitted files and writing are left out.
"""
from __future__ import annotations

import argparse
import json
import os
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from . import registry
from .io import write_atomic


def _copy_tree(root: Path, dest: Path) -> None:
    """The repository's files (as git lists them) copied to dest."""
    names = subprocess.run(["git", "ls-files", "-co", "--exclude-standard"], cwd=root, check=True,
                           capture_output=True, text=True).stdout.splitlines()
    for name in names:
        src = root / name
        if src.is_file():
            (dest / name).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(src, dest / name)


def _derive(copy: Path, cache: Path) -> tuple[float, str]:
    """Seconds of one derive of the copy, and its log."""
    env = dict(os.environ, PYTHONPATH=str(copy), PENDSYM_CACHE=str(cache))
    start = time.perf_counter()
    p = subprocess.run([sys.executable, "-m", "pendsym.cli", "derive", "--out", str(copy / "generated")],
                       cwd=copy, env=env, capture_output=True, text=True)
    took = time.perf_counter() - start
    if p.returncode != 0:
        raise SystemExit(f"derive failed in the copy:\n{p.stderr[-2000:]}")
    return took, p.stderr + p.stdout


ORIGINAL_IDS = Path(__file__).with_name("bench_original_ids.txt")


def original_ids() -> list[str]:
    """The 314 Results of issue #9 point 9 (the ids of generated/results.json at commit 103f171)."""
    lines = ORIGINAL_IDS.read_text(encoding="utf-8").splitlines()
    return [line.strip() for line in lines if line.strip() and not line.startswith("#")]


def subset_order(ids: list[str], specs, order) -> tuple[str, ...]:
    """ids with their dependencies (:func:`pendsym.registry.closure`) and the Results their chained checks feed
    (a chain step is assessed with them), closed under both, in the derive's order."""
    from .checks import Chain
    need = set(registry.closure(ids, specs))
    while more := {d for i in need if isinstance(specs[i].check, Chain) for d in specs[i].check.downstream} - need:
        need |= set(registry.closure(more, specs))
    return tuple(i for i in order if i in need)


def derive_subset(ids: list[str], level: str = "full", log=print) -> dict:
    """The stages of a derive for ids only (see the module's docstring): the wall seconds of each, the CPU
    seconds of this process and of its forked workers, the number of Results, the ids whose check failed."""
    from . import stages
    start, cpu = time.perf_counter(), time.process_time()
    full = stages.plan(level)
    order = subset_order(ids, full.specs, full.order)
    memoirs = tuple(m for m in full.memoirs if any(full.specs[i].memoir == m for i in order))
    pl = stages.Plan(level, memoirs, full.specs, order, full.keys, full.emitter, full.sections)
    figures = {"results": len(order), "plan_s": time.perf_counter() - start}
    t = time.perf_counter()
    built = stages.build(pl, log)
    figures["build_s"] = time.perf_counter() - t
    t = time.perf_counter()
    records, formed = stages.check_and_form(pl, built, log)
    figures["check_and_form_s"] = time.perf_counter() - t
    t = time.perf_counter()
    stages.measure_c(pl, built, formed, log)
    figures["measure_c_s"] = time.perf_counter() - t
    figures["total_s"] = time.perf_counter() - start
    figures["cpu_s_this_process"] = time.process_time() - cpu
    children = resource.getrusage(resource.RUSAGE_CHILDREN)
    figures["cpu_s_workers"] = children.ru_utime + children.ru_stime     # the forked workers that ended
    figures["failed"] = [r.result.id for r in stages.failures(records)]
    return figures


def _derive_original(copy: Path, cache: Path) -> dict:
    """The cold derive of the original 314 in the copy (a process of its own, the given empty cache)."""
    env = dict(os.environ, PYTHONPATH=str(copy), PENDSYM_CACHE=str(cache))
    start = time.perf_counter()
    p = subprocess.run([sys.executable, "-m", "pendsym.bench_derive", "--subset-run"], cwd=copy, env=env,
                       capture_output=True, text=True)
    if p.returncode != 0:
        raise SystemExit(f"the derive of the original 314 failed in the copy:\n{p.stderr[-2000:]}")
    figures = json.loads(p.stdout.strip().splitlines()[-1])
    figures["process_s"] = time.perf_counter() - start
    return figures


def smallest_section() -> str:
    """The module of the section with the fewest Results (a small change to time)."""
    sections = [sec for m in registry.memoirs().values() for sec in m.sections]
    return min(sections, key=lambda sec: (len(sec.specs), sec.module)).module


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m pendsym.bench_derive")
    ap.add_argument("--out", default="generated/bench")
    ap.add_argument("--section", help="the section module to change (default: the smallest)")
    ap.add_argument("--original-only", action="store_true",
                    help="only the cold derive of the original 314 Results (issue #9 point 9)")
    ap.add_argument("--subset-run", action="store_true", help=argparse.SUPPRESS)   # the child of that bench
    args = ap.parse_args(argv)
    if args.subset_run:
        figures = derive_subset(original_ids(), log=lambda m: print(m, file=sys.stderr))
        print(json.dumps(figures, ensure_ascii=False))
        return 1 if figures["failed"] else 0
    root = Path(__file__).resolve().parents[1]
    section = args.section or smallest_section()
    figures = {"section_changed": section, "cpus": os.cpu_count()}
    with tempfile.TemporaryDirectory() as tmp:
        copy, cache = Path(tmp) / "repo", Path(tmp) / "cache"
        _copy_tree(root, copy)
        figures["original_314_cold"] = _derive_original(copy, Path(tmp) / "cache-original")
        if args.original_only:
            text = json.dumps(figures, indent=1, ensure_ascii=False) + "\n"
            write_atomic(Path(args.out) / "derive_original.json", text)
            print(text, end="")
            return 0
        figures["cold_s"], _ = _derive(copy, cache)
        figures["noop_s"], log = _derive(copy, cache)
        figures["noop_said"] = log.strip().splitlines()[0]
        path = copy / (section.replace(".", "/") + ".py")
        if not path.exists():
            path = copy / section.replace(".", "/") / "__init__.py"
        path.write_text(path.read_text(encoding="utf-8") + "\n# a change for bench-derive\n", encoding="utf-8")
        figures["one_section_s"], log = _derive(copy, cache)
        figures["one_section_log"] = [line for line in log.splitlines() if line.startswith(("checked", "built"))]
    text = json.dumps(figures, indent=1, ensure_ascii=False) + "\n"
    write_atomic(Path(args.out) / "derive.json", text)
    print(text, end="")
    return 0


if __name__ == "__main__":
    sys.exit(main())
