"""The Snakemake workflow: config validation and lint (the full run and its no-op re-run are in
test_full_workflow.py).

Each test runs Snakemake in a private copy of the repository's tracked inputs, so nothing is
written into the working tree and no test depends on an earlier run's results/.
"""

import subprocess
import sys

import pytest
from conftest import copy_workflow, tool_env


@pytest.fixture()
def wf(tmp_path):
    copy_workflow(tmp_path)
    return tmp_path


def smk(cwd, *args, timeout=600):
    return subprocess.run(
        [sys.executable, "-m", "snakemake", *args],
        cwd=cwd,
        capture_output=True,
        env=tool_env(),
        text=True,
        timeout=timeout,
    )


# Every bad value of the issues is refused by the resolution itself (test_workflow_lib.py and the
# robustness fuzzing call it directly); these run the real Snakemake for a value out of range, a
# NaN and a misspelt section.
@pytest.mark.parametrize(
    "section, key, bad",
    [
        ("catt", "maxiter", 0),
        ("thesis", "tol", float("nan")),
        ("nasaa", "tol", 1e-9),
    ],
)
def test_bad_config_stops_before_any_job(wf, section, key, bad):
    import yaml

    f = wf / "config" / "config.yaml"
    cfg = yaml.safe_load(f.read_text()) or {}
    cfg.setdefault(section, {})[key] = bad
    f.write_text(yaml.safe_dump(cfg))
    out = smk(wf, "--cores", "1")
    assert out.returncode != 0
    text = out.stdout + out.stderr
    assert key in text and section in text, text[-2000:]
    assert not (wf / "results").exists(), "nothing may be written on a bad config"


def test_lint_is_clean(wf):
    out = smk(wf, "--lint")
    assert out.returncode == 0, out.stdout[-3000:] + out.stderr[-3000:]


def test_quick_run_with_the_test_configuration_plans_every_study(wf):
    """config/test.yaml (the tests' settings) drives a quick workflow run through --configfile."""
    out = smk(wf, "-n", "--configfile", "config/test.yaml")
    assert out.returncode == 0, out.stdout[-3000:] + out.stderr[-3000:]
    from gearrep.replications import REGISTRY

    for key in REGISTRY:
        assert f"{key}_checks" in out.stdout


@pytest.mark.parametrize(
    "mutation, message",
    [
        ("delete", "values_000_T5.4.csv"),
        ("header_only", "params_004_examples.csv"),
        ("cross_field", "catt.section_check.design"),
    ],
)
def test_dry_run_stops_naming_the_file_or_key(wf, mutation, message):
    """Issue 16: `snakemake -n` stops, naming the file or key, for a deleted data file, a
    header-only data file and a cross-field limit."""
    data = wf / "data" / "published"
    if mutation == "delete":
        (data / "values_000_T5.4.csv").unlink()
    elif mutation == "header_only":
        f = data / "params_004_examples.csv"
        f.write_text(f.read_text().splitlines()[0] + "\n")
    else:
        (wf / "config" / "config.yaml").write_text("catt:\n  section_check:\n    design: no_such_design\n")
    out = smk(wf, "-n")
    assert out.returncode != 0
    assert message in out.stdout + out.stderr, (out.stdout + out.stderr)[-2000:]


def test_the_run_ends_without_waiting_for_snakemakes_selection_timers(wf):
    """Snakemake starts a selection timer of one max-jobs-per-timespan span after each selection
    that leaves a job waiting (two jobs on one core here); the Snakefile's hooks cancel the timers
    still pending at the end, so the process exits when the jobs are done instead of one span (600 s
    here) later. The subprocess timeout is only the guard of that hang, far from the run's time."""
    targets = ["results/tseng/curvature_table_4_2.csv", "results/tseng/curvature_table_4_5.csv"]
    try:
        out = smk(wf, "--cores", "1", "--max-jobs-per-timespan", "1000/600s", *targets, timeout=300)
    except subprocess.TimeoutExpired as e:
        raise AssertionError("Snakemake did not exit: a selection timer kept it alive") from e
    assert out.returncode == 0, out.stdout[-3000:] + out.stderr[-3000:]
    assert all((wf / t).is_file() for t in targets)


def test_both_end_hooks_cancel_the_selection_timers():
    """A failed run (onerror) exits at once as well as a successful one (onsuccess)."""
    from conftest import ROOT

    text = (ROOT / "Snakefile").read_text()
    for hook in ("onsuccess", "onerror"):
        body = text.split(f"\n{hook}:\n", 1)[1].split("\n\n", 1)[0]
        assert body.strip() == "cancel_pending_timers()", (hook, body)
