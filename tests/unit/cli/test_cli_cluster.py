"""A small `gearrep sweep` through Snakemake's cluster-generic executor with a local submit script
(marker ``cluster``; needs the ``cluster`` extra, snakemake-executor-plugin-cluster-generic): every
shard is submitted as a cluster job, the shard tables and the aggregated sweep equal those of the
local run byte for byte, and re-running one shard rewrites that shard alone (same numbers) and
touches no other result."""

from __future__ import annotations

import contextlib
import hashlib
import io
import os
from pathlib import Path

import pytest
import yaml
from conftest import ROOT

from gearrep.cli import main

pytestmark = pytest.mark.cluster


SUBMIT = """#!/bin/bash
# A local "cluster": record the submission, run the job script now, print a job id.
jobscript="${@: -1}"
echo "$jobscript" >> "%(record)s"
bash "$jobscript" > "$jobscript.out" 2>&1
echo "local-$(basename "$jobscript")"
"""


def _run(*argv):
    err = io.StringIO()
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
        rc = main([str(a) for a in argv])
    return rc, err.getvalue()


def _state(d: Path) -> dict:
    """{relative path: (sha256, mtime_ns)} of the sweep's results (Snakemake's own dirs left out)."""
    out = {}
    for p in sorted(d.rglob("*")):
        rel = p.relative_to(d).as_posix()
        if p.is_file() and not rel.startswith((".snakemake", "logs/")):
            out[rel] = (hashlib.sha256(p.read_bytes()).hexdigest(), p.stat().st_mtime_ns)
    return out


def test_sweep_on_the_cluster_generic_executor_equals_the_local_run(tmp_path, monkeypatch):
    pytest.importorskip("snakemake_executor_plugin_cluster_generic")
    monkeypatch.setenv("PYTHONPATH", os.pathsep.join([str(ROOT / "src"), os.environ.get("PYTHONPATH", "")]))
    monkeypatch.setenv("MPLBACKEND", "Agg")
    sweep = tmp_path / "sweep.yaml"
    sweep.write_text(
        yaml.safe_dump(
            {
                "design": str(ROOT / "examples" / "crowned_spur.yaml"),
                "grid": {"misalignment.d_gamma_out_deg": [0.0, 0.05], "pinion.crowning.crown_mm": [0.05, 0.1, 0.2]},
                "phi1_points": 41,
                "solves_per_shard": 162,  # 81 solves per point: 2 points per shard, 3 shards
                "resources": {"threads": 1, "mem_mb": 500, "runtime_min": 5},
            }
        )
    )
    record = tmp_path / "submitted.txt"
    submit = tmp_path / "submit.sh"
    submit.write_text(SUBMIT % {"record": record})
    submit.chmod(0o755)
    cluster = ["--executor", "cluster-generic", "--cluster-generic-submit-cmd", str(submit), "--jobs", "3"]

    rc, err = _run("sweep", sweep, "-o", tmp_path / "local", "--cores", "1")
    assert rc == 0, err
    rc, err = _run("sweep", sweep, "-o", tmp_path / "cluster", "--", *cluster)
    assert rc == 0, err
    assert len(record.read_text().splitlines()) == 3  # the shards went through the submit script; aggregate is local

    local, clus = tmp_path / "local", tmp_path / "cluster"
    for name in ["sweep.csv"] + [f"shards/shard_{i}.csv" for i in range(3)]:
        assert (clus / name).read_bytes() == (local / name).read_bytes(), name
    for name in ["sweep.csv.prov.json"] + [f"shards/shard_{i}.csv.prov.json" for i in range(3)]:
        assert (clus / name).is_file()

    before = _state(clus)
    rc, err = _run("sweep", sweep, "-o", clus, "--", "shards/shard_1.csv", "--force", *cluster)
    assert rc == 0, err
    assert len(record.read_text().splitlines()) == 4
    after = _state(clus)
    assert set(after) == set(before)
    changed = {k for k in after if after[k] != before[k]}
    assert changed <= {"shards/shard_1.csv", "shards/shard_1.csv.prov.json"}, changed
    assert after["shards/shard_1.csv"][0] == before["shards/shard_1.csv"][0]  # same numbers


def test_slurm_profile_plans_the_sweep_with_the_declared_resources(tmp_path):
    """Dry run with profiles/slurm (needs the `slurm` extra): every shard is a job with the sweep's
    mem_mb and runtime."""
    pytest.importorskip("snakemake_executor_plugin_slurm")
    import re
    import subprocess
    import sys

    sweep = tmp_path / "sweep.yaml"
    sweep.write_text(
        yaml.safe_dump(
            {
                "design": str(ROOT / "examples" / "helical.yaml"),
                "grid": {"misalignment.d_gamma_in_deg": [0.0, 0.02, 0.05]},
                "phi1_points": 101,
                "solves_per_shard": 101,
                "resources": {"mem_mb": 1500, "runtime_min": 20},
            }
        )
    )
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src")}
    r = subprocess.run(
        [sys.executable, "-m", "gearrep", "sweep", str(sweep), "-o", str(tmp_path / "o"), "--dry-run"]
        + ["--profile", str(ROOT / "profiles" / "slurm")],
        env=env,
        capture_output=True,
        text=True,
    )
    assert r.returncode == 0, r.stderr
    res = re.findall(r"rule shard:(?:\n    .*)*?\n    resources: (.*)", r.stdout)
    assert len(res) == 3 and all("mem_mb=1500" in x and "runtime=20" in x for x in res)
