"""Write results/report.html: scorecard summary, per-paper tables, figures, errata, environment."""

import hashlib
import platform
import subprocess
from importlib.metadata import version
from pathlib import Path

import pandas as pd

from gearrep import report

smk = snakemake  # noqa: F821  (provided by Snakemake)

card = pd.read_csv(smk.input.scorecard, dtype={"seed": str}, keep_default_na=False, na_values=[""])
card["replication"] = card["replication"].astype(object).fillna("").astype(str)
figures = {
    Path(f).parent.parent.name + ": " + Path(f).stem.replace("_", " "): Path(f).read_bytes() for f in smk.input.figures
}
errata = pd.read_csv(smk.input.errata, dtype=str, keep_default_na=False)
notebooks = {Path(f).stem: "notebooks/" + Path(f).name for f in smk.input.notebooks}

try:
    commit = subprocess.run(
        ["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True, check=True
    ).stdout.strip()
    dirty = subprocess.run(
        ["git", "status", "--porcelain", "--untracked-files=no"], capture_output=True, text=True, check=True
    ).stdout.strip()
    commit += " (with uncommitted changes)" if dirty else ""
except (OSError, subprocess.CalledProcessError):
    commit = "unknown (not a git checkout)"

env = {
    "gearrep commit": commit,
    "config sha256": hashlib.sha256(Path(smk.input.config).read_bytes()).hexdigest()[:16],
    "requirements.lock sha256": hashlib.sha256(Path(smk.input.lock).read_bytes()).hexdigest(),
    "python": platform.python_version(),
    "platform": platform.platform(),
}
for pkg in ("numpy", "scipy", "pandas", "matplotlib", "snakemake", "papermill", "nbconvert"):
    env[pkg] = version(pkg)

runtime = 0.0
for tsv in Path("results/benchmarks").rglob("*.tsv"):
    b = pd.read_csv(tsv, sep="\t")
    runtime += float(b["s"].iloc[-1])

html = report.render(card, figures, errata, env, notebooks=notebooks, runtime_s=runtime)
Path(smk.output[0]).write_text(html, encoding="utf-8")
Path(smk.log[0]).write_text(f"report: {len(card)} rows, {len(figures)} figures, runtime {runtime:.1f} s\n")
