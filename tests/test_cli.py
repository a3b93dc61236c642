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


BAD_INPUT = [
    ("check", "charbonnier1908.n99.nothing"),
    ("list", "--memoir", "nosuch"),
    ("derive", "nosuch.id"),
    ("frobnicate",),
    ("check",),
    ("check", "charbonnier1908.n21.dT", "--level", "extreme"),
]


def one_line_exit_2(code, out, err, starts="pendsym: error:"):
    assert code == 2
    assert out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith(starts), err
    assert "Traceback" not in err
    return lines[0]


@pytest.mark.parametrize("args", BAD_INPUT)
def test_bad_input_is_one_line_and_exit_2_in_process(capsys, args):
    """Quick tier: the same inputs through cli.main in this process (one import of the memoirs for all);
    the real command, a process each, is the slow tier's test below."""
    code = cli.main(list(args))
    out, err = capsys.readouterr()
    one_line_exit_2(code, out, err)


@pytest.mark.slow
@pytest.mark.parametrize("args", BAD_INPUT)
def test_bad_input_is_one_line_and_exit_2(args):
    p = run(*args)
    one_line_exit_2(p.returncode, p.stdout, p.stderr)


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


def toy_env(tmp_path, root, **extra):
    import os
    return dict(os.environ, PENDSYM_MEMOIR_PACKAGES="toy_memoirs", PYTHONPATH=str(root / "tests"),
                PENDSYM_CACHE=str(tmp_path / "cache"), **extra)


def test_a_failed_check_fails_derive_with_a_summary(tmp_path, root):
    p = subprocess.run([sys.executable, "-m", "pendsym.cli", "derive", "--out", str(tmp_path / "out"), "--level",
                        "quick"], capture_output=True, text=True, env=toy_env(tmp_path, root, TOY_WRONG_ORDER="1"))
    assert p.returncode == 1, p.stderr
    assert "1 failed" in p.stdout and "FAILED toy.T" in p.stdout
    again = subprocess.run([sys.executable, "-m", "pendsym.cli", "derive", "--out", str(tmp_path / "out"), "--level",
                            "quick"], capture_output=True, text=True, env=toy_env(tmp_path, root, TOY_WRONG_ORDER="1"))
    assert again.returncode == 1 and "nothing changed" not in again.stdout   # a failure is never "nothing changed"


MORE_BAD_INPUT = [
    (("derive", "charbonnier1908.n21.dT", "--out", "x"), "apply to a full derive"),
    (("derive", "--out", "/proc/pendsym"), "cannot write"),
    (("check", "haag1935.eq43"), "nearest: haag1935.eq043"),
]


@pytest.mark.parametrize("args, message", MORE_BAD_INPUT)
def test_more_bad_input_is_one_line_in_process(capsys, args, message):
    code = cli.main(list(args))
    out, err = capsys.readouterr()
    assert message in one_line_exit_2(code, out, err)


@pytest.mark.slow
@pytest.mark.parametrize("args, message", MORE_BAD_INPUT)
def test_more_bad_input_is_one_line(args, message):
    p = run(*args)
    assert p.returncode == 2 and p.stdout == ""
    lines = p.stderr.strip().splitlines()
    assert len(lines) == 1 and message in lines[0], p.stderr


def test_derive_into_a_file_is_refused_before_any_work(tmp_path):
    f = tmp_path / "file"
    f.write_text("x")
    p = run("derive", "--out", str(f))
    assert p.returncode == 2 and "not a directory" in p.stderr


def test_a_corrupt_results_json_is_one_line(tmp_path):
    (tmp_path / "results.json").write_text('{"results": [{"no id": 1}]}')
    p = run("list", "--generated", str(tmp_path))
    assert p.returncode == 2 and len(p.stderr.strip().splitlines()) == 1 and "results.json" in p.stderr


def test_no_arguments_prints_the_usage():
    p = run()
    assert p.returncode == 0 and "usage: pendsym" in p.stdout and "list" in p.stdout and "derive" in p.stdout


def test_a_closed_pipe_is_quiet():
    p = subprocess.run(f"{sys.executable} -m pendsym.cli list | head -1", shell=True, capture_output=True, text=True)
    assert p.returncode == 0 and "Traceback" not in p.stderr and "BrokenPipe" not in p.stderr


def test_list_works_from_another_directory(tmp_path):
    p = subprocess.run([sys.executable, "-m", "pendsym.cli", "list", "--memoir", "cellerier"], cwd=tmp_path,
                       capture_output=True, text=True)
    assert p.returncode == 0 and "not derived" not in p.stdout


def test_json_output_uses_the_keys_of_results_json(capsys):
    # in process: one import of the memoirs for three commands (the process's own behaviour, exit codes and
    # one-line errors, is tested through the real command above)
    assert cli.main(["derive", "cellerier.rho_cn", "--json"]) == 0
    records = json.loads(capsys.readouterr().out)
    assert {"id", "status", "printed", "derived", "readings"} <= set(records[0])
    assert cli.main(["check", "cellerier.rho_cn", "--json", "--level", "quick"]) == 0
    record = json.loads(capsys.readouterr().out)
    assert record["id"] == "cellerier.rho_cn" and record["definition"] and not record["verified"]
    assert cli.main(["list", "--memoir", "cellerier", "--json"]) == 0
    listed = json.loads(capsys.readouterr().out)
    assert set(listed[0]) <= set(record)


def test_derive_says_how_far_it_is(tmp_path, root):
    p = subprocess.run([sys.executable, "-m", "pendsym.cli", "derive", "--out", str(tmp_path / "out"), "--level",
                        "quick"], capture_output=True, text=True, env=toy_env(tmp_path, root))
    assert p.returncode == 0, p.stderr
    progress = [line for line in p.stderr.splitlines() if line.startswith("checking: ")]
    assert progress and progress[-1] == "checking: 2/2 results done, 0 to go"
    assert "2 results: 2 verified, 0 failed" in p.stdout
