# Seed 002 (NASA CR-2000-209415): Novikov-Wildhaber helical gears from parabolic rack-cutters:
# curvatures at Q, contact ellipses (Table 6.2.4), sensitivity to dE (Table 6.2.3), TCA and TE
# under misalignment (sec. 2.8, 5.5) (gearrep.replications.nasa, surfaces in gearrep.surfaces.novikov).
NASA_DIR = "results/nasa"
NASA_TABLES = ["curvatures", "ellipse", "path_curvatures", "concavity", "te_single", "te_cycle", "te_summary",
               "sensitivity", "shifts", "rho_sweep", "parabola_relations", "worm_single", "worm_cycle", "worm_summary",
               "transverse_section", "concave_pinion", "run_info"]
NASA_FIGURES = {
    "te": "te_functions.png",
    "ellipses": "contact_ellipses.png",
    "sensitivity": "sensitivity_dE.png",
    "paths": "contact_paths.png",
    "worm": "te_worm.png",
}
NASA_LIB = lib("replications.nasa", "surfaces.novikov", "surfaces.rack", "surface", "envelope",
               "curvature", "curvature_relations", "ellipse", "tca", "solve", "checks", "published", "units")


rule nasa_run:
    input:
        io=REPLICATION_IO,
        code=NASA_LIB,
        params=published_files("params_002_*.csv") + published_files("values_002_T6.2.*.csv"),
    output:
        **{name: f"{NASA_DIR}/{name}.csv" for name in NASA_TABLES},
    params:
        settings=config.get("nasa", {}),  # a changed setting reruns the job (params are tracked)
    log:
        "results/logs/nasa_run.log",
    benchmark:
        "results/benchmarks/nasa_run.tsv"
    conda:
        "../envs/gearrep.yaml"
    script:
        "../scripts/nasa_run.py"


rule nasa_figures:
    input:
        te_cycle=f"{NASA_DIR}/te_cycle.csv",
        te_single=f"{NASA_DIR}/te_single.csv",
        te_summary=f"{NASA_DIR}/te_summary.csv",
        worm_cycle=f"{NASA_DIR}/worm_cycle.csv",
        worm_summary=f"{NASA_DIR}/worm_summary.csv",
        ellipse=f"{NASA_DIR}/ellipse.csv",
        sensitivity=f"{NASA_DIR}/sensitivity.csv",
        published=published_files("values_002_*.csv"),
        code=lib("plotting"),
    output:
        **{k: figure(f"{NASA_DIR}/figures/{v}", "nasa") for k, v in NASA_FIGURES.items()},
    log:
        "results/logs/nasa_figures.log",
    conda:
        "../envs/gearrep.yaml"
    script:
        "../scripts/nasa_figures.py"


rule nasa_checks:
    input:
        io=REPLICATION_IO,
        tables=[f"{NASA_DIR}/{name}.csv" for name in NASA_TABLES],
        published=published_files("*_002_*.csv") + published_files("claims_002.csv"),
        code=NASA_LIB,
    output:
        "results/checks/nasa.csv",
    log:
        "results/logs/nasa_checks.log",
    conda:
        "../envs/gearrep.yaml"
    script:
        "../scripts/nasa_checks.py"


rule nasa_notebook:
    input:
        checks="results/checks/nasa.csv",
        tables=[f"{NASA_DIR}/{name}.csv" for name in NASA_TABLES],
        figures=[f"{NASA_DIR}/figures/{v}" for v in NASA_FIGURES.values()],
        benchmark="results/benchmarks/nasa_run.tsv",
    output:
        touch("results/notebooks/nasa.executed"),
    log:
        notebook="results/notebooks/nasa.ipynb",
    conda:
        "../envs/gearrep.yaml"
    notebook:
        "../../notebooks/nasa.ipynb"


CHECK_FILES.append("results/checks/nasa.csv")
FINAL_OUTPUTS.extend([f"{NASA_DIR}/{name}.csv" for name in NASA_TABLES])
FINAL_OUTPUTS.extend([f"{NASA_DIR}/figures/{v}" for v in NASA_FIGURES.values()])
REPORT_FIGURES.extend([f"{NASA_DIR}/figures/{NASA_FIGURES['te']}", f"{NASA_DIR}/figures/{NASA_FIGURES['ellipses']}"])
NOTEBOOKS.append("nasa")
