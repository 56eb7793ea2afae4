"""What seed 000 ch. 4 computes, one function per job. Each takes ``p``, the resolved settings
merged with the design (:func:`gearrep.replications.hobcut_curvature.merged`), and computes only
its table; the l_1 grid (one Newton solve for the tip row) is recomputed by each job.

Model: :mod:`gearrep.surfaces.hob` (hob eq 4.40-4.48, generation set-up reconstructed as in
docs/reading-notes.md 000-C, seed 000 ch. 2-3 being missing). Curvatures two ways at every tabulated point:
(a) direct differential geometry of the generated surface r(l, psi); (b) the chapter's
two-parameter method (eq 4.33 with eq 4.37-4.39 sign-corrected, 4.24-4.26;
:mod:`gearrep.curvature_relations`). The findings are told in ``notebooks/hobcut_curvature.ipynb``.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from ...curvature import principal_curvatures
from ...ellipse import elastic_ellipse_from_relative
from ...solve import status_names
from ...surfaces.hob import GeneratedGear, ZAHob, za_hob
from .._face import Job
from .design import merged

__all__ = [
    "JOBS",
    "TABLES",
    "TABLE_COLUMNS",
    "hob",
    "gear",
    "l1_grid",
    "evaluate_rows",
    "direct_curvatures",
    "curvature_tables",
    "curvature_table",
    "detail",
    "conventions",
    "assignment",
    "variants",
    "face",
    "rc_sweep",
    "undercut",
    "ellipses",
    "pitch_l",
]

TABLES = {  # table -> (flank, R_c key)
    "4.2": ("L", "R_c_small_mm"),
    "4.3": ("R", "R_c_small_mm"),
    "4.4": ("L", "R_c_large_mm"),
    "4.5": ("R", "R_c_large_mm"),
}
TABLE_COLUMNS = ["l1_mm", "k_s_per_mm", "e_s_x", "e_s_y", "e_s_z", "k_q_per_mm", "e_q_x", "e_q_y", "e_q_z"]


def hob(p: dict, variant: str = "axial", pressure_angle_deg: float | None = None) -> ZAHob:
    """The Table 5.1 hob of the design ``p`` (or at another pressure angle): one route with
    hobcut_tca (:func:`gearrep.surfaces.hob.za_hob`)."""
    a = p["pressure_angle_deg"] if pressure_angle_deg is None else pressure_angle_deg
    return za_hob(p["module_mm"], a, p["hob_pitch_radius_mm"], variant)


def solve_tol(p: dict, R_c_mm: float) -> float:
    """``tol`` of :class:`GeneratedGear` (which scales it by max(1, R_c / 100 mm) itself)."""
    return p["tol"]


def gear(p: dict, flank: str, R_c_mm: float, variant: str = "axial", **kw) -> GeneratedGear:
    kw.setdefault("n_teeth", p["n_teeth"])
    h = kw.pop("hob", None) or hob(p, variant)
    return GeneratedGear.flank(flank, hob=h, R_c_mm=float(R_c_mm), tol=solve_tol(p, R_c_mm), maxiter=p["maxiter"], **kw)


def l1_grid(p: dict, variant: str = "axial") -> tuple[np.ndarray, object]:
    """The l_1 rows: n_rows equal steps from the exact tip l (r = tip radius) to l1_end."""
    g = gear(p, "R", p["R_c_small_mm"], variant)
    res = g.l_at_radius(p["tip_radius_mm"])
    if res.status[0] != 0:
        raise RuntimeError(f"tip l_1 solve did not converge ({status_names(res.status)[0]})")
    return np.linspace(res.x[0, 0], p["l1_end_mm"], p["n_rows"]), res


def _oriented(c):
    """Table columns from a FlankCurvatures record."""
    return np.column_stack([c.k_s, c.e_s, c.k_q, c.e_q])


def evaluate_rows(p: dict, flank: str, R_c: float, l: np.ndarray, variant: str = "axial"):
    """(columns (n, 8): k_s, e_s, k_q, e_q; FlankCurvatures) at mid-face rows l."""
    c = gear(p, flank, R_c, variant).curvatures(l, 0.0)
    return _oriented(c), c


def direct_curvatures(p: dict, flank: str, R_c: float, l, psi=0.0):
    """Method (a): principal curvatures of r(l, psi) from its fundamental forms, re-signed for
    the hob normal; returns (k_along_Z_nearest, k_other) paired like k_s, k_q."""
    g = gear(p, flank, R_c)
    l, psi = np.broadcast_arrays(np.asarray(l, float), np.asarray(psi, float))
    surf = g.surface("tooth", fd_step=(p["fd_step_l_mm"], p["fd_step_psi_rad"]))
    pc = principal_curvatures(surf.evaluate(l.reshape(-1), psi.reshape(-1)))
    _, n_hob, _ = g.points(l.reshape(-1), psi.reshape(-1))
    s = np.sign(np.sum(pc.normal * n_hob, -1))
    k1, k2 = s * pc.k1, s * pc.k2
    e1, e2 = pc.e1, pc.e2
    use1 = np.abs(e1[:, 2]) >= np.abs(e2[:, 2])
    return np.where(use1, k1, k2), np.where(use1, k2, k1)


def _table(p: dict, tab: str, l: np.ndarray, variant: str) -> pd.DataFrame:
    flank, key = TABLES[tab]
    cols, c = evaluate_rows(p, flank, p[key], l, variant)
    if not np.all(c.result.converged):
        raise RuntimeError(f"Table {tab}: meshing solve failed at rows {np.flatnonzero(~c.result.converged)}")
    return pd.DataFrame(np.column_stack([l, cols]), columns=TABLE_COLUMNS)


def curvature_table(p: dict, tab: str) -> pd.DataFrame:
    """One of Tables 4.2-4.5 at the reconstructed l grid (interface columns :data:`TABLE_COLUMNS`)."""
    return _table(p, tab, l1_grid(p)[0], "axial")


def curvature_tables(p: dict, variant: str = "axial") -> dict[str, pd.DataFrame]:
    """Tables 4.2-4.5 at the reconstructed l grid (``variant`` of the hob: axial or printed)."""
    l, _ = l1_grid(p, variant)
    return {tab: _table(p, tab, l, variant) for tab in TABLES}


def detail(p: dict) -> pd.DataFrame:
    """Per row of every table: both methods, the values at the printed (rounded) l_1 and their
    derivatives d/dl_1 (central difference, step dl_mm) for the rounding allowance."""
    grid, _ = l1_grid(p)
    dec = p["l1_printed_decimals"]
    l_pr = np.round(grid, dec)
    rows = []
    for tab, (flank, key) in TABLES.items():
        Rc = p[key]
        cg, c = evaluate_rows(p, flank, Rc, grid)
        cp, cpr = evaluate_rows(p, flank, Rc, l_pr)
        h = p["dl_mm"]
        cplus, _ = evaluate_rows(p, flank, Rc, l_pr + h)
        cminus, _ = evaluate_rows(p, flank, Rc, l_pr - h)
        deriv = (cplus - cminus) / (2 * h)
        ks_a, kq_a = direct_curvatures(p, flank, Rc, grid)
        r = np.hypot(c.point[:, 0], c.point[:, 1])
        for i in range(len(grid)):
            rec = {
                "table": tab,
                "flank": f"Sigma_2{flank}",
                "R_c_mm": Rc,
                "row": i,
                "l1_grid_mm": grid[i],
                "l1_printed_mm": l_pr[i],
                "x_mm": c.point[i, 0],
                "y_mm": c.point[i, 1],
                "z_mm": c.point[i, 2],
                "radius_mm": r[i],
                "psi_rad": c.result.param("psi")[i],
                "phi_rad": c.result.params[i, 1],
                "theta_rad": c.result.param("theta")[i],
                "status": status_names(c.result.status)[i],
                "residual": c.result.residual[i],
                "singular_measure": c.result.singular_measure[i],
                "k_s_direct_per_mm": ks_a[i],
                "k_q_direct_per_mm": kq_a[i],
                "k_s_seed_method_per_mm": float(
                    c.k_s_two_parameter[i]
                    if abs(c.k_s_two_parameter[i] - c.k_s[i]) <= abs(c.k_q_two_parameter[i] - c.k_s[i])
                    else c.k_q_two_parameter[i]
                ),
                "k_q_seed_method_per_mm": float(
                    c.k_q_two_parameter[i]
                    if abs(c.k_s_two_parameter[i] - c.k_s[i]) <= abs(c.k_q_two_parameter[i] - c.k_s[i])
                    else c.k_s_two_parameter[i]
                ),
                "sigma_seed_deg": np.degrees(c.sigma_two_parameter[i]),
                "k_f_hob_per_mm": c.generated.k_f[i],
                "k_h_hob_per_mm": c.generated.k_h[i],
            }
            for j, q in enumerate(("k_s", "e_s_x", "e_s_y", "e_s_z", "k_q", "e_q_x", "e_q_y", "e_q_z")):
                rec[f"{q}_grid"] = cg[i, j]
                rec[f"{q}_printed_l"] = cp[i, j]
                rec[f"d_{q}_dl1"] = deriv[i, j]
            rows.append(rec)
    d = pd.DataFrame(rows)
    d["rel_diff_direct_vs_relations"] = np.maximum(
        np.abs(d["k_s_direct_per_mm"] / d["k_s_grid"] - 1), np.abs(d["k_q_direct_per_mm"] / d["k_q_grid"] - 1)
    )
    d["rel_diff_direct_vs_seed_method"] = np.maximum(
        np.abs(d["k_s_direct_per_mm"] / d["k_s_seed_method_per_mm"] - 1),
        np.abs(d["k_q_direct_per_mm"] / d["k_q_seed_method_per_mm"] - 1),
    )
    return d


def assignment(p: dict) -> pd.DataFrame:
    """k_s, k_q at the tip and last rows for every (thread side, arc-centre side, R_c): which
    combination the surviving blocks come from."""
    grid, _ = l1_grid(p)
    rows = []
    for side in (1, -1):
        for arc in (-1, 1):
            for key in ("R_c_small_mm", "R_c_large_mm"):
                g = GeneratedGear(
                    hob=hob(p), n_teeth=p["n_teeth"], R_c_mm=p[key], side=side, arc_centre=arc, tol=solve_tol(p, p[key])
                )
                c = g.curvatures(grid[[0, -1]])
                rows.append(
                    {
                        "side": side,
                        "arc_centre": arc,
                        "R_c_mm": p[key],
                        "all_converged": bool(np.all(c.result.converged)),
                        "flank_shape": "convex" if c.k_s[0] * c.k_q[0] > 0 else "concave",
                        "k_s_tip_per_mm": c.k_s[0],
                        "k_s_last_per_mm": c.k_s[1],
                        "k_q_tip_per_mm": c.k_q[0],
                        "k_q_last_per_mm": c.k_q[1],
                        "note": (
                            "tables' convention"
                            if arc == -1
                            else "arc centre on the other side "
                            "(tests/unit/_envelope_cases.py::hob_case for side +1, R_c 110)"
                        ),
                    }
                )
    return pd.DataFrame(rows)


def variants(p: dict) -> pd.DataFrame:
    """The four tables with eq 4.40 as printed against the true ZA (axial) hob."""
    tabs_axial = curvature_tables(p)
    tp = curvature_tables(p, "printed")
    rows = []
    for tab in TABLES:
        a, b = tabs_axial[tab], tp[tab]
        for i in range(len(a)):
            rows.append(
                {
                    "table": tab,
                    "row": i,
                    "l1_axial_mm": a["l1_mm"][i],
                    "l1_printed_variant_mm": b["l1_mm"][i],
                    "k_s_axial_per_mm": a["k_s_per_mm"][i],
                    "k_s_printed_eq_per_mm": b["k_s_per_mm"][i],
                    "k_q_axial_per_mm": a["k_q_per_mm"][i],
                    "k_q_printed_eq_per_mm": b["k_q_per_mm"][i],
                    "k_q_rel_diff": b["k_q_per_mm"][i] / a["k_q_per_mm"][i] - 1,
                    "k_s_rel_diff": b["k_s_per_mm"][i] / a["k_s_per_mm"][i] - 1,
                }
            )
    return pd.DataFrame(rows)


def face(p: dict) -> pd.DataFrame:
    """Curvatures across the face (not only Z_f = 0), both flanks at R_c small: grid of l and
    psi; Z_f of each point is reported. ``beyond_limit_line``: the determinant of Litvin's
    singularity matrix has the other sign than at mid-face for the same l, i.e. the point lies
    beyond a singular (limiting) line of the envelope (undercut region; curvatures there pass
    through infinity and belong to the part of the envelope the hob removes)."""
    grid, _ = l1_grid(p)
    ls = np.linspace(grid[0], grid[-1], p["face_n_l"])
    rows = []
    for flank in ("R", "L"):
        Rc = p["R_c_small_mm"]
        half = 0.5 * p["face_width_mm"]
        psis = np.linspace(-np.arcsin(min(half / Rc, 1.0)), np.arcsin(min(half / Rc, 1.0)), p["face_n_z"])
        L, PS = np.meshgrid(ls, psis, indexing="ij")
        g = gear(p, flank, Rc)
        c = g.curvatures(L.reshape(-1), PS.reshape(-1))
        det_mid = np.sign(g.solve(ls, 0.0).litvin_det)
        beyond = (np.sign(c.result.litvin_det).reshape(L.shape) != det_mid[:, None]).reshape(-1)
        for i in range(L.size):
            rows.append(
                {
                    "flank": f"Sigma_2{flank}",
                    "R_c_mm": Rc,
                    "l1_mm": L.reshape(-1)[i],
                    "psi_rad": PS.reshape(-1)[i],
                    "Z_f_mm": c.point[i, 2],
                    "radius_mm": np.hypot(*c.point[i, :2]),
                    "k_s_per_mm": c.k_s[i],
                    "k_q_per_mm": c.k_q[i],
                    "e_s_z": c.e_s[i, 2],
                    "status": status_names(c.result.status)[i],
                    "singular_measure": c.result.singular_measure[i],
                    "beyond_limit_line": bool(beyond[i]),
                }
            )
    return pd.DataFrame(rows)


def rc_sweep(p: dict) -> pd.DataFrame:
    """k_s, k_q against R_c and the spur-gear limit itself (R_c = inf: the swivel becomes an axial
    feed, k_s = 0 exactly), at the tip, pitch and last rows; R_c k_s tends to a finite limit."""
    grid, _ = l1_grid(p)
    ls = np.array([grid[0], pitch_l(p), grid[-1]])
    labels = ["tip", "pitch", "last_row"]
    rows = []
    for flank in ("R", "L"):
        for Rc in sorted(float(r) for r in p["rc_sweep_mm"]) + [np.inf]:  # inf: the spur gear cut by the same hob
            c = gear(p, flank, Rc).curvatures(ls)
            for i, lab in enumerate(labels):
                rows.append(
                    {
                        "flank": f"Sigma_2{flank}",
                        "R_c_mm": Rc,
                        "row": lab,
                        "l1_mm": ls[i],
                        "k_s_per_mm": c.k_s[i],
                        "k_q_per_mm": c.k_q[i],
                        "R_c_times_k_s": Rc * c.k_s[i] if np.isfinite(Rc) else np.nan,
                        "status": status_names(c.result.status)[i],
                    }
                )
    return pd.DataFrame(rows)


def pitch_l(p: dict) -> float:
    """l at the pitch radius (mid-face, Sigma_2R at R_c small)."""
    g = gear(p, "R", p["R_c_small_mm"])
    res = g.l_at_radius(0.5 * p["module_mm"] * p["n_teeth"])
    if res.status[0] != 0:
        raise RuntimeError("pitch-radius l solve did not converge")
    return float(res.x[0, 0])


def undercut(p: dict) -> pd.DataFrame:
    """Singular-point (undercut) check on the working profile: Litvin's measure (smallest over
    largest singular value of the (2+k)-square matrix of gearrep.envelope, 0 at a singular point)
    and sign changes of its determinant along l, at mid-face and at psi = +-asin(b/2 / R_c) (the
    face ends). Where the determinant changes sign, the limiting l is located by linear
    interpolation of the determinant and reported with its radius and Z_f."""
    grid, _ = l1_grid(p)
    ls = np.linspace(grid[0], grid[-1], p["undercut_n_l"])
    rows = []
    for flank in ("R", "L"):
        for key in ("R_c_small_mm", "R_c_large_mm"):
            Rc = p[key]
            half = 0.5 * p["face_width_mm"]
            pe = float(np.arcsin(min(half / Rc, 1.0)))
            for ps in (0.0, pe, -pe):
                g = gear(p, flank, Rc)
                rec = g.solve(ls, ps)
                det = rec.litvin_det
                ch = np.flatnonzero(np.diff(np.sign(det)) != 0)
                l_sing = r_sing = z_sing = np.nan
                if len(ch):
                    i = ch[0]
                    l_sing = ls[i] - det[i] * (ls[i + 1] - ls[i]) / (det[i + 1] - det[i])
                    pt, _, r2 = g.points(np.array([l_sing]), ps)
                    r_sing, z_sing = float(np.hypot(pt[0, 0], pt[0, 1])), float(pt[0, 2])
                rows.append(
                    {
                        "flank": f"Sigma_2{flank}",
                        "R_c_mm": Rc,
                        "psi_rad": ps,
                        "Z_f_mm_at_last_row": float(g.points(ls[-1:], ps)[0][0, 2]),
                        "n_points": len(ls),
                        "l1_from_mm": ls[0],
                        "l1_to_mm": ls[-1],
                        "all_converged": bool(np.all(rec.converged)),
                        "min_singular_measure": float(np.nanmin(rec.singular_measure)),
                        "det_sign_changes": int(len(ch)),
                        "any_singular": bool(np.any(rec.singular)),
                        "l1_singular_mm": l_sing,
                        "radius_singular_mm": r_sing,
                        "Z_f_singular_mm": z_sing,
                    }
                )
    return pd.DataFrame(rows)


def ellipses(p: dict) -> pd.DataFrame:
    """Elastic-approach contact ellipse (seed 000 eq 5.14-5.17, Litvin) at the pitch point of the
    mid-face for the ideal pair: pinion (N = n_teeth) convex Sigma_2R and gear (N = ellipse_n_gear)
    concave flank, both from the same hob; at mid-face both principal frames share e_s || Z_f, so
    the relative curvatures are k_q(1) + |k_q(2)|-type sums (profile) and differences (trace).
    Informative only: Fig 5.7's contact point and R_cg are not stated (claims owned by hobcut_tca)."""
    rows = []
    for a_deg in p["ellipse_pressure_angles_deg"]:
        h = hob(p, pressure_angle_deg=a_deg)
        for Rcp, Rcg in p["ellipse_pairs"]:
            pin = GeneratedGear(hob=h, n_teeth=p["n_teeth"], R_c_mm=Rcp, side=1, arc_centre=-1, tol=solve_tol(p, Rcp))
            gr = GeneratedGear(
                hob=h, n_teeth=p["ellipse_n_gear"], R_c_mm=Rcg, side=1, arc_centre=1, tol=solve_tol(p, Rcg)
            )
            lp = pin.l_at_radius(0.5 * p["module_mm"] * p["n_teeth"]).x[0, 0]
            lg = gr.l_at_radius(0.5 * p["module_mm"] * p["ellipse_n_gear"]).x[0, 0]
            c1 = pin.curvatures(np.array([lp]))
            c2 = gr.curvatures(np.array([lg]))
            if not (c1.result.converged[0] and c2.result.converged[0]):
                raise RuntimeError(f"pitch-point solve failed for the ellipse pair {Rcp}/{Rcg}, {a_deg} deg")
            # curvatures w.r.t. the outward normal of each tooth
            s1 = np.sign(np.sum(c1.normal[0] * c1.normal_out[0]))
            s2 = np.sign(np.sum(c2.normal[0] * c2.normal_out[0]))
            ks1, kq1 = s1 * c1.k_s[0], s1 * c1.k_q[0]
            ks2, kq2 = s2 * c2.k_s[0], s2 * c2.k_q[0]
            # relative curvature (both w.r.t. outward normals, opposite at contact): -(II_1 + II_2)
            kap_trace = -(ks1 + ks2)
            kap_prof = -(kq1 + kq2)
            line = abs(kap_trace) <= 1e-12 * abs(kap_prof)  # identical trace curvatures: line contact
            ok = kap_trace > 0 and kap_prof > 0 and not line
            e = (
                elastic_ellipse_from_relative(max(kap_prof, kap_trace), min(kap_prof, kap_trace), p["ellipse_delta_mm"])
                if ok
                else None
            )
            rows.append(
                {
                    "pressure_angle_deg": a_deg,
                    "R_cp_mm": Rcp,
                    "R_cg_mm": Rcg,
                    "l_pinion_mm": lp,
                    "l_gear_mm": lg,
                    "k_s_pinion_out_per_mm": ks1,
                    "k_q_pinion_out_per_mm": kq1,
                    "k_s_gear_out_per_mm": ks2,
                    "k_q_gear_out_per_mm": kq2,
                    "kappa_trace_per_mm": kap_trace,
                    "kappa_profile_per_mm": kap_prof,
                    "a_over_b": float(np.sqrt(kap_prof / kap_trace)) if ok else np.nan,
                    "major_axis_2a_mm": float(2 * np.max([e.a, e.b])) if ok else np.nan,
                    "minor_axis_2b_mm": float(2 * np.min([e.a, e.b])) if ok else np.nan,
                    "delta_mm": p["ellipse_delta_mm"],
                    "contact": "line (trace curvatures equal)" if line else ("point" if ok else "no ellipse"),
                }
            )
    return pd.DataFrame(rows)


