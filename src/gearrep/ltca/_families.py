"""The tooth-surface families the loaded analysis supports, and what it reads from each.

The loaded analysis needs, for each member of a pair, more than the flank surface the unloaded TCA
uses: the boundary of the active flank (tip circle, lowest point of the working profile, face ends)
to find edge contact, the tooth's transverse section (its thickness along the tooth centre line,
read from the flank's own geometry) for the tooth compliance, and a start of the section-contact
solve. A :class:`Member` holds them; :func:`members` builds both of a pair or refuses it.

Supported (:data:`SUPPORTED`):

* **involute** spur and helical flanks (:class:`gearrep.surfaces.involute.InvoluteFlank`), crowned,
  relieved or not, aligned or misaligned: the transverse section is that of mid-face (the same in
  every section up to the helix twist; the small thinning of the tooth by crowning or relief is not
  counted in its compliance), the tooth symmetric about its centre line, its root fillet generated
  by the basic rack's tip radius (:func:`rack_fillet_half_angle`);
* **CATT** flanks (:class:`gearrep.surfaces.catt.CATTFlank`, as mounted by
  :func:`gearrep.surfaces.catt.assemble`): the transverse section of every face position between
  the convex and the concave flank of the same tooth (the tooth thickness changes along the face,
  seed 004 Fig 14), tabulated over the face and interpolated.

Refused with a ValueError naming the family and why (:func:`members`): spherical-involute bevel
flanks (the tooth section of a bevel gear lies on the back cone and its thickness shrinks toward
the apex, which the transverse thin-slice beam of :mod:`._compliance` does not describe), the
Novikov-Wildhaber rack-generated and worm/disk-generated flanks and the hob-generated curvilinear
flanks (their tooth section is only available through a numerical envelope whose other flank, the
one bounding the tooth, is not modelled). Their unloaded TCA is in :mod:`gearrep.tca`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..surface import RotatedSurface
from ..surfaces.catt import CATTFlank
from ..surfaces.involute import InvoluteFlank

__all__ = [
    "SUPPORTED",
    "refusal",
    "Member",
    "members",
    "member_of",
    "base_flank",
    "section_starts",
    "pitch_phi1",
    "RACK_TIP_RADIUS",
    "rack_fillet_half_angle",
]

#: families with a loaded analysis: family name -> flank class (module path)
SUPPORTED = {
    "involute": "gearrep.surfaces.involute.InvoluteFlank",
    "catt": "gearrep.surfaces.catt.CATTFlank",
}

_REFUSED = {
    "SphericalInvoluteFlank": "bevel flanks: the tooth section lies on the back cone and thins toward the apex, "
    "which the transverse thin-slice tooth model does not describe",
    "RackGeneratedFlank": "Novikov-Wildhaber flanks: the tooth section (both flanks of one tooth) is not modelled",
    "DiskGroundPinion": "disk-ground Novikov pinions: the tooth section is only known through a numerical envelope",
    "WormGeneratedPinion": "worm-generated Novikov pinions: the tooth section is only known through a numerical envelope",
    "GeneratedGear": "hob-generated flanks: the tooth section is only known through a numerical envelope",
}


def base_flank(flank):
    """The flank in its own gear frame: a :class:`gearrep.surface.RotatedSurface` unwrapped (its
    rotation Q and translation t returned too; identity for a bare flank)."""
    if isinstance(flank, RotatedSurface):
        return flank.surface, flank.Q, flank.t
    return flank, np.eye(3), np.zeros(3)


def _supported(flank) -> bool:
    base, _, _ = base_flank(flank)
    return (isinstance(base, InvoluteFlank) and base is flank) or isinstance(base, CATTFlank)


def refusal(flank) -> str:
    """Why the loaded analysis refuses ``flank`` (a mounted flank, or the surface of a generated
    member): its class and the reason, one line; "" for a flank of a :data:`SUPPORTED` family.

    Parameters
    ----------
    flank : gearrep.surface.Surface
        A flank as mounted in a pair, or a member's surface.

    Returns
    -------
    str
        The refusal (class name and reason), or "" where the loaded analysis supports the flank.

    Examples
    --------
    >>> import math
    >>> from gearrep.ltca import refusal
    >>> from gearrep.surfaces.bevel import BevelGearData, SphericalInvoluteFlank
    >>> from gearrep.surfaces.involute import InvoluteFlank, InvoluteGearData
    >>> refusal(InvoluteFlank(InvoluteGearData(20, 2.0, math.radians(20), 20.0), 1, 1))  # module mm, rad, face mm
    ''
    >>> refusal(SphericalInvoluteFlank(BevelGearData(17, 17, 1.0, math.radians(20), 4.0), 1)).split(" (")[0]
    'SphericalInvoluteFlank'
    """
    if _supported(flank):
        return ""
    base, _, _ = base_flank(flank)
    kind = type(base).__name__
    return f"{kind} ({_REFUSED.get(kind, 'no tooth section is defined for it')})"


def _refuse(flank, name: str):
    raise ValueError(
        f"{name}: gearrep.ltca supports the families {sorted(SUPPORTED)} ({', '.join(SUPPORTED.values())}); "
        f"got {refusal(flank)}"
    )


@dataclass(frozen=True)
class Member:
    """What the loaded analysis reads from one member's flank (lengths mm, angles rad).

    flank : the flank as mounted in the pair; base : the flank in its gear frame; Q, t : the
    mounting (member-frame point = Q base point + t); family : a key of :data:`SUPPORTED`;
    r_tip : tip radius; r_form : lowest radius of the working profile; r_root : root radius;
    z_lo, z_hi : face ends along the member's axis (member frame); sections : z positions [mm]
    (base frame) of the tabulated transverse sections (one for a section that does not change
    along the face); r_table : radii of the tables; half_angle : (n_sections, n_r) tooth half
    angle; centre : (n_sections,) polar angle of the tooth centre line (base frame);
    twist : for a section the same along the face, the polar angle [rad] of its centre line at z
        (the helix twist), a function of z; None: constant
    """

    flank: object
    base: object
    Q: np.ndarray
    t: np.ndarray
    family: str
    r_tip: float
    r_form: float
    r_root: float
    z_lo: float
    z_hi: float
    sections: np.ndarray
    r_table: np.ndarray
    half_angle: np.ndarray
    centre: np.ndarray
    twist: object = None

    @property
    def z_independent(self) -> bool:
        return self.sections.size == 1

    def section_at(self, z_base):
        """(half-angle tables (n, n_r), centre angles (n,)) at base-frame axial positions ``z_base``
        (linear interpolation between the tabulated sections)."""
        z = np.asarray(z_base, dtype=float)
        if self.z_independent:  # the same section, turned by the helix (twist) along the face
            centre = self.centre[0] + (0.0 if self.twist is None else self.twist(z))
            return np.broadcast_to(self.half_angle[0], z.shape + self.r_table.shape), np.broadcast_to(centre, z.shape)
        zs = self.sections
        j = np.clip(np.searchsorted(zs, z) - 1, 0, zs.size - 2)
        f = np.clip((z - zs[j]) / (zs[j + 1] - zs[j]), 0.0, 1.0)
        ha = (1.0 - f)[..., None] * self.half_angle[j] + f[..., None] * self.half_angle[j + 1]
        return ha, (1.0 - f) * self.centre[j] + f * self.centre[j + 1]

    def to_base(self, p, n=None):
        """Member-frame points ``p`` (and vectors ``n``) in the base (gear) frame."""
        pb = np.einsum("ji,...j->...i", self.Q, np.asarray(p) - self.t)
        if n is None:
            return pb
        return pb, np.einsum("ji,...j->...i", self.Q, np.asarray(n))

    def radius(self, p_member):
        return np.hypot(p_member[..., 0], p_member[..., 1])

    def inside(self, u, v, margin: float):
        """True where (u, v) lies on the working flank at least ``margin`` (a fraction of the
        profile span and of the face width) from every boundary."""
        with np.errstate(invalid="ignore"):
            p = self.flank.position(u, v)
            r = self.radius(p)
            dr, dz = margin * (self.r_tip - self.r_form), margin * (self.z_hi - self.z_lo)
            return (
                (r >= self.r_form + dr)
                & (r <= self.r_tip - dr)
                & (p[..., 2] >= self.z_lo + dz)
                & (p[..., 2] <= self.z_hi - dz)
            )

    def contains(self, u, v, tol: float = 1e-9):
        """True where (u, v) is on the working flank: radius in [r_form, r_tip] and the axial
        position within the face ends (slack ``tol`` relative to the tip radius)."""
        p = self.flank.position(u, v)
        r = self.radius(p)
        s = tol * self.r_tip
        return (
            (r >= self.r_form - s) & (r <= self.r_tip + s) & (p[..., 2] >= self.z_lo - s) & (p[..., 2] <= self.z_hi + s)
        )


#: tip radius of the generating basic rack [module]: ISO 53:1998 profile A (rho_fP = 0.38 m_n), the
#: standard basic rack of ISO 6336-1's stiffness fit; capped where the rack tooth is too narrow for it
RACK_TIP_RADIUS = 0.38


def rack_fillet_half_angle(flank, r, rho_module: float = RACK_TIP_RADIUS) -> np.ndarray:
    """Tooth half angle [rad] at radii ``r`` [mm] of an involute flank's transverse section with the
    root fillet generated by the basic rack's tip radius ``rho_module`` (in normal modules).

    The rack rolls on the reference circle (radius r_p, transverse pressure angle alpha_t); its
    tooth fills the gear's tooth space (half width at the rolling line w0 = r_p (pi/z - theta(r_p)),
    theta the flank's own half angle there, so profile shift and thinning are those of the flank),
    its tip line reaches the root circle, and the tip corner is a circle of radius rho tangent to the
    flank line and the tip line. The involute is generated down to the form radius r_Ff, where the
    straight flank meets the tip circle (depth h_c + rho sin(alpha_t) below the rolling line, h_c the
    circle centre's depth); below it the tooth boundary is the envelope of the tip circle (an offset
    trochoid: the point of the circle on the line through its centre and the pitch point, on the far
    side from the pitch point; Litvin & Fuentes, Gear Geometry and Applied Theory, 2nd ed., CUP 2004,
    ch. 6 and 10). Returned: that envelope's half angle below r_Ff and the involute's at and above
    it (the smaller of the two where the envelope cuts into the involute, i.e. undercut). The
    normal-section circle is taken as a circle of the same radius in the transverse section (exact
    for spur gears)."""
    g = flank.gear
    z, r_p, a_t, r_f, r_b = g.n_teeth, float(g.r_p), float(g.alpha_t), float(g.r_f), float(g.r_b)
    zero = np.zeros(1)
    tw = flank.twist(zero)[0]
    theta_p = float(flank.side * (flank.polar_angle(np.array([r_p]), zero) - tw)[0])
    w0 = r_p * (np.pi / z - theta_p)  # rack tooth half width at the rolling line
    depth = r_p - r_f  # rack tip line below the rolling line
    rho_max = (w0 - depth * np.tan(a_t)) / (1.0 / np.cos(a_t) - np.tan(a_t))
    if not rho_max > 0.0:
        raise ValueError(
            f"rack tip radius: the tooth space of {z} teeth leaves no room for a tip circle (rho_max {rho_max!r})"
        )
    rho = min(rho_module * float(g.module), rho_max)
    h_c = depth - rho
    x_c = w0 - h_c * np.tan(a_t) - rho / np.cos(a_t)
    h_t = h_c + rho * np.sin(a_t)  # where the rack's straight flank ends
    s_form = r_p * np.sin(a_t) - h_t / np.sin(a_t)
    r_form = np.sqrt(r_b**2 + s_form**2) if s_form > 0.0 else r_b
    r = np.asarray(r, dtype=float)
    theta_inv = flank.side * (flank.polar_angle(np.maximum(r, flank.u_min), np.zeros_like(r)) - tw)
    # the envelope of the tip circle, gear turned by phi (rack moved by -r_p phi); gear frame: the tooth
    # space centred on +y, the tooth's centre line at angle pi/z toward +x
    phi_max = min(1.0, 12.0 * float(g.module) / r_p)
    phi = np.union1d(np.linspace(-phi_max, phi_max, 8001), [x_c / r_p])  # x_c / r_p: the fillet's bottom
    cx, cy = x_c - r_p * phi, np.full_like(phi, r_p - h_c)
    dx, dy = -cx, r_p - cy
    d = np.hypot(dx, dy)
    fx, fy = cx - rho * dx / d, cy - rho * dy / d
    c, s = np.cos(phi), np.sin(phi)
    x, y = c * fx + s * fy, -s * fx + c * fy
    rad_all, th_all = np.hypot(x, y), np.pi / z - np.arctan2(x, y)
    k = int(np.searchsorted(phi, x_c / r_p))  # the bottom, on the root circle; a branch each way up
    best = np.full(r.shape, np.inf)
    for rad, th in ((rad_all[k:], th_all[k:]), (rad_all[k::-1], th_all[k::-1])):
        grows = np.concatenate([[True], np.diff(rad) > 0.0])
        n = rad.size if np.all(grows) else int(np.argmin(grows))
        rad, th = rad[:n], th[:n]
        if rad.size > 1:
            on = r <= rad[-1]  # below rad[0] (the root radius up to the sampling) its bottom angle
            best = np.where(on, np.minimum(best, np.interp(r, rad, th)), best)
    below = r < r_form
    if np.any(below & ~np.isfinite(best)):
        raise ValueError(f"the rack tip circle does not generate the section down to r = {float(np.min(r)):g} mm")
    return np.where(below, best, np.minimum(theta_inv, best))


def _involute_member(flank, n_r: int) -> Member:
    g = flank.gear
    r_form = float(flank.u_min)
    r = np.linspace(float(g.r_f), float(flank.u_max), n_r)
    theta = rack_fillet_half_angle(flank, r)  # the uncrowned mid-face section with its generated fillet
    return Member(
        flank,
        flank,
        np.eye(3),
        np.zeros(3),
        "involute",
        float(flank.u_max),
        r_form,
        float(g.r_f),
        float(flank.v_min),
        float(flank.v_max),
        np.zeros(1),
        r,
        theta[None, :],
        np.zeros(1),
        lambda z: flank.twist(np.asarray(z, dtype=float))[0],
    )


def _wrap(a):
    return (a + np.pi) % (2.0 * np.pi) - np.pi


def _catt_member(flank, n_r: int, n_z: int) -> Member:
    base, Q, t = base_flank(flank)
    g = base.gear
    other = CATTFlank(g, -base.side)
    turn = base.side * 2.0 * np.pi / g.n_teeth  # the same tooth's other flank: the next space's
    zs = np.linspace(-0.5 * g.face_width, 0.5 * g.face_width, n_z)
    r = np.linspace(float(g.r_root), float(g.r_a), n_r)
    rr = np.maximum(r, float(g.r_form))
    Z, RR = np.meshgrid(zs, rr, indexing="ij")
    psi = []
    for f in (base, other):
        sol = f.solve_point(Z.ravel(), RR.ravel())
        if not np.all(sol.converged):
            raise ValueError(f"the CATT tooth section could not be read from the flank ({f!r}): a section solve failed")
        p = f.position(sol.x[:, 0], sol.x[:, 1])
        psi.append(np.arctan2(p[:, 1], p[:, 0]).reshape(Z.shape))
    work, opp = psi[0], psi[1] + turn
    half = 0.5 * np.abs(_wrap(opp - work))
    centre = work + 0.5 * _wrap(opp - work)
    # the centre line at the pitch radius; the section's half angles about it
    j = int(np.argmin(np.abs(rr - g.r_p)))
    c = centre[:, j]
    z_member = Q[2, 2] * zs + t[2]  # the mounting turns about z, or turns the gear over (z -> -z)
    return Member(
        flank,
        base,
        Q,
        t,
        "catt",
        float(g.r_a),
        float(g.r_form),
        float(g.r_root),
        float(np.min(z_member)),
        float(np.max(z_member)),
        zs,
        r,
        half,
        c,
    )


def member_of(flank, name: str, *, n_r: int = 2000, n_z: int = 17) -> Member:
    """The :class:`Member` of one flank (ValueError for an unsupported family, naming ``name``)."""
    base, _, _ = base_flank(flank)
    if isinstance(base, InvoluteFlank) and base is flank:
        return _involute_member(flank, n_r)
    if isinstance(base, CATTFlank):
        return _catt_member(flank, min(n_r, 400), n_z)
    return _refuse(flank, name)


def members(pair) -> tuple[Member, Member]:
    """Both members of a :class:`gearrep.tca.GearPair` (ValueError naming the flank of an
    unsupported family, or pairs of two families)."""
    m1, m2 = member_of(pair.flank1, "flank1"), member_of(pair.flank2, "flank2")
    if m1.family != m2.family:
        raise ValueError(f"flank1 is {m1.family} and flank2 is {m2.family}: a pair of one family is needed")
    return m1, m2


# ----------------------------------------------------------------------------------------------
# starts of the section-contact solve: (u1, v1, u2, v2, phi2) and the contact radii they imply
# ----------------------------------------------------------------------------------------------
def _involute_starts(pair, phi1, z):
    """The aligned involute pair's section contact on the line of action (transverse section at z)."""
    g1, g2 = pair.flank1.gear, pair.flank2.gear
    side = pair.flank1.side
    tw = pair.flank1.twist(np.asarray(z, float))[0]
    s1 = g1.r_b * np.tan(g1.alpha_t) + side * g1.r_b * (phi1 + side * np.pi / (2 * pair.n1) + tw)
    a = pair.centre_distance
    s2 = np.sqrt(max(a * a - (g1.r_b + g2.r_b) ** 2, 0.0)) - s1
    with np.errstate(invalid="ignore"):
        u1 = np.where(s1 > 0, np.sqrt(g1.r_b**2 + s1**2), np.nan)
        u2 = np.where(s2 > 0, np.sqrt(g2.r_b**2 + s2**2), np.nan)
    z = np.asarray(z, float) + 0.0 * u1
    return np.column_stack([u1, z, u2, z, pair.ratio * np.asarray(phi1, float) + 0.0 * u1]), u1, u2


