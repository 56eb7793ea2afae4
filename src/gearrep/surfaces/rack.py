"""Rack-cutter surfaces: straight (involute-generating) and parabolic normal profiles.

Source: seed 002 (NASA CR-2000-209415), sec. 2.1-2.3: the rack-cutter surface is a cylinder
whose generatrix is the skew tooth direction a-a (helix angle beta) and whose normal section is
the profile,

    r_a(u) = [u, a u^2, 0, 1]^T                                 (seed 002 eq 1.1, 2.2.1)
    r_c(u, theta) = M_cb(theta) M_ba r_a(u)                     (seed 002 eq 2.2.2-2.2.3)
    N_c = L_cb L_ba N_a,   N_a = k_a x dr_a/du                  (seed 002 eq 2.2.4-2.2.5)

with theta = |O_c O_b| the displacement along the tooth direction. The straight rack of an
involute gear is the same construction with a straight normal profile at the normal pressure
angle alpha_n (GGAT ch. on involute helical gears: a rack-cutter with a straight normal
profile generates an involute helicoid, tested in tests/unit/core/test_envelope.py).

Frames (the figures of seed 002 are not in the text, so they are fixed here and used by
:func:`gearrep.motion.rack_generation_motion`):

* S_c (rack): the pitch plane is x_c = 0; x_c points AWAY from the generated member (the member
  lies on x_c < 0); y_c is the direction of the rack's translation; z_c is parallel to the
  member's axis.
* The tooth direction is t = (0, sin beta, cos beta); the normal section S_b has axes
  x_b = x_c (tooth height), y_b = (0, cos beta, -sin beta) (in the pitch plane, normal to the
  teeth) and z_b = t. So r_c(u, theta) = x_b(u) e_x + y_b(u) e_yb + theta t.
* Straight profile: (x_b, y_b) = (u cos alpha_n, y0 + side u sin alpha_n): u is the signed
  distance from the pitch line along the profile, u > 0 away from the member (the rack
  dedendum, which generates the member's addendum); side = +1 / -1 picks the flank whose
  tooth thickness grows / shrinks with x_b (with the member at x_c < 0, side = +1 is the
  right-hand flank of a rack tooth centred at y_b < y0). The profile crosses the pitch line at
  y_b = y0.
* Parabolic profile (seed 002 eq 2.2.1, fig. 1.4, 2.7.1): the parabola x_a = u, y_a = a u^2
  has its vertex at the design point Q, x_a along the tangent of the straight profile above
  (inclined at alpha_n to the tooth height), and y_a along the profile normal at Q, oriented
  from Q towards the pitch point P = (0, y0); |QP| = l (seed 002 sec. 2.7: l = cos(alpha_n)/P_n,
  see :func:`vertex_pitch_distance`). So the common normal at Q passes through P, and for
  a > 0 the centre of curvature C (|QC| = 1/(2a), seed 002 eq 2.7.4) lies on the same ray beyond or before P. The
  placement reproduces the principal curvatures of seed 002 sec. 2.5 (tested) when the pinion
  is generated on the side x_c < 0 and the gear on x_c > 0
  (:func:`gearrep.motion.rack_generation_motion`, ``member_side``): Q lies at
  x_b(Q) = l sin alpha_n > 0, i.e. in the pinion's addendum and the gear's dedendum.

* Circular-arc profile (:class:`CircularArcRackCutter`; the racks of the Novikov-Wildhaber
  versions 1-2 of seed 002 sec. 6.2, fig. 6.2.1): the circle through Q with the same tangent and
  the same curvature at Q as the parabola with a = 1/(2 rho) (its osculating circle), centre
  C = Q + rho y_a, parameterised by the arc length u from Q. With l = rho the centre is the pitch
  point P: the placement seed 002 sec. 6.2 states for the arcs that generate convex addenda.
* l is signed for both curved profiles: l > 0 puts Q above the pitch line (x_b > 0, the pinion's
  addendum, seed 002 sec. 2), l < 0 below it (the pinion's dedendum).

Normals: N = r_u x r_theta = y_b'(u) e_x - x_b'(u) e_yb (since e_x x t = -e_yb, e_yb x t = e_x);
for the straight profile N = side sin(alpha_n) e_x - cos(alpha_n) e_yb, always towards -y_b.

Units: lengths in the design data's unit (inches for seed 002, whose P_n is in 1/in).
"""

from __future__ import annotations

