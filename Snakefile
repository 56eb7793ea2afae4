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
