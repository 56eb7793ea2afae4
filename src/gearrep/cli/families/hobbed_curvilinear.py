"""The ``hobbed_curvilinear`` family: curvilinear-tooth cylindrical gears cut by a ZA worm hob
(seed 000), analysed by the library's TCA of two-parameter envelopes.

This module is an adapter, not a second TCA, and uses only the library (:mod:`gearrep.tca`,
the replication seed 000 ch. 5 being another user of it): the pair is built by
:func:`gearrep.tca.hobbed_pair`, the contact at phi1 = 0 by :func:`gearrep.tca.hobbed_continue_to`
(continuation from the ideal pair, then the physical contact among the tangencies found across
the face), paths by :func:`gearrep.tca.trace_envelope_path` from it (the rows it misses are
solved again by the robust start strategy :func:`gearrep.tca.robust_envelope_points` from the
first-order predictor off the contact at phi1 = 0) and :func:`gearrep.tca.hobbed_physical_contact`,
the engagement limits by :func:`gearrep.tca.hobbed_tip_crossing` (where the contact reaches each tip
circle, r_p + m), the contact ellipses by :func:`gearrep.tca.hobbed_elastic_ellipses` (curvature
method, eq 5.14-5.17) and the KE table by :func:`gearrep.tca.ke_table` (eq 5.12, zero at
phi1 = 0). What is added here is the design keys and their checks, the mapping of those results
onto the command's tables, the check that the contact at phi1 = 0 lies on both flanks, and the
parameter grid over a flank (hob parameter l from the tip circle to the hob's working depth,
swivel psi between the face edges) for the curvature table and the point clouds.

Frames: contact points in the fixed frame S_f of eq 5.1-5.4 (pinion axis along z for an aligned
pinion); flank grids and curvatures in each member's tooth frame (tooth centred on X, Z = axis).
"""

from __future__ import annotations

import math
from dataclasses import fields

import numpy as np
import pandas as pd

from ... import settings as st
from ...curvature import PrincipalCurvatures, with_opposite_normal
from ...meshing import contact_ratio
from ...settings import SettingError
from ...solve import Status
from ...surfaces.hob import PairDesign, za_hob
from ...tca import (
    HobbedAssembly,
    envelope_pinion_outward,
    envelope_turn_gap,
    hob_pitch_l,
    hobbed_continue_to,
    hobbed_elastic_ellipses,
    hobbed_pair,
    hobbed_phi1_grid,
    hobbed_physical_contact,
    hobbed_tip_crossing,
    ke_table,
    predict_envelope_contact,
    robust_envelope_points,
    trace_envelope_path,
)
from ...units import ARCSEC
from ..family import Design, Family
from ..keys import ANALYSIS, set_dotted
from ..tables import cloud, curvature_frame, cycle_summary, te_envelope
from .involute import undercut_teeth

__all__ = [
    "KEYS",
    "PARAMS",
    "N_STARTS",
    "assembly",
    "window_points",
    "path_solves",
    "start",
    "margin",
    "check_ke_grid",
    "tca",
    "flank_params",
    "HobbedCurvilinearFamily",
    "FAMILY",
]

_MISALIGNMENT = st.group(
    "assembly errors of seed 000 sec 5.2 (eq 5.1-5.3): the pinion axis turned about the mid-face point of its "
    "axis, the gear moved; the library (gearrep.tca.HobbedAssembly) takes at most 0.01 rad and 2 mm",
    dgamma_h_deg=st.number(
        0.0,
        "deg",
        "horizontal misalignment: pinion axis turned about the centre-distance line (axes cross)",
        ge=-0.5,
        le=0.5,
    ),
    dgamma_v_deg=st.number(
        0.0,
        "deg",
        "vertical misalignment: pinion axis turned in the plane of the axes (axes intersect)",
        ge=-0.5,
        le=0.5,
    ),
    dC_mm=st.number(0.0, "mm", "centre-distance change", ge=-2, le=2),
    dZ_mm=st.number(0.0, "mm", "axial displacement of the gear", ge=-2, le=2),
)

