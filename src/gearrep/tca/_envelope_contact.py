"""Which tangency of the envelope-pair system (private module ``_envelope``) is the contact: the
physical contact among several tangencies at one pinion angle (an almost-line contact), the
tangency near a point of the face, the first-order gap a turn of the gear opens, and the solve from
a start anywhere on the pinion flank with its outcome against a reference. Lengths in mm, angles
in rad.
"""

from __future__ import annotations

import copy

import numpy as np

from ..solve import Status
from ..surface import cross
from ._envelope import (
    _ROW_FIELDS,
    ContactPath,
    dropped_component,
    hob_pitch_l,
    member_geometry,
    solve_points,
    tangency_system,
)

__all__ = [
    "pinion_outward",
    "physical_contact",
    "turn_gap",
    "tangency_near",
    "robust_points",
    "classify_points",
]


def pinion_outward(pair, sol: ContactPath) -> np.ndarray:
    """Unit normal of the pinion flank in S_f pointing out of its tooth (n, 3). The hob normal
    keeps its side of the flank everywhere, so its outward sign is taken once, at the pitch
    point of the mid-face section (:meth:`GeneratedGear.outward` there; that test by the polar
    angle fails past the tip, where the extended flank crosses the tooth's centre line).

    Parameters
    ----------
    pair : HobbedPair
        The pair.
    sol : EnvelopeContactPath
        Solved points.

    Returns
    -------
    numpy.ndarray
        (n, 3) unit normals in S_f.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.surfaces.hob import PairDesign, za_hob
    >>> from gearrep.tca import envelope_pinion_outward, hobbed_ideal_start, hobbed_pair
    >>> design = PairDesign(20, 40, 30.0, za_hob(3.0, 20.0, 30.0))  # teeth, face mm; module mm, deg, radius mm
    >>> pair = hobbed_pair(design, 100.0, 110.0)  # tooth-trace radii [mm]
    >>> n = envelope_pinion_outward(pair, hobbed_ideal_start(pair))
    >>> np.round(n[0, :2], 4).tolist()  # x, y in S_f (z is 0 at mid-face)
    [0.3416, 0.9398]
    """
    q0 = pair.pinion.gear.solve(hob_pitch_l(pair.pinion.gear.hob), 0.0).params[0]
    r0, _, n0, _, _, _ = member_geometry(pair.pinion, np.asarray(q0, float)[None])
    R = pair.pinion.gear.to_tooth_frame
    s = float(np.sign(np.sum(pair.pinion.gear.outward(r0 @ R.T, n0 @ R.T) * (n0 @ R.T))))
    _, _, n, _, _, _ = member_geometry(pair.pinion, sol.x[:, :4])
    return s * np.einsum("nab,nb->na", pair.pinion_rotation(sol.phi1), n)


