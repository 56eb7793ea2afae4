"""What seed 003's replication computes: :data:`JOBS`, one job per table group, and the
functions of the two evidence jobs (the errata found in the thesis, the convergence protocol as
run). The larger studies' functions live in their topic modules (:mod:`.convergence`,
:mod:`.bevel_convergence`, :mod:`.te`, :mod:`.stress`, :mod:`.path_guess`, :mod:`.bevel`)."""

from __future__ import annotations

import numpy as np
import pandas as pd

from ...surfaces.involute import InvoluteGearData
from ...units import DEG
from .._face import Job
from .bevel import bevel_errata_rows, bevel_protocol_items, spiral_contact_tables, straight_contact_tables
from .bevel_convergence import convergence_tables
from .convergence import STREAMS, study_reference
from .design import Design, design_pair
from .path_guess import path_guess_table
from .stress import stress_table
from .te import crowning_areas_table, shift_common_angle_table, te_sensitivity, te_tables

__all__ = ["JOBS", "errata_table", "protocol_table"]


def errata_table(settings: dict, design: Design) -> dict:
    """Job ``errata``: the numbers behind the errata of the thesis (see the package docstring)."""
    rows = []
    pair = design_pair(design, "spur_25_25")
    fr, ref = study_reference(settings, pair, np.pi / 2)
    x = ref.x
    _, n1 = pair.member1(x[:1], x[1:2], ref.phi1)
    _, n2 = pair.member2(x[2:3], x[3:4], np.array([x[4]]))
    rows.append(
        dict(
            item="eq (27) n1 - n2 = 0",
            finding="as printed it has no solution at the contact; n1 + n2 = 0 does",
            evidence=f"at the sec 6.1 contact |n1 - n2| = {np.linalg.norm(n1 - n2):.6f}, "
            f"|n1 + n2| = {np.linalg.norm(n1 + n2):.2e} (outward unit normals)",
        )
    )
    # eq 43-44: magnitude from acos, sign rule
    mag = abs(float(fr.phi2_to_thesis(x[4])))
    rows.append(
        dict(
            item="eq (43)-(44) sign of phi2",
            finding="the sign is that of (p2 x q2) . w2 (right-handed); the worded rule gives the wrong sign",
            evidence=f"acos gives |phi2| = {mag:.4f} rad; the rotation p2 -> q2 about +z is clockwise, which the "
            f"worded rule calls positive (+{mag:.4f}); the printed value is -1.6",
        )
    )
    for name in ("spur_52_72", "spur_25_25"):
        d = design.pairs[name]
        g = InvoluteGearData(d["n1"], d["module"], d["pressure_angle_deg"] * DEG, d["face_width"])
        pr = design_pair(design, name)
        _, rr = study_reference(settings, pr, np.pi / 2)
        rows.append(
            dict(
                item=f"Table 1 tip diameter ({name})",
                finding="d_a = d_b + 2m as printed; d_p + 2m is meant",
                evidence=f"printed r_a = r_b + m = {g.r_b + g.module:.4f} vs r_p = {g.r_p:.4f}, corrected "
                f"r_a = {g.r_a:.4f}; reference contact u1 = {rr.x[0]:.4f} "
                f"{'outside' if rr.x[0] > g.r_b + g.module else 'inside'} the printed flank",
            )
        )
    pair = design_pair(design, "helical_25_77")
    frh, refh = study_reference(settings, pair, np.pi / 2)
    rows.append(
        dict(
            item="Table 9 / sec 6.1 helical reference phi2",
            finding="reproduced with normal module 5 and the pitch-point contact at phi1 = pi/2 (true helicoid)",
            evidence=f"phi2 = {frh.phi2_to_thesis(refh.x[4]):.5f} rad (printed -1.635); transverse-module "
            "reading gives -1.6246",
        )
    )
    rows.append(
        dict(
            item="Tables 3-4 crowning amounts",
            finding="amounts fall as the misalignment grows, TE grows linearly; first-order theory: shift "
            "e/(2c), TE e^2/(4c r_b2 cos^2 beta_b)",
            evidence="see te_summary.csv: first_order_* columns agree with our TCA where the crown term "
            "dominates (spur) and show that the helical TE is dominated by the rigid-body term",
        )
    )
    rows += bevel_errata_rows(design)
    return dict(errata=pd.DataFrame(rows))


