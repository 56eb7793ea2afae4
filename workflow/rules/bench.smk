# Run time against error and throughput: `snakemake --cores 2 bench`.
# Not part of the default target; timings are medians of repeated runs with the machine load
# recorded. A study joins by defining `bench_cases(settings, design)` in its package and being
# listed in config `bench: replications`.

BENCH_DIR = "results/bench"


rule bench_core:
    input:
        published_dir=PUBLISHED_DIR,
        code=script_lib("workflow/scripts/bench_core.py"),
    output:
        throughput=f"{BENCH_DIR}/throughput.csv",
        sweep=f"{BENCH_DIR}/core_tca.csv",
        figure=figure(f"{BENCH_DIR}/figures/core_tca_time_vs_error.png", "bench"),
    log:
        "results/logs/bench_core.log",
    params:
        n_vectorised=RESOLVED["bench"]["n_vectorised"],
        n_single=RESOLVED["bench"]["n_single"],
        repeats=RESOLVED["bench"]["repeats"],
    script:
        "../scripts/bench_core.py"


# Start robustness: correct-root rate of gearrep.tca.robust_contact from starts uniform over
# the flank, per family, formulation and assembly.
rule bench_robustness:
    input:
        published_dir=PUBLISHED_DIR,
        code=script_lib("workflow/scripts/bench_robustness.py"),
    output:
        f"{BENCH_DIR}/robustness.csv",
    log:
        "results/logs/bench_robustness.log",
    params:
        n_per_angle=200,
    script:
        "../scripts/bench_robustness.py"


rule bench:
    input:
        rules.bench_core.output,
        rules.bench_robustness.output,
        f"{BENCH_DIR}/defaults.csv",


rule bench_replication:
    input:
        code=lambda wc: script_lib("workflow/scripts/bench_replication.py", f"replications.{wc.name}"),
        design=lambda wc: published_files(*load_study(wc.name).DESIGN_DATA),
    output:
        sweep=f"{BENCH_DIR}/{{name}}.csv",
        defaults=f"{BENCH_DIR}/{{name}}_defaults.csv",
        figure=figure(f"{BENCH_DIR}/figures/{{name}}_time_vs_error.png", "bench"),
    log:
        "results/logs/bench_{name}.log",
    wildcard_constraints:
        name="|".join(RESOLVED["bench"]["replications"]) or "no-replication",
    params:
        settings=lambda wc: SETTINGS[wc.name],
        repeats=RESOLVED["bench"]["repeats"],
    script:
        "../scripts/bench_replication.py"


rule bench_defaults:
    input:
        expand(f"{BENCH_DIR}/{{name}}_defaults.csv", name=RESOLVED["bench"]["replications"]),
    output:
        f"{BENCH_DIR}/defaults.csv",
    log:
        "results/logs/bench_defaults.log",
    run:
        import pandas as pd

        frames = [pd.read_csv(f) for f in input]
        (
            pd.concat(frames, ignore_index=True)
            if frames
            else pd.DataFrame(
                columns=[
                    "replication",
                    "case",
                    "setting",
                    "time_s",
                    "error",
                    "error_unit",
                    "error_target",
                    "current",
                    "rule",
                ]
            )
        ).to_csv(output[0], index=False)


# Where the time of the last run went, job by job (wall, CPU, compute and overhead seconds):
# `snakemake --cores 2 results/bench/workflow_jobs.csv` after (or as) a full run.
rule workflow_timing:
    input:
        benchmarks=BENCHMARKS + ["results/benchmarks/scorecard.tsv", "results/benchmarks/report.tsv"],
        code=script_lib("workflow/scripts/workflow_timing.py"),
    output:
        f"{BENCH_DIR}/workflow_jobs.csv",
    log:
        "results/logs/workflow_timing.log",
    script:
        "../scripts/workflow_timing.py"
