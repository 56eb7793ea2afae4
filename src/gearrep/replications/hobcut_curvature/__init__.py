"""Seed 000, chapter 4: principal curvatures of the curvilinear-tooth gear cut by a ZA worm hob
(a two-parameter envelope), Tables 4.2-4.5, and the chapter's claims.

Model and methods in :mod:`.studies` (the generated surfaces of :mod:`gearrep.surfaces.hob`,
curvatures by direct differential geometry and by the chapter's two-parameter relations of
:mod:`gearrep.curvature_relations`). The findings (table assignment, sign conventions, eq 4.40
as printed vs the true ZA hob, undercut towards the face ends, the spur limit, the e_s_z erratum,
the rounded l_1 column) are told in ``notebooks/tseng_curvature.ipynb``.

Face (:mod:`gearrep.replications._face`): one job per curvature table and one per study; each
job recomputes the l_1 grid (one Newton solve).
"""

from __future__ import annotations

from dataclasses import asdict, dataclass

import numpy as np
import pandas as pd

from ... import settings as _s
from ...published import values_by
from .._face import FACE, Job, run_jobs
from .._seed000 import table_5_1
from . import studies
from .checks import SURVIVING, check_records
from .claims import normalise
from .studies import TABLE_COLUMNS, TABLES, curvature_tables, direct_curvatures, l1_grid

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


@dataclass(frozen=True)
class Design:
    """Published design data of ch. 4: the Table 5.1 pinion and hob, R_c of Examples 4.1/4.2, the
    last l1 row (sec 4.5), the face width, the Table 5.1 gear and the separation of sec 5.4.2 (for
    the informative ellipses), and the rows of the printed tables (number, decimals of l1)."""

    module_mm: float
    pressure_angle_deg: float
    hob_pitch_radius_mm: float
    n_teeth: int
    tip_radius_mm: float
    R_c_small_mm: float
    R_c_large_mm: float
    l1_end_mm: float
    face_width_mm: float
    ellipse_n_gear: int
    ellipse_delta_mm: float
    ellipse_pressure_angles_deg: tuple
    n_rows: int
    l1_printed_decimals: int


def _rows_of_table(values: pd.DataFrame, source: str) -> tuple[int, int]:
    """(number of rows, decimals of the printed l1) of a printed curvature table."""
    rows = values.loc[(values["seed"].astype(str) == SEED) & (values["source"] == source), "row"].unique()
    if len(rows) < 2:
        raise ValueError(f"published values lack the rows of {source}")
    decimals = {len(r.split("=")[1].partition(".")[2]) for r in rows}
    if len(decimals) != 1:
        raise ValueError(f"{source}: l1 printed with different decimals {sorted(decimals)}")
    return len(rows), decimals.pop()


def params_from_published(published) -> Design:
    """The design of ch. 4 from a loaded :class:`gearrep.published.Published` (params_000_*.csv
    and the row keys of Table 4.3)."""
    found = values_by(published.params, ["seed", "example", "parameter"])

    def val(example, parameter):
        r = found.get((SEED, example, parameter), [])
        if len(r) != 1:
            raise ValueError(f"published parameter {parameter!r} of example {example} not found once")
        return float(r[0])

    n_rows, decimals = _rows_of_table(published.values, "Table 4.3")
    t51 = table_5_1(published.params)  # the Table 5.1 pinion, gear and hob, shared with tseng_tca
    d = Design(
        module_mm=t51.module_mm,
        pressure_angle_deg=t51.pressure_angle_deg,
        hob_pitch_radius_mm=t51.hob_pitch_radius_mm,
        n_teeth=t51.n_pinion,
        tip_radius_mm=t51.pinion_outside_diameter_mm / 2,
        R_c_small_mm=val("4.1", "R_c"),
        R_c_large_mm=val("4.2", "R_c"),
        l1_end_mm=val("4.1", "l1_working_start"),
        face_width_mm=t51.face_width_mm,
        ellipse_n_gear=t51.n_gear,
        ellipse_delta_mm=val("5.3", "separation_threshold"),
        ellipse_pressure_angles_deg=(val("5.1", "fig5_7_pressure_angle_1"), val("5.1", "fig5_7_pressure_angle_2")),
        n_rows=n_rows,
        l1_printed_decimals=decimals,
    )
    _check_design(d)
    return d


def _check_design(d: Design) -> None:
    r_p = 0.5 * d.module_mm * d.n_teeth
    for name, v, lo, hi in (
        ("module_mm", d.module_mm, 0.1, 100.0),
        ("pressure_angle_deg", d.pressure_angle_deg, 5, 40),
        ("hob_pitch_radius_mm", d.hob_pitch_radius_mm, d.module_mm, 1000.0),
        ("tip_radius_mm", d.tip_radius_mm, r_p, r_p + 3 * d.module_mm),
        ("R_c_small_mm", d.R_c_small_mm, 1.0, 1e7),
        ("R_c_large_mm", d.R_c_large_mm, 1.0, 1e7),
        ("l1_end_mm", d.l1_end_mm, 0.0, 100.0),
        ("face_width_mm", d.face_width_mm, 0.1, 1000.0),
        ("ellipse_delta_mm", d.ellipse_delta_mm, 1e-7, 1.0),
    ):
        if not (np.isfinite(v) and lo <= v <= hi):
            raise ValueError(f"tseng_curvature design: {name} = {v!r} outside [{lo:g}, {hi:g}]")


