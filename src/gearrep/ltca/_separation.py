"""Initial separations of the tooth pairs over the potential contact area, from the surfaces.

The face of member 1 is cut into ``n_slices`` strips of equal width; the section of member 1's
flank by the mid-plane of strip j (face coordinate v1_j) is a curve r1(u1; v1_j). For tooth pair k
at member-1 angle phi1 (pair k is pair 0 one angular pitch later: its geometry is pair 0's at
phi1 - k 2 pi / N1, with the same transmission error, see :mod:`gearrep.meshing`), the section
curve first touches member 2's flank, as member 2 turns, where

    R1(phi1) r1(u1, v1_j) = O2 + R2(phi2) r2(u2, v2)        (3 equations: a common point)
    n2 . t1 = 0                                             (1 equation: the curve is tangent to flank 2)

with t1 the unit tangent r1_u of the section curve and n2 member 2's unit normal, for the unknowns
(u1, u2, v2, phi2) (Newton, :func:`gearrep.solve.newton`, central-difference Jacobian). This is
the conventional TCA system (Litvin & Fuentes ch. 9; thesis eq 26-32) with v1 fixed and the
normal-collinearity equations replaced by the tangency of the section curve: it has a root for
line contact (where n1 and n2 are collinear, so n2 . t1 = 0 too) and for localized contact (where
the section curve only touches flank 2 at the angle phi2_j that brings that section in contact).

Section j of pair k then needs member 2 at TE_kj = phi2 - (N1/N2)(phi1 - k p1). Member 2 rests where
the first section touches (the unloaded TCA): TE_0 = max_kj TE_kj (min for flanks driven by
decreasing phi1, see ``Separations.sense``), and every other section is open
by the initial separation s_kj = (TE_0 - TE_kj) h2_kj along its normal, h2 = n2 . (w2 x (p - O2))
the moment arm of the normal about member 2's axis (first order in TE_0 - TE_kj; exact for
involute flanks, whose normal distance changes by r_b cos(beta_b) per radian of turn).

Only sections whose contact point lies on both flanks (inside the parameter domains) are candidate
contacts; edge contact (a flank's boundary curve against the other flank) is not computed here.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..curvature import euler_normal_curvature
from ..solve import Status, newton
from ..tca import ContactPoints, GearPair, contact_curvatures

__all__ = ["Separations", "face_slices", "section_contacts", "initial_separations"]


def face_slices(pair: GearPair, n_slices: int):
    """Mid-planes v1_j [mm] of ``n_slices`` equal strips over member 1's face and the strip width [mm]."""
    if isinstance(n_slices, bool) or not isinstance(n_slices, (int, np.integer)) or n_slices < 1:
        raise ValueError(f"n_slices must be an integer >= 1, got {n_slices!r}")
    lo, hi = float(pair.lower1[1]), float(pair.upper1[1])
    if not np.isfinite(hi - lo):
        raise ValueError("member 1's flank needs a finite face width (v bounds) for the face slices")
    width = (hi - lo) / n_slices
    return lo + width * (np.arange(n_slices) + 0.5), width


def _residual(pair: GearPair, phi1, v1, x):
    u1, u2, v2, phi2 = x[:, 0], x[:, 1], x[:, 2], x[:, 3]
    P1 = pair.flank1.evaluate(u1, v1)
    R1 = pair.R1(phi1)
    r1 = np.einsum("nij,nj->ni", R1, P1.r)
    t1 = np.einsum("nij,nj->ni", R1, P1.r_u)
    t1 /= np.linalg.norm(t1, axis=-1, keepdims=True)
    P2 = pair.flank2.evaluate(u2, v2)
    R2 = pair.R2(phi2)
    r2 = pair.O2 + np.einsum("nij,nj->ni", R2, P2.r)
    n2 = np.einsum("nij,nj->ni", R2, P2.normal)
    return np.column_stack([r1 - r2, np.sum(n2 * t1, axis=-1)])


