"""The pendsym command: listing, one-line errors with exit code 2."""
import json
import subprocess
import sys

import pytest

from pendsym import cli


def run(*args):
    return subprocess.run([sys.executable, "-m", "pendsym.cli", *args], capture_output=True, text=True)


def test_list_json_has_every_charbonnier_paragraph(root):
    p = run("list", "--memoir", "charbonnier1908", "--json", "--generated", str(root / "generated"))
    assert p.returncode == 0, p.stderr
    rows = json.loads(p.stdout)
    ids = {r["id"] for r in rows}
    paras = {i.split(".")[1] for i in ids}
    assert {f"n{n}" for n in range(18, 36) if n != 27} <= paras
    assert all(r["status"] in ("match", "discrepancy", "derived-only") for r in rows)


@pytest.mark.parametrize("args", [
    ("check", "charbonnier1908.n99.nothing"),
    ("list", "--memoir", "nosuch"),
    ("derive", "nosuch.id"),
    ("frobnicate",),
    ("check",),
    ("check", "charbonnier1908.n21.dT", "--level", "extreme"),
])
def test_bad_input_is_one_line_and_exit_2(args):
    p = run(*args)
    assert p.returncode == 2
    assert p.stdout == ""
    lines = p.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("pendsym: error:"), p.stderr
    assert "Traceback" not in p.stderr


def test_derive_one_id_prints_its_closure(capsys):
    assert cli.main(["derive", "charbonnier1908.n21.dT"]) == 0
    out = capsys.readouterr().out
    assert "charbonnier1908.n21.dT: match" in out
    assert "charbonnier1908.n09.dT" in out
    assert "n33" not in out


@pytest.mark.slow
def test_check_prints_the_evidence():
    p = run("check", "charbonnier1908.n32.dT", "--level", "quick")
    assert p.returncode == 0, p.stderr
    assert "fitted order in a:" in p.stdout and "passed" in p.stdout
