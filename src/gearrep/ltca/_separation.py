"""Initial separations of the tooth pairs over the potential contact area, from the surfaces, with
the contact at the flanks' boundaries (edge contact) found rather than assumed away.

Nodes. Member 1's face (or a window of it around the contact, :func:`face_nodes`) carries
``n_nodes`` equally spaced nodes z_j along its axis, the first and last at the window's ends: at
the face ends they lie on the flank's boundary, so a contact that reaches a face end is computed
there. Node j stands for the strip of the face half-way to its neighbours (its tributary width).

First touch of a section. The transverse section of member 1's flank at z_j is a curve C_j. For
tooth pair k at member-1 angle phi1 (pair k is pair 0 one angular pitch later: its geometry is
pair 0's at phi1 - k 2 pi / N1, with the same transmission error, see :mod:`gearrep.meshing`),
member 2 turning toward it first touches C_j at the largest angle phi2 at which a point of C_j lies
on member 2's flank. Inside both flanks that is a tangency (kind ``interior``):

    R1(phi1) r1(u1, v1) = O2 + R2(phi2) r2(u2, v2)      (3 equations: a common point)
    z(r1(u1, v1)) = z_j                                 (1: the point is on the section)
    n2 . (e_z x n1) = 0                                 (1: C_j is tangent to flank 2)

in the unknowns (u1, v1, u2, v2, phi2) (Newton, :func:`gearrep.solve.newton`; for involute member-1
flanks v1 = z and the section equation drops out). This is the conventional TCA system (Litvin &
Fuentes ch. 9; thesis eq 26-32) with the collinearity of the normals replaced by the tangency of
the section curve: it has a root for line contact (where n1 and n2 are collinear) and for
localized contact alike. Where that root lies outside a flank, the first touch is on a boundary
of the flanks, and the last equation is replaced by the boundary (edge contact):

* ``tip1``: member 1's tip edge on flank 2, |r1 x y| = r_tip1;
* ``tip2``: member 2's tip edge on flank 1, |r2 x y| = r_tip2;
* ``face2_lo``, ``face2_hi``: member 2's face end on flank 1, z(r2) = z_lo2 or z_hi2.

(Member 1's own face ends are nodes.) Of the candidates whose points lie on both working flanks,
the first to touch is kept; an edge candidate must touch no earlier than the section's interior
tangency would (the edge point is a point of the same curve), which also rejects spurious
intersections far from the mesh.

Separations. Section j of pair k needs member 2 at TE_kj = phi2 - (N1/N2)(phi1 - k p1). Member 2
rests where the first section touches (the unloaded TCA): TE_0 = max_kj TE_kj (min for flanks
driven by decreasing phi1, ``Separations.sense``), and every other section is open by
s_kj = (TE_0 - TE_kj) h2_kj along the contact force's line, h2 = n . (w2 x (p - O2)) its moment
arm about member 2's axis (first order in TE_0 - TE_kj; exact for involute flanks). The force
acts along the normal of the smooth surface: member 1's outward normal, except at member 1's tip
edge (member 2's normal).

Across the contact the relative normal curvature is taken in member 1's principal direction
nearest the transverse section (the profile direction of a cylindrical-gear flank), or, at a tip
edge, in that of the mating flank plus 1/r_edge (a tip edge is a corner: its Hertz pressure is finite only for the
stated edge radius). The contact line runs across that direction in the tangent plane; a node's
line length is its tributary face width over the cosine of the line's angle to the axis.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..curvature import euler_normal_curvature
from ..solve import Status, newton
from ..tca import ContactPoints, GearPair, contact_curvatures
from ._families import Member, members, section_starts

__all__ = ["KINDS", "EDGE_KINDS", "Separations", "face_nodes", "section_contacts", "initial_separations"]

#: kind of a node's first touch: 0 none (no candidate on both flanks), then these
KINDS = {1: "interior", 2: "tip1", 3: "tip2", 4: "face2"}
#: kinds at a tip edge (a corner: Hertz with the edge radius)
EDGE_KINDS = (2, 3)
_INTERIOR = 1
_FACE2 = (4, 5)  # the systems of member 2's two face ends (both recorded as kind 4)


def face_nodes(m1: Member, n_nodes: int, windows=None):
    """Node positions z [mm] along member 1's axis and their tributary widths [mm]: ``n_nodes``
    equally spaced over the face (default) or over each window (..., 2) = (z_a, z_b) inside it,
    the end nodes on the window's ends with half a spacing each.

    Parameters
    ----------
    m1 : gearrep.ltca._families.Member
        Member 1's tooth (``ToothCompliance(flank).member``).
    n_nodes : int
        Nodes per window, >= 2.
    windows : array_like, optional
        (..., 2) axial windows [mm] (default the face).

    Returns
    -------
    z : numpy.ndarray
        (..., n_nodes) node positions [mm].
    width : numpy.ndarray
        (..., n_nodes) tributary widths [mm].

    Raises
    ------
    ValueError
        If ``n_nodes`` is not an integer >= 2 or the face is not finite.

    Examples
    --------
    >>> import math
    >>> from gearrep.ltca import ToothCompliance, face_nodes
    >>> from gearrep.surfaces.involute import InvoluteGearData, mating_flanks
    >>> g1, g2 = (InvoluteGearData(n, 3.0, math.radians(20), 25.0) for n in (23, 41))  # module mm, rad, face mm
    >>> z, width = face_nodes(ToothCompliance(mating_flanks(g1, g2)[0]).member, 5)
    >>> z.tolist(), width.tolist()  # mm over the 25 mm face
    ([-12.5, -6.25, 0.0, 6.25, 12.5], [3.125, 6.25, 6.25, 6.25, 3.125])
    """
    if isinstance(n_nodes, bool) or not isinstance(n_nodes, (int, np.integer)) or n_nodes < 2:
        raise ValueError(f"n_nodes must be an integer >= 2, got {n_nodes!r}")
    lo, hi = m1.z_lo, m1.z_hi
    if not np.isfinite(hi - lo) or not hi > lo:
        raise ValueError("member 1's flank needs a finite face width for the face nodes")
    w = np.array([lo, hi]) if windows is None else np.asarray(windows, dtype=float)
    a, b = w[..., 0:1], w[..., 1:2]
    t = np.linspace(0.0, 1.0, n_nodes)
    z = a + (b - a) * t
    width = np.broadcast_to((b - a) / (n_nodes - 1), z.shape).copy()
    width[..., 0] *= 0.5
    width[..., -1] *= 0.5
    return z, width


# ----------------------------------------------------------------------------------------------
# the section-contact systems
# ----------------------------------------------------------------------------------------------
def _equations(pair: GearPair, m1: Member, m2: Member, kind: int, phi1, z, x, v1_is_z: bool):
    if v1_is_z:
        u1, u2, v2, phi2 = x.T
        v1 = z
    else:
        u1, v1, u2, v2, phi2 = x.T
    P1 = pair.flank1.evaluate(u1, v1)
    R1 = pair.R1(phi1)
    r1 = np.einsum("nij,nj->ni", R1, P1.r)
    P2 = pair.flank2.evaluate(u2, v2)
    R2 = pair.R2(phi2)
    r2 = pair.O2 + np.einsum("nij,nj->ni", R2, P2.r)
    eqs = [r1 - r2]
    if not v1_is_z and kind not in _FACE2:
        eqs.append((P1.r[:, 2] - z)[:, None])
    if kind == _INTERIOR or kind in _FACE2:
        n1 = np.einsum("nij,nj->ni", R1, P1.normal)
        n2 = np.einsum("nij,nj->ni", R2, P2.normal)
        t = np.column_stack([-n1[:, 1], n1[:, 0], np.zeros(len(n1))])  # e_z x n1: the section's tangent
        eqs.append((np.sum(n2 * t, axis=1) / np.linalg.norm(t, axis=1))[:, None])
    if kind == 2:
        eqs.append((np.hypot(P1.r[:, 0], P1.r[:, 1]) - m1.r_tip)[:, None])
    elif kind == 3:
        eqs.append((np.hypot(P2.r[:, 0], P2.r[:, 1]) - m2.r_tip)[:, None])
    elif kind in _FACE2:
        eqs.append((P2.r[:, 2] - (m2.z_lo if kind == _FACE2[0] else m2.z_hi))[:, None])
    return np.concatenate(eqs, axis=1)


_K = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 0.0]])  # d Rz / d angle = Rz K


def _unit_normal_derivs(P):
    """Unit normal N = unit(r_u x r_v) and its derivatives dN/du, dN/dv of a SurfacePoint."""
    m = np.cross(P.r_u, P.r_v)
    mu = np.linalg.norm(m, axis=1, keepdims=True)
    N = m / mu

    def d(dm):
        return (dm - N * np.sum(N * dm, axis=1, keepdims=True)) / mu

    return N, d(np.cross(P.r_uu, P.r_v) + np.cross(P.r_u, P.r_uv)), d(np.cross(P.r_uv, P.r_v) + np.cross(P.r_u, P.r_vv))


def _mv(R, v):
    return np.einsum("nij,nj->ni", R, v)


def _fun_jac(pair: GearPair, m1: Member, m2: Member, kind: int, phi1, z, x, v1_is_z: bool):
    """Residual of :func:`_equations` and its analytic Jacobian (columns u1, v1, u2, v2, phi2, the
    v1 column left out when v1 = z)."""
    if v1_is_z:
        u1, u2, v2, phi2 = x.T
        v1 = z
    else:
        u1, v1, u2, v2, phi2 = x.T
    n = u1.size
    P1, P2 = pair.flank1.evaluate(u1, v1), pair.flank2.evaluate(u2, v2)
    R1, R2 = pair.R1(phi1), pair.R2(phi2)
    r2f = _mv(R2, P2.r)
    rows, jac = [_mv(R1, P1.r) - pair.O2 - r2f], []
    jp = np.zeros((n, 3, 5))
    jp[:, :, 0], jp[:, :, 1] = _mv(R1, P1.r_u), _mv(R1, P1.r_v)
    jp[:, :, 2], jp[:, :, 3] = -_mv(R2, P2.r_u), -_mv(R2, P2.r_v)
    jp[:, :, 4] = _mv(R2, P2.r @ _K.T)
    jac.append(jp)
    if not v1_is_z and kind not in _FACE2:
        rows.append((P1.r[:, 2] - z)[:, None])
        js = np.zeros((n, 1, 5))
        js[:, 0, 0], js[:, 0, 1] = P1.r_u[:, 2], P1.r_v[:, 2]
        jac.append(js)
    e = np.zeros((n, 1, 5))
    if kind == _INTERIOR or kind in _FACE2:
        N1, N1u, N1v = _unit_normal_derivs(P1)
        N2, N2u, N2v = _unit_normal_derivs(P2)
        n1, n2 = _mv(R1, N1), _mv(R2, N2)
        t = np.column_stack([-n1[:, 1], n1[:, 0], np.zeros(n)])
        tn = np.linalg.norm(t, axis=1, keepdims=True)
        g = t / tn
        rows.append(np.sum(n2 * g, axis=1)[:, None])
        for col, dN in ((0, N1u), (1, N1v)):
            dn = _mv(R1, dN)
            dt = np.column_stack([-dn[:, 1], dn[:, 0], np.zeros(n)])
            dg = (dt - g * np.sum(g * dt, axis=1, keepdims=True)) / tn
            e[:, 0, col] = np.sum(n2 * dg, axis=1)
        e[:, 0, 2], e[:, 0, 3] = np.sum(_mv(R2, N2u) * g, axis=1), np.sum(_mv(R2, N2v) * g, axis=1)
        e[:, 0, 4] = -np.sum(_mv(R2, N2 @ _K.T) * g, axis=1)
        jac.append(e.copy())
        e[:] = 0.0
    if kind in (2, 3):
        P, col, tip = (P1, 0, m1.r_tip) if kind == 2 else (P2, 2, m2.r_tip)
        rho = np.hypot(P.r[:, 0], P.r[:, 1])
        rows.append((rho - tip)[:, None])
        e[:, 0, col] = (P.r[:, 0] * P.r_u[:, 0] + P.r[:, 1] * P.r_u[:, 1]) / rho
        e[:, 0, col + 1] = (P.r[:, 0] * P.r_v[:, 0] + P.r[:, 1] * P.r_v[:, 1]) / rho
        jac.append(e)
    elif kind in _FACE2:
        rows.append((P2.r[:, 2] - (m2.z_lo if kind == _FACE2[0] else m2.z_hi))[:, None])
        e[:, 0, 2], e[:, 0, 3] = P2.r_u[:, 2], P2.r_v[:, 2]
        jac.append(e)
    J = np.concatenate(jac, axis=1)
    return np.concatenate(rows, axis=1), (J[:, :, [0, 2, 3, 4]] if v1_is_z else J)


def _solve_kind(pair, m1, m2, kind, phi1, z, x0, tol, maxiter, v1_is_z):
    """Newton on the system of ``kind`` for the rows of (phi1, z, x0 (n, 5)); returns x (n, 5) and
    the status (CONVERGED only for a root with both points on the working flanks)."""
    n = phi1.size
    x = np.full((n, 5), np.nan)
    status = np.full(n, int(Status.OFF_FLANK), dtype=int)
    v1_is_z = v1_is_z and kind not in _FACE2  # at member 2's face end the section is an unknown
    idx = np.flatnonzero(np.all(np.isfinite(x0), axis=1))
    if idx.size == 0:
        return x, status
    cols = [0, 2, 3, 4] if v1_is_z else [0, 1, 2, 3, 4]
    lo = np.array([pair.lower1[0], pair.lower1[1], pair.lower2[0], pair.lower2[1], -np.inf])[cols]
    hi = np.array([pair.upper1[0], pair.upper1[1], pair.upper2[0], pair.upper2[1], np.inf])[cols]
    p_, z_ = phi1[idx], z[idx]
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        sr = newton(
            lambda xx, rows: _equations(pair, m1, m2, kind, p_[rows], z_[rows], xx, v1_is_z),
            x0[idx][:, cols],
            fun_jac=lambda xx, rows: _fun_jac(pair, m1, m2, kind, p_[rows], z_[rows], xx, v1_is_z),
            tol=tol,
            maxiter=maxiter,
            lower=lo,
            upper=hi,
            rows=True,
            inverse_square=True,
        )
    xs = np.asarray(sr.x, dtype=float)
    full = np.full((idx.size, 5), np.nan)
    full[:, cols] = xs
    if v1_is_z:
        full[:, 1] = z_
    x[idx] = full
    ok = (sr.status == Status.CONVERGED) | (sr.status == Status.OFF_FLANK)
    with np.errstate(invalid="ignore"):
        on = ok & m1.contains(full[:, 0], full[:, 1]) & m2.contains(full[:, 2], full[:, 3])
    status[idx] = np.where(on, int(Status.CONVERGED), np.where(ok, int(Status.OFF_FLANK), sr.status))
    return x, status


def _snap(m1: Member, m2: Member, kind: int, x):
    """Start of an edge system: the involute start moved onto the edge (u = radius, v = z)."""
    x = x.copy()
    if m1.family == "involute":
        if kind == 2:
            x[:, 0] = m1.r_tip
        elif kind == 3:
            x[:, 2] = m2.r_tip
        elif kind in _FACE2:
            x[:, 3] = m2.z_lo if kind == _FACE2[0] else m2.z_hi
    return x


def _points(pair, phi1, x, status, kind) -> ContactPoints:
    """ContactPoints of the chosen candidates; ``normal`` is the contact force's line (member 1's
    outward normal, or minus member 2's at member 1's tip edge)."""
    u1, v1, u2, v2, phi2 = x.T
    n = phi1.size
    pos = np.full((n, 3), np.nan)
    nrm = np.full((n, 3), np.nan)
    ok = status == Status.CONVERGED
    if np.any(ok):
        p, n1 = pair.member1(u1[ok], v1[ok], phi1[ok])
        _, n2 = pair.member2(u2[ok], v2[ok], phi2[ok])
        pos[ok] = p
        nrm[ok] = np.where((kind[ok] == 2)[:, None], -n2, n1)
    te = phi2 - pair.ratio * phi1
    res = np.where(ok, 0.0, np.nan)
    return ContactPoints(u1, v1, u2, v2, phi1.copy(), phi2, pos, nrm, te, res, np.zeros(n, int), status, "conventional")


def section_contacts(pair: GearPair, phi1, z, start=None, *, tol: float = 1e-10, maxiter: int = 30, sense=None):
    """First touch of the member-1 sections at axial positions ``z`` [mm] with member 2 at member-1
    angles ``phi1`` (equal-length arrays; module docstring). ``start`` (n, 5) = (u1, v1, u2, v2,
    phi2), default the family's closed form. ``sense`` (+1/-1) orders the candidates (the first
    touch has the largest sense x TE; default from the interior tangencies' moment arms). Returns (:class:`gearrep.tca.ContactPoints`, kind
    (n,)); status CONVERGED only where a candidate lies on both working flanks.

    Parameters
    ----------
    pair : gearrep.tca.GearPair
        The pair (flanks of a supported family).
    phi1 : float or array_like
        Member-1 angles [rad].
    z : float or array_like
        Axial positions of the sections [mm].
    start : array_like, optional
        (n, 5) starts [mm, rad].
    tol : float, optional
        Residual tolerance [mm].
    maxiter : int, optional
        Iteration limit.
    sense : {1, -1}, optional
        The order of the candidates.

    Returns
    -------
    contacts : gearrep.tca.ContactPoints
        One row per section.
    kind : numpy.ndarray
        (n,) :data:`KINDS` key, 0 none.

    Examples
    --------
    >>> import math
    >>> from gearrep.ltca import section_contacts
    >>> from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks
    >>> from gearrep.tca import GearPair
    >>> g1, g2 = (InvoluteGearData(n, 3.0, math.radians(20), 25.0) for n in (23, 41))  # module mm, rad, face mm
    >>> pair = GearPair(*mating_flanks(g1, g2, crowning1=ParabolicCrowning(1e-4)), 23, 41, g1.r_p + g2.r_p)
    >>> c, kind = section_contacts(pair, [0.0, 0.0], [0.0, 10.0])  # rad, mm
    >>> c.status_name.tolist(), kind.tolist(), bool(c.te[1] < c.te[0])  # the crowned section touches later
    (['converged', 'converged'], [1, 1], True)
    """
    m1, m2 = members(pair)
    phi1, z = np.broadcast_arrays(np.asarray(phi1, float).ravel(), np.asarray(z, float).ravel())
    phi1, z = phi1.copy(), z.copy()
    x0 = section_starts(pair, m1, m2, phi1, z)[0] if start is None else np.asarray(start, float)
    c, kind, _ = _first_touch(pair, m1, m2, phi1, z, x0, tol, maxiter, sense)
    return c, kind


def _arms(pair, c: ContactPoints):
    """Moment arms of the contact force's line about member 1's and member 2's axes."""
    z_cross_p = np.column_stack([-c.position[:, 1], c.position[:, 0], np.zeros(len(c))])
    arm1 = np.sum(c.normal * z_cross_p, axis=1)
    arm2 = np.sum(c.normal * np.cross(pair.w2, c.position - pair.O2), axis=1)
    return arm1, arm2


