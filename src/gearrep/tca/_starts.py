"""Start strategies of the TCA (see :mod:`gearrep.tca`): first-order starts along the line of
action, random starts over the flanks, a family's nominal starts moved by the offset of a solved
contact, and the library's strategy for a start anywhere on the flank (:func:`robust_contact`).
The solver variants the start-robustness study compares are in the private module ``_variants``.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from ..inputs import check_integer, check_positive
from ..solve import Status
from ._formulations import _angles, check_formulation, solve_contact
from ._pair import GearPair
from ._variants import _guard, _start_pairs, _transverse, seed_from_reduced

__all__ = [
    "line_of_action_start",
    "line_of_action_starts",
    "draw_starts",
    "offset_start",
    "FALLBACK_GRID",
    "project_starts",
    "robust_contact",
    "meshing_sense",
    "flank_sense",
]


def offset_start(
    pair: GearPair, phi1, nominal, *, formulation="conventional", solve=None, tol=1e-12, maxiter=50, order: int = 0
):
    """Starts at member-1 angles ``phi1`` (rad): a family's nominal starts ``nominal(pair, phi1)``
    ((n, 5) conventional or (n, 2) reduced unknowns) moved by the offset of one solved contact from
    its nominal start, x_ref - nominal(pair, [phi_ref]), at the reference angle phi_ref = the phi1
    nearest the middle of their range.

    A nominal start that ignores the misalignment (an aligned contact) misses the misaligned
    contact by an offset that changes little from one meshing position to the next; Newton then
    starts far from the root on a curved valley of the residual, where the line search keeps
    shortening its steps. Example: the Novikov-Wildhaber pair of seed 002 (near-conformal profiles,
    rho_c = 5.88/P_n against rho_t = 6.35/P_n) under a 3 arcmin crossing error: its contact moves
    0.125 in across the profile and 0.93 in along the tooth from the aligned one, the same to
    2e-5 in and 7e-4 in over an angular pitch, and the damped solve from the aligned contact takes
    about 32 iterations (the residual norm on the straight line to the root rises 15-fold), from the
    moved start 2-3.

    ``order`` 1 to 3: the offset a polynomial of that degree in the angle, through the offsets
    solved at the order + 1 angles nearest the fractions (k + 1/2) / (order + 1) of the range (a
    quarter and three quarters for a linear offset), for a nominal start that drifts from the
    contact along the path: the ground Novikov pinions of seed 002, whose aligned start misses the
    contact by up to 0.8 in along the tooth at the ends of a pitch and 0.03 in at its middle (their
    mean Newton iterations over a pitch, 200 angles, 3 arcmin crossing error: disk-ground 9.9,
    3.8, 3.0 and worm-ground 4.8 from the nominal start, 3.2, 2.2 for orders 0, 1, 2). Where
    references fail, the polynomial through the others (one less degree each).

    ``solve(pair, phi_ref, start)`` -> :class:`ContactPoints` (phi_ref and start one row each) solves
    the reference; default :func:`solve_contact` (damped Newton, ``formulation``, ``tol``,
    ``maxiter``), so the reference is the root the nominal start reaches, and where the offset
    changes slowly with the angle the moved starts lead to the roots the nominal ones reach
    (tested on the seed-002 pair). A stronger start strategy (a robust solve of the reference)
    plugs in here. Where no reference converges, or ``phi1`` has at most order + 1 angles (the
    references would be the solves themselves), the nominal starts are returned unchanged.

    Parameters
    ----------
    pair : GearPair
        The pair (or a :class:`BevelPair`).
    phi1 : float or (n,) array_like
        Angles of member 1 [rad].
    nominal : callable
        ``nominal(pair, phi1)`` -> the family's nominal starts, (n, 5) conventional or (n, 2)
        reduced unknowns [flank units (mm for involute flanks), rad].
    formulation : {"conventional", "reduced"}, optional
        The unknowns of the starts and of the reference solves.
    solve : callable, optional
        ``solve(pair, phi_ref, start)`` -> :class:`ContactPoints`, the reference solve (see above).
    tol : float, optional
        Residual tolerance of the default reference solve [flank units].
    maxiter : int, optional
        Iteration limit of the default reference solve.
    order : {0, 1, 2, 3}, optional
        Degree of the offset's polynomial in the angle.

    Returns
    -------
    numpy.ndarray
        (n, 5) or (n, 2) starts, the nominal ones moved [flank units, rad].

    Raises
    ------
    ValueError
        If ``formulation`` is unknown, ``order`` is not 0 to 3, or ``nominal`` returns starts of
        another shape.

    Examples
    --------
    A crossing error of 0.05 deg moves the contact of a crowned spur pair 4.1 mm along the face,
    away from the aligned pair's mid-face starts:

    >>> import math
    >>> import numpy as np
    >>> from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks
    >>> from gearrep.tca import GearPair, Misalignment, default_start, offset_start, solve_contact
    >>> g1, g2 = (InvoluteGearData(n, 3.0, math.radians(20), 25.0) for n in (23, 41))  # module mm, rad, face mm
    >>> flanks = mating_flanks(g1, g2, crowning1=ParabolicCrowning(1e-4))  # crown 1/mm
    >>> pair = GearPair(*flanks, 23, 41, g1.r_p + g2.r_p, misalignment=Misalignment(d_gamma_out=math.radians(0.05)))
    >>> phi1 = np.linspace(-0.1, 0.1, 5)  # rad
    >>> def nominal(pair, phi1):
    ...     return default_start(pair, phi1, "conventional")
    >>> x0 = offset_start(pair, phi1, nominal)
    >>> np.round(nominal(pair, phi1)[:, 1], 3).tolist(), np.round(x0[:, 1], 3).tolist()  # v1 [mm]
    ([0.0, 0.0, 0.0, 0.0, 0.0], [4.1, 4.1, 4.1, 4.1, 4.1])
    >>> solve_contact(pair, phi1, x0, formulation="conventional").status_name.tolist()
    ['converged', 'converged', 'converged', 'converged', 'converged']
    """
    check_formulation(formulation)
    if order not in (0, 1, 2, 3) or type(order) is bool:
        raise ValueError(f"order must be 0 (a constant offset) to 3 (a polynomial in phi1), got {order!r}")
    phi1 = _angles(phi1)
    start = np.array(nominal(pair, phi1), dtype=float)
    width = 5 if formulation == "conventional" else 2
    if start.ndim != 2 or start.shape != (len(phi1), width):
        raise ValueError(f"nominal must return ({len(phi1)}, {width}) {formulation} starts, got shape {start.shape}")
    if len(phi1) <= 1 + order or not np.all(np.isfinite(phi1)):
        return start
    if solve is None:

        def solve(pair, ph, x0):
            return solve_contact(pair, ph, x0, formulation=formulation, tol=tol, maxiter=maxiter)

    lo, hi = phi1.min(), phi1.max()
    rows = {int(np.argmin(np.abs(phi1 - (lo + (k + 0.5) / (order + 1) * (hi - lo))))) for k in range(order + 1)}
    at, offsets = [], []
    for i in sorted(rows):
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            ref = solve(pair, phi1[i : i + 1], start[i : i + 1])
        if ref.converged[0]:
            at.append(phi1[i])
            offsets.append(ref.unknowns(formulation)[0] - start[i])
    if not at:
        return start
    if len(at) == 1:
        return start + offsets[0]
    # the polynomial through the solved offsets (Lagrange form, in the angle scaled to the range)
    t, ts = (phi1 - lo) / (hi - lo), (np.array(at) - lo) / (hi - lo)
    moved = start.copy()
    for j, oj in enumerate(offsets):
        w = np.ones_like(t)
        for m, tm in enumerate(ts):
            if m != j:
                w *= (t - tm) / (ts[j] - tm)
        moved += w[:, None] * oj
    return moved


def _involute_gear(pair: GearPair):
    """Member 1's gear data for a line-of-action start (a cylindrical involute gear: base radius and
    transverse pressure angle); ValueError for any other flank family."""
    g1 = getattr(pair.flank1, "gear", None)
    if not (getattr(pair.flank1, "cylindrical", False) and hasattr(g1, "alpha_t") and hasattr(g1, "r_b")):
        raise ValueError(
            "line-of-action starts need member 1 to be a cylindrical involute flank (base radius, transverse "
            f"pressure angle), got {type(pair.flank1).__name__}; use default_start or draw_starts for other families"
        )
    return g1


def line_of_action_start(pair: GearPair, phi1: float) -> np.ndarray:
    """(u1, v1) start at a fixed phi1: the contact of the aligned pair on mid-face to first order.

    The start takes the pitch point as the aligned pair's contact at phi1 = 0 (it is reached half a
    tooth angle away, pi/(2 N1) for a standard tooth: see the package docstring) and moves it along
    the line of action by r_b1 phi1 (direction by trial solve: the one that converges in fewer
    iterations); the Newton solve absorbs that offset of a few tenths of a module. Falls back to
    (r_p1, 0).

    Parameters
    ----------
    pair : GearPair
        The pair; member 1 a cylindrical involute flank.
    phi1 : float
        The angle of member 1 [rad], one finite angle.

    Returns
    -------
    numpy.ndarray
        (2,) start (u1, v1) [mm].

    Raises
    ------
    ValueError
        If ``phi1`` is not one finite angle or member 1 is not a cylindrical involute flank.

    Examples
    --------
    >>> import math
    >>> import numpy as np
    >>> from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks
    >>> from gearrep.tca import GearPair, line_of_action_start
    >>> g1, g2 = (InvoluteGearData(n, 3.0, math.radians(20), 25.0) for n in (23, 41))  # module mm, rad, face mm
    >>> pair = GearPair(*mating_flanks(g1, g2, crowning1=ParabolicCrowning(1e-4)), 23, 41, g1.r_p + g2.r_p)
    >>> np.round(line_of_action_start(pair, 0.0), 4).tolist()  # the pitch point, r_p1 = 34.5 mm
    [34.5, 0.0]
    >>> np.round(line_of_action_start(pair, 0.1), 4).tolist()  # rad -> mm
    [35.7389, 0.0]
    """
    a = np.asarray(phi1, dtype=float)
    if a.ndim != 0 or not np.isfinite(a):
        raise ValueError(f"phi1 must be one finite angle [rad], got {phi1!r}")
    phi1 = float(a)
    g1 = _involute_gear(pair)
    t_p = np.tan(g1.alpha_t)
    best = None
    for s in (1.0, -1.0):
        t = t_p + s * phi1
        if t < 0:
            continue
        u = g1.r_b * np.sqrt(1.0 + t * t)
        with np.errstate(invalid="ignore", divide="ignore"):
            c = solve_contact(pair, phi1, np.array([[u, 0.0]]), formulation="reduced", tol=1e-12, maxiter=50)
        if c.status[0] == Status.CONVERGED and (best is None or c.iterations[0] < best[1]):
            best = (np.array([u, 0.0]), c.iterations[0])
    if best is None:
        return np.array([g1.r_p, 0.0])
    return best[0]


def line_of_action_starts(pair: GearPair, phi1) -> np.ndarray:
    """First-order (u1, v1 = 0) starts along the line of action for the angles ``phi1`` (array);
    the direction in which the contact climbs member 1's flank is found by one trial solve.

    Parameters
    ----------
    pair : GearPair
        The pair; member 1 a cylindrical involute flank.
    phi1 : float or (n,) array_like
        Angles of member 1 [rad], finite.

    Returns
    -------
    numpy.ndarray
        (n, 2) starts (u1, v1 = 0) [mm], u1 clipped onto flank 1.

    Raises
    ------
    ValueError
        If an angle is not finite or member 1 is not a cylindrical involute flank.

    Examples
    --------
    >>> import math
    >>> import numpy as np
    >>> from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks
    >>> from gearrep.tca import GearPair, line_of_action_starts
    >>> g1, g2 = (InvoluteGearData(n, 3.0, math.radians(20), 25.0) for n in (23, 41))  # module mm, rad, face mm
    >>> pair = GearPair(*mating_flanks(g1, g2, crowning1=ParabolicCrowning(1e-4)), 23, 41, g1.r_p + g2.r_p)
    >>> np.round(line_of_action_starts(pair, [-0.1, 0.0, 0.1]), 4).tolist()  # rad -> (u1, v1) [mm]
    [[33.5299, 0.0], [34.5, 0.0], [35.7389, 0.0]]
    """
    phi1 = _angles(phi1)
    if not np.all(np.isfinite(phi1)):
        raise ValueError("phi1 must be finite")
    g1 = _involute_gear(pair)
    t_p = np.tan(g1.alpha_t)
    s = 1.0
    h = 0.25 * 2 * np.pi / pair.n1
    with np.errstate(invalid="ignore", divide="ignore"):
        c = solve_contact(pair, np.array([-h, h]), np.array([[g1.r_p, 0.0]]), formulation="reduced", tol=1e-10)
    if np.all(np.isfinite(c.u1)) and c.u1[1] < c.u1[0]:
        s = -1.0
    t = np.maximum(t_p + s * np.asarray(phi1, float), 1e-3)
    u = np.clip(g1.r_b * np.sqrt(1.0 + t * t), pair.lower1[0], pair.upper1[0])
    return np.column_stack([u, np.zeros_like(u)])


def draw_starts(
    pair: GearPair, n: int, rng: np.random.Generator, *, phi2_window=None, phi2_fixed=None, uv2: str = "uniform"
) -> np.ndarray:
    """Random conventional starts (n, 5), drawn in a fixed order from ``rng``: u1, v1 uniform on
    flank 1, then u2, v2 uniform on flank 2 (``uv2="uniform"``) or its mid-point
    (``"midpoint"``), then phi2 uniform on ``phi2_window`` = (low, high) or = ``phi2_fixed``.

    Parameters
    ----------
    pair : GearPair
        The pair (flank boxes ``lower1``, ``upper1``, ``lower2``, ``upper2``).
    n : int
        Number of starts.
    rng : numpy.random.Generator
        The random source.
    phi2_window : (float, float), optional
        The interval of phi2 [rad] (exactly one of ``phi2_window`` and ``phi2_fixed``).
    phi2_fixed : float, optional
        One phi2 for every start [rad].
    uv2 : {"uniform", "midpoint"}, optional
        How (u2, v2) are chosen.

    Returns
    -------
    numpy.ndarray
        (n, 5) starts (u1, v1, u2, v2, phi2) [flank units (mm for involute flanks), rad].

    Raises
    ------
    ValueError
        If both or neither of ``phi2_window`` and ``phi2_fixed`` are given, or ``uv2`` is unknown.

    Examples
    --------
    >>> import math
    >>> import numpy as np
    >>> from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks
    >>> from gearrep.tca import GearPair, draw_starts
    >>> g1, g2 = (InvoluteGearData(n, 3.0, math.radians(20), 25.0) for n in (23, 41))  # module mm, rad, face mm
    >>> pair = GearPair(*mating_flanks(g1, g2, crowning1=ParabolicCrowning(1e-4)), 23, 41, g1.r_p + g2.r_p)
    >>> x0 = draw_starts(pair, 100, np.random.default_rng(1), phi2_window=(-0.1, 0.1))  # rad
    >>> x0.shape, bool(np.all((x0[:, 0] >= pair.lower1[0]) & (x0[:, 0] <= pair.upper1[0])))
    ((100, 5), True)
    >>> x0 = draw_starts(pair, 2, np.random.default_rng(1), phi2_fixed=0.0, uv2="midpoint")
    >>> np.round(x0[:, 2:], 3).tolist()  # u2, v2 [mm] at flank 2's mid-point, phi2 [rad]
    [[61.146, 0.0, 0.0], [61.146, 0.0, 0.0]]
    """
    if (phi2_window is None) == (phi2_fixed is None):
        raise ValueError("give exactly one of phi2_window and phi2_fixed")
    if uv2 not in ("uniform", "midpoint"):
        raise ValueError(f"uv2 must be 'uniform' or 'midpoint', got {uv2!r}")
    lo1, hi1, lo2, hi2 = pair.lower1, pair.upper1, pair.lower2, pair.upper2
    u1 = rng.uniform(lo1[0], hi1[0], n)
    v1 = rng.uniform(lo1[1], hi1[1], n)
    if uv2 == "uniform":
        u2 = rng.uniform(lo2[0], hi2[0], n)
        v2 = rng.uniform(lo2[1], hi2[1], n)
    else:
        u2 = np.full(n, 0.5 * (lo2[0] + hi2[0]))
        v2 = np.full(n, 0.5 * (lo2[1] + hi2[1]))
    if phi2_fixed is not None:
        phi2 = np.full(n, float(phi2_fixed))
    else:
        a, b = phi2_window
        phi2 = rng.uniform(a, b, n)
    return np.column_stack([u1, v1, u2, v2, phi2])


#: fractions (along the profile, along the face) of flank 1's box where :func:`robust_contact`
#: restarts a row whose own start failed: a 4 x 3 grid spanning the flank
FALLBACK_GRID = tuple((fu, fv) for fv in (0.5, 0.2, 0.8) for fu in (0.4, 0.1, 0.7, 0.95))


def _explicit2(pair: GearPair) -> bool:
    """Whether member 2 has the explicit form the reduced formulation reads."""
    return bool(getattr(pair.flank2, "cylindrical", False) or getattr(pair.flank2, "spherical", False))


def project_starts(pair: GearPair, phi1, u1, v1):
    """(u1, v1) starts projected into the domain where member 2's explicit surface is defined:
    clipped onto flank 1's box, then moved down flank 1's profile until the explicit u2 (eq 40)
    lies on flank 2 (:func:`guard_reduced_starts`; member 2 in explicit form only). ``phi1`` one
    angle or one per start. Returns (u1, v1).

    Parameters
    ----------
    pair : GearPair
        The pair.
    phi1 : float or (n,) array_like
        Angles of member 1 [rad]: one, or one per start (finite).
    u1, v1 : (n,) array_like
        Starts on flank 1 [flank units, mm for involute flanks]; a NaN becomes the middle of the box.

    Returns
    -------
    u1, v1 : numpy.ndarray
        (n,) projected starts [flank units].

    Raises
    ------
    ValueError
        If the starts are not 1-D arrays of one length or ``phi1`` is not finite or matches neither
        one angle nor one per start.

    Examples
    --------
    >>> import math
    >>> import numpy as np
    >>> from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks
    >>> from gearrep.tca import GearPair, project_starts
    >>> g1, g2 = (InvoluteGearData(n, 3.0, math.radians(20), 25.0) for n in (23, 41))  # module mm, rad, face mm
    >>> pair = GearPair(*mating_flanks(g1, g2, crowning1=ParabolicCrowning(1e-4)), 23, 41, g1.r_p + g2.r_p)
    >>> u1, v1 = project_starts(pair, 0.0, [30.0, 36.0, np.nan], [0.0, 20.0, 1.0])  # rad, mm, mm
    >>> np.round(u1, 4).tolist(), np.round(v1, 4).tolist()  # onto the box (root 32.4194 mm, face +-12.5 mm)
    ([32.4194, 36.0, 34.9597], [0.0, 12.5, 1.0])
    """
    ph, u1, v1 = _start_pairs(phi1, u1, v1)
    lo, hi = pair.lower1, pair.upper1
    u1 = np.clip(np.where(np.isfinite(u1), u1, 0.5 * (lo[0] + hi[0])), lo[0], hi[0])
    v1 = np.clip(np.where(np.isfinite(v1), v1, 0.5 * (lo[1] + hi[1])), lo[1], hi[1])
    if _explicit2(pair):
        u1, _ = _guard(pair, ph, u1.copy(), v1, 40)
    return u1, v1


def _solve_projected(pair, ph, u1, v1, formulation, tol, maxiter, nominal, transverse=False, keep_failed=False):
    """One pass of :func:`robust_contact` from (u1, v1) starts at angles ``ph`` (no fallback);
    ``transverse``: the projected starts moved onto the contact line first
    (:func:`transverse_stage`, its iterations counted); ``keep_failed``: the last iterates of the
    rows that fail are kept (:func:`solve_contact`)."""
    u1, v1 = project_starts(pair, ph, u1, v1)
    it = 0
    if transverse:
        u1, it = _transverse(pair, ph, u1, v1, 1e-10, 50)
    if _explicit2(pair):
        keep = keep_failed and formulation == "reduced"
        c = solve_contact(
            pair, ph, np.column_stack([u1, v1]), formulation="reduced", tol=tol, maxiter=maxiter, keep_failed=keep
        )
        c = replace(c, iterations=c.iterations + it)
        if formulation == "reduced":
            return c
        x0 = seed_from_reduced(pair, ph, c.u1, c.v1)
        bad = ~np.all(np.isfinite(x0), axis=1)
        if bad.any():  # the reduced solve left member 2's domain: seed from the projected start
            x0[bad] = seed_from_reduced(pair, ph[bad], u1[bad], v1[bad])
        it = c.iterations
    else:
        x0 = np.array(nominal(pair, ph), dtype=float)
        x0[:, 0], x0[:, 1] = u1, v1
    out = solve_contact(pair, ph, x0, formulation="conventional", tol=tol, maxiter=maxiter, keep_failed=keep_failed)
    return replace(out, iterations=out.iterations + it)


def _settle_on_boundary(pair, ph, c, formulation, tol, maxiter):
    """``c`` (its failed rows' last iterates kept) with each OFF_FLANK row settled by one more
    Newton step from its root, then the status tested again; other failed rows NaN
    (:meth:`ContactPoints.failed_as_nan`).

    A root solved to ``tol`` is known only to about ||J^-1|| tol, more than the rounding slack of
    the flank test: a contact on a flank boundary (the engagement limits, where the path leaves
    a flank) can then be OFF_FLANK by a few 1e-11 mm that the solve does not resolve, although
    the root lies on the boundary. One full Newton step from a converged root gives it to
    rounding, and the unchanged flank test then decides on which side it lies; the rows it
    brings inside are CONVERGED (a restart from other starts would reach the same root), the
    others stay OFF_FLANK. The step's iteration counts."""
    rows = np.flatnonzero(c.status == Status.OFF_FLANK)
    if not len(rows):
        return c.failed_as_nan()
    x = c.unknowns(formulation)[rows]
    kw = dict(formulation=formulation, maxiter=1, damped=False, keep_failed=True)
    step = solve_contact(pair, ph[rows], x, tol=np.finfo(float).tiny, **kw)  # one step whatever the residual
    new = solve_contact(pair, ph[rows], step.unknowns(formulation), formulation=formulation, tol=tol, maxiter=maxiter)
    return _with_rows(c, rows, new, new.converged, step.iterations + new.iterations).failed_as_nan()


def _transverse_applies(pair) -> bool:
    """Whether the transverse stage means anything for ``pair``: parallel axes and member 2 an
    explicit cylindrical flank (the axial component of n1 x n2 is the transverse mismatch)."""
    return not pair._INTERSECTING_AXES and bool(getattr(pair.flank2, "cylindrical", False))


def _with_rows(c, rows, new, take, spent):
    """``c`` with its rows ``rows`` (indices) replaced by the rows of ``new`` (one per index) where
    ``take``; every row of ``rows`` adds the iterations ``spent`` (one per index)."""
    parts = {f: np.array(getattr(c, f), copy=True) for f in c.ARRAYS}
    for f in parts:
        parts[f][rows[take]] = getattr(new, f)[take]
    parts["iterations"][rows] = c.iterations[rows] + spent
    cond = None
    if c.condition is not None and new.condition is not None:
        cond = np.array(c.condition, dtype=float)
        cond[rows[take]] = new.condition[take]
    return type(c)(formulation=c.formulation, condition=cond, **parts)


def _retry(pair, c, new, bad):
    """``c`` with its rows ``bad`` replaced by the rows of ``new`` (one per row of ``bad``) that are
    CONVERGED and mesh; the iterations of every row of ``bad`` add those of ``new``."""
    new = _non_meshing_wrong(pair, new)
    return _with_rows(c, bad, new, new.converged, new.iterations)


def _non_meshing_wrong(pair, c):
    """``c`` with the CONVERGED rows that do not mesh in the sense flank 1 faces (:func:`flank_sense`)
    set to WRONG_ROOT."""
    wrong = c.converged & ~_meshes(pair, c)
    if not wrong.any():
        return c
    return replace(c, status=np.where(wrong, int(Status.WRONG_ROOT), c.status))


def _nominal_pass(pair, ph, c, tol, maxiter, nominal):
    """The rows of ``c`` that are not CONVERGED solved again from the family's nominal start at
    their angle (conventional): :func:`_retry`."""
    bad = np.flatnonzero(~c.converged)
    x0 = np.array(nominal(pair, ph[bad]), dtype=float)
    return _retry(pair, c, solve_contact(pair, ph[bad], x0, formulation="conventional", tol=tol, maxiter=maxiter), bad)


def meshing_sense(pair: GearPair, c):
    """(s1, s2) per contact of ``c`` (:class:`ContactPoints`): the signs of the velocity of member 1's
    point (turning about z_f by phi1 > 0) and of member 2's (about w2 by phi2 > 0) along member 1's
    outward normal. A tangency that meshes has s1 = s2 (the equation of meshing: both surfaces move
    alike along the common normal); one with s1 != s2 touches from the side that turning separates
    at once (not a contact of the flank pair that transmits the motion). Where member 2 turning
    forward moves its flank away (s2 > 0) the load pushes it to the tangency of largest TE, else of
    smallest: the loaded tangency maximises s2 TE.

    Parameters
    ----------
    pair : GearPair
        The pair.
    c : ContactPoints
        Contact points of ``pair``.

    Returns
    -------
    s1, s2 : numpy.ndarray
        (n,) signs (+1, -1; 0 or NaN where undefined) of the two velocities along the normal.

    Examples
    --------
    >>> import math
    >>> import numpy as np
    >>> from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks
    >>> from gearrep.tca import GearPair, default_start, meshing_sense, solve_contact
    >>> g1, g2 = (InvoluteGearData(n, 3.0, math.radians(20), 25.0) for n in (23, 41))  # module mm, rad, face mm
    >>> pair = GearPair(*mating_flanks(g1, g2, crowning1=ParabolicCrowning(1e-4)), 23, 41, g1.r_p + g2.r_p)
    >>> c = solve_contact(pair, [0.0, 0.05], default_start(pair, [0.0, 0.05]))  # rad
    >>> s1, s2 = meshing_sense(pair, c)
    >>> s1.tolist(), s2.tolist()  # both contacts mesh
    ([1.0, 1.0], [1.0, 1.0])
    """
    r, n = c.position, c.normal
    x, y, z = r[:, 0], r[:, 1], r[:, 2]
    nx, ny, nz = n[:, 0], n[:, 1], n[:, 2]
    (wx, wy, wz), (ox, oy, oz) = pair._soa["w2"], pair._soa["O2"]
    dx, dy, dz = x - ox, y - oy, z - oz
    with np.errstate(invalid="ignore"):  # v1 = z_f x r, v2 = w2 x (r - O2), by components
        s1 = np.sign(x * ny - y * nx)
        s2 = np.sign((wy * dz - wz * dy) * nx + (wz * dx - wx * dz) * ny + (wx * dy - wy * dx) * nz)
    return s1, s2


def flank_sense(pair: GearPair, phi1) -> np.ndarray:
    """The side flank 1 faces at each angle ``phi1``: the sign of its point's velocity (member 1
    turning by phi1 > 0) along its outward normal at the middle of its box. A contact of the flank
    pair meshes with s1 = s2 = this sign (:func:`meshing_sense`); a root where flank 1 faces the
    other way lies on a part of the parametric surface folded back over the tooth. The side is the
    same at every angle (member 1 turns about z_f), evaluated once per pair.

    Parameters
    ----------
    pair : GearPair
        The pair.
    phi1 : float or (n,) array_like
        Angles of member 1 [rad].

    Returns
    -------
    numpy.ndarray
        (n,) signs, +1 or -1.

    Examples
    --------
    >>> import math
    >>> from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks
    >>> from gearrep.tca import GearPair, flank_sense
    >>> g1, g2 = (InvoluteGearData(n, 3.0, math.radians(20), 25.0) for n in (23, 41))  # module mm, rad, face mm
    >>> pair = GearPair(*mating_flanks(g1, g2, crowning1=ParabolicCrowning(1e-4)), 23, 41, g1.r_p + g2.r_p)
    >>> flank_sense(pair, [0.0, 0.05]).tolist()  # rad
    [1.0, 1.0]
    """
    ph = np.atleast_1d(np.asarray(phi1, dtype=float))
    return np.full(len(ph), pair._flank1_facing)


def _meshes(pair, c) -> np.ndarray:
    """Rows of ``c`` whose tangency meshes in the sense flank 1 faces (:func:`flank_sense`)."""
    s1, s2 = meshing_sense(pair, c)
    return (s1 == s2) & (s1 == flank_sense(pair, c.phi1))


def robust_contact(
    pair: GearPair,
    phi1,
    u1,
    v1,
    *,
    formulation: str = "reduced",
    tol: float = 1e-12,
    maxiter: int = 50,
    nominal=None,
    grid=FALLBACK_GRID,
    fallback: bool = True,
):
    """Contact points at member-1 angles ``phi1`` from (u1, v1) starts anywhere on flank 1 (one
    angle, or one per start): the start strategy whose correct-root rate from starts uniform over
    the flank the robustness table measures.

    1. Each start is projected into the domain where member 2's explicit surface is defined
       (:func:`project_starts`).
    2. Member 2 in explicit form (cylindrical or spherical flank): the reduced solve (damped
       Newton, eq 33-44) from it; for ``formulation="conventional"`` the conventional solve
       seeded with the u2, v2, phi2 that the reduced relations give at the reduced result
       (:func:`seed_from_reduced`). Otherwise the conventional solve from the family's nominal
       start ``nominal(pair, phi1)`` -> (n, 5) with (u1, v1) replaced by the projected start.
       A root that this solve leaves OFF_FLANK gets one more Newton step and its flank test again
       (a root on a flank boundary, e.g. at an engagement limit, is known only to the solve's
       tolerance; :func:`_settle_on_boundary`).
    3. A row whose solve is not CONVERGED (verified: opposite normals, inside both flanks) or
       whose root does not mesh in the sense flank 1 faces (:func:`meshing_sense`,
       :func:`flank_sense`; such a row is WRONG_ROOT) is restarted: on parallel axes with member 2
       cylindrical from its projected start moved onto the contact line
       (:func:`transverse_stage`; a helical pair's start far along the face otherwise lands on
       the flat valley of the residual); for a member 2 without explicit form from the nominal
       start itself; then from the points ``grid`` of flank 1 (fractions of its box, in order); of the
       grid's verified roots at the row's angle that mesh, the loaded tangency is kept (the load
       pushes member 2 to the most advanced tangency in the sense its flank moves away:
       :func:`meshing_sense`).

    ``fallback=False`` stops after step 2 (how far the start alone leads).

    Parameters
    ----------
    pair : GearPair
        The pair (or a :class:`BevelPair`).
    phi1 : float or (n,) array_like
        Angles of member 1 [rad]: one, or one per start.
    u1, v1 : float or (n,) array_like
        Starts on flank 1 [its units, mm for involute flanks].
    formulation : {"reduced", "conventional"}, optional
        The formulation of the result.
    tol, maxiter : optional
        Residual tolerance and iteration limit of every solve.
    nominal : callable, optional
        ``nominal(pair, phi1)`` -> (n, 5) conventional starts, for a member 2 without explicit form.
    grid : sequence of (float, float), optional
        The restart points, as fractions of flank 1's box.
    fallback : bool, optional
        Restart failed rows (step 3).

    Returns
    -------
    ContactPoints
        One row per start (iterations: those of every pass a row took, the fallback's summed over
        its grid).

    Raises
    ------
    ValueError
        Before any solve: an unknown formulation, the reduced formulation (or no ``nominal``) for a
        member 2 without explicit form, a bad tolerance or iteration limit, or starts and angles
        of different lengths.

    Examples
    --------
    Starts far from the contact, near two corners of the pinion flank:

    >>> import math
    >>> import numpy as np
    >>> from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks
    >>> from gearrep.tca import GearPair, Misalignment, solve_contact
    >>> g1 = InvoluteGearData(23, 3.0, math.radians(20), 25.0)  # teeth, module mm, rad, face mm
    >>> g2 = InvoluteGearData(41, 3.0, math.radians(20), 25.0)
    >>> f1, f2 = mating_flanks(g1, g2, crowning1=ParabolicCrowning(1e-4))  # 1/mm
    >>> pair = GearPair(f1, f2, 23, 41, g1.r_p + g2.r_p, misalignment=Misalignment(d_E=0.01))
    >>> from gearrep.tca import robust_contact
    >>> c = robust_contact(pair, 0.0, [33.0, 37.0], [-10.0, 12.0])  # rad, mm, mm
    >>> c.status_name.tolist(), np.round(c.u1, 4).tolist()  # both reach the one contact
    (['converged', 'converged'], [35.3223, 35.3223])
    """
    check_formulation(formulation)
    ph, u1, v1 = _start_pairs(phi1, u1, v1)
    if formulation == "reduced" and not _explicit2(pair):
        raise ValueError("the reduced formulation needs member 2 in explicit (cylindrical or spherical) form")
    if not _explicit2(pair) and nominal is None:
        raise ValueError("a pair whose member 2 has no explicit form needs nominal(pair, phi1) -> (n, 5) starts")
    check_positive("tol", tol)
    check_integer("maxiter", maxiter)
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        c = _solve_projected(pair, ph, u1, v1, formulation, tol, maxiter, nominal, keep_failed=True)
        c = _non_meshing_wrong(pair, _settle_on_boundary(pair, ph, c, formulation, tol, maxiter))
        if not fallback:
            return c
        if _transverse_applies(pair) and not c.converged.all():
            bad = np.flatnonzero(~c.converged)
            new = _solve_projected(pair, ph[bad], u1[bad], v1[bad], formulation, tol, maxiter, nominal, transverse=True)
            c = _retry(pair, c, new, bad)
        if nominal is not None and not _explicit2(pair) and not c.converged.all():
            c = _nominal_pass(pair, ph, c, tol, maxiter, nominal)
        bad = np.flatnonzero(~c.converged)
        if not len(bad) or not len(grid):
            return c
        lo, hi = pair.lower1, pair.upper1
        g = lo + np.asarray(grid, float) * (hi - lo)
        k = len(g)
        phk = np.repeat(ph[bad], k)
        cg = _solve_projected(
            pair, phk, np.tile(g[:, 0], len(bad)), np.tile(g[:, 1], len(bad)), formulation, tol, maxiter, nominal
        )
        s1, s2 = meshing_sense(pair, cg)
        ok = (cg.converged & _meshes(pair, cg)).reshape(len(bad), k)
        te = np.where(ok, (s2 * cg.te).reshape(len(bad), k), -np.inf)
        pick = np.argmax(te, axis=1)
        found = ok.any(axis=1)
        spent = cg.iterations.reshape(len(bad), k).sum(axis=1)
        return _with_rows(c, bad, cg.take(np.arange(len(bad)) * k + pick), found, spent)
