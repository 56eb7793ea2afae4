"""Tables of the ``gearrep`` command shared by every family (pure: arrays in, pandas DataFrames
out, the unit in each column name): failed rows as NaN, the TE over the meshing cycle as the
envelope of sampled tooth pairs, the summary entries of a cycle, curvature rows and point clouds."""

from __future__ import annotations

import numpy as np
import pandas as pd

from ..meshing import pair_te_curves, upper_envelope
from ..units import ARCSEC

__all__ = [
    "SOLVE_COLUMNS",
    "failed_rows_nan",
    "te_envelope",
    "cycle_summary",
    "curvature_frame",
    "cloud",
]

#: the columns of a contact-path table that describe the solve, not the contact: kept in a row
#: whose status is not converged (every other column is NaN there, :func:`failed_rows_nan`)
SOLVE_COLUMNS = ("phi1_rad", "status", "residual", "iterations", "tangencies_found", "jacobian_cond")


def failed_rows_nan(path: pd.DataFrame) -> pd.DataFrame:
    """``path`` (a contact-path table) with every column but :data:`SOLVE_COLUMNS` NaN in the rows
    whose status is not ``converged``: a failed solve's last iterate is not a contact, nor is
    anything derived from it."""
    bad = (path["status"] != "converged").to_numpy()
    if not bad.any():
        return path
    out = path.copy()
    for col in out.columns:
        if col not in SOLVE_COLUMNS:
            out[col] = out[col].where(~bad)
    return out


def te_envelope(phi, te, drive, pitch, begin, n):
    """(``n`` angles over one meshing cycle from ``begin``, TE transmitted there, leading tooth pair
    -3..3): the envelope of the neighbouring pairs' curves (:func:`gearrep.meshing.pair_te_curves`,
    :func:`gearrep.meshing.upper_envelope`) of one pair's TE ``te`` at ``phi`` [rad], in the drive
    sense ``drive`` (+1: the most advanced member 2, -1: the least); NaN with fewer than 2 samples."""
    at = np.linspace(begin, begin + pitch, int(n))
    if np.sum(np.isfinite(te)) < 2:
        return at, np.full(len(at), np.nan), np.zeros(len(at), int)
    curves = pair_te_curves(phi, drive * te, pitch, at, pairs=range(-3, 4))
    env, lead = upper_envelope(curves)
    return at, drive * env, lead - 3


def cycle_summary(begin, end, env, drive) -> dict:
    """Summary entries of a meshing cycle: engagement limits [rad], TE peak to peak of the envelope
    ``env`` [rad] and the drive sense."""
    return {
        "phi1_begin_rad": float(begin),
        "phi1_end_rad": float(end),
        "te_peak_to_peak_arcsec": float((np.nanmax(env) - np.nanmin(env)) / ARCSEC)
        if np.any(np.isfinite(env))
        else float("nan"),
        "drive_sense": "max" if drive > 0 else "min",
    }


def curvature_frame(member: str, names, u, v, points, pc) -> pd.DataFrame:
    """The curvature table rows of one member: its parameters ``u``, ``v`` (columns ``names``),
    points [mm] and :class:`gearrep.curvature.PrincipalCurvatures` ``pc`` (k [1/mm], e1, e2, normal)."""
    return pd.DataFrame(
        {
            "member": member,
            names[0]: u,
            names[1]: v,
            **{f"{a}_mm": points[:, i] for i, a in enumerate("xyz")},
            "k1_per_mm": pc.k1,
            "k2_per_mm": pc.k2,
            **{f"{vec}_{a}": getattr(pc, vec)[:, i] for vec in ("e1", "e2", "normal") for i, a in enumerate("xyz")},
        }
    )


def cloud(names, u, v, points, normals, keep, n_u: int, n_v: int):
    """(points (n_u, n_v, 3) and normals, NaN where not ``keep``; the table of the kept points with
    their parameters ``u``, ``v`` under the column ``names``)."""
    pts = np.where(keep[:, None], points, np.nan)
    nrm = np.where(keep[:, None], normals, np.nan)
    table = pd.DataFrame(
        {
            names[0]: u[keep],
            names[1]: v[keep],
            **{f"{a}_mm": pts[keep, i] for i, a in enumerate("xyz")},
            **{f"normal_{a}": nrm[keep, i] for i, a in enumerate("xyz")},
        }
    )
    return pts.reshape(n_u, n_v, 3), nrm.reshape(n_u, n_v, 3), table
