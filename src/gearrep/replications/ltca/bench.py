"""Run time against error of the loaded analysis: one meshing cycle of the README pair (41
positions) for node counts along the face, each against 161 nodes computed in the same run."""

from __future__ import annotations

import numpy as np

from ... import ltca
from .design import Design, readme_pair
from .studies import README_TORQUE_NM

__all__ = ["bench_cases", "BENCH_POSITIONS"]

#: positions of the benchmarked cycle
BENCH_POSITIONS = 41


def _err(res, ref) -> float:
    """The larger of the flank pressure's and the loaded TE's change against the reference (the
    latter relative to the reference's peak-to-peak loaded TE); NaN if a position failed."""
    if not (np.all(res.converged) and np.all(ref.converged)):
        return float("nan")
    dp = float(np.max(np.abs(res.max_pressure_MPa / ref.max_pressure_MPa - 1.0)))
    dte = float(np.max(np.abs(res.lte_urad - ref.lte_urad)) / np.ptp(ref.lte_urad))
    return max(dp, dte)


def bench_cases(settings: dict, design: Design) -> dict:
    """``nodes``: knob n_nodes over one cycle of the README pair; error of :func:`_err`; target
    the 1 % accuracy the loaded analysis is declared to hold (the validation's grid-convergence
    criterion; no published tolerance applies). ``items`` = positions, so that the sweep reports the
    time per position too."""
    pair = readme_pair(design)
    phi = ltca.cycle_positions(pair, BENCH_POSITIONS)

    def run(setting):
        return ltca.loaded_contact(pair, README_TORQUE_NM, phi, n_nodes=int(setting["n_nodes"]), tol=settings["tol"])

    return {
        "nodes": {
            "run": run,
            "settings": [{"n_nodes": n} for n in (6, 11, 21, 41, 81)],
            "reference": {"n_nodes": 161},
            "error": _err,
            "error_unit": "1 (relative)",
            "error_target": 1e-2,
            "current": {"n_nodes": settings["n_nodes"]},
            "items": BENCH_POSITIONS,
        }
    }