def _involute_starts(pair: GearPair, phi1, v1):
    """(u1, u2, v2, phi2) of the aligned involute pair's section contact (line of action) as starts."""
    g1, g2 = pair.flank1.gear, pair.flank2.gear
    if not (hasattr(g1, "alpha_t") and hasattr(g2, "r_b")):
        raise ValueError(
            f"section-contact starts need involute flanks (gear data with base radius), got {type(pair.flank1).__name__}"
        )
    side = pair.flank1.side
    tw = pair.flank1.twist(np.asarray(v1, float))[0]
    s1 = g1.r_b * np.tan(g1.alpha_t) + side * g1.r_b * (phi1 + side * np.pi / (2 * pair.n1) + tw)
    a = pair.centre_distance
    s2 = np.sqrt(max(a * a - (g1.r_b + g2.r_b) ** 2, 0.0)) - s1
    with np.errstate(invalid="ignore"):
        u1 = np.sqrt(g1.r_b**2 + s1**2)
        u2 = np.sqrt(g2.r_b**2 + s2**2)
    u1 = np.where(s1 > 0, u1, np.nan)
    u2 = np.where(s2 > 0, u2, np.nan)
    return np.column_stack([u1, u2, np.asarray(v1, float) + 0.0 * u1, pair.ratio * np.asarray(phi1, float)])


def section_contacts(pair: GearPair, phi1, v1, start=None, *, tol: float = 1e-10, maxiter: int = 30) -> ContactPoints:
    """Contact of the member-1 section curves v1 with member 2 at member-1 angles ``phi1`` (equal-length
    arrays; module docstring). ``start`` (n, 4) = (u1, u2, v2, phi2), default the involute line-of-action
    position. Returns :class:`gearrep.tca.ContactPoints` (``normal`` = member 1's outward normal);
    status CONVERGED only for a root inside both flanks (OFF_FLANK outside)."""
    phi1, v1 = np.broadcast_arrays(np.asarray(phi1, float).ravel(), np.asarray(v1, float).ravel())
    x0 = _involute_starts(pair, phi1, v1) if start is None else np.asarray(start, float)
    todo = np.all(np.isfinite(x0), axis=1)
    n = phi1.size
    x = np.full((n, 4), np.nan)
    res = np.full(n, np.nan)
    its = np.zeros(n, dtype=int)
    status = np.full(n, int(Status.OFF_FLANK), dtype=int)  # no start on the flanks: out of mesh
    idx = np.flatnonzero(todo)
    if idx.size:
        lo = [pair.lower1[0], pair.lower2[0], pair.lower2[1], -np.inf]
        hi = [pair.upper1[0], pair.upper2[0], pair.upper2[1], np.inf]
        p_, v_ = phi1[idx], v1[idx]
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            sr = newton(
                lambda xx, rows: _residual(pair, p_[rows], v_[rows], xx),
                x0[idx],
                tol=tol,
                maxiter=maxiter,
                lower=lo,
                upper=hi,
                rows=True,
                inverse_square=True,
            )
        x[idx], res[idx], its[idx], status[idx] = sr.x, sr.residual, sr.iterations, sr.status
    return _points(pair, phi1, v1, x, res, its, status)


def _points(pair, phi1, v1, x, res, its, status) -> ContactPoints:
    u1, u2, v2, phi2 = x.T
    ok = np.isfinite(u1) & np.isfinite(u2)
    pos = np.full((phi1.size, 3), np.nan)
    nrm = np.full((phi1.size, 3), np.nan)
    if np.any(ok):
        p, nn = pair.member1(u1[ok], v1[ok], phi1[ok])
        pos[ok], nrm[ok] = p, nn
    te = phi2 - pair.ratio * phi1
    return ContactPoints(u1, v1.copy(), u2, v2, phi1.copy(), phi2, pos, nrm, te, res, its, status, "conventional")


@dataclass(frozen=True)
class Separations:
    """Section contacts of every tooth pair and slice at each position, shape (n_pos, n_pairs, n_slices).

    pairs : (n_pairs,) tooth-pair offsets k; v1_mm : (n_slices,) slice mid-planes; slice_width_mm
    contacts : :class:`gearrep.tca.ContactPoints` of all rows (flattened in that order)
    in_contact : candidate contact (section contact converged on both flanks)

    expected : the involute line-of-action start lies inside both flanks with a margin (a section
        that should be found; a failure there makes the position NOT_CONVERGED)

    sense : +1 if member 1 drives these flanks turning by increasing phi1 (the loads' moment arms
        about both axes positive), -1 if by decreasing phi1 (both negative: e.g. ``side=-1`` flanks)

    te_rad : TE at which the section touches; te_rigid_rad : (n_pos,) unloaded TE (the first touch:
        max over candidates, min for sense -1)

    gap_mm : initial separation (NaN where not a candidate); arm1_mm, arm2_mm : signed moment arms of
    the normal about member 1's and member 2's axes; k_rel_per_mm : relative curvature across the contact line
    """

    phi1_rad: np.ndarray
    pairs: np.ndarray
    v1_mm: np.ndarray
    slice_width_mm: float
    contacts: ContactPoints
    in_contact: np.ndarray
    expected: np.ndarray
    sense: int
    te_rad: np.ndarray
    te_rigid_rad: np.ndarray
    gap_mm: np.ndarray
    arm1_mm: np.ndarray
    arm2_mm: np.ndarray
    k_rel_per_mm: np.ndarray

    @property
    def shape(self) -> tuple:
        return self.in_contact.shape


