# Seed 003 (Temirkhan thesis 2023): conventional vs reduced TCA, convergence from random starts,
# TE and paths of crowned gears under misalignment, crowning study (gearrep.replications.thesis).

THESIS_DIR = "results/thesis"
THESIS_TABLES = [
    "convergence", "convergence_detail", "agreement", "references", "starts_table10", "starts_sec61",
    "starts_helical", "timing", "te_summary", "te_curves", "te_cycle", "te_sensitivity", "crowning_areas",
    "errata", "protocol", "run_info", "te_readings",
]
THESIS_FIGURES = {
    "clouds": "convergence_clouds_table10.png",
    "clouds_phi2": "convergence_clouds_phi2.png",
    "window": "convergence_vs_phi2_window.png",
    "guess": "convergence_vs_phi2_guess_sec61.png",
    "te": "te_curves.png",
    "paths": "contact_paths.png",
}
# lib() adds everything gearrep.replications.thesis imports in turn
THESIS_LIB = lib("replications.thesis", "checks", "published")


rule thesis_run:
    input:
        io=REPLICATION_IO,
        code=THESIS_LIB,
    output:
        **{name: f"{THESIS_DIR}/{name}.csv" for name in THESIS_TABLES},
    params:
        thesis=config.get("thesis", {}),  # a changed setting reruns the study (params are tracked)
    log:
        "results/logs/thesis_run.log",
    benchmark:
        "results/benchmarks/thesis_run.tsv"
    conda:
        "../envs/gearrep.yaml"
    script:
        "../scripts/thesis_run.py"


rule thesis_figures:
    input:
        starts_table10=f"{THESIS_DIR}/starts_table10.csv",
        convergence=f"{THESIS_DIR}/convergence.csv",
        detail=f"{THESIS_DIR}/convergence_detail.csv",
        references=f"{THESIS_DIR}/references.csv",
        te_curves=f"{THESIS_DIR}/te_curves.csv",
        te_cycle=f"{THESIS_DIR}/te_cycle.csv",
        published=published_files("values_003_*.csv"),
        code=lib("plotting", "published"),
    output:
        **{k: figure(f"{THESIS_DIR}/figures/{v}", "thesis") for k, v in THESIS_FIGURES.items()},
    log:
        "results/logs/thesis_figures.log",
    conda:
        "../envs/gearrep.yaml"
    script:
        "../scripts/thesis_figures.py"


rule thesis_checks:
    input:
        io=REPLICATION_IO,
        tables=[f"{THESIS_DIR}/{name}.csv" for name in THESIS_TABLES],
        published=published_files("*_003_*.csv") + published_files("claims_003.csv"),
        code=THESIS_LIB,
    output:
        "results/checks/thesis.csv",
    log:
        "results/logs/thesis_checks.log",
    conda:
        "../envs/gearrep.yaml"
    script:
        "../scripts/thesis_checks.py"


CHECK_FILES.append("results/checks/thesis.csv")
FINAL_OUTPUTS.extend([f"{THESIS_DIR}/{name}.csv" for name in THESIS_TABLES])
FINAL_OUTPUTS.extend([f"{THESIS_DIR}/figures/{v}" for v in THESIS_FIGURES.values()])
REPORT_FIGURES.extend([f"{THESIS_DIR}/figures/{THESIS_FIGURES['window']}",
                       f"{THESIS_DIR}/figures/{THESIS_FIGURES['clouds']}"])


rule thesis_notebook:
    input:
        checks="results/checks/thesis.csv",
        tables=[f"{THESIS_DIR}/{name}.csv" for name in THESIS_TABLES],
        figures=[f"{THESIS_DIR}/figures/{v}" for v in THESIS_FIGURES.values()],
        benchmark="results/benchmarks/thesis_run.tsv",
        errata="data/errata.csv",
    output:
        touch("results/notebooks/thesis.executed"),
    log:
        notebook="results/notebooks/thesis.ipynb",
    conda:
        "../envs/gearrep.yaml"
    notebook:
        "../../notebooks/thesis.ipynb"


NOTEBOOKS.append("thesis")