def _first_touch(pair, m1, m2, phi1, z, x0, tol, maxiter, sense=None, interior=None):
    """(ContactPoints, kind, sense): the interior tangencies (or the given ``interior`` = (x,
    status)), the drive sense from them (unless given) and the tip-edge candidates where the
    tangency lies off the flanks."""
    v1_is_z = m1.family == "involute"
    if interior is None:
        interior = _solve_kind(pair, m1, m2, _INTERIOR, phi1, z, x0, tol, maxiter, v1_is_z)
    x, st = (a.copy() for a in interior)
    kind = np.where(st == Status.CONVERGED, _INTERIOR, 0)
    if sense is None:
        ok = kind == _INTERIOR
        arm1, arm2 = _arms(pair, _points(pair, phi1[ok], x[ok], st[ok], kind[ok]))
        sense = _drive_sense(arm1, arm2)
    te_virtual = x[:, 4] - pair.ratio * phi1  # the interior tangency's TE, on the flanks or not
    todo = np.flatnonzero((kind == 0) & (st == Status.OFF_FLANK) & np.all(np.isfinite(x), axis=1))
    if todo.size:
        base = x[todo]
        best_x, best_te = np.full((todo.size, 5), np.nan), np.full(todo.size, -np.inf)
        best_k = np.zeros(todo.size, dtype=int)
        bound = 0.1 * 2.0 * np.pi / pair.n2  # no edge contact a tenth of a pitch from the tangency's TE
        ref = sense * te_virtual[todo]
        for k in EDGE_KINDS:
            xe, se = _solve_kind(pair, m1, m2, k, phi1[todo], z[todo], _snap(m1, m2, k, base), tol, maxiter, v1_is_z)
            te = sense * (xe[:, 4] - pair.ratio * phi1[todo])
            good = (se == Status.CONVERGED) & (np.abs(te - ref) < bound) & (te <= ref + 1e-12)
            better = good & (te > best_te)
            best_x[better], best_te[better], best_k[better] = xe[better], te[better], k
        found = best_k > 0
        x[todo[found]] = best_x[found]
        kind[todo[found]] = best_k[found]
    status = np.where(kind > 0, int(Status.CONVERGED), np.where(st == Status.CONVERGED, int(Status.OFF_FLANK), st))
    return _points(pair, phi1, x, status, kind), kind, sense


