"""``make bench-derive``: how long derive takes cold, with nothing changed, and after one section changed.

It works on a copy of the repository's files (tracked and untracked, not ignored) in a
temporary directory, with a cache of its own, so the working tree and its cache are not
touched.  Each derive is a separate process (``python -m pendsym.cli derive``) run with
the copy first on PYTHONPATH.  Writes ``generated/bench/derive.json``.
"""
from __future__ import annotations

import argparse
import json
import os
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


def smallest_section() -> str:
    """The module of the section with the fewest Results (a small change to time)."""
    sections = [sec for m in registry.memoirs().values() for sec in m.sections]
    return min(sections, key=lambda sec: (len(sec.specs), sec.module)).module


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m pendsym.bench_derive")
    ap.add_argument("--out", default="generated/bench")
    ap.add_argument("--section", help="the section module to change (default: the smallest)")
    args = ap.parse_args(argv)
    root = Path(__file__).resolve().parents[1]
    section = args.section or smallest_section()
    figures = {"section_changed": section, "cpus": os.cpu_count()}
    with tempfile.TemporaryDirectory() as tmp:
        copy, cache = Path(tmp) / "repo", Path(tmp) / "cache"
        _copy_tree(root, copy)
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
