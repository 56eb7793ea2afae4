"""Compute only what is asked, checked on Snakemake's own dry-run plans.

* Every rule declares as inputs exactly the gearrep modules its script or notebook imports,
  directly or through other gearrep modules (found independently here with the standard
  library's ``modulefinder``), so that a library change reruns exactly the jobs it affects.
* Asking for one replication's checks, or for the scorecard, plans no figure, notebook, report
  or benchmark job; the benchmark and the screenshot stay out of the default target.
* With every output up to date, touching one library module plans exactly the jobs that use it.

Each test runs Snakemake in a private copy of the repository's tracked inputs (dry runs only).
The plan of one target with ``--forceall`` is read off one dry run of every target at once (the
jobs its output needs, input by input); a test checks that this gives Snakemake's own plan.
"""

from __future__ import annotations

import json
import modulefinder
import re
import subprocess
import sys
import tempfile
from pathlib import Path

import pytest
from conftest import ROOT, copy_workflow, tool_env

SRC = ROOT / "src"


@pytest.fixture(scope="module")
def wf(tmp_path_factory):
    d = tmp_path_factory.mktemp("wf")
    copy_workflow(d)
    return d


def smk(cwd, *args):
    """Snakemake without the default profile (whose logger draws progress bars): its plain log lists
    every planned job with its input and output, which :func:`plan` reads."""
    out = subprocess.run(
        [sys.executable, "-m", "snakemake", "--workflow-profile", "none", *args],
        cwd=cwd,
        capture_output=True,
        env=tool_env(),
        text=True,
        timeout=300,
    )
    assert out.returncode == 0, out.stdout[-3000:] + out.stderr[-3000:]
    return out.stdout + out.stderr


#: every target at once: the default target, the benchmark (all replications) and the screenshot
EVERY_TARGET = ("all", "bench", "results/report.png")


def full_plan(wf, bench_config: Path) -> list[dict]:
    """The --forceall plan of EVERY_TARGET with every replication benchmarked (``bench_config``)."""
    return plan(wf, *EVERY_TARGET, "--forceall", "--configfile", "config/config.yaml", str(bench_config))


@pytest.fixture(scope="module")
def bench_all(tmp_path_factory) -> Path:
    """A config file that benchmarks every replication."""
    extra = tmp_path_factory.mktemp("cfg") / "bench_all.yaml"
    extra.write_text("bench:\n  replications: " + json.dumps(_bench_names()) + "\n")
    return extra


@pytest.fixture(scope="module")
def every_job(wf, bench_all):
    return full_plan(wf, bench_all)


def needed(jobs: list[dict], target: str) -> list[dict]:
    """The jobs of ``jobs`` (a --forceall plan) that ``target`` (an output file, or a rule without
    output such as ``all``) needs: its own job and, input by input, the jobs writing their inputs;
    each once, in plan order. With --forceall this is what Snakemake plans for ``target``
    (checked against Snakemake's own plans by a test)."""
    by_output = {o: i for i, j in enumerate(jobs) for o in j["output"]}
    own = [i for i, j in enumerate(jobs) if target in j["output"] or (j["rule"] == target and not j["output"])]
    assert len(own) == 1, f"{target}: {len(own)} jobs write it"
    seen, todo = set(own), list(own)
    while todo:
        for path in jobs[todo.pop()]["input"]:
            i = by_output.get(path)
            if i is not None and i not in seen:
                seen.add(i)
                todo.append(i)
    return [jobs[i] for i in sorted(seen)]


def plan(cwd, *args) -> list[dict]:
    """The jobs of a dry run: rule, input, output, wildcards, reason (lists of paths)."""
    jobs, job = [], None
    for line in smk(cwd, "-n", *args).splitlines():
        m = re.match(r"^(?:local)?rule (\w+):$", line)
        if m:
            job = {"rule": m.group(1), "input": [], "output": [], "wildcards": {}, "reason": ""}
            jobs.append(job)
            continue
        m = re.match(r"^    (input|output|wildcards|reason): (.*)$", line)
        if job is not None and m:
            key, val = m.groups()
            if key in ("input", "output"):
                job[key] = [p.strip() for p in val.split(",")]
            elif key == "wildcards":
                job[key] = dict(kv.strip().split("=", 1) for kv in val.split(","))
            else:
                job[key] = val
        elif not line.startswith("    "):
            job = None
    return jobs


