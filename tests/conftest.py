"""Shared test fixtures: repository paths, the published data, the seed texts."""

import os
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PUBLISHED_DIR = ROOT / "data" / "published"


def seeds_dir() -> Path:
    """The OCR'd seed texts: $GEARREP_SEEDS, else ../shared/seeds beside the repository."""
    return Path(os.environ.get("GEARREP_SEEDS", ROOT.parent / "shared" / "seeds"))


@pytest.fixture(scope="session")
def published():
    from gearrep import published as pub

    return pub.load(PUBLISHED_DIR)


@pytest.fixture(scope="session")
def seed_lines():
    """{'000': [line1, line2, ...], ...}: the seed texts, 1-based via index - 1."""
    d = seeds_dir()
    if not d.is_dir():
        pytest.skip(f"seed texts not found at {d} (set GEARREP_SEEDS)")
    out = {}
    for f in sorted(d.glob("*.txt")):
        out[f.name[:3]] = f.read_text(encoding="utf-8").splitlines()
    return out


#: what a workflow run needs from the repository (everything tracked that Snakemake reads)
WORKFLOW_INPUTS = ["Snakefile", "config", "workflow", "data", "src", "notebooks"]


def copy_workflow(dest: Path) -> Path:
    """Copy the workflow's tracked inputs into ``dest`` so a test can run Snakemake without
    touching the working tree (and without leftovers of an earlier run)."""
    import shutil

    for name in WORKFLOW_INPUTS:
        src = ROOT / name
        if src.is_dir():
            shutil.copytree(src, dest / name, ignore=shutil.ignore_patterns("__pycache__", ".ipynb_checkpoints"))
        elif src.exists():
            shutil.copy2(src, dest / name)
    return dest
