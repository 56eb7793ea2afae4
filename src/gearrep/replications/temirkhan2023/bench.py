"""Benchmark cases: run time against error over the main accuracy knobs
(workflow/scripts/bench_replication.py)."""

from __future__ import annotations

import numpy as np

from ...tca import BevelMisalignment, Misalignment, draw_starts
from ...units import ARCMIN, ARCSEC, DEG
from .bevel import bevel_pair
from .convergence import rng, run_variant, study_reference
from .design import TABLE34, Design, design_pair, misalignment, pair_40_37
from .model import crowning_object
from .te import te_study

#: tightest tolerance of a convergence-rate check including sampling (Table 10 conventional, 5000 + 5000 starts)
BENCH_RATE_TOL_PCT = 1.79
#: acceptance of the issue: the two formulations agree to 1e-9 mm
BENCH_AGREE_MM = 1.0e-9
#: tightest printed tolerance of a Tables 3-4 te_max (7 significant digits: 5e-7 arcsec)
BENCH_TE_TOL_ARCSEC = 5.0e-7


def bench_cases(settings: dict, design: Design) -> dict:
    """Benchmark cases (contract of workflow/scripts/bench_replication.py) for resolved ``settings``.

    * ``rate_n_starts``: knob ``n_starts`` of the Table 10 study (plain conventional Newton, phi2 over a
      full turn); error = |rate - rate_ref| [percentage points] against 20000 starts; target a tenth of the
      tightest rate tolerance (its sampling part, 1.79 pp).
    * ``newton_tol``: knob ``tol``; 400 starts solved by the robust conventional variant; error = largest
      |difference| of (u1, v1, u2, v2) [mm] against tol = 1e-14 (NaN if a start is not correct); target a
      tenth of the 1e-9 mm agreement criterion.
    * ``te_grid``: knob ``te_n_points`` (TE grid per cycle); error = |te_max - te_max_ref| [arcsec] for the
      Table 3 in-plane -0.2 deg circular crown (row 1) against 241 points; target a tenth of the
      tightest printed te_max precision.
    """
    p = settings
    pair = design_pair(design, "spur_52_72")
    _, ref = study_reference(p, pair, design.pairs["spur_52_72"]["phi1_thesis"])

    def run_rate(setting):
        n = int(setting["n_starts"])
        st = draw_starts(pair, n, rng(p, "table10"), phi2_window=(ref.x[4] - np.pi, ref.x[4] + np.pi))
        out, _, _, _ = run_variant(pair, ref, st, "plain", p)
        return 100.0 * float(np.mean(out == "correct"))

    st_tol = draw_starts(
        pair, 400, np.random.default_rng([int(p["seed"]), 99]), phi2_window=(ref.x[4] - np.pi, ref.x[4] + np.pi)
    )

    def run_tol(setting):
        q = dict(p, tol=float(setting["tol"]))
        out, _, x, _ = run_variant(pair, ref, st_tol, "robust", q)
        return out, x

    def err_tol(res, ref_res):
        (o, x), (o_r, x_r) = res, ref_res
        if not ((o == "correct").all() and (o_r == "correct").all()):
            return float("nan")
        return float(np.max(np.abs(x[:, :4] - x_r[:, :4])))

    d = design.pairs["helical_40_37"]
    amount = TABLE34[("in", -0.2)]["circular"][0]
    base = pair_40_37(design)
    te_pair = pair_40_37(
        design,
        crowning_object("circular", amount, d["face_width"], float(p["crowning_log_a2"])),
        misalignment("in", -0.2 * DEG, base, p["te_pivot"]),
    )

    def run_te(setting):
        return te_study(te_pair, int(setting["te_n_points"]))["te_extreme"] / ARCSEC

    return {
        "rate_n_starts": {
            "run": run_rate,
            "settings": [{"n_starts": n} for n in (250, 500, 1000, 2000, 5000)],
            "reference": {"n_starts": 20000},
            "error": lambda a, b: abs(a - b),
            "error_unit": "percentage points",
            "error_target": 0.1 * BENCH_RATE_TOL_PCT,
            "current": {"n_starts": p["n_starts"]},
        },
        "newton_tol": {
            "run": run_tol,
            "settings": [{"tol": t} for t in (1e-6, 1e-8, 1e-10, 1e-12, 1e-13)],
            "reference": {"tol": 1e-14},
            "error": err_tol,
            "error_unit": "mm",
            "error_target": 0.1 * BENCH_AGREE_MM,
            "current": {"tol": p["tol"]},
        },
        "te_grid": {
            "run": run_te,
            "settings": [{"te_n_points": n} for n in (11, 21, 41, 61, 121)],
            "reference": {"te_n_points": 241},
            "error": lambda a, b: abs(a - b),
            "error_unit": "arcsec",
            "error_target": 0.1 * BENCH_TE_TOL_ARCSEC,
            "current": {"te_n_points": p["te_n_points"]},
        },
    }


