"""Sec 6.1 path study (claim 003-S6.1-path_points_fail_despite_close_guess): the conventional TCA
traced along the path of contact of the 25/25 pair (m = 2.5, aligned and with the sec 6.1 in-plane
misalignment), each point started close to its root.

Protocol (the thesis states only the u2, v2 and phi2 starts; the rest is ours and stated):

* path points: ``n`` phi1 values evenly spaced over one pair's engagement (the range where the
  reduced formulation finds the contact inside both flanks, :func:`.te.engagement_contacts`),
  trimmed by 2 % at each end; the reference contact of each point is the reduced solve there (one
  vectorised call; a conventional start counts as correct only if it lands on it, which is then
  itself the agreement of the two formulations);
* start: u1, v1 and u2, v2 at the mid-points of their flanks ("the centres of the surfaces"), phi2 =
  the root + d, with |d| growing linearly from 0.03 rad at the first point (start of engagement,
  smallest phi1) to 0.3 rad at the last; the sign of the offset is not printed: both signs are run;
* solver: plain conventional Newton (variant ``plain``), the settings' tol and maxiter; each
  outcome classified against the reference (:func:`.convergence.classify`: correct, wrong_root,
  not_converged, singular, diverged).
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from ...solve import Status
from ...tca import Misalignment, line_of_action_starts, solve_contact
from ...units import DEG
from .convergence import Reference, run_variant
from .design import Design, design_pair
from .te import engagement_contacts

#: phi2-start offsets of the printed path study: 0.03 rad at the first contact, 0.3 rad at the last
OFFSET_FIRST_RAD, OFFSET_LAST_RAD = 0.03, 0.3
PATH_POINTS = 15


def path_points(pair, n: int, tol: float) -> np.ndarray:
    """``n`` phi1 values over the engagement of one pair, trimmed by 2 % at each end."""
    phi, c = engagement_contacts(pair, 41, tol)
    ok = c.converged
    if ok.sum() < 3:
        raise ValueError("no engagement found for the path study")
    lo, hi = float(phi[ok].min()), float(phi[ok].max())
    trim = 0.02 * (hi - lo)
    return np.linspace(lo + trim, hi - trim, int(n))


def path_references(pair, phis: np.ndarray, tol: float) -> list:
    """Reference contact (reduced solve from the line-of-action start) at each path point; the
    conventional solution field is NaN (not solved here, see the module docstring)."""
    with np.errstate(invalid="ignore", divide="ignore"):
        c = solve_contact(pair, phis, line_of_action_starts(pair, phis), formulation="reduced", tol=tol, maxiter=100)
    if not np.all(c.status == Status.CONVERGED):
        raise ValueError(f"path study: no reference contact at phi1 = {phis[c.status != Status.CONVERGED]}")
    x = c.unknowns("conventional")
    _, n1 = pair.member1(x[:, 0], x[:, 1], phis)
    drop = np.argmax(np.abs(n1), axis=1)
    return [Reference(float(p), x[k], np.full(5, np.nan), int(drop[k])) for k, p in enumerate(phis)]


def path_study(pair, label: str, settings: dict, n: int = PATH_POINTS) -> list:
    phis = path_points(pair, n, float(settings["tol"]))
    offsets = np.linspace(OFFSET_FIRST_RAD, OFFSET_LAST_RAD, len(phis))
    lo1, hi1, lo2, hi2 = pair.lower1, pair.upper1, pair.lower2, pair.upper2
    mid = [0.5 * (lo1[0] + hi1[0]), 0.5 * (lo1[1] + hi1[1]), 0.5 * (lo2[0] + hi2[0]), 0.5 * (lo2[1] + hi2[1])]
    rows = []
    for k, (ref, off) in enumerate(zip(path_references(pair, phis, float(settings["tol"])), offsets)):
        phi1 = ref.phi1
        for sign in (1.0, -1.0):
            start = np.array([[*mid, ref.x[4] + sign * off]])
            outcome, iters, x, _ = run_variant(pair, ref, start, "plain", settings)
            rows.append(
                dict(
                    case=label,
                    point=k,
                    phi1_rad=float(phi1),
                    offset_rad=float(sign * off),
                    outcome=str(outcome[0]),
                    iterations=int(iters[0]),
                    phi2_error_rad=float(x[0, 4] - ref.x[4]) if np.isfinite(x[0, 4]) else np.nan,
                    u1_ref_mm=float(ref.x[0]),
                    v1_ref_mm=float(ref.x[1]),
                )
            )
    return rows


def path_guess_table(settings: dict, design: Design) -> dict:
    """Job ``path_guess``: the path study on the aligned 25/25 pair and with the sec 6.1 in-plane
    misalignment."""
    deg = float(design.sec61_misalignment_deg)
    rows = path_study(design_pair(design, "spur_25_25"), "spur_25_25", settings)
    rows += path_study(
        design_pair(design, "spur_25_25", misalignment=Misalignment(d_gamma_in=deg * DEG)),
        f"spur_25_25_inplane_{deg:g}deg",
        settings,
    )
    return dict(path_guess=pd.DataFrame(rows))