def physical_contact(
    pair,
    sol: ContactPath,
    *,
    face_width_mm: float,
    n_starts: int = 9,
    tol: float = 1e-11,
    maxiter: int = 12,
    max_halvings: int = 3,
    same_tooth_rad: float = 1e-3,
    distinct_mm: float = 1e-3,
) -> ContactPath:
    """The physical contact among all tangencies of the 9 x 9 system at each phi1' of ``sol``.

    Where the lengthwise curvatures almost agree (an almost-line contact) the system has several
    isolated roots at the same phi1' (e.g. Z_p = 0 and a pair symmetric about mid-face), each a
    genuine tangency but with slightly different phi2'. The contact is
    the tangency the gear reaches first, i.e. the one at which the flanks do not interfere at any
    other tangency. With the gear at the phi2' of root A, the normal gap at root B is, to first
    order in the (tiny) difference, g(B|A) = (phi2'_A - phi2'_B) s_B,
    s_B = (e_z x (r_B - O_g)) . n_p,out(B) (rigid turn of the gear about its axis, measured along
    the pinion's outward normal; < 0 = interference). The kept root maximises min_B g(B|A), which
    is >= 0 (up to round-off) when s_B has one sign (e.g. where a positive turn of the gear moves
    its flank into the pinion tooth, s_B < 0, the physical contact is the tangency with the
    smallest phi2'). Ties (phi2' equal to round-off, e.g. the symmetric pair)
    keep the root nearest the continuation root in Z_p, then the larger Z_p.

    Search: from the continuation root x, ``n_starts`` starts spread across the face
    (Z_p = -0.45..0.45 of ``face_width_mm``, both members) along the direction d with d_psi_p = 1 that
    minimises |F_x d| (the almost-null direction of the Jacobian, i.e. along the contact line),
    all solved at once. Converged roots of the same tooth pair (|phi2' - phi2'_0| < same_tooth_rad)
    whose contact lies on both faces count; roots closer than ``distinct_mm`` in (Z_p, l_p) are one.
    Starts that do not converge are discarded (they only search); the continuation root is always
    a candidate, so every returned row is a converged, verified tangency. The result carries
    n_tangencies, tangency_phi2_spread [rad], tangency_min_gap [mm] and phi2_continuation [rad].

    Parameters
    ----------
    pair : HobbedPair
        The pair.
    sol : EnvelopeContactPath
        The continuation roots, one per phi1'.
    face_width_mm : float
        Face width of both members [mm], > 0.
    n_starts : int, optional
        Starts across the face per row, >= 2.
    tol : float, optional
        Residual tolerance of the search solves [mm].
    maxiter : int, optional
        Iteration limit of the search solves.
    max_halvings : int, optional
        Step halvings of their line search.
    same_tooth_rad : float, optional
        Largest |phi2' - phi2'_0| of a root of the same tooth pair [rad].
    distinct_mm : float, optional
        Smallest distance in (Z_p, l_p) between distinct tangencies [mm].

    Returns
    -------
    EnvelopeContactPath
        One converged, verified tangency per converged row of ``sol``, with the diagnostics set.

    Raises
    ------
    ValueError
        If ``n_starts`` is not an integer >= 2 or ``face_width_mm`` is not > 0.

    Examples
    --------
    Equal tooth-trace radii (110 mm) give an almost-line contact: a pair of tangencies off
    mid-face and one at mid-face, all within 1e-8 rad of one gear angle:

    >>> import numpy as np
    >>> from gearrep.surfaces.hob import PairDesign, za_hob
    >>> from gearrep.tca import envelope_physical_contact, hobbed_ideal_start, hobbed_pair, solve_envelope_points
    >>> design = PairDesign(20, 40, 30.0, za_hob(3.0, 20.0, 30.0))  # teeth, face mm; module mm, deg, radius mm
    >>> localised = hobbed_pair(design, 110.0, 113.0)  # tooth-trace radii [mm]
    >>> pair = hobbed_pair(design, 110.0, 110.0)
    >>> sol = solve_envelope_points(pair, [0.0], hobbed_ideal_start(localised).x)  # the mid-face tangency
    >>> c = envelope_physical_contact(pair, sol, face_width_mm=30.0)
    >>> c.n_tangencies.tolist(), np.round(c.Z_p, 3).tolist(), bool(c.tangency_phi2_spread[0] < 1e-8)  # mm, rad
    ([3], [1.097], True)
    """
    if int(n_starts) != n_starts or n_starts < 2:
        raise ValueError(f"n_starts must be an integer >= 2, got {n_starts!r}")
    if not (np.isfinite(face_width_mm) and face_width_mm > 0):
        raise ValueError(f"face_width_mm must be > 0, got {face_width_mm!r}")
    m = int(n_starts)
    cand, keep = _face_search(pair, sol, m, tol, maxiter, max_halvings, same_tooth_rad, face_width_mm)
    s_all = _turn_gap_factor(pair, cand)
    s_own = _turn_gap_factor(pair, sol)
    out = copy.deepcopy(sol)
    n = len(sol.phi1)
    n_tan = np.ones(n, int)
    spread, min_gap = np.zeros(n), np.zeros(n)
    for i in range(n):
        idx = i * m + np.flatnonzero(keep[i * m : (i + 1) * m])
        if not sol.converged[i]:
            n_tan[i] = 0
            continue
        j, n_tan[i], spread[i], min_gap[i] = _choose_tangency(sol, cand, i, idx, s_own[i], s_all[idx], distinct_mm)
        if j >= 0:
            _copy_row(out, i, cand, j)
    out.n_tangencies, out.tangency_phi2_spread, out.tangency_min_gap = n_tan, spread, min_gap
    out.phi2_continuation = sol.phi2.copy()
    return out


