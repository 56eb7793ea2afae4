"""The loaded tooth contact analysis behind ``gearrep ltca`` on a checked design (pure: tables in,
tables out; no files). Every table is a pandas DataFrame with the unit in each column name.

The analysis is the library's, :func:`gearrep.ltca.loaded_contact`, on the design's pair (a family
that lists ``ltca`` among its analyses: :data:`gearrep.ltca.SUPPORTED`), under the design's
``load`` (torque on the driving member) and the members' ``material``, at ``analysis.n_points``
positions over one meshing cycle (:func:`gearrep.ltca.cycle_positions`) with
``analysis.ltca_nodes`` nodes along the face per tooth pair.

The pitch position is solved, not assumed: the pinion angle at which tooth pair 0's unloaded
contact (the TCA's contact point of the design, at mid-face for a line contact) lies on the
pinion's operating pitch circle (:meth:`gearrep.cli.family.Family.pitch_radius_mm`), a root of
the contact radius minus that radius between two contact solves that bracket it
(:func:`scipy.optimize.brentq` to 1e-13 rad). The loaded analysis is run there twice: with every
tooth pair free to take load (the pressure and the tooth pairs sharing it) and with tooth pair 0
alone (ISO 6336-2's one loaded pair: its pressure and stiffness).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np
import pandas as pd

from ..ltca import KINDS, cycle_positions, loaded_contact
from ..solve import status_names
from .keys import materials

__all__ = [
    "Loaded",
    "ltca_tables",
    "sweep_metrics",
    "SWEEP_COLUMNS",
    "solves_per_design",
    "pitch_position",
    "positions_table",
    "pair_column",
    "pressure_map_table",
    "tip_kinds",
]

#: pinion angles at which the bracket of the pitch position is sought (between the engagement limits)
PITCH_SCAN = 17
#: angle tolerance [rad] of the pitch position (far below the cycle's spacing of about 1e-3 rad)
PITCH_XTOL_RAD = 1e-13


@dataclass
class Loaded:
    """The loaded analysis of one design: the cycle (:class:`gearrep.ltca.LoadedContact`), the
    index of its position with the largest flank pressure (None: no position converged), and the
    tables ``ltca_positions``, ``ltca_summary`` and ``ltca_pressure_map``."""

    cycle: object
    worst: int | None
    tables: dict


def tip_kinds() -> tuple:
    """The node kinds (:data:`gearrep.ltca.KINDS`) at a tip edge (a corner: Hertz with the edge radius)."""
    return tuple(k for k, name in KINDS.items() if name.startswith("tip"))


def _ltca_options(design) -> dict:
    load = design.values["load"]
    return dict(driving=load["driving"], materials=materials(design.values), n_nodes=int(design.analysis["ltca_nodes"]))


def pitch_position(design) -> tuple[float, str]:
    """(phi1 [rad], status) of the pitch position of ``design`` (module docstring): status
    ``converged``, or why there is none (phi1 NaN)."""
    from scipy.optimize import brentq

    r_w = design.family.pitch_radius_mm(design)
    b, e = design.family.engagement(design)
    phi = np.linspace(b, e, PITCH_SCAN + 2)[1:-1]

    def radius(x):
        c = design.family.contact_at(design, np.atleast_1d(x))
        return np.where(c.converged, np.hypot(c.position[:, 0], c.position[:, 1]), np.nan)

    f = radius(phi) - r_w
    ok = np.isfinite(f)
    if not ok.any():
        return float("nan"), "no converged contact of the tooth pair over its engagement"
    cross = np.flatnonzero(ok[:-1] & ok[1:] & (np.sign(f[:-1]) != np.sign(f[1:])))
    if cross.size == 0:
        lo, hi = np.nanmin(f + r_w), np.nanmax(f + r_w)
        why = f"the contact stays between radii {lo:.6g} and {hi:.6g} mm, off the pitch circle {r_w:.6g} mm"
        return float("nan"), why
    i = int(cross[0])
    if f[i] == 0.0:
        return float(phi[i]), "converged"

    def g(x):
        v = float(radius(x)[0])
        if not np.isfinite(v):
            raise ValueError("contact solve failed inside the pitch bracket")
        return v - r_w

    try:
        return float(brentq(g, phi[i], phi[i + 1], xtol=PITCH_XTOL_RAD)), "converged"
    except ValueError as err:
        return float("nan"), str(err)


def pair_column(k: int) -> str:
    """The column of tooth pair ``k``'s load: ``load_pair_0_N``, ``load_pair_+1_N``, ``load_pair_-1_N``."""
    return f"load_pair_{'0' if k == 0 else f'{k:+d}'}_N"