def _common_face(pair, m1, m2, phi_eff, windows, x, st, tol, maxiter):
    """Windows (n_pos, n_pairs, 2) cut to where the interior tangencies of the nodes lie within
    member 2's face: where the tangency locus leaves member 2's face between two nodes, the window
    ends at the section whose tangency lies on member 2's face end (the face2 system). Returns the
    windows and a mask (n_pos, n_pairs, 2) of the ends moved."""
    shape = windows.shape[:2] + (-1,)
    conv = (st == Status.CONVERGED) | (st == Status.OFF_FLANK)
    z2 = np.full(st.size, np.nan)
    if np.any(conv):
        z2[conv] = pair.flank2.position(x[conv, 2], x[conv, 3])[:, 2]
    s = 1e-9 * m2.r_tip
    inside = (conv & (z2 >= m2.z_lo - s) & (z2 <= m2.z_hi + s)).reshape(shape)
    z2 = z2.reshape(shape)
    xs = x.reshape(shape + (5,))
    phis = phi_eff.reshape(shape)
    n = inside.shape[-1]
    moved = np.zeros(windows.shape, dtype=bool)
    out = windows.copy()
    any_in = np.any(inside, axis=-1)
    first = np.argmax(inside, axis=-1)
    last = n - 1 - np.argmax(inside[..., ::-1], axis=-1)
    for end, j_in, j_out in ((0, first, first - 1), (1, last, last + 1)):
        todo = any_in & (j_out >= 0) & (j_out < n)
        P, K = np.nonzero(todo)
        if P.size == 0:
            continue
        ji, jo = j_in[P, K], j_out[P, K]
        below = z2[P, K, jo] < m2.z_lo
        for kind, sel in ((_FACE2[0], below), (_FACE2[1], ~below & np.isfinite(z2[P, K, jo]))):
            if not np.any(sel):
                continue
            p_, k_, j_ = P[sel], K[sel], ji[sel]
            x0 = _snap(m1, m2, kind, xs[p_, k_, j_])
            xe, se = _solve_kind(pair, m1, m2, kind, phis[p_, k_, j_], np.zeros(p_.size), x0, tol, maxiter, False)
            ok = se == Status.CONVERGED
            zeta = pair.flank1.position(xe[ok, 0], xe[ok, 1])[:, 2]
            out[p_[ok], k_[ok], end] = zeta
            moved[p_[ok], k_[ok], end] = True
    return out, moved


