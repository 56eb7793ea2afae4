# The one-page report. Each replication's rules add to NOTEBOOKS (the studies whose notebook rule
# writes results/notebooks/<name>.html) and to REPORT_FIGURES. The report job only assembles the
# page: every figure it embeds, the parity plots included, is drawn by a job of its own.

# The parity plots of one paper (seed), drawn as soon as the checks of its studies exist, so that
# the report job at the end of a run only assembles the page.
# (a validation study is no paper: its records have no parity plots)
PARITY_SEEDS = sorted({study.seed for study in REGISTRY.values() if not study.validation})
#: the check files of each seed's studies
SEED_CHECKS = {
    seed: [
        f"results/{load_study(key).CHECK_OUTPUTS['checks']}" for key, study in REGISTRY.items() if study.seed == seed
    ]
    for seed in PARITY_SEEDS
}


rule report_parity:
    input:
        checks=lambda wildcards: SEED_CHECKS[wildcards.seed],
        published=lambda wildcards: published_files(f"values_{wildcards.seed}_*.csv", f"claims_{wildcards.seed}.csv"),
        code=script_lib("workflow/scripts/report_parity.py"),
    output:
        directory("results/parity/{seed}"),
    log:
        "results/logs/parity_{seed}.log",
    benchmark:
        "results/benchmarks/parity/{seed}.tsv"
    wildcard_constraints:
        seed="|".join(PARITY_SEEDS),
    params:
        published_dir=PUBLISHED_DIR,
    script:
        "../scripts/report_parity.py"


BENCHMARKS.extend(expand("results/benchmarks/parity/{seed}.tsv", seed=PARITY_SEEDS))


rule report:
    input:
        scorecard="results/scorecard.csv",
        notebooks=expand("results/notebooks/{name}.html", name=NOTEBOOKS),
        figures=REPORT_FIGURES,
        parity=expand("results/parity/{seed}", seed=PARITY_SEEDS),
        errata="data/errata.csv",
        published=published_files(),
        manifest=f"{PUBLISHED_DIR}/MANIFEST.csv",
        captions="workflow/report/captions.yaml",
        highlights="workflow/report/highlights.yaml",
        config="config/config.yaml",
        lock="requirements.lock",
        code=script_lib("workflow/scripts/report.py"),
    output:
        "results/report.html",
    log:
        "results/logs/report.log",
    benchmark:
        "results/benchmarks/report.tsv"
    script:
        "../scripts/report.py"


# Optional (not in the default target; needs Chromium): `snakemake --cores 1 results/report.png`.
rule report_screenshot:
    input:
        "results/report.html",
    output:
        "results/report.png",
    log:
        "results/logs/report_screenshot.log",
    script:
        "../scripts/screenshot.py"
