"""What seed 000 ch. 5 computes, one function per job (each callable alone with the resolved
settings and the design of :func:`gearrep.replications.hobcut_tca.params_from_published`).

A job that needs a solved Example (sensitivity, contact ratio, ellipses, topology) solves it
itself: one KE path costs < 0.5 s, and solving it again gives the same numbers bit for bit."""

from __future__ import annotations

from functools import partial

import numpy as np
import pandas as pd

from ... import meshing
from ...surfaces.hob import PairDesign
from ...tca import (
    EnvelopeContactPath,
    HobbedAssembly,
    HobbedPair,
    envelope_dropped_component,
    envelope_member_geometry,
    envelope_tangency_near,
    envelope_tangency_system,
    envelope_turn_gap,
    hobbed_continue_to,
    hobbed_pair,
    hobbed_physical_contact,
    hobbed_tip_crossing,
    ke_table,
    require_converged,
    solve_envelope_points,
    trace_envelope_path,
)
from ...units import ARCSEC
from .._face import Job
from .design import TABLE_EXAMPLE, Design, phi1_grid
from .ellipses import contact_ellipses, pitch_point_ratio, topology_pattern

__all__ = [
    "JOBS",
    "assembly_of",
    "compute_case",
    "solved",
    "ke_table_of",
    "ke_table_two_tangencies",
    "sensitivity",
    "contact_ratio",
    "ke_vs_hob_radius",
    "ellipses_example_5_3",
    "ellipse_ratio",
    "topology_example_5_3",
    "SENSITIVITY_TABLES",
]

#: the tables whose sensitivity to R_c is reported (the surviving ones)
SENSITIVITY_TABLES = ("5.3", "5.4", "5.7", "5.8", "5.9")


def assembly_of(case: dict) -> HobbedAssembly:
    """The assembly errors of a case (angles printed in arc-minutes)."""
    am = np.radians(1.0 / 60.0)
    return HobbedAssembly(case["dgamma_h_arcmin"] * am, case["dgamma_v_arcmin"] * am, case["dC_mm"], case["dZ_mm"])


def compute_case(
    gears: PairDesign, case: dict, phi1_rad, *, tol=1e-11, steps=4
) -> tuple[HobbedPair, EnvelopeContactPath]:
    """(pair, path) of one Example of the pair ``gears``: continuation at phi1' = 0, then the path,
    and at every phi1' the physical contact among the tangencies found
    (:func:`gearrep.tca.hobbed_physical_contact`)."""
    pair, s0 = hobbed_continue_to(gears, case["R_cp_mm"], case["R_cg_mm"], assembly_of(case), steps=steps, tol=tol)
    return pair, hobbed_physical_contact(pair, trace_envelope_path(pair, s0, phi1_rad, tol=tol), tol=tol)


def solved(
    settings: dict, design: Design, example: str, gears: PairDesign | None = None
) -> tuple[HobbedPair, EnvelopeContactPath]:
    """The path of an Example on the settings' phi1' grid (of the design's pair, or of ``gears``)."""
    return compute_case(
        design.gears if gears is None else gears,
        design.cases[example],
        phi1_grid(settings),
        tol=settings["tol"],
        steps=settings["continuation_steps"],
    )


def ke_table_of(settings: dict, design: Design, example: str) -> pd.DataFrame:
    """The KE table (eq 5.12, re-zeroed at phi1' = 0) of one Example."""
    pair, sol = solved(settings, design, example)
    return ke_table(sol, pair.ratio)


def ke_table_two_tangencies(settings: dict, design: Design, example: str) -> pd.DataFrame:
    """The KE table of an Example (the physical, i.e. first, contact: :func:`ke_table_of`) with the
    mid-face tangency beside it, for an almost-line contact where both are tangencies of the same
    equations (Example 5.1: the first contact is a pair at Z = +-Z*, the text prints Z = 0).

    Added columns: the mid-face tangency's l, Z and KE (re-zeroed at its own phi1' = 0 row, as
    a printed table would be), its gear angle minus the first contact's [arcsec], and the two
    separations, first-order normal gaps (:func:`gearrep.tca.envelope_turn_gap`; < 0 =
    interpenetration): ``gap_at_first_contact_if_midface_mm`` at the first-contact point with the
    gear at the mid-face tangency's angle (the largest interpenetration of the mid-face tangency
    to second order in the turn; the mirror point of the pair has the same by symmetry) and
    ``gap_at_midface_if_first_contact_mm`` at mid-face with the gear at the first contact's angle;
    and the ``tangency_gap_threshold_mm`` setting they are judged against (:mod:`.checks`)."""
    pair, sol = solved(settings, design, example)
    mid = envelope_tangency_near(pair, sol, 0.0, tol=settings["tol"])
    require_converged(mid, f"mid-face tangency of Example {example}")
    if not (np.all(np.abs(mid.Z_p) < 1e-6) and np.all(np.abs(mid.phi2 - sol.phi2) < 1e-6)):
        raise RuntimeError(f"Example {example}: the search from Z_p = 0 did not return the mid-face tangency")
    t = ke_table(sol, pair.ratio)
    tm = ke_table(mid, pair.ratio)
    t["l_p_midface_mm"] = tm["l_p_mm"]
    t["Z_p_midface_mm"] = tm["Z_p_mm"]
    t["l_g_midface_mm"] = tm["l_g_mm"]
    t["Z_g_midface_mm"] = tm["Z_g_mm"]
    t["KE_midface_arcsec"] = tm["KE_arcsec"]
    t["phi2_midface_minus_phi2_arcsec"] = (mid.phi2 - sol.phi2) / ARCSEC
    t["gap_at_first_contact_if_midface_mm"] = envelope_turn_gap(pair, sol, mid.phi2)
    t["gap_at_midface_if_first_contact_mm"] = envelope_turn_gap(pair, mid, sol.phi2)
    t["tangency_gap_threshold_mm"] = float(settings["tangency_gap_threshold_mm"])
    return t