def protocol_table(settings: dict, design: Design) -> dict:
    """Job ``protocol``: the convergence protocol as items and values (protocol.csv), and the
    settings of the run (run_info.csv; the checks quote the tolerance from it)."""
    p = settings
    items = [
        ("random generator", f"numpy default_rng([seed, stream]) (PCG64), seed = {p['seed']}, streams {STREAMS}"),
        ("u1 start", "uniform on [u1_min, u1_max] = [max(r_b, r_f), r_a] of flank 1 (Table 1 corrected)"),
        ("v1 start", "uniform on [-b/2, b/2] (thesis v = v + b/2)"),
        ("u2, v2 start", "Table 10 and window sweep: uniform on flank 2; sec 6.1 and Table 9: mid-point of flank 2"),
        (
            "phi2 start",
            "Table 10: uniform on a full turn (width primary_phi2_window_rad = "
            f"{p['primary_phi2_window_rad']:.6g} rad); sweep: uniform on a window of width w centred "
            "on the root; sec 6.1: fixed guesses and (-1.7, -1.0) rad; Table 9: (-1.7, -1.3) rad (thesis frame)",
        ),
        ("phi1", "pi/2 in the thesis frame for every study"),
        ("solver", "gearrep.solve.newton: least-squares Newton step by SVD, analytic Jacobian, rcond 1e-13"),
        (
            "conventional equations",
            "r_f1 - r_f2 = 0 and two components of n_f1 + n_f2 = 0 (dropping the component "
            "largest at the reference); ablations: all six, or dropping n_z",
        ),
        ("reduced equations", "two components of n_f1 x n_f2 = 0 with u2, v2, phi2 from eq 39-44 (library tca)"),
        (
            "step control",
            "plain: full steps; damped: Armijo backtracking, up to 12 halvings; domain: damped + "
            "projection on the flank boxes (u limits moved in by domain_margin x height)",
        ),
        (
            "seeded / robust",
            "seeded: plain Newton from (u1, v1) and eq 39-44's u2, v2, phi2; robust: start guarded "
            "onto the mapped part of flank 1 and moved onto the contact line (1-D solve of the "
            "axial component of n1 x n2), then plain Newton (either formulation)",
        ),
        ("iteration limit", str(p["maxiter"])),
        ("tolerance", f"Euclidean residual norm < {p['tol']:g} (mm for positions, 1 for normals)"),
        (
            "converged (correct)",
            f"residual < tol AND equal to the verified reference (|du|,|dv| < {p['match_tol_mm']:g} mm, "
            f"|dphi2| < {p['match_tol_rad']:g} rad mod 2 pi) AND inside both flanks",
        ),
        (
            "reference",
            "reduced solve from the line-of-action start, confirmed by the conventional solve from its "
            f"seed; they agree to {p['agree_tol_mm']:g} mm / {p['agree_tol_rad']:g} rad",
        ),
        ("iterations", "mean over correct starts; robust variants include the iterations of the 1-D stage"),
        ("time", "wall time of the vectorised batch / n (one process); timing.csv adds one-start-per-call loops"),
        (
            "n starts",
            f"Table 10: {p['n_starts']}; sec 6.1 and Table 9: {p['n_starts_sec61']}; "
            f"window sweep: {p['n_starts_window']}",
        ),
    ]
    items += bevel_protocol_items(p)
    run_info = pd.DataFrame([{k: (str(v) if isinstance(v, (list, dict)) else v) for k, v in settings.items()}])
    return dict(protocol=pd.DataFrame(items, columns=["item", "value"]), run_info=run_info)


_DIR = "temirkhan2023"


JOBS = {
    "convergence": Job(
        convergence_tables,
        {
            n: f"{_DIR}/{n}.csv"
            for n in (
                "convergence",
                "convergence_detail",
                "agreement",
                "references",
                "starts_table10",
                "starts_sec61",
                "starts_helical",
                "timing",
                "bevel_references",
                "bevel_accuracy",
            )
        },
        "every convergence study, its per-start tables, the verified references and the Table 10 timing",
        priority=22,
    ),
    "te": Job(
        te_tables,
        {n: f"{_DIR}/{n}.csv" for n in ("te_summary", "te_curves", "te_cycle", "te_readings")},
        "TE and path of contact (spur sec 4.1, helical Tables 3-4) and the readings of Delta phi_max",
        priority=12,
    ),
    "te_sensitivity": Job(
        te_sensitivity,
        {"te_sensitivity": f"{_DIR}/te_sensitivity.csv"},
        "log-crown a2 and misalignment pivot sensitivity",
    ),
    "crowning_areas": Job(
        crowning_areas_table,
        {"crowning_areas": f"{_DIR}/crowning_areas.csv"},
        "TE areas S_c, S_p, S_l at 0.2 deg (first printed amounts; 6 TE studies)",
    ),
    "stress": Job(
        stress_table,
        {"stress": f"{_DIR}/stress.csv"},
        "Hertz stress ratios of the crowned helical 40/37 pair under out-of-plane misalignment (sec 4.2, Fig 29)",
        priority=8,
    ),
    "shift_common_angle": Job(
        shift_common_angle_table,
        {"shift_common_angle": f"{_DIR}/shift_common_angle.csv"},
        "contact shift of the helical 40/37 and spur 25/25 pairs at a common angle and crown (conclusions)",
    ),
    "path_guess": Job(
        path_guess_table,
        {"path_guess": f"{_DIR}/path_guess.csv"},
        "sec 6.1 path study: conventional TCA along the path from phi2 starts offset 0.03..0.3 rad",
        priority=4,
    ),
    "bevel_straight": Job(
        straight_contact_tables,
        {n: f"{_DIR}/{n}.csv" for n in ("bevel_straight_summary", "bevel_straight_curves")},
        "straight bevel 39/32 (sec 5.1): TE continuity with and without relief, lead crown and contact pressure, crown types",
        priority=10,
    ),
    "bevel_spiral": Job(
        spiral_contact_tables,
        {n: f"{_DIR}/{n}.csv" for n in ("bevel_spiral_summary", "bevel_spiral_curves")},
        "spiral bevel 17/17 (sec 5.2): TE under angular and linear errors, stress and contact deviation (Fig 53 sweep)",
        priority=10,
    ),
    "errata": Job(errata_table, {"errata": f"{_DIR}/errata.csv"}, "numbers behind the errata"),
    "protocol": Job(
        protocol_table,
        {"protocol": f"{_DIR}/protocol.csv", "run_info": f"{_DIR}/run_info.csv"},
        "the convergence protocol as run and the settings used",
    ),
}
