"""Figures of ``gearrep tca`` and ``gearrep curvature`` (matplotlib, headless): TE over three
meshing cycles with its mean removed, the path of contact on the pinion flank with the contact
ellipses' major axes, and the principal curvatures over the active profiles. What differs by
family comes from the design's family (:class:`gearrep.cli.family.Family`: the radius that turns
the TE into a length, the face edges drawn, the flank edges that cut the ellipses).

matplotlib is imported inside the functions that draw: ``gearrep check``, ``schema`` and
``--help`` then start without it (about 0.3 s of import).
"""

from __future__ import annotations

import numpy as np

from ..units import ARCSEC
from .edges import cut_at_edges

__all__ = ["tca_figures", "curvature_figure", "te_scales", "NUMERICALLY_ZERO_UM", "CYCLES_SHOWN"]

#: a peak-to-peak TE below this along the line of action [um] (1 nm) is drawn as numerically zero:
#: a thousand times below the finest gear-accuracy grades' tolerances and measuring resolution,
#: it is rounding of the solves, not a shape to be autoscaled into a sawtooth
NUMERICALLY_ZERO_UM = 1e-3
#: meshing cycles drawn in the TE figure (the cycle repeats with the angular pitch of the pinion)
CYCLES_SHOWN = 3


def te_scales(d) -> tuple[float, float]:
    """(micro-radians of the driven gear per arcsec, micrometres along the line of action per arcsec):
    a TE of the driven gear in angle times the radius of its family's ``te_radius_mm`` (a
    cylindrical gear: its base radius r_b2 = r_p2 cos(alpha_t), the pitch radius N2 m_n / (2 cos
    beta)) is the displacement along the line of action."""
    return ARCSEC * 1e6, ARCSEC * d.family.te_radius_mm(d) * 1e3


def tca_figures(d, tables) -> dict:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    path, te = tables["contact_path"], tables["te_cycle"]
    out = {}

    ok = path["status"] == "converged"
    out["transmission_error"] = _te_figure(d, te, plt)

    # contact points carried back into the pinion frame: axial coordinate vs radius
    fig, ax = plt.subplots(figsize=(6, 3.6))
    p = path[ok]
    phi = p["phi1_rad"].to_numpy()
    x, y, z = (p[c].to_numpy() for c in ("x_mm", "y_mm", "z_mm"))
    r = np.hypot(x, y)
    ax.plot(z, r, "o-", ms=3, label="path of contact")
    if "edge_contact" in p:  # the contact ellipses cut at the tooth edges (gearrep.cli.edges)
        cols = lambda *names: np.column_stack([p[c].to_numpy() for c in names])  # noqa: E731
        cut = cut_at_edges(
            lambda P: d.family.edges(d, P),
            cols("x_mm", "y_mm", "z_mm"),
            cols("normal_x", "normal_y", "normal_z"),
            cols("ellipse_major_x", "ellipse_major_y", "ellipse_major_z"),
            p["ellipse_semi_major_mm"].to_numpy(),
            p["ellipse_semi_minor_mm"].to_numpy(),
        )
        for i, o in enumerate(cut.outline):
            if len(o):  # in the tangent plane: axial position, and radius to first order (r + (X - P) . e_r)
                closed = np.vstack([o, o[:1]])
                e_r = np.array([x[i], y[i], 0.0]) / r[i]
                rr = r[i] + (closed - np.array([x[i], y[i], z[i]])) @ e_r
                ax.plot(closed[:, 2], rr, "-", c="C3" if cut.edge[i] else "C2", lw=0.7)
    else:
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
    d.family.draw_face_edges(d, ax)
    ax.set_xlabel("axial position [mm]")
    ax.set_ylabel("radius on the pinion [mm]")
    ax.set_title(
        "contact path and ellipses (red: cut at a face edge or tip)"
        if "edge_contact" in p
        else "contact path and ellipse major axes (red)",
        fontsize=9,
    )
    fig.tight_layout()
    out["contact_path"] = fig
    return out


def _te_figure(d, te, plt):
    """TE over :data:`CYCLES_SHOWN` meshing cycles, mean removed, in micro-radians of the driven gear
    (left), micrometres along the line of action (right) and arcsec (top note)."""
    urad, um = te_scales(d)
    phi = te["phi1_rad"].to_numpy()
    t = te["te_arcsec"].to_numpy()
    ok = np.isfinite(t)
    fig, ax = plt.subplots(figsize=(6.4, 3.8))
    if ok.sum() < 2:
        ax.text(0.5, 0.5, "no TE: fewer than two converged positions", ha="center", transform=ax.transAxes)
        return fig
    pitch = 2.0 * np.pi / d.values["pinion"]["teeth"]
    x = np.concatenate([phi[ok] + k * pitch for k in range(CYCLES_SHOWN)])
    y = np.tile(t[ok] - np.mean(t[ok]), CYCLES_SHOWN) * urad
    ptp_um = float(np.ptp(t[ok])) * um
    ax.set_xlabel("pinion angle phi1 [rad]")
    ax.set_ylabel("TE, mean removed [urad of the driven gear]")
    ax.set_title(f"{d.name}: TE over {CYCLES_SHOWN} meshing cycles", fontsize=10)
    if ptp_um < NUMERICALLY_ZERO_UM:
        ax.plot(x, np.zeros_like(x), "-", color="C0")
        ax.set_ylim(-1.0, 1.0)
        ax.text(
            0.5,
            0.6,
            f"TE numerically zero: {ptp_um * 1e3:.2g} nm peak to peak along the line of action (below 1 nm)",
            ha="center",
            transform=ax.transAxes,
            fontsize=8,
        )
    else:
        ax.plot(x, y, "-", color="C0")
        ax.text(
            0.01,
            0.97,
            f"peak to peak {np.ptp(y):.4g} urad = {ptp_um:.4g} um along the line of action = {np.ptp(t[ok]):.4g} arcsec",
            transform=ax.transAxes,
            fontsize=8,
            va="top",
        )
    sec = ax.secondary_yaxis("right", functions=(lambda v: v * um / urad, lambda v: v * urad / um))
    sec.set_ylabel("[um along the line of action]")
    for k in range(1, CYCLES_SHOWN):
        ax.axvline(phi[ok][0] + k * pitch, c="0.8", lw=0.6)
    fig.tight_layout()
    return fig


def curvature_figure(d, table):
    """Principal curvatures k1, k2 [1/mm] of both flanks against their first flank parameter
    (involute: the radius, over the active profile)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    name = table.columns[1]
    fig, axes = plt.subplots(1, 2, figsize=(8, 3.4), sharey=False)
    for ax, member in zip(axes, ("pinion", "gear")):
        t = table[table["member"] == member]
        ax.plot(t[name], t["k1_per_mm"], ".", ms=3, label="k1")
        ax.plot(t[name], t["k2_per_mm"], ".", ms=3, label="k2")
        ax.set_xlabel(name)
        ax.set_ylabel("principal curvature [1/mm]")
        ax.set_title(f"{member}", fontsize=10)
        ax.legend(fontsize=8)
    fig.suptitle(f"{d.name}: principal curvatures", fontsize=10)
    fig.tight_layout()
    return fig