def rule_sources() -> dict[str, tuple[Path, list[str]]]:
    """rule name -> (the script or notebook it runs, modules it imports dynamically); rules with
    run blocks are left out. The replication rules are generated from the registry."""
    from gearrep.replications import REGISTRY, load

    out = {}
    for smk_file in sorted((ROOT / "workflow" / "rules").glob("*.smk")):
        blocks = re.split(r"^rule (\w+):\s*$", smk_file.read_text(), flags=re.M)
        for name, body in zip(blocks[1::2], blocks[2::2]):
            m = re.search(r"^\s+(?:script|notebook):\s*\n?\s*f?\"([^\"]+)\"", body, flags=re.M)
            if m:
                out[name] = ((smk_file.parent / m.group(1)).resolve(), [])
    scripts = ROOT / "workflow" / "scripts"
    for key in REGISTRY:
        dynamic = [f"gearrep.replications.{key}"]
        for job in load(key).JOBS:
            out[f"{key}_{job}"] = (scripts / "run_job.py", dynamic)
        out[f"{key}_checks"] = (scripts / "run_checks.py", dynamic)
        out[f"{key}_figures"] = (scripts / f"{key}_figures.py", [])
        # the notebook and the script that executes and renders it
        out[f"{key}_notebook"] = ((ROOT / "notebooks" / f"{key}.ipynb", scripts / "notebook.py"), [])
    return out


SCRIPT_MODULES = {p.stem for p in (ROOT / "workflow" / "scripts").glob("*.py")}


class _GearrepFinder(modulefinder.ModuleFinder):
    """modulefinder restricted to gearrep and the helper modules beside the scripts (which
    Snakemake puts on sys.path): other top-level packages are not followed."""

    def import_hook(self, name, caller=None, fromlist=None, level=-1):
        if level <= 0 and name.split(".")[0] not in ("gearrep", *SCRIPT_MODULES):
            return None
        return super().import_hook(name, caller, fromlist, level)


def _is_attribute(dotted: str) -> bool:
    """``pkg.name`` where ``name`` is a function or class of package ``pkg`` (``from pkg import
    name``), which modulefinder reports as a missing submodule."""
    import importlib

    parent, _, name = dotted.rpartition(".")
    try:
        return hasattr(importlib.import_module(parent), name)
    except ImportError:
        return False


def gearrep_files(source: Path, extra_modules=()) -> set[str]:
    """Repository-relative files of every gearrep module `source` (script or notebook) imports."""
    code = source.read_text()
    if source.suffix == ".ipynb":
        cells = json.loads(code)["cells"]
        code = "\n".join("".join(c["source"]) for c in cells if c["cell_type"] == "code")
        code = "\n".join(ln for ln in code.splitlines() if not ln.lstrip().startswith(("%", "!")))
    code += "".join(f"\nimport {m}" for m in extra_modules)
    finder = _GearrepFinder(path=[str(SRC), str(ROOT / "workflow" / "scripts")] + sys.path)
    with tempfile.TemporaryDirectory() as d:
        tmp = Path(d) / f"{source.stem}.py"
        tmp.write_text(code)
        finder.run_script(str(tmp))
    missing = sorted(m for m in finder.badmodules if m.startswith("gearrep") and not _is_attribute(m))
    assert not missing, f"{source.name} imports gearrep modules that do not exist: {missing}"
    return {
        str(Path(m.__file__).resolve().relative_to(ROOT))
        for name, m in finder.modules.items()
        if name.startswith("gearrep")
    }


def _bench_names() -> list[str]:
    from gearrep.replications import REGISTRY

    return sorted(REGISTRY)


def test_every_rule_declares_exactly_the_library_it_imports(every_job):
    sources = rule_sources()
    checked, wrong, found = set(), [], {}
    for job in every_job:
        src, dynamic = sources.get(job["rule"], (None, []))
        if src is None:
            continue
        if job["rule"] == "bench_replication":
            dynamic = [f"gearrep.replications.{job['wildcards']['name']}"]
        declared = {p for p in job["input"] if p.startswith("src/gearrep/")}
        key = (src, tuple(dynamic))  # many jobs run the same source (the study steps)
        if key not in found:
            found[key] = set().union(*(gearrep_files(s, dynamic) for s in (src if isinstance(src, tuple) else [src])))
        wanted = found[key]
        if declared != wanted:
            wrong.append(
                f"rule {job['rule']} ({src}): declared but not imported {sorted(declared - wanted)}; "
                f"imported but not declared {sorted(wanted - declared)}"
            )
        checked.add(job["rule"])
    assert not wrong, "\n".join(wrong)
    assert {"scorecard", "report", "bench_core"} <= checked


FINAL_KINDS = re.compile(r"^results/(notebooks/|report|parity/|bench/|.*/figures/)")