# ----------------------------------------------------------------------------------------------
# separations of every tooth pair and node
# ----------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Separations:
    """First touches of every tooth pair and node at each position, shape (n_pos, n_pairs, n_nodes).

    Parameters
    ----------
    phi1_rad : numpy.ndarray
        (n_pos,) member-1 angles [rad].
    pairs : numpy.ndarray
        (n_pairs,) tooth-pair offsets k.
    z_mm, width_mm : numpy.ndarray
        Node positions along member 1's axis and tributary face widths [mm].
    contacts : gearrep.tca.ContactPoints
        All rows (flattened in that order; ``normal`` = the contact force's line).
    kind : numpy.ndarray
        :data:`KINDS` key, 0 none.
    in_contact : numpy.ndarray
        A candidate on both flanks.
    expected : numpy.ndarray
        The family's closed-form start lies inside both flanks with a margin (a node that must be
        found: a failure there makes the position NOT_CONVERGED).
    sense : int
        +1 if member 1 drives these flanks turning by increasing phi1 (moment arms positive), -1 if
        by decreasing phi1.
    te_rad : numpy.ndarray
        TE at which the node touches [rad].
    te_rigid_rad : numpy.ndarray
        (n_pos,) unloaded TE (the first touch) [rad].
    gap_mm : numpy.ndarray
        Initial separation [mm] (NaN where not a candidate).
    arm1_mm, arm2_mm : numpy.ndarray
        Signed moment arms of the force line about the axes [mm].
    k_rel_per_mm : numpy.ndarray
        Relative curvature across the contact line [1/mm] (with 1/edge_radius_mm at a tip edge).
    across : numpy.ndarray
        (..., 3) unit direction across the line.
    line_length_mm : numpy.ndarray
        Contact-line length of the node [mm].
    edge_radius_mm : float
        The tip-edge radius used [mm].

    Examples
    --------
    >>> import math
    >>> import numpy as np
    >>> from gearrep.ltca import initial_separations
    >>> from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks
    >>> from gearrep.tca import GearPair
    >>> g1, g2 = (InvoluteGearData(n, 3.0, math.radians(20), 25.0) for n in (23, 41))  # module mm, rad, face mm
    >>> pair = GearPair(*mating_flanks(g1, g2, crowning1=ParabolicCrowning(1e-4)), 23, 41, g1.r_p + g2.r_p)
    >>> sep = initial_separations(pair, [0.0], n_nodes=5, pairs=[0])  # rad
    >>> sep.shape, sep.kind.tolist(), np.round(sep.gap_mm * 1e3, 3).tolist()  # the crown's gaps [um]
    ((1, 1, 5), [[[1, 1, 1, 1, 1]]], [[[15.625, 3.906, 0.0, 3.906, 15.625]]])
    """

    phi1_rad: np.ndarray
    pairs: np.ndarray
    z_mm: np.ndarray
    width_mm: np.ndarray
    contacts: ContactPoints
    kind: np.ndarray
    in_contact: np.ndarray
    expected: np.ndarray
    sense: int
    te_rad: np.ndarray
    te_rigid_rad: np.ndarray
    gap_mm: np.ndarray
    arm1_mm: np.ndarray
    arm2_mm: np.ndarray
    k_rel_per_mm: np.ndarray
    across: np.ndarray
    line_length_mm: np.ndarray
    edge_radius_mm: float

    @property
    def shape(self) -> tuple:
        """(n_pos, n_pairs, n_nodes)."""
        return self.in_contact.shape

    @property
    def edge(self) -> np.ndarray:
        """True where the node touches at a boundary of a flank (tip edge or member 2's face end)."""
        return self.kind > _INTERIOR