_ANALYSIS = st.group(
    "numerical settings of the analyses (hashed as the settings in every provenance sidecar)",
    n_points=ANALYSIS.fields["n_points"],
    elastic_approach_mm=ANALYSIS.fields["elastic_approach_mm"],
    tol=st.number(
        1e-11,
        "mm",
        "residual of the 9-equation TCA system of every contact solve (seed 000 replication: 1e-11)",
        ge=1e-13,
        le=1e-6,
    ),
    continuation_steps=st.integer(
        4,
        "1",
        "warm-started solves from the ideal pair (R_cg >= R_cp + 3 mm, aligned) to the design "
        "(seed 000 replication: 4; one step fails for its almost-line-contact Example 5.2)",
        ge=1,
        le=100,
    ),
    ke_table=st.group(
        "pinion angles of the kinematic-error table (KE zero at phi1 = 0; seed 000 Tables 5.2-5.9: -10 to 10 deg "
        "in 2-deg steps); the grid must hit 0",
        start_deg=st.number(-10.0, "deg", "first pinion angle", ge=-60, le=0),
        end_deg=st.number(10.0, "deg", "last pinion angle", ge=0, le=60),
        step_deg=st.number(2.0, "deg", "step of the pinion angle", gt=0, le=60),
    ),
    curvature_grid=ANALYSIS.fields["curvature_grid"],
    flank_grid=ANALYSIS.fields["flank_grid"],
)


def _member_keys(reason):
    return st.group(
        reason,
        teeth=st.integer(None, "1", "number of teeth", ge=4, le=10000),
        cutter_radius_mm=st.number(
            None, "mm", "nominal radius R_c of the circular-arc tooth trace (the hob's swivel radius)", ge=20, le=1e6
        ),
    )


KEYS = st.declare(
    family=st.choice("hobbed_curvilinear", ("hobbed_curvilinear",), "surface family of both members"),
    name=st.text("unnamed design", "a name for the reports"),
    module_mm=st.number(None, "mm", "normal module of the ZA hob (and of both members)", gt=0, le=100),
    face_width_mm=st.number(None, "mm", "face width of both members", gt=0, le=1000),
    pressure_angle_deg=st.number(20.0, "deg", "normal pressure angle of the hob", ge=10, le=35),
    hob_pitch_radius_mm=st.number(
        None, "mm", "pitch radius r_h of the single-start ZA hob (seed 000 Table 5.1: 30 mm)", gt=0, le=1000
    ),
    hob_profile=st.choice(
        "axial",
        ("axial", "printed"),
        "axial: straight thread profile in the axial section (a true ZA hob; reproduces seed 000 Tables 4.3/4.4); "
        "printed: seed 000 eq 4.40 as printed (profile in the normal section)",
    ),
    pinion=_member_keys("the driving member (member 1): convex flank, tooth trace arc centred on the far side"),
    gear=_member_keys("the driven member (member 2): concave flank"),
    misalignment=_MISALIGNMENT,
    analysis=_ANALYSIS,
)

#: names (with units) of the two flank parameters: the hob profile parameter l and the swivel psi
PARAMS = ("hob_l_mm", "swivel_psi_rad")


def assembly(values) -> HobbedAssembly:
    """The library's assembly errors of the resolved design ``values``."""
    m = values["misalignment"]
    return HobbedAssembly(math.radians(m["dgamma_h_deg"]), math.radians(m["dgamma_v_deg"]), m["dC_mm"], m["dZ_mm"])


def build(values) -> Design:
    """The pair of the resolved design ``values`` (hob, cutter radii and KE grid checked; the
    contact at phi1 = 0 is the contact check's)."""
    v = values
    m, B, a_deg = v["module_mm"], v["face_width_mm"], v["pressure_angle_deg"]
    r_h = v["hob_pitch_radius_mm"]
    least = max(0.5 * m, 0.25 * math.pi * m / math.tan(math.radians(a_deg)))
    if not r_h > least:
        raise SettingError(
            f"design.hob_pitch_radius_mm: got {r_h!r}; allowed: above {least:.6g} mm for module {m:g} mm and "
            f"{a_deg:g} deg (the radius of the thread-groove apex, r_h - (pi m / 4) / tan(alpha_n), must be positive)"
        )
    for member in ("pinion", "gear"):
        z = v[member]["teeth"]
        # the middle section (psi = 0) is cut by the hob's straight axial profile, a rack of addendum 1 module
        undercut_teeth(member, z, m, a_deg, B, 1.0, ", cut by the hob's straight axial profile")
        R = v[member]["cutter_radius_mm"]
        if not R > 0.5 * B:
            raise SettingError(
                f"design.{member}.cutter_radius_mm: got {R!r}; allowed: above half the face width ({0.5 * B:g} mm), "
                "so that the arc tooth trace spans the face"
            )
    R_p, R_g = v["pinion"]["cutter_radius_mm"], v["gear"]["cutter_radius_mm"]
    if not R_g >= R_p:
        raise SettingError(
            f"design.gear.cutter_radius_mm: got {R_g!r}; allowed: >= pinion.cutter_radius_mm = {R_p!r} (the concave "
            "gear trace must be as flat as the convex pinion trace or flatter, else the flanks meet at the face edges)"
        )
    check_ke_grid(v)
    hob = za_hob(m, a_deg, r_h, v["hob_profile"])
    gears = PairDesign(v["pinion"]["teeth"], v["gear"]["teeth"], float(B), hob)
    pair = hobbed_pair(gears, R_p, R_g, assembly(v))
    return Design(v, FAMILY, pair, mesh=gears)


