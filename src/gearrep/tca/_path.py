"""The path of contact by continuation over a grid of angles (Litvin & Fuentes ch. 9), on the
contact solves of the formulations (:func:`gearrep.tca.solve_contact`)."""

from __future__ import annotations

import numpy as np

from ..solve import Status
from ._formulations import _angles, _check_knobs, _face_coordinates, check_formulation, default_start, solve_contact
from ._pair import ContactPoints, GearPair

__all__ = ["trace_path"]


def trace_path(
    pair: GearPair,
    phi1,
    start=None,
    *,
    formulation: str = "reduced",
    v1=None,
    jacobian: str = "analytic",
    tol: float = 1e-12,
    maxiter: int = 50,
    phi10: float = 0.0,
    phi20: float = 0.0,
    predictor: bool = True,
) -> ContactPoints:
    """Path of contact over the angles ``phi1`` (in order) by continuation (Litvin & Fuentes ch. 9).

    Each position starts from the previous converged solution (linearly extrapolated from the last
    two when ``predictor``); ``start`` (one row, as for :func:`solve_contact`) is used for the first
    position. A failed position does not seed the next one.

    Parameters
    ----------
    pair : GearPair
        The pair.
    phi1 : (n,) array_like
        Angles of member 1 [rad], in the order they are traced.
    start : (2,) or (5,) array_like, optional
        Start of the first position, as for :func:`solve_contact` (default :func:`default_start`).
    formulation, v1, jacobian, tol, maxiter, phi10, phi20 : optional
        As :func:`solve_contact`.
    predictor : bool, optional
        Extrapolate the next start linearly from the last two solutions.

    Returns
    -------
    ContactPoints
        In the order of ``phi1``.

    Raises
    ------
    ValueError
        As :func:`solve_contact`, before any solve; and if ``start`` is not one row.

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
    >>> from gearrep.tca import trace_path
    >>> path = trace_path(pair, np.linspace(-0.05, 0.05, 11))  # rad
    >>> bool(path.converged.all()), round(float(np.ptp(path.te_arcsec)), 6)  # TE [arcsec]
    (True, 0.0)
    """
    check_formulation(formulation)
    _check_knobs(tol, maxiter, phi10, phi20)
    phi1 = _angles(phi1)
    width = 2 if formulation == "reduced" else 5
    x = default_start(pair, phi1[:1], formulation)[0] if start is None else np.asarray(start, float).reshape(-1)
    if x.shape != (width,):
        raise ValueError(f"start must have {width} entries, got shape {x.shape}")
    v1a = None if v1 is None else _face_coordinates(v1, len(phi1))
    out, hist = [], []  # hist: (phi1, solution) of converged points
    for i, p in enumerate(phi1):
        guess = x
        if predictor and len(hist) >= 2 and hist[-1][0] != hist[-2][0]:
            (pa, xa), (pb, xb) = hist[-2], hist[-1]
            guess = xb + (xb - xa) * (p - pb) / (pb - pa)
        elif hist:
            guess = hist[-1][1]
        c = solve_contact(
            pair,
            p,
            guess[None, :],
            formulation=formulation,
            v1=None if v1a is None else v1a[i],
            jacobian=jacobian,
            tol=tol,
            maxiter=maxiter,
            phi10=phi10,
            phi20=phi20,
        )
        if c.status[0] != Status.CONVERGED and len(hist) >= 1 and predictor:
            c2 = solve_contact(
                pair,
                p,
                hist[-1][1][None, :],
                formulation=formulation,
                v1=None if v1a is None else v1a[i],
                jacobian=jacobian,
                tol=tol,
                maxiter=maxiter,
                phi10=phi10,
                phi20=phi20,
            )
            if c2.status[0] == Status.CONVERGED:
                c = c2
        out.append(c)
        if c.status[0] == Status.CONVERGED:
            hist.append((p, c.unknowns(formulation)[0]))
    return ContactPoints.concatenate(out)