def _drive_sense(arm1, arm2) -> int:
    """+1 or -1: the common sign of the candidates' moment arms (ValueError if they disagree, i.e. the
    flanks would push the members apart in one place and together in another)."""
    if arm1.size == 0:
        return 1
    signs = np.concatenate([np.sign(arm1), np.sign(arm2)])
    if not (np.all(signs > 0) or np.all(signs < 0)):
        raise ValueError(
            "the contact normals' moment arms about the two axes have mixed signs: the flanks do not transmit "
            "torque in one sense of rotation (check the flank sides and the mounting)"
        )
    return int(signs[0])


def _across(pair, c: ContactPoints, kind, edge_radius_mm):
    """Relative curvature across the contact line [1/mm] and the across direction (module docstring;
    curvature signs of :func:`gearrep.tca.contact_curvatures`: convex-convex positive). The across
    direction is the principal direction nearest the transverse section's tangent e_z x n (the
    profile direction of a cylindrical-gear flank, whose other principal direction runs along the
    face even where a crown's lengthwise curvature is the larger)."""
    pc1, pc2 = contact_curvatures(pair, c)
    t = np.column_stack([-c.normal[:, 1], c.normal[:, 0], np.zeros(len(c))])
    t /= np.linalg.norm(t, axis=1, keepdims=True)

    def nearest(pc):
        first = np.abs(np.sum(pc.e1 * t, axis=1)) >= np.abs(np.sum(pc.e2 * t, axis=1))
        return np.where(first[:, None], pc.e1, pc.e2)

    d1, d2 = nearest(pc1), nearest(pc2)
    k = euler_normal_curvature(pc2, d1) - euler_normal_curvature(pc1, d1)
    e = 1.0 / edge_radius_mm
    k = np.where(kind == 2, e + euler_normal_curvature(pc2, d2), k)
    k = np.where(kind == 3, e - euler_normal_curvature(pc1, d1), k)
    d = np.where((kind == 2)[:, None], d2, d1)
    return k, d