def _shifted(gears, case, pair, sol, which, h, tol):
    out = []
    for sgn in (1, -1):
        c = dict(case)
        c[which] = case[which] + sgn * h
        pr = hobbed_pair(gears, c["R_cp_mm"], c["R_cg_mm"], pair.assembly)
        s = solve_envelope_points(pr, sol.phi1, sol.x, tol=tol)
        require_converged(s, f"sensitivity {which}")
        out.append(s)
    return out


def _sensitivity_of(gears, case, pair, sol, settings) -> pd.DataFrame:
    """dZ/dR_c and dKE/dR_c at every row by central differences in R_cg and R_cp (warm
    started from the path), and Z at a loose solver tolerance (1e-6)."""
    h = float(settings["sensitivity_step_mm"])
    out = {which: _shifted(gears, case, pair, sol, which, h, settings["tol"]) for which in ("R_cg_mm", "R_cp_mm")}
    loose = solve_envelope_points(pair, sol.phi1, sol.x + 1e-5, tol=1e-6)
    # how far Z_p can move along the weakest direction of the 9 x 9 Jacobian while the residual
    # stays below 1e-6 (a solver stopping there could report any Z_p in this band)
    _, J, _ = envelope_tangency_system(pair, sol.x, sol.phi1, envelope_dropped_component(pair, sol.x, sol.phi1))
    _, sv, Vt = np.linalg.svd(J)
    Tp = envelope_member_geometry(pair.pinion, sol.x[:, 0:4])[1]  # d r_p / d q_p, z unchanged by the placement
    band = np.abs(np.einsum("nq,nq->n", Tp[:, :, 2], Vt[:, -1, 0:4])) / sv[:, -1] * 1e-6
    ke = {k: [ke_table(s, pair.ratio)["KE_arcsec"].to_numpy() for s in v] for k, v in out.items()}
    g, p = out["R_cg_mm"], out["R_cp_mm"]
    return pd.DataFrame(
        {
            "phi1_deg": np.degrees(sol.phi1),
            "dZ_p_dR_cg": (g[0].Z_p - g[1].Z_p) / (2 * h),
            "dZ_g_dR_cg": (g[0].Z_g - g[1].Z_g) / (2 * h),
            "dZ_p_dR_cp": (p[0].Z_p - p[1].Z_p) / (2 * h),
            "dl_p_dR_cg": (g[0].x[:, 0] - g[1].x[:, 0]) / (2 * h),
            "dKE_dR_cg_arcsec_per_mm": (ke["R_cg_mm"][0] - ke["R_cg_mm"][1]) / (2 * h),
            "Z_p_tol_1e-6_minus_Z_p": loose.Z_p - sol.Z_p,
            "Z_p_band_at_residual_1e-6_mm": band,
            "loose_status": loose.status_name,
            "jacobian_cond": sol.cond,
        }
    )


def sensitivity(settings: dict, design: Design) -> pd.DataFrame:
    """Sensitivity of the surviving tables' contact to R_c (each Example solved again)."""
    frames = []
    for table in SENSITIVITY_TABLES:
        ex = TABLE_EXAMPLE[table]
        pair, sol = solved(settings, design, ex)
        s = _sensitivity_of(design.gears, design.cases[ex], pair, sol, settings)
        s.insert(0, "table", table)
        frames.append(s)
    return pd.concat(frames, ignore_index=True)


def contact_ratio(settings: dict, design: Design) -> pd.DataFrame:
    """Contact ratio of the ideal 110/110 pair (Example 5.1), eq 5.13 with the angular pitch
    (:func:`.model.contact_ratio`): phi1_B, phi1_E where the contact reaches the gear tip and the
    pinion tip. The start is the physical contact at phi1' = 0 of the Example's path."""
    pair, sol = solved(settings, design, "5.1")
    start = sol.take([int(np.argmin(np.abs(sol.phi1)))])
    tol, window = settings["tol"], settings["contact_ratio_window_deg"]
    w = np.radians(window)
    path = hobbed_physical_contact(pair, trace_envelope_path(pair, start, np.linspace(-w, w, 31), tol=tol), tol=tol)
    require_converged(path, "contact-ratio path")
    d = pd.DataFrame(
        [
            hobbed_tip_crossing(pair, path, "pinion", pair.pinion.r_outside_mm, window, tol),
            hobbed_tip_crossing(pair, path, "gear", pair.gear.r_outside_mm, window, tol),
        ]
    )
    # the library's contact ratio (the printed eq 5.13 with the angular pitch, model.contact_ratio,
    # is kept as evidence and tested against it); the pinion tip comes first along the path
    d["contact_ratio"] = abs(float(meshing.contact_ratio(*np.radians(d["phi1_deg"].to_numpy()), pair.pinion.n_teeth)))
    return d