def positions_table(design, res, pairs) -> pd.DataFrame:
    """One row per position of the loaded cycle ``res``: solve record, unloaded and loaded TE (urad of
    the gear, member 2, and um along the line of action), the load of each tooth pair of ``pairs``
    (offsets), pressure, edge-contact loads and mesh stiffness (NaN where not converged)."""
    to_um = 1e-3 * design.family.te_radius_mm(design)
    col = {int(k): i for i, k in enumerate(res.separations.pairs)}
    out = {
        "phi1_rad": res.phi1_rad,
        "status": status_names(res.status),
        "iterations": res.iterations,
        "torque_balance_residual": res.moment_residual,
        "te_unloaded_urad": res.te_unloaded_rad * 1e6,
        "te_unloaded_um": res.te_unloaded_rad * 1e6 * to_um,
        "lte_urad": res.lte_urad,
        "lte_um": res.lte_um,
        "normal_load_N": res.normal_load_N,
        "pairs_loaded": pd.Series(res.pairs_loaded, dtype="Int64").where(res.converged),
        **{pair_column(k): res.pair_load_N[:, col[k]] for k in pairs},
        "max_pressure_MPa": res.max_pressure_MPa,
        "tip_edge_load_N": res.tip_edge_load_N,
        "tip_edge_pressure_MPa": res.tip_edge_pressure_MPa,
        "face_end_load_N": res.face_end_load_N,
        "mesh_stiffness_N_per_um": res.mesh_stiffness_N_per_um,
        "mesh_stiffness_N_per_mm_um": res.mesh_stiffness_N_per_mm_um,
    }
    return pd.DataFrame(out)


def pressure_map_table(res, i: int | None, n_across: int = 21) -> pd.DataFrame:
    """The Hertz pressure over the contact nodes of position ``i`` of ``res`` (every tooth pair's
    nodes in contact; ``n_across`` points across each contact line), fixed-frame points [mm] at
    that position; empty (the columns only) for ``i`` None."""
    cols = [
        "phi1_rad",
        "tooth_pair",
        "node",
        "contact_kind",
        "node_axial_mm",
        "across_mm",
        "x_mm",
        "y_mm",
        "z_mm",
        "radius_on_pinion_mm",
        "pressure_MPa",
    ]
    if i is None:
        return pd.DataFrame({c: [] for c in cols})
    m = res.pressure_map(i, n_across)
    kp, kn = np.nonzero(m.kind > 0)
    P = m.position_mm[kp, kn][:, None, :] + m.across_mm[None, :, None] * m.across[kp, kn][:, None, :]
    n = len(m.across_mm)
    rep = lambda a: np.repeat(a, n)  # noqa: E731
    return pd.DataFrame(
        {
            "phi1_rad": float(res.phi1_rad[i]),
            "tooth_pair": rep(m.pairs[kp]),
            "node": rep(kn),
            "contact_kind": rep(np.array([KINDS[int(k)] for k in m.kind[kp, kn]], dtype=object)),
            "node_axial_mm": rep(m.z_mm[kp, kn]),
            "across_mm": np.tile(m.across_mm, len(kp)),
            "x_mm": P[..., 0].ravel(),
            "y_mm": P[..., 1].ravel(),
            "z_mm": P[..., 2].ravel(),
            "radius_on_pinion_mm": np.hypot(P[..., 0], P[..., 1]).ravel(),
            "pressure_MPa": m.pressure_MPa[kp, kn].ravel(),
        },
        columns=cols,
    )


