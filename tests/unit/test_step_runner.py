"""The runner of every study step (workflow/scripts/run_study_step.py): a job run through the warm
process writes exactly what the same job writes in a fresh process, a failure keeps its status
and traceback, and the warm process steps aside when it cannot or must not take a step."""

import json
import os
import socket
import subprocess
import sys

from conftest import ROOT

sys.path.insert(0, str(ROOT / "workflow" / "scripts"))

import run_study_step  # noqa: E402

RUNNER = ROOT / "workflow" / "scripts" / "run_study_step.py"


def request(out, study="tseng_tca", job="ke_table_5_4"):
    from conftest import study_settings

    from gearrep.replications import load

    mod = load(study)
    published = sorted(
        str(p) for pat in mod.DESIGN_DATA for p in (ROOT / "data" / "published").glob(pat) if p.name != "MANIFEST.csv"
    )
    tables = mod.JOBS[job].tables if job in mod.JOBS else {"x": "x.csv"}
    return {
        "study": study,
        "step": job,
        "settings": study_settings(study),
        "published": published,
        "outputs": {t: str(out / p) for t, p in tables.items()},
        "timing": str(out / "timing.tsv"),
        "log": str(out / "step.log"),
    }


def run(cwd, req, warm):
    env = dict(os.environ, GEARREP_WARM_PROCESS="1" if warm else "0")
    return subprocess.run(
        [sys.executable, str(RUNNER), json.dumps(req)], cwd=cwd, env=env, capture_output=True, text=True, timeout=300
    )


def test_a_step_through_the_warm_process_writes_what_a_fresh_process_writes(tmp_path):
    fresh, warm = tmp_path / "fresh", tmp_path / "warm"
    a = run(tmp_path, request(fresh), warm=False)
    assert a.returncode == 0, a.stderr
    assert not (tmp_path / ".snakemake").exists()  # GEARREP_WARM_PROCESS=0: no warm process
    for _ in range(2):  # the first call starts the warm process, the second reuses it
        b = run(tmp_path, request(warm), warm=True)
        assert b.returncode == 0, b.stderr
    assert len(list((tmp_path / ".snakemake").glob("gearrep-warm-*.sock"))) == 1
    out = sorted(p.name for p in fresh.rglob("*.csv"))
    assert out and out == sorted(p.name for p in warm.rglob("*.csv"))
    for name in out:
        assert (fresh / "tseng" / name).read_bytes() == (warm / "tseng" / name).read_bytes(), name
    timing = (warm / "timing.tsv").read_text().splitlines()
    assert timing[0].split("\t") == ["s", "cpu_time", "max_rss", "compute_s"]


def test_a_failing_step_keeps_its_exit_status_and_traceback(tmp_path):
    req = dict(request(tmp_path / "out"), step="no_such_job")
    for warm in (False, True):
        r = run(tmp_path, req, warm)
        assert r.returncode == 1
        assert "KeyError" in r.stderr and "no_such_job" in r.stderr
        assert "no_such_job" in (tmp_path / "out" / "step.log").read_text()


def test_a_stale_socket_is_replaced_and_a_changed_source_refused(tmp_path, monkeypatch):
    # a dead socket file where the warm process's would be: the client starts a new one over it
    # (bound by its path relative to the working directory, as the runner does: socket paths are
    # limited to about 100 characters)
    monkeypatch.chdir(tmp_path)
    path = run_study_step.socket_path()
    path.parent.mkdir()
    dead = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    dead.bind(str(path))
    dead.close()
    r = run(tmp_path, request(tmp_path / "out"), warm=True)
    assert r.returncode == 0, r.stderr
    # the staleness test the warm process makes before each step
    src = tmp_path / "mod.py"
    src.write_text("x = 1\n")
    seen = {str(src): os.stat(src).st_mtime_ns}
    assert run_study_step._unchanged(seen)
    os.utime(src, ns=(1, 1))
    assert not run_study_step._unchanged(seen)
    src.unlink()
    assert not run_study_step._unchanged(seen)


def test_the_warm_process_can_be_switched_off(tmp_path):
    r = run(tmp_path, request(tmp_path / "out"), warm=False)
    assert r.returncode == 0, r.stderr
    assert not (tmp_path / ".snakemake").exists()
