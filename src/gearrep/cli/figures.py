"""Figures of ``gearrep tca`` (matplotlib, headless): TE over the meshing cycle, and the path of
contact on the pinion flank with the contact ellipses' major axes."""

from __future__ import annotations

import numpy as np

__all__ = ["tca_figures"]


def tca_figures(d, tables) -> dict:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    path, te = tables["contact_path"], tables["te_cycle"]
    out = {}

    fig, ax = plt.subplots(figsize=(6, 3.6))
    ok = path["status"] == "converged"
    ax.plot(path["phi1_rad"][ok], path["te_arcsec"][ok], "o", ms=3, color="0.6", label="one tooth pair")
    ax.plot(te["phi1_rad"], te["te_arcsec"], "-", color="C0", label="meshing cycle (envelope)")
    ax.set_xlabel("pinion angle phi1 [rad]")
    ax.set_ylabel("transmission error [arcsec]")
    ax.set_title(f"{d.name}: TE")
    ax.legend(fontsize=8)
    fig.tight_layout()
    out["transmission_error"] = fig

    # contact points carried back into the pinion frame: axial coordinate vs radius
    fig, ax = plt.subplots(figsize=(6, 3.6))
    p = path[ok]
    phi = p["phi1_rad"].to_numpy()
    x, y, z = (p[c].to_numpy() for c in ("x_mm", "y_mm", "z_mm"))
    r = np.hypot(x, y)
    ax.plot(z, r, "o-", ms=3, label="path of contact")
    a = p["ellipse_semi_major_mm"].to_numpy()
    mx, my, mz = (p[c].to_numpy() for c in ("ellipse_major_x", "ellipse_major_y", "ellipse_major_z"))
    dr = (x * mx + y * my) / np.where(r > 0, r, 1.0)
    for i in range(len(phi)):
        if np.isfinite(a[i]):
            ax.plot(
                [z[i] - a[i] * mz[i], z[i] + a[i] * mz[i]],
                [r[i] - a[i] * dr[i], r[i] + a[i] * dr[i]],
                "-",
                c="C3",
                lw=0.8,
            )
    half = 0.5 * d.values["face_width_mm"]
    ax.axvline(-half, c="0.5", lw=0.6)
    ax.axvline(half, c="0.5", lw=0.6)
    ax.set_xlabel("axial position [mm]")
    ax.set_ylabel("radius on the pinion [mm]")
    ax.set_title("contact path and ellipse major axes (red)")
    fig.tight_layout()
    out["contact_path"] = fig
    return out