def _across_curvature(pair: GearPair, c: ContactPoints) -> np.ndarray:
    """Relative normal curvature [1/mm] across the contact line: in member 1's principal direction of
    larger |curvature| (the profile direction of an involute flank, whose other principal curvature,
    along the contact line, is zero), convex-convex positive (module :mod:`gearrep.tca._curvature`)."""
    pc1, pc2 = contact_curvatures(pair, c)
    d = np.where((np.abs(pc1.k1) >= np.abs(pc1.k2))[:, None], pc1.e1, pc1.e2)
    return euler_normal_curvature(pc2, d) - euler_normal_curvature(pc1, d)


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


def initial_separations(
    pair: GearPair, phi1, *, n_slices: int = 20, pairs=None, tol: float = 1e-10, margin: float = 0.02
) -> Separations:
    """Section contacts and initial separations of tooth pairs ``pairs`` (offsets k, default the
    pairs within two contact ratios of pair 0) over ``n_slices`` face strips at member-1 angles
    ``phi1`` [rad] (module docstring). ``margin``: fraction of each flank's parameter span inside
    which a start counts as an expected contact."""
    phi1 = np.atleast_1d(np.asarray(phi1, dtype=float))
    if phi1.ndim != 1 or not np.all(np.isfinite(phi1)):
        raise ValueError("phi1 must be a finite angle or 1-D array of angles [rad]")
    v, width = face_slices(pair, n_slices)
    p1 = 2.0 * np.pi / pair.n1
    if pairs is None:
        pairs = np.arange(-4, 5)
    pairs = np.asarray(pairs, dtype=int)
    P, K, V = np.meshgrid(phi1, pairs, v, indexing="ij")
    phi_eff = (P - K * p1).ravel()
    start = _involute_starts(pair, phi_eff, V.ravel())
    lo = np.array([pair.lower1[0], pair.lower2[0], pair.lower2[1]])
    hi = np.array([pair.upper1[0], pair.upper2[0], pair.upper2[1]])
    span = hi - lo
    s3 = start[:, :3]
    with np.errstate(invalid="ignore"):
        near = np.all((s3 >= lo - 0.5 * span) & (s3 <= hi + 0.5 * span), axis=1)
        expected = np.all((s3 >= lo + margin * span) & (s3 <= hi - margin * span), axis=1)
    start[~near] = np.nan  # far outside the flanks: out of mesh, not solved
    c = section_contacts(pair, phi_eff, V.ravel(), start, tol=tol)
    shape = P.shape
    ok = c.status == Status.CONVERGED
    n1 = c.normal
    z_cross_p = np.column_stack([-c.position[:, 1], c.position[:, 0], np.zeros(len(c))])
    arm1 = np.sum(n1 * z_cross_p, axis=1)
    arm2 = np.sum(n1 * np.cross(pair.w2, c.position - pair.O2), axis=1)
    sense = _drive_sense(arm1[ok], arm2[ok])
    te = np.where(ok, c.te, np.nan).reshape(shape)
    with np.errstate(invalid="ignore"):
        te_rigid = sense * np.nanmax(np.where(ok.reshape(shape), sense * te, -np.inf), axis=(1, 2))
    te_rigid = np.where(np.isfinite(te_rigid), te_rigid, np.nan)
    gap = (te_rigid[:, None, None] - te) * arm2.reshape(shape)
    k_rel = np.full(len(c), np.nan)
    if np.any(ok):
        k_rel[ok] = _across_curvature(pair, c.take(ok))
    return Separations(
        phi1_rad=phi1,
        pairs=pairs,
        v1_mm=v,
        slice_width_mm=float(width),
        contacts=c,
        in_contact=ok.reshape(shape),
        expected=expected.reshape(shape),
        sense=sense,
        te_rad=te,
        te_rigid_rad=te_rigid,
        gap_mm=gap,
        arm1_mm=arm1.reshape(shape),
        arm2_mm=arm2.reshape(shape),
        k_rel_per_mm=k_rel.reshape(shape),
    )
