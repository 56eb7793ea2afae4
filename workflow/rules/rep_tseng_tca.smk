# Seed 000, chapter 5 (curvilinear-tooth gears cut by a ZA hob): TCA, kinematic-error tables
# 5.2-5.9, contact ratio (eq 5.13), KE vs hob radius (Fig 5.5) (gearrep.replications.tseng_tca).
TSENG_TCA_DIR = "results/tseng_tca"
TSENG_KE_DIR = "results/tseng"  # the KE tables, one file per table (issue 8), beside the curvature tables
TSENG_TCA_KE = [f"ke_table_5_{i}" for i in range(2, 10)] + ["ke_example_5_3"]
TSENG_TCA_TABLES = TSENG_TCA_KE + ["sensitivity", "contact_ratio", "ke_vs_hob_radius", "ellipses_example_5_3",
                                   "ellipse_ratio", "topology_example_5_3", "run_info"]
TSENG_TCA_FIGURES = {
    "ke": "ke_tables.png",
    "zp": "contact_position_tables.png",
    "hob": "ke_vs_hob_radius.png",
    "ab": "a_over_b_vs_R_c.png",
}
TSENG_TCA_FILES = {name: f"{TSENG_KE_DIR if name in TSENG_TCA_KE else TSENG_TCA_DIR}/{name}.csv"
                   for name in TSENG_TCA_TABLES}

TSENG_TCA_LIB = lib("replications.tseng_tca", "published", "checks", "curvature", "curvature_relations", "ellipse",
                    "envelope", "solve", "surfaces.hob", "units")


rule tseng_tca_run:
    input:
        io=REPLICATION_IO,
        code=TSENG_TCA_LIB,
        params=published_files("params_000_*.csv"),
    output:
        **{name: TSENG_TCA_FILES[name] for name in TSENG_TCA_TABLES},
    params:
        settings=config.get("tseng_tca", {}),  # a changed setting reruns the job (params are tracked)
    log:
        "results/logs/tseng_tca_run.log",
    benchmark:
        "results/benchmarks/tseng_tca_run.tsv"
    conda:
        "../envs/gearrep.yaml"
    script:
        "../scripts/tseng_tca_run.py"


rule tseng_tca_figures:
    input:
        tables=[TSENG_TCA_FILES[name] for name in TSENG_TCA_KE + ["ke_vs_hob_radius", "ellipse_ratio"]],
        published=published_files("values_000_T5.*.csv") + published_files("values_000_text.csv"),
        code=lib("plotting", "published"),
    output:
        **{k: figure(f"{TSENG_TCA_DIR}/figures/{v}", "tseng_tca") for k, v in TSENG_TCA_FIGURES.items()},
    log:
        "results/logs/tseng_tca_figures.log",
    conda:
        "../envs/gearrep.yaml"
    script:
        "../scripts/tseng_tca_figures.py"


rule tseng_tca_checks:
    input:
        io=REPLICATION_IO,
        tables=[TSENG_TCA_FILES[name] for name in TSENG_TCA_TABLES],
        published=published_files("*_000_*.csv") + published_files("claims_000.csv"),
        code=TSENG_TCA_LIB,
    output:
        "results/checks/tseng_tca.csv",
    log:
        "results/logs/tseng_tca_checks.log",
    conda:
        "../envs/gearrep.yaml"
    script:
        "../scripts/tseng_tca_checks.py"


rule tseng_tca_notebook:
    input:
        checks="results/checks/tseng_tca.csv",
        tables=[TSENG_TCA_FILES[name] for name in TSENG_TCA_TABLES],
        figures=[f"{TSENG_TCA_DIR}/figures/{v}" for v in TSENG_TCA_FIGURES.values()],
        published=published_files("values_000_T5.*.csv") + published_files("values_000_text.csv"),
        benchmark="results/benchmarks/tseng_tca_run.tsv",
        code=lib("plotting"),
    output:
        touch("results/notebooks/tseng_tca.executed"),
    log:
        notebook="results/notebooks/tseng_tca.ipynb",
    conda:
        "../envs/gearrep.yaml"
    notebook:
        "../../notebooks/tseng_tca.ipynb"


CHECK_FILES.append("results/checks/tseng_tca.csv")
FINAL_OUTPUTS.extend([TSENG_TCA_FILES[name] for name in TSENG_TCA_TABLES])
FINAL_OUTPUTS.extend([f"{TSENG_TCA_DIR}/figures/{v}" for v in TSENG_TCA_FIGURES.values()])
REPORT_FIGURES.extend([f"{TSENG_TCA_DIR}/figures/{TSENG_TCA_FIGURES['ke']}",
                       f"{TSENG_TCA_DIR}/figures/{TSENG_TCA_FIGURES['zp']}"])
NOTEBOOKS.append("tseng_tca")