def _pitch_summary(design, opts) -> dict:
    """The pitch-position entries of the summary (module docstring)."""
    phi, status = pitch_position(design)
    nan = float("nan")
    out = {
        "pitch_point_phi1_rad": phi,
        "pitch_point_status": status,
        "pitch_point_pressure_MPa": nan,
        "pitch_point_pairs_loaded": nan,
        "pitch_point_load_share": nan,
        "pitch_point_pressure_single_pair_MPa": nan,
        "pitch_point_single_pair_stiffness_N_per_mm_um": nan,
        "pitch_point_pressure_iso_MPa": design.family.iso_pitch_pressure_MPa(design),
    }
    if not np.isfinite(phi):
        return out
    T = design.values["load"]["torque_Nm"]
    every = loaded_contact(design.pair, T, [phi], **opts)
    one = loaded_contact(design.pair, T, [phi], pairs=[0], **opts)
    if every.converged[0]:
        k0 = int(np.flatnonzero(every.separations.pairs == 0)[0])
        out["pitch_point_pressure_MPa"] = float(every.max_pressure_MPa[0])
        out["pitch_point_pairs_loaded"] = int(every.pairs_loaded[0])
        out["pitch_point_load_share"] = float(every.pair_load_N[0, k0] / every.normal_load_N[0])
    if one.converged[0]:
        out["pitch_point_pressure_single_pair_MPa"] = float(one.max_pressure_MPa[0])
        out["pitch_point_single_pair_stiffness_N_per_mm_um"] = float(one.mesh_stiffness_N_per_mm_um[0])
    if not (every.converged[0] and one.converged[0]):
        out["pitch_point_status"] = "loaded analysis not converged at the pitch position"
    return out


#: the loaded cycle's summary fields ``gearrep sweep`` adds with ``ltca: true``
SWEEP_COLUMNS = (
    "normal_load_N",
    "lte_peak_to_peak_urad",
    "mesh_stiffness_mean_N_per_mm_um",
    "single_pair_stiffness_max_N_per_mm_um",
    "max_contact_pressure_MPa",
    "load_share_min",
    "tip_edge_contact_positions",
    "ltca_positions_failed",
)


def _cycle(design):
    T = design.values["load"]["torque_Nm"]
    return loaded_contact(
        design.pair, T, cycle_positions(design.pair, int(design.analysis["n_points"])), **_ltca_options(design)
    )


def sweep_metrics(design) -> dict:
    """The loaded cycle's summary entries of one sweep point (:data:`SWEEP_COLUMNS`; no pitch
    position, no tables)."""
    summary = dataclasses.asdict(_cycle(design).summary())
    summary["ltca_positions_failed"] = summary.pop("n_failed")
    return {k: summary[k] for k in SWEEP_COLUMNS}


#: tooth pairs the loaded analysis places nodes on (gearrep.ltca.loaded_contact's default -4 ... 4)
_PAIRS = 9


def solves_per_design(values: dict) -> int:
    """Section-contact solves of one loaded cycle of the resolved design ``values`` before any
    refinement: positions x tooth pairs x nodes (the sweep's shard sizes count them as contact solves)."""
    a = values["analysis"]
    return int(a["n_points"]) * _PAIRS * int(a["ltca_nodes"])


def ltca_tables(design, progress=None) -> Loaded:
    """The loaded analysis of the checked ``design`` (module docstring): the cycle, its worst
    position and the tables ``ltca_positions`` (one row per position), ``ltca_summary`` (one row)
    and ``ltca_pressure_map`` (the worst position's pressure map)."""
    opts = _ltca_options(design)
    if progress:
        progress("loaded meshing cycle", 0.1)
    res = _cycle(design)
    if progress:
        progress("pitch position", 0.6)
    pitch = _pitch_summary(design, opts)
    ok = res.converged
    worst = int(np.nanargmax(np.where(ok, res.max_pressure_MPa, np.nan))) if ok.any() else None
    in_mesh = np.any(res.separations.in_contact, axis=(0, 2))
    pairs = [int(k) for k in res.separations.pairs[in_mesh]]
    summary = {
        "design": design.name,
        "family": design.family.name,
        "driving": res.driving,
        **dataclasses.asdict(res.summary()),
        "max_pressure_phi1_rad": float(res.phi1_rad[worst]) if worst is not None else float("nan"),
        **pitch,
        "ltca_nodes": opts["n_nodes"],
        "node_placements": int(res.passes),
        "max_torque_balance_residual": float(np.max(np.abs(res.moment_residual[ok]))) if ok.any() else float("nan"),
    }
    tables = {
        "ltca_positions": positions_table(design, res, pairs),
        "ltca_summary": pd.DataFrame([summary]),
        "ltca_pressure_map": pressure_map_table(res, worst),
    }
    return Loaded(res, worst, tables)
