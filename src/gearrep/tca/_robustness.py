"""How reliably a start strategy finds the right contact: the reference contact of a pair at a few
angles, independent of the strategy, and the outcome of solves from starts drawn uniformly over
flank 1 (see :func:`gearrep.tca.robust_contact`).

The reference is the contact traced by continuation (:func:`trace_path`) from the family's
nominal start at the middle angle outwards, and it is verified at every angle: converged with
opposite outward normals and inside both flanks (status CONVERGED), a tangency that meshes, and
the loaded tangency: no meshing root reached from a grid of starts over flank 1 at that angle is
more advanced in the sense the load pushes member 2 (:func:`gearrep.tca.meshing_sense`).
"""

from __future__ import annotations

import time

import numpy as np

from ..inputs import check_integer
from ..solve import Status
from ._formulations import check_formulation
from ._pair import ContactPoints, GearPair, _wrap
from ._path import trace_path
from ._starts import _solve_projected, flank_sense, meshing_sense

__all__ = ["ROBUSTNESS_COLUMNS", "reference_contacts", "classify_contacts", "start_robustness"]

#: columns of a robustness row (:func:`start_robustness`)
ROBUSTNESS_COLUMNS = (
    "n_starts",
    "n_angles",
    "correct_pct",
    "wrong_root_pct",
    "not_converged_pct",
    "mean_iterations",
    "seconds_per_solve",
)

#: the grid of starts (fractions of flank 1's box along the profile x along the face) that checks
#: the reference is the loaded tangency
_CHECK_GRID = tuple((fu, fv) for fv in np.linspace(0.05, 0.95, 5) for fu in np.linspace(0.05, 0.95, 7))


def reference_contacts(
    pair: GearPair,
    phi1,
    start,
    *,
    formulation: str = "conventional",
    nominal=None,
    tol: float = 1e-12,
    maxiter: int = 100,
    te_slack_rad: float = 1e-9,
) -> ContactPoints:
    """The verified reference contact at each angle of ``phi1`` (increasing): traced by continuation
    from ``start`` (one row of ``formulation``'s unknowns, the family's nominal start at the middle
    angle) towards both ends, then checked (module docstring; ``nominal(pair, phi1)`` -> (n, 5)
    conventional starts for a member 2 without explicit form). ValueError naming the angle where
    the reference does not hold.

    Parameters
    ----------
    pair : GearPair
        The pair.
    phi1 : (n,) array_like
        Increasing angles of member 1 [rad].
    start : array_like
        One row of ``formulation``'s unknowns at the middle angle (flank units, rad).
    formulation : {"conventional", "reduced"}, optional
        The formulation traced.
    nominal : callable, optional
        ``nominal(pair, phi1) -> (n, 5)`` conventional starts, for a member 2 without explicit form.
    tol : float, optional
        Residual tolerance of the solves.
    maxiter : int, optional
        Iteration limit of the solves.
    te_slack_rad : float, optional
        Slack of the loaded-tangency check [rad].

    Returns
    -------
    ContactPoints
        The verified contact at every angle.

    Raises
    ------
    ValueError
        Naming the angle where the reference does not hold.

    Examples
    --------
    >>> import math
    >>> import numpy as np
    >>> from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks
    >>> from gearrep.tca import GearPair, Misalignment, solve_contact
    >>> g1 = InvoluteGearData(23, 3.0, math.radians(20), 25.0)  # teeth, module mm, rad, face mm
    >>> g2 = InvoluteGearData(41, 3.0, math.radians(20), 25.0)
    >>> f1, f2 = mating_flanks(g1, g2, crowning1=ParabolicCrowning(1e-4))  # 1/mm
    >>> pair = GearPair(f1, f2, 23, 41, g1.r_p + g2.r_p, misalignment=Misalignment(d_E=0.01))
    >>> from gearrep.tca import default_start, reference_contacts
    >>> ref = reference_contacts(pair, [-0.05, 0.0, 0.05], default_start(pair, 0.0, "conventional")[0])
    >>> ref.status_name.tolist()
    ['converged', 'converged', 'converged']
    """
    check_formulation(formulation)
    phi1 = np.asarray(phi1, dtype=float)
    if phi1.ndim != 1 or len(phi1) == 0 or not np.all(np.isfinite(phi1)) or np.any(np.diff(phi1) <= 0):
        raise ValueError(f"phi1 must be a non-empty 1-D array of increasing finite angles [rad], got {phi1!r}")
    i0 = len(phi1) // 2
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        up = trace_path(pair, phi1[i0:], start, formulation=formulation, tol=tol, maxiter=maxiter)
        down = trace_path(pair, phi1[i0::-1], start, formulation=formulation, tol=tol, maxiter=maxiter)
    ref = ContactPoints.concatenate([down.take(np.arange(len(down) - 1, 0, -1)), up])
    bad = np.flatnonzero(~ref.converged)
    if len(bad):
        raise ValueError(
            f"no verified reference contact at phi1 = {phi1[bad[0]]!r} rad (status {ref.status_name[bad[0]]})"
        )
    lo, hi = pair.lower1, pair.upper1
    g = lo + np.asarray(_CHECK_GRID) * (hi - lo)
    k = len(g)
    n = len(phi1)
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        c = _solve_projected(
            pair, np.repeat(phi1, k), np.tile(g[:, 0], n), np.tile(g[:, 1], n), formulation, tol, maxiter, nominal
        )
    r1, r2 = meshing_sense(pair, ref)
    bad = np.flatnonzero((r1 != r2) | (r1 != flank_sense(pair, ref.phi1)))
    if len(bad):
        raise ValueError(
            f"the traced contact at phi1 = {phi1[bad[0]]!r} rad does not mesh in the sense flank 1 faces (meshing_sense, flank_sense)"
        )
    s1, s2 = meshing_sense(pair, c)
    same = c.converged & (s1 == s2) & (s2 == np.repeat(r2, k))  # meshing as the reference does
    te = np.where(same, s2 * c.te, -np.inf).reshape(n, k).max(axis=1)
    ahead = np.flatnonzero(te > r2 * ref.te + te_slack_rad)
    if len(ahead):
        i = ahead[0]
        raise ValueError(
            f"the traced contact at phi1 = {phi1[i]!r} rad is not the loaded tangency: a meshing root "
            f"{te[i] - r2[i] * ref.te[i]:.3g} rad ahead of it"
        )
    return ref


