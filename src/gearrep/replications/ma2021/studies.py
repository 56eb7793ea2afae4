"""What seed 004's replication computes: one function per job, each returning only its tables.

Every function takes the resolved settings and the :class:`~.design.Design` and is callable alone.
The TCA of a pair is the expensive step (about 0.1 s per design, flank pair and reading); jobs
that need only a few points solve only those (pitch point, gap check).
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd

from ...surface import fd_derivatives
from ...surfaces.catt import PAIRS, assemble, middle_section_curvatures, path_limits, solve_cycle
from .._face import Job
from .assembly import (
    PRIMARY,
    READINGS,
    mesh_to_reading,
    pitch_point_closed_form,
    reading_to_mesh,
)
from .contact import contact_geometry, tip_edges
from .design import Design, merged_params
from .gap import exact_contact_region
from .loaded import loaded_footprint
from .profiles import equation_checks, section_shapes, thickness_table

__all__ = [
    "JOBS",
    "designs",
    "cycle",
    "pitch_point",
    "precision",
    "thickness",
    "sections",
    "equations",
    "gap_check",
    "settings_table",
    "reading_grid",
    "curve",
]


def _key(d: dict):
    return (d["z1"], d["z2"], d["module"], d["R_T"], d["face_width"])


def reading_grid(mesh, lim: dict, reading: str, params: dict):
    """Paper abscissa grid (deg) of one reading and the real path's ends in it: the whole real path
    plus the window where it lies within ``off_path_margin_deg`` of the path, every
    ``step_deg``, with the window ends, 0, the near-top angles and the path ends added."""
    wlo, whi = params["window_deg"]
    ends = sorted(np.degrees(mesh_to_reading(mesh, reading, [lim["phi1_lo"], lim["phi1_hi"]])))
    lo = max(min(wlo, ends[0]), ends[0] - params["off_path_margin_deg"])
    hi = min(max(whi, ends[1]), ends[1] + params["off_path_margin_deg"])
    extra = [x for x in (wlo, whi, 0.0, params["near_top_eval_deg"], whi - params["near_top_deg"]) if lo <= x <= hi]
    step = params["step_deg"]
    g = np.arange(math.floor(lo / step) * step, hi + 1e-9, step)
    grid = np.unique(np.round(np.concatenate([g, np.asarray(extra + [lo, hi, ends[0], ends[1]], float)]), 10))
    return grid[(grid >= lo - 1e-9) & (grid <= hi + 1e-9)], ends


def curve(mesh, reading: str, params: dict, tips=None, clip: bool = True, near_deg=None) -> pd.DataFrame:
    """TCA and contact geometry of one pair along the grid of one reading (:func:`reading_grid`),
    with the columns phi_paper_deg, in_window and on_path in front; only at the grid points
    nearest to the angles ``near_deg`` (paper abscissa, deg) if given."""
    wlo, whi = params["window_deg"]
    grid, ends = reading_grid(mesh, path_limits(mesh), reading, params)
    if near_deg is not None:
        grid = grid[sorted({int(np.argmin(np.abs(grid - x))) for x in near_deg})]
    cp = solve_cycle(mesh, reading_to_mesh(mesh, reading, np.radians(grid)), params)
    geo = contact_geometry(mesh, cp, params, tips, clip=clip)
    geo.insert(0, "phi_paper_deg", grid)
    geo.insert(1, "in_window", (grid >= wlo - 1e-9) & (grid <= whi + 1e-9))
    geo.insert(2, "on_path", (grid >= ends[0] - 1e-9) & (grid <= ends[1] + 1e-9))
    return geo


def _design_columns(d: dict, pid: str, rd: str) -> dict:
    return {
        "design": d["name"],
        "group": d["group"],
        "pair": pid,
        "reading": rd,
        "z1": d["z1"],
        "z2": d["z2"],
        "module_mm": d["module"],
        "R_T_mm": d["R_T"],
    }


def designs(settings: dict, design: Design) -> dict:
    """``designs``: every pair, flank pair and reading with its real path in the paper abscissa
    (closed form on the middle section) against the paper's window."""
    params = merged_params(settings, design)
    wlo, whi = params["window_deg"]
    rows = []
    for d in design.designs:
        for pid in PAIRS:
            mesh = assemble(d, pid, params)
            lim = path_limits(mesh)
            for rd in READINGS:
                _, ends = reading_grid(mesh, lim, rd, params)
                rows.append(
                    {
                        **_design_columns(d, pid, rd),
                        "B_mm": d["face_width"],
                        "pressure_angle_deg": params["pressure_angle_deg"],
                        "path_start_deg": ends[0],
                        "path_end_deg": ends[1],
                        "window_lo_deg": wlo,
                        "window_hi_deg": whi,
                        "contact_ratio": lim["contact_ratio"],
                        "window_inside_path": bool(ends[0] <= wlo and whi <= ends[1]),
                    }
                )
    return {"designs": pd.DataFrame(rows)}


