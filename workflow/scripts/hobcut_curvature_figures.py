"""Seed 000 ch. 4: figures of the curvature tables (computed lines, printed Tables 4.3/4.4 as
markers), curvature across the face and against R_c (Snakemake script of the generic figures
rule). Inputs: ``tables`` (every table of the study), ``published`` (the study's CHECK_DATA
files); one output per key of hobcut_curvature.FIGURES."""

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402
from replication_io import save_figure  # noqa: E402

from gearrep import plotting  # noqa: E402

smk = snakemake  # noqa: F821  (provided by Snakemake)
plotting.use_style()
tables = {Path(f).stem: f for f in smk.input.tables}
tabs = {
    name.replace("curvature_table_", "").replace("_", "."): pd.read_csv(f)
    for name, f in tables.items()
    if name.startswith("curvature_table_")
}
pub = pd.concat(
    [pd.read_csv(f, dtype={"seed": str}) for f in smk.input.published if Path(f).name.startswith("values_")],
    ignore_index=True,
)
pub["l1_mm"] = pub["row"].str.split("=").str[1].astype(float)
NAMES = {
    "4.2": "Sigma_2L, R_c=110",
    "4.3": "Sigma_2R, R_c=110",
    "4.4": "Sigma_2L, R_c=5000",
    "4.5": "Sigma_2R, R_c=5000",
}


def printed(tab, q):
    p = pub[(pub["source"] == f"Table {tab}") & (pub["quantity"] == q)].sort_values("l1_mm")
    return p["l1_mm"], p["value"]


fig, axes = plt.subplots(1, 3, figsize=(15, 4.2))
ax = axes[0]
for tab, t in tabs.items():
    plotting.computed(ax, t["l1_mm"], t["k_q_per_mm"], f"Table {tab} ({NAMES[tab]})")
for tab in ("4.3", "4.4"):
    plotting.published(ax, *printed(tab, "k_q"), f"Table {tab}")
plotting.label_axes(ax, "l_1 [mm]", "k_q [1/mm]", "profile curvature k_q (mid-face)")
plotting.finish(ax)
for ax, (a, b, pt) in zip(axes[1:], (("4.2", "4.3", "4.3"), ("4.4", "4.5", "4.4"))):
    for tab in (a, b):
        plotting.computed(ax, tabs[tab]["l1_mm"], tabs[tab]["k_s_per_mm"], f"Table {tab} ({NAMES[tab]})")
    plotting.published(ax, *printed(pt, "k_s"), f"Table {pt}")
    plotting.label_axes(ax, "l_1 [mm]", "k_s [1/mm]", f"trace curvature k_s, {NAMES[a].split(', ')[1]} mm")
    plotting.finish(ax)
save_figure(fig, smk.output.tables)

face = pd.read_csv(tables["face"])
fig, axes = plt.subplots(2, 2, figsize=(12, 7.5))
for i, fl in enumerate(("Sigma_2R", "Sigma_2L")):
    f = face[face["flank"] == fl]
    for l1, g in f.groupby("l1_mm"):
        g = g.sort_values("Z_f_mm")
        bad = g["beyond_limit_line"].astype(bool)
        if bad.any():  # points beyond the limiting (singular) line: marked, not joined
            axes[i, 0].plot(g.loc[bad, "Z_f_mm"], g.loc[bad, "k_s_per_mm"], "x", color="0.5")
            axes[i, 1].plot(g.loc[bad, "Z_f_mm"], g.loc[bad, "k_q_per_mm"], "x", color="0.5")
            g = g.assign(k_s_per_mm=g["k_s_per_mm"].where(~bad), k_q_per_mm=g["k_q_per_mm"].where(~bad))
        plotting.computed(axes[i, 0], g["Z_f_mm"], g["k_s_per_mm"], f"l_1 = {l1:.3f}")
        plotting.computed(axes[i, 1], g["Z_f_mm"], g["k_q_per_mm"], f"l_1 = {l1:.3f}")
    Rc = f["R_c_mm"].iloc[0]
    plotting.label_axes(axes[i, 0], "Z_f [mm]", "k_s [1/mm]", f"{fl}, R_c = {Rc:g} mm: k_s across the face")
    plotting.label_axes(axes[i, 1], "Z_f [mm]", "k_q [1/mm]", f"{fl}, R_c = {Rc:g} mm: k_q across the face")
    axes[i, 1].set_yscale("symlog", linthresh=0.05)
    plotting.finish(axes[i, 0], loc="upper right")
    plotting.finish(axes[i, 1], loc="upper right")
fig.suptitle("x = beyond the envelope's limiting line (undercut region, not joined)", fontsize=9)
fig.tight_layout()
save_figure(fig, smk.output.face)

rc = pd.read_csv(tables["rc_sweep"])
spur = rc[~np.isfinite(rc["R_c_mm"])]
rc = rc[np.isfinite(rc["R_c_mm"])]
fig, axes = plt.subplots(1, 2, figsize=(12, 4.2))
for (fl, row), g in rc.groupby(["flank", "row"], sort=False):
    g = g.sort_values("R_c_mm")
    plotting.computed(axes[0], g["R_c_mm"], g["R_c_times_k_s"], f"{fl}, {row}")
    plotting.computed(axes[1], g["R_c_mm"], g["k_q_per_mm"], f"{fl}, {row}")
axes[0].set_xscale("log")
axes[1].set_xscale("log")
axes[1].set_yscale("symlog", linthresh=0.05)
plotting.label_axes(axes[0], "R_c [mm]", "R_c * k_s [-]", "trace curvature times R_c (spur limit: k_s -> 0)")
for _, r in spur.iterrows():  # the spur gear (R_c = inf) cut by the same hob, at the right edge
    axes[1].plot(rc["R_c_mm"].max() * 1.6, r["k_q_per_mm"], ">", color="0.3")
plotting.label_axes(axes[1], "R_c [mm]", "k_q [1/mm]", "profile curvature (independent of R_c; > = spur gear)")
plotting.finish(axes[0], loc="lower right")
plotting.finish(axes[1], loc="center right")
fig.tight_layout()
save_figure(fig, smk.output.rc)
Path(smk.log[0]).write_text("figures: " + ", ".join(str(f) for f in smk.output) + "\n")
