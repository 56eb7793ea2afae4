# gearrep: every replication, its checks against the published numbers, and the scorecard.
# Run `snakemake --cores 2`; see README.md for single targets.
from snakemake.utils import min_version, validate

min_version("8.0")


configfile: "config/config.yaml"


# `snakemake --report results/snakemake_report.html` (after a run) collects figures and scorecard.
report: "workflow/report/workflow.rst"


# The schema is generated from the settings declarations (JSON: read in a millisecond, where
# Snakemake took 0.27 s to read it as YAML); common.smk then resolves every setting
# (ranges, NaN, unknown keys, cross-field limits) before any job runs.
validate(config, "config/schema.json")

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