#: misalignments of the robustness rows (the thesis's own where it has one): spur 0.05 deg in and
#: out of plane; helical the Table 9 in-plane error; bevel pairs a shaft-angle error of 0.05 deg
#: with an offset dE (0.05 mm straight, 0.01 module spiral)
ROBUSTNESS_MISALIGNMENT = {"spur_dgamma_deg": 0.05, "bevel_dgamma_deg": 0.05, "straight_dE_mm": 0.05, "spiral_dE": 0.01}


def robustness_cases(settings: dict, design: Design) -> list:
    """Pairs of the start-robustness table (:func:`gearrep.tca.start_robustness`), aligned and
    misaligned: dicts with ``family``, ``misalignment`` (label), ``pair`` and ``phi1`` (five
    angles over the part of the meshing cycle where the tooth pair is in contact, in angular
    pitches from phi1 = -pi/(2 N1) (the aligned bevel pairs' pitch-cone contact): -0.2 to 0.2 for spur and straight bevel,
    0.15 to 0.45 for the helical pair, whose profile-crowned contact crosses the face and is on
    it from about 0.1 on; for the spiral pair from 0.4 of a pitch before phi1 = 0 to it, where its
    contact ends about 0.09 after)."""
    m = ROBUSTNESS_MISALIGNMENT
    spur_mis = Misalignment(d_gamma_in=m["spur_dgamma_deg"] * DEG, d_gamma_out=m["spur_dgamma_deg"] * DEG)
    hel_mis = Misalignment(d_gamma_in=float(design.helical_misalignment_arcmin) * ARCMIN)
    out = []

    def add(family, mis_label, pair, lo, hi, pitch=True):
        per = 2 * np.pi / pair.n1
        centre = -np.pi / (2 * pair.n1) if pitch else 0.0
        out.append(dict(family=family, misalignment=mis_label, pair=pair, phi1=centre + np.linspace(lo, hi, 5) * per))

    for mis, lab in ((None, "aligned"), (spur_mis, f"dgamma_in = dgamma_out = {m['spur_dgamma_deg']:g} deg")):
        add("involute spur 52/72 (crowned)", lab, design_pair(design, "spur_52_72", mis), -0.2, 0.2)
    for mis, lab in ((None, "aligned"), (hel_mis, f"dgamma_in = {design.helical_misalignment_arcmin:g} arcmin")):
        add("involute helical 25/77 (profile-crowned)", lab, design_pair(design, "helical_25_77", mis), 0.15, 0.45)
    for case, crown, dE, unit in (
        ("straight_bevel_39_32", settings["bevel_conv_crown_straight_per_mm"], m["straight_dE_mm"], "mm"),
        ("spiral_bevel_17_17", settings["bevel_conv_crown_spiral"], m["spiral_dE"], "module"),
    ):
        flank_pairs = ("convex1", "concave1") if case.startswith("spiral") else ("convex1",)
        for fp in flank_pairs:
            family = f"{case.replace('_', ' ', 1).replace('_', ' ')} (crowned" + (
                f", {fp})" if case.startswith("spiral") else ")"
            )
            bmis = BevelMisalignment(d_E=dE, d_gamma=m["bevel_dgamma_deg"] * DEG)
            for mis, lab in ((None, "aligned"), (bmis, f"dgamma = {m['bevel_dgamma_deg']:g} deg, dE = {dE:g} {unit}")):
                pair = bevel_pair(design, case, crown=crown, flank_pair=fp, misalignment=mis)
                if case.startswith("spiral"):
                    add(family, lab, pair, -0.4, 0.0, pitch=False)
                else:
                    add(family, lab, pair, -0.2, 0.2)
    return out
