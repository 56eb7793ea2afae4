"""Replication of seed 004 (Ma et al. 2021): contact ellipses of CATT cylindrical gears.

Source: seed 004 sec. 2 (tooth surface eq 1-6, in :mod:`gearrep.surfaces.catt`), sec. 3
(curvature eq 7-20, contact ellipse eq 21-27 with the elastic approach delta), sec. 4 (3D-model
and meshing-test pairs), sec. 5 (Figs 12-15: area S = pi a b along the meshing cycle for module,
tooth-line radius and gear-tooth-number sweeps; tooth thickness vs R_T, eq 28-29). Relative
curvature and the elastic-approach ellipse after Litvin & Fuentes, "Gear Geometry and Applied
Theory", 2nd ed., sec. 9.2-9.3 (= seed 004 eq 21-26); TCA by :func:`gearrep.tca.solve_contact`.

Modules: :mod:`.design` (the paper's data, cross-field checks), :mod:`.assembly` (readings
R1/R2 of the abscissa and middle-section closed forms on the pair mounted by
:func:`gearrep.surfaces.catt.assemble`), :mod:`.contact` (curvatures
and ellipse at TCA points), :mod:`.profiles` and :mod:`.gap` (sections, eq 28-29, thickness, exact
separation), :mod:`.studies` (one function per job), :mod:`.sweeps` and :mod:`.claims` (claim
verdicts and check records), :mod:`.model` (the paper's printed eq 20 and 23-26 as evidence),
:mod:`.bench`. The notebook ``notebooks/ma2021.ipynb`` tells the findings.
"""

from __future__ import annotations

from ... import settings as _s
from .._face import FACE, run_jobs
from .assembly import (  # noqa: F401  (the names tests and the stress suite use)
    PAIR_NAMES,
    PRIMARY,
    READINGS,
    contact_radii,
    reading_to_mesh,
)
from .bench import bench_cases  # noqa: F401  (face: in __all__ through *FACE)
from .checks import checks  # noqa: F401  (face: in __all__ through *FACE)
from .claims import claim_verdicts  # noqa: F401
from .contact import contact_geometry  # noqa: F401
from .design import Design, params_from_published, validate  # noqa: F401
from .studies import JOBS

__all__ = [
    *FACE,  # the replication face (gearrep.replications._face)
    "Design",
    "claim_verdicts",
    "contact_geometry",
    "PAIR_NAMES",
    "READINGS",
    "PRIMARY",
    "contact_radii",
    "reading_to_mesh",
]

SEED = "004"

