"""Seed 004 (CATT gears): figures like the paper's Figs 12-15 from results/ma2021/ (Snakemake script:
input.tables = every table of the study, output.<key> for each key of ma2021.FIGURES).

The paper prints no numbers for Figs 12-15 (only curves), so there are no published markers:
computed S = pi a b (eq 27) as solid lines, the ellipse truncated by the flank edges as dashed
lines, the paper's phi1 window -14.5..14.5 deg shaded."""

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
inp, out = smk.input, smk.output
TABLES = {Path(f).stem: f for f in inp.tables}
cyc = pd.read_csv(TABLES["cycle"])
st = pd.read_csv(TABLES["settings"]).iloc[0]
WLO, WHI = float(st["window_lo_deg"]), float(st["window_hi_deg"])
PAIR = str(st["primary_pair"])
XLAB = {"R1": "phi1 = pinion angle, root -> top [deg]", "R2": "phi1 read as gear angle, root -> top [deg]"}


def curve(design, reading, pair=PAIR):
    c = cyc[(cyc["design"] == design) & (cyc["reading"] == reading) & (cyc["pair"] == pair)]
    return c.sort_values("phi_paper_deg")


def panel(ax, sel, col, fmt, reading, title, unit=""):
    ax.axvspan(WLO, WHI, color="0.93", zorder=0)
    for i, (val, design) in enumerate(sel):
        c = curve(design, reading)
        color = f"C{i}"
        plotting.computed(ax, c["phi_paper_deg"], c["S_mm2"], f"{col}={val:{fmt}}{unit}", color=color)
        sc = np.where(c["on_path"], c["S_clipped_mm2"], 0.0)
        ax.plot(c["phi_paper_deg"], sc, "--", color=color, lw=1.0)
    plotting.label_axes(ax, XLAB[reading], "contact-ellipse area S [mm2]", title)
    plotting.finish(ax, loc="lower center")


def designs(group, col, **fixed):
    d = cyc[cyc["group"] == group].drop_duplicates("design")
    for k, v in fixed.items():
        d = d[d[k] == v]
    return [(v, n) for v, n in sorted(zip(d[col], d["design"]))]


note = f"pair {PAIR}; solid: pi a b (eq 27), dashed: truncated by tip edges/face ends; grey: paper window"
fig, axes = plt.subplots(1, 2, figsize=(12, 4.4))
for ax, rd in zip(axes, ("R1", "R2")):
    panel(ax, designs("fig12", "module_mm"), "m", "g", rd, f"Fig 12 (z1=21, z2=29, R_T=500): {rd}", " mm")
fig.suptitle(note, fontsize=9)
save_figure(fig, out.fig12)

fig, axes = plt.subplots(1, 2, figsize=(12, 4.4))
for ax, z2 in zip(axes, (29, 89)):
    panel(ax, designs("fig13", "R_T_mm", z2=z2), "R_T", "g", "R1", f"Fig 13 (z1=21, z2={z2}, m=8): R1", " mm")
fig.suptitle(note, fontsize=9)
save_figure(fig, out.fig13)

fig, axes = plt.subplots(1, 2, figsize=(12, 4.4))
for ax, rd in zip(axes, ("R1", "R2")):
    panel(ax, designs("fig15", "z2"), "z2", "g", rd, f"Fig 15 (z1=21, m=8, R_T=500): {rd}")
fig.suptitle(note, fontsize=9)
save_figure(fig, out.fig15)

th = pd.read_csv(TABLES["thickness"])
fig, ax = plt.subplots()
for sec, g in th.groupby("section_mm"):
    g = g.sort_values("R_T_mm")
    plotting.computed(ax, g["R_T_mm"], g["thickness_mm"], f"B{sec:g}")
plotting.label_axes(
    ax,
    "tooth-line radius R_T [mm]",
    "pitch-circle tooth thickness [mm]",
    f"Fig 14: thickness vs R_T (z={int(th['z'].iloc[0])}, m={th['module_mm'].iloc[0]:g})",
)
plotting.finish(ax)
save_figure(fig, out.fig14)

fig, axes = plt.subplots(2, 2, figsize=(12, 7.5), constrained_layout=True)
for ax in axes.flat:
    ax.axvspan(WLO, WHI, color="0.93", zorder=0)
for pair, ls in (("A", "-"), ("B", "--")):
    c = curve("sec4_3d_model", "R1", pair)
    c = c[c["on_path"]]
    axes[0, 0].plot(c["phi_paper_deg"], c["S_mm2"], ls, label=f"pair {pair}")
    axes[0, 1].plot(c["phi_paper_deg"], 2 * c["a_mm"], ls, label=f"2a, pair {pair}")
    axes[1, 0].plot(c["phi_paper_deg"], 2 * c["b_mm"], ls, label=f"2b, pair {pair}")
    axes[1, 1].semilogy(c["phi_paper_deg"], np.abs(c["S_rel_diff_closed_form"]) + 1e-17, ls, label=f"pair {pair}")
plotting.label_axes(axes[0, 0], XLAB["R1"], "S = pi a b [mm2]", "sec 4 pair (z1=19, z2=31, m=8, R_T=500)")
plotting.label_axes(axes[0, 1], XLAB["R1"], "major axis 2a [mm]")
plotting.label_axes(axes[1, 0], XLAB["R1"], "minor axis 2b [mm]")
plotting.label_axes(axes[1, 1], XLAB["R1"], "|S_pipeline / S_closed_form - 1| [-]", "TCA pipeline vs closed form")
for ax in axes.flat:
    plotting.finish(ax)
save_figure(fig, out.sec4)
