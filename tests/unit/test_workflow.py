"""The Snakemake workflow: config validation, lint, and an incremental no-op re-run.

Each test runs Snakemake in a private copy of the repository's tracked inputs, so nothing is
written into the working tree and no test depends on an earlier run's results/.
"""

import shutil
import subprocess
import sys

import pytest

from conftest import ROOT

COPY = ["Snakefile", "config", "workflow", "data", "src"]


@pytest.fixture()
def wf(tmp_path):
    for name in COPY:
        src = ROOT / name
        if src.is_dir():
            shutil.copytree(src, tmp_path / name, ignore=shutil.ignore_patterns("__pycache__"))
        else:
            shutil.copy2(src, tmp_path / name)
    return tmp_path


def smk(cwd, *args, timeout=600):
    return subprocess.run([sys.executable, "-m", "snakemake", *args], cwd=cwd, capture_output=True,
                          text=True, timeout=timeout)


@pytest.mark.parametrize("key, bad", [("tol", "-1.0e-12"), ("maxiter", "0")])
def test_bad_config_stops_before_any_job(wf, key, bad):
    cfg = (wf / "config" / "config.yaml").read_text()
    lines = [ln if not ln.strip().startswith(f"{key}:") else f"  {key}: {bad}" for ln in cfg.splitlines()]
    (wf / "config" / "config.yaml").write_text("\n".join(lines) + "\n")
    out = smk(wf, "--cores", "1")
    assert out.returncode != 0
    text = out.stdout + out.stderr
    assert key in text and "solver" in text, text[-2000:]
    assert not (wf / "results").exists(), "nothing may be written on a bad config"


def test_lint_is_clean(wf):
    out = smk(wf, "--lint")
    assert out.returncode == 0, out.stdout[-3000:] + out.stderr[-3000:]


def test_scorecard_then_nothing_to_do(wf):
    out = smk(wf, "--cores", "2", "results/scorecard.md")
    assert out.returncode == 0, out.stderr[-3000:]
    card = (wf / "results" / "scorecard.md").read_text()
    assert "## Counts by paper" in card
    again = smk(wf, "-n", "results/scorecard.md")
    assert again.returncode == 0
    assert "Nothing to be done" in again.stdout + again.stderr
