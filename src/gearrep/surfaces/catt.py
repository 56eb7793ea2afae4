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
from ..inputs import check_finite
from ..solve import SolveResult, Status, newton
from ..surface import RotatedSurface, Surface, SurfacePoint
from ..tca import GearPair, solve_contact

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


@dataclass(frozen=True)
class CATTGearData:
    """Design data of one CATT gear (lengths in mm, angles in rad).

    n_teeth : number of teeth z; module : module m of the middle section (eq 5); R_T : cutter
    (tooth-line) radius; face_width : B; pressure_angle : blade angle alpha (20 deg standard);
    addendum, clearance : coefficients h*, c* (1 and 0.25 standard, seed 004 sec. 4).
    """

    n_teeth: int
    module: float
    R_T: float
    face_width: float
    pressure_angle: float = np.deg2rad(20.0)
    addendum: float = 1.0
    clearance: float = 0.25

    def __post_init__(self):
        if int(self.n_teeth) != self.n_teeth or not 5 <= self.n_teeth <= 10000:
            raise ValueError(f"n_teeth must be an integer in [5, 10000], got {self.n_teeth!r}")
        check_finite("module", self.module, positive=True)
        check_finite("face_width", self.face_width, positive=True)
        a = check_finite("pressure_angle", self.pressure_angle)
        if not 0.05 < a < 0.8:
            raise ValueError(f"pressure_angle must be in (0.05, 0.8) rad, got {a!r}")
        check_finite("addendum", self.addendum, nonneg=True)
        check_finite("clearance", self.clearance, nonneg=True)
        rt = check_finite("R_T", self.R_T, positive=True)
        if not rt > self.face_width / 2 + np.pi * self.module:
            raise ValueError(
                f"R_T must exceed face_width/2 + pi*module = {self.face_width / 2 + np.pi * self.module:g}, got {rt!r}"
            )

    @property
    def r_p(self) -> float:
        """Pitch radius R = m z / 2 (R_1 of eq 2-6)."""
        return 0.5 * self.module * self.n_teeth

    @property
    def q(self) -> float:
        """Half the tooth-space width at the pitch line, pi m / 4 (eq 5)."""
        return 0.25 * np.pi * self.module

    @property
    def r_b(self) -> float:
        """Base radius of the middle-section involute, R cos(alpha)."""
        return self.r_p * np.cos(self.pressure_angle)

    @property
    def r_a(self) -> float:
        """Tip radius R + h* m."""
        return self.r_p + self.addendum * self.module

    @property
    def r_root(self) -> float:
        """Root radius R - (h* + c*) m."""
        return self.r_p - (self.addendum + self.clearance) * self.module

    @property
    def r_form(self) -> float:
        """Lowest radius of the middle-section involute (form radius): the point generated by the
        end of the blade's straight edge at depth h* m below the pitch line (the blade tip below it,
        c* m, cuts the fillet, which is not modelled), but not below r_b."""
        s = np.sin(self.pressure_angle)
        h = self.addendum * self.module
        # rack line point at depth h touches the blank on the line of action at distance h / s from I
        l_low = h / s
        return float(max(self.r_b, np.hypot(self.r_b, self.r_p * s - l_low)) if l_low < self.r_p * s else self.r_b)


def _real_or_complex(x):
    """float array, or complex array for complex input (so that the transforms of eq (1)-(4) can be
    differentiated by the complex step, to rounding, in the independent envelope test)."""
    x = np.asarray(x)
    return x.astype(complex) if np.iscomplexobj(x) else x.astype(float)