def classify_contacts(c: ContactPoints, ref: ContactPoints, *, tol_param: float = 1e-6, tol_rad: float = 1e-8):
    """Outcome of each solve of ``c`` against the reference ``ref`` (same rows): ``"correct"``
    (CONVERGED, u1, v1, u2, v2 within ``tol_param`` and phi2 within ``tol_rad`` of the reference),
    ``"wrong_root"`` (a solution elsewhere, on or off the flanks, or with normals not opposite),
    ``"not_converged"`` (no solution: iteration limit, stalled line search, singular, diverged).

    Parameters
    ----------
    c : ContactPoints
        The solves to classify.
    ref : ContactPoints
        The reference contact of each row.
    tol_param : float, optional
        Tolerance of the flank parameters [their unit, e.g. mm].
    tol_rad : float, optional
        Tolerance of phi2 [rad].

    Returns
    -------
    numpy.ndarray
        One outcome string per row.

    Examples
    --------
    >>> import math
    >>> import numpy as np
    >>> from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks
    >>> from gearrep.tca import GearPair, Misalignment, solve_contact
    >>> g1 = InvoluteGearData(23, 3.0, math.radians(20), 25.0)  # teeth, module mm, rad, face mm
    >>> g2 = InvoluteGearData(41, 3.0, math.radians(20), 25.0)
    >>> f1, f2 = mating_flanks(g1, g2, crowning1=ParabolicCrowning(1e-4))  # 1/mm
    >>> pair = GearPair(f1, f2, 23, 41, g1.r_p + g2.r_p, misalignment=Misalignment(d_E=0.01))
    >>> from gearrep.tca import classify_contacts, default_start, reference_contacts
    >>> phi1 = [-0.05, 0.0, 0.05]
    >>> ref = reference_contacts(pair, phi1, default_start(pair, 0.0, "conventional")[0])
    >>> classify_contacts(solve_contact(pair, phi1), ref).tolist()
    ['correct', 'correct', 'correct']
    """
    d = np.column_stack([c.u1 - ref.u1, c.v1 - ref.v1, c.u2 - ref.u2, c.v2 - ref.v2])
    with np.errstate(invalid="ignore"):
        same = np.all(np.abs(d) < tol_param, axis=1) & (np.abs(_wrap(c.phi2 - ref.phi2)) < tol_rad)
    solved = np.isin(c.status, [Status.CONVERGED, Status.OFF_FLANK, Status.WRONG_ROOT])
    out = np.full(len(c), "not_converged", dtype=object)
    out[solved] = "wrong_root"
    out[solved & same & (c.status == Status.CONVERGED)] = "correct"
    return out


