"""Seed 000, chapter 5: tooth contact analysis of curvilinear-tooth cylindrical gears cut by a ZA
hob, the kinematic-error (KE) tables 5.2-5.9 and the claims of sections 5.4-5.6.

Tooth surfaces: :class:`gearrep.surfaces.hob.GeneratedGear` (the two-parameter envelope of ch. 4,
set-up verified by ``hobcut_curvature`` on Tables 4.3/4.4). TCA: the 9-unknown tangency system of
eq 5.1-5.11 (:mod:`gearrep.tca`: the envelope-pair TCA, and the hob-cut pair with its continuation
and KE table, ``hobbed_*``; the printed matrices in :mod:`.model`); each Example is reached from the ideal 110/113 pair by continuation in the
assembly errors (and in R_cg for 110/110), then traced along phi1'. KE (eq 5.12) is re-zeroed at phi1' = 0 like the printed tables, in arc-seconds. Contact
ellipses by curvature analysis and by surface topology (:mod:`.ellipses`). The findings
(ill-conditioned Z, several tangencies of the 110/110 pair, the Z_g sign erratum) are told in
``notebooks/hobcut_tca.ipynb``.

Face (:mod:`gearrep.replications._face`): one job per KE table (each solves only its Example)
and one per study.
"""

from __future__ import annotations

import pandas as pd

from ... import settings as _s
from .._face import FACE, run_jobs
from .bench import bench_cases  # noqa: F401  (face: in __all__ through *FACE)
from .checks import CHECK_PREFIXES, SURVIVING, checks  # noqa: F401  (face: in __all__ through *FACE)
from .design import TABLE_EXAMPLE, Design, params_from_published, phi1_grid, validate  # noqa: F401  (face)
from .ellipses import contact_ellipses, pitch_point_ratio, topology_pattern
from .studies import JOBS, compute_case

__all__ = [
    *FACE,  # the replication face (gearrep.replications._face)
    "Design",
    "TABLE_EXAMPLE",
    "SURVIVING",
    "CHECK_PREFIXES",
    "compute_case",
    "phi1_grid",
    "contact_ellipses",
    "pitch_point_ratio",
    "topology_pattern",
]

SEED = "000"

_n, _i = _s.number, _s.integer
SETTINGS = _s.declare(
    tol=_n(
        1e-11,
        "mm",
        "residual of the 9-equation TCA system (mm / unit normals); bench: 1e-8 already meets the KE "
        "target, 1e-11 kept so that no check sits within the solver error of its printed-precision boundary",
        gt=0.0,
        le=1e-6,
    ),
    phi1_start_deg=_n(-10.0, "deg", "Tables 5.2-5.9: phi1' from -10 deg", ge=-30.0, le=0.0),
    phi1_end_deg=_n(10.0, "deg", "Tables 5.2-5.9: phi1' to +10 deg", ge=0.0, le=30.0),
    phi1_step_deg=_n(
        2.0,
        "deg",
        "Tables 5.2-5.9: phi1' in 2-deg steps (the grid must hit 0, the tables' zero of KE)",
        gt=0.0,
        le=60.0,
    ),
    continuation_steps=_i(
        4,
        "1",
        "assembly errors (and R_cg 113 -> 110 for Tables 5.2/5.3) in this many "
        "warm-started solves (1 step fails for Table 5.3)",
        ge=1,
        le=100,
    ),
    sensitivity_step_mm=_n(
        0.01, "mm", "central-difference step in R_cp, R_cg for the ill-conditioning of Z", gt=0.0, le=1.0
    ),
    hob_radii_mm=_s.array(
        [25.0, 30.0, 40.0, 50.0, 60.0],
        "mm",
        "Fig 5.5 sweep of the hob pitch radius",
        _n(None, "mm", "", ge=10.0, le=500.0),
        min_items=2,
    ),
    tangency_gap_threshold_mm=_n(
        1e-5,
        "mm",
        "largest interpenetration at which a tangency still counts as a contact (Example 5.1: the printed mid-face "
        "tangency is 2.9e-6 mm inside the first contact). Physical scales: the examples' elastic approach is 0.00632 mm "
        "(params_000_table5_1.csv, paint_thickness), 632 times larger; flank roughness is 0.13 um rms for honed and "
        "run-in flanks, the finest process of the AGMA scoring table (5-15 uin), 0.5-2 um for hobbed ones (20-80 uin), "
        "13-200 times larger. At most 1e-4 mm (the finest roughness) and a tenth of the elastic approach",
        gt=0.0,
        le=1e-4,
    ),
    contact_ratio_window_deg=_n(30.0, "deg", "search window of the tip crossings (eq 5.13)", ge=10.0, le=60.0),
    ellipse_R_cp_mm=_s.array(
        [55.0, 110.0, 220.0, 440.0],
        "mm",
        "Fig 5.7: a/b at the pitch point against R_c",
        _n(None, "mm", "", ge=20.0, le=1e5),
        min_items=2,
    ),
    ellipse_R_gap_mm=_n(
        1.0, "mm", "Fig 5.7 pairing R_cg = R_cp + 1 mm (our reconstruction, the text gives no R_cg)", gt=0.0, le=100.0
    ),
    topology_phi1_deg=_s.array(
        [-8.0, 0.0, 8.0],
        "deg",
        "Fig 5.8: surface-topology pattern at these points of the Example 5.3 path (on the phi1' grid)",
        _n(None, "deg", "", ge=-30.0, le=30.0),
    ),
    topology_n_dirs=_i(
        8,
        "1",
        "tangent-plane directions per point (a multiple of 4: both ellipse axes included; ~0.3 s per point)",
        ge=4,
        le=360,
    ),
)

DESIGN_DATA = ["params_000_*.csv"]
CHECK_DATA = ["values_000_T5.*.csv", "values_000_text.csv", "claims_000.csv"]


CHECK_OUTPUTS = {"checks": "checks/hobcut_tca.csv"}
FIGURES = {
    "ke": "hobcut_tca/figures/ke_tables.png",
    "zp": "hobcut_tca/figures/contact_position_tables.png",
    "hob": "hobcut_tca/figures/ke_vs_hob_radius.png",
    "ab": "hobcut_tca/figures/a_over_b_vs_R_c.png",
}
REPORT_FIGURES = ["ke", "zp"]


def run(settings: dict, design: Design, jobs=None) -> dict[str, pd.DataFrame]:
    """Tables of every job (or of the named ``jobs``) in one process."""
    validate(settings, design)
    return run_jobs(JOBS, settings, design, jobs)