def _half_window(n_teeth: int) -> float:
    """Half-width [rad] of the pinion-angle window searched for the tip crossings: two angular
    pitches of the pinion (a contact ratio below 2 on each side of phi1 = 0), at most 60 deg."""
    return min(2.0 * 2.0 * np.pi / n_teeth, np.radians(60.0))


def start(values, gears, asm, tol, steps):
    """(pair, physical contact at phi1 = 0) of ``gears`` (PairDesign) under the assembly errors
    ``asm``, or (None, reason) when the continuation from the ideal pair fails."""
    try:
        with np.errstate(all="ignore"):
            return hobbed_continue_to(
                gears,
                values["pinion"]["cutter_radius_mm"],
                values["gear"]["cutter_radius_mm"],
                asm,
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


def _check_contact(design) -> None:
    """Solve the contact at phi1 = 0 of the checked ``design`` (sets ``design.pair`` and ``design.start``);
    refuse (SettingError naming the key) when it is not found or lies off the flanks."""
    v, analysis = design.values, design.analysis
    pair, sol = start(v, design.mesh, assembly(v), analysis["tol"], analysis["continuation_steps"])
    ok = pair is not None and bool(sol.converged[0])
    if ok and margin(v, pair, sol) >= 0:
        design.pair, design.start = pair, sol
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
    limit = _limit(design, name, x, pair, sol if ok else None)
    raise SettingError(
        f"design.misalignment.{name}: got {x!r}; allowed: |{name}| below about {limit:.3g} for this pair (larger "
        f"values move the contact at phi1 = 0 off the flanks: {state})"
    )


def _limit(design, name, x, pair, sol) -> float:
    """Magnitude of misalignment ``name`` at which the contact at phi1 = 0 leaves the flanks: linear
    in the margin between the aligned pair and ``sol`` (the contact moves about linearly with the
    misalignment), or by bisection (4 halvings) where the contact under ``x`` was not found or the
    linear estimate is not inside (0, |x|)."""
    v, analysis = design.values, design.analysis

    def contact(t):
        vv = set_dotted(v, f"misalignment.{name}", t * x)
        return start(vv, design.mesh, assembly(vv), analysis["tol"], analysis["continuation_steps"])

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


def _ke_grid(analysis) -> np.ndarray:
    """Pinion angles [rad] of the KE table (:func:`gearrep.tca.hobbed_phi1_grid`)."""
    g = analysis["ke_table"]
    return hobbed_phi1_grid(g["start_deg"], g["end_deg"], g["step_deg"])


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
    """The physical contact at the pinion angles ``phi1`` [rad], traced from the contact ``s0``
    (:func:`gearrep.tca.trace_envelope_path`); the rows it does not converge are solved again by
    :func:`gearrep.tca.robust_envelope_points` from the first-order predictor off ``s0``."""
    with np.errstate(all="ignore"):
        sol = trace_envelope_path(pair, s0, phi1, tol=tol)
        bad = np.flatnonzero(~sol.converged)
        if len(bad):

            def nominal(ph):
                return predict_envelope_contact(pair, np.repeat(s0.x, len(ph), 0), np.repeat(s0.phi1, len(ph)), ph)

            x0 = nominal(phi1[bad])
            _take_rows(sol, bad, robust_envelope_points(pair, phi1[bad], x0[:, 0], x0[:, 3], nominal, tol=tol))
        return hobbed_physical_contact(pair, sol, tol=tol)


def _take_rows(sol, rows, new) -> None:
    """``sol`` (a ContactPath) with its rows ``rows`` replaced, in place, by the converged rows of
    ``new`` (one row per entry of ``rows``)."""
    ok = new.converged
    at = rows[ok]
    for record, other in ((sol, new), (sol.solve, new.solve)):
        for f in fields(record):
            a, b = getattr(record, f.name), getattr(other, f.name)
            if isinstance(a, np.ndarray) and isinstance(b, np.ndarray):
                a[at] = b[ok]


def _engagement(pair, s0, tol):
    """(phi1_B, phi1_E) [rad]: where the contact reaches the pinion tip and the gear tip (the tip
    crossing nearest phi1 = 0 on the traced window)."""
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
            cross = hobbed_tip_crossing(pair, path.take([k, k + 1]), member, ra, np.degrees(w), tol)
        except RuntimeError as e:  # a secant step without a converged contact
            raise ValueError(f"the {member} tip crossing was not found: {e}") from None
        ends.append(np.radians(cross["phi1_deg"]))
    return tuple(sorted(ends))


#: starts of the tangency search at each contact (gearrep.tca.envelope_physical_contact's default)
N_STARTS = 9


def window_points(n_teeth: int) -> int:
    """Pinion angles of the window searched for the tip crossings (steps of at most 2 deg)."""
    return 2 * math.ceil(np.degrees(_half_window(n_teeth)) / 2.0) + 1


def path_solves(n_teeth: int, n_phi: int) -> int:
    """9 x 9 solves of the window and of the path of ``n_phi`` points with its phi1 = 0 row, each
    with its tangency search (1 + N_STARTS per point); the continuation to phi1 = 0 and the secant
    iterations of the two tip crossings (a few each) are not counted."""
    return (1 + N_STARTS) * (window_points(n_teeth) + n_phi + 1)


def tca(design, progress=None, n_points=None, with_ke=True):
    """(contact_path, te_cycle, summary dict, {"ke_table": ...}) of a checked hobbed design
    (``n_points`` path points, default the analysis setting; ``with_ke=False``: no KE table)."""
    analysis, pair, s0 = design.analysis, design.pair, design.start
    tol, n = analysis["tol"], int(analysis["n_points"] if n_points is None else n_points)
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
    drive = 1.0 if float(np.nanmedian(np.where(ok, envelope_turn_gap(pair, sol, sol.phi2 + 1.0), np.nan))) > 0 else -1.0
    p1 = 2.0 * np.pi / pair.pinion.n_teeth
    at, env, lead = te_envelope(phi, ke, drive, p1, b, n)
    if progress:
        progress("contact ellipses and KE table", 0.6)
    with np.errstate(all="ignore"):
        el, _, _ = hobbed_elastic_ellipses(pair, sol, analysis["elastic_approach_mm"])
        normal = envelope_pinion_outward(pair, sol)
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
        "contact_ratio": float(contact_ratio(b, e, pair.pinion.n_teeth)),
        "contact_ratio_method": method,
        **cycle_summary(b, e, env, drive),
        "te_zero": "KE of seed 000 eq 5.12, zero at phi1 = 0",
        "solves": path_solves(pair.pinion.n_teeth, n),
    }
    if not with_ke:
        return path, te, summary, {}
    ke_sol = _path(pair, s0, _ke_grid(analysis), tol)
    return path, te, summary, {"ke_table": ke_table(ke_sol, pair.ratio)}