def _merge(mask, a: ContactPoints, b: ContactPoints) -> ContactPoints:
    """Rows of ``b`` where ``mask``, of ``a`` elsewhere."""
    fields = {}
    for name in ContactPoints.ARRAYS:
        x, y = getattr(a, name), getattr(b, name)
        m = mask[:, None] if np.ndim(x) == 2 else mask
        fields[name] = np.where(m, y, x)
    return ContactPoints(**fields, formulation=a.formulation)


def _place(pair, m1: Member, m2: Member, phi_eff, n_nodes, windows, margin):
    """Nodes (Z, W) over the windows, the family's starts of their section contacts (NaN far from
    the flanks: not solved) and which are expected on the flanks."""
    Z, W = face_nodes(m1, n_nodes, windows)
    start, r1, r2 = section_starts(pair, m1, m2, phi_eff, Z.ravel())
    with np.errstate(invalid="ignore"):
        near = np.ones(phi_eff.size, dtype=bool)
        for r, m in ((r1, m1), (r2, m2)):
            span = m.r_tip - m.r_form
            near &= (r >= m.r_form - 0.5 * span) & (r <= m.r_tip + 0.5 * span)
    start[~near] = np.nan  # far from the flanks: out of mesh, not solved
    expected = near & m1.inside(start[:, 0], start[:, 1], margin) & m2.inside(start[:, 2], start[:, 3], margin)
    return Z, W, start, expected


