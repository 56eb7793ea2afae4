"""Tooth contact analysis (TCA) of two tooth surfaces on rotation axes, with misalignment.

Sources: Temirkhan, PhD thesis 2023 (seed 003): conventional (Litvin) formulation eq (26)-(32),
reduced two-unknown formulation eq (33)-(44), transmission error eq (14); Litvin & Fuentes,
"Gear Geometry and Applied Theory", 2nd ed., ch. 9 (simulation of meshing, TCA) and the spur/helical chapters.
Seed 000 eq (5.1)-(5.12) sets up the same conventional system.

Frames and conventions
----------------------
Fixed frame S_f. Member 1 turns about the z_f axis through the origin:
    r_f = Rz(phi1) r_1(u1, v1).
Member 2 turns about its own axis through O2 = (a + dE, dH, dZ) (a = centre distance):
    r_f = O2 + A2 Rz(phase2 - phi2) r_2(u2, v2),   A2 = Ry(d_gamma_in) Rx(shaft_angle + d_gamma_out).
So phi2 > 0 turns member 2 about w2 = -A2 z (the sense in which an external member 1 turning by
phi1 > 0 drives it), and for an aligned conjugate pair phi2 = (N1/N2) phi1. ``phase2`` defaults to
pi - side pi/N2: for involute flanks (tooth of each gear centred on its x axis) this places the
tooth space of member 2 on the centre line, so that the zero-backlash standard pair is in
conjugate mesh at phi1 = phi2 = 0 with contact at the pitch point.
Misalignment (all applied to member 2; the angular ones pivot about O2, i.e. the mid-face point of
its axis): d_gamma_in = rotation about y_f, in the plane of the axes (axes intersect);
d_gamma_out = rotation about x_f, the centre line (axes cross); dE = centre-distance change;
dH = offset along y_f; dZ = axial displacement along z_f.

Normals: ``normal`` of a contact point is the unit normal of member 1 pointing out of its tooth
(``outward_sign`` of the flank, -side for :class:`~gearrep.surfaces.involute.InvoluteFlank`).
At a true contact the outward normals are opposite: n_f1 + n_f2 = 0. Eq (27) prints n_f1 - n_f2 = 0,
which holds only if one normal is reversed; with both flanks parameterised alike (their
r_u x r_v both point into, or both out of, the material) eq (27) as printed has no solution near
the contact. A root with n_f1 . n_f2 > 0 (the two bodies on the same side of the common tangent
plane) is a false root and gets status WRONG_ROOT.

Transmission error (eq 14): TE = (phi2 - phi20) - (N1/N2)(phi1 - phi10), phi2 measured in the
driven sense above; TE > 0 means member 2 leads its conjugate position. Eq (14) as printed holds
only with that sign convention for phi2: if both angles are measured about +z (as the thesis's
pitch-point example phi1 = 1.5707, phi2 = -1.6 suggests), an external pair needs
TE = (phi2 - phi20) + (N1/N2)(phi1 - phi10). Default reference phi10 = phi20 = 0 (the nominal
conjugate placement), so TE is absolute; re-zero it with :func:`transmission_error`.

(a) Conventional formulation (eq 26-32): unknowns x = (u1, v1, u2, v2, phi2) for given phi1,
    F = [ r_f1 - r_f2 (3 eq),  two components of n_f1 + n_f2 ].
    The unit-normal equation has only two independent components (eq 28). We drop the component
    j = argmax |n_f1,j| at the starting point (fixed during the iterations): the kept components
    then determine the dropped one up to sign, and that is well conditioned because the dropped
    component is the largest. Dropping a small component instead (e.g. n_z of a spur gear, which
    is ~0) makes the 5x5 Jacobian singular, because the kept ones fix it only through n_z^2.
    The sign left free is checked after convergence (WRONG_ROOT if n_f1 + n_f2 != 0). For a crowned
    spur pair, keeping (x, y) instead gives a Jacobian with s_min/s_max ~ 3e-8 and, from starts
    near the root, ~40 % false roots with n_z1 = +n_z2 (tests/unit/test_tca.py). ``drop=`` overrides.
(b) Reduced formulation (eq 33-44), for member 2 in explicit cylindrical form
    r_2 = (u cos psi(u,v), u sin psi(u,v), v) (u = radius, v = axial coordinate, eq 35-36):
    unknowns (u1, v1) for given phi1; (u2, v2, phi2) follow explicitly from the point
    r_f1(u1, v1, phi1) (eq 37-40): with s = Rz(-phase2) A2^T (r_f1 - O2),
        v2 = s_z (eq 39),   u2 = sqrt(s_x^2 + s_y^2) (eq 40),
        phi2 = angle(r_2(u2, v2)) - atan2(s_y, s_x)                      (eq 41-44),
    and the two equations are two components of n_f1 x n_f2 = 0 (eq 33), dropping the component
    along argmax |n_f1,j| at the start (n_f1 x n_f2 is orthogonal to n_f1, so that component is
    dependent). The position equation holds by construction. Keeping the other pair (e.g. x, y of
    n1 x n2 for a spur gear, whose normal has n_z ~ 0) gives two nearly dependent equations
    (c . n1 = 0 ties c_x to c_y) with a Jacobian ~30 times smaller, and root accuracy to match.
    Eq (43) computes phi2 = +-acos(p2 . q2 / |q2|^2) with the sign from eq (44). Two remarks:
    |q2|^2 = |p2||q2| only because both projections have length u2; and acos loses half the digits
    near phi2 = 0 or pi (d acos/dx is infinite at x = +-1: an error eps in the cosine gives
    sqrt(2 eps) ~ 1e-8 rad). We use the equivalent atan2 form, which is exact to rounding and
    carries its own sign: phi2 is the right-handed rotation about w2 = -A2 z that takes the
    projection p2 of the member-2 surface point to the projection q2 of the contact point, i.e.
    phi2 = atan2((p2 x q2) . w2, p2 . q2). The sign of eq (44) is therefore + when (p2 x q2) . w2 > 0,
    i.e. when the rotation p2 -> q2 is counter-clockwise seen from the tip of w2; "clockwise" in the
    thesis's wording holds only when viewed from the other side. phi2 is taken on the branch
    nearest the nominal (N1/N2) phi1.

Line contact: for conjugate surfaces (aligned, unmodified involute pairs) the contact is a line
and the point solve is singular. Pass ``v1=`` to fix member 1's face-width coordinate; the
unknowns become (u1) [reduced] or (u1, u2, v2, phi2) [conventional, 5 equations, 4 unknowns,
least squares].

All solves go through :func:`gearrep.solve.newton`. Per-row data (phi1, a fixed v1, the dropped
component) are carried as extra unknowns frozen by identity rows with zero residual, because
``newton`` hands ``fun`` only the rows still iterating.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .solve import SolveResult, Status, newton, status_names
from .surface import cross
from .units import ARCSEC

try:  # rotation matrices from gearrep.frames (active rotations, (..., 3, 3))
    from .frames import rot_x as _frames_rot_x, rot_y as _frames_rot_y, rot_z as _frames_rot_z
except ImportError:  # pragma: no cover - frames not written yet
    _frames_rot_x = _frames_rot_y = _frames_rot_z = None


def _rot(axis: int, a) -> np.ndarray:
    """Active right-handed rotation by angle(s) ``a`` about coordinate axis ``axis`` -> (..., 3, 3)."""
    a = np.asarray(a, dtype=float)
    c, s = np.cos(a), np.sin(a)
    o, z = np.ones_like(a), np.zeros_like(a)
    if axis == 0:
        rows = [[o, z, z], [z, c, -s], [z, s, c]]
    elif axis == 1:
        rows = [[c, z, s], [z, o, z], [-s, z, c]]
    else:
        rows = [[c, -s, z], [s, c, z], [z, z, o]]
    return np.stack([np.stack(r, axis=-1) for r in rows], axis=-2)


def _frames_agree() -> bool:
    """True when gearrep.frames exists and its rot_x/y/z are the active rotations used here."""
    if _frames_rot_z is None:
        return False
    try:
        a = np.array([0.3, -1.2])
        return all(np.allclose(np.asarray(fn(a), float), _rot(i, a), atol=1e-15)
                   for i, fn in enumerate((_frames_rot_x, _frames_rot_y, _frames_rot_z)))
    except Exception:  # pragma: no cover - a frames module with another signature
        return False


if _frames_agree():  # pragma: no cover - depends on the concurrent gearrep.frames
    rot_x, rot_y, rot_z = _frames_rot_x, _frames_rot_y, _frames_rot_z
else:
    def rot_x(a):
        """Active right-handed rotation about x, (..., 3, 3)."""
        return _rot(0, a)

    def rot_y(a):
        """Active right-handed rotation about y, (..., 3, 3)."""
        return _rot(1, a)

    def rot_z(a):
        """Active right-handed rotation about z, (..., 3, 3)."""
        return _rot(2, a)


def _mv(M, v):
    return np.einsum("...ij,...j->...i", M, v)


def _wrap(x):
    """x - 2 pi round(x / 2 pi): exact when |x| < pi."""
    return x - 2.0 * np.pi * np.round(x / (2.0 * np.pi))


# ----------------------------------------------------------------------------------------------
# pair geometry
# ----------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Misalignment:
    """Assembly errors of member 2 (see module docstring for the frames).

    d_gamma_in : rotation [rad] about y_f, in the plane of the axes (axes intersect)
    d_gamma_out : rotation [rad] about x_f, the centre line (axes cross)
    d_E : centre-distance change; d_H : offset along y_f; d_Z : axial displacement along z_f

    The angular errors pivot about O2 (member 2's axis at mid-face). A pivot at another point Q is
    the same rotation plus the translation (I - R)(Q - O2), i.e. extra d_E, d_H, d_Z. The choice
    matters for helical gears: turning member 2 about y_f through O2 by dg also shifts its pitch
    point axially by about r_p2 dg, which turns its helix by dg tan(beta) (a constant TE offset of
    ~45 arcsec for dg = 0.05 deg, beta = 14 deg) that a pivot at the pitch point would not produce.
    """

    d_gamma_in: float = 0.0
    d_gamma_out: float = 0.0
    d_E: float = 0.0
    d_H: float = 0.0
    d_Z: float = 0.0

    def __post_init__(self):
        for n in ("d_gamma_in", "d_gamma_out", "d_E", "d_H", "d_Z"):
            v = getattr(self, n)
            if not np.isfinite(float(v)):
                raise ValueError(f"{n} must be finite, got {v!r}")
        for n in ("d_gamma_in", "d_gamma_out"):
            if abs(getattr(self, n)) >= 0.5:
                raise ValueError(f"{n} must be a small angle, |{n}| < 0.5 rad, got {getattr(self, n)!r}")


def _bounds(surface):
    lo = getattr(surface, "lower", None)
    hi = getattr(surface, "upper", None)
    lo = np.full(2, -np.inf) if lo is None else np.asarray(lo, float)
    hi = np.full(2, np.inf) if hi is None else np.asarray(hi, float)
    return lo, hi


class GearPair:
    """Two tooth surfaces mounted on their axes (frames in the module docstring).

    Parameters
    ----------
    flank1, flank2 : surfaces (``gearrep.surface.Surface``); optional attributes ``lower``,
        ``upper`` (flank domain) and ``outward_sign``; the reduced formulation needs
        ``flank2.cylindrical`` (u = radius, v = axial coordinate)
    n1, n2 : numbers of teeth (ratio N1/N2 in the TE, angular pitches 2 pi / N)
    centre_distance : a > 0 (shortest distance between the axes when aligned)
    misalignment : :class:`Misalignment` or None
    shaft_angle : nominal angle between the axes about x_f [rad], 0 for parallel axes
    phase2 : fixed turn of member 2 in its frame; default pi - side pi / n2 (see module docstring)
    """

    def __init__(self, flank1, flank2, n1: int, n2: int, centre_distance: float, *, misalignment=None,
                 shaft_angle: float = 0.0, phase2=None):
        for name, n in (("n1", n1), ("n2", n2)):
            if int(n) != n or n < 1:
                raise ValueError(f"{name} must be a positive integer, got {n!r}")
        a = float(centre_distance)
        if not (np.isfinite(a) and a > 0):
            raise ValueError(f"centre_distance must be > 0, got {centre_distance!r}")
        if not np.isfinite(float(shaft_angle)) or abs(shaft_angle) > np.pi:
            raise ValueError(f"shaft_angle must be in [-pi, pi] rad, got {shaft_angle!r}")
        mis = Misalignment() if misalignment is None else misalignment
        if not isinstance(mis, Misalignment):
            raise ValueError("misalignment must be a Misalignment or None")
        self.flank1, self.flank2 = flank1, flank2
        self.n1, self.n2 = int(n1), int(n2)
        self.ratio = self.n1 / self.n2
        self.centre_distance = a
        self.misalignment = mis
        self.shaft_angle = float(shaft_angle)
        if phase2 is None:
            side = getattr(flank1, "side", 1)
            phase2 = np.pi - side * np.pi / self.n2
        self.phase2 = float(phase2)
        self.A2 = rot_y(mis.d_gamma_in) @ rot_x(self.shaft_angle + mis.d_gamma_out)
        self.O2 = np.array([a + mis.d_E, mis.d_H, mis.d_Z])
        self.w2 = -self.A2[:, 2]  # axis of positive phi2
        self._Q = rot_z(-self.phase2) @ self.A2.T  # S_f (relative to O2) -> member-2 axis frame
        self.sign1 = int(getattr(flank1, "outward_sign", 1))
        self.sign2 = int(getattr(flank2, "outward_sign", 1))
        self.lower1, self.upper1 = _bounds(flank1)
        self.lower2, self.upper2 = _bounds(flank2)

    def with_misalignment(self, misalignment) -> "GearPair":
        """Same pair with another misalignment."""
        return GearPair(self.flank1, self.flank2, self.n1, self.n2, self.centre_distance,
                        misalignment=misalignment, shaft_angle=self.shaft_angle, phase2=self.phase2)

    def R1(self, phi1):
        """Rotation of member 1, Rz(phi1)."""
        return rot_z(phi1)

    def R2(self, phi2):
        """Rotation of member 2, A2 Rz(phase2 - phi2)."""
        return self.A2 @ rot_z(self.phase2 - np.asarray(phi2, float))

    def member1(self, u1, v1, phi1):
        """Position and outward unit normal of member 1 in S_f."""
        P = self.flank1.evaluate(u1, v1)
        R = self.R1(phi1)
        return _mv(R, P.r), self.sign1 * _mv(R, P.normal)

    def member2(self, u2, v2, phi2):
        """Position and outward unit normal of member 2 in S_f."""
        P = self.flank2.evaluate(u2, v2)
        R = self.R2(phi2)
        return self.O2 + _mv(R, P.r), self.sign2 * _mv(R, P.normal)


def transmission_error(phi1, phi2, n1, n2, phi10=0.0, phi20=0.0):
    """Transmission error (thesis eq 14), radians: (phi2 - phi20) - (N1/N2)(phi1 - phi10).

    phi2 must be measured in the driven sense (see module docstring); TE > 0: member 2 leads.
    """
    for name, n in (("n1", n1), ("n2", n2)):
        if not (np.isfinite(n) and n > 0):
            raise ValueError(f"{name} must be > 0, got {n!r}")
    phi1 = np.asarray(phi1, float)
    phi2 = np.asarray(phi2, float)
    return (phi2 - phi20) - (n1 / n2) * (phi1 - phi10)


# ----------------------------------------------------------------------------------------------
# contact record
# ----------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class ContactPoints:
    """Contact points of a batch of solves (all arrays of length n; position/normal (n, 3)).

    u1, v1, u2, v2 : surface parameters of members 1 and 2
    phi1, phi2 : rotation angles [rad]
    position : contact point in S_f; normal : outward unit normal of member 1 in S_f
    te : transmission error [rad] (eq 14 with the pair's nominal reference); ``te_arcsec``
    residual, iterations, status : from :func:`gearrep.solve.newton`, with OFF_FLANK (member-2
        parameters outside its flank, reduced form) and WRONG_ROOT (normals not opposite) added
    formulation : "reduced" or "conventional"
    condition : condition number of the Newton Jacobian at the last iteration (see
        :class:`gearrep.solve.SolveResult`); None when the points were not built by a solve
    """

    u1: np.ndarray
    v1: np.ndarray
    u2: np.ndarray
    v2: np.ndarray
    phi1: np.ndarray
    phi2: np.ndarray
    position: np.ndarray
    normal: np.ndarray
    te: np.ndarray
    residual: np.ndarray
    iterations: np.ndarray
    status: np.ndarray
    formulation: str = "reduced"
    condition: np.ndarray | None = None

    def __len__(self):
        return len(self.status)

    @property
    def te_arcsec(self) -> np.ndarray:
        return self.te / ARCSEC

    @property
    def converged(self) -> np.ndarray:
        return self.status == Status.CONVERGED

    @property
    def status_name(self) -> np.ndarray:
        return status_names(self.status)

    def take(self, idx) -> "ContactPoints":
        """Subset by index or boolean mask."""
        kw = {f: getattr(self, f)[idx] for f in ("u1", "v1", "u2", "v2", "phi1", "phi2", "position", "normal",
                                                   "te", "residual", "iterations", "status")}
        cond = None if self.condition is None else self.condition[idx]
        return ContactPoints(formulation=self.formulation, condition=cond, **kw)

    @staticmethod
    def concatenate(items) -> "ContactPoints":
        items = list(items)
        kw = {f: np.concatenate([getattr(c, f) for c in items]) for f in
              ("u1", "v1", "u2", "v2", "phi1", "phi2", "position", "normal", "te", "residual", "iterations", "status")}
        conds = [c.condition for c in items]
        cond = None if any(c is None for c in conds) else np.concatenate(conds)
        return ContactPoints(formulation=items[0].formulation, condition=cond, **kw)

    def unknowns(self, formulation=None) -> np.ndarray:
        """Solution as a start array: (u1, v1) for reduced, (u1, v1, u2, v2, phi2) for conventional."""
        f = formulation or self.formulation
        if f == "reduced":
            return np.stack([self.u1, self.v1], axis=-1)
        return np.stack([self.u1, self.v1, self.u2, self.v2, self.phi2], axis=-1)


# ----------------------------------------------------------------------------------------------
# geometry kernels with analytic derivatives
# ----------------------------------------------------------------------------------------------
def normal_derivatives(P, sign):
    """Unit normal sign * (r_u x r_v)/|.| of a :class:`~gearrep.surface.SurfacePoint` and its u- and
    v-derivatives (n_u = (N_u - n (n . N_u))/|N|, likewise n_v)."""
    N = cross(P.r_u, P.r_v)
    L = np.linalg.norm(N, axis=-1, keepdims=True)
    n = N / L
    dNu = cross(P.r_uu, P.r_v) + cross(P.r_u, P.r_uv)
    dNv = cross(P.r_uv, P.r_v) + cross(P.r_u, P.r_vv)
    dnu = (dNu - n * np.sum(n * dNu, axis=-1, keepdims=True)) / L
    dnv = (dNv - n * np.sum(n * dNv, axis=-1, keepdims=True)) / L
    return sign * n, sign * dnu, sign * dnv


def _reduced_kernel(pair: GearPair, u1, v1, phi1, *, derivs=True):
    """Explicit back-substitution of the reduced formulation (eq 37-44) and derivatives w.r.t. (u1, v1).

    Returns a dict with u2, v2, phi2, r (contact point), n1, n2 (outward normals in S_f) and, with
    ``derivs``, their derivatives d_* of shape (n, 2[, 3]) w.r.t. (u1, v1).
    """
    P1 = pair.flank1.evaluate(u1, v1)
    R1 = pair.R1(phi1)
    r = _mv(R1, P1.r)
    n1l, dn1u, dn1v = normal_derivatives(P1, pair.sign1)
    n1 = _mv(R1, n1l)
    s = _mv(pair._Q, r - pair.O2)  # member-2 axis frame, before Rz(-phi2)
    v2 = s[..., 2]
    rho2 = s[..., 0] ** 2 + s[..., 1] ** 2
    u2 = np.sqrt(rho2)
    th = np.arctan2(s[..., 1], s[..., 0])
    with np.errstate(invalid="ignore", divide="ignore"):
        P2 = pair.flank2.evaluate(u2, v2)
    ang2 = np.arctan2(P2.r[..., 1], P2.r[..., 0])
    ref = pair.ratio * np.asarray(phi1, float)
    phi2 = ref + _wrap(ang2 - th - ref)
    R2 = pair.R2(phi2)
    with np.errstate(invalid="ignore", divide="ignore"):
        n2l, dn2u, dn2v = normal_derivatives(P2, pair.sign2)
    n2 = _mv(R2, n2l)
    out = dict(u2=u2, v2=v2, phi2=phi2, r=r, n1=n1, n2=n2, P1=P1, P2=P2)
    if not derivs:
        return out
    # derivatives with respect to (u1, v1): stack directions on axis -2
    dr = _mv(R1[..., None, :, :], np.stack([P1.r_u, P1.r_v], axis=-2))  # (n,2,3)
    dn1 = _mv(R1[..., None, :, :], np.stack([dn1u, dn1v], axis=-2))
    ds = _mv(pair._Q, dr)
    sx, sy = s[..., 0, None], s[..., 1, None]
    with np.errstate(invalid="ignore", divide="ignore"):
        du2 = (sx * ds[..., 0] + sy * ds[..., 1]) / u2[..., None]
        dth = (sx * ds[..., 1] - sy * ds[..., 0]) / rho2[..., None]
        dv2 = ds[..., 2]
        r2 = P2.r
        q2 = r2[..., 0] ** 2 + r2[..., 1] ** 2
        ang_u = (r2[..., 0] * P2.r_u[..., 1] - r2[..., 1] * P2.r_u[..., 0]) / q2
        ang_v = (r2[..., 0] * P2.r_v[..., 1] - r2[..., 1] * P2.r_v[..., 0]) / q2
        dphi2 = ang_u[..., None] * du2 + ang_v[..., None] * dv2 - dth
        dn2l = dn2u[..., None, :] * du2[..., None] + dn2v[..., None, :] * dv2[..., None]
        dn2 = _mv(R2[..., None, :, :], dn2l) + cross(pair.w2, n2)[..., None, :] * dphi2[..., None]
    out.update(dr=dr, dn1=dn1, du2=du2, dv2=dv2, dphi2=dphi2, dn2=dn2)
    return out


def _keep(vec, drop):
    """Two components of (..., 3) ``vec`` (or (..., k, 3)) other than ``drop`` (per row)."""
    drop = np.asarray(drop).astype(int)
    idx = np.array([[1, 2], [0, 2], [0, 1]])[drop]  # (n, 2)
    if vec.ndim == 2:
        return np.take_along_axis(vec, idx, axis=-1)
    return np.take_along_axis(vec, idx[:, None, :], axis=-1)


def _reduced_FJ(pair, u1, v1, phi1, drop, derivs=True):
    K = _reduced_kernel(pair, u1, v1, phi1, derivs=derivs)
    c = cross(K["n1"], K["n2"])
    F = _keep(c, drop)
    if not derivs:
        return F, None, K
    dc = cross(K["dn1"], K["n2"][..., None, :]) + cross(K["n1"][..., None, :], K["dn2"])  # (n,2,3)
    J = np.swapaxes(_keep(dc, drop), -1, -2)  # (n, 2 eq, 2 unknowns)
    return F, J, K


def _conventional_FJ(pair, x, phi1, drop, derivs=True):
    u1, v1, u2, v2, phi2 = (x[:, i] for i in range(5))
    P1 = pair.flank1.evaluate(u1, v1)
    R1 = pair.R1(phi1)
    with np.errstate(invalid="ignore", divide="ignore"):
        P2 = pair.flank2.evaluate(u2, v2)
        n2l, dn2u, dn2v = normal_derivatives(P2, pair.sign2)
    n1l, dn1u, dn1v = normal_derivatives(P1, pair.sign1)
    R2 = pair.R2(phi2)
    r1 = _mv(R1, P1.r)
    rel2 = _mv(R2, P2.r)
    r2 = pair.O2 + rel2
    n1 = _mv(R1, n1l)
    n2 = _mv(R2, n2l)
    F = np.concatenate([r1 - r2, _keep(n1 + n2, drop)], axis=-1)
    if not derivs:
        return F, None
    cols_r = [_mv(R1, P1.r_u), _mv(R1, P1.r_v), -_mv(R2, P2.r_u), -_mv(R2, P2.r_v), -cross(pair.w2, rel2)]
    cols_n = [_mv(R1, dn1u), _mv(R1, dn1v), _mv(R2, dn2u), _mv(R2, dn2v), cross(pair.w2, n2)]
    Jr = np.stack(cols_r, axis=-1)  # (n,3,5)
    Jn = np.stack(cols_n, axis=-2)  # (n,5,3)
    J = np.concatenate([Jr, np.swapaxes(_keep(Jn, drop), -1, -2)], axis=-2)
    return F, J


# ----------------------------------------------------------------------------------------------
# newton with frozen per-row parameters
# ----------------------------------------------------------------------------------------------
def newton_rows(F, FJ, x0, params, *, lower=None, upper=None, jacobian="analytic", tol=1e-12, maxiter=50,
                damped=True) -> SolveResult:
    """:func:`gearrep.solve.newton` for problems with per-row data ``params`` (n, q).

    ``F(x, p) -> (n, m)``; ``FJ(x, p) -> (F, J)`` with J (n, m, k) (analytic; ignored when
    ``jacobian="numeric"``, which differentiates F by central differences). Each row's
    parameters follow it through the solve (``newton(..., rows=True)``).
    """
    x0 = np.atleast_2d(np.asarray(x0, float))
    params = np.atleast_2d(np.asarray(params, float))
    n = x0.shape[0]
    if params.shape[0] != n:
        raise ValueError(f"params has {params.shape[0]} rows for {n} starts")
    if jacobian not in ("analytic", "numeric"):
        raise ValueError(f"jacobian must be 'analytic' or 'numeric', got {jacobian!r}")

    def fun(x, idx):
        return F(x, params[idx])

    def jac(x, idx):
        return FJ(x, params[idx])[1]

    return newton(fun, x0, jac if jacobian == "analytic" else None, tol=tol, maxiter=maxiter, damped=damped,
                  lower=lower, upper=upper, rows=True)


# ----------------------------------------------------------------------------------------------
# public solves
# ----------------------------------------------------------------------------------------------
def _prep(phi1, start, width):
    start = np.atleast_2d(np.asarray(start, dtype=float))
    phi1 = np.atleast_1d(np.asarray(phi1, dtype=float))
    if start.shape[-1] != width:
        raise ValueError(f"start must have {width} columns, got shape {start.shape}")
    n = max(len(phi1), len(start))
    if len(phi1) not in (1, n) or len(start) not in (1, n):
        raise ValueError(f"phi1 ({len(phi1)}) and start ({len(start)}) must have equal length or length 1")
    if not np.all(np.isfinite(phi1)):
        raise ValueError("phi1 must be finite")
    return np.broadcast_to(phi1, (n,)).copy(), np.broadcast_to(start, (n, width)).copy()


def default_start(pair: GearPair, phi1, formulation: str = "reduced") -> np.ndarray:
    """Starting point at the middle of the flanks, phi2 = (N1/N2) phi1 (the thesis's choice of u2, v2)."""
    phi1 = np.atleast_1d(np.asarray(phi1, float))
    mid1 = np.where(np.isfinite(pair.lower1 + pair.upper1), 0.5 * (pair.lower1 + pair.upper1), 0.0)
    if formulation == "reduced":
        return np.tile(mid1, (len(phi1), 1))
    mid2 = np.where(np.isfinite(pair.lower2 + pair.upper2), 0.5 * (pair.lower2 + pair.upper2), 0.0)
    return np.column_stack([np.tile(mid1, (len(phi1), 1)), np.tile(mid2, (len(phi1), 1)), pair.ratio * phi1])


def solve_contact(pair: GearPair, phi1, start=None, *, formulation: str = "reduced", v1=None,
                  jacobian: str = "analytic", tol: float = 1e-12, maxiter: int = 50, damped: bool = True,
                  phi10: float = 0.0, phi20: float = 0.0, drop=None) -> ContactPoints:
    """Contact points of ``pair`` at member-1 angles ``phi1`` (vectorised over starts and angles).

    Parameters
    ----------
    phi1 : (n,) or scalar, rad
    start : (n, 2) (u1, v1) for ``formulation="reduced"`` (eq 33-44) or (n, 5) (u1, v1, u2, v2, phi2)
        for ``"conventional"`` (eq 26-32); default :func:`default_start`
    v1 : None (point contact: v1 unknown) or scalar/(n,) fixed face-width coordinate of member 1
        (line contact; the v1 column of ``start`` is then ignored)
    jacobian : "analytic" or "numeric" (central differences)
    tol, maxiter, damped : passed to :func:`gearrep.solve.newton`
    phi10, phi20 : TE reference (eq 14)
    drop : None (default: the component j = argmax |n_f1,j| at the start, per row) or 0, 1, 2 - the
        component of n_f1 + n_f2 (conventional) or n_f1 x n_f2 (reduced) left out of the system.
        Other choices than the default can make the Jacobian singular (see module docstring).

    Returns
    -------
    ContactPoints; status CONVERGED only for a verified root inside both flanks.
    """
    if formulation not in ("reduced", "conventional"):
        raise ValueError(f"formulation must be 'reduced' or 'conventional', got {formulation!r}")
    width = 2 if formulation == "reduced" else 5
    if start is None:
        start = default_start(pair, phi1, formulation)
    phi1, start = _prep(phi1, start, width)
    n = len(phi1)
    fixed = v1 is not None
    if fixed:
        v1a = np.broadcast_to(np.asarray(v1, float), (n,)).copy()
        if not np.all(np.isfinite(v1a)):
            raise ValueError("v1 must be finite")
        start[:, 1] = v1a
    if formulation == "reduced" and not getattr(pair.flank2, "cylindrical", False):
        raise ValueError("the reduced formulation needs flank2 in cylindrical form (flank2.cylindrical = True)")

    # dropped normal component: the largest of member 1's normal at the start
    if drop is None:
        _, n1s = pair.member1(start[:, 0], start[:, 1], phi1)
        with np.errstate(invalid="ignore"):
            drop = np.argmax(np.nan_to_num(np.abs(n1s), nan=0.0), axis=-1).astype(float)
    else:
        if drop not in (0, 1, 2):
            raise ValueError(f"drop must be None or one of 0, 1, 2, got {drop!r}")
        drop = np.full(n, float(drop))

    free = [0] if (fixed and formulation == "reduced") else ([0, 1] if formulation == "reduced" else
                                                             ([0, 2, 3, 4] if fixed else [0, 1, 2, 3, 4]))
    lo_all = np.concatenate([pair.lower1, pair.lower2, [-np.inf]])
    hi_all = np.concatenate([pair.upper1, pair.upper2, [np.inf]])

    def expand(x, p):
        full = np.empty((x.shape[0], width))
        full[:, free] = x
        if fixed:
            full[:, 1] = p[:, 2]
        return full

    if formulation == "reduced":
        def FJ(x, p):
            full = expand(x, p)
            Fv, J, _ = _reduced_FJ(pair, full[:, 0], full[:, 1], p[:, 0], p[:, 1])
            return Fv, J[:, :, free]

        def Fonly(x, p):
            full = expand(x, p)
            return _reduced_FJ(pair, full[:, 0], full[:, 1], p[:, 0], p[:, 1], derivs=False)[0]
    else:
        def FJ(x, p):
            Fv, J = _conventional_FJ(pair, expand(x, p), p[:, 0], p[:, 1])
            return Fv, J[:, :, free]

        def Fonly(x, p):
            return _conventional_FJ(pair, expand(x, p), p[:, 0], p[:, 1], derivs=False)[0]

    params = np.column_stack([phi1, drop] + ([start[:, 1]] if fixed else []))
    res = newton_rows(Fonly, FJ, start[:, free], params, lower=lo_all[free], upper=hi_all[free], jacobian=jacobian,
                      tol=tol, maxiter=maxiter, damped=damped)
    sol = expand(res.x, params)
    return _finish(pair, formulation, sol, phi1, res, phi10, phi20)


def _finish(pair, formulation, sol, phi1, res, phi10, phi20) -> ContactPoints:
    status = res.status.copy()
    u1, v1 = sol[:, 0], sol[:, 1]
    with np.errstate(invalid="ignore", divide="ignore"):
        if formulation == "reduced":
            K = _reduced_kernel(pair, u1, v1, phi1, derivs=False)
            u2, v2, phi2, r, n1, n2 = K["u2"], K["v2"], K["phi2"], K["r"], K["n1"], K["n2"]
        else:
            u2, v2, phi2 = sol[:, 2], sol[:, 3], sol[:, 4]
            ref = pair.ratio * phi1
            phi2 = ref + _wrap(phi2 - ref)
            r, n1 = pair.member1(u1, v1, phi1)
            r2, n2 = pair.member2(u2, v2, phi2)
        opposite = np.sum(n1 * n2, axis=-1) < 0
        if formulation == "conventional":
            opposite &= np.linalg.norm(n1 + n2, axis=-1) < 1e-6
    solved = (status == Status.CONVERGED) | (status == Status.OFF_FLANK)
    status[solved & ~opposite] = int(Status.WRONG_ROOT)
    tol2 = 1e-12 * (1 + np.abs(np.concatenate([pair.lower2, pair.upper2])))
    inside2 = ((u2 >= pair.lower2[0] - tol2[0]) & (u2 <= pair.upper2[0] + tol2[2])
               & (v2 >= pair.lower2[1] - tol2[1]) & (v2 <= pair.upper2[1] + tol2[3]))
    status[(status == Status.CONVERGED) & ~inside2] = int(Status.OFF_FLANK)
    te = transmission_error(phi1, phi2, pair.n1, pair.n2, phi10, phi20)
    return ContactPoints(u1=u1, v1=v1, u2=u2, v2=v2, phi1=phi1, phi2=phi2, position=r, normal=n1, te=te,
                         residual=res.residual, iterations=res.iterations, status=status, formulation=formulation,
                         condition=res.condition)


def reduced_unknowns(pair: GearPair, u1, v1, phi1):
    """(u2, v2, phi2) from (u1, v1, phi1) by the explicit relations of the reduced formulation (eq 39-44)."""
    u1, v1, phi1 = np.broadcast_arrays(*(np.asarray(a, float) for a in (u1, v1, phi1)))
    shape = u1.shape
    K = _reduced_kernel(pair, u1.ravel(), v1.ravel(), phi1.ravel(), derivs=False)
    return K["u2"].reshape(shape), K["v2"].reshape(shape), K["phi2"].reshape(shape)


def trace_path(pair: GearPair, phi1, start=None, *, formulation: str = "reduced", v1=None,
               jacobian: str = "analytic", tol: float = 1e-12, maxiter: int = 50, phi10: float = 0.0,
               phi20: float = 0.0, predictor: bool = True) -> ContactPoints:
    """Path of contact over the angles ``phi1`` (in order) by continuation (Litvin & Fuentes ch. 9).

    Each position starts from the previous converged solution (linearly extrapolated from the last
    two when ``predictor``); ``start`` (one row, as for :func:`solve_contact`) is used for the first
    position. A failed position does not seed the next one. Returns ContactPoints in the order
    of ``phi1``.
    """
    phi1 = np.atleast_1d(np.asarray(phi1, float))
    if phi1.ndim != 1 or len(phi1) < 1:
        raise ValueError("phi1 must be a non-empty 1-D array")
    width = 2 if formulation == "reduced" else 5
    x = default_start(pair, phi1[:1], formulation)[0] if start is None else np.asarray(start, float).reshape(-1)
    if x.shape != (width,):
        raise ValueError(f"start must have {width} entries, got shape {x.shape}")
    v1a = None if v1 is None else np.broadcast_to(np.asarray(v1, float), phi1.shape)
    out, hist = [], []  # hist: (phi1, solution) of converged points
    for i, p in enumerate(phi1):
        guess = x
        if predictor and len(hist) >= 2 and hist[-1][0] != hist[-2][0]:
            (pa, xa), (pb, xb) = hist[-2], hist[-1]
            guess = xb + (xb - xa) * (p - pb) / (pb - pa)
        elif hist:
            guess = hist[-1][1]
        c = solve_contact(pair, p, guess[None, :], formulation=formulation,
                          v1=None if v1a is None else v1a[i], jacobian=jacobian, tol=tol, maxiter=maxiter,
                          phi10=phi10, phi20=phi20)
        if c.status[0] != Status.CONVERGED and len(hist) >= 1 and predictor:
            c2 = solve_contact(pair, p, hist[-1][1][None, :], formulation=formulation,
                               v1=None if v1a is None else v1a[i], jacobian=jacobian, tol=tol, maxiter=maxiter,
                               phi10=phi10, phi20=phi20)
            if c2.status[0] == Status.CONVERGED:
                c = c2
        out.append(c)
        if c.status[0] == Status.CONVERGED:
            hist.append((p, c.unknowns(formulation)[0]))
    return ContactPoints.concatenate(out)


# ----------------------------------------------------------------------------------------------
# curvatures and contact ellipse at solved contact points
# ----------------------------------------------------------------------------------------------
def _fixed_frame_point(flank, u, v, R, origin=None):
    from .surface import SurfacePoint

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
    CONVERGED are NaN. Returns (PrincipalCurvatures of member 1, of member 2)."""
    from .curvature import principal_curvatures, with_opposite_normal

    ok = contact.converged
    idx = np.flatnonzero(ok)
    nan = np.full(len(contact), np.nan)
    nan3 = np.full((len(contact), 3), np.nan)
    out = []
    for flank, u, v, R, sign, origin, flip in (
            (pair.flank1, contact.u1, contact.v1, pair.R1(contact.phi1), pair.sign1, None, False),
            (pair.flank2, contact.u2, contact.v2, pair.R2(contact.phi2), pair.sign2, pair.O2, True)):
        pc = principal_curvatures(_fixed_frame_point(flank, u[idx], v[idx], R[idx], origin))
        # r_u x r_v -> outward normal of the member, then member 2 seen with member 1's normal
        if (sign < 0) != flip:
            pc = with_opposite_normal(pc)
        full = [nan.copy(), nan.copy(), nan3.copy(), nan3.copy(), nan3.copy()]
        for f, x in zip(full, pc):
            f[idx] = x
        out.append(type(pc)(*full))
    return out[0], out[1]


def contact_ellipse(pair: GearPair, contact: ContactPoints, delta):
    """Litvin's elastic-approach contact ellipse at the contact points (seed 002 eq 2.6.1-2.6.6 =
    seed 000 eq 5.14-5.17 = seed 004 eq 21-26) for an elastic approach ``delta`` (length unit of
    the design data): semi-axes a >= b, area, major/minor axis unit vectors in S_f. Rows whose
    status is not CONVERGED are NaN; a contact whose relative curvature is not definite (line
    contact) has ``elliptic`` False."""
    from .ellipse import elastic_ellipse_at

    c1, c2 = contact_curvatures(pair, contact)
    ok = contact.converged
    el = elastic_ellipse_at(type(c1)(*(x[ok] for x in c1)), type(c2)(*(x[ok] for x in c2)), delta)
    full = []
    for x in el:
        x = np.asarray(x)
        f = np.full((len(contact),) + x.shape[1:], np.nan if x.dtype != bool else False, dtype=x.dtype)
        f[ok] = x
        full.append(f)
    return type(el)(*full)