# ----------------------------------------------------------------------------------------------
# flank grids: curvatures and point clouds in each member's tooth frame
# ----------------------------------------------------------------------------------------------
def _member(design, member: int):
    return (design.pair.pinion if member == 1 else design.pair.gear).gear


def _outward_sign(g) -> float:
    """+1 if the hob normal of flank ``g`` points out of the tooth, else -1: taken once, at the hob
    pitch line of the mid-face section (the hob normal keeps its side of the flank; the polar-angle
    test of :meth:`GeneratedGear.outward` fails near the tip at the face edges, where the arc trace
    carries the tooth's centre line away from X)."""
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


def _lowest_contact_radius(design, member: int) -> float:
    """Radius [mm] on member ``member`` reached by the mating tip circle (r_p + m) in the middle
    section, taken as an involute pair at the standard centre distance:
    sqrt(r_b^2 + (a sin alpha - sqrt(r_a'^2 - r_b'^2))^2)."""
    m, alpha = design.values["module_mm"], math.radians(design.values["pressure_angle_deg"])
    r = [0.5 * m * design.values[k]["teeth"] for k in ("pinion", "gear")]
    own, other = (r[0], r[1]) if member == 1 else (r[1], r[0])
    rb, rb_o, ra_o = own * math.cos(alpha), other * math.cos(alpha), other + m
    return math.hypot(rb, (r[0] + r[1]) * math.sin(alpha) - math.sqrt(ra_o**2 - rb_o**2))


