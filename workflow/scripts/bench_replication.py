"""Run time against error for one replication (Snakemake script of the `bench` target).

The study's package defines ``bench_cases(settings, design) -> dict[case, dict]``, each case with
``run`` (setting -> result), ``settings`` (list of knob dicts), ``reference`` (the most accurate
setting, computed in the same run), ``error`` ((result, reference_result) -> float, in
``error_unit``), ``error_unit`` and optionally ``error_target`` (e.g. a tenth of the tightest
published tolerance; the default is then the fastest setting meeting it) and ``current`` (the
setting in config/config.yaml) and ``items`` (what one run computes, e.g. mesh positions: the
sweep then reports the time per item too). Writes the sweep table, one figure and the chosen
defaults.
"""

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402

from gearrep import benchmark, plotting, published  # noqa: E402
from gearrep.replications import load  # noqa: E402

smk = snakemake  # noqa: F821  (provided by Snakemake)
name = smk.wildcards.name
mod = load(name)
cases = mod.bench_cases(
    dict(smk.params.settings),
    mod.params_from_published(published.load(Path(smk.input.design[0]).parent, smk.input.design)),
)
repeats = int(smk.params.repeats)

frames, chosen = [], []
for case, c in cases.items():
    sw = benchmark.sweep(c["run"], c["settings"], c["reference"], c["error"], repeats=repeats)
    knobs = list(c["settings"][0])
    target = c.get("error_target")
    k = benchmark.knee(sw["time_s"].to_numpy(), sw["error"].to_numpy(), error_target=target)
    sw["knee"] = np.arange(len(sw)) == k
    sw.insert(0, "case", case)
    sw["error_unit"] = c["error_unit"]
    if "items" in c:
        sw["items"] = int(c["items"])
        sw["time_per_item_s"] = sw["time_s"] / int(c["items"])
    frames.append(sw)
    row = sw.iloc[k]
    chosen.append(
        {
            "replication": name,
            "case": case,
            "setting": "; ".join(f"{kn}={row[kn]}" for kn in knobs),
            "time_s": row["time_s"],
            "error": row["error"],
            "error_unit": c["error_unit"],
            "error_target": target,
            "current": "; ".join(f"{kn}={v}" for kn, v in c.get("current", {}).items()),
            "rule": "fastest meeting the target"
            if target is not None and row["error"] <= target
            else "knee of the Pareto front",
        }
    )
table = pd.concat(frames, ignore_index=True)
Path(smk.output.sweep).parent.mkdir(parents=True, exist_ok=True)
table.to_csv(smk.output.sweep, index=False)
pd.DataFrame(chosen).to_csv(smk.output.defaults, index=False)

plotting.use_style()
fig, axes = plt.subplots(1, len(cases), figsize=(5.5 * len(cases), 4), squeeze=False)
for ax, (case, g) in zip(axes[0], table.groupby("case", sort=False)):
    err = np.maximum(g["error"].to_numpy(float), 1e-17)
    ax.loglog(g["time_s"], err, "o", color="0.6", label="settings")
    front = g[g["pareto"]].sort_values("time_s")
    ax.loglog(front["time_s"], np.maximum(front["error"], 1e-17), "-", label="Pareto front")
    k = g[g["knee"]]
    ax.loglog(k["time_s"], np.maximum(k["error"], 1e-17), "k*", ms=13, label="chosen default")
    plotting.label_axes(ax, "run time [s]", f"error [{g['error_unit'].iloc[0]}]", title=case)
    ax.legend(fontsize=7)
fig.savefig(smk.output.figure, dpi=120, bbox_inches="tight")
Path(smk.log[0]).write_text(f"{name}: {len(table)} settings over {len(cases)} cases\n")
