"""Design data of seed 004 (printed in the paper) and the cross-field checks of the settings.

The design enters only through :func:`params_from_published`, from the rows of
``data/published/params_004_examples.csv``: the pairs of sec. 4 and of the sweeps of Figs 12-15,
the elastic approach delta and the phi1 window of Figs 12-15, and the tool data (pressure angle,
addendum and clearance coefficients) of the sec. 4 model pair, used for every pair.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...settings import SettingError

__all__ = ["Design", "params_from_published", "validate", "merged_params"]

_COMMON = "figs12-15_common"
_TOOL = "sec4_3d_model"
_FEA = "sec4_fea"


@dataclass(frozen=True)
class Design:
    """The paper's design data: ``designs`` (dicts name, group, z1, z2, module [mm], R_T [mm],
    face_width [mm]), ``delta_mm`` (elastic approach), ``window_deg`` (phi1 window of Figs 12-15),
    ``pressure_angle_deg``, ``addendum`` and ``clearance`` (coefficients, of every pair);
    ``fea``: the sec 4 FE model's material and torque (``E_MPa``, ``poisson``, ``torque_Nm``)."""

    designs: tuple
    delta_mm: float
    window_deg: tuple
    pressure_angle_deg: float
    addendum: float
    clearance: float
    fea: dict

    def by_name(self, name: str) -> dict:
        for d in self.designs:
            if d["name"] == name:
                return d
        raise KeyError(f"no design {name!r}; designs: {self.names()}")

    def names(self) -> list[str]:
        return [d["name"] for d in self.designs]


def _in(where: str, value: float, lo: float, hi: float) -> float:
    if not (np.isfinite(value) and lo <= value <= hi):
        raise ValueError(f"{where}: got {value!r}; allowed: a number in [{lo:g}, {hi:g}]")
    return float(value)


def _pair(example: str, v: dict) -> dict:
    where = f"params_004_examples.csv {example}"
    bw = v.get("face_width", v.get("face_width_driven"))
    if bw is None:
        raise ValueError(f"{where}: no face_width (or face_width_driven)")
    d = {
        "name": example,
        "group": example.split("_")[0],
        "z1": int(_in(f"{where}.z1", v["z1"], 5, 10000)),
        "z2": int(_in(f"{where}.z2", v["z2"], 5, 10000)),
        "module": _in(f"{where}.module", v["module"], 0.1, 100),
        "face_width": _in(f"{where}.face_width", bw, 1, 2000),
    }
    # the cutter must be larger than half the face width plus the blade offsets
    d["R_T"] = _in(
        f"{where}.tooth_line_radius", v["tooth_line_radius"], d["face_width"] / 2 + np.pi * d["module"] + 1e-9, 1e6
    )
    return d


def params_from_published(published) -> Design:
    """Design of seed 004 from the loaded published tables (pure; reads no file). Every example
    with z1, z2, module and tooth_line_radius is a pair; its group is the name's prefix."""
    t = published.params[published.params["seed"] == "004"]
    designs, names = [], set()
    for ex, rows in t.groupby("example", sort=False):
        v = dict(zip(rows["parameter"], rows["value"]))
        if {"z1", "z2", "module", "tooth_line_radius"} <= set(v):
            if ex in names:
                raise ValueError(f"params_004_examples.csv: example {ex!r} is duplicated")
            names.add(ex)
            designs.append(_pair(ex, v))
    if not designs:
        raise ValueError("params_004_examples.csv: no pair (z1, z2, module, tooth_line_radius) of seed 004")
    v = {(e, p): x for e, p, x in zip(t["example"], t["parameter"], t["value"])}

    def get(ex, p, lo, hi):
        if (ex, p) not in v:
            raise ValueError(f"params_004_examples.csv: {ex}.{p} is missing")
        return _in(f"params_004_examples.csv {ex}.{p}", float(v[(ex, p)]), lo, hi)

    lo, hi = get(_COMMON, "phi1_min", -90, 90), get(_COMMON, "phi1_max", -90, 90)
    if not lo < hi:
        raise ValueError(f"params_004_examples.csv {_COMMON}: phi1_min {lo} must be below phi1_max {hi}")
    return Design(
        tuple(designs),
        get(_COMMON, "elastic_approach", 1e-6, 0.1),
        (lo, hi),
        get(_TOOL, "pressure_angle", 5, 40),
        get(_TOOL, "addendum_coefficient", 0, 2),
        get(_TOOL, "clearance_coefficient", 0, 1),
        {
            "E_MPa": 1000.0 * get(_FEA, "young_modulus_GPa", 1, 1000),
            "poisson": get(_FEA, "poisson_ratio", 0, 0.5),
            "torque_Nm": get(_FEA, "torque_Nm", 1e-6, 1e9),
        },
    )


def validate(settings: dict, design: Design) -> None:
    """Cross-field checks of the settings against each other and the design (SettingError naming
    the key): the checked designs exist, the near-top zone lies in the window, the thickness
    sections lie within half the smallest R_T."""
    names = design.names()
    for key in ("section_check", "gap_check"):
        if settings[key]["design"] not in names:
            raise SettingError(f"ma2021.{key}.design: got {settings[key]['design']!r}; allowed: one of {names}")
    lo, hi = design.window_deg
    if not settings["near_top_deg"] <= hi - lo:
        raise SettingError(
            f"ma2021.near_top_deg: got {settings['near_top_deg']!r}; allowed: at most the window width {hi - lo:g} deg"
        )
    if not lo <= settings["near_top_eval_deg"] <= hi:
        raise SettingError(
            f"ma2021.near_top_eval_deg: got {settings['near_top_eval_deg']!r}; allowed: in the window "
            f"[{lo:g}, {hi:g}] deg"
        )
    th = settings["thickness"]
    if any(not 0 <= s < min(th["R_T"]) / 2 for s in th["sections_mm"]):
        raise SettingError(
            f"ma2021.thickness.sections_mm: got {th['sections_mm']!r}; allowed: each in "
            f"[0, min(R_T)/2) = [0, {min(th['R_T']) / 2:g}) mm"
        )


def merged_params(settings: dict, design: Design) -> dict:
    """The settings with the design's common data (delta, window, tool data) beside them: the one
    mapping the computations read."""
    return {
        **settings,
        "delta_mm": design.delta_mm,
        "window_deg": list(design.window_deg),
        "pressure_angle_deg": design.pressure_angle_deg,
        "addendum": design.addendum,
        "clearance": design.clearance,
    }
