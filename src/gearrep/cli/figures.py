"""Figures of ``gearrep tca``, ``gearrep ltca`` and ``gearrep curvature`` (matplotlib, headless): TE
over three meshing cycles with its mean removed, the path of contact on the pinion flank with the
contact ellipses' major axes; the loaded TE beside the unloaded one, the load of each tooth pair
through its engagement and the pressure pattern on the pinion flank; and the principal
curvatures over the active profiles. What differs by
family comes from the design's family (:class:`gearrep.cli.family.Family`: the radius that turns
the TE into a length, the face edges drawn, the flank edges that cut the ellipses).

matplotlib is imported inside the functions that draw: ``gearrep check``, ``schema`` and
``--help`` then start without it (about 0.3 s of import).
"""

from __future__ import annotations

import numpy as np

from ..units import ARCSEC
from .edges import cut_at_edges
from .loaded import tip_kinds

__all__ = ["tca_figures", "ltca_figures", "curvature_figure", "te_scales", "NUMERICALLY_ZERO_UM", "CYCLES_SHOWN"]

#: a peak-to-peak TE below this along the line of action [um] (1 nm) is drawn as numerically zero:
#: a thousand times below the finest gear-accuracy grades' tolerances and measuring resolution,
#: it is rounding of the solves, not a shape to be autoscaled into a sawtooth
NUMERICALLY_ZERO_UM = 1e-3
#: meshing cycles drawn in the TE figure (the cycle repeats with the angular pitch of the pinion)
CYCLES_SHOWN = 3


def te_scales(design) -> tuple[float, float]:
    """(micro-radians of the driven gear per arcsec, micrometres along the line of action per arcsec):
    a TE of the driven gear in angle times the radius of its family's ``te_radius_mm`` (a
    cylindrical gear: its base radius r_b2 = r_p2 cos(alpha_t), the pitch radius N2 m_n / (2 cos
    beta)) is the displacement along the line of action."""
    return ARCSEC * 1e6, ARCSEC * design.family.te_radius_mm(design) * 1e3


def tca_figures(design, tables) -> dict:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    path, te = tables["contact_path"], tables["te_cycle"]
    out = {}

    ok = path["status"] == "converged"
    out["transmission_error"] = _te_figure(design, te, plt)

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
            lambda P: design.family.edges(design, P),
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
    design.family.draw_face_edges(design, ax)
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


def _te_figure(design, te, plt):
    """TE over :data:`CYCLES_SHOWN` meshing cycles, mean removed, in micro-radians of the driven gear
    (left), micrometres along the line of action (right) and arcsec (top note)."""
    urad, um = te_scales(design)
    phi = te["phi1_rad"].to_numpy()
    t = te["te_arcsec"].to_numpy()
    ok = np.isfinite(t)
    fig, ax = plt.subplots(figsize=(6.4, 3.8))
    if ok.sum() < 2:
        ax.text(0.5, 0.5, "no TE: fewer than two converged positions", ha="center", transform=ax.transAxes)
        return fig
    pitch = 2.0 * np.pi / design.values["pinion"]["teeth"]
    x = np.concatenate([phi[ok] + k * pitch for k in range(CYCLES_SHOWN)])
    y = np.tile(t[ok] - np.mean(t[ok]), CYCLES_SHOWN) * urad
    ptp_um = float(np.ptp(t[ok])) * um
    ax.set_xlabel("pinion angle phi1 [rad]")
    ax.set_ylabel("TE, mean removed [urad of the driven gear]")
    ax.set_title(f"{design.name}: TE over {CYCLES_SHOWN} meshing cycles", fontsize=10)
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


def _pyplot():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def ltca_figures(design, loaded) -> dict:
    """The figures of ``gearrep ltca`` from its :class:`gearrep.cli.loaded.Loaded` result: loaded
    and unloaded TE, load sharing (over :data:`CYCLES_SHOWN` meshing cycles) and the pressure
    pattern on the pinion flank over the cycle."""
    plt = _pyplot()
    res = loaded.cycle
    return {
        "loaded_transmission_error": _loaded_te_figure(design, res, plt),
        "load_sharing": _load_sharing_figure(design, res, plt),
        "pressure_pattern": _pressure_pattern_figure(design, res, plt),
    }