def _geometry(pair, c: ContactPoints, kind, W, shape, sense, r_edge):
    """TE, rigid TE, separations, arms, curvature across, across direction and line length of the
    first touches ``c`` (flattened rows of ``shape``)."""
    ok = c.status == Status.CONVERGED
    arm1, arm2 = _arms(pair, c)
    _drive_sense(arm1[ok], arm2[ok])  # the edge contacts push the same way
    te = np.where(ok, c.te, np.nan).reshape(shape)
    with np.errstate(invalid="ignore"):
        te_rigid = sense * np.nanmax(np.where(ok.reshape(shape), sense * te, -np.inf), axis=(1, 2))
    te_rigid = np.where(np.isfinite(te_rigid), te_rigid, np.nan)
    gap = (te_rigid[:, None, None] - te) * arm2.reshape(shape)
    k_rel = np.full(len(c), np.nan)
    across = np.full((len(c), 3), np.nan)
    length = np.full(len(c), np.nan)
    if np.any(ok):
        k_rel[ok], across[ok] = _across(pair, c.take(ok), kind[ok], r_edge)
        line = np.cross(c.normal[ok], across[ok])
        line /= np.linalg.norm(line, axis=1, keepdims=True)
        length[ok] = W.ravel()[ok] / np.abs(line[:, 2])
    return te, te_rigid, gap, arm1, arm2, k_rel, across, length