def _starts_along_face(pair, sol: ContactPath, z_t):
    """Starts (n * m rows) from each row of ``sol`` moved along the almost-null direction d of the
    Jacobian (d_psi_p = 1, the direction along the contact line) to Z_p = each of ``z_t`` (m,);
    and which of them are finite (the others are the row itself)."""
    n, m = len(sol.phi1), len(z_t)
    _, J, _ = tangency_system(pair, sol.x, sol.phi1, dropped_component(pair, sol.x, sol.phi1))
    others = np.r_[0:3, 4:9]
    d = np.zeros((n, 9))
    d[:, 3] = 1.0
    d[:, others] = -np.einsum("nij,nj->ni", np.linalg.pinv(J[:, :, others]), J[:, :, 3])
    Tp = member_geometry(pair.pinion, sol.x[:, 0:4])[1]
    dZ = np.einsum("nq,nq->n", Tp[:, :, 2], d[:, 0:4])  # dZ_p / dpsi_p along d (placement keeps z)
    t = (z_t[None, :] - sol.Z_p[:, None]) / np.where(np.abs(dZ) > 1e-12, dZ, np.nan)[:, None]
    x0 = np.repeat(sol.x, m, 0) + t.reshape(-1, 1) * np.repeat(d, m, 0)
    ok0 = np.all(np.isfinite(x0), axis=1)
    x0[~ok0] = np.repeat(sol.x, m, 0)[~ok0]
    return x0, ok0


def _face_search(pair, sol: ContactPath, m: int, tol, maxiter, max_halvings, same_tooth_rad, face_width_mm):
    """Roots from ``m`` starts per row spread across the face along the almost-null direction of
    the Jacobian (d_psi_p = 1); returns the candidates (n * m rows) and which of them count."""
    x0, ok0 = _starts_along_face(pair, sol, np.linspace(-0.45, 0.45, m) * face_width_mm)
    phi1 = np.repeat(sol.phi1, m)
    cand = solve_points(pair, phi1, x0, tol=tol, maxiter=maxiter, max_halvings=max_halvings)
    keep = (
        ok0
        & cand.converged
        & (np.abs(cand.phi2 - np.repeat(sol.phi2, m)) < same_tooth_rad)
        & (np.abs(cand.Z_p) <= face_width_mm / 2)
        & (np.abs(cand.Z_g) <= face_width_mm / 2)
    )
    return cand, keep


def _turn_gap_factor(pair, sol: ContactPath) -> np.ndarray:
    """s = (e_z x (r - O_g)) . n_p,out: normal gap per unit turn of the gear about its axis."""
    return np.sum(cross([0.0, 0.0, 1.0], sol.r_f - pair.gear_origin) * pinion_outward(pair, sol), -1)


def turn_gap(pair, at: ContactPath, phi2_rad) -> np.ndarray:
    """First-order normal gap [mm] between the flanks at the tangency points of ``at`` when the gear
    is turned to ``phi2_rad`` (one per row; same phi1'): (phi2 - phi2'_at) s, s as in
    :func:`physical_contact`; < 0 = the flanks interpenetrate there, > 0 = they are apart. The
    neglected terms are of second order in the turn (for a turn of 5e-8 rad, ~1e-15 mm).

    Parameters
    ----------
    pair : HobbedPair
        The pair.
    at : EnvelopeContactPath
        Tangencies.
    phi2_rad : float or (n,) array_like
        Gear angles phi2' [rad], finite.

    Returns
    -------
    numpy.ndarray
        (n,) gaps [mm].

    Raises
    ------
    ValueError
        If ``phi2_rad`` is not finite.

    Examples
    --------
    At an almost-line contact (equal tooth-trace radii) the mid-face tangency is not the contact:
    with the gear at its angle the flanks would interpenetrate at the physical contact:

    >>> from gearrep.surfaces.hob import PairDesign, za_hob
    >>> from gearrep.tca import HobbedAssembly, envelope_tangency_near, envelope_turn_gap, hobbed_continue_to
    >>> design = PairDesign(20, 40, 30.0, za_hob(3.0, 20.0, 30.0))  # teeth, face mm; module mm, deg, radius mm
    >>> pair, contact = hobbed_continue_to(design, 110.0, 110.0, HobbedAssembly())  # radii [mm]
    >>> mid = envelope_tangency_near(pair, contact, 0.0)  # Z_p = 0 mm
    >>> bool(envelope_turn_gap(pair, contact, mid.phi2)[0] < 0), bool(envelope_turn_gap(pair, mid, contact.phi2)[0] > 0)
    (True, True)
    """
    phi2 = np.broadcast_to(np.asarray(phi2_rad, float), at.phi2.shape)
    if not np.all(np.isfinite(phi2)):
        raise ValueError("phi2_rad must be finite")
    return (phi2 - at.phi2) * _turn_gap_factor(pair, at)


