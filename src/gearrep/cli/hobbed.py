"""The ``hobbed_curvilinear`` family of the ``gearrep`` command: curvilinear-tooth cylindrical gears
cut by a ZA worm hob (seed 000), analysed by the library's TCA of two-parameter envelopes.

This module is an adapter, not a second TCA, and uses only the library (:mod:`gearrep.hobbed`,
the replication seed 000 ch. 5 being another user of it): the pair is built by
:func:`gearrep.hobbed.make_pair`, the contact at phi1 = 0 by :func:`gearrep.hobbed.continue_to`
(continuation from the ideal pair, then the physical contact among the tangencies found across
the face), paths by :func:`gearrep.tca_envelope.trace_path` and
:func:`gearrep.hobbed.physical_contact`, the engagement limits by
:func:`gearrep.hobbed.tip_crossing` (where the contact reaches each tip circle, r_p + m), the
contact ellipses by :func:`gearrep.hobbed.elastic_ellipses` (curvature method, eq 5.14-5.17) and
the KE table by :func:`gearrep.hobbed.ke_table` (eq 5.12, zero at phi1 = 0). What is added
here is the mapping of those results onto the command's tables, the check that the contact at
phi1 = 0 lies on both flanks, and the parameter grid over a flank (hob parameter l from the tip
circle to the hob's working depth, swivel psi between the face edges) for the curvature table
and the point clouds.

Frames: contact points in the fixed frame S_f of eq 5.1-5.4 (pinion axis along z for an aligned
pinion); flank grids and curvatures in each member's tooth frame (tooth centred on X, Z = axis).
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd

from ..settings import SettingError
from ..solve import Status
from ..units import ARCSEC

__all__ = [
    "PARAMS",
    "N_STARTS",
    "window_points",
    "path_solves",
    "start",
    "check_contact",
    "check_ke_grid",
    "tca",
    "flank_params",
    "curvature_table",
    "flank_cloud",
]

#: names (with units) of the two flank parameters: the hob profile parameter l and the swivel psi
PARAMS = ("hob_l_mm", "swivel_psi_rad")


def _half_window(n_teeth: int) -> float:
    """Half-width [rad] of the pinion-angle window searched for the tip crossings: two angular
    pitches of the pinion (a contact ratio below 2 on each side of phi1 = 0), at most 60 deg."""
    return min(2.0 * 2.0 * np.pi / n_teeth, np.radians(60.0))


def start(values, gears, assembly, tol, steps):
    """(pair, physical contact at phi1 = 0) of ``gears`` (PairDesign) under ``assembly``, or
    (None, reason) when the continuation from the ideal pair fails."""
    from ..tca import hobbed_continue_to as continue_to

    try:
        with np.errstate(all="ignore"):
            return continue_to(
                gears,
                values["pinion"]["cutter_radius_mm"],
                values["gear"]["cutter_radius_mm"],
                assembly,
                steps=steps,
                tol=tol,
            )
    except (RuntimeError, ValueError, np.linalg.LinAlgError) as e:
        return None, str(e).split(" (status")[0]


def margin(values, pair, sol) -> float:
    """How far [mm] the contact at phi1 = 0 lies inside both flanks: the least of the distances to
    the face edges (|Z| <= B/2 on each member) and to the working-depth band r_p +- m of each
    member (the tip circle and the reach of the mating tip); negative when outside."""
    half, m = 0.5 * values["face_width_mm"], values["module_mm"]
    rp1, rp2 = pair.pinion.r_pitch_mm, pair.gear.r_pitch_mm
    return float(
        min(
            half - abs(sol.Z_p[0]),
            half - abs(sol.Z_g[0]),
            m - abs(sol.radius_p[0] - rp1),
            m - abs(sol.radius_g[0] - rp2),
        )
    )


def check_contact(d) -> None:
    """Solve the contact at phi1 = 0 of the checked design ``d`` (sets ``d.pair`` and ``d.start``);
    refuse (SettingError naming the key) when it is not found or lies off the flanks."""
    from .design import _hob_assembly

    v, s = d.values, d.analysis
    pair, sol = start(v, d.mesh, _hob_assembly(v), s["tol"], s["continuation_steps"])
    ok = pair is not None and bool(sol.converged[0])
    if ok and margin(v, pair, sol) >= 0:
        d.pair, d.start = pair, sol
        return
    if ok:
        state = f"contact at Z_p = {sol.Z_p[0]:.4g} mm, radius {sol.radius_p[0]:.5g} mm on the pinion"
    else:
        state = f"the solve failed: {sol if pair is None else 'not converged'}"
    mis = {k: x for k, x in v["misalignment"].items() if x != 0.0}
    if not mis:
        raise SettingError(
            f"design: no contact on the flanks at phi1 = 0 of the aligned pair ({state}); allowed: a pair whose flanks "
            "meet there (check teeth, module, hob and cutter radii)"
        )
    if len(mis) > 1:
        raise SettingError(
            f"design.misalignment: got {mis!r}; allowed: a misalignment that keeps the contact at phi1 = 0 on the "
            f"flanks ({state})"
        )
    name, x = next(iter(mis.items()))
    limit = _limit(d, name, x, pair, sol if ok else None)
    raise SettingError(
        f"design.misalignment.{name}: got {x!r}; allowed: |{name}| below about {limit:.3g} for this pair (larger "
        f"values move the contact at phi1 = 0 off the flanks: {state})"
    )


def _limit(d, name, x, pair, sol) -> float:
    """Magnitude of misalignment ``name`` at which the contact at phi1 = 0 leaves the flanks: linear
    in the margin between the aligned pair and ``sol`` (the contact moves about linearly with the
    misalignment), or by bisection (4 halvings) where the contact under ``x`` was not found or the
    linear estimate is not inside (0, |x|)."""
    from .design import _hob_assembly, set_dotted

    v, s = d.values, d.analysis

    def contact(t):
        vv = set_dotted(v, f"misalignment.{name}", t * x)
        return start(vv, d.mesh, _hob_assembly(vv), s["tol"], s["continuation_steps"])

    p0, s0 = contact(0.0)
    if p0 is None or not s0.converged[0]:
        return 0.0
    m0 = margin(v, p0, s0)
    if sol is not None:
        est = m0 / (m0 - margin(v, pair, sol))
        if 0.0 < est < 1.0:
            return abs(x) * est
    lo, hi = 0.0, 1.0
    for _ in range(4):
        mid = 0.5 * (lo + hi)
        pm, sm = contact(mid)
        good = pm is not None and sm.converged[0] and margin(v, pm, sm) >= 0
        lo, hi = (mid, hi) if good else (lo, mid)
    return hi * abs(x)


def _ke_grid(s) -> np.ndarray:
    """Pinion angles [rad] of the KE table (:func:`gearrep.hobbed.phi1_grid`)."""
    from ..tca import hobbed_phi1_grid as phi1_grid

    g = s["ke_table"]
    return phi1_grid(g["start_deg"], g["end_deg"], g["step_deg"])


def check_ke_grid(values) -> None:
    """The KE-table grid must hit phi1 = 0 (the table's zero of KE)."""
    g = values["analysis"]["ke_table"]
    a, b, step = g["start_deg"], g["end_deg"], g["step_deg"]
    if step > b - a + 1e-12 or abs(round(-a / step) * step + a) > 1e-9:
        raise SettingError(
            f"design.analysis.ke_table.step_deg: got {step!r}; allowed: a step in (0, {b - a:g}] with the grid from "
            f"start_deg = {a:g} hitting 0 (the table's zero of KE)"
        )


def _path(pair, s0, phi1, tol):
    """The physical contact at the pinion angles ``phi1`` [rad], traced from the contact ``s0``."""
    from ..tca import hobbed_physical_contact as physical_contact
    from ..tca import trace_envelope_path as trace_path

    with np.errstate(all="ignore"):
        return physical_contact(pair, trace_path(pair, s0, phi1, tol=tol), tol=tol)


def _engagement(pair, s0, tol):
    """(phi1_B, phi1_E) [rad]: where the contact reaches the pinion tip and the gear tip (the tip
    crossing nearest phi1 = 0 on the traced window)."""
    from ..tca import hobbed_tip_crossing as tip_crossing

    w = _half_window(pair.pinion.n_teeth)
    n = window_points(pair.pinion.n_teeth)
    grid = np.linspace(-w, w, n)
    path = _path(pair, s0, grid, tol)
    i0 = n // 2
    ok = path.converged
    ends = []
    for member, ra in (("pinion", pair.pinion.r_outside_mm), ("gear", pair.gear.r_outside_mm)):
        g = (path.radius_p if member == "pinion" else path.radius_g) - ra
        found = None
        for direction in (1, -1):  # the crossing nearest phi1 = 0 on either side
            i = i0
            while 0 <= i + direction < n and ok[i + direction]:
                j = i + direction
                if np.sign(g[i]) != np.sign(g[j]):
                    k = min(i, j)
                    if found is None or abs(grid[k] + grid[k + 1]) < abs(sum(found)):
                        found = (grid[k], grid[k + 1], k)
                    break
                i = j
        if found is None:
            raise ValueError(
                f"the contact does not reach the {member} tip circle (r = {ra:g} mm) within +-{np.degrees(w):.4g} deg "
                "of phi1 = 0 on converged points: no engagement interval"
            )
        k = found[2]
        try:
            cross = tip_crossing(pair, path.take([k, k + 1]), member, ra, np.degrees(w), tol)
        except RuntimeError as e:  # a secant step without a converged contact
            raise ValueError(f"the {member} tip crossing was not found: {e}") from None
        ends.append(np.radians(cross["phi1_deg"]))
    return tuple(sorted(ends))


#: starts of the tangency search at each contact (tca_envelope.physical_contact's default)
N_STARTS = 9


def window_points(n_teeth: int) -> int:
    """Pinion angles of the window searched for the tip crossings (steps of at most 2 deg)."""
    return 2 * math.ceil(np.degrees(_half_window(n_teeth)) / 2.0) + 1


def path_solves(n_teeth: int, n_phi: int) -> int:
    """9 x 9 solves of the window and of the path of ``n_phi`` points with its phi1 = 0 row, each
    with its tangency search (1 + N_STARTS per point); the continuation to phi1 = 0 and the secant
    iterations of the two tip crossings (a few each) are not counted."""
    return (1 + N_STARTS) * (window_points(n_teeth) + n_phi + 1)


def tca(d, progress=None, n_points=None, with_ke=True):
    """(contact_path, te_cycle, summary dict, {"ke_table": ...}) of a checked hobbed design
    (``n_points`` path points, default the analysis setting; ``with_ke=False``: no KE table)."""
    from .. import meshing
    from ..tca import envelope_pinion_outward as pinion_outward
    from ..tca import envelope_turn_gap as turn_gap
    from ..tca import hobbed_elastic_ellipses as elastic_ellipses
    from ..tca import ke_table
    from .analysis import cycle_summary, te_envelope

    s, pair, s0 = d.analysis, d.pair, d.start
    tol, n = s["tol"], int(s["n_points"] if n_points is None else n_points)
    b, e = _engagement(pair, s0, tol)
    if progress:
        progress("path of contact", 0.3)
    phi = np.linspace(b, e, n)
    sol = _path(pair, s0, np.r_[phi, 0.0], tol)  # the last row: phi1 = 0, the zero of KE
    phi2_0 = sol.phi2[-1]
    sol = sol.take(np.arange(n))
    # contacts beyond the face edges (a misalignment can carry the path off the face) are not contacts
    half = 0.5 * pair.face_width_mm * (1 + 1e-9)
    off = sol.converged & ~((np.abs(sol.Z_p) <= half) & (np.abs(sol.Z_g) <= half))
    sol.solve.status[off] = int(Status.OFF_FLANK)
    ok = sol.converged
    method = "tip crossings of the path (seed 000 eq 5.13 with the angular pitch)"
    if off.any() and ok.sum() >= 2:
        b, e = float(phi[ok].min()), float(phi[ok].max())
        method = "tip crossings, cut where the path leaves the face (to the grid of the path)"
    ke = np.where(ok, (sol.phi2 - phi2_0) - pair.ratio * sol.phi1, np.nan)
    # the gear rests where no tooth pair interferes: turn_gap < 0 when it turns on (s < 0: the least phi2)
    drive = 1.0 if float(np.nanmedian(np.where(ok, turn_gap(pair, sol, sol.phi2 + 1.0), np.nan))) > 0 else -1.0
    p1 = 2.0 * np.pi / pair.pinion.n_teeth
    at, env, lead = te_envelope(phi, ke, drive, p1, b, n)
    if progress:
        progress("contact ellipses and KE table", 0.6)
    with np.errstate(all="ignore"):
        el, _, _ = elastic_ellipses(pair, sol, s["elastic_approach_mm"])
        normal = pinion_outward(pair, sol)
    ell = np.asarray(el.elliptic, bool) & ok
    pu, pv = PARAMS
    path = pd.DataFrame(
        {
            "phi1_rad": sol.phi1,
            "phi2_rad": sol.phi2,
            "te_arcsec": ke / ARCSEC,
            "status": sol.status_name,
            "residual": sol.solve.residual,
            "iterations": sol.solve.iterations,
            f"pinion_{pu}": sol.x[:, 0],
            f"pinion_{pv}": sol.x[:, 3],
            f"gear_{pu}": sol.x[:, 4],
            f"gear_{pv}": sol.x[:, 7],
            "x_mm": sol.r_f[:, 0],
            "y_mm": sol.r_f[:, 1],
            "z_mm": sol.r_f[:, 2],
            "radius_on_pinion_mm": sol.radius_p,
            "normal_x": normal[:, 0],
            "normal_y": normal[:, 1],
            "normal_z": normal[:, 2],
            "ellipse_semi_major_mm": np.where(ell, el.a, np.nan),
            "ellipse_semi_minor_mm": np.where(ell, el.b, np.nan),
            "ellipse_area_mm2": np.where(ell, el.area, np.nan),
            "ellipse_major_x": np.where(ell, el.major_axis[:, 0], np.nan),
            "ellipse_major_y": np.where(ell, el.major_axis[:, 1], np.nan),
            "ellipse_major_z": np.where(ell, el.major_axis[:, 2], np.nan),
            "pinion_Z_mm": sol.Z_p,
            "gear_Z_mm": sol.Z_g,
            "radius_on_gear_mm": sol.radius_g,
            "tangencies_found": sol.n_tangencies,
            "jacobian_cond": sol.cond,
        }
    )
    te = pd.DataFrame({"phi1_rad": at, "te_arcsec": env / ARCSEC, "tooth_pair": lead})
    summary = {
        "contact_ratio": float(meshing.contact_ratio(b, e, pair.pinion.n_teeth)),
        "contact_ratio_method": method,
        **cycle_summary(b, e, env, drive),
        "te_zero": "KE of seed 000 eq 5.12, zero at phi1 = 0",
        "solves": path_solves(pair.pinion.n_teeth, n),
    }
    if not with_ke:
        return path, te, summary, {}
    ke_sol = _path(pair, s0, _ke_grid(s), tol)
    return path, te, summary, {"ke_table": ke_table(ke_sol, pair.ratio)}


# ----------------------------------------------------------------------------------------------
# flank grids: curvatures and point clouds in each member's tooth frame
# ----------------------------------------------------------------------------------------------
def _member(d, member: int):
    return (d.pair.pinion if member == 1 else d.pair.gear).gear


def _outward_sign(g) -> float:
    """+1 if the hob normal of flank ``g`` points out of the tooth, else -1: taken once, at the hob
    pitch line of the mid-face section (the hob normal keeps its side of the flank; the polar-angle
    test of :meth:`GeneratedGear.outward` fails near the tip at the face edges, where the arc trace
    carries the tooth's centre line away from X)."""
    from ..tca import hob_pitch_l

    pt, n, _ = g.points(hob_pitch_l(g.hob), 0.0)
    return float(np.sign(np.sum(g.outward(pt, n) * n)))


def _psi_at_z(g, l, z, iters: int = 12):
    """Swivel psi (n,) putting the flank point at (l, psi) at axial coordinate Z = ``z`` [mm] (tooth
    frame): secant from psi = 0 (mid-face) and the arc estimate arcsin(z / R_c)."""
    a = np.zeros_like(l)
    b = np.full_like(l, math.asin(max(-1.0, min(1.0, z / g.R_c_mm))))
    fa = g.points(l, a)[0][:, 2] - z
    fb = g.points(l, b)[0][:, 2] - z
    for _ in range(iters):
        with np.errstate(all="ignore"):
            c = np.where(np.abs(fb - fa) > 0, b - fb * (b - a) / (fb - fa), b)
        a, fa = b, fb
        b = c
        fb = g.points(l, b)[0][:, 2] - z
        if np.all(np.abs(fb) < 1e-9):
            break
    return b


def _lowest_contact_radius(d, member: int) -> float:
    """Radius [mm] on member ``member`` reached by the mating tip circle (r_p + m) in the middle
    section, taken as an involute pair at the standard centre distance:
    sqrt(r_b^2 + (a sin alpha - sqrt(r_a'^2 - r_b'^2))^2)."""
    m, alpha = d.values["module_mm"], math.radians(d.values["pressure_angle_deg"])
    r = [0.5 * m * d.values[k]["teeth"] for k in ("pinion", "gear")]
    own, other = (r[0], r[1]) if member == 1 else (r[1], r[0])
    rb, rb_o, ra_o = own * math.cos(alpha), other * math.cos(alpha), other + m
    return math.hypot(rb, (r[0] + r[1]) * math.sin(alpha) - math.sqrt(ra_o**2 - rb_o**2))


def flank_params(d, member: int, n_u: int, n_v: int):
    """(l, psi) of an n_u x n_v grid (ravelled, profile-major) over member ``member``'s active
    flank: l from the tip circle r_p + m down to the lowest contact radius (the reach of the mating
    tip, :func:`_lowest_contact_radius`), both at mid-face; psi at each l from the face edge
    Z = -B/2 to Z = +B/2. Where a radius is not found, l at the hob pitch line -+ m / cos alpha_n."""
    from ..tca import hob_pitch_l

    g = _member(d, member)
    m, half = d.values["module_mm"], 0.5 * d.values["face_width_mm"]
    lp = hob_pitch_l(g.hob)
    dl = m / math.cos(g.hob.pressure_angle_rad)
    with np.errstate(all="ignore"):
        r = g.l_at_radius([g.pitch_radius_mm + m, _lowest_contact_radius(d, member)], l0_mm=lp)
    ok = r.status == Status.CONVERGED
    l_lo = float(r.x[0, 0]) if ok[0] else lp - dl
    l_hi = float(r.x[1, 0]) if ok[1] else lp + dl
    ls = np.linspace(l_lo, l_hi, int(n_u))
    with np.errstate(all="ignore"):
        lo, hi = _psi_at_z(g, ls, -half), _psi_at_z(g, ls, half)
    t = np.linspace(0.0, 1.0, int(n_v))
    psi = lo[:, None] + (hi - lo)[:, None] * t[None, :]
    return np.repeat(ls, int(n_v)), psi.ravel()


def curvature_table(d) -> pd.DataFrame:
    """Principal curvatures [1/mm] and directions of both flanks on the curvature grid (the
    two-parameter-envelope relations, :func:`gearrep.curvature_relations.generated_curvatures`),
    each in its tooth frame, positive where the flank bends toward its outward normal."""
    from ..curvature import PrincipalCurvatures, with_opposite_normal
    from .analysis import curvature_frame

    n_u, n_v = d.analysis["curvature_grid"][:2]
    rows = []
    for member, name in ((1, "pinion"), (2, "gear")):
        g = _member(d, member)
        l, psi = flank_params(d, member, n_u, n_v)
        with np.errstate(all="ignore"):
            fc = g.curvatures(l, psi)
        R = g.to_tooth_frame
        gc = fc.generated
        pc = PrincipalCurvatures(gc.k1, gc.k2, gc.e1 @ R.T, gc.e2 @ R.T, gc.normal @ R.T)
        if _outward_sign(g) < 0:
            pc = with_opposite_normal(pc)
        bad = ~fc.result.converged
        pc = pc._replace(k1=np.where(bad, np.nan, pc.k1), k2=np.where(bad, np.nan, pc.k2))
        rows.append(curvature_frame(name, PARAMS, l, psi, fc.point, pc))
    return pd.concat(rows, ignore_index=True)


def flank_cloud(d, member: int):
    """Point cloud of member ``member``'s working flank in its tooth frame: (points (n_u, n_v, 3),
    outward unit normals, table); NaN where the envelope solve did not converge."""
    from .analysis import cloud

    n_u, n_v = d.analysis["flank_grid"][:2]
    g = _member(d, member)
    l, psi = flank_params(d, member, n_u, n_v)
    with np.errstate(all="ignore"):
        pts, nrm, rec = g.points(l, psi)
        nrm = _outward_sign(g) * nrm
    return cloud(PARAMS, l, psi, pts, nrm, np.asarray(rec.converged, bool), n_u, n_v)
