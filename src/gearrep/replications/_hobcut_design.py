"""Design data shared by the two studies of seed 000 (``hobcut_curvature``, ch. 4, and ``hobcut_tca``,
ch. 5): the pinion, gear and ZA hob of Table 5.1, read and checked once from the published
parameters (``params_000_table5_1.csv``); the hob is built by :func:`gearrep.surfaces.hob.za_hob`."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from ..published import param_table
from ..surfaces.hob import ZAHob, za_hob

__all__ = ["TABLE_5_1", "Table51", "table_5_1"]

TABLE_5_1 = "params_000_table5_1.csv"


@dataclass(frozen=True)
class Table51:
    """The printed Table 5.1 inputs the models use (checked by :func:`table_5_1`)."""

    module_mm: float
    pressure_angle_deg: float
    hob_pitch_radius_mm: float
    n_pinion: int
    n_gear: int
    face_width_mm: float
    pinion_outside_diameter_mm: float

    def hob(self, variant: str = "axial") -> ZAHob:
        """The Table 5.1 hob (:func:`gearrep.surfaces.hob.za_hob`)."""
        return za_hob(self.module_mm, self.pressure_angle_deg, self.hob_pitch_radius_mm, variant)


def table_5_1(params: pd.DataFrame) -> Table51:
    """Table 5.1 from the published parameters (a loaded ``Published.params``).

    The hob needs its normal module, normal pressure angle and pitch radius (single start: the
    lead angle follows and must agree with the printed one at its 3 decimals); both members are
    cut by it (their module and pressure angle must equal the hob's), with the standard addendum
    the library assumes (printed pitch radii and outside diameters must agree) and one face width
    (the tangency search takes one for both members). Values outside their range or inconsistent
    with this model are refused with a ValueError naming the published key."""
    try:
        v = param_table(params, TABLE_5_1, "5.1")
    except KeyError:
        raise ValueError(f"published params lack the rows of {TABLE_5_1}") from None

    def get(key, lo=-np.inf, hi=np.inf, integer=False):
        if key not in v:
            raise ValueError(f"seed 000 design: {TABLE_5_1} lacks {key}")
        x = float(v[key])
        if not (np.isfinite(x) and lo <= x <= hi) or (integer and x != int(x)):
            kind = "an integer" if integer else "a number"
            raise ValueError(f"seed 000 design: {key} ({TABLE_5_1}) = {x!r}; allowed: {kind} in [{lo:g}, {hi:g}]")
        return int(x) if integer else x

    m = get("hob_normal_module", 0.1, 100.0)
    alpha = get("hob_normal_pressure_angle", 5.0, 40.0)
    r_h = get("hob_pitch_radius", m, 1000.0)
    n = {k: get(f"N_{k}", 4, 10000, integer=True) for k in ("pinion", "gear")}
    width = get("pinion_face_width", 0.1, 1000.0)
    out = Table51(m, alpha, r_h, n["pinion"], n["gear"], width, get("pinion_outside_diameter"))
    derived = {"hob_lead_angle": (np.degrees(out.hob().lead_angle_rad), 5e-4), "gear_face_width": (width, 0.0)}
    for k in ("pinion", "gear"):
        derived[f"{k}_normal_module"] = (m, 0.0)
        derived[f"{k}_normal_pressure_angle"] = (alpha, 0.0)
        derived[f"{k}_pitch_radius"] = (m * n[k] / 2, 0.0)
        derived[f"{k}_outside_diameter"] = (m * (n[k] + 2), 0.0)
    for key, (want, tol) in derived.items():
        got = get(key)
        if abs(got - want) > tol + 1e-9 * abs(want):
            raise ValueError(
                f"seed 000 design: {key} ({TABLE_5_1}) = {got!r}; allowed: {want:.6g} (+-{tol:g}), which one "
                "single-start hob cutting both members with standard addendum and one face width implies"
            )
    return out