def flank_params(design, member: int, n_u: int, n_v: int):
    """(l, psi) of an n_u x n_v grid (ravelled, profile-major) over member ``member``'s active
    flank: l from the tip circle r_p + m down to the lowest contact radius (the reach of the mating
    tip, :func:`_lowest_contact_radius`), both at mid-face; psi at each l from the face edge
    Z = -B/2 to Z = +B/2. Where a radius is not found, l at the hob pitch line -+ m / cos alpha_n."""
    g = _member(design, member)
    m, half = design.values["module_mm"], 0.5 * design.values["face_width_mm"]
    lp = hob_pitch_l(g.hob)
    dl = m / math.cos(g.hob.pressure_angle_rad)
    with np.errstate(all="ignore"):
        r = g.l_at_radius([g.pitch_radius_mm + m, _lowest_contact_radius(design, member)], l0_mm=lp)
    ok = r.status == Status.CONVERGED
    l_lo = float(r.x[0, 0]) if ok[0] else lp - dl
    l_hi = float(r.x[1, 0]) if ok[1] else lp + dl
    ls = np.linspace(l_lo, l_hi, int(n_u))
    with np.errstate(all="ignore"):
        lo, hi = _psi_at_z(g, ls, -half), _psi_at_z(g, ls, half)
    t = np.linspace(0.0, 1.0, int(n_v))
    psi = lo[:, None] + (hi - lo)[:, None] * t[None, :]
    return np.repeat(ls, int(n_v)), psi.ravel()


def _curvature_table(design) -> pd.DataFrame:
    """Principal curvatures [1/mm] and directions of both flanks on the curvature grid (the
    two-parameter-envelope relations, :func:`gearrep.curvature_relations.generated_curvatures`),
    each in its tooth frame, positive where the flank bends toward its outward normal."""
    n_u, n_v = design.analysis["curvature_grid"][:2]
    rows = []
    for member, name in ((1, "pinion"), (2, "gear")):
        g = _member(design, member)
        l, psi = flank_params(design, member, n_u, n_v)
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


def _flank_cloud(design, member: int):
    """Point cloud of member ``member``'s working flank in its tooth frame: (points (n_u, n_v, 3),
    outward unit normals, table); NaN where the envelope solve did not converge."""
    n_u, n_v = design.analysis["flank_grid"][:2]
    g = _member(design, member)
    l, psi = flank_params(design, member, n_u, n_v)
    with np.errstate(all="ignore"):
        pts, nrm, rec = g.points(l, psi)
        nrm = _outward_sign(g) * nrm
    return cloud(PARAMS, l, psi, pts, nrm, np.asarray(rec.converged, bool), n_u, n_v)


def sweep_point(design, n_phi: int) -> dict:
    """The metrics of one sweep point: those of :func:`tca` with ``n_phi`` path points (no KE table)."""
    path, _, summary, _ = tca(design, n_points=n_phi, with_ke=False)
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


class HobbedCurvilinearFamily(Family):
    """Hob-cut curvilinear-tooth pairs (module docstring)."""

    name = "hobbed_curvilinear"
    keys = KEYS
    param_names = PARAMS

    def build(self, values: dict) -> Design:
        return build(values)

    def check_contact(self, design: Design) -> None:
        """Solve the contact at phi1 = 0 (sets ``d.pair`` and ``d.start``); refuse (SettingError
        naming the key) when it is not found or lies off the flanks."""
        _check_contact(design)

    def tca(self, design: Design, progress=None) -> tuple:
        return tca(design, progress)

    def sweep_point(self, design: Design, n_phi: int) -> dict:
        return sweep_point(design, n_phi)

    def solves_per_point(self, n_phi: int) -> int:
        """An upper bound: the largest window (60 deg each side, 4 teeth or fewer) and the path
        (:func:`path_solves`)."""
        return path_solves(4, n_phi)

    def curvature_table(self, design: Design) -> pd.DataFrame:
        return _curvature_table(design)

    def flank_cloud(self, design: Design, member: int) -> tuple:
        return _flank_cloud(design, member)

    def pinion_surface(self, design: Design):
        """The pinion's generated surface (:class:`gearrep.surfaces.hob.GeneratedGear`)."""
        return design.pair.pinion.gear


FAMILY = HobbedCurvilinearFamily()
