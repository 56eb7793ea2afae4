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


#: the one lint the workflow keeps on purpose: its software is the pinned environment of
#: requirements.lock that `make setup` installs (README, Install), not a conda environment or a
#: container per rule, which could not be built or tested where the project is developed
SOFTWARE_LINT = "Specify a conda environment or container for each rule."


def test_lint_is_clean(wf):
    out = smk(wf, "--lint", "--workflow-profile", "none")
    text = out.stdout + out.stderr
    lints = [ln.strip() for ln in text.splitlines() if ln.startswith("    * ")]
    assert lints, text[-3000:]  # the lint ran and found the rules
    assert {ln.removeprefix("* ").removesuffix(":") for ln in lints} == {SOFTWARE_LINT}, text[-3000:]


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
