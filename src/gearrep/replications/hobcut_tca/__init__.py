"""Seed 000, chapter 5: tooth contact analysis of curvilinear-tooth cylindrical gears cut by a ZA
hob, the kinematic-error (KE) tables 5.2-5.9 and the claims of sections 5.4-5.6.

Tooth surfaces: :class:`gearrep.surfaces.hob.GeneratedGear` (the two-parameter envelope of ch. 4,
set-up verified by ``tseng_curvature`` on Tables 4.3/4.4). TCA: the 9-unknown tangency system of
eq 5.1-5.11 (:mod:`gearrep.tca`: the envelope-pair TCA, and the hob-cut pair with its continuation
and KE table, ``hobbed_*``; the printed matrices in :mod:`.model`); each Example is reached from the ideal 110/113 pair by continuation in the
assembly errors (and in R_cg for 110/110), then traced along phi1'. KE (eq 5.12) is re-zeroed at phi1' = 0 like the printed tables, in arc-seconds. Contact
ellipses by curvature analysis and by surface topology (:mod:`.ellipses`). The findings
(ill-conditioned Z, several tangencies of the 110/110 pair, the Z_g sign erratum) are told in
``notebooks/tseng_tca.ipynb``.

Face (:mod:`gearrep.replications._face`): one job per KE table (each solves only its Example)
and one per study.
"""

from __future__ import annotations

from functools import partial

import numpy as np
import pandas as pd

from ... import settings as _s
from ...surfaces.hob import PairDesign
from ...tca import clear_hobbed_start_cache, ke_table, require_converged
from .._face import FACE, Job, run_jobs
from .._seed000 import table_5_1
from . import studies
from .checks import CHECK_PREFIXES, SURVIVING, check_records
from .ellipses import contact_ellipses, pitch_point_ratio, topology_pattern
from .studies import TABLE_EXAMPLE, Design, compute_case, phi1_grid

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
_CASE_KEYS = {"R_cp_mm", "R_cg_mm", "dgamma_h_arcmin", "dgamma_v_arcmin", "dC_mm", "dZ_mm"}


def _cases(params: pd.DataFrame) -> dict:
    """{example: case} from the rows of params_000_examples.csv (a blank parameter is 0, as its
    note says; angles in arc-minutes or degrees as printed)."""
    sel = params[(params["seed"].astype(str) == SEED) & params["file"].astype(str).str.contains("examples")]
    if sel.empty:
        raise ValueError("published params lack the rows of params_000_examples.csv")
    out = {}
    for ex, g in sel.groupby(sel["example"].astype(str)):
        d = {
            "R_cp_mm": np.nan,
            "R_cg_mm": np.nan,
            "dgamma_h_arcmin": 0.0,
            "dgamma_v_arcmin": 0.0,
            "dC_mm": 0.0,
            "dZ_mm": 0.0,
        }
        for value, name, unit in zip(g["value"].tolist(), g["parameter"].tolist(), g["unit"].tolist()):
            v = float(value) if pd.notna(value) and str(value) != "" else 0.0
            name, unit = str(name), str(unit)
            if name in ("R_cp", "R_cg", "dC", "dZ"):
                d[f"{name}_mm"] = v
            elif name in ("dgamma_h", "dgamma_v"):
                d[f"{name}_arcmin"] = v * (60.0 if unit == "deg" else 1.0)
        out[ex] = d
    ex3 = out.get("5.3", {})  # Examples 5.4-5.9: "design as Example 5.3" (R_cp, R_cg printed anyway)
    for ex, d in out.items():
        for k in ("R_cp_mm", "R_cg_mm"):
            if not np.isfinite(d[k]) and k in ex3:
                d[k] = ex3[k]
        if not (np.isfinite(d["R_cp_mm"]) and np.isfinite(d["R_cg_mm"])):
            raise ValueError(f"example {ex}: R_cp / R_cg not found in the published parameters")
    return out