def _check_files() -> dict[str, str]:
    from gearrep.replications import REGISTRY, load

    return {key: f"results/{load(key).CHECK_OUTPUTS['checks']}" for key in REGISTRY}


def _jobs(plan_jobs) -> list[tuple]:
    return sorted((j["rule"], tuple(sorted(j["output"])), tuple(sorted(j["input"]))) for j in plan_jobs)


@pytest.mark.parametrize("target", ["results/scorecard.md", "bench"])
def test_the_jobs_a_target_needs_are_snakemakes_own_plan(wf, bench_all, every_job, target):
    """What the other tests read off the plan of every target (:func:`needed`) is the plan
    Snakemake itself makes for the target alone: the scorecard (every replication's check chain)
    and the benchmark (a rule without output, with every replication configured)."""
    extra = ("--configfile", "config/config.yaml", str(bench_all)) if target == "bench" else ()
    own = plan(wf, "--forceall", target, *extra)
    assert own and _jobs(needed(every_job, target)) == _jobs(own)


def test_one_replication_check_file_plans_only_its_own_chain(every_job):
    for name, target in _check_files().items():
        jobs = needed(every_job, target)
        rules = [j["rule"] for j in jobs]
        assert all(r.startswith(f"{name}_") for r in rules), (target, rules)
        assert len(rules) == len(set(rules)), (target, rules)
        outs = [o for j in jobs for o in j["output"]]
        assert not [o for o in outs if FINAL_KINDS.match(o)], (target, outs)


def test_scorecard_plans_no_figure_notebook_report_or_bench(every_job):
    jobs = needed(every_job, "results/scorecard.md")
    outs = [o for j in jobs for o in j["output"]]
    assert not [o for o in outs if FINAL_KINDS.match(o)], outs
    n_checks = sum(len(needed(every_job, t)) for t in _check_files().values())
    assert len(jobs) == 1 + n_checks  # the scorecard job itself plus each replication's check chain


def test_job_counts_of_framework_targets(every_job):
    assert [j["rule"] for j in needed(every_job, "results/bench/throughput.csv")] == ["bench_core"]
    from gearrep.replications import REGISTRY

    # one bench_replication job per configured replication (every_job configures all of them)
    bench = sorted(j["rule"] for j in needed(every_job, "bench"))
    assert bench == sorted(
        ["bench", "bench_core", "bench_defaults", "bench_robustness"] + ["bench_replication"] * len(REGISTRY)
    )
    default = {j["rule"] for j in needed(every_job, "all")}
    assert not {r for r in default if r.startswith("bench")} and "report_screenshot" not in default
    assert {"scorecard", "report", "all"} <= default


def test_touching_one_module_reruns_exactly_its_users(wf, every_job):
    """Mark every output of the default target as up to date (empty files + --touch), then touch
    src/gearrep/report/_page.py: only the report job, the per-seed parity-plot jobs that draw with it
    (one per seed with a study) and the `all` target may be planned."""
    for job in needed(every_job, "all"):
        for o in job["output"]:
            p = wf / o
            p.parent.mkdir(parents=True, exist_ok=True)
            p.touch()
    smk(wf, "--cores", "1", "--touch", "-q")
    assert "Nothing to be done" in smk(wf, "-n")
    (wf / "src" / "gearrep" / "report" / "_page.py").touch()
    from gearrep.replications import REGISTRY

    n_seeds = len({s.seed for s in REGISTRY.values() if not s.validation})  # a validation study has no parity plots
    assert sorted(j["rule"] for j in plan(wf)) == ["all", "report"] + ["report_parity"] * n_seeds


def test_one_table_is_one_job_and_writes_only_that_table(tmp_path):
    """Asking for one KE table plans and runs that table's job alone."""
    (tmp_path / "wf").mkdir()
    d = copy_workflow(tmp_path / "wf")
    target = "results/hobcut_tca/ke_table_5_4.csv"
    jobs = plan(d, target)
    assert [j["rule"] for j in jobs] == ["hobcut_tca_ke_table_5_4"]
    smk(d, "--cores", "1", target)
    tables = sorted(str(p.relative_to(d)) for p in (d / "results").rglob("*.csv"))
    assert tables == [target], tables


@pytest.mark.parametrize(
    "target", ["results/temirkhan2023/convergence.csv", "results/hobcut_curvature/curvature_table_4_3.csv"]
)
def test_one_study_output_plans_its_job_alone(every_job, target):
    jobs = needed(every_job, target)
    assert len(jobs) == 1, [j["rule"] for j in jobs]