def initial_separations(
    pair: GearPair,
    phi1,
    *,
    n_nodes: int = 21,
    windows=None,
    pairs=None,
    edge_radius_mm=None,
    tol: float = 1e-10,
    margin: float = 0.02,
    previous: Separations | None = None,
    keep=None,
) -> Separations:
    """First touches and initial separations of tooth pairs ``pairs`` (offsets k, default -4 ... 4)
    at ``n_nodes`` nodes over member 1's face, or over ``windows`` (n_pos, n_pairs, 2) of it, at
    member-1 angles ``phi1`` [rad] (module docstring). ``edge_radius_mm``: radius of the tip edges
    (default a tenth of member 1's module); ``margin``: fraction of each flank's profile span and
    face width inside which a closed-form start counts as an expected contact. ``previous`` and
    ``keep`` (n_pos, n_pairs): the tooth pairs whose nodes are those of ``previous`` (their windows
    its node ranges) are taken from it, not solved again.

    Parameters
    ----------
    pair : gearrep.tca.GearPair
        The pair (flanks of a supported family).
    phi1 : float or array_like
        Member-1 angles [rad], finite.
    n_nodes : int, optional
        Nodes per tooth pair.
    windows : array_like, optional
        (n_pos, n_pairs, 2) axial windows [mm].
    pairs : array_like of int, optional
        Tooth-pair offsets.
    edge_radius_mm : float, optional
        Tip-edge radius [mm], > 0.
    tol : float, optional
        Residual tolerance of the section solves [mm].
    margin : float, optional
        Fraction of the flank spans [1].
    previous : Separations, optional
        Separations to reuse.
    keep : array_like of bool, optional
        (n_pos, n_pairs) the tooth pairs taken from ``previous``.

    Returns
    -------
    Separations
        The first touches.

    Raises
    ------
    ValueError
        If an angle is not finite, the edge radius is not > 0 or the windows have another shape.

    Examples
    --------
    >>> import math
    >>> import numpy as np
    >>> from gearrep.ltca import KINDS, initial_separations
    >>> from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks
    >>> from gearrep.tca import GearPair
    >>> g1, g2 = (InvoluteGearData(n, 3.0, math.radians(20), 25.0) for n in (23, 41))  # module mm, rad, face mm
    >>> pair = GearPair(*mating_flanks(g1, g2, crowning1=ParabolicCrowning(1e-4)), 23, 41, g1.r_p + g2.r_p)
    >>> sep = initial_separations(pair, [0.0], n_nodes=5, pairs=[-1, 0, 1])  # rad
    >>> [KINDS[k] for k in sep.kind[0, :, 2]], np.round(sep.gap_mm[0, :, 2] * 1e3, 1).tolist()  # mid-face, um
    (['tip1', 'interior', 'interior'], [398.9, 0.0, 0.0])
    """
    m1, m2 = members(pair)
    phi1 = np.atleast_1d(np.asarray(phi1, dtype=float))
    if phi1.ndim != 1 or not np.all(np.isfinite(phi1)):
        raise ValueError("phi1 must be a finite angle or 1-D array of angles [rad]")
    r_edge = 0.1 * float(m1.base.gear.module) if edge_radius_mm is None else float(edge_radius_mm)
    if not (np.isfinite(r_edge) and r_edge > 0):
        raise ValueError(f"edge_radius_mm must be a finite length > 0 [mm], got {edge_radius_mm!r}")
    pairs = np.arange(-4, 5) if pairs is None else np.asarray(pairs, dtype=int)
    n_pos, n_pairs = phi1.size, pairs.size
    if windows is not None and np.shape(windows) != (n_pos, n_pairs, 2):
        raise ValueError(f"windows must have shape {(n_pos, n_pairs, 2)}, got {np.shape(windows)}")
    face = np.broadcast_to(np.array([m1.z_lo, m1.z_hi]), (n_pos, n_pairs, 2)) if windows is None else windows
    face = np.array(face, dtype=float)
    shape = (n_pos, n_pairs, n_nodes)
    p1 = 2.0 * np.pi / pair.n1
    P, K = np.meshgrid(phi1, pairs, indexing="ij")
    phi_eff = np.broadcast_to((P - K * p1)[..., None], shape).ravel()
    v1_is_z = m1.family == "involute"

    def place(win):
        return _place(pair, m1, m2, phi_eff, n_nodes, win, margin)

    Z, W, start, expected = place(face)
    kept = np.zeros(phi_eff.size, dtype=bool)
    if previous is not None:
        if previous.shape != shape or np.shape(keep) != (n_pos, n_pairs):
            raise ValueError(f"previous must have shape {shape} and keep {(n_pos, n_pairs)}")
        kept = np.broadcast_to(np.asarray(keep, dtype=bool)[..., None], shape).ravel()
        start[kept] = np.nan  # taken from previous
    x, st = _solve_kind(pair, m1, m2, _INTERIOR, phi_eff, Z.ravel(), start, tol, 30, v1_is_z)
    face, moved = _common_face(pair, m1, m2, phi_eff, face, x, st, tol, 30)
    redo = np.broadcast_to(np.any(moved, axis=-1)[..., None], shape).ravel()
    if np.any(redo):
        Z, W, start, expected = place(face)
        start[kept] = np.nan
        xr, sr = _solve_kind(pair, m1, m2, _INTERIOR, phi_eff[redo], Z.ravel()[redo], start[redo], tol, 30, v1_is_z)
        x[redo], st[redo] = xr, sr
    given = None if previous is None else previous.sense  # the rows solved again may all be at edges
    c, kind, sense = _first_touch(pair, m1, m2, phi_eff, Z.ravel(), start, tol, 30, given, interior=(x, st))
    at_face2 = np.zeros(shape, dtype=bool)
    at_face2[..., 0], at_face2[..., -1] = moved[..., 0], moved[..., 1]
    kind = np.where(at_face2.ravel() & (kind == _INTERIOR), _FACE2[0], kind)
    if previous is not None:
        c = _merge(kept, c, previous.contacts)
        kind = np.where(kept, previous.kind.ravel(), kind)
        expected = np.where(kept, previous.expected.ravel(), expected)
    ok = c.status == Status.CONVERGED
    te, te_rigid, gap, arm1, arm2, k_rel, across, length = _geometry(pair, c, kind, W, shape, sense, r_edge)
    return Separations(
        phi1_rad=phi1,
        pairs=pairs,
        z_mm=np.array(Z),
        width_mm=np.array(W),
        contacts=c,
        kind=kind.reshape(shape),
        in_contact=ok.reshape(shape),
        expected=expected.reshape(shape),
        sense=sense,
        te_rad=te,
        te_rigid_rad=te_rigid,
        gap_mm=gap,
        arm1_mm=arm1.reshape(shape),
        arm2_mm=arm2.reshape(shape),
        k_rel_per_mm=k_rel.reshape(shape),
        across=across.reshape(shape + (3,)),
        line_length_mm=length.reshape(shape),
        edge_radius_mm=r_edge,
    )
