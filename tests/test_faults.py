"""Faults as a user meets them: a killed or interrupted derive leaves no worker behind and says one line."""
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

pytestmark = pytest.mark.skipif(not Path("/proc").is_dir(), reason="needs /proc to find the workers")


def children(pid: int) -> list[int]:
    """Every descendant of pid (from /proc)."""
    parent = {}
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            try:
                fields = (entry / "stat").read_text().rsplit(")", 1)[1].split()
            except OSError:
                continue
            parent[int(entry.name)] = int(fields[1])
    out, frontier = [], [pid]
    while frontier:
        p = frontier.pop()
        kids = [c for c, pp in parent.items() if pp == p]
        out += kids
        frontier += kids
    return out


def alive(pid: int) -> bool:
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except OSError:
        return False
    return state != "Z"


def as_from_a_terminal() -> None:
    """In the child before exec: SIGINT's default disposition, as a shell on a terminal gives a command.
    A job started in the background by a non-interactive shell (``cmd &``, as CI may run the suite)
    inherits SIGINT ignored, and a Python started so never raises KeyboardInterrupt."""
    signal.signal(signal.SIGINT, signal.SIG_DFL)


def start_slow_derive(tmp_path, root) -> subprocess.Popen:
    env = dict(os.environ, PENDSYM_MEMOIR_PACKAGES="toy_memoirs", PYTHONPATH=str(root / "tests"),
               PENDSYM_CACHE=str(tmp_path / "cache"), PENDSYM_WORKERS="2", TOY_SLOW_SECONDS="30")
    proc = subprocess.Popen([sys.executable, "-m", "pendsym.cli", "derive", "--out", str(tmp_path / "out")],
                            env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            start_new_session=True, preexec_fn=as_from_a_terminal)
    deadline = time.monotonic() + 60
    while len(children(proc.pid)) < 2:               # the two check workers are running
        assert time.monotonic() < deadline and proc.poll() is None, "no workers started"
        time.sleep(0.1)
    return proc


def wait_gone(pids, seconds=10) -> list[int]:
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline and any(alive(p) for p in pids):
        time.sleep(0.1)
    return [p for p in pids if alive(p)]


def test_sigkill_of_derive_leaves_no_orphan_worker(tmp_path, root):
    proc = start_slow_derive(tmp_path, root)
    workers = children(proc.pid)
    os.kill(proc.pid, signal.SIGKILL)
    proc.wait(timeout=10)
    assert wait_gone(workers) == []


def test_ctrl_c_is_one_line_and_exit_130(tmp_path, root):
    proc = start_slow_derive(tmp_path, root)
    workers = children(proc.pid)
    os.killpg(proc.pid, signal.SIGINT)               # a terminal sends it to the whole group
    out, err = proc.communicate(timeout=30)
    assert proc.returncode == 130
    assert err.strip().splitlines()[-1] == "pendsym: interrupted" and "Traceback" not in err
    assert wait_gone(workers) == []
    assert not (tmp_path / "out" / "results.json").exists()      # nothing half-written


@pytest.mark.slow
def test_a_derive_whose_reader_went_away_ends(tmp_path, root):
    """`pendsym derive | head`, or a closed terminal: the output pipes close while the checks run.  The derive
    ends (before, a progress line written from the pool's result thread killed that thread, and the derive
    waited for its results forever)."""
    env = dict(os.environ, PENDSYM_MEMOIR_PACKAGES="toy_memoirs", PYTHONPATH=str(root / "tests"),
               PENDSYM_CACHE=str(tmp_path / "cache"), PENDSYM_WORKERS="2", TOY_SLOW_SECONDS="3")
    proc = subprocess.Popen([sys.executable, "-m", "pendsym.cli", "derive", "--out", str(tmp_path / "out")],
                            env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, start_new_session=True)
    deadline = time.monotonic() + 60
    while len(children(proc.pid)) < 2:               # the check workers are running
        assert time.monotonic() < deadline and proc.poll() is None, "no workers started"
        time.sleep(0.1)
    workers = children(proc.pid)
    proc.stdout.close()
    proc.stderr.close()
    try:
        proc.wait(timeout=30)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        raise
    assert wait_gone(workers) == []
