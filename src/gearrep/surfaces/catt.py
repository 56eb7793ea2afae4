"""Circular-arc-tooth-trace (CATT) cylindrical gear flanks cut by a rotary cutter of radius R_T.

Source: Ma, Liu, Ye, Wei, Liu, "Analysis of the tooth surface contact area of a CATT cylindrical
gear under load", Trans. FAMENA 45(1), 2021 (seed 004): coordinate transforms eq (1)-(4), blade
eq (5), tooth surface and equation of meshing eq (6), arbitrary transverse section eq (28),
middle section eq (29). Generation by a rack and the equation of meshing follow Litvin & Fuentes,
"Gear Geometry and Applied Theory", 2nd ed., ch. 6 (envelope, n . v = 0).

Frames and parameters (seed 004, sec. 2)
----------------------------------------
S_1 is fixed to the cutter axis (z_1); the blade point of eq (5) turned by the cutter angle
``theta`` about z_1 (eq 1) is carried into the fixed gear frame S_2 by eq (2): the cutter axis
is along y_2 (radial to the gear), its centre at (R_T, -R, 0) and the gear axis is z_2. The
blank turns by the roll angle ``phi`` while the cutter (an imaginary rack with circular tooth
traces) moves by R phi along x_2 (eq 3). With s = +1 for the upper signs of eq (5)-(6) (the
*inside* blade, radius R_T - pi m/4 at the pitch line) and s = -1 for the lower signs (outside
blade, R_T + pi m/4), write q = pi m / 4, rho0 = R_T - s q, c = cos(alpha), a_s = sin(alpha),
W = R_T + R phi. The equation of meshing (eq 6, fourth line) gives the blade coordinate

    u = s a_s (W sec(theta) - rho0),   blade radius rho = rho0 + s u a_s = rho0 c^2 + a_s^2 W sec(theta),

and substituting it into eq (6) gives the flank in the closed form used here:

    r(theta, phi) = Rz(-phi) [ c^2 (W - rho0 cos theta),
                               s a_s c (W sec theta - rho0) - R,
                               rho0 c^2 sin theta + a_s^2 W tan theta ]                  (C)

(Rz(-phi) turns about z only; z is the axial coordinate, z = 0 the middle section). Surface
parameters are (u, v) = (theta, phi) in the paper's order, so the normal of eq (8) is
unit(r_theta x r_phi). On the working flank (above the base circle) that normal points out of the
tooth for both blades: ``outward_sign = +1``. All first and second partial derivatives are
analytic (differentiate (C); Rz(-phi)' = Rz(-phi) J). They agree with 4th-order finite
differences to 1e-13..1e-7 of their scale (limited by the differences; tests require 1e-6), and
at the middle section they give the closed forms below to rounding.

Which flank is which. The inside blade (s = +1) leaves the tooth material on the cutter-centre
side of its circle (radius R_T - q): a **convex** flank. The outside blade (s = -1) leaves the
material outside its circle (radius R_T + q): a **concave** flank. Every tooth has one convex and
one concave flank; the tooth of this blank lies between the s = +1 flank of tooth space 0 and
the s = -1 flank of tooth space 1 (space 0 turned by one angular pitch, see
:func:`tooth_thickness`).

Middle section (theta = 0, z = 0) in closed form
------------------------------------------------
With D = s q + R phi, the point sits on the line of action through the pitch point at signed
distance l = c D along (c, s a_s): the transverse profile is an involute of base radius R c (the
claim of eq (29)). Its principal directions are the profile tangent and the axial direction
(r_theta . r_phi = 0 and r_theta_phi . n = 0 there), with curvatures w.r.t. the outward normal

    k_profile = -1 / sqrt(r^2 - r_b^2)     (convex involute, r = radius of the point)
    k_axial   = -s c / rho,   rho = R_T - s q + l a_s tan(alpha)  (the blade radius that cut it)

(:func:`middle_section_curvatures`). So the axial curvature is that of the cutter cone along its
circle, c / rho (Meusnier), negative (convex) for s = +1 and positive (concave) for s = -1.

Off the middle section the generating tooth trace is inclined by beta = asin(z / rho) at the
section z, and the transverse profile is, to leading order, the involute of transverse pressure
angle tan(alpha_t) = tan(alpha) / cos(beta), as on a helical gear: its deviation from the spur
involute falls like 1/R_T^2 (test ``test_straight_trace_limit_is_involute_spur`` checks the
predicted deviation to 0.2 %).

Corrections to seed 004 (evidence in tests/unit/surfaces/test_catt.py)
----------------------------------------------------------------------
* Eq (5)-(6) and the meshing relation are correct as printed: eq (6) equals (C) to rounding and
  the rack normal is orthogonal to the relative velocity at every generated point.
* Eq (8): the normal must be divided by |r_theta x r_phi|, not |r_theta . r_phi|; the dot
  product F = r_theta . r_phi is exactly 0 on the middle section, where every contact point lies.
* Eq (10): F = r_theta . r_phi (printed r_theta . r).
* Eq (15)-(16): the principal curvatures solve x^2 - 2 H x + K = 0, i.e. k_{1,2} = H +- sqrt(H^2 - K)
  (printed x^2 - H x + K and k_2 = H + sqrt(H^2 + K)).
* Eq (19): the first R is R^I (printed R^II twice).
* Eq (20) (like-indexed differences) holds only when the principal directions of the two
  flanks are paired by direction (sigma = 0); with curvatures ordered algebraically the convex
  and concave flanks have their profile and axial curvatures in opposite slots (sigma = 90 deg).
  Eq (23)-(24) with the true sigma are right in both cases (see gearrep.replications.ma2021).
* Eq (28)-(29) are written in a frame turned over relative to eq (6): (x, y, z) -> (x, -y, -z).
  In it their upper sign describes eq (6)'s lower-sign (concave) flank: eq (28) upper at section
  offset b equals eq (6) lower at z = -b with y -> -y and u -> -u; eq (29) upper equals eq (6)
  lower at theta = 0 with y -> -y and the same roll angle (equivalently eq (6) upper turned by pi
  about the gear axis with phi_1 = -phi). Conventions, not errors (:func:`eq28_profile`,
  :func:`eq29_profile`, tests). Eq (29) is an involute of base radius R cos(alpha): it is
  A e(psi) + R c e(psi + pi/2) with dA/dpsi = R c.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import frames
from ..surface import RotatedSurface
from ..tca import GearPair, solve_contact
from ._catt_flank import CATTFlank, CATTGearData, turn_over

__all__ = [
    "CATTGearData",
    "CATTFlank",
    "turn_over",
    "tooth_thickness",
    "pitch_thickness_closed_form",
    "middle_section_curvatures",
    "eq28_profile",
    "eq29_profile",
    "PAIRS",
    "Mesh",
    "gear_data",
    "assemble",
    "path_limits",
    "starts",
    "solve_cycle",
]


# ----------------------------------------------------------------------------------------------
# closed forms
# ----------------------------------------------------------------------------------------------
def middle_section_curvatures(gear: CATTGearData, side: int, radius):
    """Principal curvatures (w.r.t. the outward normal) of a flank at its middle-section point of
    given radius: (k_profile, k_axial, rho_blade, l) with l the signed position on the line of
    action, measured from the pitch point along (c, s a_s) of the rack frame.

    Parameters
    ----------
    gear : CATTGearData
        The gear.
    side : {1, -1}
        +1 convex flank (inside blade), -1 concave flank (outside blade).
    radius : float or array_like
        Radii of the middle-section points [mm], at or above the base radius.

    Returns
    -------
    k_profile, k_axial : numpy.ndarray
        Principal curvatures [1/mm] along the profile and along the axis.
    rho_blade : numpy.ndarray
        Radius of the blade circle that cut the point [mm].
    l : numpy.ndarray
        Signed position on the line of action [mm].

    Examples
    --------
    At the pitch point (l = 0) the axial curvature is that of the blade circle, radius
    R_T -+ pi m / 4:

    >>> from gearrep.surfaces.catt import CATTGearData, middle_section_curvatures
    >>> gear = CATTGearData(19, 8.0, 500.0, 80.0)  # teeth, module mm, cutter radius mm, face mm
    >>> k_p, k_a, rho, l = middle_section_curvatures(gear, 1, gear.r_p)  # convex flank, mm
    >>> round(float(k_p), 6), round(float(k_a), 6), round(float(rho), 4)  # 1/mm, 1/mm, mm
    (-0.038471, -0.001903, 493.7168)
    >>> round(float(middle_section_curvatures(gear, -1, gear.r_p)[1]), 6)  # concave: positive [1/mm]
    0.001856
    """
    r = np.asarray(radius, float)
    s, c, a = side, np.cos(gear.pressure_angle), np.sin(gear.pressure_angle)
    with np.errstate(invalid="ignore"):
        rho_prof = np.sqrt(r * r - gear.r_b**2)
    l = s * (gear.r_p * a - rho_prof)  # c D with D from CATTFlank.middle_section_phi
    rho = gear.R_T - s * gear.q + l * a * a / c
    return -1.0 / rho_prof, -s * c / rho, rho, l


def pitch_thickness_closed_form(gear: CATTGearData, z):
    """Transverse arc tooth thickness on the pitch circle at axial offset z (exact):
    pi m - [sqrt((R_T + q)^2 - z^2) - sqrt((R_T - q)^2 - z^2)] (rack space width on the pitch line,
    which rolls on the pitch circle in every transverse section).

    Parameters
    ----------
    gear : CATTGearData
        The gear.
    z : float or array_like
        Axial offsets of the sections [mm].

    Returns
    -------
    numpy.ndarray
        Thicknesses [mm].

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.surfaces.catt import CATTGearData, pitch_thickness_closed_form
    >>> gear = CATTGearData(19, 8.0, 500.0, 80.0)  # teeth, module mm, cutter radius mm, face mm
    >>> np.round(pitch_thickness_closed_form(gear, [0.0, 30.0]), 6).tolist()  # mm; pi m / 2 in the middle
    [12.566371, 12.543686]
    """
    z = np.asarray(z, float)
    q, RT = gear.q, gear.R_T
    return np.pi * gear.module - (np.sqrt((RT + q) ** 2 - z * z) - np.sqrt((RT - q) ** 2 - z * z))


def tooth_thickness(gear: CATTGearData, z, radius=None):
    """Transverse arc tooth thickness at ``radius`` (default pitch radius) in the section at axial
    coordinate ``z``, between the convex flank (s = +1, space 0) and the concave flank (s = -1 of
    space 1, i.e. space 0 turned by 2 pi / z). Returns (thickness (n,), max solve residual).

    Parameters
    ----------
    gear : CATTGearData
        The gear.
    z : float or array_like
        Axial coordinates of the sections [mm].
    radius : float, optional
        Radius [mm] (default: the pitch radius).

    Returns
    -------
    thickness : numpy.ndarray
        (n,) arc thicknesses [mm].
    residual : float
        The largest residual of the section-point solves [mm].

    Raises
    ------
    RuntimeError
        If a section-point solve does not converge.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.surfaces.catt import CATTGearData, tooth_thickness
    >>> gear = CATTGearData(19, 8.0, 500.0, 80.0)  # teeth, module mm, cutter radius mm, face mm
    >>> t, res = tooth_thickness(gear, [0.0, 30.0])  # mm
    >>> np.round(t, 6).tolist(), bool(res < 1e-9)  # the closed form on the pitch circle
    ([12.566371, 12.543686], True)
    """
    z = np.atleast_1d(np.asarray(z, float))
    radius = gear.r_p if radius is None else float(radius)
    rr = np.full_like(z, radius)
    out = []
    res_max = 0.0
    for side in (1, -1):
        f = CATTFlank(gear, side)
        sol = f.solve_point(z, rr)
        if not np.all(sol.converged):
            raise RuntimeError(f"section point solve failed: {sol.status_name[~sol.converged]}")
        p = f.position(sol.x[:, 0], sol.x[:, 1])
        out.append(np.arctan2(p[:, 1], p[:, 0]))
        res_max = max(res_max, float(np.max(sol.residual)))
    ang = out[1] + 2.0 * np.pi / gear.n_teeth - out[0]
    ang = (ang + np.pi) % (2 * np.pi) - np.pi
    return radius * np.abs(ang), res_max


# ----------------------------------------------------------------------------------------------
# eq (28) and eq (29) as printed
# ----------------------------------------------------------------------------------------------
def eq28_profile(gear: CATTGearData, upper: bool, b, theta):
    """Eq (28) as printed: transverse profile at section offset ``b`` parameterised by theta.
    ``upper`` selects the upper of its double signs. Returns (x1, y1, phi1, u).

    Parameters
    ----------
    gear : CATTGearData
        The gear.
    upper : bool
        The upper signs of eq (28).
    b : float
        Section offset [mm].
    theta : float or array_like
        Cutter angles [rad].

    Returns
    -------
    x1, y1 : numpy.ndarray
        Profile points [mm].
    phi1 : numpy.ndarray
        Roll angles [rad].
    u : numpy.ndarray
        Blade coordinates [mm].

    Examples
    --------
    Eq (28) upper at offset b lies on eq (6)'s concave flank at z = -b (module docstring):

    >>> import numpy as np
    >>> from gearrep.surfaces.catt import CATTFlank, CATTGearData, eq28_profile
    >>> gear = CATTGearData(19, 8.0, 500.0, 80.0)  # teeth, module mm, cutter radius mm, face mm
    >>> flank = CATTFlank(gear, -1)
    >>> theta = np.arcsin(20.0 / flank.rho0)  # rad
    >>> x1, y1, phi1, u = eq28_profile(gear, True, 20.0, theta)  # b = 20 mm
    >>> p = flank.position(theta, phi1)
    >>> round(float(p[2]), 9), bool(np.allclose([x1, -y1], p[:2], atol=1e-9))  # mm
    (-20.0, True)
    """
    theta = np.asarray(theta, float)
    sg = 1.0 if upper else -1.0  # the +- of eq (28); its -+ is -sg
    a, c = np.sin(gear.pressure_angle), np.cos(gear.pressure_angle)
    R, RT, q = gear.r_p, gear.R_T, gear.q
    phi1 = -(1.0 / R) * ((b / np.sin(theta) + c * c * (RT + sg * q)) * np.cos(theta) / (a * a) + RT)
    u = -sg * a / np.cos(theta) * (np.cos(theta) * (RT + sg * q) - (RT + R * phi1))
    A = -(sg * u * a + RT + sg * q) * np.cos(theta) + RT + R * phi1
    x1 = A * np.cos(phi1) - (R + u * c) * np.sin(phi1)
    y1 = A * np.sin(phi1) + (R + u * c) * np.cos(phi1)
    return x1, y1, phi1, u


def eq29_profile(gear: CATTGearData, upper: bool, phi1):
    """Eq (29) as printed: middle-section profile parameterised by phi1 (upper/lower signs).

    Parameters
    ----------
    gear : CATTGearData
        The gear.
    upper : bool
        The upper signs of eq (29).
    phi1 : float or array_like
        Roll angles [rad].

    Returns
    -------
    x1, y1 : numpy.ndarray
        Profile points [mm].

    Examples
    --------
    Eq (29) upper is eq (6)'s concave flank at theta = 0 with y -> -y (module docstring):

    >>> import numpy as np
    >>> from gearrep.surfaces.catt import CATTFlank, CATTGearData, eq29_profile
    >>> gear = CATTGearData(19, 8.0, 500.0, 80.0)  # teeth, module mm, cutter radius mm, face mm
    >>> phi = np.array([0.0, 0.05])  # rad
    >>> x1, y1 = eq29_profile(gear, True, phi)
    >>> p = CATTFlank(gear, -1).position(0.0 * phi, phi)
    >>> bool(np.allclose(np.column_stack([x1, -y1]), p[:, :2], atol=1e-10))
    True
    """
    phi1 = np.asarray(phi1, float)
    sg = 1.0 if upper else -1.0
    a, c = np.sin(gear.pressure_angle), np.cos(gear.pressure_angle)
    R, q = gear.r_p, gear.q
    A = R * phi1 * c - sg * q * c + sg * R * a
    psi = phi1 + sg * gear.pressure_angle
    x1 = A * np.cos(psi) - R * np.sin(psi) * c
    y1 = A * np.sin(psi) + R * np.cos(psi) * c
    return x1, y1


# ---------------------------------------------------------------------------------------------
# The assembled pair: pinion and turned-over gear cut by the same cutter, in gearrep.tca frames
#
# Member 1 = pinion (z1), member 2 = gear (z2), both cut by one cutter (same R_T, module,
# pressure angle). Flank pair "A" = pinion convex (side +1) on gear concave (side -1), pair "B" =
# pinion concave on gear convex. The gear is turned over ((x, y, z) -> (x, -y, -z),
# :func:`turn_over`) so that its circular tooth traces bend the same way as the pinion's in the
# common pitch plane. Frames are those of :class:`gearrep.tca.GearPair` (pinion axis z through the
# origin, gear axis through (R1 + R2, 0, 0)); each flank is pre-rotated so that its middle-section
# pitch point lies at the pitch point at phi1 = phi2 = 0. Lengths in mm, angles in rad.

PAIRS = {"A": (1, -1), "B": (-1, 1)}  #: flank pair -> (pinion side, gear side); +1 convex, -1 concave
_DESIGN_KEYS = ("z1", "z2", "module", "R_T", "face_width")
_PRM_KEYS = ("pressure_angle_deg", "addendum", "clearance")


@dataclass
class Mesh:
    """One assembled CATT pair with flank pair ``pair_id`` ("A" or "B"): the design dict it was
    built from, the gear data and flanks of both members, the flanks mounted in the pair's frames
    (``p1``, ``p2``) and the :class:`gearrep.tca.GearPair` (``gear_pair``).

    Parameters
    ----------
    design : dict
        The design (:func:`assemble`).
    pair_id : str
        The flank pair, a key of :data:`PAIRS`.
    g1, g2 : CATTGearData
        Gear data of pinion and gear.
    f1, f2 : CATTFlank
        Their flanks.
    p1, p2 : gearrep.surface.RotatedSurface
        The flanks mounted in the pair's frames.
    gear_pair : gearrep.tca.GearPair
        The pair for the TCA.

    Examples
    --------
    >>> from gearrep.surfaces.catt import assemble
    >>> design = {"z1": 21, "z2": 29, "module": 4.0, "R_T": 500.0, "face_width": 80.0}  # teeth, mm
    >>> prm = {"pressure_angle_deg": 20.0, "addendum": 1.0, "clearance": 0.25}  # deg, modules
    >>> mesh = assemble(design, "A", prm)
    >>> mesh.s1, round(mesh.ratio, 6), type(mesh.gear_pair).__name__  # convex pinion flank, z1 / z2
    (1, 0.724138, 'GearPair')
    """

    design: dict
    pair_id: str
    g1: CATTGearData
    g2: CATTGearData
    f1: CATTFlank
    f2: CATTFlank
    p1: RotatedSurface
    p2: RotatedSurface
    gear_pair: object

    @property
    def s1(self):
        """Side of the pinion flank (+1 convex, -1 concave)."""
        return self.f1.side

    @property
    def ratio(self):
        """Gear ratio z1 / z2 (phi2 = ratio phi1)."""
        return self.g1.n_teeth / self.g2.n_teeth


def _require_keys(name: str, d: dict, keys) -> None:
    if not isinstance(d, dict):
        raise ValueError(f"{name} must be a dict with keys {list(keys)}, got {type(d).__name__}")
    missing = [k for k in keys if k not in d]
    if missing:
        raise ValueError(f"{name} is missing the keys {missing} (needs {list(keys)})")


def gear_data(design: dict, prm: dict, member: int) -> CATTGearData:
    """Gear data of member 1 (pinion, ``design["z1"]`` teeth) or 2 (gear, ``z2``) of ``design``
    (``module``, cutter radius ``R_T`` and ``face_width`` in mm); ``prm`` brings the pressure angle
    ``pressure_angle_deg`` (deg) and the ``addendum`` and ``clearance`` coefficients (in modules).

    Parameters
    ----------
    design : dict
        ``z1``, ``z2`` (teeth), ``module``, ``R_T``, ``face_width`` [mm].
    prm : dict
        ``pressure_angle_deg`` [deg], ``addendum``, ``clearance`` [in modules].
    member : {1, 2}
        Pinion or gear.

    Returns
    -------
    CATTGearData
        The member's data.

    Raises
    ------
    ValueError
        If a key is missing, ``member`` is not 1 or 2, or a value is out of range
        (:class:`CATTGearData`).

    Examples
    --------
    >>> from gearrep.surfaces.catt import gear_data
    >>> design = {"z1": 21, "z2": 29, "module": 4.0, "R_T": 500.0, "face_width": 80.0}  # teeth, mm
    >>> prm = {"pressure_angle_deg": 20.0, "addendum": 1.0, "clearance": 0.25}  # deg, modules
    >>> g2 = gear_data(design, prm, 2)
    >>> g2.n_teeth, g2.r_p  # mm
    (29, 58.0)
    """
    _require_keys("design", design, _DESIGN_KEYS)
    _require_keys("prm", prm, _PRM_KEYS)
    if member not in (1, 2):
        raise ValueError(f"member must be 1 (pinion) or 2 (gear), got {member!r}")
    return CATTGearData(
        design["z1"] if member == 1 else design["z2"],
        design["module"],
        design["R_T"],
        design["face_width"],
        np.deg2rad(prm["pressure_angle_deg"]),
        prm["addendum"],
        prm["clearance"],
    )


def assemble(design: dict, pair_id: str, prm: dict) -> Mesh:
    """Mount the pinion and the turned-over gear of ``design`` (keys ``z1``, ``z2``, ``module``,
    ``R_T``, ``face_width``; mm) with flank pair ``pair_id`` (a key of :data:`PAIRS`) in the frames
    of :mod:`gearrep.tca`; ``prm`` as in :func:`gear_data`.

    Parameters
    ----------
    design : dict
        ``z1``, ``z2`` (teeth), ``module``, ``R_T``, ``face_width`` [mm].
    pair_id : {"A", "B"}
        The flank pair.
    prm : dict
        ``pressure_angle_deg`` [deg], ``addendum``, ``clearance`` [in modules].

    Returns
    -------
    Mesh
        The assembled pair.

    Raises
    ------
    ValueError
        If ``pair_id`` is unknown or the design or parameters are bad (:func:`gear_data`).

    Examples
    --------
    >>> from gearrep.surfaces.catt import assemble
    >>> design = {"z1": 21, "z2": 29, "module": 4.0, "R_T": 500.0, "face_width": 80.0}  # teeth, mm
    >>> prm = {"pressure_angle_deg": 20.0, "addendum": 1.0, "clearance": 0.25}  # deg, modules
    >>> mesh = assemble(design, "B", prm)  # pinion concave, gear convex
    >>> mesh.f1.convex, mesh.f2.convex, mesh.gear_pair.centre_distance  # mm
    (False, True, 100.0)
    """
    if pair_id not in PAIRS:
        raise ValueError(f"pair_id must be one of {sorted(PAIRS)}, got {pair_id!r}")
    s1, s2 = PAIRS[pair_id]
    g1, g2 = gear_data(design, prm, 1), gear_data(design, prm, 2)
    f1, f2 = CATTFlank(g1, s1), CATTFlank(g2, s2)
    Q1 = frames.rot_z(0.5 * np.pi - s1 * g1.q / g1.r_p)
    Q2 = frames.rot_z(0.5 * np.pi + s2 * g2.q / g2.r_p) @ turn_over()
    p1, p2 = RotatedSurface(f1, Q1), RotatedSurface(f2, Q2)
    gp = GearPair(p1, p2, g1.n_teeth, g2.n_teeth, g1.r_p + g2.r_p, phase2=0.0)
    return Mesh(design, pair_id, g1, g2, f1, f2, p1, p2, gp)


def path_limits(mesh: Mesh) -> dict:
    """Real meshing cycle on the middle section in mesh pinion angle phi1 (closed form).

    The middle-section contact at pinion angle phi1 lies at line-of-action coordinate D = R1 phi1
    (mm) from the pitch point; radii r_i^2 = c^2 D^2 - 2 s_i a_s c R_i D + R_i^2. The cycle is
    where both radii are below the tips. Returns ``phi1_lo``, ``phi1_hi`` (rad), ``D_lo``,
    ``D_hi`` (mm) and the transverse ``contact_ratio``.

    Parameters
    ----------
    mesh : Mesh
        The assembled pair.

    Returns
    -------
    dict
        The limits and the contact ratio [1].

    Raises
    ------
    ValueError
        If ``mesh`` is not a :class:`Mesh`.

    Examples
    --------
    >>> from gearrep.surfaces.catt import assemble, path_limits
    >>> design = {"z1": 21, "z2": 29, "module": 4.0, "R_T": 500.0, "face_width": 80.0}  # teeth, mm
    >>> prm = {"pressure_angle_deg": 20.0, "addendum": 1.0, "clearance": 0.25}  # deg, modules
    >>> lim = path_limits(assemble(design, "A", prm))
    >>> round(float(lim["phi1_lo"]), 6), round(float(lim["phi1_hi"]), 6), round(float(lim["contact_ratio"]), 4)
    (-0.234741, 0.246233, 1.6075)
    """
    if not isinstance(mesh, Mesh):
        raise ValueError(f"mesh must be a gearrep.surfaces.catt.Mesh (from assemble), got {type(mesh).__name__}")
    g1, g2 = mesh.g1, mesh.g2
    c, a = np.cos(g1.pressure_angle), np.sin(g1.pressure_angle)
    lims = []
    for g, s in ((g1, mesh.f1.side), (g2, mesh.f2.side)):
        A, B, C = c * c, -2 * s * a * c * g.r_p, g.r_p**2 - g.r_a**2  # c^2 D^2 - 2 s a c R D + R^2 - r_a^2 = 0
        disc = math.sqrt(B * B - 4 * A * C)
        lims.append(sorted([(-B - disc) / (2 * A), (-B + disc) / (2 * A)]))
    Dlo = max(lims[0][0], lims[1][0])
    Dhi = min(lims[0][1], lims[1][1])
    pb = 2 * np.pi * g1.r_b / g1.n_teeth
    return {
        "phi1_lo": Dlo / g1.r_p,
        "phi1_hi": Dhi / g1.r_p,
        "D_lo": Dlo,
        "D_hi": Dhi,
        "contact_ratio": c * (Dhi - Dlo) / pb,
    }


def starts(mesh: Mesh, phi1, offset_mm):
    """TCA starting points (theta1, phi_g1, theta2, phi_g2, phi2) at mesh pinion angles ``phi1``
    (rad): the middle-section estimate moved ``offset_mm`` (mm) off the middle section on both
    members and slightly off in roll and phi2 (so that the solve must find the contact).

    Parameters
    ----------
    mesh : Mesh
        The assembled pair.
    phi1 : (n,) array_like
        Pinion angles [rad].
    offset_mm : float
        Offset off the middle section [mm], finite.

    Returns
    -------
    numpy.ndarray
        (n, 5) conventional starts [rad].

    Raises
    ------
    ValueError
        If ``offset_mm`` is not finite.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.surfaces.catt import assemble, starts
    >>> design = {"z1": 21, "z2": 29, "module": 4.0, "R_T": 500.0, "face_width": 80.0}  # teeth, mm
    >>> prm = {"pressure_angle_deg": 20.0, "addendum": 1.0, "clearance": 0.25}  # deg, modules
    >>> x0 = starts(assemble(design, "A", prm), [0.0, 0.1], 5.0)  # rad, mm
    >>> x0.shape, np.round(x0[:, 0], 5).tolist()  # theta1 = 5 mm / blade radius [rad]
    ((2, 5), [0.01006, 0.01006])
    """
    if not np.isfinite(float(offset_mm)):
        raise ValueError(f"offset_mm must be finite, got {offset_mm!r}")
    g1, g2 = mesh.g1, mesh.g2
    phi1 = np.asarray(phi1, float)
    th1 = offset_mm / mesh.f1.rho0
    th2 = -0.7 * offset_mm / mesh.f2.rho0
    pg1 = phi1 - mesh.f1.side * g1.q / g1.r_p + 2e-3
    phi2 = mesh.ratio * phi1
    pg2 = phi2 - mesh.f2.side * g2.q / g2.r_p - 1.5e-3
    n = len(phi1)
    return np.column_stack([np.full(n, th1), pg1, np.full(n, th2), pg2, phi2 + 1e-3])


def solve_cycle(mesh: Mesh, phi1, prm: dict):
    """TCA at mesh pinion angles ``phi1`` (rad) by :func:`gearrep.tca.solve_contact`
    (conventional) from :func:`starts`; ``prm`` brings ``start_offset_mm`` (mm), ``tol`` and
    ``maxiter``. Returns the :class:`gearrep.tca.ContactPoints` (status per point).

    Parameters
    ----------
    mesh : Mesh
        The assembled pair.
    phi1 : (n,) array_like
        Pinion angles [rad].
    prm : dict
        ``start_offset_mm`` [mm], ``tol`` [mm], ``maxiter``.

    Returns
    -------
    gearrep.tca.ContactPoints
        One row per angle.

    Raises
    ------
    ValueError
        If a key of ``prm`` is missing, or the offset or the solver settings are bad.

    Examples
    --------
    The ideal pair meshes on its middle section with no transmission error:

    >>> import numpy as np
    >>> from gearrep.surfaces.catt import assemble, path_limits, solve_cycle
    >>> design = {"z1": 21, "z2": 29, "module": 4.0, "R_T": 500.0, "face_width": 80.0}  # teeth, mm
    >>> prm = {"pressure_angle_deg": 20.0, "addendum": 1.0, "clearance": 0.25}  # deg, modules
    >>> mesh = assemble(design, "A", prm)
    >>> lim = path_limits(mesh)
    >>> phi1 = np.linspace(lim["phi1_lo"], lim["phi1_hi"], 3)  # rad
    >>> c = solve_cycle(mesh, phi1, {"start_offset_mm": 5.0, "tol": 1e-11, "maxiter": 50})
    >>> c.status_name.tolist(), bool(np.all(np.abs(c.position[:, 2]) < 1e-9)), bool(np.all(np.abs(c.te) < 1e-12))
    (['converged', 'converged', 'converged'], True, True)
    """
    _require_keys("prm", prm, ("start_offset_mm", "tol", "maxiter"))
    start = starts(mesh, phi1, prm["start_offset_mm"])
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        return solve_contact(
            mesh.gear_pair, phi1, start, formulation="conventional", tol=prm["tol"], maxiter=prm["maxiter"]
        )
