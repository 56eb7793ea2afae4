"""Spherical-involute straight and (logarithmic) spiral bevel tooth flanks with crowning and relief.

Source: Temirkhan, PhD thesis 2023 (seed 003): the spherical involute eq (6)-(7) = eq (48)-(50) of
sec 5.2 (the OCR numbers the shaft-angle change of sec 5.1 "48" too), the spiral lengthwise shape
eq (8)-(9) = eq (51); the crowning and relief of the cylindrical family (eq 10-13,
:mod:`gearrep.surfaces.involute`) carried over to the cone. Reading notes: docs/reading-notes.md,
section "Temirkhan thesis (seed 003)".

Parameters (the thesis's spherical coordinates, sec 3.3)
--------------------------------------------------------
``u`` is the polar angle between the gear axis z_i and the flank point (rad) and ``v`` the distance
of the point from the cone apex (the cone distance, eq 50: R_i = v_i). In the gear's own frame S_i
(apex at the origin)

    r(u, v) = v ( sin u cos psi(u, v),  sin u sin psi(u, v),  cos u )                      (A)

with the azimuth

    psi(u, v) = side * ( c - I(u) - delta(u, v) / (v sin a_b) ) + hand * theta(v),         (B)
    I(u)      = sigma / sin a_b - atan( tan sigma / sin a_b ),  cos sigma = cos u / cos a_b,
    c         = pi / (2 N) + I(delta_p)          (half tooth angle + I at the pitch cone),
    theta(v)  = tan(Phi) / sin(a_b) * ln(R_m / v)                               (eq 51).

a_b is the base cone angle, delta_p the pitch cone angle. I(u) is the azimuth of the spherical
involute that leaves the base cone at azimuth 0, written in u instead of the generating angle
beta of eq (48)-(49): sigma = beta sin a_b is the unwound great-circle arc and eq (49) is Napier's
rule cos u = cos a_b cos sigma for the right spherical triangle (pole, tangency point on the base
cone, flank point). Eq (48) with theta = 0 gives the same points (tested). The tooth is symmetric
about the +x_i axis; ``side = +1`` is the flank on its +y_i side. ``v`` runs over the face
[R_e - b, R_e]; R_m = R_e - b/2.

Properties used by the tests and the TCA:
* every point lies on the sphere |r| = v about the apex (A);

* the great circle normal to the profile at a point is tangent to the base cone
  (|((r x n) / |r|) . z| = sin a_b), which is what makes the profile a spherical involute, and two
  such flanks with equal pressure angle on rolling pitch cones are conjugate (line contact along a
  generatrix through the apex, zero TE);

* turning the profile about the axis by dpsi moves it along its normal by v sin(a_b) dpsi (the
  spherical counterpart of the base-pitch property), so ``delta`` in (B) is an offset along the
  normal in length units (exact for constant delta, first order otherwise);

* the spiral (eq 51): at cone distance v the profile is turned by theta(v); the curve it traces on
  the base cone crosses the generatrices at the constant angle Phi, i.e. Phi is the spiral angle
  on the base cone (the angle in the tangent plane of action), not on the pitch cone. Two flanks of
  opposite hands with equal Phi (and equal pressure angle) are conjugate: the flanks are the loci of
  one logarithmic spiral drawn in the plane of action, which rolls on both base cones.

Choices the thesis leaves open (stated here, used by the replication)
---------------------------------------------------------------------

* Base cones: from the pitch cones and the pressure angle, sin a_b = sin delta_p cos alpha (the
  pressure angle is the angle at the pitch point between the profile normal great circle and the
  meridian's normal). Table 5's "base cone angles" 47.79 / 36.53 deg are the root cones
  (delta_p - atan(1.25 m / R_e)); used as base cones the pair is not conjugate.

* Tooth depth tapers to the apex: addendum angle atan(h_a m / R_e), dedendum angle
  atan(h_f m / R_e) (m = module at the outer cone distance R_e = N m / (2 sin delta_p)).

* Tip/root relief: eq (13) in the polar angle u (``TipRelief(u0, length, amount)`` with u0 and
  length in rad, the amount in length along the normal); :func:`relief_from_length` converts a
  relief length L (length units along the profile at the mean cone distance) into the angle
  L / R_m starting L / R_m below the tip.

* Longitudinal crowning (parabolic, circular, logarithmic, eq 10-12 via the classes of
  :mod:`gearrep.surfaces.involute`) is a function of the cone distance v with v0 = R_m.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..surface import Surface, SurfacePoint
from .involute import (
    InvoluteFlank,
    RootRelief,
    TipRelief,
    _broadcast2,
    _check_finite,
    _flank_options,
    _mating_pair,
    _shaped,
)

__all__ = [
    "spherical_involute_azimuth",
    "spherical_involute_eq48",
    "BevelGearData",
    "SphericalInvoluteFlank",
    "mating_bevel_flanks",
    "relief_from_length",
]


def _sigma_derivs(u, a_b):
    """sigma, I(u), I'(u), I''(u) of the spherical involute with base cone ``a_b``.

    I'(u) = cos a_b sin sigma / (sin a_b sin u);
    I''(u) = cos sigma / (sin a_b sin sigma) - cos a_b sin sigma cos u / (sin a_b sin^2 u).
    NaN inside the base cone (u < a_b)."""
    sa, ca = np.sin(a_b), np.cos(a_b)
    with np.errstate(invalid="ignore", divide="ignore"):
        cs = np.cos(u) / ca  # 1 + rounding on the base cone itself
        sig = np.arccos(np.where(cs <= 1.0 + 1e-14, np.minimum(cs, 1.0), np.nan))
        ss = np.sin(sig)
        su = np.sin(u)
        inv = sig / sa - np.arctan(np.tan(sig) / sa)
        d1 = ca * ss / (sa * su)
        d2 = np.cos(sig) / (sa * ss) - ca * ss * np.cos(u) / (sa * su * su)
    return sig, inv, d1, d2


def spherical_involute_azimuth(u, base_cone_angle):
    """Azimuth I(u) of the spherical involute of base cone ``base_cone_angle`` (rad) at polar angle
    ``u`` (rad), for the involute leaving the base cone at azimuth 0 (module docstring, eq B).

    NaN for u < base_cone_angle (inside the base cone).

    Parameters
    ----------
    u : float or array_like
        Polar angles [rad].
    base_cone_angle : float
        a_b [rad], in (0, pi/2).

    Returns
    -------
    numpy.ndarray
        I(u) [rad].

    Raises
    ------
    ValueError
        If ``base_cone_angle`` is not a finite angle in (0, pi/2).

    Examples
    --------
    >>> import math
    >>> import numpy as np
    >>> from gearrep.surfaces.bevel import spherical_involute_azimuth
    >>> np.round(spherical_involute_azimuth([math.radians(37.0), math.radians(40.0)], math.radians(38.0)), 6).tolist()
    [nan, 0.011035]
    """
    a = _check_finite("base_cone_angle", base_cone_angle)
    if not 0.0 < a < np.pi / 2:
        raise ValueError(f"base_cone_angle must be in (0, pi/2) rad, got {base_cone_angle!r}")
    return _sigma_derivs(np.asarray(u, float), a)[1]


def spherical_involute_eq48(beta, R, base_cone_angle, theta=0.0, sign: int = 1):
    """The thesis's eq (48) (= eq 7 for theta = 0, eq 8 with the spiral turn): the point of the
    spherical involute with generating angle ``beta`` at cone distance ``R``, turned by
    ``sign * theta`` about the axis. Kept as printed for the evidence test against (A)-(B).

    Parameters
    ----------
    beta : float or array_like
        Generating angle [rad].
    R : float or array_like
        Cone distance [length].
    base_cone_angle : float
        a_b [rad].
    theta : float or array_like, optional
        Spiral turn [rad].
    sign : {1, -1}, optional
        Sense of the turn.

    Returns
    -------
    numpy.ndarray
        (..., 3) points [length].

    Examples
    --------
    The point of generating angle beta lies at the polar angle u of Napier's rule
    cos u = cos a_b cos(beta sin a_b) and at the azimuth I(u) of (B):

    >>> import math
    >>> from gearrep.surfaces.bevel import spherical_involute_azimuth, spherical_involute_eq48
    >>> a_b, beta, R = math.radians(46.59), 0.2, 56.06  # rad, rad, mm
    >>> x, y, z = spherical_involute_eq48(beta, R, a_b)
    >>> u = math.acos(math.cos(a_b) * math.cos(beta * math.sin(a_b)))
    >>> abs(math.acos(z / R) - u) < 1e-12, abs(math.atan2(y, x) - float(spherical_involute_azimuth(u, a_b))) < 1e-12
    (True, True)
    """
    a = float(base_cone_angle)
    sa, ca = np.sin(a), np.cos(a)
    beta = np.asarray(beta, float)
    R = np.asarray(R, float)
    g = beta + sign * np.asarray(theta, float)
    cb, sb = np.cos(beta * sa), np.sin(beta * sa)
    return np.stack(
        [R * (cb * sa * np.cos(g) + sb * np.sin(g)), R * (cb * sa * np.sin(g) - sb * np.cos(g)), R * cb * ca], axis=-1
    )


@dataclass(frozen=True)
class BevelGearData:
    """Size of one member of a bevel pair with intersecting axes.

    ``n_teeth`` and ``mate_teeth`` (the mating member's) with ``shaft_angle`` fix the pitch cone;
    ``module`` is the transverse module at the outer cone distance, ``pressure_angle`` the profile
    angle at the pitch cone, ``face_width`` b along the generatrix, ``spiral_angle`` Phi of eq (51)
    (on the base cone; 0 for straight teeth), ``h_a``, ``h_f`` addendum and dedendum coefficients.

    Parameters
    ----------
    n_teeth, mate_teeth : int
        Tooth numbers of this member and its mate [1], >= 3.
    module : float
        Transverse module at the outer cone distance [mm], > 0.
    pressure_angle : float
        Profile angle at the pitch cone [rad], in (0, pi/2).
    face_width : float
        b along the generatrix [mm], below the outer cone distance.
    shaft_angle : float, optional
        Sigma [rad], in (0, pi).
    spiral_angle : float, optional
        Phi on the base cone [rad], in [0, pi/2).
    h_a, h_f : float, optional
        Addendum and dedendum coefficients [in modules], > 0.

    Raises
    ------
    ValueError
        If a value is out of range.

    Examples
    --------
    The straight bevel pair of the thesis's Table 5 (39 and 32 teeth, m = 2.5 mm, 20 deg, b = 14 mm):

    >>> import math
    >>> from gearrep.surfaces.bevel import BevelGearData
    >>> g1 = BevelGearData(39, 32, 2.5, math.radians(20.0), 14.0)
    >>> round(math.degrees(g1.pitch_cone_angle), 4), round(float(g1.outer_cone_distance), 4)  # deg, mm
    (50.6307, 63.06)
    >>> round(math.degrees(g1.face_cone_angle), 2), round(math.degrees(g1.root_cone_angle), 2)  # Table 5: 52.90, 47.79
    (52.9, 47.79)
    """

    n_teeth: int
    mate_teeth: int
    module: float
    pressure_angle: float
    face_width: float
    shaft_angle: float = np.pi / 2
    spiral_angle: float = 0.0
    h_a: float = 1.0
    h_f: float = 1.25

    def __post_init__(self):
        for n in ("n_teeth", "mate_teeth"):
            v = getattr(self, n)
            if int(v) != v or v < 3:
                raise ValueError(f"{n} must be an integer >= 3, got {v!r}")
        _check_finite("module", self.module, positive=True)
        a = _check_finite("pressure_angle", self.pressure_angle)
        if not 0.0 < a < np.pi / 2:
            raise ValueError(f"pressure_angle must be in (0, pi/2) rad, got {self.pressure_angle!r}")
        s = _check_finite("shaft_angle", self.shaft_angle)
        if not 0.0 < s < np.pi:
            raise ValueError(f"shaft_angle must be in (0, pi) rad, got {self.shaft_angle!r}")
        p = _check_finite("spiral_angle", self.spiral_angle)
        if not 0.0 <= p < np.pi / 2:
            raise ValueError(f"spiral_angle must be in [0, pi/2) rad, got {self.spiral_angle!r}")
        for n in ("h_a", "h_f"):
            _check_finite(n, getattr(self, n), positive=True)
        b = _check_finite("face_width", self.face_width, positive=True)
        if not b < self.outer_cone_distance:
            raise ValueError(
                f"face_width must be < the outer cone distance {self.outer_cone_distance!r}, got {self.face_width!r}"
            )

    @property
    def pitch_cone_angle(self) -> float:
        """delta_p: tan delta_p = sin(Sigma) / (N_mate / N + cos(Sigma))."""
        S = self.shaft_angle
        return float(np.arctan2(np.sin(S), self.mate_teeth / self.n_teeth + np.cos(S)))

    @property
    def base_cone_angle(self) -> float:
        """a_b: sin a_b = sin delta_p cos alpha."""
        return float(np.arcsin(np.sin(self.pitch_cone_angle) * np.cos(self.pressure_angle)))

    @property
    def outer_cone_distance(self) -> float:
        """R_e = N m / (2 sin delta_p) (the same for both members)."""
        return 0.5 * self.n_teeth * self.module / np.sin(self.pitch_cone_angle)

    @property
    def mean_cone_distance(self) -> float:
        """R_m = R_e - b/2 (eq 51)."""
        return self.outer_cone_distance - 0.5 * self.face_width

    @property
    def addendum_angle(self) -> float:
        """atan(h_a m / R_e) [rad]."""
        return float(np.arctan(self.h_a * self.module / self.outer_cone_distance))

    @property
    def dedendum_angle(self) -> float:
        """atan(h_f m / R_e) [rad]."""
        return float(np.arctan(self.h_f * self.module / self.outer_cone_distance))

    @property
    def face_cone_angle(self) -> float:
        """Tip (face) cone angle delta_p + addendum angle (Table 5's "outer cone angle")."""
        return self.pitch_cone_angle + self.addendum_angle

    @property
    def root_cone_angle(self) -> float:
        """delta_p - dedendum angle (Table 5's "base cone angle" is this value)."""
        return self.pitch_cone_angle - self.dedendum_angle


def relief_from_length(gear: BevelGearData, length: float, amount: float, *, root: bool = False):
    """Tip (or root) relief of eq (13) with a relief length ``length`` (length units along the
    profile at the mean cone distance) and ``amount`` (length along the normal, reached at the tip):
    the polar-angle relief starts ``length / R_m`` below the face cone (above the root cone).

    Parameters
    ----------
    gear : BevelGearData
        The member.
    length : float
        Relief length along the profile at R_m [mm], > 0.
    amount : float
        Relief at the tip (root) along the normal [mm], >= 0.
    root : bool, optional
        A root relief instead.

    Returns
    -------
    TipRelief or RootRelief
        The relief in the polar angle u [rad].

    Raises
    ------
    ValueError
        If ``length`` or ``amount`` is out of range.

    Examples
    --------
    >>> import math
    >>> from gearrep.surfaces.bevel import BevelGearData, relief_from_length
    >>> gear = BevelGearData(39, 32, 2.5, math.radians(20.0), 14.0)
    >>> relief = relief_from_length(gear, 1.0, 0.01)  # 1 mm long, 0.01 mm deep
    >>> round(float(relief.length), 6), round(float(relief.u0 + relief.length - gear.face_cone_angle), 12)  # rad
    (0.017838, 0.0)
    """
    L = _check_finite("length", length, positive=True)
    c = _check_finite("amount", amount, nonneg=True)
    w = L / gear.mean_cone_distance
    if root:
        return RootRelief(gear.root_cone_angle + w, w, c)
    return TipRelief(gear.face_cone_angle - w, w, c)


class SphericalInvoluteFlank(Surface):
    """One flank of a straight (spiral_angle 0) or logarithmic-spiral bevel tooth, eq (A)-(B).

    Parameters
    ----------
    gear : BevelGearData
        The member.
    side : {1, -1}, optional
        +1 (flank on the +y_i side of the tooth centred on x_i) or -1.
    hand : {1, -1}, optional
        Sense of the spiral turn theta(v) (mating members have opposite hands).
    crowning : ParabolicCrowning, CircularCrowning, LogarithmicCrowning or None, optional
        A function of the cone distance v [mm] (give it v0 = R_m).
    relief : TipRelief or RootRelief, or a sequence of them, optional
        In the polar angle u (see :func:`relief_from_length`).
    u_min, u_max : float, optional
        Flank limits in u [rad] (defaults: max(base cone, root cone) and the face cone).

    Raises
    ------
    ValueError
        If ``gear`` is not a :class:`BevelGearData`, an option is bad or the limits are out of
        range.

    Examples
    --------
    >>> import math
    >>> import numpy as np
    >>> from gearrep.surfaces.bevel import BevelGearData, SphericalInvoluteFlank
    >>> gear = BevelGearData(39, 32, 2.5, math.radians(20.0), 14.0)  # teeth, module mm, rad, face mm
    >>> flank = SphericalInvoluteFlank(gear)
    >>> u, v = 0.5 * (flank.u_min + flank.u_max), flank.R_m  # rad, mm
    >>> bool(abs(np.linalg.norm(flank.position(u, v)) - v) < 1e-12)  # on the sphere |r| = v
    True
    >>> round(float(flank.azimuth(u, v)), 6)  # rad
    0.042569
    """

    spherical = True  #: r = v (sin u cos psi, sin u sin psi, cos u): u = polar angle, v = cone distance

    def __init__(
        self, gear: BevelGearData, side: int = 1, hand: int = 1, *, crowning=None, relief=(), u_min=None, u_max=None
    ):
        if not isinstance(gear, BevelGearData):
            raise ValueError(f"gear must be a BevelGearData, got {type(gear).__name__}")
        self.gear = gear
        self.side, self.hand, self.crowning, self.relief = _flank_options(side, hand, crowning, relief)
        self.a_b = gear.base_cone_angle
        self.sin_ab = np.sin(self.a_b)
        self._sa, self._ca = math.sin(self.a_b), math.cos(self.a_b)  # for one point on floats
        self.delta_p = gear.pitch_cone_angle
        self.R_e = gear.outer_cone_distance
        self.R_m = gear.mean_cone_distance
        self.c = np.pi / (2.0 * gear.n_teeth) + float(_sigma_derivs(self.delta_p, self.a_b)[1])
        self.k_spiral = np.tan(gear.spiral_angle) / self.sin_ab
        umin = max(self.a_b, gear.root_cone_angle) if u_min is None else _check_finite("u_min", u_min, positive=True)
        umax = gear.face_cone_angle if u_max is None else _check_finite("u_max", u_max, positive=True)
        if umin < self.a_b:
            raise ValueError(f"u_min must be >= the base cone angle {self.a_b}, got {umin!r}")
        if not umin < umax < np.pi / 2:
            raise ValueError(f"u_max must be in ({umin}, pi/2), got {umax!r}")
        self.u_min, self.u_max = float(umin), float(umax)
        self.v_min, self.v_max = self.R_e - gear.face_width, self.R_e
        self.fd_step = (1e-4 * (umax - umin), 1e-4 * gear.face_width)

    # the flank domain is a (u, v) box, as for the cylindrical flanks
    lower = InvoluteFlank.lower
    upper = InvoluteFlank.upper
    outward_sign = InvoluteFlank.outward_sign  #: -side: +1 if unit(r_u x r_v) points out of the tooth
    contains = InvoluteFlank.contains

    def twist(self, v):
        """hand * theta(v) of eq (51) and its two v-derivatives.

        Parameters
        ----------
        v : float or array_like
            Cone distance [mm].

        Returns
        -------
        theta, theta_v, theta_vv : numpy.ndarray
            [rad], [rad/mm], [rad/mm^2].
        """
        v = np.asarray(v, float)
        k = self.hand * self.k_spiral
        if k == 0.0:
            z = np.zeros_like(v)
            return z, z, z
        with np.errstate(invalid="ignore", divide="ignore"):
            return k * np.log(self.R_m / v), -k / v, k / (v * v)

    def azimuth_derivs(self, u, v):
        """psi and its partials (psi, psi_u, psi_v, psi_uu, psi_uv, psi_vv) at (u, v) (eq B).

        Parameters
        ----------
        u : float or array_like
            Polar angle [rad].
        v : float or array_like
            Cone distance [mm].

        Returns
        -------
        tuple of numpy.ndarray
            psi [rad] and its partials in u [rad] and v [mm].
        """
        u, v = _broadcast2(np.asarray(u, float), np.asarray(v, float))
        _, inv, i1, i2 = _sigma_derivs(u, self.a_b)
        dp = np.zeros(u.shape)
        dp1 = np.zeros(u.shape)
        dp2 = np.zeros(u.shape)
        for r in self.relief:
            a, b, c = r(u)
            dp, dp1, dp2 = dp + a, dp1 + b, dp2 + c
        if self.crowning is not None:
            dl, dl1, dl2 = (_shaped(x, u.shape) for x in self.crowning(v))
        else:
            dl = dl1 = dl2 = np.zeros(u.shape)
        with np.errstate(invalid="ignore", divide="ignore"):
            return self._azimuth(v, inv, i1, i2, (dp, dp1, dp2), (dl, dl1, dl2), self.twist(v), self.c, self.sin_ab)

    def _azimuth(self, v, inv, i1, i2, profile, lead, twist, c, sb):
        """psi and its partials (eq B) from I(u) and its derivatives, the profile and lead
        modifications and the twist (each with its two derivatives): arrays or Python floats."""
        (dp, dp1, dp2), (dl, dl1, dl2), (tw, tw1, tw2) = profile, lead, twist
        s = self.side
        d = dp + dl
        vsb, vv = v * sb, v * v  # each used more than once (the same products)
        psi = s * (c - inv - d / vsb) + tw
        psi_u = s * (-i1 - dp1 / vsb)
        psi_uu = s * (-i2 - dp2 / vsb)
        psi_v = s * (-(dl1 / v - d / vv) / sb) + tw1
        psi_uv = s * dp1 / (vv * sb)
        psi_vv = s * (-(dl2 / v - 2.0 * dl1 / vv + 2.0 * d / v**3) / sb) + tw2
        return psi, psi_u, psi_v, psi_uu, psi_uv, psi_vv

    def azimuth(self, u, v):
        """psi(u, v) of eq (B) [rad] (:meth:`azimuth_derivs`).

        Parameters
        ----------
        u : float or array_like
            Polar angle [rad].
        v : float or array_like
            Cone distance [mm].

        Returns
        -------
        numpy.ndarray
            psi [rad].
        """
        return self.azimuth_derivs(u, v)[0]

    def position(self, u, v) -> np.ndarray:
        u, v = _broadcast2(np.asarray(u, float), np.asarray(v, float))
        psi = self.azimuth(u, v)
        su = np.sin(u)
        return np.stack([v * su * np.cos(psi), v * su * np.sin(psi), v * np.cos(u)], axis=-1)

    def evaluate(self, u, v) -> SurfacePoint:
        """Position and analytic derivatives of (A) = v E(u, psi(u, v)) with
        E = (sin u cos psi, sin u sin psi, cos u), E_u = e_u, E_psi = sin u e_psi, E_uu = -E,
        E_upsi = cos u e_psi, E_psipsi = -sin u e_rho (e_rho = (cos psi, sin psi, 0)):
        r_u = v (E_u + E_psi psi_u), r_v = E + v E_psi psi_v,
        r_uu = v (E_uu + 2 E_upsi psi_u + E_psipsi psi_u^2 + E_psi psi_uu),
        r_uv = E_u + E_psi psi_u + v (E_upsi psi_v + E_psipsi psi_u psi_v + E_psi psi_uv),
        r_vv = 2 E_psi psi_v + v (E_psipsi psi_v^2 + E_psi psi_vv)."""
        return SurfacePoint.from_components(self.evaluate_components(u, v))

    def evaluate_components(self, u, v) -> tuple:
        """:meth:`evaluate` by components (structure of arrays, see
        :meth:`gearrep.surface.Surface.evaluate_components`): e_psi and e_rho have no axial
        component, so the axial components leave out those (zero) terms. For ``u``, ``v`` Python
        floats (one point) the same expressions are evaluated with :mod:`math` on floats; inside
        the base cone that raises ValueError (where arrays give NaN)."""
        if type(u) is float and type(v) is float:
            psi, pu, pv, puu, puv, pvv = self._azimuth_of_one_point(u, v)
            su, cu, cp, sp = math.sin(u), math.cos(u), math.cos(psi), math.sin(psi)
        else:
            u, v = _broadcast2(np.asarray(u, float), np.asarray(v, float))
            psi, pu, pv, puu, puv, pvv = self.azimuth_derivs(u, v)
            su, cu = np.sin(u), np.cos(u)
            cp, sp = np.cos(psi), np.sin(psi)
        msp, msu = -sp, -su
        # E, E_u; E_psi = sin u e_psi, E_upsi = cos u e_psi, E_psipsi = -sin u e_rho (x, y only)
        Ex, Ey, Ez = su * cp, su * sp, cu
        Eux, Euy = cu * cp, cu * sp
        Epx, Epy = su * msp, su * cp
        Eupx, Eupy = cu * msp, cu * cp
        Eppx, Eppy = msu * cp, msu * sp
        w = v
        r = (w * Ex, w * Ey, w * Ez)
        r_u = (w * (Eux + Epx * pu), w * (Euy + Epy * pu), w * msu)
        r_v = (Ex + w * Epx * pv, Ey + w * Epy * pv, Ez)
        r_uu = (
            w * (-Ex + 2.0 * Eupx * pu + Eppx * pu * pu + Epx * puu),
            w * (-Ey + 2.0 * Eupy * pu + Eppy * pu * pu + Epy * puu),
            w * -Ez,
        )
        r_uv = (
            Eux + Epx * pu + w * (Eupx * pv + Eppx * pu * pv + Epx * puv),
            Euy + Epy * pu + w * (Eupy * pv + Eppy * pu * pv + Epy * puv),
            msu,
        )
        r_vv = (
            2.0 * Epx * pv + w * (Eppx * pv * pv + Epx * pvv),
            2.0 * Epy * pv + w * (Eppy * pv * pv + Epy * pvv),
            0.0 * w,
        )
        return r, r_u, r_v, r_uu, r_uv, r_vv

    def _azimuth_of_one_point(self, u: float, v: float) -> tuple:
        """:meth:`azimuth_derivs` of one point on Python floats: the expressions of
        :func:`_sigma_derivs`, :meth:`twist` and :meth:`azimuth_derivs` in the same order (the
        modifications' own functions are called and their values taken as floats)."""
        sa, ca = self._sa, self._ca
        cs = math.cos(u) / ca
        if not cs <= 1.0 + 1e-14:  # inside the base cone (NaN on arrays)
            raise ValueError(f"u = {u!r} lies inside the base cone {self.a_b!r}")
        sig = math.acos(min(cs, 1.0))
        ss, su = math.sin(sig), math.sin(u)
        inv = sig / sa - math.atan(math.tan(sig) / sa)
        i1 = ca * ss / (sa * su)
        i2 = math.cos(sig) / (sa * ss) - ca * ss * math.cos(u) / (sa * su * su)
        dp = dp1 = dp2 = 0.0
        for rel in self.relief:
            a, b, c = rel(u)
            dp, dp1, dp2 = dp + float(a), dp1 + float(b), dp2 + float(c)
        if self.crowning is not None:
            dl, dl1, dl2 = (float(x) for x in self.crowning(v))
        else:
            dl = dl1 = dl2 = 0.0
        k = float(self.hand * self.k_spiral)
        tw = (k * math.log(float(self.R_m) / v), -k / v, k / (v * v)) if k != 0.0 else (0.0, 0.0, 0.0)
        return self._azimuth(v, inv, i1, i2, (dp, dp1, dp2), (dl, dl1, dl2), tw, float(self.c), float(self.sin_ab))

    def outward_normal(self, u, v) -> np.ndarray:
        """Unit normal pointing out of the tooth.

        Parameters
        ----------
        u : float or array_like
            Polar angle [rad].
        v : float or array_like
            Cone distance [mm].

        Returns
        -------
        numpy.ndarray
            (..., 3) unit normals.
        """
        return self.outward_sign * self.evaluate(u, v).normal

    def __repr__(self) -> str:
        g = self.gear
        return (
            f"SphericalInvoluteFlank(N={g.n_teeth}, mate={g.mate_teeth}, m={g.module}, alpha={g.pressure_angle:.6g}, "
            f"spiral={g.spiral_angle:.6g}, side={self.side}, hand={self.hand})"
        )


def mating_bevel_flanks(
    gear1: BevelGearData,
    gear2: BevelGearData,
    *,
    side: int = 1,
    hand1: int = 1,
    crowning1=None,
    relief1=(),
    crowning2=None,
    relief2=(),
):
    """The two drive flanks of a bevel pair: same ``side``, opposite spiral hands. Checks that the
    members mesh (each is the other's mate; equal module, pressure angle, shaft and spiral angle).

    Parameters
    ----------
    gear1, gear2 : BevelGearData
        The members, each the other's mate.
    side : {1, -1}, optional
        The drive side.
    hand1 : {1, -1}, optional
        Spiral hand of member 1 (member 2 has the other).
    crowning1, crowning2 : optional
        Lengthwise crowning of each member (functions of the cone distance [mm]).
    relief1, relief2 : optional
        Tip and root reliefs of each member.

    Returns
    -------
    flank1, flank2 : SphericalInvoluteFlank
        The two flanks.

    Raises
    ------
    ValueError
        If the members do not mesh or an option is bad.

    Examples
    --------
    >>> import math
    >>> from gearrep.surfaces.bevel import BevelGearData, mating_bevel_flanks
    >>> g1 = BevelGearData(39, 32, 2.5, math.radians(20.0), 14.0)  # teeth, module mm, rad, face mm
    >>> g2 = BevelGearData(32, 39, 2.5, math.radians(20.0), 14.0)
    >>> f1, f2 = mating_bevel_flanks(g1, g2)
    >>> (f1.side, f1.hand), (f2.side, f2.hand)
    ((1, 1), (1, -1))
    >>> mating_bevel_flanks(g1, g1)
    Traceback (most recent call last):
        ...
    ValueError: gear1.mate_teeth = 32 must equal gear2.n_teeth = 39 and vice versa
    """
    if not (isinstance(gear1, BevelGearData) and isinstance(gear2, BevelGearData)):
        raise ValueError("gear1 and gear2 must be BevelGearData")
    if gear1.mate_teeth != gear2.n_teeth or gear2.mate_teeth != gear1.n_teeth:
        raise ValueError(
            f"gear1.mate_teeth = {gear1.mate_teeth!r} must equal gear2.n_teeth = {gear2.n_teeth!r} and vice versa"
        )
    equal = ("module", "pressure_angle", "shaft_angle", "spiral_angle")
    return _mating_pair(
        SphericalInvoluteFlank, (gear1, gear2), equal, side, hand1, (crowning1, crowning2), (relief1, relief2)
    )
