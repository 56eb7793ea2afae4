"""The loaded contact footprint of the sec 4 pair (claim ``004-S4-FE_elliptic_contact``).

Seed 004 sec 4 reports a static FE analysis of its 19/31 pair (m = 8 mm, B = 80 mm, R_T = 500 mm,
AISI 1045, E = 210 GPa, nu = 0.29, 3000 N m) whose largest contact stress lies in an
approximately elliptical region. We compute the loaded contact of the same pair with
:func:`gearrep.ltca.loaded_contact` over a meshing cycle (both flank pairs; the paper names
neither) and, at the position of the largest flank pressure, the footprint of the most loaded tooth
pair: each node's Hertz strip [c_j - b_j, c_j + b_j] across the contact line at its position s_j
along it. Its ellipse fit: b(s)^2 = B^2 (1 - ((s - s0)/A)^2), least squares on the loaded nodes'
b_j^2 (quadratic in s), about the line fitted through the strips' centres c_j. The claim's
criterion (claims_004.csv) read on it:

* the ellipse covers the footprint: intersection over union of the two regions >= 0.9, and the
  long axis runs along the face width (A > B, the contact line within 45 deg of the axis);
* refuted by a band across the face: the loaded span reaches 90 % of the face width and the strips
  at its ends are at least half as wide as the widest (a roughly constant width, as a line contact
  has).
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from ... import ltca
from ...surfaces.catt import PAIRS, assemble
from .design import Design

__all__ = ["loaded_footprint", "footprint_ellipse", "IOU_MIN", "BAND_SPAN", "BAND_END_WIDTH"]

#: the claim's criteria (claims_004.csv: "an ellipse fit covers ... at least 90 %"; a band spans most
#: of the face width: 90 % of it, with end strips at least half the widest)
IOU_MIN = 0.9
BAND_SPAN = 0.9
BAND_END_WIDTH = 0.5


def footprint_ellipse(s, c, b, left, right) -> dict:
    """Ellipse fit of a strip footprint and its intersection over union with it.

    ``s`` (n,) positions along the contact line [mm], ``c`` centres across it, ``b`` half-widths
    (all > 0), ``left``/``right`` each strip's extent along the line from s. Returns A, B, s0, the
    intersection over union ``iou`` (NaN where the fit is not an ellipse: b^2 not concave in s)."""
    s, c, b = (np.asarray(x, dtype=float) for x in (s, c, b))
    gamma, beta, alpha = np.polyfit(s, b * b, 2)
    if not gamma < 0:
        return dict(A_mm=np.nan, B_mm=np.nan, s0_mm=np.nan, iou=np.nan)
    s0 = -beta / (2.0 * gamma)
    B2 = alpha - gamma * s0 * s0
    A = float(np.sqrt(-B2 / gamma)) if B2 > 0 else np.nan
    B = float(np.sqrt(B2)) if B2 > 0 else np.nan
    tilt, off = np.polyfit(s, c, 1) if s.size > 1 else (0.0, float(c[0]))
    lo = min(float(np.min(s - left)), s0 - A)
    hi = max(float(np.max(s + right)), s0 + A)
    x = np.linspace(lo, hi, 4001)
    j = np.argmin(
        np.where((x[:, None] >= s - left) & (x[:, None] <= s + right), np.abs(x[:, None] - s), np.inf), axis=1
    )
    inside = np.any((x[:, None] >= s - left) & (x[:, None] <= s + right), axis=1)
    f_lo, f_hi = np.where(inside, c[j] - b[j], 0.0), np.where(inside, c[j] + b[j], 0.0)
    with np.errstate(invalid="ignore"):
        be = B * np.sqrt(np.clip(1.0 - ((x - s0) / A) ** 2, 0.0, None))
    e_lo, e_hi = off + tilt * x - be, off + tilt * x + be
    inter = np.clip(np.minimum(f_hi, e_hi) - np.maximum(f_lo, e_lo), 0.0, None)
    union = (f_hi - f_lo) + (e_hi - e_lo) - inter
    dx = x[1] - x[0]
    return dict(A_mm=A, B_mm=B, s0_mm=float(s0), iou=float(np.sum(inter) * dx / (np.sum(union) * dx)))


def _footprint_row(r, i, face_mm) -> dict:
    """The footprint of the most loaded tooth pair at position i of a LoadedContact."""
    sep = r.separations
    k = int(np.nanargmax(r.pair_load_N[i]))
    load = np.nan_to_num(r.node_load_N[i, k])
    on = load > 0
    flat = np.ravel_multi_index((i, k, 0), sep.shape) + np.arange(sep.shape[2])
    p = sep.contacts.position[flat]
    across = sep.across[i, k]
    n = sep.contacts.normal[flat]
    line = np.cross(n, across)
    line /= np.linalg.norm(line, axis=1, keepdims=True)
    line *= np.sign(line[:, 2:3])
    j0 = int(np.argmax(load))
    s = (p - p[j0]) @ line[j0]
    c = (p - p[j0]) @ across[j0]
    b = r.half_width_mm[i, k]
    z = sep.z_mm[i, k]
    dz = np.diff(z)
    cos = abs(float(line[j0, 2]))
    left = np.concatenate([[0.0], dz / 2]) / cos
    right = np.concatenate([dz / 2, [0.0]]) / cos
    fit = footprint_ellipse(s[on], c[on], b[on], left[on], right[on])
    zs = z[on]
    span = float(zs.max() - zs.min() + 0.5 * (left[on][0] + right[on][-1]) * cos) if zs.size else 0.0
    end_width = float(min(b[on][0], b[on][-1]) / np.max(b[on])) if zs.size else np.nan
    return dict(
        phi1_rad=float(r.phi1_rad[i]),
        tooth_pair=int(sep.pairs[k]),
        pair_load_N=float(r.pair_load_N[i, k]),
        normal_load_N=float(r.normal_load_N[i]),
        max_pressure_MPa=float(r.max_pressure_MPa[i]),
        nodes_loaded=int(on.sum()),
        loaded_span_mm=span,
        span_over_face=span / face_mm,
        end_width_over_max=end_width,
        max_half_width_mm=float(np.max(b[on])) if zs.size else np.nan,
        line_angle_to_axis_deg=float(np.degrees(np.arccos(min(1.0, cos)))),
        face_end_load_N=float(r.face_end_load_N[i]),
        **fit,
    )


def loaded_footprint(settings: dict, design: Design) -> dict:
    """Job ``loaded_footprint``: the sec 4 pair under the FE model's torque and material, each flank
    pair, a meshing cycle of ``loaded_positions`` positions; the footprint at the position of the
    largest flank pressure (module docstring), with the claim's verdict per flank pair."""
    d = design.by_name("sec4_3d_model")
    params = dict(pressure_angle_deg=design.pressure_angle_deg, addendum=design.addendum, clearance=design.clearance)
    mat = ltca.Material(design.fea["E_MPa"], design.fea["poisson"])
    rows = []
    for pid in PAIRS:
        pair = assemble(d, pid, params).gear_pair
        phi = ltca.cycle_positions(pair, int(settings["loaded_positions"]))
        r = ltca.loaded_contact(pair, design.fea["torque_Nm"], phi, materials=mat, pairs=[-2, -1, 0, 1, 2])
        ok = r.converged
        i = int(np.nanargmax(np.where(ok, r.max_pressure_MPa, -np.inf)))
        row = dict(pair=pid, torque_Nm=design.fea["torque_Nm"], n_positions=int(phi.size), n_failed=int((~ok).sum()))
        row |= _footprint_row(r, i, float(d["face_width"]))
        band = row["span_over_face"] >= BAND_SPAN and row["end_width_over_max"] >= BAND_END_WIDTH
        along = row["A_mm"] > row["B_mm"] and row["line_angle_to_axis_deg"] < 45.0
        row |= dict(band=bool(band), long_axis_along_face=bool(along))
        row["holds"] = bool(row["iou"] >= IOU_MIN and along and not band and row["n_failed"] == 0)
        rows.append(row)
    return {"loaded_footprint": pd.DataFrame(rows)}