import numpy as np

from ..surface import Surface, SurfacePoint

__all__ = [
    "RackCutter",
    "StraightRackCutter",
    "ParabolicRackCutter",
    "CircularArcRackCutter",
    "vertex_pitch_distance",
]


def _angle(x, name, lo, hi, lo_open=True, hi_open=True):
    x = float(x)
    ok = np.isfinite(x) and (x > lo if lo_open else x >= lo) and (x < hi if hi_open else x <= hi)
    if not ok:
        lb = "(" if lo_open else "["
        rb = ")" if hi_open else "]"
        raise ValueError(f"{name} must be in {lb}{lo:.6g}, {hi:.6g}{rb} rad, got {x!r}")
    return x


def _finite(x, name):
    x = float(x)
    if not np.isfinite(x):
        raise ValueError(f"{name} must be finite, got {x!r}")
    return x


def _side(side):
    if side not in (1, -1):
        raise ValueError(f"side must be +1 or -1, got {side!r}")
    return int(side)


def vertex_pitch_distance(alpha_n: float, P_n: float) -> float:
    """Distance l = |QP| from the vertex Q of the parabolic profile to the pitch point P,
    cos(alpha_n) / P_n (seed 002 sec. 2.7 item 2; P_n normal diametral pitch, 1/in; l in
    inches).

    Parameters
    ----------
    alpha_n : float
        Normal pressure angle [rad].
    P_n : float
        Normal diametral pitch [1/in], > 0.

    Returns
    -------
    float
        l [in].

    Raises
    ------
    ValueError
        If ``P_n`` is not finite and > 0.

    Examples
    --------
    >>> import math
    >>> from gearrep.surfaces.rack import vertex_pitch_distance
    >>> round(vertex_pitch_distance(math.radians(25), 5.0), 9)  # in
    0.181261557
    """
    _angle(alpha_n, "alpha_n", 0.0, np.pi / 2)
    if not (np.isfinite(P_n) and P_n > 0):
        raise ValueError(f"P_n (normal diametral pitch) must be finite and > 0, got {P_n!r}")
    return float(np.cos(alpha_n) / P_n)