def tangency_near(
    pair, sol: ContactPath, Z_p_mm: float, *, tol: float = 1e-11, maxiter: int = 30, max_halvings: int = 12
) -> ContactPath:
    """At each phi1' of ``sol``, the tangency of the 9 x 9 system found from a start moved along the
    contact line (the almost-null direction of the Jacobian, as in :func:`physical_contact`'s
    search) to Z_p = ``Z_p_mm``: e.g. the mid-face tangency (Z_p_mm = 0) of an almost-line
    contact whose physical contact is a pair off mid-face. Rows carry the solver status; the
    caller checks (:func:`require`) and whether the root is the one wanted (its Z_p).

    Parameters
    ----------
    pair : HobbedPair
        The pair.
    sol : EnvelopeContactPath
        Converged tangencies, one per phi1'.
    Z_p_mm : float
        Axial coordinate on the pinion of the start [mm], finite.
    tol : float, optional
        Residual tolerance [mm].
    maxiter : int, optional
        Iteration limit.
    max_halvings : int, optional
        Step halvings of the line search.

    Returns
    -------
    EnvelopeContactPath
        One row per row of ``sol``.

    Raises
    ------
    ValueError
        If ``Z_p_mm`` is not finite.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.surfaces.hob import PairDesign, za_hob
    >>> from gearrep.tca import HobbedAssembly, envelope_tangency_near, hobbed_continue_to
    >>> design = PairDesign(20, 40, 30.0, za_hob(3.0, 20.0, 30.0))  # teeth, face mm; module mm, deg, radius mm
    >>> pair, contact = hobbed_continue_to(design, 110.0, 110.0, HobbedAssembly())  # radii [mm]
    >>> mid = envelope_tangency_near(pair, contact, 0.0)
    >>> np.round(contact.Z_p, 3).tolist(), mid.status_name.tolist(), bool(abs(mid.Z_p[0]) < 1e-6)  # mm
    ([1.097], ['converged'], True)
    """
    if not np.isfinite(Z_p_mm):
        raise ValueError(f"Z_p_mm must be finite, got {Z_p_mm!r}")
    x0, _ = _starts_along_face(pair, sol, np.array([float(Z_p_mm)]))
    return solve_points(pair, sol.phi1, x0, tol=tol, maxiter=maxiter, max_halvings=max_halvings)


def _choose_tangency(sol: ContactPath, cand: ContactPath, i: int, idx, s_own, s_idx, distinct_mm):
    """(candidate row kept or -1 for the continuation root, number of distinct tangencies,
    their phi2' spread [rad], the kept one's smallest first-order gap [mm]) at row i."""
    zs = np.r_[sol.Z_p[i], cand.Z_p[idx]]
    ls = np.r_[sol.x[i, 0], cand.x[idx, 0]]
    p2 = np.r_[sol.phi2[i], cand.phi2[idx]]
    sg = np.r_[s_own, s_idx]
    src = np.r_[-1, idx]
    uniq = []  # distinct tangencies, the continuation root first
    for k in range(len(zs)):
        if all(np.hypot(zs[k] - zs[u], ls[k] - ls[u]) > distinct_mm for u in uniq):
            uniq.append(k)
    uniq = np.array(uniq)
    G = (p2[uniq][:, None] - p2[uniq][None, :]) * sg[uniq][None, :]  # G[A, B] = g(B | A)
    score = G.min(axis=1)
    best = score >= score.max() - 1e-12
    order = np.lexsort((-zs[uniq], np.round(np.abs(zs[uniq] - sol.Z_p[i]), 6), ~best))
    a = order[0]
    return int(src[uniq[a]]), len(uniq), np.ptp(p2[uniq]), score[a]


def _copy_row(out: ContactPath, i: int, src: ContactPath, j: int) -> None:
    """Row i of ``out`` replaced by row j of ``src`` (unknowns, geometry and solve record)."""
    out.x[i] = src.x[j]
    for f in _ROW_FIELDS:
        getattr(out, f)[i] = getattr(src, f)[j]
    for f in ("x", "residual", "iterations", "status"):
        getattr(out.solve, f)[i] = getattr(src.solve, f)[j]