_deg = _s.number(None, "deg", "", ge=-90, le=90)
SETTINGS = _s.declare(
    step_deg=_s.number(0.5, "deg", "abscissa step of the meshing-cycle grids (paper abscissa)", ge=0.01, le=5),
    off_path_margin_deg=_s.number(
        1.0, "deg", "the grids reach this far beyond the real path (there S_clipped = 0)", ge=0, le=30
    ),
    near_top_deg=_s.number(
        3.0,
        "deg",
        "the last 3 deg of the window are 'near the top' (cliff claims, claims_004); "
        "at most the window width (validate)",
        ge=0.1,
        le=180,
    ),
    near_top_eval_deg=_s.number(
        10.0, "deg", "angle of the near-top orderings (claims_004); inside the window (validate)", ge=-90, le=90
    ),
    tol=_s.number(
        1e-8,
        "mm",
        "TCA Newton residual (mm / unit normal); bench: 1e-8 gives S to 2e-15 relative "
        "(target 1e-7), the same as 1e-10",
        ge=1e-14,
        le=1e-6,
    ),
    maxiter=_s.integer(50, "1", "Newton iterations of the TCA", ge=1, le=1000),
    start_offset_mm=_s.number(
        5.0, "mm", "TCA starts 5 mm off the middle section (the solve must find it)", ge=0, le=30
    ),
    n_tip_edge=_s.integer(
        41,
        "1",
        "tip-edge samples over the face width (ellipse truncation); bench: with "
        "n_clip_nodes 50, S_clipped to 5e-4 of max S (target 1e-3)",
        ge=11,
        le=5001,
    ),
    n_clip_nodes=_s.integer(
        50, "1", "Gauss-Legendre nodes along the long axis (ellipse truncation); bench as n_tip_edge", ge=20, le=20000
    ),
    thickness=_s.group(
        "tooth thickness vs R_T (Fig 14): its gear is not printed, Fig 13's gear is assumed; sections below "
        "min(R_T)/2 (validate)",
        z=_s.integer(21, "1", "tooth number of the Fig 14 gear (Fig 13's pinion assumed)", ge=5, le=10000),
        module=_s.number(8.0, "mm", "module of the Fig 14 gear (Fig 13's assumed)", ge=0.1, le=100),
        face_width=_s.number(80.0, "mm", "face width of the Fig 14 gear (Fig 13's assumed)", gt=0),
        R_T=_s.array(
            [300.0, 400.0, 500.0, 600.0, 800.0],
            "mm",
            "tooth-line radii of Fig 14 (those of Fig 13)",
            _s.number(None, "mm", "", gt=0),
            min_items=2,
        ),
        sections_mm=_s.array(
            [0.0, 15.0, 30.0, 45.0],
            "mm",
            "transverse sections B0..B45 of Fig 14",
            _s.number(None, "mm", "", ge=0),
            min_items=2,
        ),
    ),
    section_check=_s.group(
        "transverse sections of one design against involutes, eq (28)-(29) vs eq (6)",
        design=_s.text(
            "sec4_3d_model", "the design whose pinion is checked: the sec 4 model pair (validate: must be a design)"
        ),
        sections_mm=_s.array(
            [15.0, 30.0, 45.0],
            "mm",
            "offsets of the checked sections (those of Fig 14)",
            _s.number(None, "mm", "", gt=0),
        ),
        n_points=_s.integer(41, "1", "profile points per section, form to tip", ge=5, le=1000),
    ),
    loaded_positions=_s.integer(
        9,
        "1",
        "mesh positions of the sec 4 pair's loaded cycle (claim 004-S4-FE_elliptic_contact, gearrep.ltca): "
        "the footprint is read at the position of the largest flank pressure",
        ge=3,
        le=401,
    ),
    gap_check=_s.group(
        "exact <= delta separation region against the ellipse at a few TCA points",
        design=_s.text("sec4_3d_model", "the design checked: the sec 4 model pair (validate: must be a design)"),
        phi_deg=_s.array([-10.0, 0.0, 10.0], "deg", "paper abscissae (reading R1) of the checked points", _deg),
        n_dirs=_s.integer(
            96,
            "1",
            "rays of the tangent plane per point: resolve the region's centroid (the claim's "
            "criterion); its area is not resolved (sec 4 pair: +14..26 % over pi a b with 96 rays, "
            "+1..3 % with 192, within 0.3 % with 384 and 768)",
            ge=8,
            le=2000,
        ),
    ),
)

DESIGN_DATA = ["params_004_*.csv"]
CHECK_DATA = ["claims_004.csv"]


CHECK_OUTPUTS = {"checks": "checks/ma2021.csv", "claim_readings": "ma2021/claim_readings.csv"}

FIGURES = {
    "fig12": "ma2021/figures/fig12_area_vs_module.png",
    "fig13": "ma2021/figures/fig13_area_vs_RT.png",
    "fig14": "ma2021/figures/fig14_thickness_vs_RT.png",
    "fig15": "ma2021/figures/fig15_area_vs_z2.png",
    "sec4": "ma2021/figures/sec4_example_ellipse.png",
}
REPORT_FIGURES = ["fig15", "fig13"]


def run(settings: dict, design: Design, jobs=None) -> dict:
    """Tables of every job (or of the named ``jobs``), after :func:`validate`."""
    validate(settings, design)
    return run_jobs(JOBS, settings, design, jobs)
