"""Shared test fixtures: repository paths, the published data, the seed texts, workflow copies,
and the condition-number record of the stress suite (tests/stress; `make stress` runs it in full,
the table of Jacobian condition numbers seen is printed at the end of the run)."""

import os
import sys
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[1]
PUBLISHED_DIR = ROOT / "data" / "published"


def seeds_dir() -> Path:
    """The OCR'd seed texts: $GEARREP_SEEDS, else ../shared/seeds beside the repository."""
    return Path(os.environ.get("GEARREP_SEEDS", ROOT.parent / "shared" / "seeds"))


CONFIG_FILES = [ROOT / "config" / "config.yaml", ROOT / "config" / "test.yaml"]


def study_settings(key: str) -> dict:
    """Settings of study ``key`` as the quick workflow run resolves them: the declared values,
    overridden by config/config.yaml, then by config/test.yaml (the test configuration, the same
    file `snakemake --configfile config/test.yaml` uses)."""
    import yaml

    from gearrep import settings
    from gearrep.replications import load

    layers = [(yaml.safe_load(f.read_text()) or {}).get(key) for f in CONFIG_FILES]
    return settings.resolve(load(key).SETTINGS, *layers, where=key)


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
WORKFLOW_INPUTS = ["Snakefile", "config", "workflow", "data", "src", "notebooks", "profiles", "requirements.lock"]


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


def run_target(dest: Path, target: str) -> Path:
    """Make ``target`` (a path) with Snakemake in a fresh copy of the workflow under ``dest``
    (:func:`copy_workflow`, :func:`tool_env`); the path of the made file (assertion with the end of
    Snakemake's error output if the run fails)."""
    import subprocess

    wf = copy_workflow(dest)
    run = subprocess.run(
        [sys.executable, "-m", "snakemake", "--cores", "2", target],
        cwd=wf,
        capture_output=True,
        env=tool_env(),
        text=True,
        timeout=3600,
    )
    assert run.returncode == 0, run.stderr[-3000:]
    return wf / target


def tool_env() -> dict:
    """Environment for running Snakemake from a test as a user with no activated venv: the
    interpreter's bin directory is taken OFF the PATH, so every workflow test also checks that the
    rules find papermill and nbconvert through the interpreter running Snakemake."""
    env = dict(os.environ)
    own = str(Path(sys.executable).parent)
    env["PATH"] = os.pathsep.join(p for p in env.get("PATH", "").split(os.pathsep) if p and p != own)
    env.setdefault("MPLBACKEND", "Agg")
    return env


_SEEN: list[tuple[str, int, int, float, float, float]] = []


@pytest.fixture()
def record_conditions(request):
    """Call with (array of condition numbers) to report them under the test's name."""

    def record(cond, label=""):
        c = np.asarray(cond, float)
        n_inf = int(np.sum(np.isposinf(c)))
        c = c[np.isfinite(c)]
        name = request.node.name + (f" [{label}]" if label else "")
        stats = (float(c.min()), float(np.median(c)), float(c.max())) if c.size else (np.nan,) * 3
        _SEEN.append((name, c.size, n_inf, *stats))

    return record


def pytest_terminal_summary(terminalreporter):
    if not _SEEN:
        return
    tr = terminalreporter
    tr.section("Jacobian condition numbers seen (converged and unconverged solves)")
    tr.write_line(f"{'case':70s} {'n':>6s} {'singular':>8s} {'min':>10s} {'median':>10s} {'max':>10s}")
    for name, n, n_inf, lo, med, hi in _SEEN:
        tr.write_line(f"{name[:70]:70s} {n:6d} {n_inf:8d} {lo:10.3g} {med:10.3g} {hi:10.3g}")


def assert_honest(c, ref=None, tol=1e-12, atol=1e-8):
    """Stress-suite check of a batch of contact points (gearrep.tca.ContactPoints): every status is
    known; converged points are finite with residual below ``tol`` and, if ``ref`` is given, equal
    to that reference contact. Returns the converged positions."""
    from gearrep.solve import Status

    assert set(np.unique(c.status)) <= {int(s) for s in Status}
    ok = c.converged
    for name in ("u1", "v1", "u2", "v2", "phi2", "te", "residual"):
        assert np.all(np.isfinite(getattr(c, name)[ok])), name
    assert np.all(np.isfinite(c.position[ok])) and np.all(np.isfinite(c.normal[ok]))
    assert np.all(c.residual[ok] < tol)
    p = c.position[ok]
    if ref is not None:
        assert np.all(np.abs(c.u1[ok] - ref.u1[0]) < atol), np.max(np.abs(c.u1[ok] - ref.u1[0]))
        assert np.all(np.abs(c.v1[ok] - ref.v1[0]) < atol)
        assert np.all(np.abs(c.phi2[ok] - ref.phi2[0]) < atol)
    return p


# Files that take longest (whole files per pytest-xdist worker, --dist loadfile) are handed out
# first, so the two workers end together: the cold full workflow run, then the Snakemake plans.
_LONG_FILES = ("tests/unit/workflow/test_full_workflow.py", "tests/unit/workflow/test_rule_graph.py")


def pytest_collection_modifyitems(config, items):
    def rank(item):
        path = item.nodeid.split("::", 1)[0]
        return _LONG_FILES.index(path) if path in _LONG_FILES else len(_LONG_FILES)

    items.sort(key=rank)  # stable: the order within and among the other files is kept