def _replace_rows(sol: ContactPath, rows, new: ContactPath, ok) -> None:
    """Rows ``rows[ok]`` of ``sol`` replaced by the rows ``ok`` of ``new`` (in place); the
    iterations of every row of ``rows`` add those of ``new``."""
    spent = new.solve.iterations.copy()
    for i, j in zip(rows[ok], np.flatnonzero(ok)):
        _copy_row(sol, int(i), new, int(j))
        sol.solve.iterations[i] = 0
    sol.solve.iterations[rows] += spent


def robust_points(
    pair, phi1, l_p, psi_p, nominal, *, tol: float = 1e-11, maxiter: int = 30, fallback: bool = True
) -> ContactPath:
    """Contact points at pinion angles ``phi1`` (n,) [rad] from starts (l_p, psi_p) (n,) anywhere
    on the pinion flank: the start strategy of :func:`gearrep.tca.robust_contact` for the
    9-unknown system. Each start is projected onto the pinion's generated flank (its own envelope
    solve gives (phi_p, theta_p) at (l_p, psi_p)); the gear's unknowns and phi2' come from the
    family's nominal start ``nominal(phi1)`` -> (n, 9) (e.g. :func:`predict` off a solved point);
    a row that does not converge, whose root is not a tangency or lies on another branch of a
    member's equation of meshing (WRONG_ROOT), or off either tooth (past its outside radius or the
    face: OFF_FLANK) is solved again from the nominal start itself (unless ``fallback`` is False). Where several tangencies meet at one angle (an almost-line
    contact) :func:`physical_contact` picks the physical one.

    Parameters
    ----------
    pair : HobbedPair
        The pair.
    phi1 : float or (n,) array_like
        Pinion angles phi1' [rad].
    l_p : float or (n,) array_like
        Hob parameter of the starts [mm], finite.
    psi_p : float or (n,) array_like
        Swivel angle of the starts [rad], finite.
    nominal : callable
        ``nominal(phi1)`` -> (n, 9) the family's nominal starts [mm, rad].
    tol : float, optional
        Residual tolerance [mm].
    maxiter : int, optional
        Iteration limit.
    fallback : bool, optional
        Solve failed rows again from the nominal start.

    Returns
    -------
    EnvelopeContactPath
        One row per angle (iterations: both passes).

    Raises
    ------
    ValueError
        If a start is not finite.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.surfaces.hob import PairDesign, za_hob
    >>> from gearrep.tca import hobbed_ideal_start, hobbed_pair, predict_envelope_contact, robust_envelope_points
    >>> design = PairDesign(20, 40, 30.0, za_hob(3.0, 20.0, 30.0))  # teeth, face mm; module mm, deg, radius mm
    >>> pair = hobbed_pair(design, 100.0, 110.0)  # tooth-trace radii [mm]
    >>> start = hobbed_ideal_start(pair)
    >>> def nominal(phi1):  # the first-order prediction off the contact at phi1' = 0
    ...     return predict_envelope_contact(pair, np.repeat(start.x, len(phi1), 0), np.zeros(len(phi1)), phi1)
    >>> sol = robust_envelope_points(pair, np.radians([0.0, 2.0]), [5.0, 7.0], [0.0, 0.02], nominal)  # mm, rad
    >>> sol.status_name.tolist(), np.round(sol.x[:, 0], 4).tolist()  # l_p [mm]
    (['converged', 'converged'], [6.0869, 6.4439])
    """
    phi1 = np.atleast_1d(np.asarray(phi1, float))
    l_p, psi_p = (np.broadcast_to(np.asarray(a, float), phi1.shape) for a in (l_p, psi_p))
    if not (np.all(np.isfinite(l_p)) and np.all(np.isfinite(psi_p))):
        raise ValueError("l_p and psi_p (the starts on the pinion flank) must be finite")
    x_nom = np.array(nominal(phi1), dtype=float).reshape(len(phi1), 9)
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        rec = pair.pinion.gear.solve(l_p, psi_p)
        x0 = x_nom.copy()
        on = rec.converged & np.all(np.isfinite(rec.params), axis=1)
        x0[on, 0:4] = rec.params[on]
        sol = _off_teeth(pair, solve_points(pair, phi1, x0, tol=tol, maxiter=maxiter))
        bad = np.flatnonzero(~sol.converged)
        if len(bad) and fallback:
            again = _off_teeth(pair, solve_points(pair, phi1[bad], x_nom[bad], tol=tol, maxiter=maxiter))
            _replace_rows(sol, bad, again, again.converged)
    return sol


