# Seed 000 ch. 4 (curvilinear-tooth gear cut by a ZA hob): principal-curvature Tables 4.2-4.5 and the
# chapter's claims (gearrep.replications.tseng_curvature, model in gearrep.surfaces.hob).
# The four curvature tables are an interface (issue 7): results/tseng/curvature_table_4_{2,3,4,5}.csv.
TSENG_IFACE_DIR = "results/tseng"
TC_DIR = "results/tseng_curvature"
TC_IFACE = ["curvature_table_4_2", "curvature_table_4_3", "curvature_table_4_4", "curvature_table_4_5"]
TC_TABLES = ["curvature_detail", "conventions", "run_info"]
TC_EXTRAS = ["assignment", "variants", "face", "rc_sweep", "undercut", "ellipses", "extras_run_info"]
TC_FIGURES = {
    "tables": "curvature_tables_4_2_to_4_5.png",
    "face": "curvature_across_face.png",
    "rc": "curvature_vs_Rc.png",
}
TC_LIB = lib("replications.tseng_curvature", "surfaces.hob", "checks", "published", "solve", "curvature",
             "curvature_relations", "envelope", "ellipse")


rule tseng_curvature_tables:
    input:
        io=REPLICATION_IO,
        code=TC_LIB,
        params=published_files("params_000_*.csv"),
    output:
        **{name: f"{TSENG_IFACE_DIR}/{name}.csv" for name in TC_IFACE},
        **{name: f"{TC_DIR}/{name}.csv" for name in TC_TABLES},
    log:
        "results/logs/tseng_curvature_tables.log",
    benchmark:
        "results/benchmarks/tseng_curvature_tables.tsv"
    params:
        parts=["tables"],
        settings=config.get("tseng_curvature", {}),  # a changed setting reruns the job (params are tracked)
    conda:
        "../envs/gearrep.yaml"
    script:
        "../scripts/tseng_curvature_run.py"


rule tseng_curvature_extras:
    input:
        io=REPLICATION_IO,
        code=TC_LIB,
        params=published_files("params_000_*.csv"),
    output:
        **{name: f"{TC_DIR}/{name}.csv" for name in TC_EXTRAS},
    log:
        "results/logs/tseng_curvature_extras.log",
    benchmark:
        "results/benchmarks/tseng_curvature_extras.tsv"
    params:
        parts=["extras"],
        settings=config.get("tseng_curvature", {}),
    conda:
        "../envs/gearrep.yaml"
    script:
        "../scripts/tseng_curvature_run.py"


rule tseng_curvature_figures:
    input:
        tables=[f"{TSENG_IFACE_DIR}/{name}.csv" for name in TC_IFACE],
        face=f"{TC_DIR}/face.csv",
        rc_sweep=f"{TC_DIR}/rc_sweep.csv",
        published=published_files("values_000_T4.*.csv"),
        code=lib("plotting"),
    output:
        **{k: figure(f"{TC_DIR}/figures/{v}", "tseng_curvature") for k, v in TC_FIGURES.items()},
    log:
        "results/logs/tseng_curvature_figures.log",
    conda:
        "../envs/gearrep.yaml"
    script:
        "../scripts/tseng_curvature_figures.py"


rule tseng_curvature_checks:
    input:
        io=REPLICATION_IO,
        tables=[f"{TSENG_IFACE_DIR}/{name}.csv" for name in TC_IFACE]
        + [f"{TC_DIR}/{name}.csv" for name in TC_TABLES + TC_EXTRAS],
        published=published_files("*_000_*.csv") + published_files("claims_000.csv"),
        code=TC_LIB,
    output:
        "results/checks/tseng_curvature.csv",
    log:
        "results/logs/tseng_curvature_checks.log",
    conda:
        "../envs/gearrep.yaml"
    script:
        "../scripts/tseng_curvature_checks.py"


rule tseng_curvature_notebook:
    input:
        checks="results/checks/tseng_curvature.csv",
        tables=[f"{TSENG_IFACE_DIR}/{name}.csv" for name in TC_IFACE],
        detail=f"{TC_DIR}/curvature_detail.csv",
        conventions=f"{TC_DIR}/conventions.csv",
        run_info=f"{TC_DIR}/run_info.csv",
        extras=[f"{TC_DIR}/{name}.csv" for name in TC_EXTRAS],
        figures=[f"{TC_DIR}/figures/{v}" for v in TC_FIGURES.values()],
        benchmarks=["results/benchmarks/tseng_curvature_tables.tsv", "results/benchmarks/tseng_curvature_extras.tsv"],
    output:
        touch("results/notebooks/tseng_curvature.executed"),
    log:
        notebook="results/notebooks/tseng_curvature.ipynb",
    conda:
        "../envs/gearrep.yaml"
    notebook:
        "../../notebooks/tseng_curvature.ipynb"


CHECK_FILES.append("results/checks/tseng_curvature.csv")
FINAL_OUTPUTS.extend([f"{TSENG_IFACE_DIR}/{name}.csv" for name in TC_IFACE])
FINAL_OUTPUTS.extend([f"{TC_DIR}/{name}.csv" for name in TC_TABLES + TC_EXTRAS])
FINAL_OUTPUTS.extend([f"{TC_DIR}/figures/{v}" for v in TC_FIGURES.values()])
REPORT_FIGURES.extend([f"{TC_DIR}/figures/{TC_FIGURES['tables']}", f"{TC_DIR}/figures/{TC_FIGURES['rc']}"])
NOTEBOOKS.append("tseng_curvature")