def _pair_design(params: pd.DataFrame) -> PairDesign:
    """The Table 5.1 pinion, gear and hob (read and checked once for both seed-000 studies:
    :func:`gearrep.replications._seed000.table_5_1`)."""
    t = table_5_1(params)
    return PairDesign(t.n_pinion, t.n_gear, t.face_width_mm, t.hob())


def params_from_published(published) -> Design:
    """The Examples' design and assembly data (params_000_examples.csv), the Table 5.1 pair and
    hob, the paint thickness and the Fig 5.7 pressure angles (params_000_table5_1.csv) of a loaded
    :class:`gearrep.published.Published`."""
    params = published.params
    sel = params[params["seed"].astype(str) == SEED].set_index("parameter")["value"]
    try:
        delta = float(sel["paint_thickness"])
        alpha = (float(sel["fig5_7_pressure_angle_1"]), float(sel["fig5_7_pressure_angle_2"]))
    except KeyError as e:
        raise ValueError(f"published params lack the seed-000 ellipse parameter {e}") from None
    if not 0 < delta < 1:
        raise ValueError(f"tseng_tca design: paint_thickness must be in (0, 1) mm, got {delta!r}")
    if not all(10 <= a <= 35 for a in alpha):
        raise ValueError(f"tseng_tca design: fig5_7 pressure angles must be in [10, 35] deg, got {alpha!r}")
    return Design(cases=_cases(params), delta_mm=delta, ellipse_alpha_deg=alpha, gears=_pair_design(params))


def validate(settings: dict, design: Design) -> None:
    """Cross-field checks: the phi1' grid contains 0 (the tables' zero of KE), the topology
    points lie on it, topology_n_dirs is a multiple of 4, every Example is in the design."""
    err = _s.SettingError
    a, b, step = settings["phi1_start_deg"], settings["phi1_end_deg"], settings["phi1_step_deg"]
    if not a < b:
        raise err(f"tseng_tca.phi1_end_deg: got {b}; allowed: > phi1_start_deg = {a}")
    if step > b - a or abs(round(-a / step) * step + a) > 1e-9:
        raise err(f"tseng_tca.phi1_step_deg: got {step}; allowed: in (0, {b - a}] with the grid from {a} hitting 0")
    grid = np.degrees(phi1_grid(settings))
    for x in settings["topology_phi1_deg"]:
        if not np.any(np.isclose(grid, x)):
            raise err(f"tseng_tca.topology_phi1_deg: got {x}; allowed: a point of the phi1 grid {grid.tolist()}")
    if settings["topology_n_dirs"] % 4:
        raise err(f"tseng_tca.topology_n_dirs: got {settings['topology_n_dirs']}; allowed: a multiple of 4 in [4, 360]")
    missing = sorted((set(TABLE_EXAMPLE.values()) | {"5.3"}) - set(design.cases))
    if missing:
        raise ValueError(f"tseng_tca design: the published cases lack examples {missing}")
    thr = settings["tangency_gap_threshold_mm"]
    if not thr <= design.delta_mm / 10:
        raise err(
            f"tseng_tca.tangency_gap_threshold_mm: got {thr}; allowed: <= a tenth of the elastic approach "
            f"({design.delta_mm / 10:g} mm), far below it"
        )
    half = design.gears.face_width_mm / 2  # a circular tooth trace must span the face
    for ex, case in design.cases.items():
        if set(case) != _CASE_KEYS:
            raise ValueError(f"tseng_tca design: case {ex!r} must have keys {sorted(_CASE_KEYS)}")
        for k in ("R_cp_mm", "R_cg_mm"):
            if not case[k] > half:
                raise ValueError(
                    f"tseng_tca design: case {ex!r} {k} = {case[k]!r}; allowed: > face width / 2 = {half:g} mm"
                )
    for r in settings["ellipse_R_cp_mm"]:
        if not r > half:
            raise err(f"tseng_tca.ellipse_R_cp_mm: got {r}; allowed: > face width / 2 = {half:g} mm")


