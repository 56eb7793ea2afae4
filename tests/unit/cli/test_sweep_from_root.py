"""`gearrep sweep` run from the repository root, as the README shows it: Snakemake gets the sweep's
own settings, not the repository's default workflow profile (which Snakemake picks up from the
current directory), and the command returns when the sweep is done."""

from __future__ import annotations

import os
import subprocess
import sys
import time

import pandas as pd
import yaml
from conftest import ROOT


def test_sweep_from_the_repository_root_ignores_the_repository_profile(tmp_path):
    assert (ROOT / "profiles" / "default" / "config.yaml").is_file()  # what could leak in
    sweep = tmp_path / "sweep.yaml"
    sweep.write_text(
        yaml.safe_dump(
            {
                "design": str(ROOT / "examples" / "crowned_spur.yaml"),
                "grid": {"pinion.crowning.crown_mm": [0.05, 0.1]},
                "phi1_points": 41,
                "solves_per_shard": 82,  # one point per shard: two shard jobs
            }
        )
    )
    env = {**os.environ, "MPLBACKEND": "Agg"}
    t0 = time.perf_counter()
    r = subprocess.run(
        [sys.executable, "-m", "gearrep", "sweep", str(sweep), "-o", str(tmp_path / "out")],
        cwd=ROOT,
        env=env,
        capture_output=True,
        text=True,
        timeout=600,  # only the guard of a hang, far from the run's time
    )
    elapsed = time.perf_counter() - t0
    assert r.returncode == 0, r.stdout[-3000:] + r.stderr[-3000:]
    assert "profiles/default" not in r.stdout + r.stderr and "workflow specific profile" not in r.stdout + r.stderr
    table = pd.read_csv(tmp_path / "out" / "sweep.csv")
    assert len(table) == 2 and (table["status"] == "ok").all()
    print(f"\nsweep from the repository root: {elapsed:.1f} s")
