"""Meshing cycle: engagement limits, contact ratio and transmission error over the real cycle
(angles and TE in rad, lengths in the unit of the design data, mm in the examples).

Sources: seed 000 (curvilinear-tooth gear dissertation) eq (5.12)-(5.13); Temirkhan thesis
(seed 003) eq (14); Litvin & Fuentes, "Gear Geometry and Applied Theory", 2nd ed., ch. 9
(TE functions of neighbouring tooth pairs and their transfer points).

Contact ratio (eq 5.13, corrected). Seed 000 prints m_c = (phi'_1E - phi'_1B) / 360 deg, where
phi'_1B, phi'_1E are the pinion angles at which one pair of teeth comes into and goes out of
mesh. Dimensionally the divisor must be the angular pitch 360 deg / T_p, not a full turn: with
360 deg its own example (T_p = 20, m_c = 1.62) would need the pair to stay in mesh for 583 deg,
more than a turn. Corrected:  m_c = (phi_1E - phi_1B) / (2 pi / N1).
phi_1B and phi_1E are found here as the angles at which the contact point of one tooth pair
reaches the boundary of either flank domain (tip/form circle or face edge of either member),
by a Newton solve that adds the boundary equation and phi1 as unknown to the reduced TCA system.
For an aligned involute pair with line contact pass ``v1=`` (the transverse section); the result
is then the transverse contact ratio epsilon_alpha, which equals
(sqrt(r_a1^2 - r_b1^2) + sqrt(r_a2^2 - r_b2^2) - a sin(alpha_w)) / p_b (:func:`contact_ratio_closed_form`).

Real meshing cycle (TE envelope). Tooth pair k (k = 0 the reference pair) engages one angular
pitch p1 = 2 pi / N1 later than pair k - 1 and its TE, with eq (14)'s nominal reference, is
TE_k(phi1) = TE_0(phi1 - k p1) (identical teeth). Member 2 is driven: it is pushed to the most
advanced of the positions demanded by the pairs in their engagement intervals, so the TE actually
transmitted is the upper envelope max_k TE_k(phi1), and the pair in contact is the one with the
largest (leading) TE. Pair 0 hands over to pair 1 at the transfer point phi_T where
TE_0(phi_T) = TE_0(phi_T - p1) (inside the overlap [phi_1B + p1, phi_1E]); if pair 1 leads as soon
as it engages the transfer is at phi_1B + p1, and if pair 0 leads until it leaves its flank the
transfer is at phi_1E (edge contact beyond the flank is not modelled). The real cycle is
[phi_T - p1, phi_T]. When the TE curves of neighbouring pairs coincide (conjugate action) the
transfer point is indeterminate and is reported as NaN.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ._te_envelope import SampledCycle, handover_gap, handover_jump, pair_te_curves, sampled_cycle, upper_envelope
from .inputs import check_positive
from .solve import SolveResult, Status, newton
from .tca import ContactPoints, GearPair, newton_rows, reduced_system, solve_contact, trace_path

__all__ = [
    "contact_ratio",
    "contact_ratio_closed_form",
    "centre_distance_limits",
    "EngagementLimit",
    "engagement_limits",
    "MeshingCycle",
    "meshing_cycle",
    "pair_te_curves",
    "upper_envelope",
    "handover_jump",
    "handover_gap",
    "SampledCycle",
    "sampled_cycle",
]


def contact_ratio(phi1_begin, phi1_end, n1):
    """Contact ratio from the engagement limits of one tooth pair, seed 000 eq (5.13) corrected:
    m_c = (phi_1E - phi_1B) / (2 pi / N1) (angles in rad; negative when phi1 decreases through the
    mesh, e.g. for the opposite sense of rotation). Vectorised.

    Parameters
    ----------
    phi1_begin, phi1_end : float or array_like
        Engagement limits of one tooth pair [rad].
    n1 : float
        Teeth of member 1, > 0.

    Returns
    -------
    float or numpy.ndarray
        The contact ratio [1].

    Raises
    ------
    ValueError
        If ``n1`` is not a finite number > 0.

    Examples
    --------
    >>> import math
    >>> from gearrep.meshing import contact_ratio
    >>> round(float(contact_ratio(-0.2, 0.2, 23)), 6)  # 0.4 rad of a 2 pi / 23 pitch
    1.464225
    """
    check_positive("n1", n1)
    return (np.asarray(phi1_end, float) - np.asarray(phi1_begin, float)) * n1 / (2.0 * np.pi)


def contact_ratio_closed_form(r_a1, r_b1, r_a2, r_b2, centre_distance, base_pitch):
    """Transverse contact ratio of an external involute pair (standard involute geometry, Litvin & Fuentes ch. 10):
    (sqrt(r_a1^2 - r_b1^2) + sqrt(r_a2^2 - r_b2^2) - a sin(alpha_w)) / p_b, cos(alpha_w) = (r_b1 + r_b2)/a.

    For the standard centre distance alpha_w = alpha and p_b = pi m cos(alpha). Vectorised.

    Parameters
    ----------
    r_a1, r_b1, r_a2, r_b2 : float or array_like
        Tip and base radii of both members [mm].
    centre_distance : float or array_like
        Operating centre distance a [mm], >= r_b1 + r_b2.
    base_pitch : float or array_like
        Transverse base pitch p_b [mm].

    Returns
    -------
    float or numpy.ndarray
        The transverse contact ratio [1].

    Raises
    ------
    ValueError
        If a radius or the pitch is not a finite number > 0, or the centre distance is below
        r_b1 + r_b2.

    Examples
    --------
    >>> import math
    >>> from gearrep.meshing import contact_ratio_closed_form
    >>> from gearrep.surfaces.involute import InvoluteGearData
    >>> g1 = InvoluteGearData(23, 3.0, math.radians(20), 25.0)
    >>> g2 = InvoluteGearData(41, 3.0, math.radians(20), 25.0)
    >>> round(float(contact_ratio_closed_form(g1.r_a, g1.r_b, g2.r_a, g2.r_b, 96.0, g1.base_pitch)), 4)
    1.655
    """
    names = ("r_a1", "r_b1", "r_a2", "r_b2", "centre_distance", "base_pitch")
    values = (r_a1, r_b1, r_a2, r_b2, centre_distance, base_pitch)
    arrays = {}
    for name, v in zip(names, values):
        try:
            arrays[name] = x = np.asarray(v, float)
        except (TypeError, ValueError):
            raise ValueError(f"{name} must be a number or an array of numbers [mm], got {v!r}") from None
        if not np.all(np.isfinite(x) & (x > 0)):
            raise ValueError(f"{name} must be finite and > 0 [mm], got {v!r}")
    ra1, rb1, ra2, rb2, a, pb = arrays.values()
    if np.any(ra1 < rb1) or np.any(ra2 < rb2):
        raise ValueError(
            f"tip radii must be >= the base radii, got r_a1 = {r_a1!r}, r_b1 = {r_b1!r}, r_a2 = {r_a2!r}, r_b2 = {r_b2!r}"
        )
    if np.any(a < rb1 + rb2):
        raise ValueError(f"centre_distance must be >= r_b1 + r_b2 = {rb1 + rb2!r}, got {centre_distance!r}")
    sin_aw = np.sqrt(1.0 - ((rb1 + rb2) / a) ** 2)
    ratio = (np.sqrt(ra1**2 - rb1**2) + np.sqrt(ra2**2 - rb2**2) - a * sin_aw) / pb
    if not np.all(ratio > 0):
        raise ValueError(
            f"no path of contact: at centre_distance = {centre_distance!r} the tip circles do not reach across "
            f"the line of action (contact ratio {np.round(ratio, 6).tolist()!r}); allowed: a centre distance where the teeth overlap"
        )
    return ratio


def centre_distance_limits(r_a1, r_b1, r_lo1, r_a2, r_b2, r_lo2, base_pitch, overlap_ratio=0.0) -> dict:
    """The range of operating centre distances [mm] over which an external involute pair meshes
    without interference and without a gap (transverse section; radii in mm).

    The line of action runs between the points T1, T2 where it touches the base circles,
    |T1 T2| = sqrt(a^2 - (r_b1 + r_b2)^2). Member 2's tip circle cuts it at sqrt(r_a2^2 - r_b2^2)
    from T2; that point lies on member 1's involute flank only if it is at least
    sqrt(r_lo1^2 - r_b1^2) from T1 (``r_lo1``: the radius where member 1's involute flank begins,
    max(base, root) radius). Closer, member 2's tip meets member 1 below its involute: tip
    interference (and the same with the members exchanged). The contact ratio
    (:func:`contact_ratio_closed_form`) plus ``overlap_ratio`` falls below 1 as |T1 T2| grows: the
    next tooth pair engages after the last one left, a gap in the meshing. Returns a dict: ``a_min``
    (the larger of ``a_min_tip2`` and ``a_min_tip1``, the centre distance at which member 2's or
    member 1's tip reaches the other member's lowest involute point) and ``a_max`` (total contact
    ratio 1).

    Parameters
    ----------
    r_a1, r_b1, r_lo1 : float
        Tip and base radius of member 1 and the radius where its involute flank begins [mm].
    r_a2, r_b2, r_lo2 : float
        The same for member 2 [mm].
    base_pitch : float
        Transverse base pitch [mm].
    overlap_ratio : float, optional
        The overlap (face) contact ratio added to the transverse one (0 for spur gears).

    Returns
    -------
    dict
        ``a_min``, ``a_min_tip2``, ``a_min_tip1``, ``a_max`` [mm].

    Raises
    ------
    ValueError
        If a radius or the pitch is not a finite number > 0.

    Examples
    --------
    >>> import math
    >>> from gearrep.meshing import centre_distance_limits
    >>> from gearrep.surfaces.involute import InvoluteGearData
    >>> g1 = InvoluteGearData(23, 3.0, math.radians(20), 25.0)
    >>> g2 = InvoluteGearData(41, 3.0, math.radians(20), 25.0)
    >>> lim = centre_distance_limits(g1.r_a, g1.r_b, max(g1.r_b, g1.r_f), g2.r_a, g2.r_b, max(g2.r_b, g2.r_f), g1.base_pitch)
    >>> round(lim["a_min"], 4), round(lim["a_max"], 4)  # mm, about the standard 96 mm
    (94.6487, 98.1354)
    """
    R = float(r_b1) + float(r_b2)
    g1 = float(np.sqrt(r_a1**2 - r_b1**2))
    g2 = float(np.sqrt(r_a2**2 - r_b2**2))
    s1 = float(np.sqrt(max(r_lo1**2 - r_b1**2, 0.0)))
    s2 = float(np.sqrt(max(r_lo2**2 - r_b2**2, 0.0)))
    tip2, tip1 = float(np.hypot(g2 + s1, R)), float(np.hypot(g1 + s2, R))
    path_max = g1 + g2 - float(base_pitch) * max(1.0 - float(overlap_ratio), 0.0)
    return {
        "a_min": max(tip1, tip2),
        "a_min_tip2": tip2,
        "a_min_tip1": tip1,
        "a_max": float(np.hypot(path_max, R)) if path_max > 0 else float("nan"),
    }


# ----------------------------------------------------------------------------------------------
# engagement limits
# ----------------------------------------------------------------------------------------------
def _values(c: ContactPoints):
    return np.stack([c.u1, c.v1, c.u2, c.v2], axis=-1)


def _margins(pair: GearPair, vals):
    lo = np.concatenate([pair.lower1, pair.lower2])
    hi = np.concatenate([pair.upper1, pair.upper2])
    span = np.where(np.isfinite(hi - lo), hi - lo, 1.0)
    m = np.empty(vals.shape[:-1] + (8,))
    m[..., 0::2] = (vals - lo) / span
    m[..., 1::2] = (hi - vals) / span
    return np.where(np.isfinite(m), m, np.inf), lo, hi


@dataclass(frozen=True)
class EngagementLimit:
    """One end of the engagement interval: angle, the contact there, and which flank boundary.

    Attributes
    ----------
    phi1 : float
        The angle of member 1 [rad].
    contact : gearrep.tca.ContactPoints
        The contact there (one row).
    boundary : str
        The flank boundary reached, e.g. "u2_max" (tip of member 2), "u1_max", "v1_min".
    solve : gearrep.solve.SolveResult
        The solve of the boundary system.

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
    >>> from gearrep.meshing import engagement_limits
    >>> begin, end = engagement_limits(pair)
    >>> round(begin.phi1, 6), begin.boundary, round(end.phi1, 6), end.boundary  # rad
    (-0.302387, 'u2_max', 0.148817, 'u1_max')
    """

    phi1: float
    contact: ContactPoints
    boundary: str  # e.g. "u2_max" (tip of member 2), "u1_max", "v1_min", ...
    solve: SolveResult


#: halvings of the last continuation step when the first position beyond the flanks has no root
#: (2^-30 of a tenth of the angular pitch: below 1e-10 rad for any tooth number)
_BISECTIONS = 30

_BNAMES = ["u1_min", "u1_max", "v1_min", "v1_max", "u2_min", "u2_max", "v2_min", "v2_max"]


def _boundary_solve(pair, contact: ContactPoints, j: int, v1_fixed, tol=1e-12, maxiter=50):
    """Solve the reduced system plus 'parameter j//2 on its bound' for (u1[, v1], phi1)."""
    lo = np.concatenate([pair.lower1, pair.lower2])
    hi = np.concatenate([pair.upper1, pair.upper2])
    p_idx, bound = j // 2, (lo if j % 2 == 0 else hi)[j // 2]
    fixed = v1_fixed is not None
    _, n1 = pair.member1(contact.u1, contact.v1, contact.phi1)
    drop = float(np.argmax(np.abs(n1[0])))

    def F(x, p):
        u1 = x[:, 0]
        v1 = p[:, 1] if fixed else x[:, 1]
        phi1 = x[:, -1]
        Fv, _, K = reduced_system(pair, u1, v1, phi1, p[:, 0], derivs=False)
        vals = np.stack([u1, v1, K["u2"], K["v2"]], axis=-1)[:, p_idx]
        return np.column_stack([Fv, vals - bound])

    x0 = [contact.u1[0]] + ([] if fixed else [contact.v1[0]]) + [contact.phi1[0]]
    params = [drop] + ([float(v1_fixed)] if fixed else [])
    res = newton_rows(F, None, np.array([x0]), np.array([params]), jacobian="numeric", tol=tol, maxiter=maxiter)
    phi1 = float(res.x[0, -1])
    v1 = float(v1_fixed) if fixed else float(res.x[0, 1])
    c = solve_contact(pair, phi1, np.array([[res.x[0, 0], v1]]), v1=v1_fixed, keep_failed=True)
    # the point is on the boundary: CONVERGED or OFF_FLANK by rounding; keep the boundary-solve status
    st = c.status.copy()
    if res.status[0] == Status.CONVERGED and st[0] in (Status.CONVERGED, Status.OFF_FLANK):
        st[0] = Status.CONVERGED
    else:
        st[0] = res.status[0] if res.status[0] != Status.CONVERGED else st[0]
    c = ContactPoints(**{**c.__dict__, "status": st}).failed_as_nan()
    return phi1, c, res


def _one_angle(phi1_start) -> float:
    """``phi1_start`` as one finite angle [rad]."""
    a = np.asarray(phi1_start, dtype=float)
    if a.ndim != 0 or not np.isfinite(a):
        raise ValueError(f"phi1_start must be one finite angle [rad], got {phi1_start!r}")
    return float(a)


def _check_undercut(pair: GearPair) -> None:
    """Involute flanks of gears below the rack's undercut limit have no meshing cycle to trace
    (flanks whose gear data know their limit, ``min_teeth_without_undercut``)."""
    for name in ("flank1", "flank2"):
        gear = getattr(getattr(pair, name), "gear", None)
        n_min = getattr(gear, "min_teeth_without_undercut", None)
        if n_min is not None:
            if gear.n_teeth < n_min:
                raise ValueError(
                    f"{name}: n_teeth = {gear.n_teeth} is undercut by its generating rack (undercut limit "
                    f"{n_min:.4g} = 2 (h_a - x) cos(beta) / sin^2(alpha_t) teeth); allowed: n_teeth >= "
                    f"{int(np.ceil(n_min))}, or a profile shift x that lowers the limit"
                )


def engagement_limits(
    pair: GearPair, phi1_start: float = 0.0, start=None, *, v1=None, step=None, max_steps: int = 400, tol: float = 1e-12
):
    """Angles phi_1B < phi_1E at which one tooth pair enters and leaves mesh (eq 5.13's limits).

    Walks the path of contact by continuation from ``phi1_start`` (a position inside the
    engagement interval, default 0) in both directions with ``step`` (default p1/10) until the
    contact leaves the flank domain, then solves for the exact angle at which the contact is on the
    boundary that was crossed (reduced formulation, eq 33-44).

    Parameters
    ----------
    pair : GearPair
        The pair.
    phi1_start : float, optional
        An angle inside the engagement interval [rad].
    start : array_like, optional
        The (u1, v1) start there (default :func:`gearrep.tca.default_start`).
    v1 : float, optional
        Fixed face-width coordinate of member 1 [mm] for line contact (None: point contact).
    step : float, optional
        Continuation step [rad] (default a tenth of the angular pitch 2 pi / N1).
    max_steps : int, optional
        Steps allowed in each direction.
    tol : float, optional
        Residual tolerance of the solves.

    Returns
    -------
    tuple of EngagementLimit
        (begin, end), phi_1B < phi_1E.

    Raises
    ------
    ValueError
        Before any solve for a bad argument or an undercut gear; and if the start position has no
        contact or the contact does not leave the flanks within ``max_steps``.

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
    >>> from gearrep.meshing import contact_ratio, engagement_limits
    >>> begin, end = engagement_limits(pair)
    >>> round(float(contact_ratio(begin.phi1, end.phi1, 23)), 4)
    1.6517
    """
    phi1_start = _one_angle(phi1_start)
    if v1 is not None and (np.ndim(v1) != 0 or not np.isfinite(float(v1))):
        raise ValueError(f"v1 must be None (point contact) or one finite face-width coordinate [mm], got {v1!r}")
    _check_undercut(pair)
    p1 = 2.0 * np.pi / pair.n1
    h = p1 / 10.0 if step is None else float(step)
    if not (np.isfinite(h) and h > 0):
        raise ValueError(f"step must be > 0, got {step!r}")
    c0 = solve_contact(pair, phi1_start, start, v1=v1, tol=tol)
    if c0.status[0] == Status.SINGULAR and v1 is None:
        raise ValueError(
            f"singular contact system at phi1_start = {phi1_start!r}: the pair is in line contact (e.g. unmodified "
            "flanks); pass v1= (the fixed face-width coordinate of member 1, e.g. v1=0.0) for line contact"
        )
    if c0.status[0] != Status.CONVERGED:
        raise ValueError(
            f"no contact inside the flanks at phi1_start = {phi1_start!r} "
            f"(status {c0.status_name[0]}); give another phi1_start or start"
        )
    out = []
    for direction in (-1.0, 1.0):
        last = c0
        prev = None
        first_out = None
        for i in range(1, max_steps + 1):
            phi = phi1_start + direction * i * h
            guess = last.unknowns("reduced")
            if prev is not None:
                guess = guess + (guess - prev.unknowns("reduced"))
            c = solve_contact(pair, phi, guess, v1=v1, tol=tol, keep_failed=True)  # OFF_FLANK: which boundary
            if c.status[0] not in (Status.CONVERGED, Status.OFF_FLANK) and prev is not None:
                # the extrapolated start can fall outside the surface (inside the base circle): the last root
                c = solve_contact(pair, phi, last.unknowns("reduced"), v1=v1, tol=tol, keep_failed=True)
            if c.status[0] != Status.CONVERGED:
                first_out = c
                break
            prev, last = last, c
        if first_out is None:
            raise ValueError(f"contact did not leave the flanks within {max_steps} steps of {h!r} rad")
        # no root computed outside (e.g. beyond the base circle, where the involute ends): bisect the
        # last step until the first position out is a root beyond the boundary or next to it
        for _ in range(_BISECTIONS):
            if first_out.status[0] == Status.OFF_FLANK:
                break
            phi = 0.5 * (last.phi1[0] + first_out.phi1[0])
            c = solve_contact(pair, phi, last.unknowns("reduced"), v1=v1, tol=tol, keep_failed=True)
            if c.status[0] == Status.CONVERGED:
                last = c
            else:
                first_out = c
        if first_out.status[0] == Status.OFF_FLANK:
            m, _, _ = _margins(pair, _values(first_out))
            j = int(np.argmin(m[0]))
        else:  # no contact computed outside: the boundary nearest at the last inside point
            m, _, _ = _margins(pair, _values(last))
            j = int(np.argmin(m[0]))
        phi, c, res = _boundary_solve(pair, last, j, v1, tol=tol)
        if res.status[0] != Status.CONVERGED or not (
            min(last.phi1[0], first_out.phi1[0]) - 1e-9 <= phi <= max(last.phi1[0], first_out.phi1[0]) + 1e-9
        ):
            # a different boundary was crossed first: try all, keep the one nearest the last inside point
            best = None
            for jj in range(8):
                p2, c2, r2 = _boundary_solve(pair, last, jj, v1, tol=tol)  # reports, never raises
                lo_, hi_ = sorted((last.phi1[0], first_out.phi1[0]))
                if r2.status[0] == Status.CONVERGED and lo_ - 1e-9 <= p2 <= hi_ + 1e-9:
                    if best is None or abs(p2 - last.phi1[0]) < abs(best[0] - last.phi1[0]):
                        best = (p2, c2, r2, jj)
            if best is None:
                raise ValueError("could not locate the flank boundary crossed by the path of contact")
            phi, c, res, j = best
        out.append(EngagementLimit(phi1=phi, contact=c, boundary=_BNAMES[j], solve=res))
    return out[0], out[1]


# ----------------------------------------------------------------------------------------------
# meshing cycle
# ----------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class MeshingCycle:
    """Meshing cycle of a gear pair.

    Attributes
    ----------
    begin, end : EngagementLimit
        Engagement limits of one tooth pair (phi_1B, phi_1E) with the boundary reached.
    contact_ratio : float
        (phi_1E - phi_1B) / (2 pi / N1) (eq 5.13 corrected) [1].
    path : gearrep.tca.ContactPoints
        Contact points of the reference pair on a grid over [phi_1B, phi_1E].
    transfer_in, transfer_out : float
        Real-cycle limits (transfer points) [rad], NaN if indeterminate.
    transfer_kind : str
        "crossing", "at_engagement" (next pair leads at once), "at_exit" (pair leads until it
        leaves its flank) or "indeterminate".
    phi1, te, pair_index : numpy.ndarray
        The TE envelope over the real cycle (or over [phi_1B, phi_1B + p1] when indeterminate):
        angle [rad], TE [rad], and which pair (k = -1, 0, 1) is in contact; ``te_peak_to_peak``
        is max - min of ``te`` [rad].

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
    >>> from gearrep.meshing import meshing_cycle
    >>> cycle = meshing_cycle(pair, n_points=21)
    >>> cycle.begin.boundary, cycle.end.boundary, bool(cycle.path.converged.all())
    ('u2_max', 'u1_max', True)
    """

    begin: EngagementLimit
    end: EngagementLimit
    contact_ratio: float
    path: ContactPoints
    transfer_in: float
    transfer_out: float
    transfer_kind: str
    phi1: np.ndarray
    te: np.ndarray
    pair_index: np.ndarray

    @property
    def te_peak_to_peak(self) -> float:
        """max - min of the real cycle's TE [rad]."""
        return float(np.nanmax(self.te) - np.nanmin(self.te))


class _TEFunction:
    """TE of the reference pair at arbitrary phi1 in its engagement interval (solves warm-started
    from the traced path)."""

    def __init__(self, pair, path: ContactPoints, v1, tol):
        ok = path.converged
        self.pair, self.v1, self.tol = pair, v1, tol
        self.phi = path.phi1[ok]
        self.x = path.unknowns("reduced")[ok]
        self.lo, self.hi = self.phi.min(), self.phi.max()

    def __call__(self, phi1):
        phi1 = np.atleast_1d(np.asarray(phi1, float))
        te = np.full(phi1.shape, -np.inf)
        inside = (phi1 >= self.lo - 1e-12) & (phi1 <= self.hi + 1e-12)
        if np.any(inside):
            p = np.clip(phi1[inside], self.lo, self.hi)
            start = np.column_stack([np.interp(p, self.phi, self.x[:, 0]), np.interp(p, self.phi, self.x[:, 1])])
            c = solve_contact(self.pair, p, start, v1=self.v1, tol=self.tol, keep_failed=True)
            # inside the engagement interval an OFF_FLANK status can only be rounding at its ends
            ok = (c.status == Status.CONVERGED) | (c.status == Status.OFF_FLANK)
            t = np.where(ok, c.te, np.nan)
            te[inside] = t
        return te


def meshing_cycle(
    pair: GearPair, phi1_start: float = 0.0, start=None, *, v1=None, n_points: int = 81, tol: float = 1e-12
) -> MeshingCycle:
    """Engagement limits, contact ratio (eq 5.13 corrected), transfer points and the TE over the
    real meshing cycle (upper envelope of neighbouring pairs' TE, see module docstring). Angles
    and TE in rad (member 2's angle for the TE), the contact ratio dimensionless.

    Parameters
    ----------
    pair : GearPair
        The pair.
    phi1_start, start : optional
        A position with contact inside the flanks: angle [rad] and (u1, v1) start.
    v1 : float, optional
        Fixed face-width coordinate [mm] for line contact (None for point contact).
    n_points : int, optional
        Grid size of the path and of the real-cycle TE, >= 5.
    tol : float, optional
        Residual tolerance of the solves.

    Returns
    -------
    MeshingCycle
        Limits, contact ratio, path, transfer points and the real cycle's TE.

    Raises
    ------
    ValueError
        As :func:`engagement_limits`, and if ``n_points`` is not an integer >= 5.

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
    >>> from gearrep.meshing import meshing_cycle
    >>> cycle = meshing_cycle(pair, n_points=21)
    >>> round(cycle.contact_ratio, 4), cycle.transfer_kind, len(cycle.phi1)
    (1.6517, 'indeterminate', 21)
    >>> cycle.te_peak_to_peak < 1e-9  # d_E alone: the crowned involute pair stays conjugate [rad]
    True
    """
    if isinstance(n_points, bool) or not isinstance(n_points, (int, np.integer)) or n_points < 5:
        raise ValueError(f"n_points must be an integer >= 5, got {n_points!r}")
    b, e = engagement_limits(pair, phi1_start, start, v1=v1, tol=tol)
    mc = float(contact_ratio(b.phi1, e.phi1, pair.n1))
    p1 = 2.0 * np.pi / pair.n1
    grid = np.linspace(b.phi1, e.phi1, int(n_points))
    path = trace_path(pair, grid[1:-1], b.contact.unknowns("reduced")[0], v1=v1, tol=tol)
    path = ContactPoints.concatenate([b.contact, path, e.contact])
    TE = _TEFunction(pair, path, v1, tol)

    def envelope(phi):
        cand = np.stack([TE(phi + p1), TE(phi), TE(phi - p1)])  # pairs k = -1, 0, +1
        env, lead = upper_envelope(np.where(np.isnan(cand), -np.inf, cand))
        return env, lead - 1

    kind, t_out = "indeterminate", np.nan
    if mc > 1.0:
        ov = np.linspace(b.phi1 + p1, e.phi1, int(n_points))
        g = TE(ov - p1) - TE(ov)
        scale = np.nanmax(np.abs(path.te[path.converged])) if np.any(path.converged) else 0.0
        gtol = 1e-13 + 1e-9 * scale
        if np.all(np.abs(g) <= gtol * 10):
            kind = "indeterminate"
        elif g[0] > gtol:
            kind, t_out = "at_engagement", float(b.phi1 + p1)
        elif np.all(g < gtol):
            kind, t_out = "at_exit", float(e.phi1)
        else:
            i = int(np.flatnonzero(g >= 0)[0])
            lo_, hi_ = ov[i - 1], ov[i]
            x0 = lo_ - g[i - 1] * (hi_ - lo_) / (g[i] - g[i - 1])

            def G(x):
                return (TE(x[:, 0] - p1) - TE(x[:, 0]))[:, None]

            gt = max(1e-16, 1e-6 * gtol)
            res = newton(G, np.array([[x0]]), tol=gt, maxiter=30, lower=[lo_ - 1e-9], upper=[hi_ + 1e-9])
            if res.status[0] == Status.CONVERGED:
                kind, t_out = "crossing", float(res.x[0, 0])
            else:  # fall back to the secant estimate, flagged by the kind
                kind, t_out = "crossing_unrefined", float(x0)
    if np.isfinite(t_out):
        t_in = t_out - p1
        phi = np.linspace(t_in, t_out, int(n_points))
    else:
        t_in = np.nan
        phi = np.linspace(b.phi1, b.phi1 + p1, int(n_points))
    te, k = envelope(phi)
    return MeshingCycle(
        begin=b,
        end=e,
        contact_ratio=mc,
        path=path,
        transfer_in=float(t_in),
        transfer_out=float(t_out),
        transfer_kind=kind,
        phi1=phi,
        te=te,
        pair_index=k,
    )