def conventions(p: dict) -> pd.DataFrame:
    """The conventions of the tables (tip and pitch l_1, hob data, frames, signs), as computed."""
    grid, tip = l1_grid(p)
    g = gear(p, "R", p["R_c_small_mm"])
    return pd.DataFrame(
        [
            {
                "item": "tip_l1_mm",
                "value": f"{grid[0]:.10f}",
                "note": f"l at r = {p['tip_radius_mm']} mm (Newton residual {tip.residual[0]:.1e})",
            },
            {"item": "pitch_l1_mm", "value": f"{pitch_l(p):.10f}", "note": "l at the pitch radius (mid-face)"},
            {
                "item": "lead_angle_deg",
                "value": f"{np.degrees(g.hob.lead_angle_rad):.6f}",
                "note": "asin(m / (2 r_h)); Table 5.1 prints 2.866",
            },
            {
                "item": "apex_radius_mm",
                "value": f"{g.hob.apex_radius_mm:.6f}",
                "note": "r_t = r_h - (pi m / 4) / tan(alpha_n)",
            },
            {"item": "lead_per_rad_mm", "value": f"{g.hob.lead_per_rad_mm:.8f}", "note": "P_1 = m / (2 cos lambda)"},
            {
                "item": "frame",
                "value": "S_f = S_2 turned by pi/N about Z",
                "note": "X_f = tooth centre line; Sigma_2R on +Y_f",
            },
            {
                "item": "curvature_sign",
                "value": "hob normal unit(r_l x r_phi) (eq 4.41)",
                "note": "into the tooth on Sigma_2R, out of it on Sigma_2L",
            },
            {
                "item": "direction_orientation",
                "value": "e_s.Z_f > 0; e_q = n_out x e_s",
                "note": "read off the printed tables",
            },
            {"item": "arc_centre", "value": "-1", "note": "upper-sign thread -> convex Sigma_2R"},
            {"item": "hob_variant", "value": "axial (true ZA)", "note": "eq 4.40 without beta in the profile terms"},
            {
                "item": "l1_rows",
                "value": f"{p['n_rows']} equal steps tip .. {p['l1_end_mm']}",
                "note": f"printed to {p['l1_printed_decimals']} decimals",
            },
        ]
    )


