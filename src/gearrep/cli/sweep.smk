# The sweep workflow of `gearrep sweep` (run in the sweep's output directory; config: spec=<DIR>/sweep.json).
# Rules are thin: I/O only; the computation is gearrep.cli.sweep.run_shard / aggregate.
import json

from gearrep.cli import sweep as _sweep

SPEC = json.loads(open(config["spec"]).read())
RES = SPEC["resources"]


localrules:
    all,
    aggregate,


rule all:
    input:
        "sweep.csv",


rule shard:
    input:
        config["spec"],
    output:
        csv="shards/shard_{i}.csv",
        prov="shards/shard_{i}.csv.prov.json",
    log:
        "logs/shard_{i}.log",
    threads: RES["threads"]
    resources:
        mem_mb=RES["mem_mb"],
        runtime=RES["runtime_min"],
    run:
        _sweep.run_shard(input[0], int(wildcards.i), output.csv, log[0])


rule aggregate:
    input:
        spec=config["spec"],
        shards=expand("shards/shard_{i}.csv", i=range(SPEC["n_shards"])),
    output:
        csv="sweep.csv",
        prov="sweep.csv.prov.json",
    run:
        _sweep.aggregate(input.spec, input.shards, output.csv)
