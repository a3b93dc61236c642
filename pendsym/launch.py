"""The ``pendsym`` console entry: fixes Python's string-hash seed before anything heavy is imported.

A derive is byte-reproducible only under one hash seed (see :func:`pendsym.cli.main`), so the
command re-executes itself under ``PYTHONHASHSEED=0``.  Doing that here, before SymPy and the
memoirs are imported, saves a second import of them on every command (about 1.5 s of CPU).
"""
from __future__ import annotations

import os
import sys


def main() -> int:
    """Re-execute under hash seed 0 when needed, then run :func:`pendsym.cli.main`."""
    if os.environ.get("PYTHONHASHSEED") != "0":
        os.environ["PYTHONHASHSEED"] = "0"
        os.execv(sys.executable, [sys.executable, "-m", "pendsym.cli", *sys.argv[1:]])
    from .cli import main as run_command
    return run_command()