def _cycles(design, phi):
    """(angles over CYCLES_SHOWN cycles (CYCLES_SHOWN, n), the pinion's angular pitch [rad])."""
    pitch = 2.0 * np.pi / design.values["pinion"]["teeth"]
    return np.array([phi + c * pitch for c in range(CYCLES_SHOWN)]), pitch


def _loaded_te_figure(design, res, plt):
    """Loaded and unloaded TE [urad of the gear, member 2; um along the line of action on the right]."""
    x, pitch = _cycles(design, res.phi1_rad)
    um_per_urad = 1e-3 * design.family.te_radius_mm(design)
    fig, ax = plt.subplots(figsize=(6.4, 3.8))
    loaded, rigid = res.lte_urad, res.te_unloaded_rad * 1e6
    ax.plot(x.ravel(), np.tile(rigid, CYCLES_SHOWN), "-", c="0.5", label="unloaded (rigid flanks)")
    ok = np.isfinite(loaded)
    ptp = np.ptp(loaded[ok]) if ok.any() else float("nan")
    label = f"loaded, {res.torque_Nm:g} N m (peak to peak {ptp:.4g} urad = {ptp * um_per_urad:.4g} um)"
    ax.plot(x.ravel(), np.tile(loaded, CYCLES_SHOWN), "-", c="C0", label=label)
    bad = ~res.converged
    if bad.any():
        ax.plot(x[:, bad].ravel(), np.tile(rigid[bad], CYCLES_SHOWN), "x", c="C3", label="not converged")
    for k in range(1, CYCLES_SHOWN):
        ax.axvline(res.phi1_rad[0] + k * pitch, c="0.85", lw=0.6)
    ax.set_xlabel("pinion angle phi1 [rad]")
    ax.set_ylabel("TE [urad of the gear]")
    ax.set_title(f"{design.name}: loaded TE over {CYCLES_SHOWN} meshing cycles", fontsize=10)
    sec = ax.secondary_yaxis("right", functions=(lambda v: v * um_per_urad, lambda v: v / um_per_urad))
    sec.set_ylabel("[um along the line of action]")
    ax.legend(fontsize=7, loc="center right")
    fig.tight_layout()
    return fig


def _load_sharing_figure(design, res, plt):
    """Each tooth pair's load through its engagement and the total normal load: tooth pair k at
    phi1 + c pitch carries what pair k - c carries at phi1 (:func:`gearrep.ltca.initial_separations`)."""
    x, pitch = _cycles(design, res.phi1_rad)
    pairs = [int(k) for k in res.separations.pairs]
    col = {k: i for i, k in enumerate(pairs)}
    fig, ax = plt.subplots(figsize=(6.4, 3.8))
    for j, k in enumerate(range(min(pairs), max(pairs) + CYCLES_SHOWN)):
        ys = [
            res.pair_load_N[:, col[k - c]] if k - c in col else np.zeros(len(res.phi1_rad)) for c in range(CYCLES_SHOWN)
        ]
        y = np.concatenate(ys)
        idle = (y == 0) & (np.roll(y, 1) == 0) & (np.roll(y, -1) == 0)  # out of mesh: not drawn
        y = np.where(idle, np.nan, y)
        if np.nanmax(np.nan_to_num(y)) > 0:
            ax.plot(x.ravel(), y, "-", c=f"C{j % 10}", lw=1.0)
    ax.plot(x.ravel(), np.tile(res.normal_load_N, CYCLES_SHOWN), "--", c="k", lw=0.8, label="total normal load")
    for k in range(1, CYCLES_SHOWN):
        ax.axvline(res.phi1_rad[0] + k * pitch, c="0.85", lw=0.6)
    ax.set_xlabel("pinion angle phi1 [rad]")
    ax.set_ylabel("normal load [N]")
    ax.set_title(f"{design.name}: load of each tooth pair through its engagement", fontsize=10)
    ax.set_ylim(bottom=0)
    ax.legend(fontsize=7, loc="lower right")
    fig.tight_layout()
    return fig