def start_robustness(
    pair: GearPair,
    ref: ContactPoints,
    n_per_angle: int,
    rng: np.random.Generator,
    solve,
    *,
    box=None,
    classify=None,
) -> dict:
    """One robustness row: ``n_per_angle`` starts (u1, v1) drawn uniformly over flank 1 (``box`` =
    (lower, upper), default the pair's ``lower1``, ``upper1``) at every angle of the reference
    ``ref`` (:func:`reference_contacts`; any record with ``phi1`` and ``take``), solved as one
    batch by ``solve(pair, phi1, u1, v1)`` (e.g. :func:`gearrep.tca.robust_contact` with its
    options) and classified by ``classify(result, reference rows)`` -> (outcomes, iterations)
    (default :func:`classify_contacts` of :class:`ContactPoints`). Returns the
    :data:`ROBUSTNESS_COLUMNS` (percentages of the starts; mean iterations over all solves; wall
    seconds per solve of the batch).

    Parameters
    ----------
    pair : GearPair
        The pair.
    ref : ContactPoints
        The reference contacts (:func:`reference_contacts`).
    n_per_angle : int
        Starts per angle.
    rng : numpy.random.Generator
        The source of the starts.
    solve : callable
        ``solve(pair, phi1, u1, v1)`` -> a record ``classify`` reads.
    box : tuple of array_like, optional
        (lower, upper) of the drawn (u1, v1) [flank units].
    classify : callable, optional
        ``classify(result, reference rows)`` -> (outcomes, iterations).

    Returns
    -------
    dict
        The :data:`ROBUSTNESS_COLUMNS` of the row.

    Raises
    ------
    ValueError
        If ``n_per_angle`` is not an integer >= 1.

    Examples
    --------
    >>> import math
    >>> import numpy as np
    >>> from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks
    >>> from gearrep.tca import GearPair, Misalignment, solve_contact
    >>> g1 = InvoluteGearData(23, 3.0, math.radians(20), 25.0)  # teeth, module mm, rad, face mm
    >>> g2 = InvoluteGearData(41, 3.0, math.radians(20), 25.0)
    >>> f1, f2 = mating_flanks(g1, g2, crowning1=ParabolicCrowning(1e-4))  # 1/mm
    >>> pair = GearPair(f1, f2, 23, 41, g1.r_p + g2.r_p, misalignment=Misalignment(d_E=0.01))
    >>> from gearrep.tca import default_start, reference_contacts, robust_contact, start_robustness
    >>> phi1 = [-0.05, 0.0, 0.05]
    >>> ref = reference_contacts(pair, phi1, default_start(pair, 0.0, "conventional")[0])
    >>> row = start_robustness(pair, ref, 20, np.random.default_rng(0), robust_contact)
    >>> row["n_starts"], float(row["correct_pct"])
    (60, 100.0)
    """
    check_integer("n_per_angle", n_per_angle)
    n = n_per_angle * len(ref.phi1)
    idx = np.repeat(np.arange(len(ref.phi1)), n_per_angle)
    lo, hi = (pair.lower1, pair.upper1) if box is None else box
    u1 = rng.uniform(lo[0], hi[0], n)
    v1 = rng.uniform(lo[1], hi[1], n)
    t0 = time.perf_counter()
    c = solve(pair, ref.phi1[idx], u1, v1)
    sec = time.perf_counter() - t0
    if classify is None:
        out, iterations = classify_contacts(c, ref.take(idx)), c.iterations
    else:
        out, iterations = classify(c, ref.take(idx))
    return dict(
        n_starts=n,
        n_angles=len(ref.phi1),
        correct_pct=100.0 * np.mean(out == "correct"),
        wrong_root_pct=100.0 * np.mean(out == "wrong_root"),
        not_converged_pct=100.0 * np.mean(out == "not_converged"),
        mean_iterations=float(np.mean(iterations)),
        seconds_per_solve=sec / n,
    )
