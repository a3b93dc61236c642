"""pendsym.launch: the console entry re-executes under hash seed 0 before importing anything heavy."""
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest


def test_the_console_script_is_the_light_entry():
    project = tomllib.loads((Path(__file__).parents[1] / "pyproject.toml").read_text())
    assert project["project"]["scripts"]["pendsym"] == "pendsym.launch:main"


def test_importing_the_entry_does_not_import_sympy():
    out = subprocess.run([sys.executable, "-c", "import sys, pendsym.launch; print('sympy' in sys.modules)"],
                         capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "False"


@pytest.mark.slow
def test_the_entry_runs_the_command_under_seed_0():
    code = "import sys; sys.argv = ['pendsym', 'list', '--memoir', 'nosuch']; import pendsym.launch as l; sys.exit(l.main())"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         env={"PATH": "/usr/bin:/bin", "PYTHONHASHSEED": "1"})
    assert out.returncode == 2
    assert out.stderr.count("\n") == 1 and "unknown memoir: nosuch" in out.stderr
