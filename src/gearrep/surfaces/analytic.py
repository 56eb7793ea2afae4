"""Closed-form test surfaces with analytic first and second derivatives.

Plane, sphere, circular cylinder, torus, right helicoid and involute helicoid. Each class
subclasses :class:`gearrep.surface.Surface`, overrides :meth:`evaluate` with exact
derivatives and offers :meth:`exact_principal` = (k1, k2, e1, e2) in the gearrep contract
convention (normal n = unit(r_u x r_v), k > 0 where the surface bends toward n, k1 >= k2,
e1 x e2 = n). Curvature closed forms: Litvin & Fuentes, *Gear Geometry and Applied Theory*,
ch. 7 (and any differential-geometry text); the involute helicoid is the tangent developable
of its base helix (curvature tau/(|t| kappa) of a tangent developable), giving
k = p/(r_b |u|) = cos(beta_b)/rho_t, the classical normal curvature of a helical involute
flank (rho_t = transverse radius of curvature, beta_b = base helix angle).

They serve as references for :mod:`gearrep.curvature` and other modules' tests. To obtain
the finite-difference version of any of them (the :class:`Surface` default), wrap it with
:func:`finite_difference_version`.
"""

from __future__ import annotations

import numpy as np

from ..surface import Surface, SurfacePoint, unit

__all__ = [
    "Plane",
    "Sphere",
    "Cylinder",
    "Torus",
    "Helicoid",
    "InvoluteHelicoid",
    "finite_difference_version",
]


def _uv(u, v):
    u = np.asarray(u, dtype=float)
    v = np.asarray(v, dtype=float)
    return np.broadcast_arrays(u, v)


def _vec(*comps):
    comps = np.broadcast_arrays(*(np.asarray(c, dtype=float) for c in comps))
    return np.stack(comps, axis=-1)


class _Analytic(Surface):
    def _derivs(self, u, v):  # pragma: no cover - abstract
        raise NotImplementedError

    def position(self, u, v) -> np.ndarray:
        u, v = _uv(u, v)
        return self._derivs(u, v)[0]

    def evaluate(self, u, v) -> SurfacePoint:
        """Position and exact first/second derivatives at (u, v)."""
        u, v = _uv(u, v)
        return SurfacePoint(*self._derivs(u, v))


class Plane(_Analytic):
    """r(u, v) = origin + u a + v b (a, b need not be orthonormal). k1 = k2 = 0.

    Parameters
    ----------
    origin, a, b : (3,) array_like, optional
        A point [length] and two independent directions.

    Examples
    --------
    >>> from gearrep.surfaces.analytic import Plane
    >>> Plane(origin=(0.0, 0.0, 1.0)).position(2.0, 3.0).tolist()
    [2.0, 3.0, 1.0]
    """

    def __init__(self, origin=(0.0, 0.0, 0.0), a=(1.0, 0.0, 0.0), b=(0.0, 1.0, 0.0)):
        self.origin = np.asarray(origin, float)
        self.a = np.asarray(a, float)
        self.b = np.asarray(b, float)

    def _derivs(self, u, v):
        r = self.origin + u[..., None] * self.a + v[..., None] * self.b
        z = np.zeros_like(r)
        return (
            r,
            np.broadcast_to(self.a, r.shape).copy(),
            np.broadcast_to(self.b, r.shape).copy(),
            z,
            z.copy(),
            z.copy(),
        )

    def exact_principal(self, u, v):
        """Principal curvatures and directions in closed form (the reference the tests compare with).

        Parameters
        ----------
        u, v : float or array_like
            Surface parameters.

        Returns
        -------
        tuple of numpy.ndarray
            (k1, k2 [1/length], e1, e2 (..., 3)), signed w.r.t. n = unit(r_u x r_v).
        """
        u, v = _uv(u, v)
        n = unit(np.cross(self.a, self.b))
        e1 = np.broadcast_to(unit(self.a), u.shape + (3,))
        e2 = np.broadcast_to(np.cross(n, unit(self.a)), u.shape + (3,))
        return np.zeros(u.shape), np.zeros(u.shape), e1, e2


