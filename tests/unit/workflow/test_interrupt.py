"""Ctrl-C during a run: SIGINT to the run's foreground process group (what a terminal sends) stops
every process computing for it, nothing under results/ changes once the command has returned, and
the next run does the interrupted job again.

The run is Snakemake in a private copy of the repository, in a session of its own (so that the
signal reaches its group and not the test's), asked for one long table job."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
from conftest import copy_workflow, tool_env

TARGET = "results/temirkhan2023/convergence.csv"  # one job computing for many seconds
RULE = "temirkhan2023_convergence"


def _processes_of(wf: Path, session: int) -> list[str]:
    """Processes of the run's session, or working in its directory (a detached worker would be)."""
    found = []
    for d in Path("/proc").iterdir():
        if not d.name.isdigit() or int(d.name) == os.getpid():
            continue
        try:
            stat = (d / "stat").read_text()
            sid = int(stat.rsplit(")", 1)[1].split()[3])
            cwd = os.readlink(d / "cwd")
        except OSError:
            continue
        if sid == session or cwd == str(wf) or cwd.startswith(f"{wf}{os.sep}"):
            command = (d / "cmdline").read_bytes().replace(b"\0", b" ").decode(errors="replace")
            found.append(f"{d.name} {command}")
    return found


def _snapshot(wf: Path) -> dict[str, tuple[int, int]]:
    return {str(p.relative_to(wf)): (p.stat().st_mtime_ns, p.stat().st_size) for p in (wf / "results").rglob("*")}


@pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="reads the process table from /proc (Linux)")
def test_ctrl_c_stops_every_process_writes_nothing_after_and_the_next_run_redoes_the_job(tmp_path):
    wf = copy_workflow(tmp_path)
    cmd = [sys.executable, "-m", "snakemake", "--cores", "2", TARGET]
    run = subprocess.Popen(
        cmd, cwd=wf, env=tool_env(), stdout=subprocess.PIPE, stderr=subprocess.STDOUT, start_new_session=True
    )
    try:
        # the job has started once Snakemake marks its output incomplete; then let it compute a while
        deadline = time.monotonic() + 300
        marks = wf / ".snakemake" / "incomplete"
        while not (marks.is_dir() and any(marks.iterdir())):
            assert run.poll() is None, run.stdout.read().decode()[-3000:]
            assert time.monotonic() < deadline, "the job did not start"
            time.sleep(0.2)
        time.sleep(3.0)
        assert run.poll() is None, "the job ended before it could be interrupted"
        os.killpg(run.pid, signal.SIGINT)
        out = run.communicate(timeout=120)[0].decode(errors="replace")
    finally:
        if run.poll() is None:
            os.killpg(run.pid, signal.SIGKILL)
            run.wait()
    assert run.returncode != 0, out[-3000:]
    assert not (wf / TARGET).exists(), "an interrupted job's output must not be kept"
    before = _snapshot(wf)
    # any process left would still be computing: none may be, now or a few seconds later
    time.sleep(1.0)
    assert _processes_of(wf, run.pid) == []
    time.sleep(4.0)
    assert _processes_of(wf, run.pid) == []
    assert _snapshot(wf) == before, "files under results/ changed after the command returned"
    again = subprocess.run(
        # without the default profile's logger: the plain log names every planned rule
        [sys.executable, "-m", "snakemake", "--workflow-profile", "none", "-n", TARGET],
        cwd=wf,
        env=tool_env(),
        capture_output=True,
        text=True,
    )
    assert again.returncode == 0 and f"rule {RULE}:" in again.stdout, again.stdout[-3000:] + again.stderr[-3000:]