#: largest distance [mm] between a root's point on a member and the member's generated flank
#: point at the same (l, psi) for the root to lie on that flank (the envelope solves hold 1e-11)
_ON_FLANK_MM = 1e-6


def _off_teeth(pair, sol: ContactPath) -> ContactPath:
    """``sol`` with the CONVERGED rows that are no contact of the two teeth marked (in place):
    WRONG_ROOT where a member's (phi, theta) are another branch of its equation of meshing (its
    point differs from the member's generated flank at the same (l, psi), the branch that
    ``GeneratedGear.solve`` verifies), OFF_FLANK where the point lies past either member's outside
    radius or outside the face (``pair.face_width_mm``, where the pair has one)."""
    ok = sol.converged.copy()
    for flank, cols in ((pair.pinion, slice(0, 4)), (pair.gear, slice(4, 8))):
        i = np.flatnonzero(ok)
        if not len(i):
            break
        q = sol.x[i, cols]
        own = flank.gear.solve(q[:, 0], q[:, 3])
        r_root = member_geometry(flank, q)[0]
        r_own = np.full_like(r_root, np.nan)
        good = own.converged
        if good.any():
            r_own[good] = member_geometry(flank, own.params[good])[0]
        with np.errstate(invalid="ignore"):
            other = ~(np.linalg.norm(r_root - r_own, axis=1) <= _ON_FLANK_MM)
        sol.solve.status[i[other]] = int(Status.WRONG_ROOT)
        ok[i[other]] = False
    on = (sol.radius_p <= pair.pinion.r_outside_mm) & (sol.radius_g <= pair.gear.r_outside_mm)
    B = getattr(pair, "face_width_mm", None)
    if B is not None:
        on &= (np.abs(sol.Z_p) <= 0.5 * B) & (np.abs(sol.Z_g) <= 0.5 * B)
    sol.solve.status[ok & ~on] = int(Status.OFF_FLANK)
    return sol


def classify_points(sol: ContactPath, ref: ContactPath, *, tol: float = 1e-6):
    """(outcomes, iterations) of the solves ``sol`` against the reference ``ref`` (same rows), as
    :func:`gearrep.tca.classify_contacts` names them: ``"correct"`` (CONVERGED and every unknown
    within ``tol`` [mm, rad] of the reference), ``"wrong_root"`` (a root elsewhere, or not a
    tangency), ``"not_converged"``.

    Parameters
    ----------
    sol : EnvelopeContactPath
        The solves.
    ref : EnvelopeContactPath
        The reference, row for row.
    tol : float, optional
        Largest difference of an unknown from the reference [mm, rad].

    Returns
    -------
    outcomes : numpy.ndarray
        (n,) object array of the outcome names.
    iterations : numpy.ndarray
        (n,) the solves' iterations.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.surfaces.hob import PairDesign, za_hob
    >>> from gearrep.tca import classify_envelope_points, hobbed_ideal_start, hobbed_pair, solve_envelope_points
    >>> from gearrep.tca import trace_envelope_path
    >>> design = PairDesign(20, 40, 30.0, za_hob(3.0, 20.0, 30.0))  # teeth, face mm; module mm, deg, radius mm
    >>> pair = hobbed_pair(design, 100.0, 110.0)  # tooth-trace radii [mm]
    >>> start = hobbed_ideal_start(pair)
    >>> ref = trace_envelope_path(pair, start, [0.0, 0.0])  # rad
    >>> sol = solve_envelope_points(pair, [0.0, 0.0], np.vstack([start.x, np.zeros((1, 9))]), maxiter=3)
    >>> classify_envelope_points(sol, ref)[0].tolist()
    ['correct', 'not_converged']
    """
    with np.errstate(invalid="ignore"):
        same = np.all(np.abs(sol.x - ref.x) < tol, axis=1)
    st = sol.solve.status
    solved = np.isin(st, [Status.CONVERGED, Status.OFF_FLANK, Status.WRONG_ROOT])
    out = np.full(len(st), "not_converged", dtype=object)
    out[solved] = "wrong_root"
    out[solved & same & (st == Status.CONVERGED)] = "correct"
    return out, sol.solve.iterations