class Sphere(_Analytic):
    """r(u, v) = R (cos v cos u, cos v sin u, sin v): u longitude, v latitude (|v| < pi/2).

    n = unit(r_u x r_v) is the OUTWARD normal, so k1 = k2 = -1/R (umbilic everywhere).

    Parameters
    ----------
    R : float, optional
        Radius [length].

    Examples
    --------
    >>> from gearrep.surfaces.analytic import Sphere
    >>> k1, k2, e1, e2 = Sphere(R=2.0).exact_principal(0.3, 0.2)
    >>> float(k1), float(k2)  # 1/length
    (-0.5, -0.5)
    """

    def __init__(self, R: float = 1.0):
        self.R = float(R)

    def _derivs(self, u, v):
        R = self.R
        cu, su, cv, sv = np.cos(u), np.sin(u), np.cos(v), np.sin(v)
        z = np.zeros_like(u)
        r = R * _vec(cv * cu, cv * su, sv)
        r_u = R * _vec(-cv * su, cv * cu, z)
        r_v = R * _vec(-sv * cu, -sv * su, cv)
        r_uu = R * _vec(-cv * cu, -cv * su, z)
        r_uv = R * _vec(sv * su, -sv * cu, z)
        r_vv = R * _vec(-cv * cu, -cv * su, -sv)
        return r, r_u, r_v, r_uu, r_uv, r_vv

    def exact_principal(self, u, v):
        """Principal curvatures and directions in closed form (the reference the tests compare with).

        Parameters
        ----------
        u, v : float or array_like
            Surface parameters.

        Returns
        -------
        tuple of numpy.ndarray
            (k1, k2 [1/length], e1, e2 (..., 3)), signed w.r.t. n = unit(r_u x r_v).
        """
        u, v = _uv(u, v)
        p = self.evaluate(u, v)
        k = np.full(u.shape, -1.0 / self.R)
        e1 = unit(p.r_u)
        return k, k.copy(), e1, np.cross(p.normal, e1)


class Cylinder(_Analytic):
    """r(u, v) = (R cos u, R sin u, v): circular cylinder about z, outward normal.

    k1 = 0 along the generator (e1 = +-z), k2 = -1/R around (e2 = circumferential).

    Parameters
    ----------
    R : float, optional
        Radius [length].

    Examples
    --------
    >>> from gearrep.surfaces.analytic import Cylinder
    >>> k1, k2, e1, e2 = Cylinder(R=2.0).exact_principal(0.0, 0.0)
    >>> float(k1), float(k2), e1.tolist()
    (0.0, -0.5, [0.0, 0.0, 1.0])
    """

    def __init__(self, R: float = 1.0):
        self.R = float(R)

    def _derivs(self, u, v):
        R = self.R
        cu, su = np.cos(u), np.sin(u)
        z, o = np.zeros_like(u), np.ones_like(u)
        r = _vec(R * cu, R * su, v)
        r_u = _vec(-R * su, R * cu, z)
        r_v = _vec(z, z, o)
        r_uu = _vec(-R * cu, -R * su, z)
        return r, r_u, r_v, r_uu, _vec(z, z, z), _vec(z, z, z)

    def exact_principal(self, u, v):
        """Principal curvatures and directions in closed form (the reference the tests compare with).

        Parameters
        ----------
        u, v : float or array_like
            Surface parameters.

        Returns
        -------
        tuple of numpy.ndarray
            (k1, k2 [1/length], e1, e2 (..., 3)), signed w.r.t. n = unit(r_u x r_v).
        """
        u, v = _uv(u, v)
        p = self.evaluate(u, v)
        e1 = unit(p.r_v)
        return np.zeros(u.shape), np.full(u.shape, -1.0 / self.R), e1, np.cross(p.normal, e1)


