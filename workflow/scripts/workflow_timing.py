"""Where the time of a workflow run goes, job by job (Snakemake script of `results/bench/workflow_jobs.csv`).

Reads the timing file of every job: the replication and check jobs write their own
(replication_io.write_timing: wall seconds ``s`` and ``cpu_time`` of the process, peak ``max_rss``
in MB, and ``compute_s``, the computation alone); the figure, notebook, render, scorecard and
report jobs have Snakemake benchmark files (the same columns, without ``compute_s``). The
difference between a job's wall time and its compute time is what the job pays to exist: the
interpreter, the imports, reading its inputs and writing its tables. Rows are sorted by CPU time;
the last row sums them.
"""

from pathlib import Path

import pandas as pd

smk = snakemake  # noqa: F821  (provided by Snakemake)

rows = []
for tsv in map(Path, smk.input.benchmarks):
    b = pd.read_csv(tsv, sep="\t").iloc[-1]
    rel = tsv.relative_to("results/benchmarks").with_suffix("")
    study, step = (rel.parts[0], rel.parts[1]) if len(rel.parts) == 2 else ("", rel.parts[0])
    compute = float(b["compute_s"]) if "compute_s" in b.index else float("nan")
    rows.append(
        {
            "study": study,
            "step": step,
            "wall_s": float(b["s"]),
            "cpu_s": float(b["cpu_time"]),
            "compute_s": compute,
            "max_rss_MB": float(b["max_rss"]),
        }
    )

table = pd.DataFrame(rows).sort_values("cpu_s", ascending=False, ignore_index=True)
table["overhead_s"] = table["wall_s"] - table["compute_s"]
total = {
    "study": "all",
    "step": f"{len(table)} jobs",
    **table[["wall_s", "cpu_s", "compute_s", "overhead_s"]].sum().to_dict(),
    "max_rss_MB": table["max_rss_MB"].max(),
}
table = pd.concat([table, pd.DataFrame([total])], ignore_index=True)
Path(smk.output[0]).parent.mkdir(parents=True, exist_ok=True)
table.to_csv(smk.output[0], index=False, float_format="%.3f")
Path(smk.log[0]).write_text(
    f"{len(table) - 1} jobs: {total['cpu_s']:.1f} s CPU, {total['compute_s']:.1f} s compute in the replication jobs\n"
)
