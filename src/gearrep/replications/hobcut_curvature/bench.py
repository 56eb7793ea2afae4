"""Time-vs-error cases of seed 000 ch. 4 (contract of workflow/scripts/bench_replication.py): the
meshing-solve tolerance of the four curvature tables and the finite-difference steps of method (a)."""

from __future__ import annotations

import numpy as np

from .design import Design, merged, validate
from .studies import TABLES, curvature_tables, direct_curvatures, l1_grid

__all__ = ["bench_cases"]


def bench_cases(settings: dict, design: Design) -> dict:
    """Run time against error (contract in workflow/scripts/bench_replication.py).

    * ``four_tables``: the meshing-solve tolerance of the four tables; error = max |change of
      k_s, k_q| (1/mm) against tol = 1e-13; target a tenth of the tightest printed half-unit (k_s
      of Table 4.4, 7 significant digits: 0.5e-10 1/mm -> 5e-12).
    * ``direct_method``: the finite-difference steps of method (a); error = max relative
      difference from method (b) at the 44 rows (acceptance 1e-7; target 1e-8)."""
    validate(settings, design)
    base = merged(settings, design)

    def run_tables(setting):
        t = curvature_tables(dict(base, tol=setting["tol"]))
        return np.concatenate([t[k][["k_s_per_mm", "k_q_per_mm"]].to_numpy() for k in TABLES])

    grid, _ = l1_grid(base)
    exact = curvature_tables(base)

    def run_direct(setting):
        p = dict(base, fd_step_l_mm=setting["fd_step_l_mm"], fd_step_psi_rad=setting["fd_step_psi_rad"])
        out = []
        for tab, (flank, key) in TABLES.items():
            ks, kq = direct_curvatures(p, flank, p[key], grid)
            out.append(
                np.c_[ks / exact[tab]["k_s_per_mm"].to_numpy() - 1, kq / exact[tab]["k_q_per_mm"].to_numpy() - 1]
            )
        return np.concatenate(out)

    steps = [{"fd_step_l_mm": h, "fd_step_psi_rad": h / 10} for h in (1e-1, 3e-2, 1e-2, 3e-3, 1e-3, 1e-4)]
    return {
        "four_tables": {
            "run": run_tables,
            "settings": [{"tol": t} for t in (1e-4, 1e-6, 1e-8, 1e-10, 1e-12)],
            "reference": {"tol": 1e-13},
            "error": lambda res, ref: float(np.max(np.abs(res - ref))),
            "error_unit": "per_mm",
            "error_target": 0.1 * 0.5e-10,
            "current": {"tol": base["tol"]},
        },
        "direct_method": {
            "run": run_direct,
            "settings": steps,
            "reference": steps[-2],
            "error": lambda res, _ref: float(np.max(np.abs(res))),
            "error_unit": "relative",
            "error_target": 1e-8,
            "current": {"fd_step_l_mm": base["fd_step_l_mm"], "fd_step_psi_rad": base["fd_step_psi_rad"]},
        },
    }