class CATTFlank(Surface):
    """One flank of a CATT gear, r(theta, phi) of eq (6) in the closed form (C) of the module docstring.

    Parameters
    ----------
    gear : CATTGearData
    side : +1 for the upper signs of eq (5)-(6) (inside blade, convex flank), -1 for the lower
        signs (outside blade, concave flank)

    The parameter domain used for bounds is a box in (theta, phi) that contains the flank (radius
    between :attr:`CATTGearData.r_form` and r_a, |z| <= B/2); :meth:`contains` tests the true
    boundaries.
    """

    outward_sign = 1  #: unit(r_theta x r_phi) points out of the tooth on the working flank

    def __init__(self, gear: CATTGearData, side: int = 1):
        if not isinstance(gear, CATTGearData):
            raise ValueError(f"gear must be a CATTGearData, got {type(gear).__name__}")
        if side not in (1, -1):
            raise ValueError(f"side must be +1 (convex) or -1 (concave), got {side!r}")
        self.gear = gear
        self.side = int(side)
        self.R = gear.r_p
        self.R_T = gear.R_T
        self.alpha = gear.pressure_angle
        self.c = np.cos(self.alpha)
        self.sa = np.sin(self.alpha)
        self.rho0 = gear.R_T - self.side * gear.q
        self.fd_step = (1e-4, 1e-4)
        # generous parameter box (theta, phi) containing the flank
        th = np.arcsin(min(1.0, 0.5 * gear.face_width / (self.rho0 * self.c**2)))
        ph = (self.side * gear.q) / self.R
        span = (gear.r_a + gear.module) / (self.R * self.c)
        self.lower = np.array([-1.2 * th, -ph - span])
        self.upper = np.array([1.2 * th, -ph + span])

    @property
    def convex(self) -> bool:
        return self.side == 1

    def __repr__(self) -> str:
        g = self.gear
        return (
            f"CATTFlank(z={g.n_teeth}, m={g.module}, R_T={g.R_T}, B={g.face_width}, "
            f"alpha={g.pressure_angle:.6g}, side={self.side} ({'convex' if self.convex else 'concave'}))"
        )

    # -- the paper's equations as printed ------------------------------------------------------
    def blade_u(self, theta, phi):
        """Blade coordinate u from the equation of meshing, eq (6) fourth line as printed."""
        theta, phi = np.broadcast_arrays(np.asarray(theta, float), np.asarray(phi, float))
        s, q = self.side, self.gear.q
        return -s * self.sa * (np.cos(theta) * (self.R_T - s * q) - (self.R_T + self.R * phi)) / np.cos(theta)

    def cutter_point(self, u, theta):
        """Blade point of eq (5) turned by theta (eq 1) and carried into S_2 by eq (2) (homogeneous
        product M_21 M_1d0 r_d0), i.e. the generating surface in the rack frame (before the roll)."""
        u, theta = np.broadcast_arrays(_real_or_complex(u), _real_or_complex(theta))
        s, q = self.side, self.gear.q
        x0 = -(self.R_T - s * q + s * u * self.sa)  # eq (5), x_d0
        z0 = u * self.c
        # eq (1): rotation about z_1 by theta
        x1 = x0 * np.cos(theta)
        y1 = x0 * np.sin(theta)
        z1 = z0
        # eq (2)
        return np.stack([x1 + self.R_T, z1 - self.R, -y1], axis=-1)

    def position_eq6(self, theta, phi):
        """Eq (6) evaluated literally (u from its fourth line)."""
        theta, phi = np.broadcast_arrays(np.asarray(theta, float), np.asarray(phi, float))
        s, q = self.side, self.gear.q
        u = self.blade_u(theta, phi)
        rho = self.R_T - s * q + s * u * self.sa
        R = self.R
        x = (-rho * np.cos(theta) + self.R_T + R * phi) * np.cos(phi) + (u * self.c - R) * np.sin(phi)
        y = (rho * np.cos(theta) - self.R_T - R * phi) * np.sin(phi) + (u * self.c - R) * np.cos(phi)
        z = rho * np.sin(theta)
        return np.stack([x, y, z], axis=-1)

    def position_by_transforms(self, u, theta, phi):
        """Blade point (u, theta) carried by M_d2 M_21 M_1d0 (eq 4) at roll angle phi (any u).
        Accepts complex arguments (complex-step differentiation); real input gives real output."""
        p = self.cutter_point(u, theta)
        phi = np.broadcast_to(_real_or_complex(phi), p.shape[:-1])
        c, s = np.cos(phi), np.sin(phi)
        R = self.R
        x = c * p[..., 0] + s * p[..., 1] + R * phi * c  # eq (3)
        y = -s * p[..., 0] + c * p[..., 1] - R * phi * s
        return np.stack([x, y, p[..., 2]], axis=-1)

    def meshing_residual(self, u, theta, phi):
        """n . v of the generating surface at blade point (u, theta), roll angle phi, in S_2:
        zero where the blade point touches the generated flank (Litvin ch. 6)."""
        u, theta, phi = np.broadcast_arrays(*(np.asarray(a, float) for a in (u, theta, phi)))
        s = self.side
        p = self.cutter_point(u, theta) + np.stack([self.R * phi, 0 * phi, 0 * phi], axis=-1)
        rho = self.R_T - s * self.gear.q + s * u * self.sa
        # generating-surface normal r_u x r_theta (rack frame, any length)
        r_u = np.stack([-s * self.sa * np.cos(theta), np.full_like(u, self.c), s * self.sa * np.sin(theta)], -1)
        r_t = np.stack([rho * np.sin(theta), 0 * u, rho * np.cos(theta)], -1)
        N = np.cross(r_u, r_t)
        # velocity of the rack relative to the blank per unit roll: rack moves R x_2, blank turns +z
        v_rack = np.stack([np.full_like(u, self.R), 0 * u, 0 * u], -1)
        v_blank = np.stack([-p[..., 1], p[..., 0], 0 * u], -1)
        return np.sum(N * (v_rack - v_blank), axis=-1) / np.linalg.norm(N, axis=-1)

    # -- closed form (C) with analytic derivatives -------------------------------------------
    def _P(self, theta, phi, order=2):
        """Rack-frame point P(theta, W) of (C) and its partials P_theta, P_phi, P_thetatheta,
        P_thetaphi (before Rz(-phi); P_phiphi = 0, P is linear in W), each a 3-tuple of components
        (a constant component is a float); ``order`` 0: P alone."""
        s, c, a, R, rho0 = self.side, self.c, self.sa, self.R, self.rho0
        ct, st = np.cos(theta), np.sin(theta)
        sec = 1.0 / ct
        tn = st * sec
        W = self.R_T + R * phi
        sc = s * a * c
        P = (c * c * (W - rho0 * ct), sc * (W * sec - rho0) - R, rho0 * c * c * st + a * a * W * tn)
        if order == 0:
            return P
        P_t = (c * c * rho0 * st, sc * W * sec * tn, rho0 * c * c * ct + a * a * W * sec * sec)
        P_p = (R * (c * c), R * (sc * sec), R * (a * a * tn))
        P_tt = (
            c * c * rho0 * ct,
            sc * W * (sec * tn * tn + sec**3),
            -rho0 * c * c * st + 2 * a * a * W * sec * sec * tn,
        )
        P_tp = (0.0, R * (sc * sec * tn), R * (a * a * sec * sec))
        return P, P_t, P_p, P_tt, P_tp

    def position(self, theta, phi) -> np.ndarray:
        """r(theta, phi), closed form (C) (equal to eq (6))."""
        theta, phi = np.broadcast_arrays(np.asarray(theta, float), np.asarray(phi, float))
        cm, sm = np.cos(-phi), np.sin(-phi)
        return np.stack(np.broadcast_arrays(*frames.rotate_z(cm, sm, self._P(theta, phi, order=0))), axis=-1)

    def evaluate(self, theta, phi) -> SurfacePoint:
        """Position and analytic first and second partials with respect to (theta, phi)."""
        return SurfacePoint.from_components(self.evaluate_components(theta, phi))

    def evaluate_components(self, theta, phi) -> tuple:
        """:meth:`evaluate` by components (structure of arrays): r = Rz(-phi) P with
        r_theta = Rz P_theta, r_phi = Rz' P + Rz P_phi, r_thetatheta = Rz P_thetatheta,
        r_thetaphi = Rz' P_theta + Rz P_thetaphi, r_phiphi = Rz'' P + 2 Rz' P_phi (Rz' and Rz'' the
        phi-derivatives of Rz(-phi): no axial row)."""
        theta, phi = np.broadcast_arrays(np.asarray(theta, float), np.asarray(phi, float))
        P, P_t, P_p, P_tt, P_tp = self._P(theta, phi)
        cm, sm = np.cos(-phi), np.sin(-phi)  # Rz(-phi) = rot_z(a) at a = -phi

        def Q(V):
            return frames.rotate_z(cm, sm, V)

        def Q1(V):  # d/dphi Rz(-phi) = -rot_z'(a): [[sm, cm, 0], [-cm, sm, 0], [0, 0, 0]]
            return sm * V[0] + cm * V[1], sm * V[1] - cm * V[0]

        r_p, r_tp = Q1(P), Q1(P_t)
        Qp, Qtp = Q(P_p), Q(P_tp)
        q2x, q2y = sm * P[1] - cm * P[0], -(sm * P[0] + cm * P[1])  # d2/dphi2 Rz(-phi) = rot_z''(a)
        q1x, q1y = Q1(P_p)
        return (
            Q(P),
            Q(P_t),
            (r_p[0] + Qp[0], r_p[1] + Qp[1], Qp[2]),
            Q(P_tt),
            (r_tp[0] + Qtp[0], r_tp[1] + Qtp[1], Qtp[2]),
            (q2x + 2.0 * q1x, q2y + 2.0 * q1y, 0.0),
        )

    def outward_normal(self, theta, phi) -> np.ndarray:
        """Unit normal pointing out of the tooth material."""
        return self.outward_sign * self.evaluate(theta, phi).normal

    # -- positions on the flank --------------------------------------------------------------
    def middle_section_phi(self, radius):
        """Roll angle phi of the middle-section (theta = 0) point at ``radius`` (closed form)."""
        r = np.asarray(radius, float)
        s, g = self.side, self.gear
        with np.errstate(invalid="ignore"):
            D = s * (self.R * self.sa - np.sqrt(r * r - g.r_b**2)) / self.c
        return (D - s * g.q) / self.R

    def solve_point(self, z, radius, *, tol=1e-11, maxiter=40) -> SolveResult:
        """Parameters (theta, phi) of the flank point at axial coordinate ``z`` and ``radius``
        (Newton on z(theta, phi) - z = 0, |r_xy| - radius = 0; start from the middle section)."""
        z, radius = np.broadcast_arrays(np.atleast_1d(np.asarray(z, float)), np.atleast_1d(np.asarray(radius, float)))
        z, radius = z.ravel(), radius.ravel()
        th0 = np.arcsin(np.clip(z / self.rho0, -0.99, 0.99))
        ph0 = self.middle_section_phi(radius)
        x0 = np.column_stack([th0, ph0])

        # newton passes only the active rows to fun; carry the targets as frozen extra unknowns
        def F(X):
            p = self.position(X[:, 0], X[:, 1])
            return np.column_stack(
                [p[:, 2] - X[:, 2], np.hypot(p[:, 0], p[:, 1]) - X[:, 3], np.zeros(len(X)), np.zeros(len(X))]
            )

        def J(X):
            P = self.evaluate(X[:, 0], X[:, 1])
            rad = np.hypot(P.r[:, 0], P.r[:, 1])
            Jm = np.zeros((len(X), 4, 4))
            Jm[:, 0, 0], Jm[:, 0, 1], Jm[:, 0, 2] = P.r_u[:, 2], P.r_v[:, 2], -1.0
            Jm[:, 1, 0] = (P.r[:, 0] * P.r_u[:, 0] + P.r[:, 1] * P.r_u[:, 1]) / rad
            Jm[:, 1, 1] = (P.r[:, 0] * P.r_v[:, 0] + P.r[:, 1] * P.r_v[:, 1]) / rad
            Jm[:, 1, 3] = -1.0
            Jm[:, 2, 2] = Jm[:, 3, 3] = 1.0
            return Jm

        res = newton(F, np.column_stack([x0, z, radius]), J, tol=tol, maxiter=maxiter)
        st = res.status.copy()
        st[(res.iterations == 0) & (res.residual < tol)] = int(Status.CONVERGED)
        return SolveResult(res.x[:, :2], res.residual, res.iterations, st, res.condition)

    def section_profile(self, z, radii):
        """Transverse profile at axial coordinate ``z``: points (n, 3) at ``radii`` and the solve record."""
        radii = np.atleast_1d(np.asarray(radii, float))
        res = self.solve_point(np.full_like(radii, float(z)), radii)
        return self.position(res.x[:, 0], res.x[:, 1]), res

    def contains(self, theta, phi, tol: float = 1e-9) -> np.ndarray:
        """True where (theta, phi) is on the flank: r_form <= radius <= r_a and |z| <= B/2."""
        p = self.position(theta, phi)
        rad = np.hypot(p[..., 0], p[..., 1])
        g = self.gear
        return (
            (rad >= g.r_form - tol)
            & (rad <= g.r_a + tol)
            & (np.abs(p[..., 2]) <= 0.5 * g.face_width + tol)
            & (np.abs(np.asarray(theta)) < 0.5 * np.pi)
        )

    def tip_edge(self, z):
        """Points (n, 3) of the tip edge (intersection with the tip cylinder) at axial coordinates z."""
        z = np.atleast_1d(np.asarray(z, float))
        res = self.solve_point(z, np.full_like(z, self.gear.r_a))
        return self.position(res.x[:, 0], res.x[:, 1]), res