def ke_vs_hob_radius(settings: dict, design: Design) -> pd.DataFrame:
    """Fig 5.5: KE of Example 5.1 for each hob pitch radius of ``hob_radii_mm``."""
    rows = []
    for r_h in settings["hob_radii_mm"]:
        gears = design.gears.with_hob(pitch_radius_mm=float(r_h))
        hob = gears.hob
        pair, sol = solved(settings, design, "5.1", gears)
        require_converged(sol, f"hob sweep r_h={r_h}")
        t = ke_table(sol, pair.ratio)
        rows += [
            {
                "hob_pitch_radius_mm": float(r_h),
                "lead_angle_deg": np.degrees(hob.lead_angle_rad),
                "phi1_deg": a,
                "KE_arcsec": k,
            }
            for a, k in zip(t["phi1_deg"], t["KE_arcsec"])
        ]
    return pd.DataFrame(rows)


def ellipses_example_5_3(settings: dict, design: Design) -> pd.DataFrame:
    """Curvature-method contact ellipses along the Example 5.3 path."""
    pair, sol = solved(settings, design, "5.3")
    return contact_ellipses(pair, sol, float(design.delta_mm))


def ellipse_ratio(settings: dict, design: Design) -> pd.DataFrame:
    """Fig 5.7: a/b at the pitch point of the ideal pair R_cg = R_cp + ellipse_R_gap_mm."""
    rows = [
        pitch_point_ratio(
            design.gears,
            float(rc),
            float(rc) + float(settings["ellipse_R_gap_mm"]),
            float(a),
            delta_mm=float(design.delta_mm),
            tol=settings["tol"],
        )
        for a in design.ellipse_alpha_deg
        for rc in settings["ellipse_R_cp_mm"]
    ]
    return pd.DataFrame(rows)


def topology_example_5_3(settings: dict, design: Design) -> pd.DataFrame:
    """Fig 5.8: surface-topology pattern at the topology_phi1_deg points of the Example 5.3 path."""
    pair, sol = solved(settings, design, "5.3")
    topo = []
    for a in settings["topology_phi1_deg"]:
        i = int(np.argmin(np.abs(np.degrees(sol.phi1) - a)))
        t = topology_pattern(pair, sol, i, float(design.delta_mm), int(settings["topology_n_dirs"]))
        if not t["converged"].all():
            raise RuntimeError(f"topology pattern at phi1' = {a} deg: separation solve did not converge")
        topo.append(t)
    return pd.concat(topo, ignore_index=True)


def _ke_job(settings, design, *, example: str, name: str) -> dict:
    table = ke_table_two_tangencies if name in TWO_TANGENCY_TABLES else ke_table_of
    return {name: table(settings, design, example)}


#: KE tables that report the mid-face tangency beside the first contact (Table 5.2: ideal 110/110)
TWO_TANGENCY_TABLES = ("ke_table_5_2",)


def _one(fn, name):
    def compute(settings, design):
        return {name: fn(settings, design)}

    compute.__name__ = compute.__qualname__ = name
    compute.__doc__ = fn.__doc__
    return compute


_KE = {f"ke_table_5_{i}": f"5.{i}" for i in range(2, 10)}


JOBS = {
    **{
        name: Job(
            partial(_ke_job, example=TABLE_EXAMPLE[tab], name=name),
            {name: f"hobcut_tca/{name}.csv"},
            f"Table {tab} (Example {TABLE_EXAMPLE[tab]}) alone",
        )
        for name, tab in _KE.items()
    },
    "ke_example_5_3": Job(
        partial(_ke_job, example="5.3", name="ke_example_5_3"),
        {"ke_example_5_3": "hobcut_tca/ke_example_5_3.csv"},
        "Example 5.3 (ideal 110/113, no table)",
    ),
    **{
        name: Job(
            _one(fn, name),
            {name: f"hobcut_tca/{name}.csv"},
            fn.__doc__,
            priority,
        )
        for name, fn, priority in (  # priority: about the seconds of the long jobs (.._face.Job)
            ("sensitivity", sensitivity, 10),
            ("contact_ratio", contact_ratio, 2),
            ("ke_vs_hob_radius", ke_vs_hob_radius, 4),
            ("ellipses_example_5_3", ellipses_example_5_3, 0),
            ("ellipse_ratio", ellipse_ratio, 6),
            ("topology_example_5_3", topology_example_5_3, 5),
        )
    },
}
