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


# Every bad value is refused by the resolution itself (test_workflow_lib.py and the robustness
# fuzzing call it directly); these run the real Snakemake for an unknown section, an unknown key, a
# wrong type, a value out of range and a NaN, given each of the three ways a user sets them.
BAD_CONFIGS = [
    ({"litvin200": {"tol": 1e-9}}, "config.litvin200: unknown setting (did you mean 'litvin2000'?)", "config.yaml"),
    ({"litvin200": {"tol": 1e-9}}, "config.litvin200: unknown setting (did you mean 'litvin2000'?)", "--configfile"),
    ({"litvin200": {"tol": 1e-9}}, "config.litvin200: unknown setting (did you mean 'litvin2000'?)", "--config"),
    ({"ma2021": {"maxitr": 5}}, "config.ma2021.maxitr: unknown setting (did you mean 'maxiter'?)", "--config"),
    (
        {"ma2021": {"maxiter": "ten"}},
        "config.ma2021.maxiter: got 'ten'; allowed: an integer in [1, 1000]",
        "config.yaml",
    ),
    ({"ma2021": {"maxiter": 0}}, "config.ma2021.maxiter: got 0; allowed: an integer in [1, 1000]", "--configfile"),
    ({"temirkhan2023": {"tol": float("nan")}}, "config.temirkhan2023.tol: got", "--config"),
]


@pytest.mark.parametrize("bad, message, route", BAD_CONFIGS, ids=[f"{r}-{m.split(':')[0]}" for _, m, r in BAD_CONFIGS])
def test_bad_config_stops_before_any_job_with_one_line(wf, bad, message, route):
    """One line naming the key, the value and what is allowed (the closest name for an unknown
    one), before any job and without a traceback or the schema, however the value is given."""
    import json

    import yaml

    ((section, values),) = bad.items()
    args = []
    if route == "config.yaml":
        (wf / "config" / "config.yaml").write_text(yaml.safe_dump(bad))
    elif route == "--configfile":
        (wf / "bad.yaml").write_text(yaml.safe_dump(bad))
        args = ["--configfile", "bad.yaml"]
    else:
        args = ["--config", f"{section}={json.dumps(values).replace('NaN', '.nan')}"]
    out = smk(wf, "--cores", "1", *args)
    assert out.returncode != 0
    text = out.stdout + out.stderr
    errors = [ln for ln in text.splitlines() if "bad configuration" in ln]
    assert len(errors) == 1 and message in errors[0], text[-2000:]
    assert "allowed" in errors[0] or "declared" in errors[0], errors[0]
    assert len(text.splitlines()) <= 4 and "Traceback" not in text and "File " not in text, text[-2000:]
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

    for key in REGISTRY:  # the progress display's plan names each rule with spaces for underscores
        assert f"{key}_checks".replace("_", " ") in out.stdout + out.stderr, (out.stdout + out.stderr)[-3000:]


@pytest.mark.parametrize(
    "mutation, message",
    [
        ("delete", "values_000_T5.4.csv"),
        ("header_only", "params_004_examples.csv"),
        ("cross_field", "ma2021.section_check.design"),
    ],
)
def test_dry_run_stops_naming_the_file_or_key(wf, mutation, message):
    """`snakemake -n` stops, naming the file or key, for a deleted data file, a
    header-only data file and a cross-field limit."""
    data = wf / "data" / "published"
    if mutation == "delete":
        (data / "values_000_T5.4.csv").unlink()
    elif mutation == "header_only":
        f = data / "params_004_examples.csv"
        f.write_text(f.read_text().splitlines()[0] + "\n")
    else:
        (wf / "config" / "config.yaml").write_text("ma2021:\n  section_check:\n    design: no_such_design\n")
    out = smk(wf, "-n")
    assert out.returncode != 0
    assert message in out.stdout + out.stderr, (out.stdout + out.stderr)[-2000:]