def cycle(settings: dict, design: Design) -> dict:
    """``cycle``: TCA and contact ellipse along the meshing cycle, one row per design x flank pair x
    reading x abscissa (pairs with equal data are solved once)."""
    params = merged_params(settings, design)
    done, frames = {}, []
    for d in design.designs:
        for pid in PAIRS:
            if (_key(d), pid) not in done:
                mesh = assemble(d, pid, params)
                tips = tip_edges(mesh, params["n_tip_edge"])
                done[(_key(d), pid)] = {rd: curve(mesh, rd, params, tips) for rd in READINGS}
            for rd, geo in done[(_key(d), pid)].items():
                cols = _design_columns(d, pid, rd)
                frames.append(pd.concat([pd.DataFrame({k: [v] * len(geo) for k, v in cols.items()}), geo], axis=1))
    return {"cycle": pd.concat(frames, ignore_index=True)}


def _pitch_points(params: dict, design: Design):
    """(design, mesh, contact row at the pitch point, closed form) per design and flank pair: the
    TCA from the perturbed start at phi1 = 0 (pairs with equal data solved once)."""
    out, done = [], {}
    for d in design.designs:
        cf = pitch_point_closed_form(d, params)
        for pid in PAIRS:
            mesh = assemble(d, pid, params)
            if (_key(d), pid) not in done:
                geo0 = contact_geometry(mesh, solve_cycle(mesh, np.array([0.0]), params), params, clip=False)
                done[(_key(d), pid)] = geo0.iloc[0]
            out.append((d, mesh, done[(_key(d), pid)], cf))
    return out


def pitch_point(settings: dict, design: Design) -> dict:
    """``pitch_point``: the TCA pipeline at the pitch point against the closed form."""
    rows = []
    for d, mesh, r0, cf in _pitch_points(merged_params(settings, design), design):
        rows.append(
            {
                "design": d["name"],
                "pair": mesh.pair_id,
                "status": r0["status"],
                "z_mm": r0["z_mm"],
                "te_arcsec": r0["te_arcsec"],
                "iterations": r0["iterations"],
                "dist_to_pitch_point_mm": float(np.hypot(r0["x_mm"] - mesh.g1.r_p, r0["y_mm"])),
                "kappa_axial_pipeline_per_mm": r0["kappa_long_per_mm"],
                "kappa_axial_closed_per_mm": cf["kappa_axial"],
                "kappa_profile_pipeline_per_mm": r0["kappa_short_per_mm"],
                "kappa_profile_closed_per_mm": cf["kappa_profile"],
                "a_pipeline_mm": r0["a_mm"],
                "a_closed_mm": cf["a"],
                "b_pipeline_mm": r0["b_mm"],
                "b_closed_mm": cf["b"],
                "S_pipeline_mm2": r0["S_mm2"],
                "S_closed_mm2": cf["S"],
                "S_rel_err": r0["S_mm2"] / cf["S"] - 1.0,
                "a_rel_err": r0["a_mm"] / cf["a"] - 1.0,
                "b_rel_err": r0["b_mm"] / cf["b"] - 1.0,
            }
        )
    return {"pitch_point": pd.DataFrame(rows)}


def _precision_row(mesh, r0: pd.Series, cf: dict) -> dict:
    """Cancellation in the axial relative curvature and the curvature accuracy S needs; analytic
    vs 4th-order finite-difference derivatives of the flank (independent check)."""
    cancel = abs(r0["k_axial_pinion_per_mm"]) / cf["kappa_axial"]
    th, ph = r0["theta1_rad"], r0["phig1_rad"]
    Pa = mesh.f1.evaluate(th, ph)
    Pf = fd_derivatives(mesh.f1.position, np.array(th), np.array(ph), 1e-4, 1e-4)
    n = Pa.normal
    kk = [(P.r_uu @ n) / (P.r_u @ P.r_u) for P in (Pa, Pf)]
    _, ka1, _, _ = middle_section_curvatures(mesh.g1, mesh.f1.side, np.hypot(*Pa.r[:2]))
    return {
        "design": mesh.design["name"],
        "pair": mesh.pair_id,
        "k_axial_pinion_per_mm": r0["k_axial_pinion_per_mm"],
        "k_axial_gear_per_mm": r0["k_axial_gear_per_mm"],
        "kappa_axial_per_mm": cf["kappa_axial"],
        "cancellation_factor": cancel,
        "curvature_rel_accuracy_needed_for_S_1e-6": 1e-6 * np.sqrt(2.0) / cancel,
        "k_axial_analytic_vs_closed_rel": abs(kk[0] / ka1 - 1.0),
        "k_axial_fd_vs_analytic_rel": abs(kk[1] / kk[0] - 1.0),
    }


