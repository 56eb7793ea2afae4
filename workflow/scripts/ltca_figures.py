"""Validation of the loaded contact analysis: figures from results/ltca/ (Snakemake script:
input.tables = every table of the study, output.<key> for each key of ltca.FIGURES).

No paper prints these: ISO 6336's closed forms are drawn as the reference (open markers and the
band of the checks), the loaded analysis as lines."""

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
out = smk.output
T = {Path(f).stem: pd.read_csv(f) for f in smk.input.tables}

# loaded TE and load sharing over three cycles
cyc = T["cycle"]
fig, axes = plt.subplots(1, 2, figsize=(12, 4.4))
ax = axes[0]
for i, (case, g) in enumerate(cyc.groupby("case", sort=False)):
    p = g.drop_duplicates("phi1_rad").sort_values("phi1_rad")
    deg = np.degrees(p["phi1_rad"])
    plotting.computed(ax, deg, p["lte_um"], f"{case}: loaded TE", color=f"C{i}")
    ax.plot(deg, p["te_unloaded_um"], "--", color=f"C{i}", lw=1.0, label=f"{case}: unloaded TE")
plotting.label_axes(ax, "phi1 [deg]", "TE along the line of action r_b2 TE [um]", "loaded and unloaded TE, 50 N m")
plotting.finish(ax, loc="lower right")
ax = axes[1]
g = cyc[cyc["case"] == "readme_pair"]
for k, gk in g.groupby("pair"):
    gk = gk.sort_values("phi1_rad")
    if np.nanmax(gk["pair_load_N"]) <= 0:
        continue
    share = np.where(gk["pair_load_N"] > 0, gk["pair_load_N"] / gk["normal_load_N"], np.nan)
    ax.plot(np.degrees(gk["phi1_rad"]), share, ".-", ms=3, label=f"tooth pair {k}")
tip = g.drop_duplicates("phi1_rad").sort_values("phi1_rad")
ax.plot(np.degrees(tip["phi1_rad"]), tip["tip_edge_load_N"] / tip["normal_load_N"], "k:", label="at tip edges")
plotting.label_axes(ax, "phi1 [deg]", "share of the normal load [-]", "load sharing (README pair)")
plotting.finish(ax, loc="upper right")
save_figure(fig, out.cycle)

# pressure map of the position of largest pressure
pm = T["pressure_map"]
fig, ax = plt.subplots(figsize=(8, 4.2))
sc = None
for _k, gk in pm.groupby("pair"):
    v = gk[gk["pressure_MPa"] > 0]
    if len(v):
        y = v["radius1_mm"] + v["across_mm"]
        sc = ax.scatter(v["z_mm"], y, c=v["pressure_MPa"], s=6, cmap="viridis", marker="s")
if sc is not None:
    fig.colorbar(sc, ax=ax, label="Hertz pressure [MPa]")
phi = float(pm["phi1_rad"].iloc[0]) if len(pm) else float("nan")
plotting.label_axes(
    ax,
    "axial position z [mm]",
    "pinion radius + offset across the line [mm]",
    f"pressure on the flank at phi1 = {np.degrees(phi):.3f} deg (README pair; across offsets stretched)",
)
save_figure(fig, out.pressure)

# stiffness against ISO 6336-1
st = T["iso_stiffness"]
fig, axes = plt.subplots(1, 2, figsize=(12, 4.2))
x = np.arange(len(st))
for ax, (col, ref, title) in zip(
    axes,
    (
        ("c_single_N_per_mm_um", "c_ref_iso_N_per_mm_um", "single-pair stiffness c'"),
        ("c_gamma_N_per_mm_um", "c_gamma_alpha_iso_N_per_mm_um", "mean mesh stiffness c_gamma"),
    ),
):
    ax.fill_between(x, 0.8 * st[ref], st[ref], color="0.9", label="band [C_M, 1] x ISO")
    plotting.published(ax, x, st[ref], "ISO 6336-1", label="ISO theoretical (c'_th C_B)")
    plotting.computed(ax, x, st[col], "gearrep.ltca")
    ax.set_xticks(x, st["design"], rotation=12, fontsize=8)
    plotting.label_axes(ax, "design [-]", f"{title} [N/(mm um)]", title)
    plotting.finish(ax, loc="lower right")
save_figure(fig, out.stiffness)

# grid convergence
cv = T["convergence"].sort_values("n_nodes")
fig, ax = plt.subplots(figsize=(6.5, 4.2))
for q, lab in (
    ("max_pressure_MPa", "largest flank pressure"),
    ("lte_peak_to_peak_urad", "loaded TE peak to peak"),
    ("mesh_stiffness_mean_N_per_mm_um", "mean mesh stiffness"),
):
    ref = float(cv[q].iloc[-1])
    ax.semilogy(cv["n_nodes"].iloc[:-1], np.abs(cv[q].iloc[:-1] / ref - 1.0) + 1e-17, "o-", label=lab)
ax.axhline(0.01, color="k", lw=0.8, ls="--", label="1 % (the checks' bound)")
plotting.label_axes(ax, "nodes along the face [-]", "change against the finest grid [-]", "grid convergence")
plotting.finish(ax)
save_figure(fig, out.convergence)
