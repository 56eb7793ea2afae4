# Run time against error and throughput (issue 10): `snakemake --cores 2 bench`.
# Not part of the default target; timings are medians of repeated runs with the machine load
# recorded. A replication joins by defining `bench_cases(params)` in its module and being listed
# in config `bench: replications`.

BENCH_DIR = "results/bench"


rule bench_core:
    input:
        published_dir=config["published_dir"],
        code=lib("benchmark", "plotting", "published", "solve", "tca", "surfaces.involute", "surface", "units"),
    output:
        throughput=f"{BENCH_DIR}/throughput.csv",
        sweep=f"{BENCH_DIR}/core_tca.csv",
        figure=figure(f"{BENCH_DIR}/figures/core_tca_time_vs_error.png", "bench"),
    params:
        n_vectorised=config["bench"]["n_vectorised"],
        n_single=config["bench"]["n_single"],
        repeats=config["bench"]["repeats"],
    log:
        "results/logs/bench_core.log",
    conda:
        "../envs/gearrep.yaml"
    script:
        "../scripts/bench_core.py"


rule bench:
    input:
        rules.bench_core.output,
        f"{BENCH_DIR}/defaults.csv",


rule bench_replication:
    input:
        code=lambda wc: lib("benchmark", "plotting", f"replications.{wc.name}"),
    output:
        sweep=f"{BENCH_DIR}/{{name}}.csv",
        defaults=f"{BENCH_DIR}/{{name}}_defaults.csv",
        figure=figure(f"{BENCH_DIR}/figures/{{name}}_time_vs_error.png", "bench"),
    wildcard_constraints:
        name="|".join(config["bench"]["replications"]) or "no-replication",
    log:
        "results/logs/bench_{name}.log",
    conda:
        "../envs/gearrep.yaml"
    script:
        "../scripts/bench_replication.py"


rule bench_defaults:
    input:
        expand(f"{BENCH_DIR}/{{name}}_defaults.csv", name=config["bench"]["replications"]),
    output:
        f"{BENCH_DIR}/defaults.csv",
    log:
        "results/logs/bench_defaults.log",
    run:
        import pandas as pd

        frames = [pd.read_csv(f) for f in input]
        (pd.concat(frames, ignore_index=True) if frames else pd.DataFrame(
            columns=["replication", "case", "setting", "time_s", "error", "error_unit", "error_target", "current",
                     "rule"])).to_csv(output[0], index=False)
