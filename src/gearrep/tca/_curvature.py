"""Curvatures and the contact ellipse at solved contact points."""

from __future__ import annotations

import numpy as np

from ..curvature import principal_curvatures, with_opposite_normal
from ..ellipse import elastic_ellipse_at, hertz_contact_at
from ..surface import SurfacePoint
from ._pair import ContactPoints, GearPair, _mv

__all__ = ["contact_curvatures", "contact_ellipse", "contact_hertz"]


def _fixed_frame_point(flank, u, v, R, origin=None):
    P = flank.evaluate(u, v)
    vecs = [_mv(R, x) for x in (P.r, P.r_u, P.r_v, P.r_uu, P.r_uv, P.r_vv)]
    if origin is not None:
        vecs[0] = vecs[0] + origin
    return SurfacePoint(*vecs)


def contact_curvatures(pair: GearPair, contact: ContactPoints):
    """Principal curvatures of both members at the contact points, in S_f and both expressed with
    the common unit normal ``contact.normal`` (outward from member 1, into member 2), ready for
    :func:`gearrep.curvature.relative_curvature` and :func:`gearrep.ellipse.elastic_ellipse_at`.

    Curvatures follow the convention of :mod:`gearrep.curvature` (positive where the surface bends
    toward the normal): a convex member-1 flank has negative values, a convex member-2 flank
    (seen from member 1) positive ones. Computed for every row; rows whose status is not
    CONVERGED are NaN.

    Parameters
    ----------
    pair : GearPair
        The pair.
    contact : ContactPoints
        Solved contact points of ``pair``.

    Returns
    -------
    tuple of gearrep.curvature.PrincipalCurvatures
        (member 1, member 2): k1 >= k2 [1/length], principal directions and the common normal in S_f.

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
    >>> from gearrep.tca import contact_curvatures
    >>> k_1, k_2 = contact_curvatures(pair, solve_contact(pair, [0.0]))
    >>> np.round([k_1.k1[0], k_1.k2[0], k_2.k1[0], k_2.k2[0]], 6).tolist()  # 1/mm
    [-0.0002, -0.071311, 0.053078, 0.0]
    """
    ok = contact.converged
    idx = np.flatnonzero(ok)
    nan = np.full(len(contact), np.nan)
    nan3 = np.full((len(contact), 3), np.nan)
    out = []
    for flank, u, v, R, sign, origin, flip in (
        (pair.flank1, contact.u1, contact.v1, pair.R1(contact.phi1), pair.sign1, None, False),
        (pair.flank2, contact.u2, contact.v2, pair.R2(contact.phi2), pair.sign2, pair.O2, True),
    ):
        pc = principal_curvatures(_fixed_frame_point(flank, u[idx], v[idx], R[idx], origin))
        # r_u x r_v -> outward normal of the member, then member 2 seen with member 1's normal
        if (sign < 0) != flip:
            pc = with_opposite_normal(pc)
        full = [nan.copy(), nan.copy(), nan3.copy(), nan3.copy(), nan3.copy()]
        for f, x in zip(full, pc):
            f[idx] = x
        out.append(type(pc)(*full))
    return out[0], out[1]


def _per_point(name: str, value, contact: ContactPoints, ok):
    """``value`` (a scalar, or one per contact point) for the converged rows ``ok``; ValueError
    naming ``name`` for any other shape (a length-n array is taken row by row, never broadcast
    against the converged subset)."""
    a = np.asarray(value, dtype=float)
    n = len(contact)
    if a.ndim == 0:
        return value
    if a.ndim == 1 and len(a) == 1:
        return a[0]
    if a.ndim == 1 and len(a) == n:
        return a[ok]
    raise ValueError(f"{name} must be a scalar or one value per contact point (length {n}), got shape {a.shape}")