def _pressure_quads(res, i: int, tips, n_across: int = 9):
    """(quads (n, 4, 2) in (axial position, radius on the pinion) [mm], their Hertz pressure [MPa],
    the loaded tip-edge contact points (m, 3)) of position ``i``: each loaded node's strip across its
    contact line, cut into ``n_across - 1`` pieces, spanning the node's share of the face along the
    axis (half-way to its neighbours)."""
    m = res.pressure_map(int(i), n_across)
    loaded = (np.nan_to_num(res.node_load_N[i]) > 0) & (m.kind > 0)
    face = loaded & ~tips[i]
    z_node = m.z_mm
    mid = 0.5 * (z_node[:, 1:] + z_node[:, :-1])
    lo = (np.concatenate([z_node[:, :1], mid], axis=1) - z_node)[face][:, None]
    hi = (np.concatenate([mid, z_node[:, -1:]], axis=1) - z_node)[face][:, None]
    P = m.position_mm[face][:, None, :] + m.across_mm[None, :, None] * m.across[face][:, None, :]
    z, r = P[..., 2], np.hypot(P[..., 0], P[..., 1])
    corners = [(z[:, :-1] + lo, r[:, :-1]), (z[:, :-1] + hi, r[:, :-1]), (z[:, 1:] + hi, r[:, 1:])]
    corners.append((z[:, 1:] + lo, r[:, 1:]))
    quads = np.stack([np.stack(c, axis=-1) for c in corners], axis=-2).reshape(-1, 4, 2)
    p = m.pressure_MPa[face]
    return quads, (0.5 * (p[:, :-1] + p[:, 1:])).ravel(), m.position_mm[loaded & tips[i]]


def _pressure_pattern_figure(design, res, plt):
    """Hertz pressure over the cycle on the pinion flank (axial position against radius): every
    loaded node's strip at every converged position (a tooth pair k at phi1 is the reference
    tooth pair at phi1 - k pitch, so together they cover one tooth's engagement); loaded tip
    edges marked apart (their pressure depends on the edge radius)."""
    from matplotlib.collections import PolyCollection

    fig, ax = plt.subplots(figsize=(6.4, 3.8))
    tips = np.isin(res.separations.kind, tip_kinds())
    parts = [_pressure_quads(res, i, tips) for i in np.flatnonzero(res.converged)]
    quads = np.concatenate([q for q, _, _ in parts]) if parts else np.zeros((0, 4, 2))
    if len(quads):
        p = np.concatenate([v for _, v, _ in parts])
        keep = p > 0
        order = np.argsort(p[keep])  # the largest pressures drawn last, on top
        pc = PolyCollection(quads[keep][order], array=p[keep][order], cmap="viridis", edgecolors="none")
        ax.add_collection(pc)
        ax.autoscale_view()
        fig.colorbar(pc, ax=ax, label="Hertz pressure [MPa]")
        E = np.concatenate([e for _, _, e in parts])
        if len(E):
            ax.plot(E[:, 2], np.hypot(E[:, 0], E[:, 1]), "x", c="C3", ms=3, label="loaded tip edge")
            ax.legend(fontsize=7, loc="upper right")
    else:
        ax.text(0.5, 0.5, "no loaded position", ha="center", transform=ax.transAxes)
    design.family.draw_face_edges(design, ax)
    ax.set_xlabel("axial position [mm]")
    ax.set_ylabel("radius on the pinion [mm]")
    ax.set_title(f"{design.name}: contact pressure on the pinion flank over the cycle", fontsize=10)
    fig.tight_layout()
    return fig


def curvature_figure(design, table):
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
    fig.suptitle(f"{design.name}: principal curvatures", fontsize=10)
    fig.tight_layout()
    return fig
