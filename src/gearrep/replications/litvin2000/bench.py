"""Time-vs-error cases of seed 002 for ``workflow/scripts/bench_replication.py`` (gearrep.benchmark)."""

from __future__ import annotations

import numpy as np

from ...surfaces.novikov import aligned_start
from ...tca import Misalignment
from ...units import ARCMIN
from .geometry import basics, make_pair
from .te_studies import face_width, te_cycle, worm

__all__ = ["BENCH_TE_TOL_ARCSEC", "bench_cases", "crowned_pair", "robustness_cases"]

#: tightest printed tolerance of the TE maxima (sec. 5.5, 2 decimals): +-0.005 arcsec
BENCH_TE_TOL_ARCSEC = 0.005


def crowned_pair(settings: dict, design: dict, misalignment=None):
    """The profile-crowned pair of sec. 2 (rack-generated flanks, radii rho_c, rho_t of the design)
    with the settings' tolerance and pinion hand, under ``misalignment``."""
    Pn, an, beta, lead = basics(design)
    return make_pair(
        design,
        design["rho_c_times_Pn"] / Pn,
        design["rho_t_times_Pn"] / Pn,
        an,
        lead,
        beta,
        tol=settings["tol"],
        hand=settings["pinion_hand"],
        misalignment=misalignment,
    )


def bench_cases(settings: dict, design: dict) -> dict:
    """Benchmark cases. ``worm_te_max``: TE_max of the worm-ground pinion (all cases) against the
    TCA grid ``worm_points_per_cycle`` (spline-interpolated envelope). ``te_max``: TE_max of the
    profile-crowned pair with dgamma = ``misalignment_arcmin`` against the knobs
    ``te_points_per_cycle`` (grid of the contact interval) and ``tol`` (TCA Newton residual).
    Errors: |TE_max - TE_max_ref| (max over cases) in arcsec, target a tenth of the printed +-0.005.
    ``settings``: the resolved settings; ``design``: :func:`.design.params_from_published`."""
    s, d = dict(settings), design
    B, _ = face_width(s, d)

    def run_te(setting):
        q = {**s, **setting}
        pair = crowned_pair(q, d, Misalignment(d_gamma_out=q["misalignment_arcmin"] * ARCMIN))
        return te_cycle(pair, q, B)[2]["te_max_arcsec"]

    def run_worm(setting):
        return worm({**s, **setting}, d)["worm_summary"].set_index("case")["te_max_arcsec"].to_dict()

    return {
        "worm_te_max": {
            "run": run_worm,
            "settings": [{"worm_points_per_cycle": n} for n in (6, 8, 12)],
            "reference": {"worm_points_per_cycle": 24},
            "error": lambda res, ref: float(max(abs(res[k] - ref[k]) for k in ref)),
            "error_unit": "arcsec",
            "error_target": 0.1 * BENCH_TE_TOL_ARCSEC,
            "current": {"worm_points_per_cycle": s["worm_points_per_cycle"]},
        },
        "te_max": {
            "run": run_te,
            "settings": [{"te_points_per_cycle": n, "tol": t} for n in (8, 16, 40, 100) for t in (1e-8, 1e-10, 1e-12)],
            "reference": {"te_points_per_cycle": 400, "tol": 1e-13},
            "error": lambda res, ref: float(abs(res - ref)) if np.isfinite(res) else float("nan"),
            "error_unit": "arcsec",
            "error_target": 0.1 * BENCH_TE_TOL_ARCSEC,
            "current": {"te_points_per_cycle": s["te_points_per_cycle"], "tol": s["tol"]},
        },
    }


def robustness_cases(settings: dict, design: dict) -> list:
    """The profile-crowned Novikov-Wildhaber pair (rack-generated flanks) of the start-robustness
    table, aligned and under the study's crossing error dgamma: dicts with ``family``,
    ``misalignment``, ``pair``, ``phi1`` (five angles over 0.6 of an angular pitch around phi1 =
    0, the aligned contact at mid-face), ``nominal`` (the family's start,
    :func:`gearrep.surfaces.novikov.aligned_start`) and ``formulations`` (conventional only: the
    flanks are envelopes in rack parameters, with no explicit form)."""
    out = []
    arcmin = settings["misalignment_arcmin"]
    for mis, lab in ((None, "aligned"), (Misalignment(d_gamma_out=arcmin * ARCMIN), f"dgamma_out = {arcmin:g} arcmin")):
        pair = crowned_pair(settings, design, mis)
        per = 2 * np.pi / pair.n1
        out.append(
            dict(
                family="Novikov-Wildhaber (profile-crowned, rack-generated)",
                misalignment=lab,
                pair=pair,
                phi1=np.linspace(-0.3, 0.3, 5) * per,
                nominal=aligned_start,
                formulations=("conventional",),
            )
        )
    return out
