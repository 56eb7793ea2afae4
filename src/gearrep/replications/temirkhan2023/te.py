"""TE and path of contact of crowned spur and helical gears under misalignment (thesis sec 4.1,
Tables 3-4), the crowning areas, and the candidate readings of the printed Delta phi_max.

The TE transmitted over a mesh cycle is the upper envelope of the tooth pairs' TE curves
(:func:`gearrep.meshing.sampled_cycle`).
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from ...meshing import sampled_cycle
from ...solve import Status
from ...surfaces.involute import ParabolicCrowning
from ...tca import GearPair, Misalignment, line_of_action_starts, robust_start, solve_contact
from ...units import ARCSEC, DEG
from .design import TABLE34, Design, misalignment, pair_40_37, pair_spur_m1
from .model import ThesisFrame, crown_curvature, crowning_object

#: a hand-over jump above this counts as a discontinuous TE (0.01 arcsec ~ 5e-8 rad; also the bevel studies')
JUMP_TOL_ARCSEC = 0.01
#: tooth pairs k whose TE curves (shifted by k angular pitches) enter the envelope
PAIRS = range(-2, 3)


def engagement_contacts(pair: GearPair, n_points: int, tol: float = 1e-12):
    """(phi1 grid, :class:`gearrep.tca.ContactPoints`) of one tooth pair over +-1.25 angular pitches
    around phi1 = 0 (4 n_points + 1 angles), each angle solved by the reduced
    formulation from its own robust start; rows outside the flanks are not CONVERGED."""
    p1 = 2 * np.pi / pair.n1
    phi = np.linspace(-1.25 * p1, 1.25 * p1, 4 * int(n_points) + 1)
    st = line_of_action_starts(pair, phi)
    u1r, _ = robust_start(pair, phi, st[:, 0], st[:, 1])  # every angle from its own robust start
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        c = solve_contact(pair, phi, np.column_stack([u1r, st[:, 1]]), formulation="reduced", damped=False, tol=tol)
    return phi, c


def te_study(pair: GearPair, n_points: int, tol: float = 1e-12) -> dict:
    """TE (eq 14, library sign: > 0 = member 2 leads) and path of contact of one tooth pair over
    its engagement, and the TE transmitted over one cycle (upper envelope of the pairs k = -2..2).

    The grid spans +-1.25 angular pitches around phi1 = 0; a grid point counts
    only if the contact lies inside both flanks (edge contact is not modelled: the envelope then
    has a gap, i.e. the TE is discontinuous).
    """
    p1 = 2 * np.pi / pair.n1
    phi, c = engagement_contacts(pair, n_points, tol)
    ok = c.status == Status.CONVERGED
    te = np.where(ok, c.te, np.nan)
    cycle = sampled_cycle(phi, te, p1, int(n_points), PAIRS, handover="jump")
    i0 = int(np.argmin(np.where(ok, np.abs(phi), np.inf))) if ok.any() else None  # nearest phi1 = 0
    if ok.sum() >= 3:
        c2, c1, _ = np.polyfit(phi[ok], te[ok], 2)
        lin_slope, parab = float(c1), float(abs(c2) * (0.5 * p1) ** 2)
    else:
        lin_slope = parab = np.nan
    return dict(
        phi1=phi,
        te=te,
        ok=ok,
        u1=c.u1,
        v1=c.v1,
        u2=c.u2,
        v2=c.v2,
        cycle_phi1=cycle.phi1,
        cycle_te=cycle.te,
        continuous=cycle.continuous(JUMP_TOL_ARCSEC),
        te_extreme=cycle.te_extreme,
        area=float(np.trapezoid(cycle.te, cycle.phi1)) if np.isfinite(cycle.te).all() else np.nan,
        jump_arcsec=cycle.jump_arcsec,
        te_pair_range=(float(np.nanmin(te)), float(np.nanmax(te))) if ok.any() else (np.nan, np.nan),
        v1_at_phi1_0=float(c.v1[i0]) if i0 is not None else np.nan,
        te_at_phi1_0=float(te[i0]) if i0 is not None else np.nan,
        env_pp=cycle.te_peak_to_peak,
        te_linear_slope=lin_slope,
        te_parabolic_part=parab,
        engagement=(float(phi[ok].min()), float(phi[ok].max())) if ok.any() else (np.nan, np.nan),
    )


def first_order_te(pair_aligned: GearPair, plane: str, angle: float, c: float, n_line: int = 9) -> dict:
    """First-order estimate of the contact shift and TE of a crowned pair under angular misalignment.

    Member 2 turned by ``angle`` about axis a (y_f in-plane, x_f out-of-plane) through O2 moves a
    point P of its flank along the normal by angle * n . (a x (P - O2)). Along the instantaneous
    contact line of the aligned pair (parameter v) this is a lead error e = d/dv of that (fitted
    over the line), the crown adds c cos(beta_b) v^2 along the normal, so the contact moves to
    v* = e / (2 c cos beta_b) and member 2 must turn by e^2 / (4 c cos beta_b) / (r_b2 cos beta_b)
    (TE > 0: member 2 leads). Returns e, v*, TE [rad].
    """
    a = {"in": np.array([0.0, 1.0, 0.0]), "out": np.array([1.0, 0.0, 0.0])}[plane]
    g1, g2 = pair_aligned.flank1.gear, pair_aligned.flank2.gear
    cb = np.cos(g1.beta_b)
    hw = 0.25 * g1.face_width
    v = np.linspace(-hw, hw, n_line)
    with np.errstate(invalid="ignore", divide="ignore"):
        cpt = solve_contact(
            pair_aligned,
            np.zeros(n_line),
            np.column_stack([np.full(n_line, g1.r_p), v]),
            formulation="reduced",
            v1=v,
            tol=1e-12,
        )
    P, n = cpt.position, cpt.normal
    disp = angle * np.einsum("ij,ij->i", -n, np.cross(a, P - pair_aligned.O2))
    ok = np.isfinite(disp)
    e = float(np.polyfit(cpt.v1[ok], disp[ok], 1)[0]) if ok.sum() >= 2 else np.nan
    k = c * cb
    return dict(lead_error=e, v_shift=e / (2 * k), te=e * e / (4 * k) / (g2.r_b * cb))


def _te_rows(label, kind, amount, plane, angle_deg, pair, res, fo, frame):
    return dict(
        case=label,
        crown_kind=kind,
        crown_amount=amount,
        plane=plane,
        misalignment_deg=angle_deg,
        te_max_arcsec=res["te_extreme"] / ARCSEC,
        te_max_thesis_sign_arcsec=-res["te_extreme"] / ARCSEC,
        continuous=res["continuous"],
        jump_arcsec=res["jump_arcsec"],
        te_pair_min_arcsec=res["te_pair_range"][0] / ARCSEC,
        te_pair_max_arcsec=res["te_pair_range"][1] / ARCSEC,
        te_area_arcsec_rad=res["area"] / ARCSEC if np.isfinite(res["area"]) else np.nan,
        v1_shift_mm=res["v1_at_phi1_0"],
        first_order_te_arcsec=fo["te"] / ARCSEC if fo else np.nan,
        first_order_v_shift_mm=fo["v_shift"] if fo else np.nan,
        lead_error_rad=fo["lead_error"] if fo else np.nan,
        engagement_begin_rad=res["engagement"][0],
        engagement_end_rad=res["engagement"][1],
        te_at_phi1_0_arcsec=res["te_at_phi1_0"] / ARCSEC,
        te_cycle_pp_arcsec=res["env_pp"] / ARCSEC,
        te_linear_slope_arcsec_per_rad=res["te_linear_slope"] / ARCSEC,
        te_parabolic_part_arcsec=res["te_parabolic_part"] / ARCSEC,
    )


def _curve_rows(label, kind, amount, plane, angle_deg, res, frame):
    ok = res["ok"]
    return pd.DataFrame(
        dict(
            case=label,
            crown_kind=kind,
            crown_amount=amount,
            plane=plane,
            misalignment_deg=angle_deg,
            phi1_rad=res["phi1"][ok],
            te_pair_arcsec=res["te"][ok] / ARCSEC,
            u1_mm=res["u1"][ok],
            v1_thesis_mm=frame.v_to_thesis(res["v1"][ok]),
            u2_mm=res["u2"][ok],
            v2_thesis_mm=frame.v_to_thesis(res["v2"][ok]),
        )
    )


def _cycle_rows(label, kind, amount, plane, angle_deg, res):
    return pd.DataFrame(
        dict(
            case=label,
            crown_kind=kind,
            crown_amount=amount,
            plane=plane,
            misalignment_deg=angle_deg,
            phi1_rad=res["cycle_phi1"],
            te_arcsec=res["cycle_te"] / ARCSEC,
        )
    )


#: candidate readings of the thesis's "maximum TE" (Tables 3-4), see :func:`te_readings`
TE_READINGS = {
    "env_max_arcsec": "largest |TE| transmitted over one cycle, pivot at the pitch point (our te_max) [arcsec]",
    "cycle_pp_arcsec": "peak-to-peak of the transmitted TE over one cycle, pitch-point pivot [arcsec]",
    "pair_linear_half_period_arcsec": "|linear part| of one pair's TE (least-squares quadratic over its engagement) "
    "times half a period pi/N1, pitch-point pivot [arcsec]",
    "parabolic_part_arcsec": "parabolic part only: |c2| (T/2)^2 of the same quadratic, T = 2 pi/N1 [arcsec]",
    "crown_first_order_arcsec": "crown term alone, first order e^2/(4 c r_b2 cos^2 beta_b) [arcsec]",
    "pair_at_phi1_0_arcsec": "TE of one pair at phi1 = 0 (tooth 1 centred on the centre line; the pitch point is "
    "pi/(2 N1) away), pitch-point pivot [arcsec]",
    "axis_pivot_rigid_arcsec": "rigid-body TE of the member-2 axis pivot (mid-face on its axis): in-plane the axial "
    "shift r_p2 sin(angle) times tan(beta)/r_p2; out-of-plane none [arcsec]",
    "face_end_rigid_arcsec": "rigid-body TE of a pivot at a face end (lever b/2), member 2 turned, gear angle (eq 14): "
    "(b/2) sin(angle)/r_p2, in-plane times tan(alpha_t) [arcsec]",
    "face_end_tca_plus_arcsec": "our TCA, pivot at the face end z = +b/2 of member 2, one pair at the pitch-point "
    "position [arcsec]",
    "face_end_tca_minus_arcsec": "same, pivot at the face end z = -b/2 [arcsec]",
    "face_end_rigid_pinion_mrad": "face-end rigid-body TE expressed as pinion angle (r_p1 instead of r_p2, i.e. eq 14 "
    "times N2/N1) in 1e-3 rad (the thesis states its misalignments in mrad) [mrad]",
    "face_end_rigid_pinion_mrad_transverse_module": "same with a transverse module 1 (r_p1 = N1/2 = 20 mm) [mrad]",
    "face_end_tca_plus_pinion_mrad": "face_end_tca_plus as pinion angle in 1e-3 rad [mrad]",
    "face_end_tca_minus_pinion_mrad": "face_end_tca_minus as pinion angle in 1e-3 rad [mrad]",
}


def contact_at_phi1_0(pair: GearPair, tol: float = 1e-12):
    """Contact of one pair at phi1 = 0 (tooth 1 centred on the centre line, not the pitch-point
    position, which is pi/(2 N1) away): reduced solve from (r_p1, v1 = 0),
    then from the robust start (:class:`gearrep.tca.ContactPoints` of one row; its status says
    whether either converged)."""
    phi = np.zeros(1)
    u0 = np.array([pair.flank1.gear.r_p])
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        c = solve_contact(pair, phi, np.column_stack([u0, [0.0]]), formulation="reduced", damped=False, tol=tol)
        if c.status[0] != Status.CONVERGED:
            u1r, _ = robust_start(pair, phi, u0, np.zeros(1))
            c = solve_contact(pair, phi, np.column_stack([u1r, [0.0]]), formulation="reduced", damped=False, tol=tol)
    return c


def _te_at_phi1_0(pair: GearPair, tol: float = 1e-12) -> float:
    """TE [rad] of one pair at phi1 = 0; NaN (reported, not guessed) if no contact."""
    c = contact_at_phi1_0(pair, tol)
    return float(c.te[0]) if c.status[0] == Status.CONVERGED else np.nan


def readings_of(settings: dict, design: Design, te_summary: pd.DataFrame) -> pd.DataFrame:
    """Candidate readings of the thesis's Delta phi_max for every computed row of Tables 3-4 (long
    format: one row per table row and reading; magnitudes, since the sign depends on axis
    orientations the thesis does not print). Nothing here is fitted to the printed values: the
    pivots (pitch point, member-2 axis, face ends z = +-b/2), radii (r_p1, r_p2) and units are
    fixed alternatives. Rigid-body terms are first order in the angle; turning the pinion instead
    of the gear about the same pivot gives the same relative displacement (opposite sign), so the
    member does not change these magnitudes."""
    h = te_summary[te_summary["case"] == "helical_40_37"]
    d = design.pairs["helical_40_37"]
    base = pair_40_37(design)
    g1, g2 = base.flank1.gear, base.flank2.gear
    half_b = 0.5 * d["face_width"]
    p1 = 2 * np.pi / d["n1"]
    tan_at, tan_b = np.tan(g1.alpha_t), np.tan(d["helix_angle_deg"] * DEG)
    r_p1_transverse = 0.5 * d["n1"] * d["module"]
    a2 = float(settings["crowning_log_a2"])
    rows = []
    for r in h.itertuples():
        ang = abs(r.misalignment_deg) * DEG
        lever = tan_at if r.plane == "in" else 1.0
        crown = crowning_object(r.crown_kind, r.crown_amount, d["face_width"], a2)
        tca = {}
        for sgn, name in ((1.0, "plus"), (-1.0, "minus")):
            m = misalignment(r.plane, r.misalignment_deg * DEG, base, "pitch_point")
            hz, a = sgn * half_b, r.misalignment_deg * DEG
            # pivot Q = C + (0, 0, hz): extra translation (I - R)(Q - C) of member 2
            m = (
                Misalignment(d_gamma_in=m.d_gamma_in, d_E=m.d_E - hz * np.sin(a), d_Z=m.d_Z + hz * (1 - np.cos(a)))
                if r.plane == "in"
                else Misalignment(
                    d_gamma_out=m.d_gamma_out, d_H=m.d_H + hz * np.sin(a), d_Z=m.d_Z + hz * (1 - np.cos(a))
                )
            )
            tca[name] = _te_at_phi1_0(pair_40_37(design, crown, m), tol=float(settings["tol"]))
        vals = {
            "env_max_arcsec": abs(r.te_max_arcsec),
            "cycle_pp_arcsec": r.te_cycle_pp_arcsec,
            "pair_linear_half_period_arcsec": abs(r.te_linear_slope_arcsec_per_rad) * 0.5 * p1,
            "parabolic_part_arcsec": r.te_parabolic_part_arcsec,
            "crown_first_order_arcsec": abs(r.first_order_te_arcsec),
            "pair_at_phi1_0_arcsec": abs(r.te_at_phi1_0_arcsec),
            "axis_pivot_rigid_arcsec": (np.sin(ang) * tan_b if r.plane == "in" else 0.0) / ARCSEC,
            "face_end_rigid_arcsec": half_b * np.sin(ang) * lever / g2.r_p / ARCSEC,
            "face_end_tca_plus_arcsec": abs(tca["plus"]) / ARCSEC,
            "face_end_tca_minus_arcsec": abs(tca["minus"]) / ARCSEC,
            "face_end_rigid_pinion_mrad": half_b * np.sin(ang) * lever / g1.r_p * 1e3,
            "face_end_rigid_pinion_mrad_transverse_module": half_b * np.sin(ang) * lever / r_p1_transverse * 1e3,
            "face_end_tca_plus_pinion_mrad": abs(tca["plus"]) * g2.r_p / g1.r_p * 1e3,
            "face_end_tca_minus_pinion_mrad": abs(tca["minus"]) * g2.r_p / g1.r_p * 1e3,
        }
        for k, v in vals.items():
            rows.append(
                dict(
                    table=r.table,
                    plane=r.plane,
                    misalignment_deg=r.misalignment_deg,
                    crown_kind=r.crown_kind,
                    table_row=int(r.table_row),
                    crown_amount=r.crown_amount,
                    reading=k,
                    value_abs=float(v),
                    unit="mrad" if "mrad" in k else "arcsec",
                    description=TE_READINGS[k],
                )
            )
    return pd.DataFrame(rows)


def crowning_areas(te_summary: pd.DataFrame) -> pd.DataFrame:
    """TE areas S_c, S_p, S_l at 0.2 deg (first row of Tables 3-4), thesis sign, and their ratios."""
    t = te_summary[
        (te_summary["case"] == "helical_40_37")
        & (te_summary["misalignment_deg"].abs() == 0.2)
        & (te_summary["table_row"] == 1)
    ]
    rows = []
    for plane, g in t.groupby("plane"):
        s = {r.crown_kind: -r.te_area_arcsec_rad for r in g.itertuples()}
        rows.append(
            dict(
                plane=plane,
                S_c=s.get("circular"),
                S_p=s.get("parabolic"),
                S_l=s.get("logarithmic"),
                l_vs_p_pct=100 * (abs(s["logarithmic"]) / abs(s["parabolic"]) - 1),
                l_vs_c_pct=100 * (abs(s["logarithmic"]) / abs(s["circular"]) - 1),
            )
        )
    return pd.DataFrame(rows)


def spur_te(settings: dict, design: Design):
    """Sec 4.1: spur 25/25, m = 1, crowns a1 on gear 1, no / in-plane / out-of-plane misalignment."""
    n = int(settings["te_n_points"])
    gam = float(design.spur_te_misalignment_mrad) * 1e-3
    base = pair_spur_m1(design, None)
    summary, curves, cycles = [], [], []
    for crown in design.spur_te_crowns:
        for plane, ang in (("none", 0.0), ("in", gam), ("out", gam)):
            pair = pair_spur_m1(design, crown, misalignment(plane, ang, base, settings["te_pivot"]))
            fr = ThesisFrame.of(pair)
            res = te_study(pair, n)
            fo = first_order_te(base, plane, ang, crown) if plane != "none" else None
            lab = "spur_25_25_m1"
            summary.append(_te_rows(lab, "parabolic", crown, plane, ang / DEG, pair, res, fo, fr))
            curves.append(_curve_rows(lab, "parabolic", crown, plane, ang / DEG, res, fr))
            cycles.append(_cycle_rows(lab, "parabolic", crown, plane, ang / DEG, res))
    return summary, curves, cycles


def table34_te(settings: dict, design: Design, select=None):
    """Tables 3-4: helical 40/37, each printed crown amount (rows of ``crowning_rows``; ``select(plane,
    angle_deg, row)`` restricts further) under its misalignment, pivot ``te_pivot``."""
    n = int(settings["te_n_points"])
    base = pair_40_37(design)
    a2 = float(settings["crowning_log_a2"])
    b = design.pairs["helical_40_37"]["face_width"]
    summary, curves, cycles = [], [], []
    for (plane, ang_deg), kinds in TABLE34.items():
        for kind, amounts in kinds.items():
            for i, amount in enumerate(amounts):
                if i + 1 not in settings["crowning_rows"] or (select is not None and not select(plane, ang_deg, i + 1)):
                    continue
                pair = pair_40_37(
                    design,
                    crowning_object(kind, amount, b, a2),
                    misalignment(plane, ang_deg * DEG, base, settings["te_pivot"]),
                )
                fr = ThesisFrame.of(pair)
                res = te_study(pair, n)
                fo = first_order_te(base, plane, ang_deg * DEG, crown_curvature(kind, amount, b, a2))
                row = _te_rows("helical_40_37", kind, amount, plane, ang_deg, pair, res, fo, fr)
                row.update(table="Table 3" if plane == "in" else "Table 4", table_row=i + 1, log_a2=a2)
                summary.append(row)
                if i == 0 and abs(ang_deg) == 0.2:
                    curves.append(_curve_rows("helical_40_37", kind, amount, plane, ang_deg, res, fr))
                    cycles.append(_cycle_rows("helical_40_37", kind, amount, plane, ang_deg, res))
    return summary, curves, cycles


def te_tables(settings: dict, design: Design) -> dict:
    """Job ``te``: te_summary, te_curves, te_cycle of the spur (sec 4.1) and helical (Tables 3-4)
    studies, and te_readings (candidate readings of Delta phi_max, read from the same Tables 3-4
    rows: computing them alone would rerun every Tables 3-4 TE study)."""
    s1, c1, y1 = spur_te(settings, design)
    s2, c2, y2 = table34_te(settings, design)
    summary = pd.DataFrame(s1 + s2)
    return dict(
        te_summary=summary,
        te_curves=pd.concat(c1 + c2, ignore_index=True),
        te_cycle=pd.concat(y1 + y2, ignore_index=True),
        te_readings=readings_of(settings, design, summary),
    )


def te_sensitivity(settings: dict, design: Design) -> dict:
    """Job ``te_sensitivity``: the unprinted a2 of the logarithmic crown and the misalignment pivot,
    at 0.2 deg (first printed amount of each crown)."""
    n = int(settings["te_n_points"])
    a2 = float(settings["crowning_log_a2"])
    b = design.pairs["helical_40_37"]["face_width"]
    base = pair_40_37(design)
    other = "axis" if settings["te_pivot"] == "pitch_point" else "pitch_point"
    jobs = [("logarithmic", a2s, settings["te_pivot"]) for a2s in settings["crowning_log_a2_sensitivity"]]
    jobs += [(kind, a2, other) for kind in ("circular", "parabolic", "logarithmic")]
    sens = []
    for kind, a2s, pivot in jobs:
        for (plane, ang_deg), kinds in TABLE34.items():
            if abs(ang_deg) != 0.2:
                continue
            amount = kinds[kind][0]
            res = te_study(
                pair_40_37(
                    design, crowning_object(kind, amount, b, a2s), misalignment(plane, ang_deg * DEG, base, pivot)
                ),
                n,
            )
            sens.append(
                dict(
                    crown_kind=kind,
                    plane=plane,
                    misalignment_deg=ang_deg,
                    crown_amount=amount,
                    log_a2=a2s,
                    pivot=pivot,
                    te_max_arcsec=res["te_extreme"] / ARCSEC,
                    continuous=res["continuous"],
                    jump_arcsec=res["jump_arcsec"],
                    te_area_arcsec_rad=res["area"] / ARCSEC if np.isfinite(res["area"]) else np.nan,
                )
            )
    return dict(te_sensitivity=pd.DataFrame(sens))


def crowning_areas_table(settings: dict, design: Design) -> dict:
    """Job ``crowning_areas``: TE areas of the 0.2 deg, first-row amounts of Tables 3-4 only."""
    rows, _, _ = table34_te(settings, design, select=lambda plane, ang, row: abs(ang) == 0.2 and row == 1)
    return dict(crowning_areas=crowning_areas(pd.DataFrame(rows)))


def shift_common_angle_table(settings: dict, design: Design) -> dict:
    """Job ``shift_common_angle`` (claim 003-C6-helical_shift_much_larger_than_spur): the contact
    shift from mid-face at phi1 = 0 of the helical 40/37 pair and of the spur 25/25
    (m = 1) pair at the SAME misalignment (each angle and plane of Tables 3-4) with the SAME crown:
    the parabolic row-1 amount c1 of that angle on the pinion of both pairs (pivot ``te_pivot``)."""
    rows = []
    hel0, spur0 = pair_40_37(design), pair_spur_m1(design, None)
    for (plane, ang_deg), kinds in TABLE34.items():
        c1 = kinds["parabolic"][0]
        shift = {}
        for label, make, base in (
            ("helical_40_37", lambda m: pair_40_37(design, ParabolicCrowning(c1), m), hel0),
            ("spur_25_25_m1", lambda m: pair_spur_m1(design, c1, m), spur0),
        ):
            c = contact_at_phi1_0(
                make(misalignment(plane, ang_deg * DEG, base, settings["te_pivot"])), float(settings["tol"])
            )
            shift[label] = float(c.v1[0]) if c.status[0] == Status.CONVERGED else np.nan
        rows.append(
            dict(
                plane=plane,
                misalignment_deg=ang_deg,
                crown_kind="parabolic",
                crown_amount=c1,
                helical_shift_mm=shift["helical_40_37"],
                spur_shift_mm=shift["spur_25_25_m1"],
                ratio_helical_to_spur=abs(shift["helical_40_37"]) / abs(shift["spur_25_25_m1"]),
            )
        )
    return dict(shift_common_angle=pd.DataFrame(rows))
