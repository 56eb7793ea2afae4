# gearrep: every replication, its checks against the published numbers, and the scorecard.
# Run `snakemake --cores 2`; see README.md for single targets.
from snakemake.utils import min_version

min_version("8.0")


configfile: "config/config.yaml"


# `snakemake --report results/snakemake_report.html` (after a run) collects figures and scorecard.
report: "workflow/report/workflow.rst"


# The replication rules append their check files, final outputs, notebooks and report figures.
CHECK_FILES = []
FINAL_OUTPUTS = []
NOTEBOOKS = []
BENCHMARKS = []  # every job's benchmark file (results/bench/workflow_jobs.csv lists them)
REPORT_FIGURES = []


include: "workflow/rules/common.smk"
include: "workflow/rules/replications.smk"
include: "workflow/rules/scorecard.smk"
include: "workflow/rules/report.smk"
include: "workflow/rules/bench.smk"


localrules:
    all,
    scorecard,
    report,
    bench,
    bench_defaults,
    workflow_timing,


rule all:
    default_target: True
    input:
        "results/scorecard.csv",
        "results/scorecard.md",
        "results/report.html",
        FINAL_OUTPUTS,


# The end of a run of the default target (a no-op one too): where the report is and the verdict of
# each paper, read from the scorecard.
onsuccess:
    if not set(workflow.dag_settings.targets) - {"all"} and Path("results/report.html").is_file():
        import pandas as pd
        from gearrep.report import paper_verdicts

        card = pd.read_csv("results/scorecard.csv", dtype={"seed": str}, keep_default_na=False, na_values=[""])
        documents = {
            study.seed: (study.paper, study.document) for study in REGISTRY.values() if not study.validation
        }
        print("\nReport: results/report.html  (scorecard: results/scorecard.md)")
        for seed, (verdict, why) in paper_verdicts(card).items():
            name, document = documents[seed]
            print(f"  {name} (seed {seed}): {document}: {verdict.upper()} - {why}")