def _catt_starts(pair, m1: Member, m2: Member, phi1, z):
    """The CATT pair's middle-section contact (closed form: at mesh pinion angle phi1 it lies on the
    line of action at D = R1 phi1 from the pitch point, seed 004 eq 29), moved to the section z."""
    b1, b2 = m1.base, m2.base
    g1, g2 = b1.gear, b2.gear
    c, a = np.cos(g1.pressure_angle), np.sin(g1.pressure_angle)
    phi1 = np.asarray(phi1, float)
    D = g1.r_p * phi1
    with np.errstate(invalid="ignore"):
        r1 = np.sqrt(c * c * D * D - 2 * b1.side * a * c * g1.r_p * D + g1.r_p**2)
        r2 = np.sqrt(c * c * D * D - 2 * b2.side * a * c * g2.r_p * D + g2.r_p**2)
    phi2 = pair.ratio * phi1
    out = []
    for b, m, roll in ((b1, m1, phi1), (b2, m2, phi2)):
        zb = (np.asarray(z, float) - m.t[2]) * m.Q[2, 2]  # base-frame axial position (aligned)
        W = b.R_T + b.R * roll
        theta = zb / (b.rho0 * b.c**2 + b.sa**2 * W)
        out.append((theta, roll - b.side * b.gear.q / b.R))
    (t1, p1), (t2, p2) = out
    return np.column_stack([t1, p1, t2, p2, phi2]), r1, r2


def section_starts(pair, m1: Member, m2: Member, phi1, z):
    """Starts (n, 5) = (u1, v1, u2, v2, phi2) of the section contacts at member-1 angles ``phi1``
    (tooth-pair angles) and member-1 axial positions ``z`` [mm], and the contact radii (r1, r2)
    [mm] of the family's closed form (NaN off the line of action)."""
    if m1.family == "involute":
        return _involute_starts(pair, phi1, z)
    return _catt_starts(pair, m1, m2, phi1, z)


def pitch_phi1(pair, m1: Member) -> float:
    """Member-1 angle [rad] at which tooth pair 0 touches at the pitch point in mid-face."""
    if m1.family == "involute":
        f = pair.flank1
        return float(-f.side * np.pi / (2 * pair.n1) - f.twist(np.zeros(1))[0][0])
    return 0.0  # gearrep.surfaces.catt.assemble mounts the middle-section pitch points at phi1 = phi2 = 0
