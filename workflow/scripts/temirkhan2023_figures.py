"""Seed 003 (thesis): figures from the tables in results/temirkhan2023/ (Snakemake script).

Convergence clouds coloured by outcome, convergence rate against the phi2 guess window and
against fixed phi2 guesses (published values as markers), TE curves and paths of contact."""

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402
from replication_io import save_figure  # noqa: E402

from gearrep import plotting, published  # noqa: E402

smk = snakemake  # noqa: F821  (provided by Snakemake)
plotting.use_style()
#: {table name: path} of every table of the study (workflow contract: input.tables lists them all)
TABLES = {Path(f).stem: f for f in smk.input.tables}
#: the published data directory, found from the CHECK_DATA files (input.published)
PUB = published.load(Path(smk.input.published[0]).parent).values.set_index("id")["value"].astype(float)
T10_CONV = "003-T10-case=spur_52_72;method=conventional-convergence_rate"
S61 = "003-S6.1-case=spur_25_25;method=conventional;phi2_guess_rad={g}-{q}"
COLORS = {
    "correct": "tab:blue",
    "wrong_root": "tab:orange",
    "not_converged": "tab:red",
    "singular": "tab:purple",
    "diverged": "0.6",
}


def cloud(ax, df, x, y, variant, title):
    o = df[f"outcome_{variant}"]
    for name, col in COLORS.items():
        m = o == name
        if m.any():
            ax.scatter(df.loc[m, x], df.loc[m, y], s=3, c=col, label=f"{name} ({100 * m.mean():.1f} %)", linewidths=0)
    ax.set_title(title)


# --- convergence clouds, Table 10 -------------------------------------------------------------
st = pd.read_csv(TABLES["starts_table10"])
fig, axes = plt.subplots(2, 3, figsize=(13, 7.5), sharex=True, sharey=True)
for ax, v in zip(axes.flat, ["plain", "damped", "domain", "seeded", "reduced", "reduced_robust"]):
    cloud(ax, st, "u1_0_mm", "v1_0_thesis_mm", v, f"{v}")
    ax.legend(loc="upper right", markerscale=3, fontsize=7, frameon=True, framealpha=0.9)
for ax in axes[-1]:
    ax.set_xlabel("start u1 [mm]")
for ax in axes[:, 0]:
    ax.set_ylabel("start v1 (thesis) [mm]")
fig.suptitle("Table 10 (spur 52/72): outcome of each start on the (u1, v1) plane")
save_figure(fig, smk.output.clouds)

fig, axes = plt.subplots(1, 3, figsize=(13, 4.2), sharey=True)
for ax, v in zip(axes, ["plain", "damped", "domain"]):
    cloud(ax, st, "phi2_0_thesis_rad", "u1_0_mm", v, f"conventional, {v}")
    ax.legend(loc="upper right", markerscale=3, fontsize=7, frameon=True, framealpha=0.9)
    ax.set_xlabel("start phi2 (thesis frame) [rad]")
axes[0].set_ylabel("start u1 [mm]")
fig.suptitle("Table 10: the outcome is decided by the phi2 start")
save_figure(fig, smk.output.clouds_phi2)

# --- convergence against the phi2 window -------------------------------------------------------
conv = pd.read_csv(TABLES["convergence"])
c = conv[conv["case"] == "spur_52_72"]
fig, ax = plt.subplots()
for v, mk in (("plain", "o"), ("damped", "s"), ("domain", "^")):
    d = c[c["variant"] == v].sort_values("phi2_window_rad")
    plotting.computed(ax, d["phi2_window_rad"], d["correct_pct"], f"conventional, {v}", marker=mk)
for v, ls in (("seeded", "--"), ("reduced", ":"), ("robust", "-.")):
    d = c[c["variant"] == v]
    if len(d):
        ax.axhline(float(d["correct_pct"].iloc[0]), ls=ls, color="0.3", lw=1, label=f"{v} (independent of phi2 start)")
plotting.published(
    ax, [2 * np.pi], [PUB[T10_CONV]], "Table 10", label="thesis conventional, window not stated", marker="D"
)
plotting.label_axes(
    ax,
    "width of the phi2 start window, centred on the root [rad]",
    "correct-root convergence [%]",
    "Spur 52/72: convergence against the phi2 guess window",
)
ax.set_ylim(-2, 105)
save_figure(plotting.finish(ax, loc="lower left"), smk.output.window)

