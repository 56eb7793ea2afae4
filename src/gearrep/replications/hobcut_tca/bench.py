"""The hob-cut curvilinear pair in the start-robustness table (workflow/scripts/bench_robustness.py)."""

from __future__ import annotations

import numpy as np

from ...tca import HobbedAssembly, hob_pitch_l, hobbed_continue_to, predict_envelope_contact
from .studies import TABLE_EXAMPLE, assembly_of, phi1_grid

__all__ = ["robustness_cases"]


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