def precision(settings: dict, design: Design) -> dict:
    """``precision``: how much the long axis loses to cancellation at the pitch point, per pair."""
    return {
        "precision": pd.DataFrame(
            [_precision_row(mesh, r0, cf) for _, mesh, r0, cf in _pitch_points(merged_params(settings, design), design)]
        )
    }


def thickness(settings: dict, design: Design) -> dict:
    """``thickness``: pitch-circle tooth thickness vs R_T at the sections of Fig 14."""
    return {"thickness": thickness_table(merged_params(settings, design))}


def sections(settings: dict, design: Design) -> dict:
    """``sections``: transverse sections of the ``section_check`` design against involutes."""
    params = merged_params(settings, design)
    return {"sections": section_shapes(design.by_name(settings["section_check"]["design"]), params)}


def equations(settings: dict, design: Design) -> dict:
    """``equations``: eq (6) literal vs closed form, eq (28)-(29) vs eq (6), the meshing residual."""
    params = merged_params(settings, design)
    return {"equations": equation_checks(design.by_name(settings["section_check"]["design"]), params)}


def gap_check(settings: dict, design: Design) -> dict:
    """``gap_check``: exact <= delta separation region vs the ellipse at the grid points (reading R1)
    nearest to ``gap_check.phi_deg`` of the ``gap_check`` design, both flank pairs."""
    params = merged_params(settings, design)
    d = design.by_name(settings["gap_check"]["design"])
    rows = []
    for pid in PAIRS:
        mesh = assemble(d, pid, params)
        sel = curve(mesh, "R1", params, clip=False, near_deg=settings["gap_check"]["phi_deg"])
        for ph in settings["gap_check"]["phi_deg"]:
            r = sel.loc[(sel["phi_paper_deg"] - ph).abs().idxmin()]
            if not r["solved"]:
                continue
            ex = exact_contact_region(mesh, r, params, settings["gap_check"]["n_dirs"])
            rows.append(
                {
                    "design": d["name"],
                    "pair": pid,
                    "phi_paper_deg": r["phi_paper_deg"],
                    "S_ellipse_mm2": r["S_mm2"],
                    **ex,
                    "area_rel_diff": ex["area_exact_mm2"] / r["S_mm2"] - 1.0,
                    "centroid_offset_over_2b": np.hypot(ex["centroid_long_mm"], ex["centroid_short_mm"])
                    / (2 * r["b_mm"]),
                }
            )
    return {"gap_check": pd.DataFrame(rows)}


def settings_table(settings: dict, design: Design) -> dict:
    """``settings``: the settings and design data the claims read back (window, near-top zone,
    delta, grid, tool data, tolerance) and the primary flank pair and reading."""
    params = merged_params(settings, design)
    wlo, whi = params["window_deg"]
    return {
        "settings": pd.DataFrame(
            [
                {
                    "window_lo_deg": wlo,
                    "window_hi_deg": whi,
                    "near_top_deg": params["near_top_deg"],
                    "near_top_eval_deg": params["near_top_eval_deg"],
                    "delta_mm": params["delta_mm"],
                    "step_deg": params["step_deg"],
                    "off_path_margin_deg": params["off_path_margin_deg"],
                    "pressure_angle_deg": params["pressure_angle_deg"],
                    "addendum": params["addendum"],
                    "clearance": params["clearance"],
                    "tol": params["tol"],
                    "n_designs": len(design.designs),
                    "primary_pair": PRIMARY[0],
                    "primary_reading": PRIMARY[1],
                }
            ]
        )
    }


def _job(fn, *names):
    return Job(fn, {n: f"ma2021/{n}.csv" for n in names}, " ".join(fn.__doc__.split("\n\n")[0].split()))


JOBS = {
    "designs": _job(designs, "designs"),
    "cycle": _job(cycle, "cycle"),
    "pitch_point": _job(pitch_point, "pitch_point"),
    "precision": _job(precision, "precision"),
    "thickness": _job(thickness, "thickness"),
    "sections": _job(sections, "sections"),
    "equations": _job(equations, "equations"),
    "gap_check": _job(gap_check, "gap_check"),
    "settings": _job(settings_table, "settings"),
    "loaded_footprint": _job(loaded_footprint, "loaded_footprint"),
}
