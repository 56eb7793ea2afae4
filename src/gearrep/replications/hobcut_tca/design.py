"""Design data of seed 000 ch. 5: the Examples' design and assembly data, the Table 5.1 pair and hob
(:mod:`.._hobcut_design`), the paint thickness and the Fig 5.7 pressure angles, read from the
published parameters; the KE tables' Examples, the phi1' grid of the settings and the cross-field
checks of the settings."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from ... import tca
from ...settings import SettingError
from ...surfaces.hob import PairDesign
from .._hobcut_design import table_5_1

__all__ = ["Design", "TABLE_EXAMPLE", "phi1_grid", "params_from_published", "validate"]

SEED = "000"


#: KE table (seed 000 Table 5.x) -> the Example (sec 5.5) whose assembly it lists
TABLE_EXAMPLE = {
    "5.2": "5.1",
    "5.3": "5.2",
    "5.4": "5.4",
    "5.5": "5.5",
    "5.6": "5.6",
    "5.7": "5.7",
    "5.8": "5.8",
    "5.9": "5.9",
}


@dataclass(frozen=True)
class Design:
    """Published design data of ch. 5: ``cases`` {example: {R_cp_mm, R_cg_mm, dgamma_h_arcmin,
    dgamma_v_arcmin, dC_mm, dZ_mm}}, the paint thickness ``delta_mm`` (sec 5.4.2), the Fig 5.7
    pressure angles ``ellipse_alpha_deg`` and the Table 5.1 pinion, gear and hob ``gears``."""

    cases: dict
    delta_mm: float
    ellipse_alpha_deg: tuple
    gears: PairDesign


def phi1_grid(settings: dict) -> np.ndarray:
    """phi1' [rad] of the settings' grid, phi1_start_deg to phi1_end_deg in phi1_step_deg steps
    (:func:`gearrep.tca.hobbed_phi1_grid`; 0 exactly on it)."""
    return tca.hobbed_phi1_grid(settings["phi1_start_deg"], settings["phi1_end_deg"], settings["phi1_step_deg"])


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
    :func:`gearrep.replications._hobcut_design.table_5_1`)."""
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
        raise ValueError(f"hobcut_tca design: paint_thickness must be in (0, 1) mm, got {delta!r}")
    if not all(10 <= a <= 35 for a in alpha):
        raise ValueError(f"hobcut_tca design: fig5_7 pressure angles must be in [10, 35] deg, got {alpha!r}")
    return Design(cases=_cases(params), delta_mm=delta, ellipse_alpha_deg=alpha, gears=_pair_design(params))


def validate(settings: dict, design: Design) -> None:
    """Cross-field checks: the phi1' grid contains 0 (the tables' zero of KE), the topology
    points lie on it, topology_n_dirs is a multiple of 4, every Example is in the design."""
    err = SettingError
    a, b, step = settings["phi1_start_deg"], settings["phi1_end_deg"], settings["phi1_step_deg"]
    if not a < b:
        raise err(f"hobcut_tca.phi1_end_deg: got {b}; allowed: > phi1_start_deg = {a}")
    if step > b - a or abs(round(-a / step) * step + a) > 1e-9:
        raise err(f"hobcut_tca.phi1_step_deg: got {step}; allowed: in (0, {b - a}] with the grid from {a} hitting 0")
    grid = np.degrees(phi1_grid(settings))
    for x in settings["topology_phi1_deg"]:
        if not np.any(np.isclose(grid, x)):
            raise err(f"hobcut_tca.topology_phi1_deg: got {x}; allowed: a point of the phi1 grid {grid.tolist()}")
    if settings["topology_n_dirs"] % 4:
        raise err(
            f"hobcut_tca.topology_n_dirs: got {settings['topology_n_dirs']}; allowed: a multiple of 4 in [4, 360]"
        )
    missing = sorted((set(TABLE_EXAMPLE.values()) | {"5.3"}) - set(design.cases))
    if missing:
        raise ValueError(f"hobcut_tca design: the published cases lack examples {missing}")
    thr = settings["tangency_gap_threshold_mm"]
    if not thr <= design.delta_mm / 10:
        raise err(
            f"hobcut_tca.tangency_gap_threshold_mm: got {thr}; allowed: <= a tenth of the elastic approach "
            f"({design.delta_mm / 10:g} mm), far below it"
        )
    half = design.gears.face_width_mm / 2  # a circular tooth trace must span the face
    for ex, case in design.cases.items():
        if set(case) != _CASE_KEYS:
            raise ValueError(f"hobcut_tca design: case {ex!r} must have keys {sorted(_CASE_KEYS)}")
        for k in ("R_cp_mm", "R_cg_mm"):
            if not case[k] > half:
                raise ValueError(
                    f"hobcut_tca design: case {ex!r} {k} = {case[k]!r}; allowed: > face width / 2 = {half:g} mm"
                )
    for r in settings["ellipse_R_cp_mm"]:
        if not r > half:
            raise err(f"hobcut_tca.ellipse_R_cp_mm: got {r}; allowed: > face width / 2 = {half:g} mm")