def _ke_job(settings, design, *, example: str, name: str) -> dict:
    table = studies.ke_table_two_tangencies if name in TWO_TANGENCY_TABLES else studies.ke_table_of
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
            {name: f"tseng/{name}.csv"},
            f"Table {tab} (Example {TABLE_EXAMPLE[tab]}) alone",
        )
        for name, tab in _KE.items()
    },
    "ke_example_5_3": Job(
        partial(_ke_job, example="5.3", name="ke_example_5_3"),
        {"ke_example_5_3": "tseng/ke_example_5_3.csv"},
        "Example 5.3 (ideal 110/113, no table)",
    ),
    **{
        name: Job(
            _one(getattr(studies, name), name),
            {name: f"tseng_tca/{name}.csv"},
            getattr(studies, name).__doc__,
            priority,
        )
        for name, priority in (  # priority: about the seconds of the long jobs (.._face.Job)
            ("sensitivity", 10),
            ("contact_ratio", 2),
            ("ke_vs_hob_radius", 4),
            ("ellipses_example_5_3", 0),
            ("ellipse_ratio", 6),
            ("topology_example_5_3", 5),
        )
    },
}

CHECK_OUTPUTS = {"checks": "checks/tseng_tca.csv"}
FIGURES = {
    "ke": "tseng_tca/figures/ke_tables.png",
    "zp": "tseng_tca/figures/contact_position_tables.png",
    "hob": "tseng_tca/figures/ke_vs_hob_radius.png",
    "ab": "tseng_tca/figures/a_over_b_vs_R_c.png",
}
REPORT_FIGURES = ["ke", "zp"]


def run(settings: dict, design: Design, jobs=None) -> dict[str, pd.DataFrame]:
    """Tables of every job (or of the named ``jobs``) in one process."""
    validate(settings, design)
    return run_jobs(JOBS, settings, design, jobs)


def checks(tables: dict, published) -> dict:
    """{"checks": records of every chapter-5 value and claim} (:func:`.checks.check_records`)."""
    return {"checks": check_records(tables, published)}


def bench_cases(settings: dict, design: Design) -> dict[str, dict]:
    """Cases for workflow/scripts/bench_replication.py: one KE table (the assembly of Table 5.4,
    Example 5.4, 11 positions), computed cold (ideal start not cached), over the solver tolerance
    and the number of continuation steps. Errors against the most accurate setting: max |KE -
    KE_ref| [arcsec] and max |Z_p - Z_p,ref| [mm]; targets a tenth of the printed half-unit."""
    validate(settings, design)
    phi1 = phi1_grid(settings)
    case = design.cases[TABLE_EXAMPLE["5.4"]]
    grid = [{"tol": t, "continuation_steps": s} for t in (1e-6, 1e-8, 1e-10, 1e-11, 1e-12) for s in (1, 2, 4)]
    reference = {"tol": 1e-13, "continuation_steps": 8}

    def run_one(setting):
        clear_hobbed_start_cache()
        pair, sol = compute_case(design.gears, case, phi1, tol=setting["tol"], steps=setting["continuation_steps"])
        require_converged(sol, f"bench {setting}")
        return ke_table(sol, pair.ratio)

    current = {"tol": settings["tol"], "continuation_steps": settings["continuation_steps"]}
    common = {"run": run_one, "settings": grid, "reference": reference, "error_target": 5e-5, "current": current}
    return {
        "ke_table_5_4_KE": {
            **common,
            "error": lambda r, ref: float(np.max(np.abs(r["KE_arcsec"] - ref["KE_arcsec"]))),
            "error_unit": "arcsec",
        },
        "ke_table_5_4_Zp": {
            **common,
            "error": lambda r, ref: float(np.max(np.abs(r["Z_p_mm"] - ref["Z_p_mm"]))),
            "error_unit": "mm",
        },
    }
