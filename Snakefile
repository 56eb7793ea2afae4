# gearrep: every replication, its checks against the published numbers, and the scorecard.
# Run `snakemake --cores 2`; see README.md for single targets.
from pathlib import Path

from snakemake.utils import min_version, validate

min_version("8.0")

configfile: "config/config.yaml"
# `snakemake --report report.html` (after a run) collects the figures and the scorecard.
report: "workflow/report/workflow.rst"
# Stop before any job runs (and before anything is written) on a bad config value.
validate(config, "config/schema.yaml")

# Each replication's rules file appends its check file here; the scorecard gathers them.
CHECK_FILES = []
# Each replication's rules file appends its final outputs here (tables, figures).
FINAL_OUTPUTS = []
# Notebook names (notebooks/<name>.py.ipynb) and the key figures the report embeds.
NOTEBOOKS = []
REPORT_FIGURES = []

include: "workflow/rules/common.smk"

for _smk in sorted(Path(workflow.basedir, "workflow", "rules").glob("rep_*.smk")):
    include: str(_smk.relative_to(workflow.basedir))

include: "workflow/rules/scorecard.smk"
include: "workflow/rules/report.smk"
include: "workflow/rules/bench.smk"


rule all:
    default_target: True
    input:
        "results/scorecard.csv",
        "results/scorecard.md",
        "results/report.html",
        FINAL_OUTPUTS,
