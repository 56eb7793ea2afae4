"""The analyses behind ``gearrep tca``, ``curvature`` and ``sweep`` on a checked design (pure: tables
in, tables out; no files). Every table is a pandas DataFrame with the unit in each column name.

TCA route per family: involute pairs use :func:`gearrep.meshing.meshing_cycle` (engagement limits
solved exactly, contact ratio, TE envelope; line contact of an aligned unmodified pair is traced in
the mid-face section v1 = 0). Novikov-Wildhaber and CATT pairs are solved with the conventional
formulation on a grid of pinion angles (the starts of their replications); their engagement
interval is where the contact lies on the face width (Novikov) or inside the tip circles on the
middle section (CATT, closed form of :func:`gearrep.surfaces.catt.path_limits`), and
the TE over the meshing cycle is the upper envelope of the neighbouring tooth pairs
(:func:`gearrep.meshing.pair_te_curves`, :func:`gearrep.meshing.upper_envelope`) in the drive sense.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from ..solve import Status
from ..units import ARCSEC

__all__ = [
    "contact_at",
    "tca_tables",
    "curvature_table",
    "flank_grid",
    "te_metrics",
    "te_envelope",
    "cycle_summary",
    "curvature_frame",
    "cloud",
    "sweep_point",
    "solves_per_point",
    "PARAM_NAMES",
    "SOLVE_COLUMNS",
    "failed_rows_nan",
]

#: the columns of a contact-path table that describe the solve, not the contact: kept in a row
#: whose status is not converged (every other column is NaN there, :func:`failed_rows_nan`)
SOLVE_COLUMNS = ("phi1_rad", "status", "residual", "iterations", "tangencies_found", "jacobian_cond")


def failed_rows_nan(path: pd.DataFrame) -> pd.DataFrame:
    """``path`` (a contact-path table) with every column but :data:`SOLVE_COLUMNS` NaN in the rows
    whose status is not ``converged``: a failed solve's last iterate is not a contact, nor is
    anything derived from it."""
    bad = (path["status"] != "converged").to_numpy()
    if not bad.any():
        return path
    out = path.copy()
    for col in out.columns:
        if col not in SOLVE_COLUMNS:
            out[col] = out[col].where(~bad)
    return out


#: names (with units) of the two flank parameters of each family
PARAM_NAMES = {
    "involute": ("radius_mm", "axial_mm"),
    "novikov": ("rack_u_mm", "rack_theta_mm"),
    "catt": ("theta_rad", "phi_rad"),
    "hobbed_curvilinear": ("hob_l_mm", "swivel_psi_rad"),
}


def _novikov_mask(d, c):
    """Novikov contacts beyond the face width get status OFF_FLANK (1e-9 relative: the engagement
    limits themselves are on the face edges)."""
    half = 0.5 * d.values["face_width_mm"] * (1 + 1e-9)
    z = np.where(c.converged, c.position[:, 2], np.nan)
    st = c.status.copy()
    st[c.converged & ~(np.abs(z) <= half)] = Status.OFF_FLANK
    return type(c)(**{**c.__dict__, "status": st}).failed_as_nan()


def _catt_mask(d, c):
    """CATT contacts outside the true flank boundaries (the solve bounds are a box around them) get
    status OFF_FLANK."""
    ok = c.converged
    inside = np.zeros(len(c), bool)
    if ok.any():
        inside[ok] = np.asarray(d.pair.flank1.contains(c.u1[ok], c.v1[ok]), bool) & np.asarray(
            d.pair.flank2.contains(c.u2[ok], c.v2[ok]), bool
        )
    st = c.status.copy()
    st[ok & ~inside] = Status.OFF_FLANK
    return type(c)(**{**c.__dict__, "status": st}).failed_as_nan()


def contact_at(d, phi1, quick: bool = False, face: bool = True):
    """Contact points of design ``d`` at pinion angles ``phi1`` [rad] (one independent solve each,
    from the family's start); returns (ContactPoints, line_contact). ``quick``: Novikov pairs get
    the plain Newton solve only (no damped retry); ``face=False``: Novikov contacts beyond the face
    width are kept (the helical tooth surface extended along its helices)."""
    from ..tca import solve_contact

    s = d.analysis
    phi1 = np.asarray(phi1, float)
    with np.errstate(all="ignore"):
        if d.family == "involute":
            c = solve_contact(d.pair, phi1, tol=s["tol"], maxiter=s["maxiter"])
            if np.any(c.status == Status.SINGULAR) or d.line_contact:
                return solve_contact(d.pair, phi1, v1=0.0, tol=s["tol"], maxiter=s["maxiter"]), True
            return c, False
        if d.family == "catt":
            from ..surfaces.catt import solve_cycle

            prm = {"start_offset_mm": 0.5 * d.values["module_mm"], "tol": s["tol"], "maxiter": s["maxiter"]}
            return _catt_mask(d, solve_cycle(d.mesh, phi1, prm)), False
        from ..surfaces.novikov import aligned_start

        # plain Newton from the aligned contact first (7 iterations where the damped one takes ~20
        # under a shaft-angle error, same root); the rows it misses get the damped solve
        start = aligned_start(d.pair, phi1)
        kw = dict(formulation="conventional", tol=s["tol"], maxiter=s["maxiter"])
        c = solve_contact(d.pair, phi1, start, damped=False, **kw)
        bad = np.flatnonzero(~c.converged)
        if len(bad) and not quick:
            c2 = solve_contact(d.pair, phi1[bad], start[bad], **kw)
            rows = np.arange(len(c))
            rows[bad] = len(c) + np.arange(len(bad))
            c = type(c).concatenate([c, c2]).take(rows)
        return (_novikov_mask(d, c) if face else c), False


def _drive_sign(pair, c) -> float:
    """+1 if member 1's flank moves along its outward normal as phi1 grows (it pushes member 2)."""
    ok = np.flatnonzero(c.converged)
    if len(ok) == 0:
        return 1.0
    i = ok[np.argmin(np.abs(c.phi1[ok]))]
    p, n = c.position[i], c.normal[i]
    return 1.0 if (-p[1] * n[0] + p[0] * n[1]) >= 0 else -1.0


def _engagement(d) -> tuple[float, float]:
    """Engagement limits (phi_1B, phi_1E) [rad] of one tooth pair of a non-hobbed design."""
    p1 = 2.0 * np.pi / d.pair.n1
    if d.family == "catt":
        from ..surfaces.catt import path_limits

        lim = path_limits(d.mesh)
        return lim["phi1_lo"], lim["phi1_hi"]
    if d.family == "involute":
        return involute_limits(d)
    # Novikov: the contact runs along the helix, z(phi1) linear; probed near phi1 = 0 on the
    # extended surface, the engagement is where z crosses the face edges
    probe = np.array([-0.25, 0.0, 0.25]) * p1
    c, _ = contact_at(d, probe, face=False)
    ok = c.converged
    if ok.sum() < 2:
        raise ValueError("fewer than two contact points near phi1 = 0: no path of contact to follow")
    k, z0 = np.polyfit(c.phi1[ok], c.position[ok, 2], 1)
    half = 0.5 * d.values["face_width_mm"]
    return tuple(sorted(((-half - z0) / k, (half - z0) / k)))


def involute_limits(d) -> tuple[float, float]:
    """Engagement limits (phi_1B, phi_1E) [rad] of an involute design: the angles at which the
    contact reaches a flank boundary, solved exactly (:func:`gearrep.meshing.engagement_limits`,
    the same solve as ``gearrep tca``'s :func:`gearrep.meshing.meshing_cycle`); the contact ratio
    is then :func:`gearrep.meshing.contact_ratio` of these, whatever the number of points."""
    from ..meshing import engagement_limits

    with np.errstate(all="ignore"):
        b, e = engagement_limits(d.pair, v1=0.0 if d.line_contact else None, tol=d.analysis["tol"])
    return b.phi1, e.phi1


def iso_contact_ratios(d) -> dict:
    """The ISO-style contact ratios of the nominal involute pair (ISO 21771 / ISO 6336-1 definitions,
    no modification or misalignment): transverse eps_alpha = (length of the path of contact in the
    transverse section) / (transverse base pitch), overlap eps_beta = b sin(beta) / (pi m_n) and total
    eps_gamma = eps_alpha + eps_beta; NaN for families whose flanks are not involute helicoids."""
    names = ("transverse_contact_ratio_iso", "overlap_ratio_iso", "total_contact_ratio_iso")
    g1 = getattr(getattr(d.pair, "flank1", None), "gear", None)
    g2 = getattr(getattr(d.pair, "flank2", None), "gear", None)
    if g1 is None or g2 is None or not hasattr(g1, "base_pitch"):
        return dict.fromkeys(names, float("nan"))
    from ..meshing import contact_ratio_closed_form

    eps_a = float(contact_ratio_closed_form(g1.r_a, g1.r_b, g2.r_a, g2.r_b, d.pair.centre_distance, g1.base_pitch))
    eps_b = float(g1.face_width * abs(np.sin(g1.helix_angle)) / (np.pi * g1.module))
    return dict(zip(names, (eps_a, eps_b, eps_a + eps_b)))


def te_envelope(phi, te, drive, pitch, begin, n):
    """(``n`` angles over one meshing cycle from ``begin``, TE transmitted there, leading tooth pair
    -3..3): the envelope of the neighbouring pairs' curves (:func:`gearrep.meshing.pair_te_curves`,
    :func:`gearrep.meshing.upper_envelope`) of one pair's TE ``te`` at ``phi`` [rad], in the drive
    sense ``drive`` (+1: the most advanced member 2, -1: the least); NaN with fewer than 2 samples."""
    from .. import meshing

    at = np.linspace(begin, begin + pitch, int(n))
    if np.sum(np.isfinite(te)) < 2:
        return at, np.full(len(at), np.nan), np.zeros(len(at), int)
    curves = meshing.pair_te_curves(phi, drive * te, pitch, at, pairs=range(-3, 4))
    env, lead = meshing.upper_envelope(curves)
    return at, drive * env, lead - 3


def cycle_summary(begin, end, env, drive) -> dict:
    """Summary entries of a meshing cycle: engagement limits [rad], TE peak to peak of the envelope
    ``env`` [rad] and the drive sense."""
    return {
        "phi1_begin_rad": float(begin),
        "phi1_end_rad": float(end),
        "te_peak_to_peak_arcsec": float((np.nanmax(env) - np.nanmin(env)) / ARCSEC)
        if np.any(np.isfinite(env))
        else float("nan"),
        "drive_sense": "max" if drive > 0 else "min",
    }


def te_metrics(d, n_phi: int):
    """(path ContactPoints on the engagement interval, TE envelope table, summary dict) of a
    non-hobbed pair (``gearrep sweep``; ``gearrep tca`` of Novikov and CATT pairs); the path has
    ``n_phi`` positions. The engagement limits and the contact ratio are those of ``gearrep tca``."""
    p1 = 2.0 * np.pi / d.pair.n1
    b, e = _engagement(d)
    solves = solves_per_point(d.family, int(n_phi))
    phi = np.linspace(b, e, int(n_phi))
    c, _ = contact_at(d, phi)
    te = np.where(c.converged & (phi >= b - 1e-12) & (phi <= e + 1e-12), c.te, np.nan)
    drive = _drive_sign(d.pair, c)
    from ..meshing import contact_ratio

    mc = float(contact_ratio(b, e, d.pair.n1))
    at, env, lead = te_envelope(phi, te, drive, p1, b, n_phi)
    table = pd.DataFrame({"phi1_rad": at, "te_arcsec": env / ARCSEC, "tooth_pair": lead})
    summary = {
        "contact_ratio": float(mc),
        "contact_ratio_method": {
            "catt": "middle-section closed form",
            "novikov": "face crossings of the path",
            "involute": "engagement limits solved on the flank boundaries",
        }[d.family],
        **cycle_summary(b, e, env, drive),
        "solves": solves,
    }
    return c, table, summary


def _path_table(d, c, delta) -> pd.DataFrame:
    from ..tca import contact_ellipse

    pu, pv = PARAM_NAMES[d.family]
    with np.errstate(all="ignore"):
        el = contact_ellipse(d.pair, c, delta)
    r = np.hypot(c.position[:, 0], c.position[:, 1])
    # line contact (traced in a fixed section; relative curvature zero to rounding): no ellipse
    ell = np.asarray(el.elliptic, bool) & (not d.line_contact)
    el = el._replace(
        a=np.where(ell, el.a, np.nan),
        b=np.where(ell, el.b, np.nan),
        area=np.where(ell, el.area, np.nan),
        major_axis=np.where(ell[:, None], el.major_axis, np.nan),
    )
    from .edges import cut_at_edges

    cut = cut_at_edges(d.pair, d.values["face_width_mm"], c.position, c.normal, el.major_axis, el.a, el.b)
    return pd.DataFrame(
        {
            "phi1_rad": c.phi1,
            "phi2_rad": c.phi2,
            "te_arcsec": np.where(c.converged, c.te / ARCSEC, np.nan),
            "status": c.status_name,
            "residual": c.residual,
            "iterations": c.iterations,
            f"pinion_{pu}": c.u1,
            f"pinion_{pv}": c.v1,
            f"gear_{pu}": c.u2,
            f"gear_{pv}": c.v2,
            "x_mm": c.position[:, 0],
            "y_mm": c.position[:, 1],
            "z_mm": c.position[:, 2],
            "radius_on_pinion_mm": r,
            "normal_x": c.normal[:, 0],
            "normal_y": c.normal[:, 1],
            "normal_z": c.normal[:, 2],
            "ellipse_semi_major_mm": el.a,
            "ellipse_semi_minor_mm": el.b,
            "ellipse_area_mm2": el.area,
            "ellipse_major_x": el.major_axis[:, 0],
            "ellipse_major_y": el.major_axis[:, 1],
            "ellipse_major_z": el.major_axis[:, 2],
            "ellipse_major_from_mm": cut.lo,
            "ellipse_major_to_mm": cut.hi,
            "ellipse_area_on_flank_mm2": cut.area,
            "edge_contact": cut.edge,
        }
    )


def tca_tables(d, progress=None) -> dict:
    """TCA of design ``d`` over its meshing cycle: tables ``contact_path`` (contact points, TE,
    ellipses), ``te_cycle`` (TE envelope over one cycle) and ``summary`` (one row)."""
    s = d.analysis
    n = s["n_points"]
    if progress:
        progress("meshing cycle", 0.1)
    if d.family == "involute":
        from ..meshing import meshing_cycle

        with np.errstate(all="ignore"):
            cyc = meshing_cycle(d.pair, v1=0.0 if d.line_contact else None, n_points=n, tol=s["tol"])
        c = cyc.path
        te = pd.DataFrame({"phi1_rad": cyc.phi1, "te_arcsec": cyc.te / ARCSEC, "tooth_pair": cyc.pair_index})
        summary = {
            "contact_ratio": cyc.contact_ratio,
            "contact_ratio_method": "engagement limits solved on the flank boundaries",
            "phi1_begin_rad": cyc.begin.phi1,
            "phi1_end_rad": cyc.end.phi1,
            "te_peak_to_peak_arcsec": cyc.te_peak_to_peak / ARCSEC,
            "drive_sense": "max",
        }
    elif d.family == "hobbed_curvilinear":
        from . import hobbed

        path, te, summary, extra = hobbed.tca(d, progress)
    else:
        c, te, summary = te_metrics(d, n)
    if progress:
        progress("contact ellipses", 0.6)
    if d.family != "hobbed_curvilinear":
        path, extra = _path_table(d, c, s["elastic_approach_mm"]), {}
    path = failed_rows_nan(path)
    ok = path["status"] == "converged"
    summary = {
        "design": d.name,
        "family": d.family,
        "line_contact": d.line_contact,
        **summary,
        **iso_contact_ratios(d),
        "points_converged": int(ok.sum()),
        "points_total": len(path),
        "max_residual_mm": float(path.loc[ok, "residual"].max()) if ok.any() else float("nan"),
        "max_ellipse_semi_major_mm": float(path["ellipse_semi_major_mm"].max())
        if path["ellipse_semi_major_mm"].notna().any()
        else float("nan"),
        "transfer_kind": getattr(locals().get("cyc"), "transfer_kind", "envelope of sampled pairs"),
        "edge_contact_positions": int((path["edge_contact"].fillna("") != "").sum())
        if "edge_contact" in path
        else float("nan"),
    }
    return {"contact_path": path, "te_cycle": te, "summary": pd.DataFrame([summary]), **extra}


def flank_grid(d, member: int, n_u: int, n_v: int):
    """Parameters (u, v) of an n_u x n_v grid over member ``member``'s flank, kept where the flank
    exists (CATT: the true boundaries; Novikov: within the face width)."""
    pair = d.pair
    lo, hi = (pair.lower1, pair.upper1) if member == 1 else (pair.lower2, pair.upper2)
    flank = pair.flank1 if member == 1 else pair.flank2
    if d.family == "involute":  # the active profile: from where the mating tip reaches (not the base-circle cusp)
        lo = np.array([_active_profile_start(d)[member - 1], lo[1]])
    u, v = np.meshgrid(np.linspace(lo[0], hi[0], n_u), np.linspace(lo[1], hi[1], n_v), indexing="ij")
    u, v = u.ravel(), v.ravel()
    if d.family == "catt":
        keep = np.asarray(flank.contains(u, v), bool)
        u, v = u[keep], v[keep]
    elif d.family == "novikov":
        u, v = u * (1.0 / 1.2) * 0.95, v * (1.0 / 1.5)  # the active height and the face width
    return flank, u, v


def _active_profile_start(d) -> tuple[float, float]:
    """Radii [mm] at which the active profiles of an involute pair begin (pinion, gear): where the
    mating member's tip circle cuts the line of action, sqrt(r_b^2 + (sqrt(a^2 - (r_b1 + r_b2)^2)
    - sqrt(r_a'^2 - r_b'^2))^2) (a: the operating centre distance), and not below the start of the
    involute flank."""
    pair, m = d.pair, d.values["misalignment"]
    g1, g2 = pair.flank1.gear, pair.flank2.gear
    a = float(np.hypot(g1.r_p + g2.r_p + m["d_E_mm"], m["d_H_mm"]))
    loa = np.sqrt(max(a**2 - (g1.r_b + g2.r_b) ** 2, 0.0))
    out = []
    for g, other, lo in ((g1, g2, pair.lower1[0]), (g2, g1, pair.lower2[0])):
        t = max(loa - np.sqrt(other.r_a**2 - other.r_b**2), 0.0)
        out.append(max(float(np.hypot(g.r_b, t)), float(lo)))
    return out[0], out[1]


def curvature_frame(member: str, names, u, v, points, pc) -> pd.DataFrame:
    """The curvature table rows of one member: its parameters ``u``, ``v`` (columns ``names``),
    points [mm] and :class:`gearrep.curvature.PrincipalCurvatures` ``pc`` (k [1/mm], e1, e2, normal)."""
    return pd.DataFrame(
        {
            "member": member,
            names[0]: u,
            names[1]: v,
            **{f"{a}_mm": points[:, i] for i, a in enumerate("xyz")},
            "k1_per_mm": pc.k1,
            "k2_per_mm": pc.k2,
            **{f"{vec}_{a}": getattr(pc, vec)[:, i] for vec in ("e1", "e2", "normal") for i, a in enumerate("xyz")},
        }
    )


def curvature_table(d) -> pd.DataFrame:
    """Principal curvatures [1/mm] and directions on a grid over both flanks (each in its own frame;
    curvature positive where the surface bends toward its outward normal)."""
    from ..curvature import principal_curvatures, with_opposite_normal

    if d.family == "hobbed_curvilinear":
        from . import hobbed

        return hobbed.curvature_table(d)
    n_u, n_v = d.analysis["curvature_grid"][:2]
    pu, pv = PARAM_NAMES[d.family]
    rows = []
    for member, name in ((1, "pinion"), (2, "gear")):
        flank, u, v = flank_grid(d, member, n_u, n_v)
        sign = d.pair.sign1 if member == 1 else d.pair.sign2
        with np.errstate(all="ignore"):
            P = flank.evaluate(u, v)
            pc = principal_curvatures(P)
            if sign < 0:
                pc = with_opposite_normal(pc)
        rows.append(curvature_frame(name, (pu, pv), u, v, P.r, pc))
    return pd.concat(rows, ignore_index=True)


def flank_cloud(d, member: int):
    """Point cloud of member ``member``'s flank in its own frame: (points (n_u, n_v, 3) with NaN where
    the grid leaves the flank, outward unit normals, table)."""
    if d.family == "hobbed_curvilinear":
        from . import hobbed

        return hobbed.flank_cloud(d, member)
    n_u, n_v = d.analysis["flank_grid"][:2]
    pair = d.pair
    lo, hi = (pair.lower1, pair.upper1) if member == 1 else (pair.lower2, pair.upper2)
    flank = pair.flank1 if member == 1 else pair.flank2
    sign = pair.sign1 if member == 1 else pair.sign2
    _, u, v = flank_grid(d, member, n_u, n_v)
    if d.family == "catt":  # keep the full grid shape, NaN outside the flank
        uu, vv = np.meshgrid(np.linspace(lo[0], hi[0], n_u), np.linspace(lo[1], hi[1], n_v), indexing="ij")
        uu, vv = uu.ravel(), vv.ravel()
        keep = np.asarray(flank.contains(uu, vv), bool)
        u, v = uu, vv
    else:
        keep = np.ones(len(u), bool)
    with np.errstate(all="ignore"):
        P = flank.evaluate(u, v)
        nrm = sign * P.normal
    return cloud(PARAM_NAMES[d.family], u, v, P.r, nrm, keep, n_u, n_v)


def cloud(names, u, v, points, normals, keep, n_u: int, n_v: int):
    """(points (n_u, n_v, 3) and normals, NaN where not ``keep``; the table of the kept points with
    their parameters ``u``, ``v`` under the column ``names``)."""
    pts = np.where(keep[:, None], points, np.nan)
    nrm = np.where(keep[:, None], normals, np.nan)
    table = pd.DataFrame(
        {
            names[0]: u[keep],
            names[1]: v[keep],
            **{f"{a}_mm": pts[keep, i] for i, a in enumerate("xyz")},
            **{f"normal_{a}": nrm[keep, i] for i, a in enumerate("xyz")},
        }
    )
    return pts.reshape(n_u, n_v, 3), nrm.reshape(n_u, n_v, 3), table


def solves_per_point(family: str, n_phi: int) -> int:
    """Contact solves of one sweep point (:func:`te_metrics`): the engagement interval (n_phi) and
    the solves that find it (involute: about 40, the walk of :func:`gearrep.meshing.engagement_limits`
    in steps of a tenth of the angular pitch through a contact ratio up to about 3 and the boundary
    solves; Novikov: 3; CATT: none, closed form); hobbed_curvilinear pairs: an upper bound of the 9 x 9 solves of the window and the
    path (:func:`gearrep.cli.hobbed.path_solves`)."""
    if family == "hobbed_curvilinear":  # the largest window (60 deg each side, 4 teeth or fewer)
        from .hobbed import path_solves

        return path_solves(4, n_phi)
    return {"involute": n_phi + 40, "novikov": n_phi + 3, "catt": n_phi}[family]


def sweep_point(d, n_phi: int) -> dict:
    """The metrics of one sweep point: TE over the meshing cycle (envelope of the sampled pairs),
    contact ratio, largest contact-ellipse semi-axis, convergence (``n_phi`` contact solves)."""
    if d.family == "hobbed_curvilinear":
        from .hobbed import tca

        path, _, summary, _ = tca(d, n_points=n_phi, with_ke=False)
        ok = path["status"] == "converged"
        a = path["ellipse_semi_major_mm"]
        return {
            "contact_ratio": summary["contact_ratio"],
            "te_peak_to_peak_arcsec": summary["te_peak_to_peak_arcsec"],
            "max_ellipse_semi_major_mm": float(a.max()) if a.notna().any() else float("nan"),
            "solves": summary["solves"],
            "converged": int(ok.sum()),
            "max_residual_mm": float(path.loc[ok, "residual"].max()) if ok.any() else float("nan"),
        }
    c, _, summary = te_metrics(d, n_phi)
    with np.errstate(all="ignore"):
        from ..tca import contact_ellipse

        el = contact_ellipse(d.pair, c, d.analysis["elastic_approach_mm"])
    ok = c.converged
    a = np.where(np.asarray(el.elliptic, bool) & (not d.line_contact), el.a, np.nan)
    return {
        "contact_ratio": summary["contact_ratio"],
        "te_peak_to_peak_arcsec": summary["te_peak_to_peak_arcsec"],
        "max_ellipse_semi_major_mm": float(np.nanmax(a)) if np.isfinite(a).any() else float("nan"),
        "solves": summary["solves"],
        "converged": int(ok.sum()),
        "max_residual_mm": float(c.residual[ok].max()) if ok.any() else float("nan"),
    }
