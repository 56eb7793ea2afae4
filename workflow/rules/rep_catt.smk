# Seed 004 (Ma et al. 2021): CATT cylindrical gears, TCA and contact-ellipse area trends
# (gearrep.replications.catt, surfaces in gearrep.surfaces.catt).
CATT_DIR = "results/catt"
CATT_TABLES = ["designs", "cycle", "pitch_point", "precision", "thickness", "sections", "equations", "gap_check",
               "settings", "run_info"]
CATT_FIGURES = {
    "fig12": "fig12_area_vs_module.png",
    "fig13": "fig13_area_vs_RT.png",
    "fig14": "fig14_thickness_vs_RT.png",
    "fig15": "fig15_area_vs_z2.png",
    "sec4": "sec4_example_ellipse.png",
}
CATT_LIB = lib("replications.catt", "surfaces.catt", "surface", "checks", "published", "solve", "tca",
               "curvature", "ellipse", "units")


rule catt_run:
    input:
        io=REPLICATION_IO,
        code=CATT_LIB,
        params=published_files("params_004_*.csv"),
    output:
        **{name: f"{CATT_DIR}/{name}.csv" for name in CATT_TABLES},
    params:
        catt=config.get("catt", {}),  # a changed setting reruns the study (params are tracked)
    log:
        "results/logs/catt_run.log",
    benchmark:
        "results/benchmarks/catt_run.tsv"
    conda:
        "../envs/gearrep.yaml"
    script:
        "../scripts/catt_run.py"


rule catt_figures:
    input:
        cycle=f"{CATT_DIR}/cycle.csv",
        settings=f"{CATT_DIR}/settings.csv",
        thickness=f"{CATT_DIR}/thickness.csv",
        code=lib("plotting"),
    output:
        **{k: figure(f"{CATT_DIR}/figures/{v}", "catt") for k, v in CATT_FIGURES.items()},
    log:
        "results/logs/catt_figures.log",
    conda:
        "../envs/gearrep.yaml"
    script:
        "../scripts/catt_figures.py"


rule catt_checks:
    input:
        io=REPLICATION_IO,
        tables=[f"{CATT_DIR}/{name}.csv" for name in CATT_TABLES],
        published=published_files("*_004_*.csv") + published_files("claims_004.csv"),
        code=CATT_LIB,
    output:
        checks="results/checks/catt.csv",
        readings=f"{CATT_DIR}/claim_readings.csv",
    log:
        "results/logs/catt_checks.log",
    benchmark:
        "results/benchmarks/catt_checks.tsv"
    conda:
        "../envs/gearrep.yaml"
    script:
        "../scripts/catt_checks.py"


rule catt_notebook:
    input:
        checks="results/checks/catt.csv",
        readings=f"{CATT_DIR}/claim_readings.csv",
        tables=[f"{CATT_DIR}/{name}.csv" for name in CATT_TABLES],
        figures=[f"{CATT_DIR}/figures/{v}" for v in CATT_FIGURES.values()],
        benchmark="results/benchmarks/catt_run.tsv",
        code=lib("plotting"),
    output:
        touch("results/notebooks/catt.executed"),
    log:
        notebook="results/notebooks/catt.ipynb",
    conda:
        "../envs/gearrep.yaml"
    notebook:
        "../../notebooks/catt.ipynb"


CHECK_FILES.append("results/checks/catt.csv")
FINAL_OUTPUTS.extend([f"{CATT_DIR}/{name}.csv" for name in CATT_TABLES])
FINAL_OUTPUTS.append(f"{CATT_DIR}/claim_readings.csv")
FINAL_OUTPUTS.extend([f"{CATT_DIR}/figures/{v}" for v in CATT_FIGURES.values()])
REPORT_FIGURES.extend([f"{CATT_DIR}/figures/{CATT_FIGURES['fig15']}", f"{CATT_DIR}/figures/{CATT_FIGURES['fig13']}"])
NOTEBOOKS.append("catt")
