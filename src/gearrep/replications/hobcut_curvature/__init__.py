"""Seed 000, chapter 4: principal curvatures of the curvilinear-tooth gear cut by a ZA worm hob
(a two-parameter envelope), Tables 4.2-4.5, and the chapter's claims.

Model and methods in :mod:`.studies` (the generated surfaces of :mod:`gearrep.surfaces.hob`,
curvatures by direct differential geometry and by the chapter's two-parameter relations of
:mod:`gearrep.curvature_relations`). The findings (table assignment, sign conventions, eq 4.40
as printed vs the true ZA hob, undercut towards the face ends, the spur limit, the e_s_z erratum,
the rounded l_1 column) are told in ``notebooks/hobcut_curvature.ipynb``.

Face (:mod:`gearrep.replications._face`): one job per curvature table and one per study; each
job recomputes the l_1 grid (one Newton solve).
"""

from __future__ import annotations

import pandas as pd

from ... import settings as _s
from .._face import FACE, run_jobs
from .bench import bench_cases  # noqa: F401  (face: in __all__ through *FACE)
from .checks import SURVIVING, checks  # noqa: F401  (face: in __all__ through *FACE)
from .claims import normalise
from .design import Design, merged, params_from_published, validate  # noqa: F401  (face: in __all__ through *FACE)
from .studies import JOBS, TABLE_COLUMNS, TABLES, curvature_tables, direct_curvatures, l1_grid

__all__ = [
    *FACE,  # the replication face (gearrep.replications._face)
    "Design",
    "merged",
    "TABLES",
    "TABLE_COLUMNS",
    "SURVIVING",
    "curvature_tables",
    "direct_curvatures",
    "l1_grid",
    "normalise",
]

SEED = "000"

_n, _i = _s.number, _s.integer
SETTINGS = _s.declare(
    tol=_n(
        1e-12,
        "mm",
        "meshing residual, scaled by max(1, R_c/100 mm); bench: 1e-10 moves k by 2e-11 1/mm "
        "(> 5e-12 target), 1e-12 by 4e-14",
        ge=1e-15,
        le=1e-6,
    ),
    maxiter=_i(50, "1", "Newton iterations of the meshing solves", ge=1, le=1000),
    fd_step_l_mm=_n(
        1e-3,
        "mm",
        "l step of the direct method (a) (tangential second derivatives only); bench: every "
        "step from 1e-4 to 0.1 mm gives 4.57e-12 relative (the floor), same time",
        ge=1e-6,
        le=0.1,
    ),
    fd_step_psi_rad=_n(1e-4, "rad", "psi step of the direct method (a)", ge=1e-8, le=1e-2),
    dl_mm=_n(1e-4, "mm", "central-difference step of d(value)/d(l1) for the rounded-l1 allowance", ge=1e-7, le=1e-2),
    face_n_l=_i(7, "1", "curvature across the face: l1 values", ge=2, le=201),
    face_n_z=_i(21, "1", "curvature across the face: Z_f values", ge=3, le=401),
    rc_sweep_mm=_s.array(
        [50.0, 110.0, 200.0, 500.0, 1000.0, 2000.0, 5000.0, 10000.0, 20000.0, 50000.0],
        "mm",
        "R_c sweep towards the spur limit (evaluated in increasing order)",
        _n(None, "mm", "", ge=1.0),
        min_items=2,
    ),
    undercut_n_l=_i(61, "1", "l1 samples of the singular-point scan", ge=3, le=2001),
    ellipse_pairs=_s.array(
        [[110.0, 110.0], [110.0, 111.0], [110.0, 113.0]],
        "mm",
        "(R_cp, R_cg) of the mid-face pitch-point ellipses (informative; 110/111 kept from the workflow configuration)",
        _s.array(None, "mm", "", _n(None, "mm", "", ge=1.0), min_items=2, max_items=2),
    ),
)

DESIGN_DATA = ["params_000_*.csv", "values_000_T4.3.csv"]
CHECK_DATA = ["values_000_T4.*.csv", "claims_000.csv"]


CHECK_OUTPUTS = {"checks": "checks/hobcut_curvature.csv"}
FIGURES = {
    "tables": "hobcut_curvature/figures/curvature_tables_4_2_to_4_5.png",
    "face": "hobcut_curvature/figures/curvature_across_face.png",
    "rc": "hobcut_curvature/figures/curvature_vs_Rc.png",
}
REPORT_FIGURES = ["tables", "rc"]


def run(settings: dict, design: Design, jobs=None) -> dict[str, pd.DataFrame]:
    """Tables of every job (or of the named ``jobs``) in one process."""
    validate(settings, design)
    return run_jobs(JOBS, settings, design, jobs)
