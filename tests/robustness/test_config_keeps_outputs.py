"""A bad configuration written after a successful build stops Snakemake before any job, names
the key, and deletes none of the earlier outputs (outputs used to be removed by the
failing job)."""

import hashlib
import subprocess
import sys

import yaml
from conftest import copy_workflow, tool_env

TARGET = "results/ma2021/equations.csv"


def _smk(cwd, *args):
    return subprocess.run(
        [sys.executable, "-m", "snakemake", "--cores", "1", *args],
        cwd=cwd,
        capture_output=True,
        env=tool_env(),
        text=True,
        timeout=600,
    )


def _snapshot(results):
    return {
        p.relative_to(results): hashlib.sha256(p.read_bytes()).hexdigest() for p in results.rglob("*") if p.is_file()
    }


def test_nan_setting_after_a_build_stops_before_any_job_and_keeps_outputs(tmp_path):
    wf = copy_workflow(tmp_path)
    built = _smk(wf, TARGET)
    assert built.returncode == 0, built.stdout[-2000:] + built.stderr[-2000:]
    before = _snapshot(wf / "results")
    assert (wf / TARGET).stat().st_size > 0 and before

    f = wf / "config" / "config.yaml"
    cfg = yaml.safe_load(f.read_text()) or {}
    cfg.setdefault("temirkhan2023", {})["tol"] = float("nan")
    f.write_text(yaml.safe_dump(cfg))
    for args in ([TARGET, "--forceall"], []):  # the same target forced, and the default target
        out = _smk(wf, *args)
        text = out.stdout + out.stderr
        assert out.returncode != 0, text[-2000:]
        assert "temirkhan2023.tol" in text, text[-2000:]
        assert "Select jobs to execute" not in text and "rule ma2021_" not in text, text[-2000:]
        assert _snapshot(wf / "results") == before, "an output was deleted or changed"