class Torus(_Analytic):
    """r(u, v) = ((c + a cos v) cos u, (c + a cos v) sin u, a sin v), c > a > 0; outward normal.

    Along the parallel (e1 = unit(r_u)): k1 = -cos v / (c + a cos v); along the meridian
    (e2 = unit(r_v)): k2 = -1/a. Outer equator v = 0: k1 = -1/(c + a); inner equator v = pi:
    k1 = +1/(c - a) (hyperbolic points).

    Parameters
    ----------
    c, a : float, optional
        Radius of the centre circle and of the tube [length], c > a > 0.

    Raises
    ------
    ValueError
        Unless c > a > 0.

    Examples
    --------
    >>> import math
    >>> from gearrep.surfaces.analytic import Torus
    >>> [round(float(k), 12) for k in Torus(3.0, 1.0).exact_principal(0.0, math.pi)[:2]]  # inner equator
    [0.5, -1.0]
    """

    def __init__(self, c: float = 3.0, a: float = 1.0):
        if not (c > a > 0):
            raise ValueError(f"Torus needs c > a > 0, got c={c!r}, a={a!r}")
        self.c = float(c)
        self.a = float(a)

    def _derivs(self, u, v):
        c, a = self.c, self.a
        cu, su, cv, sv = np.cos(u), np.sin(u), np.cos(v), np.sin(v)
        W = c + a * cv
        z = np.zeros_like(u)
        r = _vec(W * cu, W * su, a * sv)
        r_u = _vec(-W * su, W * cu, z)
        r_v = _vec(-a * sv * cu, -a * sv * su, a * cv)
        r_uu = _vec(-W * cu, -W * su, z)
        r_uv = _vec(a * sv * su, -a * sv * cu, z)
        r_vv = _vec(-a * cv * cu, -a * cv * su, -a * sv)
        return r, r_u, r_v, r_uu, r_uv, r_vv

    def exact_principal(self, u, v):
        """Principal curvatures and directions in closed form (the reference the tests compare with).

        Parameters
        ----------
        u, v : float or array_like
            Surface parameters.

        Returns
        -------
        tuple of numpy.ndarray
            (k1, k2 [1/length], e1, e2 (..., 3)), signed w.r.t. n = unit(r_u x r_v).
        """
        u, v = _uv(u, v)
        p = self.evaluate(u, v)
        k1 = -np.cos(v) / (self.c + self.a * np.cos(v))
        k2 = np.full(u.shape, -1.0 / self.a)
        e1 = unit(p.r_u)
        return k1, k2, e1, np.cross(p.normal, e1)


class Helicoid(_Analytic):
    """Right helicoid r(u, v) = (u cos v, u sin v, c v): u = rho (radius), v = theta.

    Minimal surface: k1 = -k2 = |c|/(rho^2 + c^2); principal directions bisect the
    (orthogonal) parameter lines: e1 = (t1 - sgn(c) t2)/sqrt 2, t1 = unit(r_u), t2 = unit(r_v).

    Parameters
    ----------
    c : float, optional
        Pitch: axial advance per radian [length], non-zero.

    Raises
    ------
    ValueError
        If ``c`` is 0.

    Examples
    --------
    >>> from gearrep.surfaces.analytic import Helicoid
    >>> [round(float(k), 12) for k in Helicoid(1.0).exact_principal(1.0, 0.0)[:2]]  # |c|/(rho^2 + c^2)
    [0.5, -0.5]
    """

    def __init__(self, c: float = 1.0):
        if c == 0:
            raise ValueError("Helicoid needs c != 0")
        self.c = float(c)

    def _derivs(self, u, v):
        c = self.c
        cv, sv = np.cos(v), np.sin(v)
        z = np.zeros_like(u)
        r = _vec(u * cv, u * sv, c * v)
        r_u = _vec(cv, sv, z)
        r_v = _vec(-u * sv, u * cv, c + z)
        r_uu = _vec(z, z, z)
        r_uv = _vec(-sv, cv, z)
        r_vv = _vec(-u * cv, -u * sv, z)
        return r, r_u, r_v, r_uu, r_uv, r_vv

    def exact_principal(self, u, v):
        """Principal curvatures and directions in closed form (the reference the tests compare with).

        Parameters
        ----------
        u, v : float or array_like
            Surface parameters.

        Returns
        -------
        tuple of numpy.ndarray
            (k1, k2 [1/length], e1, e2 (..., 3)), signed w.r.t. n = unit(r_u x r_v).
        """
        u, v = _uv(u, v)
        p = self.evaluate(u, v)
        k = abs(self.c) / (u**2 + self.c**2)
        t1, t2 = unit(p.r_u), unit(p.r_v)
        e1 = (t1 - np.sign(self.c) * t2) / np.sqrt(2.0)
        return k, -k, e1, np.cross(p.normal, e1)