class RackCutter(Surface):
    """A rack-cutter cylinder r_c(u, theta) = x_b(u) e_x + y_b(u) e_yb + theta t (module doc;
    seed 002 eq 2.2.3) with analytic first and second derivatives.

    Subclasses define the normal profile by :meth:`profile` returning (x, y, x', y', x'', y'')
    as functions of u.

    Parameters
    ----------
    beta : float, optional
        Helix angle of the rack teeth [rad], in (-pi/2, pi/2).

    Raises
    ------
    ValueError
        If ``beta`` is out of range.

    Examples
    --------
    >>> import math
    >>> from gearrep.surfaces.rack import StraightRackCutter
    >>> rack = StraightRackCutter(math.radians(20))  # a subclass: the straight profile
    >>> [round(float(x), 6) for x in rack.profile(0.5)[:4]]  # x, y [length], x', y'
    [0.469846, 0.17101, 0.939693, 0.34202]
    """

    def __init__(self, beta: float = 0.0):
        self.beta = _angle(beta, "beta (helix angle)", -np.pi / 2, np.pi / 2)
        sb, cb = np.sin(self.beta), np.cos(self.beta)
        self._sb, self._cb = float(sb), float(cb)
        self.e_x = np.array([1.0, 0.0, 0.0])
        self.e_yb = np.array([0.0, cb, -sb])  # normal to the teeth, in the pitch plane
        self.t = np.array([0.0, sb, cb])  # tooth direction a-a

    def _place_q(self, alpha_n, l, y0, side):
        """Validate and set the design point of a curved profile (module doc): alpha_n, signed l,
        y0, side, the axes x_a (``tangent_q``) and y_a (``normal_q``, from Q towards P for l > 0)
        in (x_b, y_b), and Q = P - l y_a (``q_point``)."""
        self.alpha_n = _angle(alpha_n, "alpha_n (normal pressure angle)", 0.0, np.pi / 2)
        self.l = _finite(l, "l (|QP|)")
        self.y0 = _finite(y0, "y0")
        self.side = _side(side)
        ca, sa = np.cos(self.alpha_n), np.sin(self.alpha_n)
        s = self.side
        self.tangent_q = np.array([ca, s * sa])
        self.normal_q = np.array([-sa, s * ca])
        self.q_point = np.array([0.0, self.y0]) - self.l * self.normal_q

    def profile(self, u):  # pragma: no cover - abstract
        """The normal profile at u and its first two derivatives.

        Parameters
        ----------
        u : float or array_like
            Profile parameter [length].

        Returns
        -------
        tuple
            (x, y [length], x', y' [1], x'', y'' [1/length]).

        Raises
        ------
        NotImplementedError
            On the base class.
        """
        raise NotImplementedError

    def _combine(self, x, y, theta):
        return x[..., None] * self.e_x + y[..., None] * self.e_yb + np.asarray(theta)[..., None] * self.t

    def position(self, u, theta):
        u, theta = np.broadcast_arrays(np.asarray(u, float), np.asarray(theta, float))
        x, y = self.profile(u)[:2]
        return self._combine(x, y, theta)

    def evaluate(self, u, theta) -> SurfacePoint:
        """Position and analytic derivatives: r_u = x' e_x + y' e_yb, r_theta = t,
        r_uu = x'' e_x + y'' e_yb, r_utheta = r_thetatheta = 0."""
        u, theta = np.broadcast_arrays(np.asarray(u, float), np.asarray(theta, float))
        x, y, xu, yu, xuu, yuu = self.profile(u)
        zero = np.zeros(u.shape + (3,))
        r = self._combine(x, y, theta)
        r_u = xu[..., None] * self.e_x + yu[..., None] * self.e_yb
        r_t = np.broadcast_to(self.t, u.shape + (3,)).copy()
        r_uu = xuu[..., None] * self.e_x + yuu[..., None] * self.e_yb
        return SurfacePoint(r, r_u, r_t, r_uu, zero, zero.copy())

    def evaluate_components(self, u, theta) -> tuple:
        """:meth:`evaluate` by components (structure of arrays, no (..., 3) arrays; the same
        values): with e_x = (1, 0, 0), e_yb = (0, cos b, -sin b) and t = (0, sin b, cos b),
        r = (x, y cos b + theta sin b, -y sin b + theta cos b), r_u = (x', y' cos b, -y' sin b),
        r_theta = t, r_uu = (x'', y'' cos b, -y'' sin b) and r_utheta = r_thetatheta = 0. Python
        floats u, theta (one point) give floats."""
        cb, sb = self._cb, self._sb
        if type(u) is float and type(theta) is float:
            zero, s_, c_ = 0.0, sb, cb
        else:
            u, theta = np.broadcast_arrays(np.asarray(u, float), np.asarray(theta, float))
            zero, s_, c_ = np.zeros(u.shape), np.full(u.shape, sb), np.full(u.shape, cb)
        x, y, xu, yu, xuu, yuu = self.profile(u)
        return (
            (x, y * cb + theta * sb, y * -sb + theta * cb),
            (xu, yu * cb, yu * -sb),
            (zero, s_, c_),
            (xuu, yuu * cb, yuu * -sb),
            (zero, zero, zero),
            (zero, zero, zero),
        )

    def pitch_crossing(self, u):
        """Where the normal of the profile at u meets the pitch line x_b = 0, as y_b, and its first
        two derivatives in u: y_P = y_b + x_b x_b' / y_b' (the normal direction is (y_b', -x_b')).
        The rolling angle of the generating motion is linear in it
        (:meth:`gearrep.surfaces.novikov.RackGeneratedFlank.rolling_angle`). This base form takes
        the third derivatives of the profile as zero (straight and parabolic profiles);
        :class:`CircularArcRackCutter` overrides it. A Python float u gives floats (a zero y_b'
        then raises ZeroDivisionError; arrays give inf or NaN there).

        Parameters
        ----------
        u : float or array_like
            Profile parameter [length].

        Returns
        -------
        tuple
            (y_P [length], dy_P/du [1], d2y_P/du2 [1/length]).

        Raises
        ------
        ZeroDivisionError
            For a Python float u where y_b' = 0.
        """
        if type(u) is float:
            return self._pitch_crossing(*self.profile(u))
        with np.errstate(divide="ignore", invalid="ignore"):
            return self._pitch_crossing(*self.profile(np.asarray(u, float)))

    @staticmethod
    def _pitch_crossing(x, y, x1, y1, x2, y2):
        P, P1, P2 = x * x1, x1 * x1 + x * x2, 3.0 * x1 * x2  # x_b x_b' and derivatives (x''' = 0)
        Q, Q1 = y1, y2  # y_b' and its derivative (y''' = 0)
        h = P / Q
        h1 = (P1 * Q - P * Q1) / Q**2
        h2 = (P2 * Q**2 - 2.0 * P1 * Q * Q1 + 2.0 * P * Q1**2) / Q**3
        return y + h, y1 + h1, y2 + h2

    def profile_curvature(self, u):
        """Signed curvature of the normal profile, (x'y'' - y'x'') / |r_u|^3 (positive when it
        turns towards the normal N = r_u x r_theta).

        Parameters
        ----------
        u : float or array_like
            Profile parameter [length].

        Returns
        -------
        numpy.ndarray
            The curvature [1/length].
        """
        u = np.asarray(u, float)
        _, _, xu, yu, xuu, yuu = self.profile(u)
        return (xu * yuu - yu * xuu) / np.hypot(xu, yu) ** 3