def _job(fn, name):
    def compute(settings, design):
        return {name: fn(merged(settings, design))}

    compute.__name__ = compute.__qualname__ = name
    compute.__doc__ = fn.__doc__
    return compute


def _table_job(tab, name):
    def compute(settings, design):
        return {name: curvature_table(merged(settings, design), tab)}

    compute.__name__ = compute.__qualname__ = name
    return compute


_TABLE_NAMES = {f"curvature_table_{t.replace('.', '_')}": t for t in TABLES}


JOBS = {
    **{
        name: Job(_table_job(tab, name), {name: f"hobcut_curvature/{name}.csv"}, f"Table {tab} alone")
        for name, tab in _TABLE_NAMES.items()
    },
    **{
        name: Job(
            _job(fn, name),
            {name: f"hobcut_curvature/{name}.csv"},
            fn.__doc__,
            priority,
        )
        for name, fn, priority in (  # priority: about the seconds of the long jobs (.._face.Job)
            ("curvature_detail", detail, 4),
            ("conventions", conventions, 4),
            ("assignment", assignment, 0),
            ("variants", variants, 0),
            ("face", face, 0),
            ("rc_sweep", rc_sweep, 0),
            ("undercut", undercut, 2),
            ("ellipses", ellipses, 3),
        )
    },
}