class InvoluteHelicoid(_Analytic):
    """Involute helicoid: tangent developable of the base helix h(v) = (r_b cos v, r_b sin v, p v).

    r(u, v) = h(v) + u T(v), T = h'/|h'| = (-r_b sin v, r_b cos v, p)/w, w = sqrt(r_b^2 + p^2);
    u (!= 0) is the true length along the straight generator from the base-helix tangency, v the
    helix angle parameter; p = lead / (2 pi) (screw parameter, signed: p > 0 right-handed),
    base helix angle beta_b with tan beta_b = r_b/|p|. Transverse sections are involutes of the
    base circle. With n = unit(r_u x r_v) = sgn(u) (p sin v, -p cos v, r_b)/w:
    one principal curvature 0 along the generator T, the other p/(r_b |u|) across it
    (= cos beta_b / rho_t with rho_t = ``|u|`` sin beta_b the transverse radius of curvature).

    Parameters
    ----------
    rb : float, optional
        Base radius r_b [length], > 0.
    p : float, optional
        Screw parameter lead / (2 pi) [length per rad], non-zero.

    Raises
    ------
    ValueError
        If ``rb`` <= 0 or ``p`` = 0.

    Examples
    --------
    >>> from gearrep.surfaces.analytic import InvoluteHelicoid
    >>> [round(float(k), 12) for k in InvoluteHelicoid(1.0, 1.0).exact_principal(-1.0, 0.0)[:2]]
    [1.0, 0.0]
    """

    def __init__(self, rb: float = 1.0, p: float = 1.0):
        if not (rb > 0):
            raise ValueError(f"rb must be > 0, got {rb!r}")
        if p == 0:
            raise ValueError("p must be != 0 (p = 0 degenerates into a plane)")
        self.rb = float(rb)
        self.p = float(p)
        self.w = float(np.hypot(rb, p))

    def _derivs(self, u, v):
        rb, p, w = self.rb, self.p, self.w
        cv, sv = np.cos(v), np.sin(v)
        z = np.zeros_like(u)
        T = _vec(-rb * sv, rb * cv, p + z) / w
        Tp = _vec(-rb * cv, -rb * sv, z) / w
        Tpp = _vec(rb * sv, -rb * cv, z) / w
        h = _vec(rb * cv, rb * sv, p * v)
        hpp = _vec(-rb * cv, -rb * sv, z)
        U = u[..., None]
        r = h + U * T
        r_u = T
        r_v = w * T + U * Tp
        r_uu = _vec(z, z, z)
        r_uv = Tp
        r_vv = hpp + U * Tpp
        return r, r_u, r_v, r_uu, r_uv, r_vv

    def exact_principal(self, u, v):
        """Principal curvatures and directions in closed form (the reference the tests compare with).

        Parameters
        ----------
        u, v : float or array_like
            Surface parameters.

        Returns
        -------
        tuple of numpy.ndarray
            (k1, k2 [1/length], e1, e2 (..., 3)), signed w.r.t. n = unit(r_u x r_v).
        """
        u, v = _uv(u, v)
        p = self.evaluate(u, v)
        kn = self.p / (self.rb * np.abs(u))
        gen = unit(p.r_u)
        n = p.normal
        across = np.cross(n, gen)
        if self.p > 0:  # k = p/(rb|u|) > 0 across the generator
            return kn, np.zeros(u.shape), across, np.cross(n, across)
        return np.zeros(u.shape), kn, gen, across


def finite_difference_version(surface: Surface, fd_step=None) -> Surface:
    """A :class:`Surface` with the same ``position`` whose ``evaluate`` is the base-class
    fourth-order finite-difference default (optionally with steps ``fd_step`` = (h_u, h_v)).

    Parameters
    ----------
    surface : Surface
        The surface whose ``position`` is used.
    fd_step : tuple of float, optional
        (h_u, h_v) in parameter units (default the surface's own).

    Returns
    -------
    Surface
        The finite-difference twin.

    Examples
    --------
    >>> from gearrep.surfaces.analytic import Sphere, finite_difference_version
    >>> round(float(finite_difference_version(Sphere(R=2.0)).evaluate(0.0, 0.0).r_uu[0]), 9)
    -2.0
    """

    class _FD(Surface):
        def position(self, u, v):
            return surface.position(u, v)

    fd = _FD()
    if fd_step is not None:
        fd.fd_step = tuple(fd_step)
    return fd
