"""Involute spur and helical tooth flanks with longitudinal crowning and tip/root relief.

Source: Temirkhan, PhD thesis 2023 (seed 003): involute profile eq (1)-(2), spur flank eq (3)-(4),
helical flank eq (5), longitudinal crowning eq (10)-(12), tip relief eq (13), the flanks with
modifications eq (57)-(58), and the gear-size table (Table 1). Standard involute geometry
(Litvin & Fuentes, "Gear Geometry and Applied Theory", 2nd ed., ch. 10 and 14) is used where
the thesis, as printed, is wrong; every correction is listed below with its evidence.

Parameters (as in the thesis, eq (35)-(36))
-------------------------------------------
``u`` is the distance of the flank point from the gear axis (the involute "radius") and ``v`` its
axial coordinate (face-width coordinate), so that in the gear's own frame S_i::

    r(u, v) = ( u cos psi(u, v),  u sin psi(u, v),  v )                                    (A)

with the polar angle::

    psi(u, v) = side * ( c - inv(u) - delta(u, v) / r_b ) + twist(v),                      (B)
    inv(u)    = tan(a_u) - a_u = sqrt(u^2 - r_b^2)/r_b - atan(sqrt(u^2 - r_b^2)/r_b),
                cos(a_u) = r_b / u                     (the polar angle of eq (3)-(4)),
    c         = s_t / (2 r_p) + inv(alpha_t)           (half tooth-thickness angle + inv at r_p).

The tooth is symmetric about the +x_i axis; ``side = +1`` is the flank on the +y_i side of that
tooth and ``side = -1`` the flank on the -y_i side. ``v`` runs over the face width
``[-b/2, b/2]`` (the mid-face plane is v = 0; the thesis measures v from the face edge,
``v_thesis = v + b/2``, so its v_o = b/2 is our v = 0).

Modifications ``delta(u, v) = delta_lead(v) + delta_profile(u)`` are material removed, measured
in the transverse plane along the profile normal: turning an involute of base radius r_b by the
angle delta / r_b moves it by exactly delta along its normal (base-pitch property), so (B) is an
exact normal offset for constant delta and a first-order one for delta varying with u. On a
helical flank the offset along the 3-D surface normal is delta * cos(beta_b).

Helix (``helix_form``):

* ``"true"`` (default): the involute helicoid, twist(v) = hand * v * tan(beta) / r_p, i.e. a
  constant lead 2 pi r_p / tan(beta) = 2 pi r_b / tan(beta_b). Two helicoids of opposite hands with
  equal normal module/pressure/helix angle are conjugate on parallel axes (line contact, TE = 0).
* ``"asin"``: eq (5)/(58) as printed, twist(v) = hand * asin(v sin(beta) / r_b). It is not a
  helicoid (see correction 3).

Corrections to the thesis (evidence in tests/unit/surfaces/test_involute.py)
----------------------------------------------------------------------------
1. Eq (1) and eq (57): the y component must read r_b (sin t - t cos t), not r_b (cos t - t sin t).
   With the printed form the point at t = 0 is (r_b, r_b), at distance sqrt(2) r_b from the axis,
   and its distance from the axis is not u of eq (2) (|r|^2 = 2 r_b^2 (cos^2 t + t^2 sin^2 t) instead
   of r_b^2 (1 + t^2)). The thesis's own numbers were computed with a true involute: the pitch-point
   example of section 6.1 (25/25 teeth, m = 2.5, 20 deg: u1 = 31.103, u2 = 31.402) satisfies
   sqrt(u1^2 - r_b^2) + sqrt(u2^2 - r_b^2) = a sin(alpha) (21.375 vs 21.376), i.e. u1, u2 are the radii
   of one point of the line of action, which holds only for the true involute.
2. Table 1: the tip diameter is d_a = d_p + 2m (pitch diameter plus two addenda), not
   "d_{1,2} + 2m" with d_{1,2} the base diameter. With the printed formula the 52/72-tooth,
   m = 1 pair of section 6.2 would have its tip circle (r_a1 = 25.43) inside its pitch circle
   (r_p1 = 26) and a negative contact ratio (-0.88): it could not mesh.
3. Eq (5)/(58) is not a helicoid: the twist asin(v sin(beta)/r_b) is not linear in v (the lead
   varies across the face, and the formula is undefined for |v| sin(beta) > r_b), and even at
   mid-face its helix angle at the pitch cylinder is atan(sin(beta) / cos(alpha_t)) (14.48 deg for
   the thesis's 14 deg example), not beta. Two such flanks with N1 != N2 are not conjugate (the
   aligned, unmodified pair has no line contact and a non-zero TE). ``helix_form="true"`` gives the
   involute helicoid; ``"asin"`` reproduces (5)/(58) for comparison.
4. Eq (57)/(58) add the modification to the Cartesian x and y components. That displaces the
   profile in a fixed direction (not along its normal) and destroys the property that u is the
   distance from the axis, on which the reduced TCA (eq 35-40) depends. Here the modification is
   applied as a rotation of the transverse section by delta/r_b (eq B), which keeps u = ``|r_xy|``
   and offsets the flank by delta along its normal.
5. Eq (12) normalises v - v_o by v_o: with the thesis's v in [0, b] and v_o = b/2 that is the half
   face width; here the half width is an explicit parameter (default b/2).

Eq (3)-(4) themselves are correct: acos((r_b/u)(cos t + t sin t)) equals inv(u) for u >= r_b (the
polar angle of the involute that starts on the x axis), i.e. the ``side = -1`` flank with c = 0.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..inputs import check_finite as _check_finite
from ..surface import Surface, SurfacePoint
from ._modifications import CircularCrowning, LogarithmicCrowning, ParabolicCrowning, RootRelief, TipRelief

__all__ = [
    "involute_polar_angle",
    "involute_xy",
    "ParabolicCrowning",
    "CircularCrowning",
    "LogarithmicCrowning",
    "TipRelief",
    "RootRelief",
    "InvoluteGearData",
    "InvoluteFlank",
    "mating_flanks",
    "standard_centre_distance",
    "undercut_limit",
]


# ----------------------------------------------------------------------------------------------
# involute function in terms of the radius u (eq 2-4)
# ----------------------------------------------------------------------------------------------
def involute_polar_angle(u, r_b):
    """Polar angle inv(u) of the involute of base radius ``r_b`` at radius ``u`` (thesis eq 2-4).

    inv(u) = tan(a_u) - a_u with cos(a_u) = r_b/u, which equals eq (4)'s
    acos((r_b/u)(cos t + t sin t)) with t = sqrt(u^2/r_b^2 - 1) (eq 2). Vectorised over ``u``;
    NaN for u < r_b (inside the base circle, where the involute does not exist).

    Parameters
    ----------
    u : float or array_like
        Radius of the flank point [length, the unit of ``r_b``].
    r_b : float
        Base radius [length], > 0.

    Returns
    -------
    numpy.ndarray
        inv(u) [rad], of the shape of ``u``.

    Raises
    ------
    ValueError
        If ``r_b`` is not a finite number > 0.

    Examples
    --------
    >>> import math
    >>> from gearrep.surfaces.involute import involute_polar_angle
    >>> r_b = 10 * math.cos(math.radians(20))  # pitch radius 10 mm, 20 deg
    >>> round(float(involute_polar_angle(10.0, r_b)), 9)  # inv(20 deg) = tan 20 deg - 20 deg
    0.014904384
    """
    r_b = _check_finite("r_b", r_b, positive=True)
    u = np.asarray(u, dtype=float)
    with np.errstate(invalid="ignore"):
        t = np.sqrt(u * u - r_b * r_b) / r_b
    return t - np.arctan(t)


def _shaped(x, shape):
    """``x`` broadcast to ``shape`` (a read-only view), or ``x`` itself where it has that shape
    already (on small batches a broadcast costs more than the arithmetic)."""
    return x if np.shape(x) == shape else np.broadcast_to(x, shape)


def _broadcast2(u, v):
    """``np.broadcast_arrays(u, v)`` of two arrays, or the two themselves where their shapes agree."""
    return (u, v) if u.shape == v.shape else np.broadcast_arrays(u, v)


def _inv_derivs(u, r_b):
    """inv(u), d inv/du = s/(r_b u), d2 inv/du2 = r_b/(s u^2) with s = sqrt(u^2 - r_b^2)."""
    with np.errstate(invalid="ignore", divide="ignore"):
        s = np.sqrt(u * u - r_b * r_b)
        t = s / r_b
        inv = t - np.arctan(t)
        d1 = s / (r_b * u)
        d2 = r_b / (s * u * u)
    return inv, d1, d2


def involute_xy(theta, r_b, corrected: bool = True):
    """Involute point of eq (1): x = r_b (cos t + t sin t), y = r_b (sin t - t cos t) (corrected).

    ``corrected=False`` returns the y component as printed in the thesis, r_b (cos t - t sin t),
    for the evidence test of correction 1.

    Parameters
    ----------
    theta : float or array_like
        The roll angle t of eq (2) [rad].
    r_b : float
        Base radius [length], > 0.
    corrected : bool, optional
        The true involute (default) or the thesis's printed y component.

    Returns
    -------
    (..., 2) numpy.ndarray
        The points (x, y) [length of ``r_b``].

    Raises
    ------
    ValueError
        If ``r_b`` is not a finite number > 0.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.surfaces.involute import involute_xy
    >>> p = involute_xy([0.0, 0.5], 10.0)
    >>> np.round(p, 6).tolist()
    [[10.0, 0.0], [11.172953, 0.406343]]
    >>> np.round(np.hypot(*p.T), 6).tolist()  # radius r_b sqrt(1 + t^2) (eq 2)
    [10.0, 11.18034]
    """
    r_b = _check_finite("r_b", r_b, positive=True)
    t = np.asarray(theta, dtype=float)
    x = r_b * (np.cos(t) + t * np.sin(t))
    y = r_b * (np.sin(t) - t * np.cos(t)) if corrected else r_b * (np.cos(t) - t * np.sin(t))
    return np.stack([x, y], axis=-1)


def _flank_options(side, hand, crowning, relief):
    """Checked (side, hand, crowning, relief tuple) of a flank: side and hand +-1, crowning a crowning
    object or None, relief a sequence of TipRelief / RootRelief (shared by the flank families)."""
    if side not in (1, -1):
        raise ValueError(f"side must be +1 or -1, got {side!r}")
    if hand not in (1, -1):
        raise ValueError(f"hand must be +1 or -1, got {hand!r}")
    if crowning is not None and not callable(crowning):
        raise ValueError("crowning must be a crowning object (callable v -> (d, d', d'')) or None")
    relief = tuple(relief)
    for r in relief:
        if not isinstance(r, (TipRelief, RootRelief)):
            raise ValueError(f"relief entries must be TipRelief or RootRelief, got {type(r).__name__}")
    return int(side), int(hand), crowning, relief


# ----------------------------------------------------------------------------------------------
# gear data (Table 1, corrected) and the flank surface
# ----------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class InvoluteGearData:
    """Size of an involute spur/helical gear (thesis Table 1, tip diameter corrected: d_a = d_p + 2m).

    Units: ``module`` and ``face_width`` [length, mm in the examples; every radius and pitch of the
    gear data is in the same unit], ``pressure_angle`` and ``helix_angle`` [rad].
    ``module`` and ``pressure_angle`` are normal values (for spur gears normal = transverse);
    ``helix_angle`` beta at the pitch cylinder. Profile shift ``x`` (coefficient), addendum and
    dedendum coefficients ``h_a``, ``h_f``, and ``thinning`` (transverse arc tooth-thickness
    reduction at the pitch circle, e.g. a backlash allowance) follow standard practice.

    Parameters
    ----------
    n_teeth : int
        Number of teeth, >= 3.
    module : float
        Normal module [length], > 0.
    pressure_angle : float
        Normal pressure angle [rad], in (0, pi/2).
    face_width : float
        Face width b [length], > 0.
    helix_angle : float, optional
        Helix angle beta at the pitch cylinder [rad], in [0, pi/2) (0: spur).
    x : float, optional
        Profile shift coefficient [1].
    h_a, h_f : float, optional
        Addendum and dedendum coefficients [1] (1 and 1.25).
    thinning : float, optional
        Transverse arc tooth-thickness reduction at the pitch circle [length].

    Raises
    ------
    ValueError
        Naming the field and its allowed range: a value not finite or out of range, a root circle
        at or below the axis, a thinning that leaves no tooth space or a pointed tooth.

    Examples
    --------
    >>> import math
    >>> from gearrep.surfaces.involute import InvoluteGearData
    >>> g = InvoluteGearData(23, 3.0, math.radians(20), 25.0)  # teeth, mm, rad, mm
    >>> float(g.r_p), float(g.r_a), round(float(g.r_b), 6), round(float(g.base_pitch), 6)  # mm
    (34.5, 37.5, 32.419395, 8.856394)
    >>> round(g.min_teeth_without_undercut, 4)
    17.0973
    """

    n_teeth: int
    module: float
    pressure_angle: float
    face_width: float
    helix_angle: float = 0.0
    x: float = 0.0
    h_a: float = 1.0
    h_f: float = 1.25
    thinning: float = 0.0

    def __post_init__(self):
        if int(self.n_teeth) != self.n_teeth or self.n_teeth < 3:
            raise ValueError(f"n_teeth must be an integer >= 3, got {self.n_teeth!r}")
        _check_finite("module", self.module, positive=True)
        a = _check_finite("pressure_angle", self.pressure_angle)
        if not 0.0 < a < np.pi / 2:
            raise ValueError(f"pressure_angle must be in (0, pi/2) rad, got {self.pressure_angle!r}")
        _check_finite("face_width", self.face_width, positive=True)
        b = _check_finite("helix_angle", self.helix_angle)
        if not 0.0 <= b < np.pi / 2:
            raise ValueError(f"helix_angle must be in [0, pi/2) rad, got {self.helix_angle!r}")
        for n in ("x", "h_a", "h_f", "thinning"):
            _check_finite(n, getattr(self, n))
        if not self.h_a > 0:
            raise ValueError(f"h_a (addendum coefficient) must be > 0, got {self.h_a!r}")
        if not self.h_f > -self.h_a:
            raise ValueError(f"h_f (dedendum coefficient) must be > -h_a = {-self.h_a!r}, got {self.h_f!r}")
        if not self.r_f > 0:
            raise ValueError(
                f"h_f = {self.h_f!r} puts the root circle at r_f = {float(self.r_f)!r} mm; allowed range: "
                f"h_f < {float(self.r_p / self.module + self.x)!r} (r_f = r_p - (h_f - x) m > 0)"
            )
        s0 = float(self.tooth_thickness + self.thinning)  # unthinned transverse thickness at the pitch circle
        p_t = float(np.pi * self.transverse_module)  # transverse circular pitch
        if not self.thinning > s0 - p_t:
            raise ValueError(
                f"thinning = {self.thinning!r} mm makes the tooth at least as thick as the circular pitch "
                f"{p_t!r} mm (no tooth space); allowed range: thinning > {s0 - p_t!r} mm"
            )
        if not self.thinning < s0:
            raise ValueError(
                f"thinning = {self.thinning!r} mm must be < {s0!r} mm, the tooth thickness at the pitch circle "
                "(allowed range: thinning < m_t (pi/2 + 2 x tan alpha_n))"
            )
        if self.r_a > self.r_b:  # the two flanks of the tooth must not cross below the tip circle
            inv_p = float(involute_polar_angle(self.r_p, self.r_b))
            inv_a = float(involute_polar_angle(self.r_a, self.r_b))
            t_max = float(s0 + 2.0 * self.r_p * (inv_p - inv_a))
            if not self.thinning < t_max:
                raise ValueError(
                    f"thinning = {self.thinning!r} mm leaves a pointed tooth (no thickness at the tip radius "
                    f"r_a = {float(self.r_a)!r} mm); allowed range: thinning < {t_max!r} mm"
                )

    @property
    def transverse_module(self) -> float:
        """Transverse module m / cos(beta) [length]."""
        return self.module / np.cos(self.helix_angle)

    @property
    def min_teeth_without_undercut(self) -> float:
        """:func:`undercut_limit` of this gear (the core reads it without importing the family)."""
        return undercut_limit(self)

    @property
    def alpha_t(self) -> float:
        """Transverse pressure angle [rad], tan(alpha_t) = tan(alpha_n)/cos(beta)."""
        return float(np.arctan(np.tan(self.pressure_angle) / np.cos(self.helix_angle)))

    @property
    def r_p(self) -> float:
        """Pitch (reference) radius N m_t / 2 [length] (Table 1: d_p = N m)."""
        return 0.5 * self.n_teeth * self.transverse_module

    @property
    def r_b(self) -> float:
        """Base radius r_p cos(alpha_t) [length] (Table 1: d_b = d_p cos alpha)."""
        return self.r_p * np.cos(self.alpha_t)

    @property
    def r_a(self) -> float:
        """Tip radius r_p + (h_a + x) m [length] (Table 1 corrected: d_a = d_p + 2m for h_a = 1, x = 0)."""
        return self.r_p + (self.h_a + self.x) * self.module

    @property
    def r_f(self) -> float:
        """Root radius r_p - (h_f - x) m [length]."""
        return self.r_p - (self.h_f - self.x) * self.module

    @property
    def beta_b(self) -> float:
        """Base helix angle [rad], tan(beta_b) = tan(beta) cos(alpha_t)."""
        return float(np.arctan(np.tan(self.helix_angle) * np.cos(self.alpha_t)))

    @property
    def tooth_thickness(self) -> float:
        """Transverse circular tooth thickness at the pitch circle m_t (pi/2 + 2 x tan alpha_n) - thinning [length]."""
        return self.transverse_module * (0.5 * np.pi + 2.0 * self.x * np.tan(self.pressure_angle)) - self.thinning

    @property
    def base_pitch(self) -> float:
        """Transverse base pitch 2 pi r_b / N [length]."""
        return 2.0 * np.pi * self.r_b / self.n_teeth

    def half_angle(self, r) -> float:
        """Half the angle the tooth subtends at radius ``r`` >= r_b [mm], rad: s/(2 r_p) + inv(alpha_t)
        - inv(alpha_r) (the flank's polar angle from the tooth's centre plane).

        Parameters
        ----------
        r : float
            Radius [length], >= r_b.

        Returns
        -------
        float
            The half angle [rad].
        """
        return float(
            self.tooth_thickness / (2.0 * self.r_p)
            + involute_polar_angle(self.r_p, self.r_b)
            - involute_polar_angle(float(r), self.r_b)
        )

    def max_flank_removal(self, r) -> float:
        """The largest material removal normal to one flank at radius ``r`` [mm] that leaves the
        tooth any thickness there, mm: an offset of an involute helicoid along its normal by d is
        a turn about the axis by d / (r_b cos(beta_b)), and the flank reaches the tooth's centre
        plane when that turn equals :meth:`half_angle` (both flanks removed alike: the tooth
        ends in a point).

        Parameters
        ----------
        r : float
            Radius [length], >= r_b.

        Returns
        -------
        float
            The removal [length].
        """
        return float(self.r_b * np.cos(self.beta_b) * self.half_angle(r))


def _flank_components(u, v, c, s, pu, pv, puu, pvv):
    """r, r_u, r_v, r_uu, r_uv, r_vv of eq (A) by components from cos/sin of psi and its partials
    (arrays or floats; see :meth:`InvoluteFlank.evaluate`): a e_r + b e_t in x, y. psi_uv = 0 (eq B
    is a function of u plus one of v), so the e_t part of r_uv is psi_v."""
    upv = u * pv
    b_u = u * pu
    a_uu, b_uu = -u * pu * pu, 2 * pu + u * puu
    a_uv = -u * pu * pv
    a_vv, b_vv = -upv * pv, u * pvv
    return (
        (u * c, u * s, v),
        (c - b_u * s, s + b_u * c, 0.0),
        (-(upv * s), upv * c, 1.0),
        (a_uu * c - b_uu * s, a_uu * s + b_uu * c, 0.0),
        (a_uv * c - pv * s, a_uv * s + pv * c, 0.0),
        (a_vv * c - b_vv * s, a_vv * s + b_vv * c, 0.0),
    )


class InvoluteFlank(Surface):
    """One flank of an involute spur or helical tooth, r(u, v) of eq (A)-(B) of the module docstring.

    Parameters
    ----------
    gear : InvoluteGearData
        The gear's size.
    side : int, optional
        +1 (flank on the +y_i side of the tooth centred on x_i) or -1.
    hand : int, optional
        +1 right-hand, -1 left-hand helix (ignored for spur gears); mating external helical
        gears have opposite hands.
    crowning : ParabolicCrowning or CircularCrowning or LogarithmicCrowning, optional
        Lengthwise crowning (eq 10-12).
    relief : sequence of TipRelief or RootRelief, optional
        Profile relief (eq 13).
    helix_form : {"true", "asin"}, optional
        "true" (involute helicoid) or "asin" (eq 5/58 as printed: twist asin(v sin(beta) / r_b)).
    u_min, u_max : float, optional
        Flank limits in u [length] (defaults: max(r_b, r_f) = start of the involute above the
        root or base circle, and r_a). Evaluation exactly at u = r_b is singular (cusp).

    Raises
    ------
    ValueError
        If an argument is of the wrong kind or out of range (``u_min < r_b``, ``u_max <= u_min``).

    Examples
    --------
    >>> import math
    >>> import numpy as np
    >>> from gearrep.surfaces.involute import InvoluteFlank, InvoluteGearData
    >>> flank = InvoluteFlank(InvoluteGearData(23, 3.0, math.radians(20), 25.0))
    >>> np.round(flank.lower, 6).tolist(), flank.upper.tolist()  # (u, v) domain [mm]
    ([32.419395, -12.5], [37.5, 12.5])
    >>> p = flank.evaluate(34.5, 0.0)  # the pitch circle at mid-face
    >>> round(float(np.hypot(*p.r[:2])), 12), bool(flank.contains(34.5, 0.0))
    (34.5, True)
    """

    cylindrical = True  #: r = (u cos psi, u sin psi, v): u = radius, v = axial coordinate

    def __init__(
        self,
        gear: InvoluteGearData,
        side: int = 1,
        hand: int = 1,
        *,
        crowning=None,
        relief=(),
        helix_form: str = "true",
        u_min=None,
        u_max=None,
    ):
        if not isinstance(gear, InvoluteGearData):
            raise ValueError(f"gear must be an InvoluteGearData, got {type(gear).__name__}")
        if helix_form not in ("true", "asin"):
            raise ValueError(f"helix_form must be 'true' or 'asin', got {helix_form!r}")
        self.gear = gear
        self.side, self.hand, self.crowning, self.relief = _flank_options(side, hand, crowning, relief)
        self.helix_form = helix_form
        self.r_b = gear.r_b
        self.r_p = gear.r_p
        self.c = gear.tooth_thickness / (2.0 * gear.r_p) + float(involute_polar_angle(gear.r_p, gear.r_b))
        umin = max(gear.r_b, gear.r_f) if u_min is None else _check_finite("u_min", u_min, positive=True)
        umax = gear.r_a if u_max is None else _check_finite("u_max", u_max, positive=True)
        if umin < gear.r_b:
            raise ValueError(f"u_min must be >= r_b = {gear.r_b}, got {umin!r}")
        if not umax > umin:
            raise ValueError(f"u_max must be > u_min = {umin}, got {umax!r}")
        self.u_min, self.u_max = float(umin), float(umax)
        self.v_min, self.v_max = -0.5 * gear.face_width, 0.5 * gear.face_width
        self.fd_step = (1e-4 * gear.r_p, 1e-4 * gear.face_width)
        self._tan_b = np.tan(gear.helix_angle)
        self._sin_b = np.sin(gear.helix_angle)

    # -- domain -----------------------------------------------------------------------------
    @property
    def lower(self) -> np.ndarray:
        """Lower bounds (u_min, v_min) of the flank parameter domain."""
        return np.array([self.u_min, self.v_min])

    @property
    def upper(self) -> np.ndarray:
        """Upper bounds (u_max, v_max) of the flank parameter domain."""
        return np.array([self.u_max, self.v_max])

    @property
    def outward_sign(self) -> int:
        """+1 if unit(r_u x r_v) points out of the tooth material, else -1 (here: -side)."""
        return -self.side

    def contains(self, u, v, tol: float = 1e-12) -> np.ndarray:
        """True where (u, v) lies in the flank domain (closed, with relative slack ``tol``).

        Parameters
        ----------
        u, v : float or array_like
            Flank parameters [length].
        tol : float, optional
            Relative slack.

        Returns
        -------
        numpy.ndarray of bool
            Of the broadcast shape of ``u`` and ``v``.
        """
        u = np.asarray(u, float)
        v = np.asarray(v, float)
        lo, hi = self.lower, self.upper
        s = tol * (1.0 + np.abs(np.concatenate([lo, hi])))
        return (u >= lo[0] - s[0]) & (u <= hi[0] + s[2]) & (v >= lo[1] - s[1]) & (v <= hi[1] + s[3])

    # -- polar angle and its derivatives (eq B) ---------------------------------------------
    def twist(self, v):
        """Helix twist of the transverse section at axial coordinate v, and its two derivatives.

        Parameters
        ----------
        v : float or array_like
            Axial coordinate [length].

        Returns
        -------
        tuple
            (twist [rad], d twist/dv [rad/length], d2 twist/dv2 [rad/length^2]).
        """
        if type(v) is float and self.gear.helix_angle == 0.0:  # one point of a spur flank
            return 0.0, 0.0, 0.0
        v = np.asarray(v, dtype=float)
        if self.gear.helix_angle == 0.0:
            z = np.zeros_like(v)
            return z, z, z
        if self.helix_form == "true":
            k = self.hand * self._tan_b / self.r_p
            return k * v, np.full_like(v, k), np.zeros_like(v)
        a = self._sin_b / self.r_b
        w = a * v
        with np.errstate(invalid="ignore"):
            q = 1.0 - w * w
            return self.hand * np.arcsin(w), self.hand * a / np.sqrt(q), self.hand * a * a * w / q**1.5

    def polar_angle_derivs(self, u, v):
        """psi and its partials (psi, psi_u, psi_v, psi_uu, psi_uv, psi_vv) at (u, v) (eq B).

        Parameters
        ----------
        u, v : float or array_like
            Flank parameters: radius and axial coordinate [length].

        Returns
        -------
        tuple of numpy.ndarray
            psi [rad] and its first and second partials [rad/length, rad/length^2].
        """
        u = np.asarray(u, dtype=float)
        v = np.asarray(v, dtype=float)
        u, v = _broadcast2(u, v)
        inv, i1, i2 = _inv_derivs(u, self.r_b)
        if self.crowning is not None:
            dl, dl1, dl2 = (_shaped(x, u.shape) for x in self.crowning(v))
        else:
            dl = dl1 = dl2 = 0.0
        tw, tw1, tw2 = self.twist(v)
        s, rb = self.side, self.r_b
        if self.relief:
            dp = np.zeros_like(u)
            dp1 = np.zeros_like(u)
            dp2 = np.zeros_like(u)
            for r in self.relief:
                a, b, c = r(u)
                dp, dp1, dp2 = dp + a, dp1 + b, dp2 + c
            psi = s * (self.c - inv - (dp + dl) / rb) + tw
            psi_u = s * (-i1 - dp1 / rb)
            psi_uu = s * (-i2 - dp2 / rb)
        else:  # the same numbers without the zero profile terms (0 + dl = dl, -i - 0 / rb = -i)
            psi = s * (self.c - inv - dl / rb) + tw
            psi_u = s * -i1
            psi_uu = s * -i2
        psi_v = tw1 - s * dl1 / rb
        psi_vv = tw2 - s * dl2 / rb
        return psi, psi_u, _shaped(psi_v, u.shape), psi_uu, np.zeros_like(u), _shaped(psi_vv, u.shape)

    def polar_angle(self, u, v):
        """Polar angle psi(u, v) of the flank point in the gear frame (eq B).

        Parameters
        ----------
        u, v : float or array_like
            Flank parameters: radius and axial coordinate [length].

        Returns
        -------
        numpy.ndarray
            psi [rad].
        """
        return self.polar_angle_derivs(u, v)[0]

    # -- surface ----------------------------------------------------------------------------
    def position(self, u, v) -> np.ndarray:
        """r(u, v) = (u cos psi, u sin psi, v) (eq A; thesis eq 3-5 with corrections 1, 3, 4)."""
        u = np.asarray(u, dtype=float)
        v = np.asarray(v, dtype=float)
        u, v = _broadcast2(u, v)
        psi = self.polar_angle(u, v)
        return np.stack([u * np.cos(psi), u * np.sin(psi), v], axis=-1)

    def evaluate(self, u, v) -> SurfacePoint:
        """Position and analytic first and second partial derivatives (eq A-B differentiated).

        With e_r = (cos psi, sin psi, 0), e_t = (-sin psi, cos psi, 0), k = (0, 0, 1):
        r_u = e_r + u psi_u e_t, r_v = u psi_v e_t + k,
        r_uu = -u psi_u^2 e_r + (2 psi_u + u psi_uu) e_t,
        r_uv = -u psi_u psi_v e_r + (psi_v + u psi_uv) e_t,
        r_vv = -u psi_v^2 e_r + u psi_vv e_t.
        """
        # the components of evaluate_components (arrays: no one-point float path), stacked
        return SurfacePoint.from_components(
            self.evaluate_components(np.asarray(u, dtype=float), np.asarray(v, dtype=float))
        )

    def evaluate_components(self, u, v) -> tuple:
        """:meth:`evaluate` by components (structure of arrays, see
        :meth:`gearrep.surface.Surface.evaluate_components`): the same expressions without the
        (..., 3) arrays; the constant axial components are the floats 0.0 and 1.0. For ``u``, ``v``
        Python floats (one point) the same expressions are evaluated with :mod:`math` on floats;
        inside the base circle that raises ValueError (where arrays give NaN)."""
        if type(u) is float and type(v) is float:
            return self._components_of_one_point(u, v)
        u = np.asarray(u, dtype=float)
        v = np.asarray(v, dtype=float)
        u, v = _broadcast2(u, v)
        psi, pu, pv, puu, _, pvv = self.polar_angle_derivs(u, v)
        return _flank_components(u, v, np.cos(psi), np.sin(psi), pu, pv, puu, pvv)

    def _components_of_one_point(self, u: float, v: float) -> tuple:
        """:meth:`evaluate_components` of one point on Python floats: the expressions of
        :func:`_inv_derivs`, :meth:`polar_angle_derivs` and :meth:`evaluate_components` in the
        same order (the modifications' own functions are called and their values taken as floats)."""
        rb = float(self.r_b)  # Python floats throughout: no numpy scalar (and no numpy warning) enters
        sq = math.sqrt(u * u - rb * rb)
        t = sq / rb
        inv, i1, i2 = t - math.atan(t), sq / (rb * u), rb / (sq * u * u)
        if self.crowning is not None:
            dl, dl1, dl2 = self.crowning(v)
            dl, dl1, dl2 = float(dl), float(dl1), float(dl2)
        else:
            dl = dl1 = dl2 = 0.0
        tw, tw1, tw2 = self.twist(v)
        tw, tw1, tw2 = float(tw), float(tw1), float(tw2)
        s = self.side
        if self.relief:
            dp = dp1 = dp2 = 0.0
            for r in self.relief:
                a, b, c = r(u)
                dp, dp1, dp2 = dp + float(a), dp1 + float(b), dp2 + float(c)
            psi = s * (float(self.c) - inv - (dp + dl) / rb) + tw
            pu = s * (-i1 - dp1 / rb)
            puu = s * (-i2 - dp2 / rb)
        else:
            psi = s * (float(self.c) - inv - dl / rb) + tw
            pu = s * -i1
            puu = s * -i2
        pv = tw1 - s * dl1 / rb
        pvv = tw2 - s * dl2 / rb
        return _flank_components(u, v, math.cos(psi), math.sin(psi), pu, pv, puu, pvv)

    def outward_normal(self, u, v) -> np.ndarray:
        """Unit normal pointing out of the tooth material.

        Parameters
        ----------
        u, v : float or array_like
            Flank parameters: radius and axial coordinate [length].

        Returns
        -------
        numpy.ndarray
            Unit normals of shape S + (3,), S the broadcast shape of ``u`` and ``v``.
        """
        return self.outward_sign * self.evaluate(u, v).normal

    def helix_angle_at(self, radius, v=0.0):
        """Helix angle of the flank's helix at ``radius`` and axial position v: atan(radius dpsi/dv).

        Parameters
        ----------
        radius : float or array_like
            Radius [length].
        v : float, optional
            Axial position [length].

        Returns
        -------
        numpy.ndarray
            The helix angle [rad], >= 0.

        Examples
        --------
        >>> import math
        >>> from gearrep.surfaces.involute import InvoluteFlank, InvoluteGearData
        >>> g = InvoluteGearData(23, 3.0, math.radians(20), 25.0, helix_angle=math.radians(15))
        >>> round(math.degrees(float(InvoluteFlank(g).helix_angle_at(g.r_p))), 9)  # beta at r_p
        15.0
        """
        radius = np.asarray(radius, dtype=float)
        _, tw1, _ = self.twist(np.broadcast_to(np.asarray(v, float), radius.shape))
        return np.arctan(np.abs(radius * tw1))

    def __repr__(self) -> str:
        g = self.gear
        return (
            f"InvoluteFlank(N={g.n_teeth}, m={g.module}, alpha={g.pressure_angle:.6g}, beta={g.helix_angle:.6g}, "
            f"side={self.side}, hand={self.hand}, helix_form={self.helix_form!r})"
        )


def mating_flanks(
    gear1: InvoluteGearData,
    gear2: InvoluteGearData,
    *,
    side: int = 1,
    hand1: int = 1,
    crowning1=None,
    crowning2=None,
    relief1=(),
    relief2=(),
    helix_form: str = "true",
):
    """The two drive flanks of an external involute pair: same ``side``, opposite hands. Their
    parameters are u = radius and v = axial coordinate [length of the gear data, mm in the examples].

    Checks that the pair can mesh (same normal module, pressure angle and helix angle).

    Parameters
    ----------
    gear1, gear2 : InvoluteGearData
        Pinion and gear.
    side : int, optional
        The drive side, +1 or -1, of both flanks.
    hand1 : int, optional
        The pinion's hand (+1 right, -1 left); the gear gets the other one.
    crowning1, crowning2 : crowning, optional
        Lengthwise crowning of each member (:class:`ParabolicCrowning`, ...).
    relief1, relief2 : sequence of TipRelief or RootRelief, optional
        Profile relief of each member.
    helix_form : {"true", "asin"}, optional
        See :class:`InvoluteFlank`.

    Returns
    -------
    tuple of InvoluteFlank
        (pinion flank, gear flank).

    Raises
    ------
    ValueError
        If the two gears' normal module, pressure angle or helix angle differ (relative 1e-12),
        naming the attribute and both values, or a flank argument is bad.

    Examples
    --------
    >>> import math
    >>> from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks
    >>> g1 = InvoluteGearData(23, 3.0, math.radians(20), 25.0)
    >>> g2 = InvoluteGearData(41, 3.0, math.radians(20), 25.0)
    >>> f1, f2 = mating_flanks(g1, g2, crowning1=ParabolicCrowning(1e-4))
    >>> f1.side, f2.side, f1.hand, f2.hand
    (1, 1, 1, -1)
    >>> mating_flanks(g1, InvoluteGearData(41, 2.5, math.radians(20), 25.0))
    Traceback (most recent call last):
        ...
    ValueError: gear1.module = 3.0 and gear2.module = 2.5 must be equal for meshing
    """
    equal = ("module", "pressure_angle", "helix_angle")
    return _mating_pair(
        InvoluteFlank,
        (gear1, gear2),
        equal,
        side,
        hand1,
        (crowning1, crowning2),
        (relief1, relief2),
        helix_form=helix_form,
    )


def _mating_pair(flank_type, gears, equal, side, hand1, crownings, reliefs, **options):
    """The two drive flanks ``flank_type(gear, side, hand, crowning=, relief=, **options)`` of the
    pair ``gears`` (with their ``crownings`` and ``reliefs``): same ``side``, opposite hands, once
    the attributes ``equal`` of the two gears agree (relative 1e-12; else a ValueError naming the
    attribute and both values). Shared by :func:`mating_flanks` and
    :func:`gearrep.surfaces.bevel.mating_bevel_flanks`."""
    gear1, gear2 = gears
    for name in equal:
        a, b = getattr(gear1, name), getattr(gear2, name)
        if not np.isclose(a, b, rtol=1e-12, atol=0):
            raise ValueError(f"gear1.{name} = {a!r} and gear2.{name} = {b!r} must be equal for meshing")
    f1 = flank_type(gear1, side, hand1, crowning=crownings[0], relief=reliefs[0], **options)
    f2 = flank_type(gear2, side, -hand1, crowning=crownings[1], relief=reliefs[1], **options)
    return f1, f2


def standard_centre_distance(gear1: InvoluteGearData, gear2: InvoluteGearData) -> float:
    """Reference centre distance r_p1 + r_p2 of an external pair (zero profile shift sum).

    Parameters
    ----------
    gear1, gear2 : InvoluteGearData
        Pinion and gear.

    Returns
    -------
    float
        The centre distance [length of the gear data].

    Examples
    --------
    >>> import math
    >>> from gearrep.surfaces.involute import InvoluteGearData, standard_centre_distance
    >>> g1 = InvoluteGearData(52, 1.0, math.radians(20), 11.42)
    >>> g2 = InvoluteGearData(72, 1.0, math.radians(20), 11.42)
    >>> float(standard_centre_distance(g1, g2))  # mm
    62.0
    """
    return gear1.r_p + gear2.r_p


def undercut_limit(gear: InvoluteGearData) -> float:
    """Smallest tooth number the generating rack cuts without undercut: 2 (h_a - x) cos(beta) / sin^2(alpha_t).

    The rack's addendum ``h_a`` (module units, the gear's addendum coefficient) less the profile
    shift ``x`` must not reach below the interference point r_p sin^2(alpha_t) of the line of action.
    Below this tooth number the root of the flank is cut away and the involute flank of
    :class:`InvoluteFlank` no longer describes the tooth near its base circle.

    Parameters
    ----------
    gear : InvoluteGearData
        The gear (its addendum, profile shift, helix and pressure angles).

    Returns
    -------
    float
        The limiting tooth number (not rounded).

    Raises
    ------
    ValueError
        If ``gear`` is not an :class:`InvoluteGearData`.

    Examples
    --------
    >>> import math
    >>> from gearrep.surfaces.involute import InvoluteGearData, undercut_limit
    >>> round(undercut_limit(InvoluteGearData(23, 3.0, math.radians(20), 25.0)), 4)  # 2 / sin^2(20 deg)
    17.0973
    """
    if not isinstance(gear, InvoluteGearData):
        raise ValueError(f"gear must be an InvoluteGearData, got {type(gear).__name__}")
    return float(2.0 * (gear.h_a - gear.x) * np.cos(gear.helix_angle) / np.sin(gear.alpha_t) ** 2)