def turn_over() -> np.ndarray:
    """Rotation by pi about the x axis, (x, y, z) -> (x, -y, -z): the mate is turned over so that
    its tooth traces bend the same way as the pinion's in the common pitch plane."""
    return np.diag([1.0, -1.0, -1.0])


# ----------------------------------------------------------------------------------------------
# closed forms
# ----------------------------------------------------------------------------------------------
def middle_section_curvatures(gear: CATTGearData, side: int, radius):
    """Principal curvatures (w.r.t. the outward normal) of a flank at its middle-section point of
    given radius: (k_profile, k_axial, rho_blade, l) with l the signed position on the line of
    action, measured from the pitch point along (c, s a_s) of the rack frame."""
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
    which rolls on the pitch circle in every transverse section)."""
    z = np.asarray(z, float)
    q, RT = gear.q, gear.R_T
    return np.pi * gear.module - (np.sqrt((RT + q) ** 2 - z * z) - np.sqrt((RT - q) ** 2 - z * z))


def tooth_thickness(gear: CATTGearData, z, radius=None):
    """Transverse arc tooth thickness at ``radius`` (default pitch radius) in the section at axial
    coordinate ``z``, between the convex flank (s = +1, space 0) and the concave flank (s = -1 of
    space 1, i.e. space 0 turned by 2 pi / z). Returns (thickness (n,), max solve residual)."""
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
    ``upper`` selects the upper of its double signs. Returns (x1, y1, phi1, u)."""
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
    """Eq (29) as printed: middle-section profile parameterised by phi1 (upper/lower signs)."""
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
    (``p1``, ``p2``) and the :class:`gearrep.tca.GearPair` (``gear_pair``)."""

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
    ``pressure_angle_deg`` (deg) and the ``addendum`` and ``clearance`` coefficients (in modules)."""
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
    of :mod:`gearrep.tca`; ``prm`` as in :func:`gear_data`."""
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
    ``D_hi`` (mm) and the transverse ``contact_ratio``."""
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
    members and slightly off in roll and phi2 (so that the solve must find the contact)."""
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
    ``maxiter``. Returns the :class:`gearrep.tca.ContactPoints` (status per point)."""
    _require_keys("prm", prm, ("start_offset_mm", "tol", "maxiter"))
    start = starts(mesh, phi1, prm["start_offset_mm"])
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        return solve_contact(
            mesh.gear_pair, phi1, start, formulation="conventional", tol=prm["tol"], maxiter=prm["maxiter"]
        )
