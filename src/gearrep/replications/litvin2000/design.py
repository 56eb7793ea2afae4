"""Design data of the seed-002 examples, read from the loaded published tables (never from files)."""

from __future__ import annotations

import numpy as np

from ...published import values_by
from ...settings import SettingError

__all__ = ["params_from_published", "design_beta", "validate"]


def _param(params: dict, file: str, example: str, name: str) -> float:
    sel = params.get((file, example, name), [])
    if len(sel) != 1:
        raise KeyError(f"published params: no unique {name!r} in {file} / {example}")
    return float(sel[0])


def _value(values: dict, vid: str) -> float:
    sel = values.get((vid,), [])
    if len(sel) != 1:
        raise KeyError(f"published values: no unique id {vid!r}")
    return float(sel[0])


def params_from_published(published) -> dict:
    """Design data of the seed-002 examples from a :class:`gearrep.published.Published`.

    The helix angle used is beta = arccos((N1 + N2) / (2 P_n E)) from the printed centre
    distance E = 10 in (19.948 deg; the printed 19.548 deg is kept as ``beta_printed_deg`` and
    computed as a variant, see errata). Rack radii: rho = (5.88, 6.35)/P_n (eq 2.7.2); the
    printed a_c, a_t (their rounded halves-reciprocals) are a variant."""
    P = values_by(published.params, ["file", "example", "parameter"])
    V = values_by(published.values, ["id"])
    f5, f6, f54 = "params_002_S2.5.csv", "params_002_T6.2.csv", "params_002_S5.4.csv"
    design = {
        "N1": _param(P, f5, "S2.5_example", "N1"),
        "N2": _param(P, f5, "S2.5_example", "N2"),
        "P_n_per_in": _param(P, f5, "S2.5_example", "normal_diametral_pitch"),
        "alpha_n_deg": _param(P, f5, "S2.5_example", "normal_pressure_angle"),
        "a_c_printed_per_in": _param(P, f5, "S2.5_example", "a_c"),
        "a_t_printed_per_in": _param(P, f5, "S2.5_example", "a_t"),
        "beta_printed_deg": _param(P, f5, "S2.5_example", "helix_angle"),
        "beta_s54_deg": _param(P, f54, "S5.4_example", "helix_angle"),
        "center_distance_in": _param(P, f6, "version3", "center_distance"),
        "alpha_n_v12_deg": _param(P, f6, "version1", "normal_pressure_angle"),
        "rho_c_times_Pn": _param(P, "params_002_S2.7.csv", "S2.7_recommended", "rho_c_times_Pn"),
        "rho_t_times_Pn": _param(P, "params_002_S2.7.csv", "S2.7_recommended", "rho_t_times_Pn"),
        "delta_in": _param(P, f6, "version3", "elastic_approach"),
        "delta_s26_in": _param(P, "params_002_S2.6.csv", "S2.6_ellipse", "elastic_approach"),
        "delta_E_printed_mm": _param(P, f6, "version3", "delta_E"),
        "a_pl_per_in": _param(P, f54, "S5.4_example", "a_pl"),
        "a_c_s54_per_in": _param(P, f54, "S5.4_example", "a_c"),
        "a_t_s54_per_in": _param(P, f54, "S5.4_example", "a_t"),
        "r_pw_in": _param(P, f54, "S5.4_example", "r_pw"),
        "N_w": _param(P, "params_002_S5.3.csv", "S5.3_worm", "worm_threads"),
        "s3_a_c_over_Pn": _param(P, "params_002_S3.csv", "S3.2_concave_pinion", "a_c_over_Pn"),
        "s3_a_t_over_Pn": _param(P, "params_002_S3.csv", "S3.2_concave_pinion", "a_t_over_Pn"),
        "s3_l_c_times_Pn": _param(P, "params_002_S3.csv", "S3.2_concave_pinion", "l_c_times_Pn"),
        "s3_N2_min": _param(P, "params_002_S3.csv", "S3.3_pointing", "N2_min"),
        "rho_v1": (_value(V, "002-T6.2.1-version=1-rho_pinion"), _value(V, "002-T6.2.1-version=1-rho_gear")),
        "rho_v2_add": (
            _value(V, "002-T6.2.1-version=2;zone=pinion_addendum-rho_pinion"),
            _value(V, "002-T6.2.1-version=2;zone=pinion_addendum-rho_gear"),
        ),
        "rho_v2_ded": (
            _value(V, "002-T6.2.1-version=2;zone=pinion_dedendum-rho_pinion"),
            _value(V, "002-T6.2.1-version=2;zone=pinion_dedendum-rho_gear"),
        ),
        # active heights (Table 6.2.2) for delta_1 = shift / height (eq 2.8.6, Table 6.2.3)
        "h_Pn": {v: _value(V, f"002-T6.2.2-version={v}-h_Pn") for v in (1, 2, 3)},
        "ha_Pn_v2": _value(V, "002-T6.2.2-version=2-ha_Pn"),
        "ha_Pn": {v: _value(V, f"002-T6.2.2-version={v}-ha_Pn") for v in (1, 2, 3)},
        "hd_Pn": {v: _value(V, f"002-T6.2.2-version={v}-hd_Pn") for v in (1, 2, 3)},
        # the printed aligned TE_max of the disk-ground pinion: input of the disk-size inference only
        "disk_te_aligned_printed_arcsec": _value(V, "002-S5.5-crowning=disk;misalignment=none-TE_max"),
        # Table 6.2.3 as printed: only to infer the step dE each version implies (eq 2.8.7 inverted)
        "delta_alpha_T623_deg": {v: _value(V, f"002-T6.2.3-version={v}-delta_alpha") for v in (1, 2, 3)},
        "delta_1_T623": {v: _value(V, f"002-T6.2.3-version={v}-delta_1") for v in (1, 2, 3)},
    }
    for k in ("N1", "N2"):
        design[k] = int(design[k])
    if not (design["P_n_per_in"] > 0 and 0 < design["alpha_n_deg"] < 90 and design["center_distance_in"] > 0):
        raise ValueError("published design data of seed 002 out of range (P_n, alpha_n, E)")
    return design


def design_beta(design: dict) -> float:
    """Helix angle from the centre distance, cos(beta) = (N1 + N2) / (2 P_n E) (rad)."""
    c = (design["N1"] + design["N2"]) / (2.0 * design["P_n_per_in"] * design["center_distance_in"])
    if not 0 < c < 1:
        raise ValueError(f"(N1 + N2)/(2 P_n E) must be in (0, 1), got {c!r}")
    return float(np.arccos(c))


def validate(settings: dict, design: dict) -> None:
    """Cross-field checks: every swept gear rack radius above the pinion's (eq 2.8.7 divides by
    rho_t - rho_c). Raises :class:`gearrep.settings.SettingError` naming the key."""
    rc = design["rho_c_times_Pn"]
    bad = [x for x in settings["rho_t_sweep_times_Pn"] if not x > rc]
    if bad:
        raise SettingError(
            f"litvin2000.rho_t_sweep_times_Pn: got {bad!r}; allowed: values above the pinion rack radius "
            f"rho_c P_n = {rc:g} of the design"
        )
