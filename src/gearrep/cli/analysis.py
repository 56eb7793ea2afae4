"""The analyses behind ``gearrep tca``, ``curvature`` and ``sweep`` on a checked design (pure: tables
in, tables out; no files). Every table is a pandas DataFrame with the unit in each column name.

Each family computes its own tables (:class:`gearrep.cli.family.Family`: the library's meshing
cycle for the involute and bevel pairs, a sampled cycle for the Novikov-Wildhaber and CATT pairs,
the TCA of envelopes for the hob-cut pair); what is the same for every family is here: the failed
rows of the contact path made NaN and the one-row summary.
"""

from __future__ import annotations

import pandas as pd

from .tables import SOLVE_COLUMNS, failed_rows_nan

__all__ = ["tca_tables", "curvature_table", "flank_cloud", "sweep_point", "SOLVE_COLUMNS", "failed_rows_nan"]

#: how the load passes between tooth pairs when a family's cycle does not say (the envelope of
#: the sampled pairs' TE)
SAMPLED_TRANSFER = "envelope of sampled pairs"


def tca_tables(design, progress=None) -> dict:
    """TCA of design ``design`` over its meshing cycle: tables ``contact_path`` (contact points, TE,
    ellipses), ``te_cycle`` (TE envelope over one cycle), ``summary`` (one row) and the family's
    further tables."""
    if progress:
        progress("meshing cycle", 0.1)
    path, te, summary, extra = design.family.tca(design, progress)
    if progress:
        progress("contact ellipses", 0.6)
    path = failed_rows_nan(path)
    ok = path["status"] == "converged"
    summary = dict(summary)
    transfer = summary.pop("transfer_kind", SAMPLED_TRANSFER)
    summary = {
        "design": design.name,
        "family": design.family.name,
        "line_contact": design.line_contact,
        **summary,
        **design.family.iso_contact_ratios(design),
        "points_converged": int(ok.sum()),
        "points_total": len(path),
        "max_residual_mm": float(path.loc[ok, "residual"].max()) if ok.any() else float("nan"),
        "max_ellipse_semi_major_mm": float(path["ellipse_semi_major_mm"].max())
        if path["ellipse_semi_major_mm"].notna().any()
        else float("nan"),
        "transfer_kind": transfer,
        "edge_contact_positions": int((path["edge_contact"].fillna("") != "").sum())
        if "edge_contact" in path
        else float("nan"),
    }
    return {"contact_path": path, "te_cycle": te, "summary": pd.DataFrame([summary]), **extra}


def curvature_table(design) -> pd.DataFrame:
    """Principal curvatures [1/mm] and directions on a grid over both flanks (each in its own frame;
    curvature positive where the surface bends toward its outward normal)."""
    return design.family.curvature_table(design)


def flank_cloud(design, member: int):
    """Point cloud of member ``member``'s flank in its own frame: (points (n_u, n_v, 3) with NaN where
    the grid leaves the flank, outward unit normals, table)."""
    return design.family.flank_cloud(design, member)


def sweep_point(design, n_phi: int) -> dict:
    """The metrics of one sweep point: TE over the meshing cycle, contact ratio, largest
    contact-ellipse semi-axis, convergence (``n_phi`` contact positions)."""
    return design.family.sweep_point(design, n_phi)