def contact_ellipse(pair: GearPair, contact: ContactPoints, delta):
    """Litvin's elastic-approach contact ellipse at the contact points (seed 002 eq 2.6.1-2.6.6 =
    seed 000 eq 5.14-5.17 = seed 004 eq 21-26) for an elastic approach ``delta`` (length unit of
    the design data, mm in the examples): semi-axes a >= b [length], area [length^2], major/minor
    axis unit vectors in S_f. Rows whose
    status is not CONVERGED are NaN; a contact whose relative curvature is not definite (line
    contact) has ``elliptic`` False.

    Parameters
    ----------
    pair : GearPair
        The pair.
    contact : ContactPoints
        Solved contact points of ``pair``.
    delta : float or (n,) array_like
        Elastic approach [length], one value or one per contact point.

    Returns
    -------
    gearrep.ellipse.ContactEllipse
        One row per contact point.

    Raises
    ------
    ValueError
        If ``delta`` is neither a scalar nor one value per contact point.

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
    >>> from gearrep.tca import contact_ellipse
    >>> el = contact_ellipse(pair, solve_contact(pair, [0.0]), 0.00632)  # delta [mm]
    >>> round(float(el.a[0]), 4), round(float(el.b[0]), 4), bool(el.elliptic[0])  # semi-axes [mm]
    (7.9498, 0.3188, True)
    """
    c1, c2 = contact_curvatures(pair, contact)
    ok = contact.converged
    delta = _per_point("delta", delta, contact, ok)
    el = elastic_ellipse_at(type(c1)(*(x[ok] for x in c1)), type(c2)(*(x[ok] for x in c2)), delta)
    full = []
    for x in el:
        x = np.asarray(x)
        f = np.full((len(contact),) + x.shape[1:], np.nan if x.dtype != bool else False, dtype=x.dtype)
        f[ok] = x
        full.append(f)
    return type(el)(*full)


def contact_hertz(pair: GearPair, contact: ContactPoints, load_N, E1_MPa, nu1, E2_MPa=None, nu2=None):
    """Hertz contact at the contact points (:func:`gearrep.ellipse.hertz_contact_at` with the
    curvatures of :func:`contact_curvatures`): semi-axes a >= b [mm] and maximum contact pressure
    p0 [MPa] for the normal load ``load_N`` [N] carried by each point (design lengths in mm).
    Rows whose contact status is not CONVERGED are NaN and keep that status; a line contact (a
    relative curvature of 0 or of mixed sign) is NaN with status SINGULAR.

    Parameters
    ----------
    pair : GearPair
        The pair (lengths in mm).
    contact : ContactPoints
        Solved contact points of ``pair``.
    load_N : float or (n,) array_like
        Normal load at each point [N].
    E1_MPa, nu1 : float
        Young's modulus [MPa] and Poisson's ratio of member 1.
    E2_MPa, nu2 : float, optional
        Those of member 2 (default: member 1's).

    Returns
    -------
    gearrep.ellipse.HertzContact
        Semi-axes [mm], p0 [MPa], approach [mm], ... and a status per contact point.

    Raises
    ------
    ValueError
        If ``load_N`` is neither a scalar nor one value per contact point, or a material value is bad.

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
    >>> from gearrep.tca import contact_hertz
    >>> h = contact_hertz(pair, solve_contact(pair, [0.0]), 1000.0, 210e3, 0.3)  # N, MPa, 1
    >>> round(float(h.a[0]), 3), round(float(h.b[0]), 4), round(float(h.p0[0]), 1)  # mm, mm, MPa
    (5.641, 0.1086, 779.6)
    """
    c1, c2 = contact_curvatures(pair, contact)
    ok = contact.converged
    load_N = _per_point("load_N", load_N, contact, ok)
    h = hertz_contact_at(
        type(c1)(*(x[ok] for x in c1)), type(c2)(*(x[ok] for x in c2)), load_N, E1_MPa, nu1, E2_MPa, nu2
    )
    full = []
    for name, x in zip(h._fields, h):
        x = np.broadcast_to(np.asarray(x), (int(ok.sum()),))
        if name == "status":  # rows without a contact keep the contact's own status
            f = np.asarray(contact.status).astype(x.dtype)
        else:
            f = np.full(len(contact), np.nan if x.dtype.kind == "f" else 0, dtype=x.dtype)
        f[ok] = x
        full.append(f)
    return type(h)(*full)