class StraightRackCutter(RackCutter):
    """Rack-cutter with a straight normal profile at pressure angle alpha_n (generates an
    involute helicoid, transverse pressure angle tan(alpha_t) = tan(alpha_n)/cos(beta)).

    Parameters
    ----------
    alpha_n : normal pressure angle, in (0, pi/2) rad
    beta : helix angle of the rack teeth, in (-pi/2, pi/2) rad (beta > 0 generates a
        right-hand member with :func:`gearrep.motion.rack_generation_motion` and
        member_side = -1, a left-hand one with member_side = +1)
    y0 : where the profile crosses the pitch line, along y_b (length)
    side : +1 or -1, the flank (module doc)

    Raises
    ------
    ValueError
        If an angle is out of range, ``y0`` is not finite or ``side`` is not +-1.

    Examples
    --------
    >>> import math
    >>> from gearrep.surfaces.rack import StraightRackCutter
    >>> rack = StraightRackCutter(math.radians(20))
    >>> float(rack.profile_curvature(0.5)), [round(float(x), 6) for x in rack.pitch_crossing(0.5)]
    (0.0, [1.461902, 2.923804, 0.0])
    """

    def __init__(self, alpha_n: float, beta: float = 0.0, y0: float = 0.0, side: int = 1):
        super().__init__(beta)
        self.alpha_n = _angle(alpha_n, "alpha_n (normal pressure angle)", 0.0, np.pi / 2)
        self.y0 = _finite(y0, "y0")
        self.side = _side(side)

    def profile(self, u):
        u = np.asarray(u, float)
        ca, sa = np.cos(self.alpha_n), np.sin(self.alpha_n)
        z = np.zeros_like(u)
        return (u * ca, self.y0 + self.side * u * sa, z + ca, z + self.side * sa, z, z.copy())


class ParabolicRackCutter(RackCutter):
    """Rack-cutter with the parabolic normal profile x_a = u, y_a = a u^2 of seed 002
    (eq 1.1, 2.2.1-2.2.5), placed as in the module doc.

    Parameters
    ----------
    a : parabola coefficient (1/length); the profile curvature at Q is 2a (seed 002
        eq 2.5.2, 2.7.4); a > 0 bends the profile towards P; any finite value (a = 0 gives a
        straight profile offset by l from P)
    alpha_n : normal pressure angle, in (0, pi/2) rad
    l : |QP| (length, finite), signed (module doc): >= 0 puts Q above the pitch line, the
        placement of seed 002 sec. 2 (l = cos(alpha_n)/P_n, :func:`vertex_pitch_distance`);
        < 0 below it
    beta, y0, side : as for :class:`StraightRackCutter`

    Raises
    ------
    ValueError
        If a value is not finite, an angle is out of range or ``side`` is not +-1.

    Examples
    --------
    >>> import math
    >>> from gearrep.surfaces.rack import ParabolicRackCutter
    >>> rack = ParabolicRackCutter(0.1, math.radians(20), 0.5)  # 1/length, rad, length
    >>> round(float(rack.profile_curvature(0.0)), 12)  # 2a at the vertex Q
    0.2
    """

    def __init__(self, a: float, alpha_n: float, l: float, beta: float = 0.0, y0: float = 0.0, side: int = 1):
        super().__init__(beta)
        self.a = _finite(a, "a (parabola coefficient)")
        self._place_q(alpha_n, l, y0, side)
        # Q, the tangent and the normal at Q as float tuples (the profile on one point computes on floats)
        self._qdm = tuple(tuple(float(c) for c in v) for v in (self.q_point, self.tangent_q, self.normal_q))

    def profile(self, u):
        """(x, y, x', y', x'', y'') of the profile at u (a Python float gives floats).

        Parameters
        ----------
        u : float or array_like
            Profile parameter [length].

        Returns
        -------
        tuple
            (x, y [length], x', y' [1], x'', y'' [1/length]).
        """
        one = type(u) is float
        if not one:
            u = np.asarray(u, float)
        Q, d, m = self._qdm
        a = self.a
        x = Q[0] + u * d[0] + a * u**2 * m[0]
        y = Q[1] + u * d[1] + a * u**2 * m[1]
        xu = d[0] + 2 * a * u * m[0]
        yu = d[1] + 2 * a * u * m[1]
        z = 0.0 if one else np.zeros_like(u)
        return x, y, xu, yu, z + 2 * a * m[0], z + 2 * a * m[1]


