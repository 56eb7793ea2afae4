"""Design data of seed 000 ch. 4: the Table 5.1 pinion and hob (:mod:`.._hobcut_design`), the
chapter's cutter radii and working range, read from the published parameters, and the cross-field
checks of the settings."""

from __future__ import annotations

from dataclasses import asdict, dataclass

import numpy as np
import pandas as pd

from ...published import values_by
from ...settings import SettingError
from .._hobcut_design import table_5_1

__all__ = ["Design", "params_from_published", "merged", "validate"]

SEED = "000"


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
    t51 = table_5_1(published.params)  # the Table 5.1 pinion, gear and hob, shared with hobcut_tca
    design = Design(
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
    _check_design(design)
    return design


def _check_design(design: Design) -> None:
    r_p = 0.5 * design.module_mm * design.n_teeth
    for name, v, lo, hi in (
        ("module_mm", design.module_mm, 0.1, 100.0),
        ("pressure_angle_deg", design.pressure_angle_deg, 5, 40),
        ("hob_pitch_radius_mm", design.hob_pitch_radius_mm, design.module_mm, 1000.0),
        ("tip_radius_mm", design.tip_radius_mm, r_p, r_p + 3 * design.module_mm),
        ("R_c_small_mm", design.R_c_small_mm, 1.0, 1e7),
        ("R_c_large_mm", design.R_c_large_mm, 1.0, 1e7),
        ("l1_end_mm", design.l1_end_mm, 0.0, 100.0),
        ("face_width_mm", design.face_width_mm, 0.1, 1000.0),
        ("ellipse_delta_mm", design.ellipse_delta_mm, 1e-7, 1.0),
    ):
        if not (np.isfinite(v) and lo <= v <= hi):
            raise ValueError(f"hobcut_curvature design: {name} = {v!r} outside [{lo:g}, {hi:g}]")


def merged(settings: dict, design: Design) -> dict:
    """One dict of the design and the settings (what the study functions take)."""
    return {**asdict(design), **settings}


def validate(settings: dict, design: Design) -> None:
    """Cross-field checks: the R_c sweep has distinct radii; the tip row lies above the last row."""
    rc = settings["rc_sweep_mm"]
    if len(set(rc)) != len(rc):
        raise SettingError(f"hobcut_curvature.rc_sweep_mm: got {rc!r}; allowed: distinct radii >= 1 mm")
    _check_design(design)