# --- sec 6.1: fixed phi2 guesses ----------------------------------------------------------------
det = pd.read_csv(TABLES["convergence_detail"])
g = det[det["case"].str.startswith("spur_25_25_guess_")].copy()
g["guess"] = g["case"].str.extract(r"guess_([+-][0-9.]+)rad").astype(float)
ref = pd.read_csv(TABLES["references"]).set_index("case").loc["spur_25_25", "phi2_thesis_rad"]
fig, ax = plt.subplots()
for v, mk in (("plain", "o"), ("damped", "s"), ("domain", "^")):
    d = g[g["variant"] == v].sort_values("guess")
    plotting.computed(ax, d["guess"] - ref, d["correct_pct"], f"conventional, {v}", marker=mk)
# printed: 0 % at 0, 48 % at -1.1, 670 of 1000 at -1.15 (data/published); -1.2 "almost all" (no number, not drawn)
pg = [
    (0.0, PUB[S61.format(g="0", q="convergence_rate")]),
    (-1.1, PUB[S61.format(g="-1.1", q="convergence_rate")]),
    (-1.15, PUB[S61.format(g="-1.15", q="converged_count")] / 10.0),
]
plotting.published(
    ax,
    np.array([x for x, _ in pg]) - ref,
    [y for _, y in pg],
    "sec 6.1",
    label="thesis (-1.2 rad: 'almost all', no number)",
)
plotting.label_axes(
    ax,
    "phi2 guess minus root (thesis frame) [rad]",
    "correct-root convergence [%]",
    "Spur 25/25 (sec 6.1): fixed phi2 guess, u2 and v2 at the flank mid-point",
)
save_figure(plotting.finish(ax), smk.output.guess)

# --- TE curves -----------------------------------------------------------------------------------
cur = pd.read_csv(TABLES["te_curves"])
cyc = pd.read_csv(TABLES["te_cycle"])
fig, axes = plt.subplots(1, 2, figsize=(12, 4.2))
s = cur[cur["case"] == "spur_25_25_m1"]
for (crown, plane), d in s.groupby(["crown_amount", "plane"]):
    if plane == "none":
        continue
    plotting.computed(axes[0], d["phi1_rad"], d["te_pair_arcsec"], f"a1 = {crown:g}, {plane}-plane")
plotting.label_axes(
    axes[0], "phi1 [rad]", "TE of one tooth pair [arcsec]", "Spur 25/25 m = 1, 17.5 mrad misalignment (library sign)"
)
plotting.finish(axes[0])
h = cyc[cyc["case"] == "helical_40_37"]
for (kind, plane), d in h.groupby(["crown_kind", "plane"]):
    plotting.computed(axes[1], d["phi1_rad"], -d["te_arcsec"], f"{kind}, {plane}-plane 0.2 deg")
plotting.label_axes(
    axes[1], "phi1 [rad]", "transmitted TE, thesis sign [arcsec]", "Helical 40/37, Tables 3-4 first rows, one cycle"
)
plotting.finish(axes[1], loc="best")
save_figure(fig, smk.output.te)

# --- paths of contact ------------------------------------------------------------------------------
fig, axes = plt.subplots(1, 2, figsize=(12, 4.2))
for (crown, plane), d in s.groupby(["crown_amount", "plane"]):
    plotting.computed(axes[0], d["v1_thesis_mm"], d["u1_mm"], f"a1 = {crown:g}, {plane}", markersize=2)
axes[0].axvline(5.0, ls="--", color="0.5", lw=1)
axes[0].set_xlim(0.0, 10.0)
plotting.label_axes(axes[0], "v1 (thesis, face 0..10) [mm]", "u1 [mm]", "Spur 25/25 m = 1: path of contact on gear 1")
plotting.finish(axes[0], loc="best")
hc = cur[cur["case"] == "helical_40_37"]
for (kind, plane), d in hc.groupby(["crown_kind", "plane"]):
    plotting.computed(axes[1], d["v1_thesis_mm"], d["u1_mm"], f"{kind}, {plane} 0.2 deg", markersize=2)
axes[1].axvline(10.0, ls="--", color="0.5", lw=1)
axes[1].set_xlim(0.0, 20.0)
plotting.label_axes(axes[1], "v1 (thesis, face 0..20) [mm]", "u1 [mm]", "Helical 40/37: path of contact on the pinion")
plotting.finish(axes[1], loc="best")
save_figure(fig, smk.output.paths)