def merged(settings: dict, design: Design) -> dict:
    """One dict of the design and the settings (what the study functions take)."""
    return {**asdict(design), **settings}


def validate(settings: dict, design: Design) -> None:
    """Cross-field checks: the R_c sweep has distinct radii; the tip row lies above the last row."""
    rc = settings["rc_sweep_mm"]
    if len(set(rc)) != len(rc):
        raise _s.SettingError(f"tseng_curvature.rc_sweep_mm: got {rc!r}; allowed: distinct radii >= 1 mm")
    _check_design(design)


def _job(fn, name):
    def compute(settings, design):
        return {name: fn(merged(settings, design))}

    compute.__name__ = compute.__qualname__ = name
    compute.__doc__ = fn.__doc__
    return compute


def _table_job(tab, name):
    def compute(settings, design):
        return {name: studies.curvature_table(merged(settings, design), tab)}

    compute.__name__ = compute.__qualname__ = name
    return compute


_TABLE_NAMES = {f"curvature_table_{t.replace('.', '_')}": t for t in TABLES}
JOBS = {
    **{
        name: Job(_table_job(tab, name), {name: f"tseng/{name}.csv"}, f"Table {tab} alone")
        for name, tab in _TABLE_NAMES.items()
    },
    **{
        name: Job(
            _job(getattr(studies, fn), name),
            {name: f"tseng_curvature/{name}.csv"},
            getattr(studies, fn).__doc__,
            priority,
        )
        for name, fn, priority in (  # priority: about the seconds of the long jobs (.._face.Job)
            ("curvature_detail", "detail", 4),
            ("conventions", "conventions", 4),
            ("assignment", "assignment", 0),
            ("variants", "variants", 0),
            ("face", "face", 0),
            ("rc_sweep", "rc_sweep", 0),
            ("undercut", "undercut", 2),
            ("ellipses", "ellipses", 3),
        )
    },
}

CHECK_OUTPUTS = {"checks": "checks/tseng_curvature.csv"}
FIGURES = {
    "tables": "tseng_curvature/figures/curvature_tables_4_2_to_4_5.png",
    "face": "tseng_curvature/figures/curvature_across_face.png",
    "rc": "tseng_curvature/figures/curvature_vs_Rc.png",
}
REPORT_FIGURES = ["tables", "rc"]


def run(settings: dict, design: Design, jobs=None) -> dict[str, pd.DataFrame]:
    """Tables of every job (or of the named ``jobs``) in one process."""
    validate(settings, design)
    return run_jobs(JOBS, settings, design, jobs)


def checks(tables: dict, published) -> dict:
    """{"checks": records of every value of Tables 4.3/4.4 and the chapter-4 claims}."""
    return {"checks": check_records(tables, published)}


def bench_cases(settings: dict, design: Design) -> dict:
    """Run time against error (contract in workflow/scripts/bench_replication.py).

    * ``four_tables``: the meshing-solve tolerance of the four tables; error = max |change of
      k_s, k_q| (1/mm) against tol = 1e-13; target a tenth of the tightest printed half-unit (k_s
      of Table 4.4, 7 significant digits: 0.5e-10 1/mm -> 5e-12).
    * ``direct_method``: the finite-difference steps of method (a); error = max relative
      difference from method (b) at the 44 rows (acceptance 1e-7; target 1e-8)."""
    validate(settings, design)
    base = merged(settings, design)

    def run_tables(setting):
        t = curvature_tables(dict(base, tol=setting["tol"]))
        return np.concatenate([t[k][["k_s_per_mm", "k_q_per_mm"]].to_numpy() for k in TABLES])

    grid, _ = l1_grid(base)
    exact = curvature_tables(base)

    def run_direct(setting):
        p = dict(base, fd_step_l_mm=setting["fd_step_l_mm"], fd_step_psi_rad=setting["fd_step_psi_rad"])
        out = []
        for tab, (flank, key) in TABLES.items():
            ks, kq = direct_curvatures(p, flank, p[key], grid)
            out.append(
                np.c_[ks / exact[tab]["k_s_per_mm"].to_numpy() - 1, kq / exact[tab]["k_q_per_mm"].to_numpy() - 1]
            )
        return np.concatenate(out)

    steps = [{"fd_step_l_mm": h, "fd_step_psi_rad": h / 10} for h in (1e-1, 3e-2, 1e-2, 3e-3, 1e-3, 1e-4)]
    return {
        "four_tables": {
            "run": run_tables,
            "settings": [{"tol": t} for t in (1e-4, 1e-6, 1e-8, 1e-10, 1e-12)],
            "reference": {"tol": 1e-13},
            "error": lambda res, ref: float(np.max(np.abs(res - ref))),
            "error_unit": "per_mm",
            "error_target": 0.1 * 0.5e-10,
            "current": {"tol": base["tol"]},
        },
        "direct_method": {
            "run": run_direct,
            "settings": steps,
            "reference": steps[-2],
            "error": lambda res, _ref: float(np.max(np.abs(res))),
            "error_unit": "relative",
            "error_target": 1e-8,
            "current": {"fd_step_l_mm": base["fd_step_l_mm"], "fd_step_psi_rad": base["fd_step_psi_rad"]},
        },
    }