class CircularArcRackCutter(RackCutter):
    """Rack-cutter whose normal profile is a circular arc (module doc): the circle of signed radius
    ``rho`` through Q, tangent there to the direction at alpha_n from the tooth height, centre
    C = Q + rho y_a (rho > 0: on the side of P, like the parabola with a = 1/(2 rho) > 0),
    parameterised by the arc length u from Q:

        (x_b, y_b)(u) = C - rho [cos(u/rho) y_a - sin(u/rho) x_a].

    Parameters
    ----------
    rho : signed radius of the arc (length, finite, nonzero)
    alpha_n : normal pressure angle at Q, in (0, pi/2) rad
    l : signed |QP| (length, finite; module doc); l = rho puts the centre on the pitch point P
    beta, y0, side : as for :class:`StraightRackCutter`

    Raises
    ------
    ValueError
        If ``rho`` is zero, a value is not finite, an angle is out of range or ``side`` is not +-1.

    Examples
    --------
    >>> import math
    >>> from gearrep.surfaces.rack import CircularArcRackCutter
    >>> rack = CircularArcRackCutter(5.0, math.radians(20), 0.5)  # length, rad, length
    >>> round(float(rack.profile_curvature(0.0)), 12)  # 1 / rho
    0.2
    """

    def __init__(self, rho: float, alpha_n: float, l: float, beta: float = 0.0, y0: float = 0.0, side: int = 1):
        super().__init__(beta)
        self.rho = _finite(rho, "rho (arc radius)")
        if self.rho == 0:
            raise ValueError(f"rho (arc radius) must be nonzero, got {rho!r}")
        self.a = 1.0 / (2.0 * self.rho)  # coefficient of the osculating parabola at Q
        self._place_q(alpha_n, l, y0, side)
        self.centre = self.q_point + self.rho * self.normal_q

    def _w(self, u):
        """Unit vector w(u) = cos(u/rho) y_a - sin(u/rho) x_a (the point is C - rho w) and w'."""
        t = np.asarray(u, float) / self.rho
        c, sn = np.cos(t)[..., None], np.sin(t)[..., None]
        m, d = self.normal_q, self.tangent_q
        return c * m - sn * d, -(sn * m + c * d) / self.rho

    def profile(self, u):
        w, w1 = self._w(u)
        C, rho = self.centre, self.rho
        return (
            C[0] - rho * w[..., 0],
            C[1] - rho * w[..., 1],
            -rho * w1[..., 0],
            -rho * w1[..., 1],
            w[..., 0] / rho,  # w'' = -w / rho^2
            w[..., 1] / rho,
        )

    def pitch_crossing(self, u):
        """Closed form (every normal passes through the centre C): y_P = y_C - x_C tan(psi), psi
        the polar angle of w (rate psi' = w x w', constant). Finite where the base formula is 0/0:
        an arc centred on the pitch line has y_P = y_C at every u, its crossing with the line
        included."""
        w, w1 = self._w(u)
        xc, yc = self.centre
        if xc == 0.0:
            z = np.zeros(w.shape[:-1])
            return z + yc, z, z.copy()
        dpsi = w[..., 0] * w1[..., 1] - w[..., 1] * w1[..., 0]
        with np.errstate(divide="ignore", invalid="ignore"):
            g = w[..., 1] / w[..., 0]
        g1 = dpsi * (1.0 + g * g)
        return yc - xc * g, -xc * g1, -xc * 2.0 * g * g1 * dpsi
