"""Time-vs-error cases of seed 000 ch. 5 (workflow/scripts/bench_replication.py) and the hob-cut
curvilinear pair in the start-robustness table (workflow/scripts/bench_robustness.py)."""

from __future__ import annotations

import numpy as np

from ...tca import (
    HobbedAssembly,
    clear_hobbed_start_cache,
    hob_pitch_l,
    hobbed_continue_to,
    ke_table,
    predict_envelope_contact,
    require_converged,
)
from .design import TABLE_EXAMPLE, Design, phi1_grid, validate
from .studies import assembly_of, compute_case

__all__ = ["bench_cases", "robustness_cases"]


def robustness_cases(settings: dict, design) -> list:
    """The Table 5.4 example pair (seed 000 ch. 5), aligned and with the example's assembly errors:
    dicts with ``family``, ``misalignment``, ``pair``, ``phi1`` (five angles over 0.8 of the
    study's phi1' grid), ``start`` (the physical contact at phi1' = 0 by continuation,
    :func:`gearrep.tca.hobbed_continue_to`), ``nominal(phi1)`` (the first-order path predictor off
    it, :func:`gearrep.tca.predict_envelope_contact`), ``box`` (the pinion flank of the starts: hob
    parameter l over the working depth, pitch line +- m / cos(alpha_n) along the profile; swivel
    psi over the face, +- (B / 2) / R_cp) and ``tol``."""
    case = design.cases[TABLE_EXAMPLE["5.4"]]
    tol = settings["tol"]
    g = phi1_grid(settings)
    out = []
    for asm, lab in (
        (HobbedAssembly(0.0, 0.0, 0.0, 0.0), "aligned"),
        (assembly_of(case), "Table 5.4 example's errors"),
    ):
        pair, s0 = hobbed_continue_to(
            design.gears, case["R_cp_mm"], case["R_cg_mm"], asm, steps=settings["continuation_steps"], tol=tol
        )
        hob = pair.pinion.gear.hob
        dl = hob.module_mm / np.cos(hob.pressure_angle_rad)
        l0 = hob_pitch_l(hob)
        dpsi = 0.5 * pair.face_width_mm / case["R_cp_mm"]

        def nominal(phi1, pair=pair, s0=s0):
            n = len(phi1)
            return predict_envelope_contact(pair, np.repeat(s0.x, n, 0), np.repeat(s0.phi1, n), phi1)

        out.append(
            dict(
                family="hob-cut curvilinear pair (seed 000 Table 5.4 example)",
                misalignment=lab,
                pair=pair,
                phi1=np.linspace(0.4 * g.min(), 0.4 * g.max(), 5),
                start=s0,
                nominal=nominal,
                box=(np.array([l0 - dl, -dpsi]), np.array([l0 + dl, dpsi])),
                tol=tol,
            )
        )
    return out


def bench_cases(settings: dict, design: Design) -> dict[str, dict]:
    """Cases for workflow/scripts/bench_replication.py: one KE table (the assembly of Table 5.4,
    Example 5.4, 11 positions), computed cold (ideal start not cached), over the solver tolerance
    and the number of continuation steps. Errors against the most accurate setting: max |KE -
    KE_ref| [arcsec] and max |Z_p - Z_p,ref| [mm]; targets a tenth of the printed half-unit."""
    validate(settings, design)
    phi1 = phi1_grid(settings)
    case = design.cases[TABLE_EXAMPLE["5.4"]]
    grid = [{"tol": t, "continuation_steps": s} for t in (1e-6, 1e-8, 1e-10, 1e-11, 1e-12) for s in (1, 2, 4)]
    reference = {"tol": 1e-13, "continuation_steps": 8}

    def run_one(setting):
        clear_hobbed_start_cache()
        pair, sol = compute_case(design.gears, case, phi1, tol=setting["tol"], steps=setting["continuation_steps"])
        require_converged(sol, f"bench {setting}")
        return ke_table(sol, pair.ratio)

    current = {"tol": settings["tol"], "continuation_steps": settings["continuation_steps"]}
    common = {"run": run_one, "settings": grid, "reference": reference, "error_target": 5e-5, "current": current}
    return {
        "ke_table_5_4_KE": {
            **common,
            "error": lambda r, ref: float(np.max(np.abs(r["KE_arcsec"] - ref["KE_arcsec"]))),
            "error_unit": "arcsec",
        },
        "ke_table_5_4_Zp": {
            **common,
            "error": lambda r, ref: float(np.max(np.abs(r["Z_p_mm"] - ref["Z_p_mm"]))),
            "error_unit": "mm",
        },
    }
